"""Symbolic proof checker for the paper's claims (polynomial reduction, never "close enough")."""
