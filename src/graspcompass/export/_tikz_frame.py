"""The coordinates of one TikZ picture (the diagram, or a zoomed inset) that TeX can hold.

TeX's lengths stop at 16383.99 pt: a coordinate times the picture's unit beyond it stops
pdflatex with "Dimension too large".  An inset drawn at hundreds of points per unit
cannot take the scene's lines (a few thousand units long) nor a circle far from its
region, so every picture is written in coordinates about the centre of its box, and
what reaches beyond a margin around the box is cut there (shapely), the cut ends
outside the picture's clip.  A circle or arc that would still be too large is written
as the polyline of its visible part.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from shapely.geometry import LineString, Polygon
from shapely.geometry import box as _shapely_box

__all__ = ["PT_PER_CM", "Frame", "arc_points"]

#: Points per centimetre.
PT_PER_CM = 72.27 / 2.54

#: The largest coordinate written, in points: far below TeX's 16383.99 pt, so that the
#: sums TikZ forms (a node's anchor, a circle's extent) stay inside it too.
_LARGEST_PT = 4000.0

#: The margin around the box, a fraction of its width: the cut ends lie beyond the clip.
_MARGIN = 0.25

#: Points of a whole circle written as a polyline (a chord's sagitta is r * 3.8e-7).
_CIRCLE_POINTS = 3600

XY = tuple[float, float]


def _num(v: float) -> str:
    """A decimal with 12 significant digits, never in exponent notation."""
    text = f"{v:.12g}"
    if "e" in text or "E" in text:
        text = f"{v:.12f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _parts(geom: object) -> list[object]:
    if geom.is_empty:  # type: ignore[attr-defined]
        return []
    return list(getattr(geom, "geoms", [geom]))


@dataclass(frozen=True)
class Frame:
    """One picture: ``box`` ``(xmin, xmax, ymin, ymax)`` drawn at ``unit_cm`` per unit.

    Examples
    --------
    A diagram keeps the paper's coordinates; a line thousands of units long is cut a
    quarter of the box's width beyond it:

    >>> f = Frame((-1.0, 1.0, -1.0, 1.0), 5.0)
    >>> f.xy((0.5, 2.0))
    '(0.5, 2)'
    >>> f.polylines([(-3000.0, 0.0), (3000.0, 0.0)])
    [[(-1.5, 0.0), (1.5, 0.0)]]

    An inset at 2000 cm per unit far from O is written about its centre:

    >>> g = Frame((0.999, 1.001, 2.999, 3.001), 2000.0)
    >>> g.origin
    (1.0, 3.0)
    >>> g.fits((1.0, 3.0), 0.5), g.fits((1.0, 3.0), 0.01)
    (False, True)
    """

    box: tuple[float, ...]
    unit_cm: float

    @property
    def origin(self) -> XY:
        """The point written as (0, 0): the paper's origin O where the box is near enough
        to it (the diagram: coordinates as in the paper), else the box's centre."""
        if max(map(abs, self.box)) <= self._reach / 2:
            return (0.0, 0.0)
        return ((self.box[0] + self.box[1]) / 2, (self.box[2] + self.box[3]) / 2)

    @property
    def _reach(self) -> float:
        """The largest local coordinate allowed, in units."""
        return _LARGEST_PT / (self.unit_cm * PT_PER_CM)

    @property
    def _cut(self) -> object:
        w = max(self.box[1] - self.box[0], self.box[3] - self.box[2])
        m = _MARGIN * w
        return _shapely_box(self.box[0] - m, self.box[2] - m, self.box[1] + m, self.box[3] + m)

    def local(self, p: Sequence[float]) -> XY:
        """``p`` in the picture's coordinates (about :attr:`origin`)."""
        o = self.origin
        return (float(p[0]) - o[0], float(p[1]) - o[1])

    def xy(self, p: Sequence[float]) -> str:
        """``p`` as a TikZ coordinate of the picture."""
        x, y = self.local(p)
        return f"({_num(x)}, {_num(y)})"

    def fits(self, center: Sequence[float], radius: float) -> bool:
        """Whether a circle about ``center`` can be written as one (its extent in range)."""
        x, y = self.local(center)
        return math.hypot(x, y) + abs(radius) <= self._reach

    def polylines(self, points: Sequence[Sequence[float]]) -> list[list[XY]]:
        """The parts of the polyline ``points`` inside the margin around the box."""
        if len(points) < 2:
            return []
        cut = LineString([tuple(map(float, p)) for p in points]).intersection(self._cut)
        return [
            [self.local(q) for q in part.coords]  # type: ignore[attr-defined]
            for part in _parts(cut)
            if part.geom_type == "LineString"  # type: ignore[attr-defined]
        ]

    def polygons(self, points: Sequence[Sequence[float]]) -> list[list[XY]]:
        """The parts of the polygon ``points`` inside the margin around the box."""
        if len(points) < 3:
            return []
        shape = Polygon([tuple(map(float, p)) for p in points])
        if not shape.is_valid:
            shape = shape.buffer(0)
        cut = shape.intersection(self._cut)
        return [
            [self.local(q) for q in part.exterior.coords[:-1]]  # type: ignore[attr-defined]
            for part in _parts(cut)
            if part.geom_type == "Polygon"  # type: ignore[attr-defined]
        ]

    def path(self, points: Sequence[XY], closed: bool = False) -> str:
        """A TikZ path through ``points`` (already local)."""
        text = " -- ".join(f"({_num(x)}, {_num(y)})" for x, y in points)
        return text + (" -- cycle" if closed else "")


def arc_points(center: Sequence[float], radius: float, start: float, delta: float) -> list[XY]:
    """Points of the arc about ``center`` from ``start`` degrees through ``delta``."""
    n = max(2, math.ceil(abs(delta) / 360.0 * _CIRCLE_POINTS) + 1)
    cx, cy = float(center[0]), float(center[1])
    return [
        (
            cx + radius * math.cos(math.radians(start + delta * i / (n - 1))),
            cy + radius * math.sin(math.radians(start + delta * i / (n - 1))),
        )
        for i in range(n)
    ]
