"""The table of :data:`graspcompass.construction.operations.OPERATIONS` and its kernel functions.

One :class:`Row` per operation (the fields of
:class:`~graspcompass.construction.operations.Operation`), with the kernel functions
that are not a single call of the geometry package.  Private to
:mod:`graspcompass.construction.operations`, which makes the records.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

import sympy as sp

from .. import geometry as geo
from ..geometry import Circle, Line, NoIntersectionError, Point
from ..geometry.trig import sincos
from . import _ops_class as _cls


class Row(NamedTuple):
    """The fields of one :class:`~graspcompass.construction.operations.Operation`."""

    name: str
    function: Callable[..., Any]
    instrument: str
    inputs: tuple[str, ...]
    params: tuple[str, ...]
    makes: str
    caption: str
    ggb: str | None
    draws: str
    doc: str


# -- kernel functions that are not a single call of the geometry package --------------
def _point(x: sp.Expr, y: sp.Expr) -> Point:
    return Point.canonical(x, y)


def _line(p: Point, dx: sp.Expr, dy: sp.Expr) -> Line:
    return geo.line_with_direction(p, Point.canonical(dx, dy))


def _line_at_angle(p: Point, angle: sp.Expr) -> Line:
    s, c = sincos(angle)
    return geo.line_with_direction(p, Point.canonical(s, -c))


def _from_lengths(a: sp.Expr, b: sp.Expr, sx: sp.Expr, sy: sp.Expr) -> Point:
    return Point.canonical(sx * a, sy * b)


def _perpendicular(line: Line, p: Point) -> Line:
    return geo.perpendicular(line, p)


def _branch(points: tuple[Point, ...], branch: sp.Expr, what: str, *objs: object) -> Point:
    k = int(branch)
    if len(points) <= k:
        have = "no common point" if not points else "one common point (tangent)"
        raise NoIntersectionError(f"{what} have {have}, so there is no branch {k}", *objs)
    return points[k]


def _line_circle(line: Line, circle: Circle, branch: sp.Expr) -> Point:
    return _branch(
        geo.intersect_line_circle(line, circle),
        branch,
        f"the line {line} and the circle {circle}",
        line,
        circle,
    )


def _second_intersection(c1: Circle, c2: Circle, known: Point) -> Point:
    """:func:`graspcompass.geometry.second_intersection`, once ``known`` is on both circles.

    The kernel's mirror image of ``known`` in the line of centres is the second common
    point only when ``known`` is a common point: a point on neither circle would give a
    point on neither.  A point shown to be off a circle (exactly; floats to 1e-12 of the
    circle's size) is refused with :class:`~graspcompass.geometry.NoIntersectionError`;
    one with symbols is taken (the certifier of ``check`` decides it for all parameters).
    """
    from ..geometry.exact import Frac, NotAFraction

    for c in (c1, c2):
        values = (known.x, known.y, c.center.x, c.center.y, c.radius2)
        if any(v.free_symbols for v in values):
            continue
        try:
            kx, ky, cx, cy, r2 = (Frac.of(v) for v in values)
            if (((kx - cx) * (kx - cx) + (ky - cy) * (ky - cy)) - r2).is_zero():
                continue
        except NotAFraction:
            pass
        _cls.on_circle_check(known, c, "second_intersection (a common point of the circles)")
    return geo.second_intersection(c1, c2, known)


def _circles(c1: Circle, c2: Circle, branch: sp.Expr) -> Point:
    return _branch(geo.intersect_circles(c1, c2), branch, f"the circles {c1} and {c2}", c1, c2)


def _op(
    name: str,
    function: Callable[..., Any],
    instrument: str,
    inputs: str,
    params: str,
    makes: str,
    caption: str,
    ggb: str | None,
    draws: str,
    doc: str,
) -> Row:
    return Row(
        name,
        function,
        instrument,
        tuple(inputs.split()),
        tuple(params.split()),
        makes,
        caption,
        ggb,
        draws,
        doc,
    )


_PAPER: tuple[Row, ...] = (
    _op(
        "point",
        _point,
        "mark",
        "",
        "number number",
        "point",
        "{name}: a given point",
        "({p0}, {p1})",
        "point",
        "A given point (x, y), e.g. a contact P1 = (x1, y) of §2.2.1.",
    ),
    _op(
        "line_through",
        geo.line_through,
        "ruler",
        "point point",
        "",
        "line",
        "{name}: the line through {0} and {1}",
        "Line[{0}, {1}]",
        "line",
        "The line through two points, oriented from the first to the second.",
    ),
    _op(
        "line_with_direction",
        _line,
        "ruler",
        "point",
        "number number",
        "line",
        "{name}: the line through {0} along ({p0}, {p1})",
        "Line[{0}, {0} + ({p0}, {p1})]",
        "line",
        "The line through a point along a direction (dx, dy), e.g. a cone side.",
    ),
    _op(
        "line_at_angle",
        _line_at_angle,
        "ruler",
        "point",
        "angle",
        "line",
        "{name}: the line through {0} at an angle from the negative y-axis",
        "Line[{0}, {0} + (sin({p0}), -cos({p0}))]",
        "line",
        "The line through a point along e(a) = (sin a, -cos a) of eq. (26).",
    ),
    _op(
        "perpendicular",
        _perpendicular,
        "perpendicular",
        "line point",
        "",
        "line",
        "{name}: the perpendicular to {0} through {1}",
        "OrthogonalLine[{1}, {0}]",
        "line",
        "The perpendicular to a line through a point (§3.3 step (2)).",
    ),
    _op(
        "parallel",
        geo.parallel,
        "ruler",
        "line point",
        "",
        "line",
        "{name}: the parallel to {0} through {1}",
        "Line[{1}, {0}]",
        "line",
        "The parallel to a line through a point, with the same orientation.",
    ),
    _op(
        "foot",
        geo.foot,
        "perpendicular",
        "point line",
        "",
        "point",
        "{name}: the foot of the perpendicular from {0} to {1}",
        "ClosestPoint[{1}, {0}]",
        "point",
        "The foot of the perpendicular from a point to a line (P1x, P2x of §3.3).",
    ),
    _op(
        "midpoint",
        geo.midpoint,
        "compass",
        "point point",
        "",
        "point",
        "{name}: the midpoint of {0} and {1}",
        "Midpoint[{0}, {1}]",
        "point",
        "The midpoint of two points (O_M of §3.3).",
    ),
    _op(
        "meet",
        geo.meet,
        "ruler",
        "line line",
        "",
        "point",
        "{name}: where {0} meets {1}",
        "Intersect[{0}, {1}]",
        "point",
        "The one common point of two lines (X_n, Y_n of §3.3).",
    ),
    _op(
        "reflect",
        geo.reflect,
        "perpendicular",
        "point line",
        "",
        "point",
        "{name}: the mirror image of {0} in {1}",
        "Mirror[{0}, {1}]",
        "point",
        "The mirror image of a point in a line.",
    ),
    _op(
        "circle_through",
        geo.circle_through,
        "compass",
        "point point",
        "",
        "circle",
        "{name}: the circle with centre {0} through {1}",
        "Circle[{0}, {1}]",
        "circle",
        "The circle with a centre through a point.",
    ),
    _op(
        "circle_on_diameter",
        geo.circle_on_diameter,
        "compass",
        "point point",
        "",
        "circle",
        "{name}: the circle on the diameter {0}{1}",
        "Circle[Midpoint[{0}, {1}], {0}]",
        "circle",
        "The circle on a diameter: the polar graph of k_n, eq. (31)-(32), Fig. 3.",
    ),
    _op(
        "intersect_line_circle",
        _line_circle,
        "mark",
        "line circle",
        "branch",
        "point",
        "{name}: where {0} crosses {1} (branch {p0})",
        None,
        "point",
        "A common point of a line and a circle; branch 0 lies further along the line.",
    ),
    _op(
        "intersect_circles",
        _circles,
        "mark",
        "circle circle",
        "branch",
        "point",
        "{name}: where {0} crosses {1} (branch {p0})",
        None,
        "point",
        "A common point of two circles; branch 0 lies left of the line of centres.",
    ),
    _op(
        "second_intersection",
        _second_intersection,
        "mark",
        "circle circle point",
        "",
        "point",
        "{name}: the second common point of {0} and {1} (besides {2})",
        "Mirror[{2}, Line[Center[{0}], Center[{1}]]]",
        "point",
        "The other common point of two circles through a known one (break points, §3.3).",
    ),
    _op(
        "signed_length",
        geo.signed_length,
        "compass",
        "point point line",
        "",
        "number",
        "{name}: the signed length {0}{1} along {2}",
        "Vector[{0}, {1}] * UnitVector[{2}]",
        "length",
        "The directed length from a point to a point along a line (O_M X_n, O Y_n).",
    ),
    _op(
        "point_from_lengths",
        _from_lengths,
        "compass",
        "number number",
        "number number",
        "point",
        "{name}: the point ({p0}·{0}, {p1}·{1})",
        "({p0} * {0}, {p1} * {1})",
        "point",
        "The point (sx·a, sy·b) from two lengths: V_n = (−O_M X_n, −O Y_n), eq. (30)/(33).",
    ),
    # -- a geometry class's operations (issue 24) -----------------------------------------
    _op(
        "point_on_line",
        _cls.point_on_line,
        "mark",
        "line",
        "number",
        "point",
        "{name}: a point of {0} (parameter {p0})",
        None,
        "point",
        "The point P + t·d of a line through P along d: a free point of the line.",
    ),
    _op(
        "point_on_circle",
        _cls.point_on_circle,
        "mark",
        "circle point",
        "number",
        "point",
        "{name}: a point of {0} ({1} turned by 2 atan {p0})",
        None,
        "point",
        "A point of a circle: its point A turned about the centre by θ, tan(θ/2) = t.",
    ),
    _op(
        "circumcircle",
        _cls.circumcircle,
        "compass",
        "point point point",
        "",
        "circle",
        "{name}: the circle through {0}, {1} and {2}",
        "Circle[{0}, {1}, {2}]",
        "circle",
        "The circle through three points that are not collinear.",
    ),
    _op(
        "circle_radius",
        _cls.circle_radius,
        "compass",
        "point",
        "number",
        "circle",
        "{name}: the circle about {0} with radius {p0}",
        "Circle[{0}, {p0}]",
        "circle",
        "The circle with a centre and a radius r ≠ 0.",
    ),
    _op(
        "circle_compass",
        _cls.circle_compass,
        "compass",
        "point point point",
        "",
        "circle",
        "{name}: the circle about {0} with radius {1}{2}",
        "Circle[{0}, Segment[{1}, {2}]]",
        "circle",
        "The circle about a centre with the radius of a segment AB (Euclid I.2).",
    ),
    _op(
        "bisector",
        _cls.bisector,
        "ruler",
        "point point point",
        "",
        "line",
        "{name}: the bisector of the angle {0}{1}{2}",
        "AngularBisector[{0}, {1}, {2}]",
        "line",
        "The internal bisector of the angle ABC, through B.",
    ),
    _op(
        "tangent_at",
        _cls.tangent_at,
        "ruler",
        "circle point",
        "",
        "line",
        "{name}: the tangent to {0} at {1}",
        "OrthogonalLine[{1}, Line[Center[{0}], {1}]]",
        "line",
        "The tangent to a circle at its point: perpendicular to the radius.",
    ),
    _op(
        "tangent_point",
        _cls.tangent_point,
        "mark",
        "point circle",
        "branch",
        "point",
        "{name}: the point of contact of a tangent from {0} to {1} (branch {p0})",
        None,
        "point",
        "Where a tangent from an outside point touches a circle; branch 0 lies "
        "left of the ray from the centre to the point.",
    ),
    _op(
        "rotate",
        _cls.rotate,
        "compass",
        "point point",
        "angle",
        "point",
        "{name}: {0} turned about {1} by {p0}",
        "Rotate[{0}, {p0}, {1}]",
        "point",
        "A point turned about a centre by an angle (radians, counter-clockwise).",
    ),
    _op(
        "homothety",
        _cls.homothety,
        "ruler",
        "point point",
        "number",
        "point",
        "{name}: the image of {0} by the homothety of centre {1}, ratio {p0}",
        "Dilate[{0}, {p0}, {1}]",
        "point",
        "C + k(P − C): the homothety of centre C, ratio k.",
    ),
    _op(
        "point_reflect",
        _cls.point_reflect,
        "compass",
        "point point",
        "",
        "point",
        "{name}: the reflection of {0} in the point {1}",
        "Mirror[{0}, {1}]",
        "point",
        "2C − P: the reflection in a point (a half turn about it).",
    ),
    _op(
        "radical_axis",
        _cls.radical_axis,
        "ruler",
        "circle circle",
        "",
        "line",
        "{name}: the radical axis of {0} and {1}",
        "RadicalAxis[{0}, {1}]",
        "line",
        "The points of equal power with respect to two circles with distinct centres.",
    ),
)


# -- issue 25: the vertex construction for n contacts (docs/ncontact.md) -----------------
def _quarter_turn(p: Point, centre: Point) -> Point:
    """``p`` turned a quarter turn clockwise about ``centre``: (x, y) -> (y, -x) about it."""
    dx, dy = p.x - centre.x, p.y - centre.y
    return Point.canonical(centre.x + dy, centre.y - dx)


def _parallel_to_points(a: Point, b: Point, p: Point) -> Line:
    """The parallel through ``p`` to the line from ``a`` to ``b`` (same orientation)."""
    return geo.parallel(geo.line_through(a, b), p)


_NCONTACT: tuple[Row, ...] = (
    _op(
        "parallel_to_points",
        _parallel_to_points,
        "ruler",
        "point point point",
        "",
        "line",
        "{name}: the parallel to {0}{1} through {2}",
        "Line[{2}, Vector[{0}, {1}]]",
        "line",
        "The parallel through a point to the line through two points (two set squares; "
        "the vertex recipe's transfer of p_i p_k and p_i O, docs/ncontact.md).",
    ),
    _op(
        "quarter_turn",
        _quarter_turn,
        "compass",
        "point point",
        "",
        "point",
        "{name}: {0} turned a quarter turn clockwise about {1}",
        "Rotate[{0}, -90°, {1}]",
        "point",
        "A point turned a quarter turn clockwise about a centre (set square and "
        "compass): the vertex q = J^T R of the n-contact recipe (docs/ncontact.md).",
    ),
)
#: Every operation's fields, in the order of the language reference.
ROWS = _PAPER + _NCONTACT
