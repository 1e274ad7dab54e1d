"""Predicates of the kernel: exact True/False, or None when undecidable."""

from __future__ import annotations

from .exact import decide_zero
from .primitives import Circle, Line, Point

__all__ = ["are_parallel", "are_perpendicular", "is_on", "same_line", "same_point"]


def same_point(p: Point, q: Point) -> bool | None:
    """Whether ``p`` and ``q`` coincide (exactly).

    Examples
    --------
    >>> from sympy import sqrt
    >>> same_point(Point(sqrt(2)*sqrt(2), 0), Point(2, 0))
    True
    """
    zx, zy = decide_zero(p.x - q.x), decide_zero(p.y - q.y)
    if zx is False or zy is False:
        return False
    return None if zx is None or zy is None else True


def is_on(p: Point, obj: Line | Circle) -> bool | None:
    """Whether ``p`` lies on a line or a circle.

    Examples
    --------
    >>> is_on(Point(1, 1), Line(Point(0, 0), Point(2, 2)))
    True
    >>> is_on(Point(0, 1), Circle(Point(0, 0), 1))
    True
    """
    if isinstance(obj, Line):
        z = decide_zero((p - obj.point).cross(obj.direction))
    else:
        z = decide_zero((p.x - obj.center.x) ** 2 + (p.y - obj.center.y) ** 2 - obj.radius2)
    return z


def are_parallel(a: Line, b: Line) -> bool | None:
    """Whether two lines are parallel (or the same line)."""
    return decide_zero(a.direction.cross(b.direction))


def are_perpendicular(a: Line, b: Line) -> bool | None:
    """Whether two lines are perpendicular."""
    return decide_zero(a.direction.dot(b.direction))


def same_line(a: Line, b: Line) -> bool | None:
    """Whether two lines are the same point set (orientation ignored)."""
    par = are_parallel(a, b)
    if not par:
        return par
    return is_on(b.point, a)
