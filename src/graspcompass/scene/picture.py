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

import sympy as sp

from ..construction.describe import describe
from ..geometry.numeric import to_float
from . import labelling, layout
from ._labels import labels_of
from ._numbers import NUMBER_SCALE
from ._values import INSET_PT, INSET_SHRINK, Arc, Inset, Label
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
    "NUMBER_SCALE",
    "Arc",
    "Inset",
    "Instrument",
    "Label",
    "Scene",
    "build_scene",
    "exact_text",
    "grasp_title",
    "group_points",
    "label_tex",
    "scene_of",
]

XY = tuple[float, float]
Box = tuple[float, float, float, float]

#: Colours of the pictures: the one palette, the PNG's too (:mod:`graspcompass.palette`).
COLORS = PALETTE

for _cls in (Arc, Inset, Label):  # documented, pickled and shown as this module's
    _cls.__module__ = __name__


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
    #: the zoomed views of the crowds: the crowded region first, if points crowd, then
    #: each crowd of points whose labels have no place in the whole view
    insets: tuple[Inset, ...] = ()
    #: the compass arcs, right-angle marks and guides (:mod:`graspcompass.scene.instruments`)
    instruments: tuple[Instrument, ...] = ()

    @property
    def inset(self) -> Inset | None:
        """The first inset (:attr:`insets`), or None."""
        return self.insets[0] if self.insets else None

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
        insets = tuple(
            replace(ins, labels=cut_labels(ins.labels), main=cut_labels(ins.main))
            for ins in self.insets
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
            insets=insets,
            instruments=tuple(x for x in self.instruments if ok(x.step)),
            envelope=self.envelope if ok("envelope") else (),
        )


def grasp_title(grasp: Grasp | None) -> str:
    """The grasp's own title, or one from its parameters (a grasp of one's own): the
    title of every picture of its construction.

    >>> from graspcompass import Grasp
    >>> grasp_title(Grasp(1.2, 0.3, 0.4, "61*pi/180", "118*pi/180", xi1="67*pi/180", xi2="pi/4"))
    'x1 = 1.2, x2 = 0.3, y = 0.4, φ1 = 61°, φ2 = 118°, ξ1 = 67°, ξ2 = 45°'
    """
    if grasp is None:
        return ""
    own = getattr(grasp, "title", None)
    if own:
        return str(own)
    try:
        p = grasp.params
        deg = {k: _decimal(sp.sympify(p[k]) / sp.pi * 180) for k in ("phi1", "phi2", "xi1", "xi2")}
        return (
            f"x1 = {_decimal(p['x1'])}, x2 = {_decimal(p['x2'])}, y = {_decimal(p['y'])}, "
            f"φ1 = {deg['phi1']}°, φ2 = {deg['phi2']}°, "
            f"ξ1 = {deg['xi1']}°, ξ2 = {deg['xi2']}°"
        )
    except (AttributeError, KeyError, TypeError, ValueError):
        return ""


def _decimal(v: Any) -> str:
    """``v`` as typed where it is a decimal of at most 8 places (179.75, 0.0756), else to
    6 significant digits.

    >>> _decimal(sp.Rational(719, 4)), _decimal(sp.Rational(1, 3)), _decimal(0.5)
    ('179.75', '0.333333', '0.5')
    """
    if isinstance(v, sp.Rational) or (isinstance(v, sp.Expr) and v.is_Rational):
        q = sp.Rational(v)
        for places in range(9):
            if (q * 10**places).is_integer:
                whole = abs(q.p) * 10**places // q.q
                digits = str(whole).rjust(places + 1, "0")
                text = digits[: len(digits) - places] + ("." + digits[-places:] if places else "")
                return ("-" if q < 0 else "") + text
    return f"{float(v):.6g}"


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
    break_points: bool | str = False,
    font_pt: float = labelling.FONT_PT,
    num: Mapping[str, Any] | None = None,
    with_insets: bool = True,
) -> Scene:
    """The numeric picture of ``construction`` (any prefix ``c.upto(i)`` too).

    ``box`` ``(xmin, xmax, ymin, ymax)`` frames it (default: the one rule
    :func:`graspcompass.layout.view_box` on its own objects); a prefix drawn in the
    whole construction's box keeps the frame of the whole, as the web page does when
    it steps through the protocol.  ``break_points`` labels the break points that lie
    on the envelope (an end of one of its arcs: where k_grasp passes from one circle
    to the next), placed by the rules of every label; the other break points, off
    the envelope, stay small unlabelled markers; ``"all"`` labels every break point
    (an animation names each at its step).  ``num``: the numbers of the objects
    (:func:`graspcompass.scene.layout.numeric_objects` of this construction or of one it
    is a prefix of), when the caller has them.  ``with_insets`` false leaves the insets out
    (:attr:`Scene.insets` empty; :attr:`Scene.labels` the same): for a painter that
    zooms on its own, an animation's camera.

    Raises
    ------
    ValueError
        For a symbolic construction, which has no picture.
    """
    if num is None:
        num = layout.numeric_objects(construction)
    else:
        num = {s.name: num[s.name] for s in construction.steps}
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
        if n in small
        and (
            break_points == "all"
            or (break_points and any(math.dist(xy, c) <= 1e-6 * span for c in cusps))
        )
    }
    grouped = group_points([p for p in inside if p[0] not in small], 1e-9 * span)
    grouped += group_points([p for p in inside if p[0] in on], 1e-9 * span)
    grouped += [((n,), xy) for n, xy in inside if n in small - on]
    text = title if title is not None else grasp_title(grasp)
    # the unlabelled break points' markers and the cusps are avoided, as in figure.py
    named = [g for g in grouped if g[0][0] not in small or g[0][0] in on]
    lit = [xy for n, xy in inside if n in on]  # a labelled break point's cusp is its point
    free = [a.start for a in envelope if all(math.dist(a.start, xy) > 1e-6 * span for xy in lit)]
    labels, insets = labels_of(
        box,
        named,
        lines,
        lengths,
        circles,
        envelope,
        [xy for names, xy in grouped if names[0] in small - on] + free,
        font_pt,
        with_insets,
        frozenset(small),
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
        insets=insets,
        instruments=instruments_of(construction, num, box),
    )


_SCENES: dict[tuple[int, bool, float], tuple[Any, Scene]] = {}


def scene_of(
    construction: Construction,
    title: str | None = None,
    break_points: bool = False,
    font_pt: float | None = None,
) -> Scene:
    """The :class:`Scene` of ``construction`` in its own view box, built once.

    Every painter of one construction reads this one object (the PNG, the SVG,
    the TikZ, the animation frames); it lives as long as the construction.
    ``title`` replaces the grasp's title; ``break_points`` labels the break points
    on the envelope (:func:`build_scene`), a scene of its own (cached apart).
    ``font_pt``: the labels' size in points of the placement's frame
    (:data:`~graspcompass.scene.labelling.FRAME_PT` wide; default
    :data:`~graspcompass.scene.labelling.FONT_PT`), for a painter whose labels are
    larger or smaller than that against its frame (an animation's theme): they are
    placed at the size they are drawn.
    """
    if title is not None:
        return replace(
            scene_of(construction, break_points=break_points, font_pt=font_pt), title=title
        )
    font = labelling.FONT_PT if font_pt is None else round(float(font_pt), 2)
    key = (id(construction), bool(break_points), font)
    hit = _SCENES.get(key)
    if hit is not None and hit[0]() is construction:
        return hit[1]
    scene = build_scene(construction, break_points=bool(break_points), font_pt=font)
    _SCENES[key] = (weakref.ref(construction, lambda _r: _SCENES.pop(key, None)), scene)
    return scene


def exact_text(obj: Any) -> str:
    """One line with the exact value of an object (ASCII, for comments)."""
    return describe(obj, ascii=True)
