"""Outlines of real parts from drawing files: SVG and DXF, in metres (issue 13 §1).

:func:`read_outline` reads the closed outline of a part from an SVG file (the
``svgelements`` library: every transform, arc and Bézier curve of the SVG
specification) or a DXF file (``ezdxf``: closed ``LWPOLYLINE``/``POLYLINE``
with bulges, ``CIRCLE``, ``ELLIPSE``, closed ``SPLINE``), flattens its curves to
chords, and returns a :class:`shapely.Polygon` in metres in a right-handed
frame with y up, ready for :func:`graspcompass.place_grasp` (``outline=``) and
``graspcompass size --shape FILE``.  Both libraries come with the main install
(``pip install graspcompass``; the extra ``graspcompass[outlines]`` names them too).

Frames and units
    SVG's y-axis points down: y is negated, so the part is seen as drawn.  SVG
    lengths follow CSS: ``width="100mm"`` with a ``viewBox`` makes one user unit a
    millimetre; a drawing without physical units is read at 96 user units per
    inch unless ``unit=`` says how long one user unit is (``"1mm"``).  DXF
    coordinates are in the drawing's ``$INSUNITS``; a unitless drawing is read in
    millimetres unless ``unit=`` says otherwise.

Curves
    Arcs, circles and splines are flattened to chords whose distance from the
    curve is at most ``tolerance`` times the outline's size (default 1e-4).  A
    contact on a curved part lies on a chord only to that tolerance, and a chord's
    normal differs from the curve's by up to about ``sqrt(8·tolerance)`` radians:
    for a contact on a curve give its normal (``normals=``, ``--n1``), or pick the
    contact on the flattened outline (``outline.exterior.interpolate(d)``).

Which outline
    The file must hold at least one closed shape; of several, the one with the
    largest area is the part (``element=`` picks an SVG element by its ``id`` or a
    DXF entity by its handle).  An open path, a self-intersecting outline or one of
    zero area is refused with :class:`~graspcompass.world.OutlineError`.

Examples
--------
>>> import tempfile, pathlib
>>> svg = pathlib.Path(tempfile.mkdtemp()) / "plate.svg"
>>> _ = svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" '
...                    'viewBox="0 0 100 60"><rect x="10" y="10" width="80" height="40"/></svg>')
>>> poly = read_outline(svg)
>>> round(poly.area * 1e6, 6), [round(v * 1000, 6) for v in poly.bounds]  # mm², mm
(3200.0, [10.0, -50.0, 90.0, -10.0])
"""

from __future__ import annotations

import io
import math
import os
import re
from pathlib import Path
from typing import Any

from ..boundary._infiles import read_bounded
from ..boundary.errors import GraspCompassError, InputError, InputTooLargeError, WrongTypeError
from ..world import OutlineError
from ._checks import (
    MAX_VERTICES,
    check_coordinates,
    check_extent,
    check_use_expansion,
    chord_budget,
    svg_utf8,
)

__all__ = ["DEFAULT_TOLERANCE", "MAX_OUTLINE_BYTES", "MissingExtraError", "read_outline"]

#: Largest drawing file read (bytes).
MAX_OUTLINE_BYTES = 5_000_000
#: Flattening tolerance, relative to the outline's size.
DEFAULT_TOLERANCE = 1e-4
_METRES = {"m": 1.0, "cm": 0.01, "mm": 0.001, "um": 1e-6, "in": 0.0254, "ft": 0.3048}
_UNIT = re.compile(r"\s*([0-9]*\.?[0-9]+(?:[eE][-+]?\d+)?)\s*(m|cm|mm|um|in|ft)\s*")


class MissingExtraError(InputError):
    """Reading SVG or DXF needs svgelements or ezdxf, which the main install brings.

    (Raised where they were removed: ``pip install 'graspcompass[outlines]'`` brings them
    back.)
    """


def _unit_length(unit: str | None, default: float) -> float:
    if unit is None:
        return default
    m = _UNIT.fullmatch(unit) if isinstance(unit, str) else None
    if m is None:
        raise InputError(f"unit {unit!r}: give a length such as '1mm', '0.5in' or '1m'")
    value = float(m.group(1)) * _METRES[m.group(2)]
    if not (value > 0 and math.isfinite(value)):
        raise InputError(f"unit {unit!r} must be a positive length")
    return value


def _polygon(
    rings: list[tuple[str, list[tuple[float, float]]]], where: str, element: str | None
) -> Any:
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    if element is not None:
        rings = [r for r in rings if r[0] == element]
        if not rings:
            raise OutlineError(f"{where}: no closed shape with the id or handle {element!r}")
    if not rings:
        raise OutlineError(
            f"{where}: no closed shape (an outline must be a closed path, "
            "polygon, rectangle, circle or closed polyline)"
        )
    polys = []
    for name, pts in rings:
        if len(pts) > MAX_VERTICES:
            raise InputTooLargeError(
                f"{where}: the outline {name!r} has {len(pts)} vertices "
                f"after flattening; at most {MAX_VERTICES}"
            )
        poly = Polygon(pts)
        polys.append((poly.area if poly.is_valid else -1.0, name, poly))
    area, name, poly = max(polys, key=lambda t: t[0])
    if area <= 0 or not poly.is_valid:
        raise OutlineError(
            f"{where}: the outline {name!r} is not a simple closed shape with "
            "area (it crosses itself or is degenerate)"
        )
    return orient(poly, 1.0)


# -- SVG ------------------------------------------------------------------------------------
def _svg_rings(
    data: bytes, tolerance: float, where: str
) -> list[tuple[str, list[tuple[float, float]]]]:
    try:
        from svgelements import SVG, Close, Line, Move, Path, Shape
    except ImportError:
        raise MissingExtraError(
            "reading SVG needs the optional extra graspcompass[outlines] "
            "(pip install 'graspcompass[outlines]')"
        ) from None
    check_use_expansion(data, where)  # data: svg_utf8's, without a DTD
    try:
        svg = SVG.parse(io.BytesIO(data))
        shapes = [e for e in svg.elements() if isinstance(e, Shape)]
    except Exception as exc:  # a malformed file: svgelements raises many kinds
        raise InputError(
            f"not a readable SVG file: {type(exc).__name__}: {str(exc)[:120]}"
        ) from None
    try:
        return _svg_shape_rings(shapes, tolerance, where, Close, Line, Move, Path)
    except (GraspCompassError, MemoryError):
        raise
    except Exception as exc:  # svgelements on degenerate shapes (a zero scale, ...)
        raise InputError(
            f"{where}: cannot read the SVG's shapes: {type(exc).__name__}: {str(exc)[:120]}"
        ) from None


def _svg_shape_rings(
    shapes: list, tolerance: float, where: str, Close: Any, Line: Any, Move: Any, Path: Any
) -> list[tuple[str, list[tuple[float, float]]]]:
    boxes = [Path(s).bbox() for s in shapes]
    boxes = [b for b in boxes if b is not None]
    check_coordinates([v for b in boxes for v in b], where)
    size = max((max(b[2] - b[0], b[3] - b[1]) for b in boxes), default=1.0) or 1.0
    step = max(tolerance * size, 1e-12)
    budget = chord_budget(where)
    for shape in shapes:  # every segment's chords counted before any point is made
        for seg in Path(shape).segments():
            if not isinstance(seg, (Move, Close)):
                budget.take(1 if isinstance(seg, Line) else _chords(seg, step))
    rings = []
    for k, shape in enumerate(shapes):
        name = str(shape.id) if getattr(shape, "id", None) else f"shape {k + 1}"
        pts: list[tuple[float, float]] = []
        for seg in Path(shape).segments():
            if isinstance(seg, Move):
                if len(pts) > 2:
                    break  # one outline per shape: the first subpath
                pts = [(float(seg.end.x), float(seg.end.y))]
            elif isinstance(seg, Close):
                if len(pts) > 2:
                    rings.append((name, [(x, -y) for x, y in pts]))
                pts = []
                break
            elif isinstance(seg, Line):
                pts.append((float(seg.end.x), float(seg.end.y)))
            else:
                n = _chords(seg, step)
                pts += [
                    (float(p.x), float(p.y)) for p in (seg.point(i / n) for i in range(1, n + 1))
                ]
    return rings


def _chords(seg: Any, step: float) -> int:
    """Chords of sagitta <= step for a curve (a radius of at least length/2π, the tightest
    arc of that length: chord c with c²/(8R) <= step)."""
    length = float(seg.length(error=1e-6))
    chord = math.sqrt(4 * step * max(length, step) / math.pi)
    return max(2, min(10_000, math.ceil(length / chord) + 1))


_WIDTH = re.compile(rb"<svg\b[^>]*?\bwidth\s*=\s*[\"']\s*[0-9.eE+-]+\s*(mm|cm|m)?\s*[\"']", re.S)


def _svg_px(data: bytes) -> float:
    """Metres per px, svgelements' unit.  svgelements takes 96 px per inch but 3.7795296
    px per mm (not 96/25.4): a drawing sized in mm or cm is read with its millimetre, any
    other with its inch, so that either reads exactly."""
    from svgelements import Length

    m = _WIDTH.search(data[:65536])  # data: svg_utf8's, so UTF-16 reads the same
    if m is not None and m.group(1) is not None:
        return 0.001 / float(Length("1mm").value(ppi=96))
    return 0.0254 / 96


# -- DXF ------------------------------------------------------------------------------------
def _dxf_rings(
    data: bytes, tolerance: float, where: str
) -> tuple[list[tuple[str, list[tuple[float, float]]]], int]:
    try:
        import ezdxf
        from ezdxf import path as dxfpath
        from ezdxf import recover
    except ImportError:
        raise MissingExtraError(
            "reading DXF needs the optional extra graspcompass[outlines] "
            "(pip install 'graspcompass[outlines]')"
        ) from None
    import logging
    import warnings

    log = logging.getLogger("ezdxf")
    level, log_propagates = log.level, log.propagate
    log.setLevel(logging.CRITICAL + 1)  # its warnings would be more lines on stderr
    log.propagate = False
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return _dxf_read(data, tolerance, where, ezdxf, dxfpath, recover)
    except (GraspCompassError, MemoryError):
        raise
    except Exception as exc:  # ezdxf on degenerate entities
        raise InputError(
            f"{where}: cannot read the DXF's entities: {type(exc).__name__}: {str(exc)[:120]}"
        ) from None
    finally:
        log.setLevel(level)
        log.propagate = log_propagates


def _dxf_read(
    data: bytes, tolerance: float, where: str, ezdxf: Any, dxfpath: Any, recover: Any
) -> tuple[list[tuple[str, list[tuple[float, float]]]], int]:
    try:
        doc, _ = recover.read(io.BytesIO(data))
    except Exception as exc:  # ezdxf raises DXFStructureError and others
        raise InputError(
            f"not a readable DXF file: {type(exc).__name__}: {str(exc)[:120]}"
        ) from None
    try:
        insunits = int(doc.header.get("$INSUNITS", 0) or 0)
    except (TypeError, ValueError):
        raise InputError(
            f"{where}: $INSUNITS {doc.header.get('$INSUNITS')!r} is not a unit code"
        ) from None
    entities = []
    for e in doc.modelspace():
        kind = e.dxftype()
        closed = (
            kind in ("CIRCLE", "ELLIPSE")
            or (kind in ("LWPOLYLINE", "POLYLINE") and e.is_closed)
            or (kind == "SPLINE" and e.closed)
        )
        if closed:
            entities.append(e)
    paths = []
    for e in entities:
        try:
            paths.append((e.dxf.handle, dxfpath.make_path(e)))
        except (TypeError, ValueError, ezdxf.DXFError):
            continue
    size = 1.0
    boxes = [p.control_vertices() for _, p in paths]
    check_coordinates([c for b in boxes for v in b for c in (v.x, v.y)], where)
    if any(boxes):
        xs = [v.x for b in boxes for v in b]
        ys = [v.y for b in boxes for v in b]
        size = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    rings = []
    budget = chord_budget(where)
    for handle, p in paths:
        pts = []
        for v in p.flattening(max(tolerance * size, 1e-12)):  # counted as they are made
            budget.take(1)
            pts.append((float(v.x), float(v.y)))
        if len(pts) > 1 and pts[0] == pts[-1]:
            pts.pop()
        if len(pts) > 2:
            rings.append((str(handle), pts))
    return rings, insunits


def read_outline(
    path: str | os.PathLike[str],
    *,
    unit: str | None = None,
    tolerance: float = DEFAULT_TOLERANCE,
    element: str | None = None,
) -> Any:
    """The closed outline of a part in an SVG or DXF file, in metres, y up.

    Parameters
    ----------
    path : str or path-like
        A ``.svg`` or ``.dxf`` file, at most :data:`MAX_OUTLINE_BYTES`.
    unit : str, optional
        The length of one drawing unit (``"1mm"``, ``"0.5in"``), for drawings
        without physical units: an SVG without them is otherwise read at 96 units
        per inch, a DXF without ``$INSUNITS`` in millimetres.
    tolerance : float
        Largest distance of a chord from its curve, relative to the outline's size.
    element : str, optional
        The ``id`` of an SVG element or the handle of a DXF entity; default the
        closed shape with the largest area.

    Returns
    -------
    shapely.Polygon
        Counter-clockwise, in metres; the outline of :func:`graspcompass.place_grasp`.

    Raises
    ------
    OutlineError
        No closed shape, or one that crosses itself or has no area.
    graspcompass.errors.InputError
        A file that cannot be read or parsed, a bad ``unit``, an SVG declaring
        entities; :class:`MissingExtraError` without the optional libraries;
        :class:`~graspcompass.errors.InputTooLargeError` for a file or an outline
        beyond the limits.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise WrongTypeError(
            f"path: expected a file name (str or pathlib.Path), got {type(path).__name__}"
        )
    if isinstance(tolerance, bool) or not (
        isinstance(tolerance, (int, float)) and 1e-9 <= tolerance <= 0.1
    ):
        raise InputError(f"tolerance {tolerance!r} must be a number from 1e-9 to 0.1")
    suffix = Path(path).suffix.lower()
    if suffix not in (".svg", ".dxf"):
        raise InputError(f"cannot read an outline from {str(path)!r}: use a .svg or .dxf file")
    data = read_bounded(path, MAX_OUTLINE_BYTES)
    where = str(path)
    if suffix == ".svg":
        data = svg_utf8(data)
        rings = _svg_rings(data, tolerance, where)
        scale = _unit_length(unit, _svg_px(data))
        poly = _polygon(rings, where, element)
    else:
        rings, insunits = _dxf_rings(data, tolerance, where)
        from ezdxf import units as dxfunits

        if insunits:
            scale = _dxf_scale(insunits, where, dxfunits)
        else:
            scale = _unit_length(unit, 0.001)
        poly = _polygon(rings, where, element)
    from shapely import affinity

    x0, y0, x1, y1 = poly.bounds
    check_extent(max(x1 - x0, y1 - y0) * scale, where)  # nor infinite nor zero area
    return affinity.scale(poly, xfact=scale, yfact=scale, origin=(0, 0))


def _dxf_scale(insunits: int, where: str, dxfunits: Any) -> float:
    """Metres per unit of the DXF's ``$INSUNITS`` code (1 to 24), or InputError."""
    try:
        scale = (
            float(dxfunits.conversion_factor(insunits, dxfunits.M))
            if 0 < insunits <= 24
            else math.nan
        )
    except (TypeError, ValueError, IndexError, KeyError):
        scale = math.nan
    if not (math.isfinite(scale) and scale > 0):
        raise InputError(
            f"{where}: $INSUNITS {insunits} is not a length unit this reader "
            "knows (1 to 24, see the DXF reference): give unit=, --shape-unit"
        )
    return scale
