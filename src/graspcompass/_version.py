"""The package's version, a leaf module so that every layer can read it (issue 21)."""

from __future__ import annotations

__all__ = ["__version__"]

__version__ = "0.1.0"
