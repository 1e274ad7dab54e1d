"""Named degeneracy errors of the geometry kernel.

Every error is a :class:`GeometryError`, itself a :class:`ValueError`, and
carries the objects that made the construction impossible (``.objects``), so a
caller can say *which* inputs were degenerate, not only that something was.
"""

from __future__ import annotations

from ..boundary.errors import GraspCompassError

__all__ = [
    "CoincidentPointsError",
    "DegenerateCircleError",
    "GeometryError",
    "NoIntersectionError",
    "ParallelLinesError",
    "ZeroDirectionError",
]


class GeometryError(GraspCompassError):
    """A construction step is impossible for the given objects."""

    def __init__(self, message: str, *objects: object) -> None:
        super().__init__(message)
        self.objects = objects


class CoincidentPointsError(GeometryError):
    """Two points that must be distinct coincide (e.g. a line through them)."""


class ZeroDirectionError(GeometryError):
    """A direction vector is the zero vector."""


class ParallelLinesError(GeometryError):
    """Two lines that must meet in one point are parallel (or the same line)."""


class NoIntersectionError(GeometryError):
    """Objects that must meet do not (a line missing a circle, disjoint circles)."""


class DegenerateCircleError(GeometryError):
    """A circle of zero radius, or two concentric circles where a meet is needed."""
