"""Outlines: the object's polygon, its centroid, and the inward normal at a contact.

An outline is a shapely Polygon (floats) or a sequence of vertices (read exactly
like the points).  :func:`_outline` orients every ring with the material on its
left and takes the centroid of a uniform polygon (the shoelace sums, exact for
exact vertices); :func:`_outline_normal` gives the inward unit normal of the
edge a contact lies on, or at a vertex refuses (:class:`VertexContactError`) or
takes the bisector of the two edges' normals (the rules in
:mod:`graspcompass.world`).

Examples
--------
>>> box = _outline([(-2, -4), (2, -4), (2, 4), (-2, 4)], True)
>>> box.centroid, _outline_normal(box, (2, 1), "A", "refuse", True)
((0, 0), ((-1, 0), False))
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from ..boundary.errors import WrongTypeError
from ..geometry.exact import canon
from ._arith import (
    ON_OUTLINE_TOL,
    Vec,
    _as_kind,
    _c,
    _cross,
    _dot,
    _pt,
    _scaled,
    _sign,
    _sqrt,
    _sub,
    _vec,
)
from ._errors import ContactOffOutlineError, OutlineError, VertexContactError

__all__: list[str] = []


@dataclasses.dataclass(frozen=True)
class _Outline:
    rings: tuple[tuple[Vec, ...], ...]  # material on the left of every edge
    centroid: Vec
    size: float  # largest |coordinate|, the scale of the float tolerance


def _outline(outline: Any, exact: bool) -> _Outline:
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    if hasattr(outline, "geom_type") and not isinstance(outline, Polygon):
        raise OutlineError(
            f"the outline must be one shapely Polygon, got a "
            f"{outline.geom_type}"
            + (" (pick one of its polygons)" if "Multi" in str(outline.geom_type) else "")
        )
    if isinstance(outline, Polygon):
        if outline.is_empty or not outline.is_valid or outline.area <= 0:
            raise OutlineError(
                "the outline is not a valid polygon with area (shapely "
                "is_valid is False, or it is empty)"
            )
        poly = orient(outline, 1.0)  # exterior counter-clockwise, holes clockwise
        rings = tuple(
            tuple((float(x), float(y)) for x, y in list(r.coords)[:-1])
            for r in (poly.exterior, *poly.interiors)
        )
        c = poly.centroid
        size = max(abs(v) for r in rings for p in r for v in p)
        return _Outline(rings, (float(c.x), float(c.y)), size)
    pts = [(_as_kind(x, exact), _as_kind(y, exact)) for x, y in outline]
    if len(pts) >= 2 and pts[0] == pts[-1]:
        pts = pts[:-1]  # a closed ring given with its first vertex repeated
    if len(pts) < 3 or not Polygon([(float(x), float(y)) for x, y in pts]).is_valid:
        raise OutlineError(
            "the outline must be a simple polygon of at least 3 vertices (its edges must not cross)"
        )
    # the centroid of a uniform polygon (shoelace sums), exact for exact vertices
    a2 = cx = cy = 0
    for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
        w = x0 * y1 - x1 * y0
        a2, cx, cy = a2 + w, cx + (x0 + x1) * w, cy + (y0 + y1) * w
    if _sign(a2, exact) == -1:
        pts = pts[::-1]
    elif _sign(a2, exact) == 0:
        raise OutlineError("the outline has zero area")
    centroid = _c((cx / (3 * a2), cy / (3 * a2)), exact)
    size = max(abs(float(v)) for p in pts for v in p)
    return _Outline((tuple(pts),), centroid, size)


def _vertices(outline: Any) -> list[Vec]:
    """The vertices of an outline given as a sequence, through the input boundary."""
    if isinstance(outline, (str, bytes, dict)):
        raise WrongTypeError(
            "outline: expected a shapely Polygon or a sequence of (x, y) "
            f"vertices, got {type(outline).__name__}"
        )
    try:
        return [_vec(p, f"outline vertex {i}") for i, p in enumerate(outline)]
    except TypeError:
        raise WrongTypeError(
            "outline: expected a shapely Polygon or a sequence of (x, y) "
            f"vertices, got {type(outline).__name__}"
        ) from None


def _inward(p: Vec, q: Vec, exact: bool) -> Vec:
    """Unit normal to the edge p → q on its left (the material's side)."""
    e = _sub(q, p)
    return _scaled((-e[1], e[0]), 1 / _sqrt(_dot(e, e), exact), exact)


def _outline_normal(
    out: _Outline, x: Vec, name: str, at_vertex: str, exact: bool
) -> tuple[Vec, bool]:
    """The inward normal of the outline at contact ``x`` and whether x is a vertex."""
    tol = ON_OUTLINE_TOL * max(out.size, 1.0)
    for ring in out.rings:  # vertices first: a vertex also ends two edges
        for i, p in enumerate(ring):
            if not _near(x, p, tol, exact):
                continue
            if at_vertex != "bisector":
                raise VertexContactError(
                    f"contact {name} at {_pt(x)} is at a vertex {_pt(p)} of the outline, "
                    "where the normal is undefined: move it onto an edge, give its normal "
                    "(normals=...), or pass at_vertex='bisector'"
                )
            a = _inward(ring[i - 1], p, exact)
            b = _inward(p, ring[(i + 1) % len(ring)], exact)
            s = (a[0] + b[0], a[1] + b[1])
            if _sign(_dot(s, s), exact) != 1:
                raise VertexContactError(
                    f"contact {name} at {_pt(x)}: the outline "
                    "folds back at this vertex (no bisector)"
                )
            return _scaled(s, 1 / _sqrt(_dot(s, s), exact), exact), True
    for ring in out.rings:
        for p, q in zip(ring, ring[1:] + ring[:1]):
            if _on_segment(x, p, q, tol, exact):
                return _inward(p, q, exact), False
    raise ContactOffOutlineError(
        f"contact {name} at {_pt(x)} does not lie on the outline"
        + ("" if exact else f" (tolerance {tol:.2g})")
    )


def _near(x: Vec, p: Vec, tol: float, exact: bool) -> bool:
    if exact:
        return canon(x[0] - p[0]) == 0 and canon(x[1] - p[1]) == 0
    return math.hypot(x[0] - p[0], x[1] - p[1]) <= tol


def _on_segment(x: Vec, p: Vec, q: Vec, tol: float, exact: bool) -> bool:
    e, r = _sub(q, p), _sub(x, p)
    t = _dot(r, e)
    if exact:
        return (
            _sign(_cross(e, r), True) == 0
            and _sign(t, True) in (0, 1)
            and _sign(_dot(e, e) - t, True) in (0, 1)
        )
    ee = _dot(e, e)
    u = min(max(t / ee, 0.0), 1.0)
    return math.hypot(r[0] - u * e[0], r[1] - u * e[1]) <= tol
