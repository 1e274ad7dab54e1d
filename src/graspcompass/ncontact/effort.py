"""The effort whose least value the grasp needs: named choices and custom linear weights.

A linear effort is ``Σ_i w_i · f_i`` for the contact forces ``f_i``: the cost of a
unit weight on edge ``d`` of contact ``i`` is ``c = w_i · d``.

* ``"sum-normal"``: the sum of the normal forces, ``w_i = n_i`` (every edge costs 1);
* ``"pair:I,J"``: the normal forces of contacts I and J (1-based), the others free;
* ``"paper"`` (n = 2 only): the paper's k, linear in the contact forces,
  ``k = F·F_N/|F_N|² = (x1 + x2)/2 · (f2x - f1x)`` (eqs. (15)-(17)), i.e.
  ``w_1 = (p2 - p1)/2``, ``w_2 = (p1 - p2)/2``, with the sign constraint
  ``k >= 0`` of eq. (25) (the "0" of ``max{k1, ..., k4, 0}``);
* custom: a sequence of n numbers (weights of the normal forces, ``w_i = λ_i n_i``)
  or of n pairs (the vectors ``w_i`` themselves);
* ``"max-normal"``: the largest normal force ``max_i N_i`` (sublinear, not linear).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..geometry.exact import canon, has_float
from .contact import read_number
from .errors import EffortError

__all__ = ["EFFORTS", "Effort", "read_effort"]

#: The named efforts.
EFFORTS = ("paper", "sum-normal", "pair:I,J", "max-normal")


@dataclass(frozen=True)
class Effort:
    """A parsed effort.

    Attributes
    ----------
    name : str
        ``"paper"``, ``"sum-normal"``, ``"pair:I,J"``, ``"max-normal"`` or ``"custom"``.
    weights : tuple or None
        Per contact the vector ``w_i`` (None for ``"max-normal"``).
    nonnegative : bool
        True when the effort itself is constrained to be >= 0 (the paper's k >= 0).
    """

    name: str
    weights: tuple | None
    nonnegative: bool = False

    @property
    def linear(self) -> bool:
        """True for a linear effort (all but ``"max-normal"``)."""
        return self.weights is not None


def _num(v: Any, name: str) -> sp.Expr:
    return read_number(v, name, EffortError)


def read_effort(spec: Any, contacts: tuple) -> Effort:
    """An :class:`Effort` for the contacts (a named choice or custom weights).

    Raises
    ------
    EffortError
        For an unknown name, a pair out of range, ``"paper"`` with n != 2, or
        custom weights of the wrong number or kind.
    """
    n = len(contacts)
    numeric = any(c.numeric for c in contacts)

    def conv(v: sp.Expr) -> Any:
        return float(v) if numeric else canon(v)

    if isinstance(spec, str):
        s = spec.strip()
        if s == "sum-normal":
            return Effort(s, tuple(c.n for c in contacts))
        if s == "max-normal":
            return Effort(s, None)
        if s == "paper":
            if n != 2:
                raise EffortError(
                    f"effort 'paper' (the paper's k) needs exactly 2 contacts, got {n}"
                )
            p1, p2 = contacts[0].p, contacts[1].p
            w1 = tuple(conv((b - a) / 2) for a, b in zip(p1, p2))
            w2 = tuple(conv((a - b) / 2) for a, b in zip(p1, p2))
            return Effort(s, (w1, w2), nonnegative=True)
        m = re.fullmatch(r"pair:\s*(\d{1,4})\s*,\s*(\d{1,4})", s)
        if m:
            i, j = int(m.group(1)), int(m.group(2))
            if not (1 <= i <= n and 1 <= j <= n) or i == j:
                raise EffortError(
                    f"effort {s!r}: I and J must be two different contacts among 1..{n}"
                )
            zero = (0.0, 0.0) if numeric else (sp.Integer(0), sp.Integer(0))
            return Effort(
                f"pair:{i},{j}",
                tuple(c.n if k + 1 in (i, j) else zero for k, c in enumerate(contacts)),
            )
        raise EffortError(
            f"unknown effort {spec[:40]!r}; choose one of {', '.join(EFFORTS)} "
            "or give custom weights"
        )
    if isinstance(spec, Effort):
        return spec
    if not isinstance(spec, (list, tuple)) or len(spec) != n:
        raise EffortError(
            f"custom effort: expected {n} weights (one per contact), got {type(spec).__name__}"
        )
    ws = []
    for k, (w, c) in enumerate(zip(spec, contacts)):
        if isinstance(w, (list, tuple)):
            if len(w) != 2:
                raise EffortError(f"custom effort: weight {k + 1} must be a number or a pair")
            vx, vy = (_num(v, f"effort weight {k + 1}") for v in w)
            ws.append((vx, vy))
        else:
            lam = _num(w, f"effort weight {k + 1}")
            ws.append((lam * c.n[0], lam * c.n[1]))
    if any(has_float(v) for w in ws for v in w) and not numeric:
        raise EffortError("custom effort: float weights need a float grasp (give exact text)")
    return Effort("custom", tuple(tuple(conv(v) for v in w) for w in ws))
