"""Frozen, hashable value objects of the kernel: Point, Line, Circle, Segment, Ray.

Coordinates are sympy expressions: exact numbers (integers, rationals,
radicals, ``pi``), symbols, or floats when the user gave floats.  Values never
change after construction; every constructor keeps its type (a line is always
a :class:`Line`).  Each object also carries the non-degeneracy conditions it
was built under (``conditions``: expressions assumed non-zero); they take no
part in equality or hashing.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from ..boundary.inputs import real_value
from .errors import CoincidentPointsError, DegenerateCircleError, ZeroDirectionError
from .exact import Frac, NotAFraction, canon, decide_sign, decide_zero, sym, text

__all__ = ["ORIGIN", "Circle", "Conditions", "Line", "Point", "Ray", "Segment"]

Conditions = frozenset  # frozenset[sympy.Expr]: each expression is assumed != 0


def _outside(value: object, name: str) -> object:
    """A coordinate from a caller goes through the input boundary (:func:`real_value`).

    Everything that is not a sympy expression (text, floats, ints, ``None``, bools,
    bytes, complex numbers, Fractions, Decimals, numpy scalars) is checked there, and so
    is a sympy atom that is no real number (``I``, ``oo``, ``zoo``, ``nan``): named errors,
    never a TypeError from sympify.  Other sympy values are the kernel's own results
    (code, which is trusted; its rationals may exceed the bounds of outside integers) and
    pass as they are: the kernel makes millions of points.
    """
    if isinstance(value, sp.Basic):
        if (
            value.is_Atom
            and not value.is_Symbol
            and not value.is_Rational
            and (value.is_extended_real is not True or value.is_finite is not True)
        ):
            return real_value(value, name)
        return value
    return real_value(value, name)


def _merge(*objs: object) -> frozenset:
    out: frozenset = frozenset()
    for o in objs:
        out |= getattr(o, "conditions", frozenset())
    return out


@dataclass(frozen=True)
class Point:
    """A point (or a free vector) with coordinates ``x``, ``y``.

    Examples
    --------
    >>> from sympy import sqrt, Rational
    >>> p = Point(sqrt(3)/2, Rational(1, 2))
    >>> p
    Point(sqrt(3)/2, 1/2)
    >>> p == Point(sqrt(3)/2, Rational(1, 2)) and hash(p) == hash(Point(sqrt(3)/2, Rational(1, 2)))
    True
    """

    x: sp.Expr
    y: sp.Expr
    conditions: frozenset = field(default=frozenset(), compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "x", sym(_outside(self.x, "x")))
        object.__setattr__(self, "y", sym(_outside(self.y, "y")))

    @classmethod
    def canonical(cls, x: object, y: object, conditions: frozenset = frozenset()) -> Point:
        """A point whose coordinates are put in canonical form (:func:`canon`)."""
        return cls(canon(sym(x)), canon(sym(y)), conditions)

    def __repr__(self) -> str:
        return f"Point({text(self.x)}, {text(self.y)})"

    def __iter__(self):  # allows ``x, y = p``
        yield self.x
        yield self.y

    def __add__(self, other: Point) -> Point:
        try:
            x = (Frac.of(self.x) + Frac.of(other.x)).expr()
            y = (Frac.of(self.y) + Frac.of(other.y)).expr()
            return Point(x, y, _merge(self, other))
        except NotAFraction:
            return Point.canonical(self.x + other.x, self.y + other.y, _merge(self, other))

    def __sub__(self, other: Point) -> Point:
        try:
            x = (Frac.of(self.x) - Frac.of(other.x)).expr()
            y = (Frac.of(self.y) - Frac.of(other.y)).expr()
            return Point(x, y, _merge(self, other))
        except NotAFraction:
            return Point.canonical(self.x - other.x, self.y - other.y, _merge(self, other))

    def __neg__(self) -> Point:
        return Point(-self.x, -self.y, self.conditions)

    def scale(self, factor: object) -> Point:
        """The vector ``factor * self``."""
        f = sym(factor)
        return Point.canonical(f * self.x, f * self.y, self.conditions)

    def dot(self, other: Point) -> sp.Expr:
        """Exact dot product."""
        try:
            a, b, c, d = (Frac.of(v) for v in (self.x, self.y, other.x, other.y))
            return (a * c + b * d).expr()
        except NotAFraction:
            return canon(self.x * other.x + self.y * other.y)

    def cross(self, other: Point) -> sp.Expr:
        """Exact 2D cross product ``self.x*other.y - self.y*other.x``."""
        try:
            a, b, c, d = (Frac.of(v) for v in (self.x, self.y, other.x, other.y))
            return (a * d - b * c).expr()
        except NotAFraction:
            return canon(self.x * other.y - self.y * other.x)

    def perp(self) -> Point:
        """The vector turned a quarter turn counter-clockwise, ``(-y, x)``."""
        return Point(-self.y, self.x, self.conditions)

    @property
    def is_exact(self) -> bool:
        """True when no coordinate holds a float."""
        return not (self.x.atoms(sp.Float) or self.y.atoms(sp.Float))

    def evalf(self) -> tuple[float, float]:
        """Coordinates as Python floats (needs numeric coordinates)."""
        return float(self.x), float(self.y)


ORIGIN = Point(0, 0)


@dataclass(frozen=True)
class Line:
    """The oriented line through ``point`` with direction ``direction``.

    Two lines are equal when both fields are; use
    :func:`graspcompass.geometry.predicates.same_line` for the point-set test.

    Examples
    --------
    >>> Line(Point(0, 0), Point(1, 0))
    Line(Point(0, 0), direction=Point(1, 0))
    >>> Line(Point(0, 0), Point(0, 0))
    Traceback (most recent call last):
    ...
    graspcompass.geometry.errors.ZeroDirectionError: a line needs a non-zero direction, ...
    """

    point: Point
    direction: Point
    conditions: frozenset = field(default=frozenset(), compare=False, repr=False)

    def __post_init__(self) -> None:
        d = self.direction
        zx, zy = decide_zero(d.x), decide_zero(d.y)
        if zx and zy:
            raise ZeroDirectionError(
                f"a line needs a non-zero direction, got {d} at {self.point}", self.point, d
            )
        conds = _merge(self.point, d) | self.conditions
        if None in (zx, zy) and False not in (zx, zy):  # |d| != 0 only assumed
            conds |= {canon(d.x**2 + d.y**2)}
        object.__setattr__(self, "conditions", conds)

    def __repr__(self) -> str:
        return f"Line({self.point}, direction={self.direction})"

    def at(self, t: object) -> Point:
        """The point ``point + t * direction``."""
        return self.point + self.direction.scale(t)

    @property
    def normal(self) -> Point:
        """A normal vector (the direction turned counter-clockwise)."""
        return self.direction.perp()

    def coefficients(self) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(a, b, c)`` with ``a*x + b*y + c = 0`` on the line."""
        a, b = -self.direction.y, self.direction.x
        return a, b, canon(-(a * self.point.x + b * self.point.y))


@dataclass(frozen=True)
class Circle:
    """The circle with ``center`` and squared radius ``radius2`` (exact, no sqrt).

    Examples
    --------
    >>> c = Circle(Point(1, 0), 1)
    >>> c.radius
    1
    """

    center: Point
    radius2: sp.Expr
    conditions: frozenset = field(default=frozenset(), compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius2", sym(self.radius2))
        if decide_sign(self.radius2) in (-1, 0):
            raise DegenerateCircleError(
                f"a circle needs a positive squared radius, got {self.radius2} "
                f"at centre {self.center}",
                self.center,
            )
        object.__setattr__(self, "conditions", _merge(self.center) | self.conditions)

    def __repr__(self) -> str:
        return f"Circle({self.center}, radius2={text(self.radius2)})"

    @property
    def radius(self) -> sp.Expr:
        """The radius, ``sqrt(radius2)``."""
        return sp.sqrt(self.radius2)


@dataclass(frozen=True)
class Segment:
    """The segment from ``start`` to ``end`` (for drawing)."""

    start: Point
    end: Point

    def __post_init__(self) -> None:
        if decide_zero(self.start.x - self.end.x) and decide_zero(self.start.y - self.end.y):
            raise CoincidentPointsError(
                f"a segment needs two distinct points, got {self.start} twice", self.start
            )

    @property
    def line(self) -> Line:
        """The oriented line carrying the segment."""
        return Line(self.start, self.end - self.start)


@dataclass(frozen=True)
class Ray:
    """The half-line from ``origin`` along ``direction`` (for drawing)."""

    origin: Point
    direction: Point

    @property
    def line(self) -> Line:
        """The oriented line carrying the ray."""
        return Line(self.origin, self.direction)
