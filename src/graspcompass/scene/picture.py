"""The one picture of a construction, computed once and read by every painter.

The matplotlib drawing (:mod:`graspcompass.render.figure`), the SVG and TikZ
writers and the GeoGebra file read the same :class:`Scene`: the objects by role,
the view box, the palette, the label placement and the step at which each
object is made, so that :meth:`Scene.upto` shows and labels nothing made after
a step (issue 23).  No matplotlib here: the numbers of every object
(:func:`graspcompass.geometry.evaluate`),
a view box, lines clipped to it, the signed lengths as offset arrows, the circles
on O V_n, the points grouped where they coincide (``O = O_M``), the friction
cones and object outline (the given data of Fig. 2), and the envelope k_grasp
(eq. (25)) as exact circular arcs: on the circle on the diameter O V_n the point
k_n(θ) e(θ) sits at the angle ``2θ − π − arg V_n`` about the centre V_n / 2, so
an arc of the envelope for θ in [θ0, θ1] turns by ``2(θ1 − θ0)``.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..construction.describe import describe
from ..geometry.numeric import to_float
from . import fit as fitting
from . import labelling, layout
from .instruments import Instrument, in_view, instruments_of
from .layout import group_points, label_tex, wedge
from .palette import PALETTE

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

__all__ = [
    "COLORS",
    "INSET_PT",
    "INSET_SHRINK",
    "Arc",
    "Inset",
    "Instrument",
    "Label",
    "Scene",
    "build_scene",
    "exact_text",
    "group_points",
    "label_tex",
    "scene_of",
]

XY = tuple[float, float]
Box = tuple[float, float, float, float]

#: Colours of the pictures: the one palette, the PNG's too (:mod:`graspcompass.palette`).
COLORS = PALETTE
#: Side in points of the zoomed inset's square frame (the main one is
#: :data:`graspcompass.scene.labelling.FRAME_PT`), its labels at the same font size.
INSET_PT = 1.25 * labelling.FRAME_PT
#: The sides of the inset tried, as fractions of the crowded region's
#: (:func:`graspcompass.scene.fit.crowded_region`): a smaller one zooms in further where
#: a label has no place that keeps every rule.
INSET_SHRINK = (1.0, 0.8, 0.64, 0.5, 0.4)


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
    #: from the point to the anchor, in points of the placement's frame (the PNG's)
    offset: XY = (0.0, 0.0)
    #: the labelled point, in the frame of the paper
    point: XY = (0.0, 0.0)
    #: a thin line from the point to the label (a label set far from a crowded point)
    leader: bool = False
    #: per name, the group of coinciding points it belongs to: names of one group are
    #: joined by an equals sign, points apart but closer than a marker (one place to
    #: the eye) by a comma (empty: all coincide)
    groups: tuple[int, ...] = ()

    def join(self, text: Any = label_tex) -> str:
        """The names, each written by ``text``, joined as they coincide."""
        out = text(self.names[0])
        for i in range(1, len(self.names)):
            same = not self.groups or self.groups[i] == self.groups[i - 1]
            out += (" = " if same else ", ") + text(self.names[i])
        return out

    def tex(self) -> str:
        """The label's TeX math body, ``O = O_M = Y_4`` (``P_1, P_{1x}`` when only near)."""
        return self.join()


@dataclass(frozen=True)
class Inset:
    """A zoomed view of the crowded region (:func:`graspcompass.scene.fit.crowded_region`).

    ``box`` ``(xmin, xmax, ymin, ymax)`` is the region in the frame of the paper;
    ``labels`` are placed in a frame of :data:`INSET_PT` points on its side.
    """

    box: Box
    labels: tuple[Label, ...]
    #: the labels of the whole view when the inset is shown beside it: those of the
    #: crowded points that break a rule there are left to the inset
    main: tuple[Label, ...] = ()

    @property
    def zoom(self) -> float:
        """Points per unit of the inset."""
        return INSET_PT / (self.box[1] - self.box[0])


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
    #: points drawn small (break points), unlabelled but for those with a label
    #: (:func:`build_scene` ``break_points``)
    small: frozenset[str] = frozenset()
    labels: tuple[Label, ...] = ()  # one per labelled group of points, in placement order
    #: name -> index of the step that makes it; ``cone1``/``cone2`` are made with their
    #: second side, ``object`` (the outline, given data) at step 0
    made: Mapping[str, int] = field(default_factory=dict)
    #: the last step shown (None: every step)
    step: int | None = None
    #: the zoomed view of the crowded region, if points crowd
    inset: Inset | None = None
    #: the compass arcs, right-angle marks and guides (:mod:`graspcompass.scene.instruments`)
    instruments: tuple[Instrument, ...] = ()

    def label_of(self, name: str) -> Label | None:
        """The label of the group of points whose first name is ``name``, or None."""
        return next((lab for lab in self.labels if lab.names[0] == name), None)

    def visible(self, name: str) -> bool:
        """Whether the object ``name`` is made at the step shown."""
        return self.step is None or self.made.get(name, math.inf) <= self.step

    def instruments_at(self, zoom: float | None = None) -> tuple[Instrument, ...]:
        """The instruments as drawn at ``zoom`` points per unit (:attr:`Inset.zoom`; the
        diagram's :data:`~graspcompass.scene.labelling.FRAME_PT` per box width if None):
        right-angle marks keep their size on the page in a zoomed view."""
        if zoom is None:
            return self.instruments
        return in_view(self.instruments, labelling.FRAME_PT / (self.box[1] - self.box[0]) / zoom)

    def upto(self, step: int | None) -> Scene:
        """The picture after step ``step``: nothing made after it is drawn or named.

        The frame and the places of the labels are the whole construction's, so
        a picture does not jump from step to step; a group of coinciding points is
        drawn and labelled by the names made so far (``O = O_M`` at step 11,
        ``O = O_M = Y_4`` from step 32 on).
        """
        if step is None:
            return self if self.step is None else replace(self, step=None)
        cut = replace(self, step=step)
        ok = cut.visible
        pts = []
        for names, xy in self.points:
            kept = tuple(n for n in names if ok(n))
            if kept:
                pts.append((kept, xy))

        def cut_labels(labs: tuple[Label, ...]) -> tuple[Label, ...]:
            out = []
            for lab in labs:
                keep = [i for i, n in enumerate(lab.names) if ok(n)]
                if keep:
                    out.append(
                        replace(
                            lab,
                            names=tuple(lab.names[i] for i in keep),
                            groups=tuple(lab.groups[i] for i in keep) if lab.groups else (),
                        )
                    )
            return tuple(out)

        labels = cut_labels(self.labels)
        inset = (
            None
            if self.inset is None
            else replace(
                self.inset, labels=cut_labels(self.inset.labels), main=cut_labels(self.inset.main)
            )
        )
        cones = tuple(c for i, c in enumerate(self.cones, start=1) if ok(f"cone{i}"))
        return replace(
            cut,
            lines=tuple(x for x in self.lines if ok(x[0])),
            lengths=tuple(x for x in self.lengths if ok(x[0])),
            circles=tuple(x for x in self.circles if ok(x[0])),
            points=tuple(pts),
            labels=labels,
            cones=cones,
            inset=inset,
            instruments=tuple(x for x in self.instruments if ok(x.step)),
            envelope=self.envelope if ok("envelope") else (),
        )


def _f(v: sp.Expr) -> float:
    return to_float(v, 20)


def _shape(grasp: Grasp | None) -> tuple[str, tuple[float, ...]] | None:
    shape = getattr(grasp, "shape", None)
    if not shape:
        return None
    if shape[0] == "circle" and len(shape) >= 2:
        return "circle", (float(shape[1]),)
    if shape[0] == "rectangle" and len(shape) >= 3:
        return "rectangle", (float(shape[1]), float(shape[2]))
    return None


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
        arcs.append(
            Arc(
                a.n,
                s,
                e,
                (vx / 2, vy / 2),
                math.hypot(vx, vy) / 2,
                (start + 180.0) % 360.0 - 180.0,
                math.degrees(2 * (t1 - t0)),
            )
        )
    return tuple(arcs)


def build_scene(
    construction: Construction,
    title: str | None = None,
    box: Box | None = None,
    break_points: bool = False,
) -> Scene:
    """The numeric picture of ``construction`` (any prefix ``c.upto(i)`` too).

    ``box`` ``(xmin, xmax, ymin, ymax)`` frames it (default: the one rule
    :func:`graspcompass.layout.view_box` on its own objects); a prefix drawn in the
    whole construction's box keeps the frame of the whole, as the web page does when
    it steps through the protocol.  ``break_points`` labels the break points that lie
    on the envelope (an end of one of its arcs: where k_grasp passes from one circle
    to the next), placed by the rules of every label; the other break points, off
    the envelope, stay small unlabelled markers.

    Raises
    ------
    ValueError
        For a symbolic construction, which has no picture.
    """
    num = layout.numeric_objects(construction)
    made: dict[str, int] = {s.name: s.index for s in construction.steps}
    made["object"] = 0
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
            role = "axis" if s.role == "axis" else "perp" if s.op == "perpendicular" else "side"
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
                poly = wedge(num[apex], num[sa][1], num[sb][1], reach, samples=17)
                cones.append(tuple((float(x), float(y)) for x, y in poly))
                made[f"cone{len(cones)}"] = max(made[sa], made[sb])
    inside = [(n, xy) for n, xy in pts if box[0] <= xy[0] <= box[1] and box[2] <= xy[1] <= box[3]]
    small = {n for n, r in roles.items() if r == "break_point"}
    cusps = [a.start for a in envelope] + [a.end for a in envelope]
    on = {  # the break points labelled on request: those at an end of an envelope arc
        n
        for n, xy in inside
        if break_points and n in small and any(math.dist(xy, c) <= 1e-6 * span for c in cusps)
    }
    grouped = group_points([p for p in inside if p[0] not in small], 1e-9 * span)
    grouped += group_points([p for p in inside if p[0] in on], 1e-9 * span)
    grouped += [((n,), xy) for n, xy in inside if n in small - on]
    text = title if title is not None else (getattr(grasp, "title", None) or "")
    # the unlabelled break points' markers and the cusps are avoided, as in figure.py
    named = [g for g in grouped if g[0][0] not in small or g[0][0] in on]
    lit = [xy for n, xy in inside if n in on]  # a labelled break point's cusp is its point
    free = [a.start for a in envelope if all(math.dist(a.start, xy) > 1e-6 * span for xy in lit)]
    labels, inset = _labels(
        box,
        named,
        lines,
        lengths,
        circles,
        envelope,
        [xy for names, xy in grouped if names[0] in small - on] + free,
    )
    return Scene(
        box,
        tuple(lines),
        tuple(lengths),
        tuple(circles),
        tuple(grouped),
        envelope,
        tuple(cones),
        outline,
        text,
        frozenset(small),
        labels,
        made,
        inset=inset,
        instruments=instruments_of(construction, num, box),
    )


_SCENES: dict[tuple[int, bool], tuple[Any, Scene]] = {}


def scene_of(
    construction: Construction, title: str | None = None, break_points: bool = False
) -> Scene:
    """The :class:`Scene` of ``construction`` in its own view box, built once.

    Every painter of one construction reads this one object (the PNG, the SVG,
    the TikZ, the animation frames); it lives as long as the construction.
    ``title`` replaces the grasp's title; ``break_points`` labels the break points
    on the envelope (:func:`build_scene`), a scene of its own (cached apart).
    """
    if title is not None:
        return replace(scene_of(construction, break_points=break_points), title=title)
    key = (id(construction), bool(break_points))
    hit = _SCENES.get(key)
    if hit is not None and hit[0]() is construction:
        return hit[1]
    scene = build_scene(construction, break_points=bool(break_points))
    _SCENES[key] = (weakref.ref(construction, lambda _r: _SCENES.pop(key, None)), scene)
    return scene


def _arc_points(a: Arc) -> np.ndarray:
    if a.n == 0:
        return np.array([a.start, a.end])
    t = np.radians(a.start_angle + a.delta * np.linspace(0.0, 1.0, max(2, int(abs(a.delta)))))
    return np.column_stack([a.center[0] + a.radius * np.cos(t), a.center[1] + a.radius * np.sin(t)])


def _labels(
    box: Box,
    groups: list[tuple[tuple[str, ...], XY]],
    lines: list[Any],
    lengths: list[Any],
    circles: list[Any],
    envelope: tuple[Arc, ...],
    obstacles: list[XY],
) -> tuple[tuple[Label, ...], Inset | None]:
    """The labels of ``groups`` in the main frame and, where points crowd, in an inset.

    The main frame's labels name every point (a painter without the inset reads
    them); :attr:`Inset.main` are those of the main frame beside the inset.

    Placed by :func:`graspcompass.scene.fit.fit` in points of a frame of
    :data:`~graspcompass.scene.labelling.FRAME_PT` (the PNG's axes).  A point of the
    crowded region whose label breaks a rule in the main frame is named in the inset only.
    """
    side = labelling.FRAME_PT
    s = side / (box[1] - box[0])
    t = np.linspace(0, 2 * np.pi, 100)
    curves = [np.asarray([a, b], dtype=float) for _, _, a, b in lines]
    curves += [
        np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)]) for _, _, c, r in circles
    ]
    curves += [np.asarray([a, b], dtype=float) for _, a, b in lengths]
    if envelope:
        curves.append(np.vstack([_arc_points(a) for a in envelope]))
    order = sorted(groups, key=lambda g: labelling.label_order(g[0]))
    anchors = [xy for _, xy in order]

    def to_pt(xy: Any, frame: Box, scale: float) -> np.ndarray:
        a = np.asarray(xy, dtype=float).reshape(-1, 2)
        return np.column_stack([(a[:, 0] - frame[0]) * scale, (a[:, 1] - frame[2]) * scale])

    region = fitting.crowded_region(to_pt(anchors, box, s), to_pt(obstacles, box, s), side)
    within = [False] * len(order)
    if region is not None:
        within = [
            region[0] <= x <= region[2] and region[1] <= y <= region[3]
            for x, y in to_pt(anchors, box, s)
        ]

    def placed(
        frame: Box,
        scale: float,
        keep: list[bool],
        optional: list[bool],
        height: float,
        avoid: tuple[Label, ...] = (),
    ) -> tuple[Label, ...]:
        idx = [i for i, k in enumerate(keep) if k]
        # groups closer than a marker are one place to the eye: one label names them all
        near = layout.group_points(
            [(str(i), (anchors[i][0] * scale, anchors[i][1] * scale)) for i in idx],
            labelling.MARKER_PT,
        )
        joined = {int(g[0]): [int(j) for j in g] for g, _ in near}
        idx = [i for i in idx if i in joined]
        names_of = {i: tuple(n for j in joined[i] for n in order[j][0]) for i in idx}
        group_of = {i: tuple(k for k, j in enumerate(joined[i]) for _ in order[j][0]) for i in idx}
        text_of = {
            i: "$"
            + ", ".join(" = ".join(label_tex(n) for n in order[j][0]) for j in joined[i])
            + "$"
            for i in idx
        }
        # the other points of a label's group: markers no label covers
        members = [anchors[j] for i in idx for j in joined[i] if j != i]
        fits = fitting.fit(
            to_pt([anchors[i] for i in idx], frame, scale),
            [text_of[i] for i in idx],
            curves=[to_pt(c, frame, scale) for c in curves],
            frame=(0.0, 0.0, (frame[1] - frame[0]) * scale, height),
            obstacles=np.vstack([to_pt(obstacles, frame, scale), to_pt(members, frame, scale)]),
            optional=[optional[i] for i in idx],
            avoid=[
                (
                    (b[0] - frame[0]) * scale,
                    (b[1] - frame[2]) * scale,
                    (b[2] - frame[0]) * scale,
                    (b[3] - frame[2]) * scale,
                )
                for b in (lab.box for lab in avoid)
            ],
        )
        out = []
        broken.append(sum(p is not None and not p.ok for p in fits))
        for i, p in zip(idx, fits):
            if p is None:
                continue
            xy, (x0, y0, x1, y1) = order[i][1], p.box
            out.append(
                Label(
                    names_of[i],
                    (xy[0] + p.offset[0] / scale, xy[1] + p.offset[1] / scale),
                    p.direction,
                    (
                        frame[0] + x0 / scale,
                        frame[2] + y0 / scale,
                        frame[0] + x1 / scale,
                        frame[2] + y1 / scale,
                    ),
                    p.offset,
                    xy,
                    p.leader,
                    group_of[i],
                )
            )
        return tuple(out)

    broken: list[int] = []  # per call of placed: how many labels break a rule
    every = [True] * len(order)
    beside = placed(box, s, every, within, (box[3] - box[2]) * s)
    if region is None:
        return beside, None
    # the labels left to the inset, set where they break the fewest rules, for the
    # painters without the inset
    done = {n for lab in beside for n in lab.names}
    rest = [not (within[i] and order[i][0][0] not in done) for i in range(len(order))]
    rest = [not r for r in rest]
    more = placed(box, s, rest, [False] * len(order), (box[3] - box[2]) * s, avoid=beside)
    main = tuple(sorted(beside + more, key=lambda lab: labelling.label_order(lab.names)))
    # the inset: the region, zoomed further (about the points left to it) while some
    # label breaks a rule there, as long as it holds every point left to it; a point
    # named in the whole view is named in the inset only where a place keeps every rule
    left = [within[i] and order[i][0][0] not in done for i in range(len(order))]
    mine = np.array([xy for xy, k in zip(anchors, left) if k]).reshape(-1, 2)
    best: tuple[tuple[int, float], Inset] | None = None
    for shrink in INSET_SHRINK:
        half = (region[2] - region[0]) * shrink / 2 / s
        if len(mine):
            lo, hi = mine.min(axis=0), mine.max(axis=0)
            half = max(half, float((hi - lo).max()) / 2 * 1.25)
            cx, cy = (lo + hi) / 2
        else:
            cx = box[0] + (region[0] + region[2]) / 2 / s
            cy = box[2] + (region[1] + region[3]) / 2 / s
        sub = (cx - half, cx + half, cy - half, cy + half)
        inside = [sub[0] <= x <= sub[1] and sub[2] <= y <= sub[3] for x, y in anchors]
        optional = [a and not b for a, b in zip(inside, left)]
        z = INSET_PT / (sub[1] - sub[0])
        labs = placed(sub, z, inside, optional, INSET_PT)
        key = (broken[-1], shrink and -shrink)
        if best is None or key < best[0]:
            best = (key, Inset(sub, labs, beside))
        if broken[-1] == 0:
            break
    assert best is not None
    return main, best[1]


def exact_text(obj: Any) -> str:
    """One line with the exact value of an object (ASCII, for comments)."""
    return describe(obj, ascii=True)
