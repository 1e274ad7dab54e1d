"""Symbolic proof checker for the paper's claims (polynomial reduction, never "close enough").

* :func:`prove_identity` and :func:`prove_sign` give PROVED, REFUTED (with an
  exact counterexample) or UNDECIDED;
* :data:`CLAIMS` is the catalogue of the paper's statements, run by
  :func:`run_catalogue` (``graspcompass verify``);
* :func:`certify` proves every step of one construction;
* :func:`run_crosscheck` compares the closed form with scipy's ``linprog``.
"""

from .._lazy import attach
from .certify import StepCertificate, certify, certify_records
from .recheck import RecheckError, recheck

#: Where the other public names live, imported on first use (PEP 562): ``check`` of a
#: file does not load the paper's catalogue.  ``certify`` and ``recheck`` are imported
#: at once: they are also the names of their modules, which an import of the module
#: would otherwise put in their place.
_HOMES = {
    **dict.fromkeys(("CLAIMS", "Claim", "check", "claim"), "catalogue"),
    **dict.fromkeys(("sample", "violations"), "model"),
    **dict.fromkeys(
        (
            "CONDITION_1",
            "ProofResult",
            "Status",
            "find_counterexample",
            "prove_identity",
            "prove_sign",
        ),
        "prove",
    ),
    **dict.fromkeys(
        ("DegenerateClaimError", "is_identically_zero", "reduce_expr", "trig_to_poly"), "reduce"
    ),
    **dict.fromkeys(
        ("ClaimReport", "exit_status", "run_catalogue", "to_json", "to_markdown", "to_table"),
        "report",
    ),
}
__getattr__, __dir__ = attach(__name__, _HOMES)

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
