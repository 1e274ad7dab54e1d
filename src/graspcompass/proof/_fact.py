"""A fact a construction step must establish (:class:`Fact`), shared by the certifiers.

Private: documented and pickled as :class:`graspcompass.proof.certify_facts.Fact`;
here so that :mod:`.certify_facts` and :mod:`.certify_envelope` both read it without
an import cycle (issue 21).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

__all__ = ["Fact"]


@dataclass(frozen=True)
class Fact:
    """One statement about a step: ``lhs == rhs`` (``kind="eq"``), ``lhs != 0``
    (``"nonzero"``, a non-degeneracy condition) or ``lhs >= 0`` (``"nonneg"``).

    ``scale`` returns the magnitude of the quantities involved (float path only).
    """

    text: str
    lhs: Any
    rhs: Any = 0
    kind: str = "eq"
    scale: Callable[..., float] = field(default=lambda: 1.0, compare=False, repr=False)


def _f(*vals: Any) -> float:
    out = 0.0
    for v in vals:
        try:
            out += abs(float(v))
        except (TypeError, ValueError):
            return math.inf
    return out


Fact.__module__ = "graspcompass.proof.certify_facts"
