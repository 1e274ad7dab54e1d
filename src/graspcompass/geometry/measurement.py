"""Exact measurements: squared distance, signed (directed) length, direction angle."""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .exact import canon, decide_sign
from .primitives import Line, Point
from .trig import is_radical

__all__ = ["angle_of", "distance", "distance2", "signed_length"]


def distance2(p: Point, q: Point) -> sp.Expr:
    """Squared distance, exact and free of square roots.

    Examples
    --------
    >>> distance2(Point(0, 0), Point(3, 4))
    25
    """
    return canon((q.x - p.x) ** 2 + (q.y - p.y) ** 2)


def distance(p: Point, q: Point) -> sp.Expr:
    """Euclidean distance ``sqrt(distance2(p, q))``."""
    return sp.sqrt(distance2(p, q))


def signed_length(start: Point, end: Point, line: Line) -> sp.Expr:
    """Directed length from ``start`` to ``end`` measured along ``line``.

    Positive when ``end`` lies ahead of ``start`` in ``line``'s direction (the
    paper's overlined lengths such as O_M X_n and O Y_n, §3.3).

    Examples
    --------
    >>> x_axis = Line(Point(0, 0), Point(1, 0))
    >>> signed_length(Point(3, 0), Point(1, 0), x_axis)
    -2
    """
    d = line.direction
    return canon((end - start).dot(d) / sp.sqrt(d.dot(d)))


@lru_cache(maxsize=1)
def _atan_values() -> dict[sp.Expr, sp.Expr]:
    """The arguments at which sympy's ``atan`` returns a multiple of π, and those values."""
    table: dict[sp.Expr, sp.Expr] = {sp.Integer(0): sp.Integer(0), sp.Integer(1): sp.pi / 4}
    table.update(sp.atan._atan_table())
    table.update({-k: -v for k, v in list(table.items())})
    return table


def _atan(ratio: sp.Expr) -> sp.Expr:
    """``sympy.atan(ratio)`` for a canonical number, without sympy's costly ``eval``.

    Gives what sympy's evaluation gives on such arguments (a multiple of π from its
    table, else ``atan`` of the positive-looking argument with the sign outside),
    which ``test_geometry`` checks against ``sympy.atan``.
    """
    if not is_radical(ratio):
        return sp.atan(ratio, evaluate=False)
    known = _atan_values().get(ratio)
    if known is not None:
        return known
    if ratio.could_extract_minus_sign():
        return -sp.atan(-ratio, evaluate=False)
    return sp.atan(ratio, evaluate=False)


def angle_of(vector: Point) -> sp.Expr:
    """Angle θ from the negative y-axis, counter-clockwise, with ``e(θ) ∥ vector``.

    The paper's convention (26): ``e(θ) = (sin θ, -cos θ)``.

    Examples
    --------
    >>> angle_of(Point(1, 0)), angle_of(Point(0, -1))
    (pi/2, 0)
    """
    x, y = vector.x, -vector.y  # θ = atan2(x, y), with the branch decided exactly
    sy, sx = decide_sign(y), decide_sign(x)
    if sy is None or sx is None:  # symbolic: leave the branch to sympy
        angle = sp.atan2(x, y)
        return angle.replace(sp.atan, lambda z: sp.atan(canon(z)))
    if sy == 0:
        if sx == 0:
            raise ValueError("the zero vector has no direction")
        return sx * sp.pi / 2
    ratio = canon(x / y)
    base = _atan(ratio)
    if sy > 0:
        return base
    return base + sp.pi if sx >= 0 else base - sp.pi
