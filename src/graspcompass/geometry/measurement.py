"""Exact measurements: squared distance, signed (directed) length, direction angle."""

from __future__ import annotations

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
    # sympy's atan evaluates radical arguments (atan(1) = pi/4); others stay unevaluated
    base = sp.atan(ratio, evaluate=is_radical(ratio))
    if sy > 0:
        return base
    return base + sp.pi if sx >= 0 else base - sp.pi
