"""Exact measurements: squared distance, signed (directed) length, direction angle."""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .errors import ZeroDirectionError
from .exact import Frac, NotAFraction, canon, decide_sign
from .primitives import Line, Point

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
    from .roots import constructed_sqrt

    return canon((end - start).dot(d) / constructed_sqrt(canon(d.dot(d))))


@lru_cache(maxsize=1)
def _atan_values() -> dict[sp.Expr, sp.Expr]:
    """Positive arguments at which ``atan`` is a multiple of π, and those values.

    The entries of sympy's own table (``atan._atan_table``) whose arguments the kernel
    can make: square roots of rationals, no nested radicals (``tan(pi/5)`` is
    ``sqrt(5 - 2*sqrt(5))``, never a canonical number).  Written out: building
    sympy's table costs 25 ms in every new process (``test_geometry`` checks that
    both agree).
    """
    return {r: q * sp.pi for r, q in _atan_multiples().items()}


@lru_cache(maxsize=1)
def _atan_multiples() -> dict[sp.Expr, sp.Rational]:
    """:func:`_atan_values` divided by π (the multiples of π are made only when met)."""
    r2, r3, q = sp.sqrt(2), sp.sqrt(3), sp.Rational
    return {
        sp.Integer(1): q(1, 4),
        r3 / 3: q(1, 6),
        r3: q(1, 3),
        r2 - 1: q(1, 8),
        r2 + 1: q(3, 8),
        2 - r3: q(1, 12),
        r3 + 2: q(5, 12),
    }


def _atan_positive(ratio: sp.Expr) -> sp.Expr:
    """``atan`` of a positive canonical number without sympy's costly ``eval``: a
    multiple of π where sympy's table has one (``atan(2 - sqrt(3)) = pi/12``), else
    ``atan(ratio)`` unevaluated."""
    known = _atan_multiples().get(ratio)
    return known * sp.pi if known is not None else sp.atan(ratio, evaluate=False)


def angle_of(vector: Point) -> sp.Expr:
    """Angle θ from the negative y-axis, counter-clockwise, with ``e(θ) ∥ vector``.

    The paper's convention (26): ``e(θ) = (sin θ, -cos θ)``.  Exact vectors give
    ``±atan(r) + kπ`` with r > 0 canonical (a multiple of π where one is known).

    Raises
    ------
    ZeroDirectionError
        For the zero vector.

    Examples
    --------
    >>> angle_of(Point(1, 0)), angle_of(Point(0, -1))
    (pi/2, 0)
    >>> from sympy import sqrt
    >>> angle_of(Point(1, 2 + sqrt(3))), angle_of(Point(-2, -1))
    (11*pi/12, -atan(2))
    """
    try:
        fx, fy = Frac.of(vector.x), -Frac.of(vector.y)  # θ = atan2(x, y)
    except NotAFraction:
        return _angle_of_sympy(vector)
    sy, sx = fy.sign(), fx.sign()
    if sy is None or sx is None:  # symbolic: leave the branch to sympy
        return _angle_of_sympy(vector)
    if sy == 0:
        if sx == 0:
            raise ZeroDirectionError("the zero vector has no direction", vector)
        return sx * sp.pi / 2
    if sx == 0:
        base = sp.Integer(0)
    else:
        ratio = fx / fy
        base = _atan_positive((ratio if sx * sy > 0 else -ratio).expr())
        if sx * sy < 0:
            base = -base
    if sy > 0:
        return base
    return base + sp.pi if sx >= 0 else base - sp.pi


def _angle_of_sympy(vector: Point) -> sp.Expr:
    """:func:`angle_of` with sympy arithmetic (floats, symbols)."""
    x, y = vector.x, -vector.y
    sy, sx = decide_sign(y), decide_sign(x)
    if sy is None or sx is None:  # symbolic: leave the branch to sympy
        angle = sp.atan2(x, y)
        return angle.replace(sp.atan, lambda z: sp.atan(canon(z)))
    if sy == 0:
        if sx == 0:
            raise ZeroDirectionError("the zero vector has no direction", vector)
        return sx * sp.pi / 2
    base = sp.atan(canon(x / y))
    if sy > 0:
        return base
    return base + sp.pi if sx >= 0 else base - sp.pi
