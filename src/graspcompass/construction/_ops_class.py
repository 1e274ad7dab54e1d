"""Kernel functions of the operations a geometry class needs beyond the paper's (issue 24).

A point on a line or on a circle with a parameter, the circle through three points,
the circle by centre and radius or by centre and a segment (Euclid's compass), the
internal angle bisector, the tangent at a point and the point of contact of a tangent
from a point, the rotation, the homothety, the reflection in a point and the radical
axis.  Each is exact: rational in its inputs except where a length is a square root
(the bisector, whose unit vectors are ``u/√(u·u)``) or an intersection with a circle
(the point of contact, branch 0 or 1 as the kernel's line-circle intersection).
Their records (instrument, caption, GeoGebra command, drawing) are in
:data:`graspcompass.construction.operations.OPERATIONS`; their non-degeneracy
conditions, worded geometrically, in
:func:`graspcompass.proof.program_conditions.operation_conditions`.

Examples
--------
>>> from graspcompass.geometry import Point, Line
>>> circumcircle(Point(0, 0), Point(2, 0), Point(0, 2))
Circle(Point(1, 1), radius2=2)
>>> rotate(Point(1, 0), Point(0, 0), sp.pi / 2)
Point(0, 1)
>>> point_on_line(Line(Point(1, 1), Point(2, 0)), sp.Rational(1, 2))
Point(2, 1)
"""

from __future__ import annotations

import sympy as sp

from ..geometry import (
    Circle,
    CoincidentPointsError,
    DegenerateCircleError,
    Line,
    NoIntersectionError,
    Point,
)
from ..geometry import constructive as _k
from ..geometry.exact import canon, decide_zero, has_float
from ..geometry.roots import constructed_sqrt
from ..geometry.trig import sincos

__all__ = [
    "bisector",
    "circle_compass",
    "circle_radius",
    "circumcircle",
    "homothety",
    "on_circle_check",
    "point_on_circle",
    "point_on_line",
    "point_reflect",
    "radical_axis",
    "rotate",
    "tangent_at",
    "tangent_point",
]


def _conds(*objs: object) -> frozenset:
    out: frozenset = frozenset()
    for o in objs:
        out |= getattr(o, "conditions", frozenset())
    return out


def point_on_line(line: Line, t: sp.Expr) -> Point:
    """The point ``P + t·d`` of the line through P along d (t = 0 is the line's point)."""
    p, d = line.point, line.direction
    return Point.canonical(p.x + t * d.x, p.y + t * d.y, _conds(line))


def on_circle_check(known: Point, c: Circle, what: str) -> None:
    """Refuse a point shown off the circle (exactly, or to 1e-12 of its size for floats).

    A point with symbols whose power is not decided is taken: the checker proves it
    (its power is a condition of the step, ``== 0``).
    """
    power = canon((known.x - c.center.x) ** 2 + (known.y - c.center.y) ** 2 - c.radius2)
    scale = 0.0
    if has_float(power):
        scale = abs(float(c.radius2)) + float(c.center.x) ** 2 + float(c.center.y) ** 2
    if decide_zero(power, scale) is False:
        raise NoIntersectionError(
            f"{known} is not on the circle {c}: {what} needs a point of the circle", known, c
        )


def _turn(p: Point, centre: Point, s: sp.Expr, c: sp.Expr, conds: frozenset) -> Point:
    u = p - centre
    return Point.canonical(centre.x + c * u.x - s * u.y, centre.y + s * u.x + c * u.y, conds)


def point_on_circle(circle: Circle, known: Point, t: sp.Expr) -> Point:
    """``known`` (a point of the circle) turned about the centre by the angle θ with
    tan(θ/2) = t: cos θ = (1 − t²)/(1 + t²), sin θ = 2t/(1 + t²), rational in t; every
    point of the circle but the antipode of ``known`` (t → ∞)."""
    on_circle_check(known, circle, "point_on_circle")
    w = 1 + t * t
    return _turn(known, circle.center, 2 * t / w, (1 - t * t) / w, _conds(circle, known))


def circumcircle(a: Point, b: Point, c: Point) -> Circle:
    """The circle through three points that are not collinear.

    With u = B − A, v = C − A and D = 2 (u × v) ≠ 0 the centre is
    A + ((v_y |u|² − u_y |v|²)/D, (u_x |v|² − v_x |u|²)/D).
    """
    u, v = b - a, c - a
    d = 2 * u.cross(v)
    conds = _k._nonzero(
        d,
        DegenerateCircleError,
        lambda: f"{a}, {b} and {c} are collinear: no circle passes through them",
        a,
        b,
        c,
        scale=_k._size(u, v),
    )
    uu, vv = u.dot(u), v.dot(v)
    centre = Point.canonical(
        a.x + (v.y * uu - u.y * vv) / d, a.y + (u.x * vv - v.x * uu) / d, _conds(a, b, c) | conds
    )
    w = centre - a
    return Circle(centre, canon(w.x**2 + w.y**2), conds)


def circle_radius(centre: Point, r: sp.Expr) -> Circle:
    """The circle with a centre and a radius r ≠ 0 (squared radius r²)."""
    return Circle(centre, canon(r * r))


def circle_compass(centre: Point, a: Point, b: Point) -> Circle:
    """The circle about ``centre`` with the radius |AB| (Euclid I.2's compass)."""
    d = b - a
    return Circle(centre, canon(d.x**2 + d.y**2), _conds(a, b))


def bisector(a: Point, b: Point, c: Point) -> Line:
    """The internal bisector of the angle ABC: through B along u/|u| + v/|v| (u = A − B,
    v = C − B), written u·|v| + v·|u| with |u| = √(u·u) > 0."""
    u, v = a - b, c - b
    for w, other in ((u, a), (v, c)):
        if decide_zero(w.x) and decide_zero(w.y):
            raise CoincidentPointsError(f"an angle needs arms: {other} is its vertex {b}", other, b)
    lu, lv = constructed_sqrt(canon(u.dot(u))), constructed_sqrt(canon(v.dot(v)))
    d = Point.canonical(u.x * lv + v.x * lu, u.y * lv + v.y * lu)
    return Line(b, d, _conds(a, b, c))


def tangent_at(circle: Circle, p: Point) -> Line:
    """The tangent to a circle at its point ``p``: through p, perpendicular to the radius
    (its direction is the radius turned a quarter turn counter-clockwise)."""
    on_circle_check(p, circle, "tangent_at")
    r = p - circle.center
    return Line(p, Point.canonical(-r.y, r.x), _conds(circle, p))


def polar(p: Point, circle: Circle) -> Line:
    """The polar of ``p``: the line {X : (X − O)·(P − O) = r²}, along (P − O) turned a
    quarter turn counter-clockwise; it holds the points of contact of the tangents."""
    n = p - circle.center
    nn = canon(n.dot(n))
    zero = decide_zero(nn)
    if zero:
        raise DegenerateCircleError(
            f"the centre {p} of the circle has no tangent through it", p, circle
        )
    k = circle.radius2 / nn
    return Line(
        Point.canonical(circle.center.x + k * n.x, circle.center.y + k * n.y),
        Point.canonical(-n.y, n.x),
        _conds(p, circle) | ({nn} if zero is None else frozenset()),
    )


def tangent_point(p: Point, circle: Circle, branch: sp.Expr) -> Point:
    """The point of contact of a tangent from ``p`` to the circle: a common point of the
    circle and the polar of p (branch 0 lies left of the ray from the centre to p)."""
    pts = _k.intersect_line_circle(polar(p, circle), circle)
    k = int(branch)
    if len(pts) <= k:
        raise NoIntersectionError(
            f"{p} is inside the circle {circle}: no tangent through it"
            if not pts
            else f"{p} is on the circle {circle}: one tangent, no branch {k}",
            p,
            circle,
        )
    return pts[k]


def rotate(p: Point, centre: Point, angle: sp.Expr) -> Point:
    """``p`` turned about ``centre`` by ``angle`` (radians, counter-clockwise; exact sine
    and cosine of multiples of π/12, :func:`graspcompass.geometry.trig.sincos`)."""
    s, c = sincos(sp.sympify(angle))
    return _turn(p, centre, s, c, _conds(p, centre))


def homothety(p: Point, centre: Point, k: sp.Expr) -> Point:
    """The image of ``p`` by the homothety of ``centre`` and ratio k: C + k (P − C)."""
    return Point.canonical(
        centre.x + k * (p.x - centre.x), centre.y + k * (p.y - centre.y), _conds(p, centre)
    )


def point_reflect(p: Point, centre: Point) -> Point:
    """The reflection of ``p`` in the point ``centre``: 2C − P (a half turn)."""
    return Point.canonical(2 * centre.x - p.x, 2 * centre.y - p.y, _conds(p, centre))


def radical_axis(c1: Circle, c2: Circle) -> Line:
    """The radical axis of two circles with distinct centres: the points of equal power,
    perpendicular to the line of centres (through the common points where they meet)."""
    return _k._radical_axis(c1, c2)
