"""Symbolic proof checker for the paper's claims (polynomial reduction, never "close enough").

* :func:`prove_identity` and :func:`prove_sign` give PROVED, REFUTED (with an
  exact counterexample) or UNDECIDED;
* :data:`CLAIMS` is the catalogue of the paper's statements, run by
  :func:`run_catalogue` (``graspcompass verify``);
* :func:`certify` proves every step of one construction;
* :func:`run_crosscheck` compares the closed form with scipy's ``linprog``.
"""

from .catalogue import CLAIMS, Claim, check, claim
from .certify import StepCertificate, certify, certify_records
from .model import sample, violations
from .prove import CONDITION_1, ProofResult, Status, find_counterexample, prove_identity, prove_sign
from .recheck import RecheckError, recheck
from .reduce import DegenerateClaimError, is_identically_zero, reduce_expr, trig_to_poly
from .report import ClaimReport, exit_status, run_catalogue, to_json, to_markdown, to_table

__all__ = [
    "CLAIMS",
    "CONDITION_1",
    "Claim",
    "ClaimReport",
    "DegenerateClaimError",
    "ProofResult",
    "RecheckError",
    "Status",
    "StepCertificate",
    "certify",
    "certify_records",
    "check",
    "claim",
    "exit_status",
    "find_counterexample",
    "is_identically_zero",
    "prove_identity",
    "prove_sign",
    "recheck",
    "reduce_expr",
    "run_catalogue",
    "sample",
    "to_json",
    "to_markdown",
    "to_table",
    "trig_to_poly",
    "violations",
]
