"""Numbers for drawing: float values of the objects, the view box, clipping, labels text.

Part of the one picture model :mod:`graspcompass.scene`, read by
:mod:`graspcompass.render` (matplotlib) and :mod:`graspcompass.export` (SVG, TikZ,
GeoGebra); nothing here imports matplotlib.  The float values of a construction
are computed once (:func:`numeric_objects` remembers them while it lives).
"""

from __future__ import annotations

import math
import re
import weakref
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..geometry import evaluate

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

__all__ = [
    "FRAMING",
    "Box",
    "clip",
    "clip_line",
    "clip_segment",
    "group_points",
    "label_tex",
    "numeric_objects",
    "roles_of",
    "shape_extent",
    "share_numeric",
    "tex",
    "view_box",
    "wedge",
]

#: ``(xmin, xmax, ymin, ymax)``.
Box = tuple[float, float, float, float]
XY = tuple[float, float]

_NAME = re.compile(r"([A-Za-z])_?([A-Za-z0-9]*)")


def tex(name: str, math: bool = True) -> str:
    """The paper's label of a point name in mathtext: ``"P1x"`` -> ``"$P_{1x}$"``.

    Examples
    --------
    >>> tex("P1x"), tex("O_M"), tex("X3"), tex("O")
    ('$P_{1x}$', '$O_M$', '$X_3$', '$O$')
    >>> tex("B12", math=False)
    'B_{12}'
    """
    m = _NAME.fullmatch(name)
    if m is None:
        body = name
    else:
        head, rest = m.groups()
        body = head if not rest else (f"{head}_{rest}" if len(rest) == 1 else f"{head}_{{{rest}}}")
    return f"${body}$" if math else body


def label_tex(name: str) -> str:
    """The paper's label of a point name, TeX math body: ``"P1x"`` -> ``"P_{1x}"``.

    Examples
    --------
    >>> label_tex("P1x"), label_tex("O_M"), label_tex("X3"), label_tex("B12")
    ('P_{1x}', 'O_M', 'X_3', 'B_{12}')
    """
    return tex(name, math=False)


_NUMERIC: dict[int, tuple[Any, dict[str, Any]]] = {}


def numeric_objects(construction: Construction) -> dict[str, Any]:
    """Float values of every object of ``construction`` (the envelope is kept as is).

    Points become ``(x, y)``, lines ``((px, py), (dx, dy))``, circles
    ``((cx, cy), r)``, lengths a float.

    Raises
    ------
    ValueError
        For a symbolic construction, which has no picture until numbers are
        substituted (:meth:`graspcompass.Grasp.subs`).

    Notes
    -----
    Computed once per construction: a second call returns a copy of the first
    result (the cache entry goes with the construction).
    """
    key = id(construction)
    hit = _NUMERIC.get(key)
    if hit is not None and hit[0]() is construction:
        return dict(hit[1])
    out = _numeric(construction)
    try:
        ref = weakref.ref(construction, lambda _r: _NUMERIC.pop(key, None))
    except TypeError:  # an object without weak references is not remembered
        return out
    _NUMERIC[key] = (ref, out)
    return dict(out)


def share_numeric(part: Construction, values: dict[str, Any]) -> None:
    """Remember ``values`` (:func:`numeric_objects` of a construction ``part`` takes its
    steps from, by name) as the float values of ``part``, so that they are not computed
    again (a worksheet's page 1 draws the given steps of its construction alone)."""
    out = {s.name: values[s.name] for s in part.steps}
    key = id(part)
    try:
        ref = weakref.ref(part, lambda _r: _NUMERIC.pop(key, None))
    except TypeError:  # an object without weak references is not remembered
        return
    _NUMERIC[key] = (ref, out)


def _numeric(construction: Construction) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for s in construction.steps:
        if s.kind == "envelope":
            out[s.name] = s.obj
            continue
        try:
            out[s.name] = evaluate(s.obj)
        except (ValueError, TypeError) as exc:
            if not _symbolic(s.obj):
                raise ValueError(
                    f"cannot draw {s.name!r}: a value of it is beyond double precision "
                    "(1.8e308): give the construction's values in other units"
                ) from None
            raise ValueError(
                f"cannot draw {s.name!r}: the construction is symbolic ({exc}); substitute "
                "numbers for the symbols first (Grasp.subs)"
            ) from exc
    return out


def _symbolic(obj: Any, depth: int = 0) -> bool:
    """Whether a construction object (a point, line, circle, number) holds a symbol."""
    if hasattr(obj, "free_symbols"):
        return bool(obj.free_symbols)
    if depth > 3 or not hasattr(obj, "__dict__"):
        return False
    return any(_symbolic(v, depth + 1) for v in vars(obj).values())


def shape_extent(shape: Any) -> Box | None:
    """The bounding box of the object outline ``grasp.shape`` (centred at O), or None."""
    if not shape:
        return None
    kind = shape[0]
    if kind == "circle" and len(shape) >= 2:
        r = float(shape[1])
        return (-r, r, -r, r)
    if kind == "rectangle" and len(shape) >= 3:
        w, h = float(shape[1]) / 2, float(shape[2]) / 2
        return (-w, w, -h, h)
    return None


#: Roles of points that frame the picture (the break points do not: they lie on circles).
FRAMING = frozenset({"", "given", "contact", "foot", "midpoint", "X", "Y", "V"})


def roles_of(construction: Construction) -> dict[str, str]:
    """Name -> role of every step (``""`` for a step without one), the roles as data."""
    return {s.name: getattr(s, "role", "") or "" for s in construction.steps}


def view_box(
    grasp: Grasp | None,
    objects: dict[str, Any],
    margin: float = 0.08,
    factor: float = 3.0,
    square: bool = True,
    roles: dict[str, str] | None = None,
) -> Box:
    """An automatic view box of the diagram, the one rule of every picture.

    It holds O, the contacts, P1x, P2x, O_M, every X_n, Y_n, V_n, the circles
    on O V_n and the object outline, plus ``margin`` of the size on each side.
    A point far away (X_n when a cone side is nearly horizontal) is cut off:
    the box stays within ``factor`` times the largest of :math:`|V_n|`, the object
    size and the contact spread from O.  With ``roles`` (:func:`roles_of`) the
    objects are chosen by their role, not their name: every point whose role
    is in :data:`FRAMING` (a point without a role too) and every circle; the
    scale is that of the ``V`` and ``contact`` points, or of all points.
    """
    if roles is None:  # the paper's names stand for their roles (V_n, X_n, Y_n, feet, O_M)
        kinds = {"V": "V", "X": "X", "Y": "Y", "P": "foot"}
        roles = {
            name: "midpoint" if name == "O_M" else kinds.get(name[:1], "other") for name in objects
        }
        objects = {
            k: v for k, v in objects.items() if not (_is_circle(v) and not k.startswith("circle"))
        }
    return _view_box_by_roles(grasp, objects, roles, margin, factor, square)


def _is_circle(v: Any) -> bool:
    return (
        isinstance(v, tuple) and len(v) == 2 and isinstance(v[0], tuple) and isinstance(v[1], float)
    )


def _view_box_by_roles(
    grasp: Grasp | None,
    objects: dict[str, Any],
    roles: dict[str, str],
    margin: float,
    factor: float,
    square: bool,
) -> Box:
    pts: list[XY] = [(0.0, 0.0)]
    scale = 0.0
    if grasp is not None:
        for p in (grasp.P1, grasp.P2):
            xy = evaluate(p)
            pts.append(xy)
            scale = max(scale, math.hypot(*xy))
    ext = shape_extent(getattr(grasp, "shape", None))
    if ext is not None:
        pts += [(ext[0], ext[2]), (ext[1], ext[3])]
        scale = max(scale, max(abs(v) for v in ext))
    circles: list[XY] = []
    for name, v in objects.items():
        role = roles.get(name, "")
        if isinstance(v, tuple) and len(v) == 2 and isinstance(v[0], float):
            if role in FRAMING:
                pts.append(v)
                if role in ("V", "contact"):
                    scale = max(scale, math.hypot(*v))
        elif _is_circle(v):  # a circle: ((cx, cy), r)
            (cx, cy), r = v
            circles += [(cx - r, cy - r), (cx + r, cy + r)]
    if scale == 0.0:  # no V, no contact: the points themselves set the scale
        scale = max((math.hypot(*p) for p in pts), default=0.0)
    arr = np.array(pts + circles, dtype=float)
    limit = factor * (scale if scale > 0 else 1.0)
    arr = np.clip(arr, -limit, limit)
    xmin, ymin = arr.min(axis=0)
    xmax, ymax = arr.max(axis=0)
    span = max(xmax - xmin, ymax - ymin, 1e-9)
    if square:
        cx, cy = (xmin + xmax) / 2, (ymin + ymax) / 2
        xmin, xmax, ymin, ymax = cx - span / 2, cx + span / 2, cy - span / 2, cy + span / 2
    m = margin * span
    return (float(xmin - m), float(xmax + m), float(ymin - m), float(ymax + m))


def clip_line(point: XY, direction: XY, box: Box) -> tuple[XY, XY] | None:
    """The part of the infinite line ``point + t·direction`` inside ``box`` (Liang-Barsky)."""
    return clip(point, direction, box)


def clip_segment(a: XY, b: XY, box: Box) -> tuple[XY, XY] | None:
    """The part of the segment ``a b`` inside ``box``, or None."""
    return clip(a, (b[0] - a[0], b[1] - a[1]), box, 0.0, 1.0)


def clip(
    p: XY, d: XY, box: Box, t0: float = -math.inf, t1: float = math.inf
) -> tuple[XY, XY] | None:
    """The part of ``p + t·d`` (``t0 <= t <= t1``) inside ``box`` (Liang-Barsky), or None."""
    xmin, xmax, ymin, ymax = box
    for pi, di, lo, hi in ((p[0], d[0], xmin, xmax), (p[1], d[1], ymin, ymax)):
        if abs(di) < 1e-300:
            if pi < lo or pi > hi:
                return None
            continue
        ta, tb = (lo - pi) / di, (hi - pi) / di
        if ta > tb:
            ta, tb = tb, ta
        t0, t1 = max(t0, ta), min(t1, tb)
        if t0 > t1:
            return None
    if not (math.isfinite(t0) and math.isfinite(t1)):
        return None
    return ((p[0] + t0 * d[0], p[1] + t0 * d[1]), (p[0] + t1 * d[0], p[1] + t1 * d[1]))


def wedge(apex: XY, u: XY, v: XY, length: float, samples: int = 24) -> np.ndarray:
    """Polygon of the convex angular sector at ``apex`` from direction ``u`` to ``v``.

    The sector is the one of opening below π (a friction cone, 2ξ < π).
    """
    a, b = math.atan2(u[1], u[0]), math.atan2(v[1], v[0])
    delta = (b - a + math.pi) % (2 * math.pi) - math.pi
    t = a + np.linspace(0.0, delta, samples)
    arc = np.column_stack([apex[0] + length * np.cos(t), apex[1] + length * np.sin(t)])
    return np.vstack([[apex], arc, [apex]])


def group_points(items: Sequence[tuple[str, XY]], tol: float) -> list[tuple[tuple[str, ...], XY]]:
    """Names of points closer than ``tol`` to each other, with the first one's place.

    Examples
    --------
    >>> group_points([("O", (0.0, 0.0)), ("P1", (1.0, 0.0)), ("O_M", (0.0, 0.0))], 1e-9)
    [(('O', 'O_M'), (0.0, 0.0)), (('P1',), (1.0, 0.0))]
    """
    groups: list[tuple[XY, list[str]]] = []
    for name, xy in items:
        for where, names in groups:
            if math.hypot(xy[0] - where[0], xy[1] - where[1]) <= tol:
                names.append(name)
                break
        else:
            groups.append((xy, [name]))
    return [(tuple(names), where) for where, names in groups]
