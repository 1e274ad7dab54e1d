"""Exact signs for the n-contact code: :func:`decide_sign` or a named error, never a guess."""

from __future__ import annotations

import sympy as sp

from ..geometry.exact import canon, decide_sign
from .errors import UndecidedSignError

__all__ = ["cross2", "det", "exact_sgn", "sign"]


def sign(expr: sp.Expr, what: str) -> int:
    """The exact sign of ``expr`` (-1, 0, +1); :class:`UndecidedSignError` when undecidable.

    Parameters
    ----------
    expr : sympy.Expr
        An exact number (canonical or not).
    what : str
        What the sign decides, for the message.
    """
    s = decide_sign(expr)
    if s is None:
        raise UndecidedSignError(
            f"cannot decide the sign of {what} (value {sp.N(expr, 6)}): "
            "give the grasp exactly in simpler numbers"
        )
    return s


def det(rows: list[list[sp.Expr]]) -> sp.Expr:
    """Determinant of a small square matrix by cofactor expansion, unreduced (no ``canon``)."""
    n = len(rows)
    if n == 1:
        return rows[0][0]
    if n == 2:
        return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    total = sp.Integer(0)
    for j in range(n):
        if rows[0][j] == 0:
            continue
        minor = [r[:j] + r[j + 1 :] for r in rows[1:]]
        total += (-1) ** j * rows[0][j] * det(minor)
    return total


def cross2(a: tuple, b: tuple) -> sp.Expr:
    """``a_x b_y - a_y b_x`` in canonical form (the orientation of the pair)."""
    return canon(a[0] * b[1] - a[1] * b[0])


def exact_sgn(v: sp.Expr, what: str) -> int:
    """:func:`sign` of a (canonicalised) expression (also :func:`.polygon.exact_sgn`)."""
    return sign(canon(v), what)
