"""Exact ruler-and-compass geometry kernel over sympy.

Nouns are types (:class:`Point`, :class:`Line`, :class:`Circle`,
:class:`Segment`, :class:`Ray`); verbs live in modules:
:mod:`~graspcompass.geometry.constructive` (constructions),
:mod:`~graspcompass.geometry.measurement`,
:mod:`~graspcompass.geometry.predicates` and
:mod:`~graspcompass.geometry.numeric`.  Degenerate input raises a named
:class:`GeometryError` (a :class:`ValueError`).
"""

from .constructive import (
    circle_on_diameter,
    circle_through,
    foot,
    intersect_circles,
    intersect_line_circle,
    intersection,
    line_through,
    line_with_direction,
    meet,
    midpoint,
    parallel,
    perpendicular,
    reflect,
    second_intersection,
)
from .errors import (
    CoincidentPointsError,
    DegenerateCircleError,
    GeometryError,
    NoIntersectionError,
    ParallelLinesError,
    ZeroDirectionError,
)
from .exact import canon, decide_sign, decide_zero
from .measurement import angle_of, distance, distance2, signed_length
from .numeric import evaluate
from .predicates import are_parallel, are_perpendicular, is_on, same_line, same_point
from .primitives import ORIGIN, Circle, Line, Point, Ray, Segment

__all__ = [
    "ORIGIN",
    "Circle",
    "CoincidentPointsError",
    "DegenerateCircleError",
    "GeometryError",
    "Line",
    "NoIntersectionError",
    "ParallelLinesError",
    "Point",
    "Ray",
    "Segment",
    "ZeroDirectionError",
    "angle_of",
    "are_parallel",
    "are_perpendicular",
    "canon",
    "circle_on_diameter",
    "circle_through",
    "decide_sign",
    "decide_zero",
    "distance",
    "distance2",
    "evaluate",
    "foot",
    "intersect_circles",
    "intersect_line_circle",
    "intersection",
    "is_on",
    "line_through",
    "line_with_direction",
    "meet",
    "midpoint",
    "parallel",
    "perpendicular",
    "reflect",
    "same_line",
    "same_point",
    "second_intersection",
    "signed_length",
]
