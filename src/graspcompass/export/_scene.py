"""A neutral 2D picture of a construction, shared by the SVG and TikZ writers.

No matplotlib here: the numbers of every object (:func:`graspcompass.geometry.evaluate`),
a view box, lines clipped to it, the signed lengths as offset arrows, the circles
on O V_n, the points grouped where they coincide (``O = O_M``), the friction
cones and object outline (the given data of Fig. 2), and the envelope k_grasp
(eq. (25)) as exact circular arcs: on the circle on the diameter O V_n the point
k_n(θ) e(θ) sits at the angle ``2θ − π − arg V_n`` about the centre V_n / 2, so
an arc of the envelope for θ in [θ0, θ1] turns by ``2(θ1 − θ0)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from .. import labelling, layout
from ..construction.describe import describe
from ..geometry.numeric import to_float
from ..layout import tex
from ..palette import PALETTE

__all__ = ["COLORS", "Label", "Scene", "build_scene", "group_points", "label_tex"]

XY = tuple[float, float]
Box = tuple[float, float, float, float]

#: Colours of the pictures: the one palette, the PNG's too (:mod:`graspcompass.palette`).
COLORS = PALETTE


@dataclass(frozen=True)
class Arc:
    """One piece of the envelope: from ``start`` about ``center``, radius ``radius``.

    Angles in degrees, counter-clockwise; ``delta == 0`` marks the zero region (O).
    """

    n: int
    start: XY
    end: XY
    center: XY
    radius: float
    start_angle: float
    delta: float


@dataclass(frozen=True)
class Label:
    """Where the label of one group of points goes (:func:`graspcompass.labelling.place`).

    ``at`` is the label's anchor in the frame of the paper, ``direction`` its
    side ``(dx, dy)`` of the point (1, 1: the label's lower left corner at
    ``at``, above right of the point; 0: centred), ``box`` its estimated extent
    ``(xmin, ymin, xmax, ymax)``, for text of :data:`graspcompass.labelling.FONT_PT`
    points in a picture :data:`graspcompass.labelling.FRAME_PT` points wide.
    """

    names: tuple[str, ...]
    at: XY
    direction: tuple[int, int]
    box: Box


@dataclass(frozen=True)
class Scene:
    """What to draw, in the frame of the paper (y up)."""

    box: Box
    lines: tuple[tuple[str, str, XY, XY], ...]  # name, role (axis/side/perp), ends
    lengths: tuple[tuple[str, XY, XY], ...]  # name, offset start and end
    circles: tuple[tuple[str, int, XY, float], ...]
    points: tuple[tuple[tuple[str, ...], XY], ...]
    envelope: tuple[Arc, ...]
    cones: tuple[tuple[XY, ...], ...]
    outline: tuple[str, tuple[float, ...]] | None
    title: str
    small: frozenset[str] = frozenset()  # points drawn small and unlabelled (break points)
    labels: tuple[Label, ...] = ()  # one per labelled group of points, in placement order

    def label_of(self, name: str) -> Label | None:
        """The label of the group of points whose first name is ``name``, or None."""
        return next((lab for lab in self.labels if lab.names[0] == name), None)


def _f(v: sp.Expr) -> float:
    return to_float(v, 20)


def label_tex(name: str) -> str:
    """The paper's label of a point name, TeX math body: ``"P1x"`` -> ``"P_{1x}"``.

    Examples
    --------
    >>> label_tex("P1x"), label_tex("O_M"), label_tex("X3"), label_tex("B12")
    ('P_{1x}', 'O_M', 'X_3', 'B_{12}')
    """
    return tex(name, math=False)


def group_points(items: list[tuple[str, XY]], tol: float) -> list[tuple[tuple[str, ...], XY]]:
    """Names of points closer than ``tol`` to each other, with the first one's place."""
    where = dict(items)
    return [(tuple(names), where[names[0]]) for names in layout.group_points(items, tol)]


def _shape(grasp: Any) -> tuple[str, tuple[float, ...]] | None:
    shape = getattr(grasp, "shape", None)
    if not shape:
        return None
    if shape[0] == "circle" and len(shape) >= 2:
        return "circle", (float(shape[1]),)
    if shape[0] == "rectangle" and len(shape) >= 3:
        return "rectangle", (float(shape[1]), float(shape[2]))
    return None


def _wedge(apex: XY, u: XY, v: XY, length: float, samples: int = 16) -> tuple[XY, ...]:
    poly = layout.wedge(apex, u, v, length, samples=samples + 1)
    return tuple((float(x), float(y)) for x, y in poly)


def _envelope(env: Any) -> tuple[Arc, ...]:
    arcs = []
    V = {n: (_f(v.x), _f(v.y)) for n, v in enumerate(env.V, start=1)}
    for a in env.arcs:
        s, e = (_f(a.start.x), _f(a.start.y)), (_f(a.end.x), _f(a.end.y))
        t0, t1 = _f(a.theta_start), _f(a.theta_end)
        if a.is_zero:
            arcs.append(Arc(0, s, e, (0.0, 0.0), 0.0, 0.0, 0.0))
            continue
        vx, vy = V[a.n]
        start = math.degrees(2 * t0 - math.pi - math.atan2(vy, vx))
        arcs.append(Arc(a.n, s, e, (vx / 2, vy / 2), math.hypot(vx, vy) / 2,
                        (start + 180.0) % 360.0 - 180.0, math.degrees(2 * (t1 - t0))))
    return tuple(arcs)


def build_scene(construction: Any, title: str | None = None, box: Box | None = None) -> Scene:
    """The numeric picture of ``construction`` (any prefix ``c.upto(i)`` too).

    ``box`` ``(xmin, xmax, ymin, ymax)`` frames it (default: the one rule
    :func:`graspcompass.layout.view_box` on its own objects); a prefix drawn in the
    whole construction's box keeps the frame of the whole, as the web page does when
    it steps through the protocol.

    Raises
    ------
    ValueError
        For a symbolic construction, which has no picture.
    """
    num = layout.numeric_objects(construction)
    grasp = construction.grasp
    outline = _shape(grasp)
    roles = layout.roles_of(construction)
    by_role = {(s.role, s.n[:1]): s.name for s in construction.steps if s.role}
    # one view box for every picture: the rule of the matplotlib drawing (layout.view_box)
    if box is None:
        box = layout.view_box(grasp, num, roles=roles)
    span = box[1] - box[0]
    lines, lengths, circles, pts = [], [], [], []
    envelope: tuple[Arc, ...] = ()
    for s in construction.steps:
        v = num[s.name]
        kind = s.kind
        if kind == "point":
            pts.append((s.name, v))
        elif kind == "line":
            role = ("axis" if s.role == "axis" else
                    "perp" if s.op == "perpendicular" else "side")
            seg = layout.clip(v[0], v[1], box)
            if seg is not None:
                lines.append((s.name, role, *seg))
        elif kind == "circle":
            circles.append((s.name, s.n[0] if s.n else 1, *v))
        elif kind == "length" and len(s.inputs) >= 3:
            a, b, axis = (num[k] for k in s.inputs[:3])
            d = axis[1]
            norm = math.hypot(*d)
            n = s.n[0] if s.n else 1
            off = (d[1] / norm * 0.012 * span * (n + 0.5), -d[0] / norm * 0.012 * span * (n + 0.5))
            a2, b2 = (a[0] + off[0], a[1] + off[1]), (b[0] + off[0], b[1] + off[1])
            seg = layout.clip_segment(a2, b2, box)
            if seg is not None and math.dist(a2, b2) > 1e-9 * span:
                lengths.append((s.name, *seg))
        elif kind == "envelope":
            envelope = _envelope(v)
    cones = []
    p1, p2 = by_role.get(("contact", (1,))), by_role.get(("contact", (2,)))
    if p1 in num and p2 in num:  # the cones between the sides by role (cone_side n)
        reach = 0.6 * math.dist(num[p1], num[p2])
        for apex, (a, b) in ((p1, (1, 3)), (p2, (2, 4))):
            sa, sb = by_role.get(("cone_side", (a,))), by_role.get(("cone_side", (b,)))
            if sa in num and sb in num:
                cones.append(_wedge(num[apex], num[sa][1], num[sb][1], reach))
    inside = [(n, xy) for n, xy in pts
              if box[0] <= xy[0] <= box[1] and box[2] <= xy[1] <= box[3]]
    small = {n for n, r in roles.items() if r == "break_point"}
    grouped = group_points([p for p in inside if p[0] not in small], 1e-9 * span)
    grouped += [((n,), xy) for n, xy in inside if n in small]
    text = title if title is not None else (getattr(grasp, "title", None) or "")
    # the break points' markers are avoided, as in the matplotlib drawing (figure.py)
    labels = _labels(box, [g for g in grouped if g[0][0] not in small], lines, lengths, circles,
                     envelope, [xy for names, xy in grouped if names[0] in small])
    return Scene(box, tuple(lines), tuple(lengths), tuple(circles), tuple(grouped), envelope,
                 tuple(cones), outline, text, frozenset(small), labels)


def _arc_points(a: Arc) -> np.ndarray:
    if a.n == 0:
        return np.array([a.start, a.end])
    t = np.radians(a.start_angle + a.delta * np.linspace(0.0, 1.0, max(2, int(abs(a.delta)))))
    return np.column_stack([a.center[0] + a.radius * np.cos(t),
                            a.center[1] + a.radius * np.sin(t)])


def _labels(box: Box, groups: list[tuple[tuple[str, ...], XY]], lines: list[Any],
            lengths: list[Any], circles: list[Any], envelope: tuple[Arc, ...],
            obstacles: list[XY] = ()) -> tuple[Label, ...]:  # type: ignore[assignment]
    """The labels of ``groups`` placed as the matplotlib drawing places them, in points."""
    s = labelling.FRAME_PT / (box[1] - box[0])

    def pt(xy: Any) -> np.ndarray:
        a = np.asarray(xy, dtype=float).reshape(-1, 2)
        return np.column_stack([(a[:, 0] - box[0]) * s, (a[:, 1] - box[2]) * s])

    t = np.linspace(0, 2 * np.pi, 100)
    curves = [pt([a, b]) for _, _, a, b in lines]
    curves += [pt(np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)]))
               for _, _, c, r in circles]
    curves += [pt([a, b]) for _, a, b in lengths]
    if envelope:
        curves.append(pt(np.vstack([_arc_points(a) for a in envelope])))
    order = sorted(groups, key=lambda g: labelling.label_order(g[0]))
    texts = ["$" + " = ".join(label_tex(n) for n in names) + "$" for names, _ in order]
    placed = labelling.place(pt([xy for _, xy in order]) if order else np.zeros((0, 2)), texts,
                             curves=curves,
                             frame=(0.0, 0.0, labelling.FRAME_PT, (box[3] - box[2]) * s),
                             obstacles=pt(obstacles) if len(obstacles) else ())
    out = []
    for (names, xy), p in zip(order, placed):
        x0, y0, x1, y1 = p.box
        out.append(Label(names, (xy[0] + p.offset[0] / s, xy[1] + p.offset[1] / s), p.direction,
                         (box[0] + x0 / s, box[2] + y0 / s, box[0] + x1 / s, box[2] + y1 / s)))
    return tuple(out)


def exact_text(obj: Any) -> str:
    """One line with the exact value of an object (ASCII, for comments)."""
    return describe(obj, ascii=True)
