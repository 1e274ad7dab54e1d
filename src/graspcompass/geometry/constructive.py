"""Ruler-and-compass constructions of the kernel (the verbs).

Every function takes and returns frozen values from
:mod:`graspcompass.geometry.primitives`.  A construction that would divide by
zero raises a named :class:`~graspcompass.geometry.errors.GeometryError`;
one whose divisor is symbolic and cannot be decided records the divisor in the
result's ``conditions`` (assumed non-zero) instead.  Intersections that may
have several answers (:func:`intersect_line_circle`, :func:`intersect_circles`,
:func:`intersection`) return a tuple of 0-2 points in a fixed *branch* order
that does not depend on the numbers, so a symbolic and a numeric replay pick
the same point.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy as sp

from .errors import (
    CoincidentPointsError,
    DegenerateCircleError,
    GeometryError,
    NoIntersectionError,
    ParallelLinesError,
)
from .exact import Frac, NotAFraction, canon, decide_sign, decide_zero, has_float
from .primitives import Circle, Line, Point, _merge
from .roots import constructed_sqrt

__all__ = [
    "circle_on_diameter",
    "circle_through",
    "foot",
    "intersect_circles",
    "intersect_line_circle",
    "intersection",
    "line_through",
    "line_with_direction",
    "meet",
    "midpoint",
    "parallel",
    "perpendicular",
    "reflect",
    "second_intersection",
]


def _size(*vectors: Point) -> float:
    """Product of the vectors' lengths when they are floats (a scale for zero tests)."""
    out = 1.0
    if not any(has_float(c) for v in vectors for c in (v.x, v.y)):
        return 0.0  # exact data: zero means zero
    for v in vectors:
        try:
            out *= float(sp.sqrt(v.x**2 + v.y**2))
        except TypeError:
            return 0.0
    return out


def _nonzero(
    value: sp.Expr,
    error: type[GeometryError],
    message: Callable[[], str],
    *objs: object,
    scale: float = 0.0,
) -> frozenset:
    """Raise ``error`` if ``value`` is zero; return ``{value}`` if undecidable.

    ``message`` makes the text only when it is raised (printing exact objects is slow).
    """
    z = decide_zero(value, scale)
    if z:
        raise error(message(), *objs)
    return frozenset({canon(value)}) if z is None else frozenset()


def _nonzero_frac(
    value: Frac, error: type[GeometryError], message: Callable[[], str], *objs: object
) -> frozenset:
    """:func:`_nonzero` for an exact fraction, deciding without a sympy expression."""
    z = value.is_zero()
    if z:
        raise error(message(), *objs)
    return frozenset({value.expr()}) if z is None else frozenset()


def _fracs(*points: Point) -> list[tuple[Frac, Frac]]:
    """The coordinates as exact fractions (raises NotAFraction for floats)."""
    return [(Frac.of(p.x), Frac.of(p.y)) for p in points]


def line_through(p: Point, q: Point) -> Line:
    """The line through ``p`` and ``q``, oriented from ``p`` to ``q`` (ruler).

    Examples
    --------
    >>> line_through(Point(0, 0), Point(2, 2))
    Line(Point(0, 0), direction=Point(2, 2))
    >>> line_through(Point(1, 1), Point(1, 1))
    Traceback (most recent call last):
    ...
    graspcompass.geometry.errors.CoincidentPointsError: a line through two points needs ...
    """
    if decide_zero(p.x - q.x) and decide_zero(p.y - q.y):
        raise CoincidentPointsError(
            f"a line through two points needs two distinct points, got {p} twice", p, q
        )
    return Line(p, q - p)


def line_with_direction(p: Point, direction: Point) -> Line:
    """The line through ``p`` along ``direction`` (ruler set to a given angle)."""
    return Line(p, direction)


def parallel(line: Line, through: Point) -> Line:
    """The parallel to ``line`` through ``through``, with the same orientation."""
    return Line(through, line.direction, line.conditions)


def perpendicular(line: Line, through: Point) -> Line:
    """The perpendicular to ``line`` through ``through``.

    Its direction is ``line``'s turned a quarter turn counter-clockwise.

    Examples
    --------
    >>> perpendicular(Line(Point(0, 0), Point(1, 0)), Point(3, 5))
    Line(Point(3, 5), direction=Point(0, 1))
    """
    return Line(through, line.normal, line.conditions)


def meet(a: Line, b: Line) -> Point:
    """The one point common to two lines (ruler).

    Raises
    ------
    ParallelLinesError
        If the lines are parallel or the same line.

    Examples
    --------
    >>> meet(Line(Point(0, 1), Point(1, 1)), Line(Point(0, 0), Point(1, 0)))
    Point(-1, 0)
    >>> meet(Line(Point(0, 1), Point(1, 0)), Line(Point(0, 0), Point(2, 0)))
    Traceback (most recent call last):
    ...
    graspcompass.geometry.errors.ParallelLinesError: lines are parallel, they do not meet ...
    """
    try:  # fast path: fractions of polynomials, no sympy expression trees
        (ax, ay), (adx, ady), (bx, by), (bdx, bdy) = _fracs(
            a.point, a.direction, b.point, b.direction
        )
        den_f = adx * bdy - ady * bdx
    except NotAFraction:
        den_f = None

    def parallel() -> str:
        return f"lines are parallel, they do not meet in one point: {a} and {b}"

    if den_f is not None:
        conds = _nonzero_frac(den_f, ParallelLinesError, parallel, a, b)
        t = ((bx - ax) * bdy - (by - ay) * bdx) / den_f
        return Point((ax + t * adx).expr(), (ay + t * ady).expr(), _merge(a, b) | conds)
    den = a.direction.cross(b.direction)
    conds = _nonzero(den, ParallelLinesError, parallel, a, b, scale=_size(a.direction, b.direction))
    t = (b.point - a.point).cross(b.direction) / den
    p = a.point
    d = a.direction
    return Point.canonical(p.x + t * d.x, p.y + t * d.y, _merge(a, b) | conds)


def foot(point: Point, line: Line) -> Point:
    """Foot of the perpendicular from ``point`` to ``line``.

    Examples
    --------
    >>> from sympy import sqrt
    >>> foot(Point(sqrt(3)/2, 5), Line(Point(0, 0), Point(1, 0)))
    Point(sqrt(3)/2, 0)
    """
    try:
        (qx, qy), (px, py), (dx, dy) = _fracs(point, line.point, line.direction)
        t = ((qx - px) * dx + (qy - py) * dy) / (dx * dx + dy * dy)
        return Point((px + t * dx).expr(), (py + t * dy).expr(), _merge(point, line))
    except NotAFraction:
        pass
    d = line.direction
    t = (point - line.point).dot(d) / d.dot(d)
    p = line.point
    return Point.canonical(p.x + t * d.x, p.y + t * d.y, _merge(point, line))


def reflect(point: Point, line: Line) -> Point:
    """Mirror image of ``point`` in ``line``."""
    f = foot(point, line)
    return Point.canonical(2 * f.x - point.x, 2 * f.y - point.y, f.conditions)


def midpoint(p: Point, q: Point) -> Point:
    """Midpoint of ``p`` and ``q``.

    Examples
    --------
    >>> from sympy import sqrt
    >>> midpoint(Point(sqrt(3)/2, 0), Point(-sqrt(3)/2, 0))
    Point(0, 0)
    """
    try:
        (px, py), (qx, qy) = _fracs(p, q)
        half = Frac.of(sp.S.Half)
        return Point(((px + qx) * half).expr(), ((py + qy) * half).expr(), _merge(p, q))
    except NotAFraction:
        return Point.canonical((p.x + q.x) / 2, (p.y + q.y) / 2, _merge(p, q))


def circle_on_diameter(a: Point, b: Point) -> Circle:
    """The circle with diameter ``ab`` (compass; Thales circle of eq. (31)).

    Examples
    --------
    >>> circle_on_diameter(Point(0, 0), Point(2, 0))
    Circle(Point(1, 0), radius2=1)
    """

    def same() -> DegenerateCircleError:
        return DegenerateCircleError(
            f"a circle on a diameter needs two distinct end points, got {a} twice", a, b
        )

    try:
        (ax, ay), (bx, by) = _fracs(a, b)
    except NotAFraction:
        if decide_zero(a.x - b.x) and decide_zero(a.y - b.y):
            raise same() from None
        r2 = canon(((b.x - a.x) ** 2 + (b.y - a.y) ** 2) / 4)
    else:
        dx, dy = bx - ax, by - ay
        if dx.is_zero() and dy.is_zero():
            raise same()
        r2 = ((dx * dx + dy * dy) * Frac.of(sp.Rational(1, 4))).expr()
    c = midpoint(a, b)
    return Circle(c, r2, _merge(a, b))


def circle_through(center: Point, point: Point) -> Circle:
    """The circle with ``center`` through ``point`` (compass)."""
    return Circle(center, canon((point.x - center.x) ** 2 + (point.y - center.y) ** 2))


def intersect_line_circle(line: Line, circle: Circle) -> tuple[Point, ...]:
    """Points common to a line and a circle: 0, 1 (tangent) or 2 points.

    Branch order: the point further along ``line``'s direction comes first.
    With symbolic data the two branches are returned and the discriminant is
    recorded as a condition.

    Examples
    --------
    >>> intersect_line_circle(Line(Point(0, 0), Point(1, 0)), Circle(Point(0, 0), 4))
    (Point(2, 0), Point(-2, 0))
    >>> intersect_line_circle(Line(Point(0, 5), Point(1, 0)), Circle(Point(0, 0), 4))
    ()
    """
    d = line.direction
    w = line.point - circle.center
    a = d.dot(d)
    b = d.dot(w)
    disc = canon(b**2 - a * (w.dot(w) - circle.radius2))
    sign = decide_sign(disc)
    conds = _merge(line, circle)
    if sign == -1:
        return ()
    if sign is None:
        conds |= {disc}
    root = constructed_sqrt(disc)
    ts = (-b / a,) if sign == 0 else ((-b + root) / a, (-b - root) / a)
    p = line.point
    return tuple(Point.canonical(p.x + t * d.x, p.y + t * d.y, conds) for t in ts)


def _radical_axis(c1: Circle, c2: Circle) -> Line:
    n = c2.center - c1.center
    if decide_zero(n.x) and decide_zero(n.y):
        raise DegenerateCircleError(
            f"concentric circles have no radical axis: {c1} and {c2}", c1, c2
        )
    h = (c1.radius2 - c2.radius2 + c2.center.dot(c2.center) - c1.center.dot(c1.center)) / 2
    return Line(n.scale(h / n.dot(n)), n.perp(), _merge(c1, c2))


def intersect_circles(c1: Circle, c2: Circle) -> tuple[Point, ...]:
    """Points common to two circles: 0, 1 (tangent) or 2 points.

    Branch order: the point to the left of the directed line from ``c1``'s
    centre to ``c2``'s centre comes first.

    Examples
    --------
    >>> intersect_circles(Circle(Point(0, 0), 1), Circle(Point(1, 0), 1))
    (Point(1/2, sqrt(3)/2), Point(1/2, -sqrt(3)/2))
    """
    return intersect_line_circle(_radical_axis(c1, c2), c1)


def second_intersection(c1: Circle, c2: Circle, known: Point) -> Point:
    """The other common point of two circles that both pass through ``known``.

    Rational in the data: the mirror image of ``known`` in the line of centres
    (no square root, no branch to choose).

    Raises
    ------
    NoIntersectionError
        If the circles are tangent at ``known`` (no second point).

    Examples
    --------
    >>> second_intersection(Circle(Point(1, 0), 1), Circle(Point(0, 1), 1), Point(0, 0))
    Point(1, 1)
    """

    def concentric() -> DegenerateCircleError:
        return DegenerateCircleError(
            f"concentric circles through one point coincide: {c1} and {c2}", c1, c2
        )

    def tangent() -> str:
        return f"circles {c1} and {c2} are tangent at {known}: there is no second common point"

    try:
        (cx, cy), (c2x, c2y), (kx0, ky0) = _fracs(c1.center, c2.center, known)
    except NotAFraction:
        return _second_intersection_sympy(c1, c2, known, concentric, tangent)
    wx, wy = (c2x - cx).reduced(), (c2y - cy).reduced()  # small: gcds taken once
    if wx.is_zero() and wy.is_zero():
        raise concentric()
    kx, ky = kx0 - cx, ky0 - cy
    side_f = wx * ky - wy * kx
    conds = _nonzero_frac(side_f, NoIntersectionError, tangent, c1, c2)
    # mirror image of `known` in the line of centres: known - 2 (side / |w|^2) perp(w),
    # reduced piece by piece (small gcds beat one large one)
    tf = (Frac.of(sp.Integer(2)) * side_f / (wx * wx + wy * wy)).reduced()
    return Point((kx0 + tf * wy).expr(), (ky0 - tf * wx).expr(), _merge(c1, c2, known) | conds)


def _second_intersection_sympy(
    c1: Circle,
    c2: Circle,
    known: Point,
    concentric: Callable[[], GeometryError],
    tangent: Callable[[], str],
) -> Point:
    """:func:`second_intersection` with sympy arithmetic (floats)."""
    c, w = c1.center, c2.center - c1.center
    if decide_zero(w.x) and decide_zero(w.y):
        raise concentric()
    k = Point(known.x - c.x, known.y - c.y)
    side = canon(w.x * k.y - w.y * k.x)
    conds = _nonzero(side, NoIntersectionError, tangent, c1, c2, scale=_size(w, k))
    t = canon(2 * side / canon(w.x**2 + w.y**2))
    return Point.canonical(known.x + t * w.y, known.y - t * w.x, _merge(c1, c2, known) | conds)


def intersection(a: Line | Circle, b: Line | Circle) -> tuple[Point, ...]:
    """All common points of two lines/circles, as a tuple (possibly empty).

    Unlike :func:`meet`, parallel lines give ``()`` instead of an error.
    Coincident lines or circles raise, since they share infinitely many points.

    Examples
    --------
    >>> intersection(Line(Point(0, 1), Point(1, 0)), Line(Point(0, 0), Point(1, 0)))
    ()
    """
    if isinstance(a, Line) and isinstance(b, Line):
        if decide_zero(a.direction.cross(b.direction)):
            if decide_zero((b.point - a.point).cross(a.direction)):
                raise ParallelLinesError(f"the lines coincide: {a} and {b}", a, b)
            return ()
        return (meet(a, b),)
    if isinstance(a, Line):
        return intersect_line_circle(a, b)  # type: ignore[arg-type]
    if isinstance(b, Line):
        return intersect_line_circle(b, a)
    return intersect_circles(a, b)
