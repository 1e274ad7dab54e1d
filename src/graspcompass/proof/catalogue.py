"""The catalogue: every claim of the paper, with its id, reference and hypotheses.

Each :class:`Claim` is checked by :func:`check` for general symbolic
parameters; its hypotheses (condition (1), μ = tan ξ (22), extra ones) and the
non-degeneracy conditions of its proof are part of its result.  Claims about
the drawing (§3.3, Appendix) are checked on the objects that the recipe
constructs with every parameter a symbol, not on the closed form.  Where the
paper as printed is wrong, the printed claim stays in the catalogue (and comes
out REFUTED with a counterexample, a point of the model) and names the
corrected claim that is PROVED.

The claims live in :mod:`.catalogue_model` (§2), :mod:`.catalogue_drawing`
(§3, Appendix) and :mod:`.catalogue_section5` (§4.2, §5).
"""

from __future__ import annotations

from .catalogue_core import Claim, check, session, symbolic_construction
from .catalogue_drawing import appendix_claims, diagram_claims
from .catalogue_model import model_claims
from .catalogue_ncontact import ncontact_claims
from .catalogue_section5 import section5_claims

#: The n-contact claims in the default catalogue (instant); ``verify --ncontact`` adds the rest.
DEFAULT_NCONTACT = ("table1c-V4-redundant",)

__all__ = [
    "CLAIMS",
    "DEFAULT_NCONTACT",
    "Claim",
    "build_claims",
    "check",
    "claim",
    "ncontact_extra",
    "session",
    "symbolic_construction",
]


def build_claims() -> tuple[Claim, ...]:
    """A fresh catalogue (new claim objects) in the paper's order."""
    out = model_claims()
    eq24 = next(c for c in out if c.id == "eq24-25")
    eq27: list[Claim] = []
    out += diagram_claims(eq27)
    out += appendix_claims()
    out += section5_claims(eq27, eq24)
    out += [c for c in ncontact_claims() if c.id in DEFAULT_NCONTACT]
    ids = [c.id for c in out]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise ValueError(f"duplicate claim ids: {sorted(dup)}")
    return tuple(out)


CLAIMS: tuple[Claim, ...] = build_claims()


def claim(claim_id: str) -> Claim:
    """The claim with this id."""
    for c in CLAIMS:
        if c.id == claim_id:
            return c
    raise KeyError(f"no claim {claim_id!r}")


def ncontact_extra() -> tuple[Claim, ...]:
    """The n-contact claims that ``verify --ncontact`` adds (docs/ncontact.md)."""
    return tuple(c for c in ncontact_claims() if c.id not in DEFAULT_NCONTACT)
