"""Tests of graspcompass.geometry: the exact ruler-and-compass kernel.

Every expected value is derived inside the test from first principles (cross and
dot products, the equation of a circle, the discriminant of a quadratic, the
Pythagorean parametrisation of rational points on a circle), never copied from
the output of the code under test.  Property tests draw rational coordinates, so
every check is exact; radical data are checked with ``expand``/``radsimp``.
"""

from __future__ import annotations

import dataclasses
import math
from fractions import Fraction

import pytest
import sympy
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graspcompass.geometry import (
    ORIGIN,
    Circle,
    CoincidentPointsError,
    DegenerateCircleError,
    GeometryError,
    Line,
    NoIntersectionError,
    ParallelLinesError,
    Point,
    Ray,
    Segment,
    ZeroDirectionError,
    angle_of,
    are_parallel,
    are_perpendicular,
    canon,
    circle_on_diameter,
    circle_through,
    decide_sign,
    decide_zero,
    distance,
    distance2,
    evaluate,
    foot,
    intersect_circles,
    intersect_line_circle,
    intersection,
    is_on,
    line_through,
    line_with_direction,
    meet,
    midpoint,
    parallel,
    perpendicular,
    reflect,
    same_line,
    same_point,
    second_intersection,
    signed_length,
)

R = sympy.Rational
sqrt = sympy.sqrt
pi = sympy.pi
a, b = sympy.symbols("a b")

# Property tests stay small: the whole file must run in well under 30 s.
FAST = settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
SLOW = settings(
    max_examples=12,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)


# --------------------------------------------------------------------------- helpers


def _rational(f: Fraction) -> sympy.Rational:
    return R(f.numerator, f.denominator)


rationals = st.fractions(min_value=-8, max_value=8, max_denominator=9).map(_rational)
small_rationals = st.fractions(min_value=-3, max_value=3, max_denominator=5).map(_rational)
positive_rationals = st.fractions(min_value=Fraction(1, 4), max_value=6, max_denominator=7).map(
    _rational
)
points = st.builds(Point, rationals, rationals)
vectors = st.tuples(rationals, rationals).filter(lambda v: v != (0, 0)).map(lambda v: Point(*v))


def cross(u: tuple, v: tuple) -> sympy.Expr:
    """2D cross product written out in the test (not the kernel's)."""
    return u[0] * v[1] - u[1] * v[0]


def dot(u: tuple, v: tuple) -> sympy.Expr:
    return u[0] * v[0] + u[1] * v[1]


def sub(p: Point, q: Point) -> tuple:
    return (p.x - q.x, p.y - q.y)


_A, _B, _R = sympy.symbols("a b r")


def is_zero(expr: sympy.Expr) -> bool:
    """Exact zero test, independent of the kernel.

    The numbers of these tests lie in Q(√2, √3, √D), D in Q(√2, √3): √2, √3, √6 become
    a, b, ab, the nested root r, and the numerator of the expression is reduced modulo
    the triangular (Gröbner) basis r² − D(a, b), b² − 3, a² − 2.  A zero remainder
    means zero; a non-zero one means non-zero when the tower has degree 8 (D not a
    square in Q(√2, √3), where the test would fail, never pass, wrongly).  Other radicals
    fall back to sympy's radsimp.
    """
    expr = sympy.expand(sympy.sympify(expr))
    if expr == 0:
        return True
    roots = {p for p in expr.atoms(sympy.Pow) if p.exp == sympy.S.Half}
    simple = {sympy.sqrt(2): _A, sympy.sqrt(3): _B, sympy.sqrt(6): _A * _B}
    nested = [p for p in roots if not p.base.is_Rational]
    if len(nested) > 1 or any(p.base.is_Rational and p not in simple for p in roots):
        return sympy.expand(sympy.radsimp(expr)) == 0
    rep = dict(simple)
    basis = [_B**2 - 3, _A**2 - 2]
    if nested:
        rep = {nested[0]: _R, **simple}
        basis.insert(0, _R**2 - sympy.expand(nested[0].base.xreplace(simple)))
    poly = expr.xreplace(rep)
    if any(not p.exp.is_Integer for p in poly.atoms(sympy.Pow)):
        return sympy.expand(sympy.radsimp(expr)) == 0
    num = sympy.together(poly).as_numer_denom()[0]
    _, rem = sympy.reduced(sympy.expand(num), basis, _R, _B, _A, order="lex")
    return rem == 0


def test_is_zero_tells_zero_from_almost_zero() -> None:
    d = 5 - sympy.sqrt(2) + 3 * sympy.sqrt(6)
    r = (1 + sympy.sqrt(3) * sympy.sqrt(d)) / (2 - sympy.sqrt(2))
    assert is_zero(r * r - sympy.expand(r**2))
    assert is_zero((r - 1) * (r + 1) - r**2 + 1)
    assert not is_zero(r * r - sympy.expand(r**2) + sympy.Rational(1, 10**40))
    assert not is_zero(sympy.sqrt(d) * sympy.sqrt(2) - sympy.sqrt(2 * d) + sympy.sqrt(3) - 1)


def on_line(p: Point, line: Line) -> bool:
    return is_zero(cross(sub(p, line.point), (line.direction.x, line.direction.y)))


def on_circle(p: Point, c: Circle) -> bool:
    return is_zero((p.x - c.center.x) ** 2 + (p.y - c.center.y) ** 2 - c.radius2)


def sign_of(expr: sympy.Expr) -> int:
    """Sign of an exact number: rationals directly, radicals at 50 digits."""
    expr = sympy.nsimplify(expr) if expr.is_Float else expr
    if expr.is_Rational:
        return int(bool(expr > 0)) - int(bool(expr < 0))
    v = sympy.N(expr, 50)
    assert abs(v) > sympy.Float(10) ** -30, f"sign of {expr} too close to 0 to trust"
    return 1 if v > 0 else -1


def line_circle_discriminant(line: Line, c: Circle) -> sympy.Expr:
    """Quarter discriminant of |P + t d - C|² = r² as a quadratic in t."""
    d = (line.direction.x, line.direction.y)
    w = sub(line.point, c.center)
    return dot(d, w) ** 2 - dot(d, d) * (dot(w, w) - c.radius2)


def circles_discriminant(c1: Circle, c2: Circle) -> sympy.Expr:
    """4 D² R1 − (D² + R1 − R2)² (D = distance of centres, R = squared radii).

    Positive: two common points, zero: tangent, negative: none (D > 0).
    """
    D2 = dot(sub(c2.center, c1.center), sub(c2.center, c1.center))
    return 4 * D2 * c1.radius2 - (D2 + c1.radius2 - c2.radius2) ** 2


def on_unit_circle(t: sympy.Rational) -> tuple:
    """Rational point on the unit circle, ((1 − t²)/(1 + t²), 2t/(1 + t²))."""
    return ((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))


def no_float(*objs: object) -> bool:
    exprs: list = []
    for o in objs:
        if isinstance(o, Point):
            exprs += [o.x, o.y]
        elif isinstance(o, Line):
            exprs += [o.point.x, o.point.y, o.direction.x, o.direction.y]
        elif isinstance(o, Circle):
            exprs += [o.center.x, o.center.y, o.radius2]
        else:
            exprs.append(sympy.sympify(o))
    return all(not e.atoms(sympy.Float) for e in exprs)


# --------------------------------------------------------------------------- values


@pytest.mark.parametrize(
    ("obj", "field"),
    [
        (Point(1, 2), "x"),
        (Line(Point(0, 0), Point(1, 0)), "direction"),
        (Circle(Point(0, 0), 1), "radius2"),
        (Segment(Point(0, 0), Point(1, 0)), "end"),
        (Ray(Point(0, 0), Point(1, 0)), "origin"),
    ],
)
def test_values_are_frozen(obj, field):
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(obj, field, 5)
    with pytest.raises(dataclasses.FrozenInstanceError):
        obj.conditions = frozenset() if hasattr(obj, "conditions") else None  # type: ignore[misc]


@FAST
@given(rationals, rationals, rationals, rationals)
def test_points_equal_iff_coordinates_equal(x1, y1, x2, y2):
    p, q = Point(x1, y1), Point(x2, y2)
    assert (p == q) == (x1 == x2 and y1 == y2)
    if p == q:
        assert hash(p) == hash(q)
        assert len({p, q}) == 1
    assert Point(x1, y1) == p and hash(Point(x1, y1)) == hash(p)


def test_values_are_hashable_and_usable_as_keys():
    objs = [
        Point(sqrt(3) / 2, R(1, 2)),
        Line(Point(0, 0), Point(1, 1)),
        Circle(Point(1, 0), 2),
        Segment(Point(0, 0), Point(1, 0)),
        Ray(Point(0, 0), Point(0, 1)),
    ]
    table = {o: i for i, o in enumerate(objs)}
    for i, o in enumerate(objs):
        twin = dataclasses.replace(o)
        assert twin == o and hash(twin) == hash(o)
        assert table[twin] == i


def test_conditions_take_no_part_in_equality():
    p = Point(1, 2, frozenset({a}))
    assert p == Point(1, 2) and hash(p) == hash(Point(1, 2))
    assert p.conditions == frozenset({a})


def test_python_numbers_become_sympy_numbers():
    p = Point(1, 2)
    assert isinstance(p.x, sympy.Integer) and isinstance(p.y, sympy.Integer)
    assert Point(Fraction(1, 3), 0).x == R(1, 3)
    assert isinstance(Point(0.5, 0).x, sympy.Float)
    from graspcompass.errors import WrongTypeError

    with pytest.raises(WrongTypeError):  # issue 22: a named error, no longer a TypeError
        Point(True, 0)


def test_strings_are_read_exactly():
    assert Point("sqrt(3)/2", "1/2") == Point(sqrt(3) / 2, R(1, 2))
    assert Point("1.2", "0.1").x == R(6, 5)
    assert Point("1.2", "0.1") == Point(R(6, 5), R(1, 10))
    assert Circle(Point(0, 0), "1.2").radius2 == R(6, 5)
    assert Point("1.2", 0).is_exact


def test_constructors_keep_their_type():
    p, q, r = Point(0, 0), Point(2, 0), Point(1, 3)
    lpq = line_through(p, q)
    for obj in (
        lpq,
        line_with_direction(p, Point(1, 1)),
        parallel(lpq, r),
        perpendicular(lpq, r),
        Segment(p, q).line,
        Ray(p, q).line,
    ):
        assert type(obj) is Line
    for obj in (circle_on_diameter(p, q), circle_through(r, p)):
        assert type(obj) is Circle
    for obj in (
        meet(lpq, perpendicular(lpq, r)),
        foot(r, lpq),
        reflect(r, lpq),
        midpoint(p, q),
        p + q,
        q - p,
        -q,
        q.scale(3),
        q.perp(),
        lpq.at(2),
        Point.canonical(1, 2),
    ):
        assert type(obj) is Point
    pts = intersect_circles(Circle(p, 4), Circle(q, 4))
    assert isinstance(pts, tuple) and all(type(x) is Point for x in pts)
    assert ORIGIN == Point(0, 0)


def test_line_circle_accessors():
    line = Line(Point(1, 2), Point(3, -1))
    A, B, C = line.coefficients()
    for t in (0, 1, R(-5, 2)):
        pt = line.at(t)
        assert A * pt.x + B * pt.y + C == 0
    assert dot((line.normal.x, line.normal.y), (3, -1)) == 0
    assert Circle(Point(0, 0), 9).radius == 3
    assert Circle(Point(0, 0), 2).radius == sqrt(2)


# --------------------------------------------------------------------------- lines


@FAST
@given(points, vectors, points, vectors)
def test_meet_lies_on_both_lines(p1, d1, p2, d2):
    assume(cross((d1.x, d1.y), (d2.x, d2.y)) != 0)
    l1, l2 = Line(p1, d1), Line(p2, d2)
    m = meet(l1, l2)
    assert cross(sub(m, p1), (d1.x, d1.y)) == 0
    assert cross(sub(m, p2), (d2.x, d2.y)) == 0
    assert m.is_exact and m.conditions == frozenset()
    assert meet(l2, l1) == m


@FAST
@given(points, points, vectors)
def test_foot_is_on_the_line_and_perpendicular(p, q, d):
    line = Line(q, d)
    f = foot(p, line)
    assert cross(sub(f, q), (d.x, d.y)) == 0
    assert dot(sub(p, f), (d.x, d.y)) == 0


@FAST
@given(points, points, vectors)
def test_reflect_is_an_involution(p, q, d):
    line = Line(q, d)
    r = reflect(p, line)
    assert reflect(r, line) == p
    # the mirror line is the perpendicular bisector of p r (when p is off the line)
    mx, my = (p.x + r.x) / 2, (p.y + r.y) / 2
    assert cross((mx - q.x, my - q.y), (d.x, d.y)) == 0
    assert dot(sub(r, p), (d.x, d.y)) == 0


@FAST
@given(points, points)
def test_midpoint_is_equidistant(p, q):
    m = midpoint(p, q)
    d_pm = (m.x - p.x) ** 2 + (m.y - p.y) ** 2
    d_qm = (m.x - q.x) ** 2 + (m.y - q.y) ** 2
    assert d_pm == d_qm
    assert 4 * d_pm == (q.x - p.x) ** 2 + (q.y - p.y) ** 2
    assert distance2(p, m) == d_pm


@FAST
@given(points, points)
def test_circle_on_diameter(p, q):
    assume(p != q)
    c = circle_on_diameter(p, q)
    assert c.center == Point((p.x + q.x) / 2, (p.y + q.y) / 2)
    assert on_circle(p, c) and on_circle(q, c)
    assert 4 * c.radius2 == (q.x - p.x) ** 2 + (q.y - p.y) ** 2


@FAST
@given(points, vectors, points)
def test_parallel_and_perpendicular(p, d, r):
    line = Line(p, d)
    par, per = parallel(line, r), perpendicular(line, r)
    assert par.point == r and per.point == r
    assert cross((par.direction.x, par.direction.y), (d.x, d.y)) == 0
    assert dot((per.direction.x, per.direction.y), (d.x, d.y)) == 0
    assert are_parallel(line, par) is True
    assert are_perpendicular(line, per) is True
    assert are_perpendicular(line, par) is False


def test_line_through_is_oriented_from_p_to_q():
    line = line_through(Point(1, 1), Point(4, 5))
    assert line.point == Point(1, 1)
    assert line.direction == Point(3, 4)


def test_predicates():
    line = Line(Point(0, 0), Point(2, 2))
    assert is_on(Point(5, 5), line) is True
    assert is_on(Point(5, 4), line) is False
    assert is_on(Point(3, 4), Circle(Point(0, 0), 25)) is True
    assert is_on(Point(3, 5), Circle(Point(0, 0), 25)) is False
    assert same_line(line, Line(Point(-1, -1), Point(-3, -3))) is True
    assert same_line(line, Line(Point(-1, 0), Point(-3, -3))) is False
    assert same_point(Point(sqrt(2) * sqrt(3), 0), Point(sqrt(6), 0)) is True
    assert same_point(Point(sqrt(2), 0), Point(R(141421, 100000), 0)) is False
    assert same_point(Point(a, 0), Point(0, 0)) is None


# --------------------------------------------------------------------------- circles


@FAST
@given(points, vectors, points, positive_rationals)
def test_line_circle_count_matches_discriminant(p, d, centre, r2):
    line, c = Line(p, d), Circle(centre, r2)
    pts = intersect_line_circle(line, c)
    assert len(pts) == {-1: 0, 0: 1, 1: 2}[sign_of(line_circle_discriminant(line, c))]
    for x in pts:
        assert on_line(x, line) and on_circle(x, c)
        assert no_float(x)
    if len(pts) == 2:
        assert pts[0] != pts[1]
        # branch order: the point further along the line's direction first
        assert sign_of(dot(sub(pts[0], pts[1]), (d.x, d.y))) == 1
    assert intersect_line_circle(line, c) == pts  # deterministic
    assert intersection(line, c) == pts and intersection(c, line) == pts


@FAST
@given(points, positive_rationals, small_rationals, small_rationals)
def test_line_circle_rational_chord(centre, r, t1, t2):
    """Pythagorean points: a chord of a rational circle meets it in rational points."""
    assume(t1 != t2)
    u1, u2 = on_unit_circle(t1), on_unit_circle(t2)
    A = Point(centre.x + r * u1[0], centre.y + r * u1[1])
    B = Point(centre.x + r * u2[0], centre.y + r * u2[1])
    assume(A != B)
    c = Circle(centre, r**2)
    pts = intersect_line_circle(line_through(A, B), c)
    assert len(pts) == 2
    assert all(x.x.is_Rational and x.y.is_Rational for x in pts)  # no sqrt left
    assert pts == (B, A)  # B is further along A -> B


@FAST
@given(points, positive_rationals, small_rationals, small_rationals, small_rationals)
def test_circles_rational_common_chord(A, t, s1, s2, k):
    """Centres on the perpendicular bisector of a rational chord AB."""
    assume(s1 != s2)
    B = Point(A.x + t, A.y + k)
    M = ((A.x + B.x) / 2, (A.y + B.y) / 2)
    nrm = (-(B.y - A.y), B.x - A.x)  # left normal of A -> B
    c1 = circle_through(Point(M[0] + s1 * nrm[0], M[1] + s1 * nrm[1]), A)
    c2 = circle_through(Point(M[0] + s2 * nrm[0], M[1] + s2 * nrm[1]), A)
    pts = intersect_circles(c1, c2)
    assert set(pts) == {A, B}
    assert len(pts) == 2
    # branch order: first the point left of the directed line c1 -> c2
    axis = sub(c2.center, c1.center)
    assert cross(axis, sub(pts[0], c1.center)) > 0
    assert cross(axis, sub(pts[1], c1.center)) < 0


@FAST
@given(points, positive_rationals, points, positive_rationals)
def test_circles_count_matches_discriminant(c1c, r1, c2c, r2):
    assume(c1c != c2c)
    c1, c2 = Circle(c1c, r1), Circle(c2c, r2)
    pts = intersect_circles(c1, c2)
    assert len(pts) == {-1: 0, 0: 1, 1: 2}[sign_of(circles_discriminant(c1, c2))]
    for x in pts:
        assert on_circle(x, c1) and on_circle(x, c2)
        assert no_float(x)
    if len(pts) == 2:
        axis = sub(c2c, c1c)
        assert sign_of(cross(axis, sub(pts[0], c1c))) == 1
        assert sign_of(cross(axis, sub(pts[1], c1c))) == -1
    assert intersect_circles(c1, c2) == pts
    assert intersection(c1, c2) == pts


@SLOW
@given(st.lists(small_rationals, min_size=8, max_size=8))
def test_intersections_with_radical_data(q):
    s2, s3 = sqrt(2), sqrt(3)
    c1 = Circle(Point(q[0] + q[1] * s2, q[2]), 4 + q[3] ** 2)
    c2 = Circle(Point(q[4], q[5] * s3 + 1), 3 + q[6] ** 2 + s2)
    assume(not (c1.center.x == c2.center.x and c1.center.y == c2.center.y))
    pts = intersect_circles(c1, c2)
    assert len(pts) == {-1: 0, 0: 1, 1: 2}[sign_of(circles_discriminant(c1, c2))]
    for x in pts:
        assert on_circle(x, c1) and on_circle(x, c2)
        assert no_float(x)
    line = Line(Point(q[0] * s3, q[7]), Point(1 + q[1], s2))
    lpts = intersect_line_circle(line, c1)
    assert len(lpts) == {-1: 0, 0: 1, 1: 2}[sign_of(line_circle_discriminant(line, c1))]
    for x in lpts:
        assert on_line(x, line) and on_circle(x, c1)
        assert no_float(x)


@FAST
@given(points, positive_rationals, small_rationals)
def test_tangent_line_gives_one_point(centre, r, t):
    u = on_unit_circle(t)
    touch = Point(centre.x + r * u[0], centre.y + r * u[1])
    tangent = Line(touch, Point(-u[1], u[0]))
    pts = intersect_line_circle(tangent, Circle(centre, r**2))
    assert pts == (touch,)


@FAST
@given(points, positive_rationals, positive_rationals, small_rationals, st.booleans())
def test_tangent_circles_give_one_point(centre, r1, r2, t, internal):
    assume(not internal or r1 != r2)
    u = on_unit_circle(t)
    dist = abs(r1 - r2) if internal else r1 + r2
    c2c = Point(centre.x + dist * u[0], centre.y + dist * u[1])
    touch = (
        Point(centre.x + r1 * u[0], centre.y + r1 * u[1])
        if r1 >= r2 or not internal
        else Point(centre.x - r1 * u[0], centre.y - r1 * u[1])
    )
    pts = intersect_circles(Circle(centre, r1**2), Circle(c2c, r2**2))
    assert pts == (touch,)


def test_tangent_with_radicals():
    c = Circle(Point(sqrt(2), 1), 3)
    tangent = Line(Point(sqrt(2) + sqrt(3), 0), Point(0, 1))  # x = sqrt(2) + sqrt(3)
    assert intersect_line_circle(tangent, c) == (Point(sqrt(2) + sqrt(3), 1),)
    c2 = Circle(Point(sqrt(2) + 3 * sqrt(3), 1), 12)  # externally tangent: |d| = sqrt3 + 2 sqrt3
    pts = intersect_circles(c, c2)
    assert len(pts) == 1
    assert is_zero(pts[0].x - sqrt(2) - sqrt(3)) and is_zero(pts[0].y - 1)


def test_intersection_examples_by_hand():
    # unit circles at (0,0) and (1,0): x = 1/2, y = ±sqrt(3)/2, left of +x first
    assert intersect_circles(Circle(Point(0, 0), 1), Circle(Point(1, 0), 1)) == (
        Point(R(1, 2), sqrt(3) / 2),
        Point(R(1, 2), -sqrt(3) / 2),
    )
    # swapping the circles swaps the branch
    assert intersect_circles(Circle(Point(1, 0), 1), Circle(Point(0, 0), 1)) == (
        Point(R(1, 2), -sqrt(3) / 2),
        Point(R(1, 2), sqrt(3) / 2),
    )
    # x-axis against radius 2: (2, 0) lies further along +x
    x_axis = Line(Point(0, 0), Point(1, 0))
    assert intersect_line_circle(x_axis, Circle(Point(0, 0), 4)) == (Point(2, 0), Point(-2, 0))
    reverse = Line(Point(0, 0), Point(-1, 0))
    assert intersect_line_circle(reverse, Circle(Point(0, 0), 4)) == (Point(-2, 0), Point(2, 0))
    assert intersect_line_circle(Line(Point(0, 5), Point(1, 0)), Circle(Point(0, 0), 4)) == ()


# ---- branch order: symbolic then substituted == numeric

_SYM_CIRCLES = (Circle(Point(a, 0), 4), Circle(Point(1, b), 3))
_SYM_LINE_CIRCLE = (Line(Point(a, 1), Point(1, b)), Circle(Point(0, 0), 5))


def _sym_circles():
    return intersect_circles(*_SYM_CIRCLES)


def _sym_line_circle():
    return intersect_line_circle(*_SYM_LINE_CIRCLE)


_SYM_CACHE: dict = {}


def _cached(name, fn):
    if name not in _SYM_CACHE:
        _SYM_CACHE[name] = fn()
    return _SYM_CACHE[name]


def _subs_point(p: Point, values: dict) -> Point:
    return Point(p.x.subs(values), p.y.subs(values))


@SLOW
@given(small_rationals, small_rationals)
def test_circle_branches_symbolic_then_substituted_match_numeric(av, bv):
    assume((av, bv) != (1, 0))
    sym = _cached("circles", _sym_circles)
    assert len(sym) == 2
    num = intersect_circles(Circle(Point(av, 0), 4), Circle(Point(1, bv), 3))
    assume(len(num) == 2)
    for s, n in zip(sym, num):
        s = _subs_point(s, {a: av, b: bv})
        assert is_zero(s.x - n.x) and is_zero(s.y - n.y), (s, n)
    assert _sym_circles() == sym  # same order on a second run


@SLOW
@given(small_rationals, small_rationals)
def test_line_circle_branches_symbolic_then_substituted_match_numeric(av, bv):
    sym = _cached("line-circle", _sym_line_circle)
    assert len(sym) == 2
    num = intersect_line_circle(Line(Point(av, 1), Point(1, bv)), Circle(Point(0, 0), 5))
    assume(len(num) == 2)
    for s, n in zip(sym, num):
        s = _subs_point(s, {a: av, b: bv})
        assert is_zero(s.x - n.x) and is_zero(s.y - n.y), (s, n)


def test_symbolic_intersection_records_discriminant():
    c1, c2 = _SYM_CIRCLES
    pts = _cached("circles", _sym_circles)
    # expected discriminant from the test's own formula: zero exactly where the circles touch
    disc = circles_discriminant(c1, c2)
    for p in pts:
        assert any(sympy.cancel(c / disc).is_number for c in p.conditions), p.conditions


# ---- second intersection


@FAST
@given(points, points, points)
def test_second_intersection(k, m1, m2):
    assume(m1 != k and m2 != k)
    assume(cross(sub(m2, m1), sub(k, m1)) != 0)  # K is off the line of centres
    c1, c2 = circle_through(m1, k), circle_through(m2, k)
    s = second_intersection(c1, c2, k)
    assert on_circle(s, c1) and on_circle(s, c2)
    assert s != k
    assert s.x.is_Rational and s.y.is_Rational  # mirror image: no square root
    assert set(intersect_circles(c1, c2)) == {k, s}


def test_second_intersection_with_radicals():
    k = Point(0, 0)
    c1 = circle_on_diameter(k, Point(sqrt(3), 1))
    c2 = circle_on_diameter(k, Point(-1, sqrt(2)))
    s = second_intersection(c1, c2, k)
    assert on_circle(s, c1) and on_circle(s, c2)
    assert same_point(s, k) is False
    assert no_float(s)


def test_second_intersection_tangent_and_concentric():
    k = Point(0, 0)
    with pytest.raises(NoIntersectionError) as info:
        second_intersection(Circle(Point(1, 0), 1), Circle(Point(2, 0), 4), k)
    assert info.value.objects == (Circle(Point(1, 0), 1), Circle(Point(2, 0), 4))
    with pytest.raises(NoIntersectionError):  # internally tangent at K
        second_intersection(Circle(Point(1, 1), 2), Circle(Point(-3, -3), 18), k)
    with pytest.raises(DegenerateCircleError):
        second_intersection(Circle(Point(1, 0), 1), Circle(Point(1, 0), 1), k)
    with pytest.raises(DegenerateCircleError):
        intersect_circles(Circle(Point(1, 0), 1), Circle(Point(1, 0), 4))


# --------------------------------------------------------------------------- degeneracies


def test_meet_of_parallel_lines_names_both():
    l1 = Line(Point(0, 1), Point(1, 2))
    l2 = Line(Point(5, 0), Point(-2, -4))
    with pytest.raises(ParallelLinesError) as info:
        meet(l1, l2)
    assert str(l1) in str(info.value) and str(l2) in str(info.value)
    assert info.value.objects == (l1, l2)
    assert isinstance(info.value, GeometryError) and isinstance(info.value, ValueError)


DEGENERATE = [
    (
        lambda: meet(Line(Point(0, 0), Point(1, 1)), Line(Point(0, 0), Point(3, 3))),
        ParallelLinesError,
    ),
    (
        lambda: meet(Line(Point(0, 0), Point(sqrt(2), 1)), Line(Point(1, 0), Point(2, sqrt(2)))),
        ParallelLinesError,
    ),
    (
        lambda: meet(
            Line(Point(0.0, 0.0), Point(0.1, 0.3)), Line(Point(1.0, 0.0), Point(1.0, 3.0))
        ),
        ParallelLinesError,
    ),
    (lambda: line_through(Point(1, 1), Point(1, 1)), CoincidentPointsError),
    (lambda: line_through(Point(sqrt(2) * sqrt(2), 0), Point(2, 0)), CoincidentPointsError),
    (lambda: line_through(Point(0.5, 0.5), Point(0.5, 0.5)), CoincidentPointsError),
    (lambda: Line(Point(1, 1), Point(0, 0)), ZeroDirectionError),
    (lambda: line_with_direction(Point(1, 1), Point(sqrt(8) - 2 * sqrt(2), 0)), ZeroDirectionError),
    (lambda: Line(Point(1, 1), Point(0.0, 0.0)), ZeroDirectionError),
    (lambda: Segment(Point(1, 2), Point(1, 2)), CoincidentPointsError),
    (lambda: circle_on_diameter(Point(3, 4), Point(3, 4)), DegenerateCircleError),
    (lambda: circle_on_diameter(Point(0.5, 1.0), Point(0.5, 1.0)), DegenerateCircleError),
    (
        lambda: intersect_circles(Circle(Point(2, 2), 1), Circle(Point(2, 2), 4)),
        DegenerateCircleError,
    ),
    (
        lambda: intersection(Line(Point(0, 0), Point(1, 0)), Line(Point(3, 0), Point(-2, 0))),
        ParallelLinesError,
    ),
]


@pytest.mark.parametrize(("make", "error"), DEGENERATE)
def test_degeneracies_raise_named_errors(make, error):
    with pytest.raises(error) as info:  # a ZeroDivisionError or a nan would fail here
        make()
    assert isinstance(info.value, GeometryError)
    assert info.value.objects
    assert str(info.value)


def test_line_through_coincident_points_message():
    with pytest.raises(CoincidentPointsError) as info:
        line_through(Point(1, 1), Point(1, 1))
    assert "Point(1, 1)" in str(info.value)


def test_intersection_of_parallel_lines_is_empty():
    assert intersection(Line(Point(0, 1), Point(1, 0)), Line(Point(0, 0), Point(1, 0))) == ()
    assert intersection(Line(Point(0, 1), Point(1, 1)), Line(Point(0, 0), Point(-2, -2))) == ()
    l1, l2 = Line(Point(0, 0), Point(1, 2)), Line(Point(0, 3), Point(1, 0))
    m = intersection(l1, l2)
    assert len(m) == 1 and m[0] == Point(R(3, 2), 3)  # y = 2x meets y = 3 at x = 3/2


def test_intersection_of_coincident_lines_raises():
    with pytest.raises(GeometryError):
        intersection(Line(Point(0, 0), Point(1, 1)), Line(Point(2, 2), Point(-1, -1)))


def test_no_nan_on_near_degenerate_floats():
    pts = intersect_line_circle(
        Line(Point(0.0, 1.0), Point(1.0, 0.0)), Circle(Point(0.0, 0.0), 1.0)
    )
    assert len(pts) == 1
    for p in pts:
        assert all(math.isfinite(v) for v in evaluate(p))


# --------------------------------------------------------------------------- symbolic


def test_meet_with_symbolic_directions_records_the_denominator():
    l1 = Line(Point(0, 0), Point(1, a))
    l2 = Line(Point(1, 0), Point(b, 1))
    m = meet(l1, l2)
    den = cross((1, a), (b, 1))  # 1 - a*b: the lines are parallel where it vanishes
    assert any(sympy.cancel(c / den).is_number for c in m.conditions), m.conditions
    assert is_zero(sympy.cancel(cross(sub(m, l1.point), (1, a))))
    assert is_zero(sympy.cancel(cross(sub(m, l2.point), (b, 1))))


def test_symbolic_values_agree_with_numbers_after_substitution():
    l1 = Line(Point(a, 0), Point(1, 2))
    l2 = Line(Point(0, b), Point(-1, 3))
    m = meet(l1, l2)
    for av, bv in ((1, 2), (R(-3, 4), 5), (0, 0)):
        num = meet(Line(Point(av, 0), Point(1, 2)), Line(Point(0, bv), Point(-1, 3)))
        assert _subs_point(m, {a: av, b: bv}) == num
    assert evaluate(m, {a: 1, b: 2}) == pytest.approx(
        evaluate(meet(Line(Point(1, 0), Point(1, 2)), Line(Point(0, 2), Point(-1, 3))))
    )


def test_decide_zero_and_sign():
    assert decide_zero(a) is None
    assert decide_zero(a - a) is True
    assert decide_zero((a + 1) ** 2 - a**2 - 2 * a - 1) is True
    assert decide_zero(sqrt(6) - sqrt(2) * sqrt(3)) is True
    assert decide_zero(sqrt(2) - R(141421356237, 10**11)) is False
    assert decide_zero(sympy.Integer(0)) is True
    assert decide_sign(a) is None
    assert decide_sign(sqrt(3) - 2) == -1
    assert decide_sign(sqrt(5) - 2) == 1
    assert decide_sign(pi / 2 - pi / 2) == 0


def test_canon_of_radicals():
    # (1 + √3)/(1 − √3) · (1 + √3)/(1 + √3) = (4 + 2√3)/(−2) = −2 − √3
    assert canon((sqrt(3) + 1) / (1 - sqrt(3))) == -2 - sqrt(3)
    assert canon(1 / sqrt(2)) == sqrt(2) / 2
    assert canon(1 / (sqrt(2) + sqrt(3))) == sqrt(3) - sqrt(2)
    assert canon(sympy.tan(pi / 3)) == sqrt(3)
    assert canon((a**2 - b**2) / (a - b)) == a + b
    assert canon(R(6, 4)) == R(3, 2)


def test_exact_results_hold_no_float():
    s3 = sqrt(3)
    p, q, r = Point(s3 / 2, R(1, 2)), Point(-s3 / 2, R(1, 2)), Point(R(1, 3), -2)
    lpq, lpr = line_through(p, q), line_through(p, r)
    m = meet(perpendicular(lpq, r), lpr)
    c1, c2 = circle_on_diameter(ORIGIN, p), circle_on_diameter(ORIGIN, r)
    objs = [
        lpq,
        lpr,
        m,
        foot(r, lpq),
        reflect(r, lpr),
        midpoint(p, r),
        c1,
        c2,
        second_intersection(c1, c2, ORIGIN),
        *intersect_circles(c1, Circle(q, 2)),
        *intersect_line_circle(lpr, c1),
        distance2(p, r),
        distance(p, r),
        signed_length(p, r, lpr),
        angle_of(Point(s3, -1)),
    ]
    assert no_float(*objs)


def test_float_inputs_stay_on_the_float_path():
    l1 = Line(Point(0.5, 0.0), Point(1.0, 1.0))
    l2 = Line(Point(0.0, 0.0), Point(1.0, -1.0))
    m = meet(l1, l2)
    assert not m.is_exact
    assert m.x.atoms(sympy.Float) and m.y.atoms(sympy.Float)
    # the lines y = x - 1/2 and y = -x meet at (1/4, -1/4)
    assert evaluate(m) == pytest.approx((0.25, -0.25), abs=1e-15)
    pts = intersect_circles(Circle(Point(0.0, 0.0), 1.0), Circle(Point(1.0, 0.0), 1.0))
    assert len(pts) == 2 and not any(p.is_exact for p in pts)
    assert evaluate(pts[0]) == pytest.approx((0.5, math.sqrt(3) / 2), abs=1e-14)
    assert evaluate(pts[1]) == pytest.approx((0.5, -math.sqrt(3) / 2), abs=1e-14)


def test_evaluate():
    assert evaluate(Point(sqrt(2), a), {a: 2}) == pytest.approx((math.sqrt(2), 2.0))
    (cx, cy), r = evaluate(Circle(Point(1, 0), 2))
    assert (cx, cy, r) == pytest.approx((1.0, 0.0, math.sqrt(2)))
    (px, py), (dx, dy) = evaluate(Line(Point(0, 1), Point(1, sqrt(3))))
    assert (px, py, dx, dy) == pytest.approx((0.0, 1.0, 1.0, math.sqrt(3)))
    assert evaluate(sqrt(2) / 2) == pytest.approx(math.sqrt(0.5))
    with pytest.raises(ValueError, match="free symbols"):
        evaluate(Point(a, 0))


# --------------------------------------------------------------------------- measurement


def test_signed_length_along_the_x_axis():
    x_axis = Line(Point(0, 0), Point(1, 0))
    assert signed_length(Point(0, 0), Point(3, 0), x_axis) == 3
    assert signed_length(Point(3, 0), Point(1, 0), x_axis) == -2
    assert signed_length(Point(1, 0), Point(1, 0), x_axis) == 0
    # the length of the direction vector does not matter, its sense does
    assert signed_length(Point(0, 0), Point(3, 0), Line(Point(0, 0), Point(5, 0))) == 3
    assert signed_length(Point(0, 0), Point(3, 0), Line(Point(0, 0), Point(-2, 0))) == -3
    # only the component along the line counts
    assert signed_length(Point(-1, 7), Point(sqrt(3) / 2, -4), x_axis) == sqrt(3) / 2 + 1


@FAST
@given(points, points, vectors)
def test_signed_length_squared_is_projected_distance(p, q, d):
    sl = signed_length(p, q, Line(ORIGIN, d))
    proj = dot(sub(q, p), (d.x, d.y))
    assert is_zero(sl**2 - proj**2 / dot((d.x, d.y), (d.x, d.y)))
    if proj == 0:
        assert sl == 0
    else:
        assert sign_of(sl) == sign_of(proj)


def test_distance():
    assert distance2(Point(0, 0), Point(3, 4)) == 25
    assert distance(Point(0, 0), Point(3, 4)) == 5
    assert distance(Point(0, 0), Point(1, 1)) == sqrt(2)


def test_angle_of_uses_the_papers_theta():
    # θ is measured from the negative y-axis, counter-clockwise: e(θ) = (sin θ, −cos θ)
    assert angle_of(Point(1, 0)) == pi / 2
    assert angle_of(Point(0, -1)) == 0
    assert angle_of(Point(0, -5)) == 0
    assert sympy.simplify(angle_of(Point(0, 1)) - pi) == 0
    assert angle_of(Point(sqrt(3), -1)) == pi / 3
    assert angle_of(Point(1, -1)) == pi / 4


@FAST
@given(vectors)
def test_angle_of_gives_a_parallel_unit_vector(v):
    theta = angle_of(v)
    e = (sympy.sin(theta), -sympy.cos(theta))
    # e(θ) is v / |v|: check at 40 digits
    n = sympy.sqrt(v.x**2 + v.y**2)
    assert abs(sympy.N(e[0] - v.x / n, 40)) < 1e-30
    assert abs(sympy.N(e[1] - v.y / n, 40)) < 1e-30


# --------------------------------------------------------------------------- known bugs


def test_decide_sign_uses_the_symbols_assumptions():
    p = sympy.Symbol("p", positive=True)
    assert decide_sign(p) == 1
    assert decide_sign(-p) == -1
    assert decide_sign(p + 1) == 1


def test_line_with_symbolic_vertical_direction_records_a_condition():
    line = Line(Point(0, 0), Point(0, a))
    # the direction vanishes exactly where a = 0: some condition must vanish there
    assert any(c.subs(a, 0) == 0 for c in line.conditions), line.conditions


def test_symbolic_circle_intersection_records_the_centre_distance():
    pts = intersect_circles(Circle(Point(0, 0), 4), Circle(Point(b, 0), 1))
    for p in pts:
        assert any(c.subs(b, 0) == 0 for c in p.conditions), p.conditions


def test_small_float_perpendicular_lines_meet():
    m = meet(Line(Point(0.0, 0.0), Point(1e-7, 0.0)), Line(Point(1.0, 1.0), Point(0.0, 1e-7)))
    assert evaluate(m) == pytest.approx((1.0, 0.0))


# --------------------------------------------------------------------------- atan shortcut
_RADICALS = [
    sympy.Integer(1),
    sympy.Integer(2),
    sympy.Rational(1, 2),
    sympy.sqrt(2),
    sympy.sqrt(3),
    sympy.sqrt(6),
    sympy.sqrt(5),
]


@settings(max_examples=150, deadline=None)
@given(
    st.lists(st.tuples(st.integers(-3, 3), st.sampled_from(_RADICALS)), min_size=1, max_size=3),
    st.lists(st.tuples(st.integers(-3, 3), st.sampled_from(_RADICALS)), min_size=1, max_size=3),
)
def test_angle_of_is_atan2_on_radical_vectors(xs, ys):
    """angle_of skips sympy's atan eval; its value must still be atan2(x, -y) (eq. (26)),
    checked at 50 digits against mpmath, with the argument of any atan positive."""
    import mpmath

    x = sum((k * v for k, v in xs), sympy.Integer(0))
    y = sum((k * v for k, v in ys), sympy.Integer(0))
    assume(not (sympy.simplify(x) == 0 and sympy.simplify(y) == 0))
    a = angle_of(Point(x, y))
    with mpmath.workdps(50):
        want = mpmath.atan2(mpmath.mpf(sympy.N(x, 60)), -mpmath.mpf(sympy.N(y, 60)))
        assert abs(mpmath.mpf(sympy.N(a, 60)) - want) < mpmath.mpf(10) ** -45
    for t in a.atoms(sympy.atan):
        assert sympy.N(t.args[0], 30) > 0


@pytest.mark.parametrize("k", range(-11, 13))
def test_angle_of_gives_multiples_of_pi_where_sympy_knows_them(k):
    """Directions at multiples of π/12 come out as those multiples (no atan left over),
    and tan(π/8) = √2 − 1 as π/8, as sympy's atan table gives them."""
    from graspcompass.geometry.trig import sincos

    a = sympy.pi * k / 12
    s, c = sincos(a)
    assert angle_of(Point(s, -c)) == a  # e(a) = (sin a, -cos a)
    assert angle_of(Point(sympy.sqrt(2) - 1, -1)) == sympy.pi / 8
    assert angle_of(Point(-1 - sympy.sqrt(2), 1)) == -5 * sympy.pi / 8


def test_atan_table_is_sympys_on_the_kernels_numbers():
    """measurement._atan_values is written out; it must be sympy's table restricted to
    the arguments without nested radicals (the only ones a canonical number can be)."""
    from graspcompass.geometry.measurement import _atan_values
    from graspcompass.geometry.trig import is_radical

    theirs = {k: v for k, v in sympy.atan._atan_table().items() if v > 0 and is_radical(k)}
    theirs[sympy.Integer(1)] = sympy.pi / 4
    assert _atan_values() == theirs


def test_small_primes_sieve_is_sympys():
    from graspcompass.geometry._exact_convert import _TRIAL, _small_primes

    assert _small_primes() == tuple(sympy.primerange(2, _TRIAL))
