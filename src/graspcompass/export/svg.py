"""Standalone, scalable SVG of a construction, written directly (no matplotlib).

The picture is in the paper's frame (y up) mapped to SVG user units (y down)
by ``X = (x − xmin)·s``, ``Y = (ymax − y)·s``; the root element has a
``viewBox`` and a width in ``mm`` only, so it scales.  Every object is a group
``<g id="..." class="kind">`` whose ``<title>`` holds the step's caption and
its exact value, so a browser shows them on hover.  The envelope k_grasp
(eq. (25)) is drawn with exact circular arcs (``A`` path commands).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any
from xml.sax.saxutils import escape, quoteattr

from ..scene import metrics
from ..scene.labelling import FONT_PT, FRAME_PT, MARKER_PT, SMALL_MARKER
from ..scene.picture import (
    COLORS,
    INSET_PT,
    NUMBER_SCALE,
    Label,
    Scene,
    exact_text,
    label_tex,
    scene_of,
)
from ._svg_font import FONT_STACK, font_face

if TYPE_CHECKING:
    from pathlib import Path

    from ..construction import Construction

__all__ = ["to_svg", "write_svg"]

_SIZE = 800.0  # user units of the square picture
_MARGIN_TOP = 40.0
#: Label font in user units: the ratio font / picture width of the placement
#: (:data:`graspcompass.labelling.FONT_PT` in :data:`~graspcompass.labelling.FRAME_PT`).
_FONT = FONT_PT * _SIZE / FRAME_PT
#: Marker radii in user units: the placement's marker (:data:`MARKER_PT`), a break point's.
_MARKER_R = MARKER_PT / 2 * _SIZE / FRAME_PT
_SMALL_R = SMALL_MARKER * _MARKER_R
#: The inset's side and its gap to the diagram, in user units: the font keeps its size
#: (:data:`graspcompass.scene.picture.INSET_PT` points of the placement).
_INSET = INSET_PT * _SIZE / FRAME_PT
_GAP = 24.0
#: Room under an inset for its caption.
_CAPTION = 34.0


def _label_svg(name: str) -> str:
    """``<tspan>`` markup of a point label with its subscript: the size and drop of
    :mod:`graspcompass.scene.metrics`, which the placement measured the box with."""
    out = []
    for chars, sub in metrics.runs(label_tex(name)):
        out.append(
            f'<tspan baseline-shift="{-metrics.SUB_SHIFT * _FONT:.2f}" '
            f'font-size="{metrics.SUB_SCALE * _FONT:.2f}">{escape(chars)}</tspan>'
            if sub
            else escape(chars)
        )
    return "".join(out)


class _Map:
    """Frame of the paper -> SVG user units: ``box`` onto a square ``size`` at ``(left, top)``."""

    def __init__(
        self,
        box: tuple[float, float, float, float],
        size: float = _SIZE,
        left: float = 0.0,
        top: float = _MARGIN_TOP,
    ) -> None:
        self.x0, self.x1, self.y0, self.y1 = box
        self.s = size / (self.x1 - self.x0)
        self.left, self.top = left, top

    def xy(self, p: tuple[float, float]) -> tuple[float, float]:
        return ((p[0] - self.x0) * self.s + self.left, (self.y1 - p[1]) * self.s + self.top)

    def __call__(self, p: tuple[float, float]) -> str:
        x, y = self.xy(p)
        return f"{x:.3f},{y:.3f}"


#: The white halo round a label's glyphs (SVG paint order: the stroke under the fill).
_HALO = 'paint-order="stroke" stroke="white" stroke-width="3.2" stroke-linejoin="round"'


def _label_text(lab: Label, m: _Map, label: str) -> str:
    """The ``<text>`` of a label in its box (:attr:`Scene.labels`).

    The box is the one the placement measured (:func:`graspcompass.scene.fit.label_box`):
    the text starts at its left side, the baseline :data:`~graspcompass.scene.metrics.ASCENT`
    font sizes below its top, in the font the metrics are of.  A white halo keeps the
    curves behind it from running through the glyphs.
    """
    left, top = m.xy((lab.box[0], lab.box[3]))
    return (
        f'<text x="{left:.3f}" y="{top + metrics.ASCENT * _FONT:.3f}" '
        f'font-size="{_FONT:.2f}" font-family="{FONT_STACK}" '
        f'font-style="italic" {_HALO}>{label}</text>'
    )


def _leader(lab: Label, m: _Map) -> str:
    """A thin line from the point to its label's box, for a label set far from it."""
    if not lab.leader:
        return ""
    (x0, y0, x1, y1) = lab.box
    px, py = lab.point
    near = (min(max(px, x0), x1), min(max(py, y0), y1))
    a, b = m.xy(lab.point), m.xy(near)
    return (
        f'<line class="leader" x1="{a[0]:.3f}" y1="{a[1]:.3f}" x2="{b[0]:.3f}" '
        f'y2="{b[1]:.3f}" stroke="{COLORS["point"]}" stroke-width="0.6"/>'
    )


def _arc_path(scene: Scene, m: _Map) -> str:
    if not scene.envelope:
        return ""
    parts = [f"M{m(scene.envelope[0].start)}"]
    for a in scene.envelope:
        if a.n == 0:
            parts.append(f"L{m(a.end)}")
            continue
        pieces = max(1, math.ceil(abs(a.delta) / 170.0))
        r = a.radius * m.s
        for i in range(1, pieces + 1):
            t = math.radians(a.start_angle + a.delta * i / pieces)
            end = (a.center[0] + a.radius * math.cos(t), a.center[1] + a.radius * math.sin(t))
            sweep = 0 if a.delta > 0 else 1  # y flipped: counter-clockwise is SVG's negative
            parts.append(f"A{r:.3f},{r:.3f} 0 0 {sweep} {m(end)}")
    return " ".join(parts) + " Z"


_INSTRUMENT_DASH = {
    "bisector": ' stroke-dasharray="1.5,3"',
    "coordinate": ' stroke-dasharray="1.5,2"',
    "drop": ' stroke-dasharray="6,3"',
}


def _instruments(scene: Scene, m: _Map) -> list[str]:
    """The compass arcs, right-angle marks and V_n's guides of the scene, thin
    (:mod:`graspcompass.scene.instruments`), at the zoom of ``m`` (points per unit: the
    frame is FRAME_PT points for _SIZE user units); ``data-step`` names their step."""
    out = []
    for ins in scene.instruments_at(m.s * FRAME_PT / _SIZE):
        color = (
            COLORS.get(f"circle{ins.n}", COLORS["perp"])
            if ins.role == "coordinate"
            else COLORS["perp"]
        )
        pts = " ".join(m(p) for p in ins.points)
        out.append(
            f'<polyline class="instrument {ins.role}" data-step={quoteattr(ins.step)} '
            f'points="{pts}" fill="none" stroke="{color}" stroke-width="0.7"'
            f"{_INSTRUMENT_DASH.get(ins.role, '')}/>"
        )
    return out


def _drawing(scene: Scene, m: _Map, tip: Callable[[str], str], pre: str) -> list[str]:
    """The object, the cones, the envelope, the lines, lengths and circles in ``m``."""
    out = []
    if scene.outline is not None:
        kind, dims = scene.outline
        style = f'fill="{COLORS["objectfill"]}" stroke="{COLORS["object"]}" stroke-width="1.2"'
        if kind == "circle":
            cx, cy = m.xy((0, 0))
            out.append(
                f'<circle id="{pre}object" cx="{cx:.3f}" cy="{cy:.3f}" '
                f'r="{dims[0] * m.s:.3f}" {style}/>'
            )
        else:
            w, h = dims
            x, y = m.xy((-w / 2, h / 2))
            out.append(
                f'<rect id="{pre}object" x="{x:.3f}" y="{y:.3f}" width="{w * m.s:.3f}" '
                f'height="{h * m.s:.3f}" {style}/>'
            )
    path = _arc_path(scene, m)
    if path:
        out.append(
            f'<g id="{pre}envelope" class="envelope">{tip("envelope")}<path d="{path}" '
            f'fill="{COLORS["fill"]}" fill-opacity="0.35" stroke="{COLORS["envelope"]}" '
            'stroke-width="3" stroke-linejoin="round"/></g>'
        )
    for i, cone in enumerate(scene.cones, start=1):  # over the envelope's light filling
        pts = " ".join(m(p) for p in cone)
        out.append(
            f'<polygon id="{pre}cone{i}" points="{pts}" fill="{COLORS["cone"]}" '
            'fill-opacity="0.35" stroke="none"/>'
        )
    out += _instruments(scene, m)
    for name, role, a, b in scene.lines:
        dash = ' stroke-dasharray="6,3"' if role == "perp" else ""
        width = 1.0 if role == "perp" else 1.4
        (x0, y0), (x1, y1) = m.xy(a), m.xy(b)
        out.append(
            f'<g id={quoteattr(pre + name)} class="line {role}">{tip(name)}<line '
            f'x1="{x0:.3f}" y1="{y0:.3f}" x2="{x1:.3f}" y2="{y1:.3f}" '
            f'stroke="{COLORS[role]}" stroke-width="{width}"{dash}/></g>'
        )
    for name, a, b in scene.lengths:
        (x0, y0), (x1, y1) = m.xy(a), m.xy(b)
        out.append(
            f'<g id={quoteattr(pre + name)} class="length">{tip(name)}<line '
            f'x1="{x0:.3f}" y1="{y0:.3f}" x2="{x1:.3f}" y2="{y1:.3f}" '
            f'stroke="{COLORS["length"]}" stroke-width="0.8" marker-end="url(#head)"/></g>'
        )
    for name, n, c, r in scene.circles:
        x, y = m.xy(c)
        out.append(
            f'<g id={quoteattr(pre + name)} class="circle">{tip(name)}<circle '
            f'cx="{x:.3f}" cy="{y:.3f}" r="{r * m.s:.3f}" fill="none" '
            f'stroke="{COLORS.get(f"circle{n}", "black")}" stroke-width="1.4" '
            'stroke-dasharray="8,4"/></g>'
        )
    return out


def _points(
    scene: Scene,
    m: _Map,
    labels: tuple[Label, ...],
    tip: Callable[[str], str],
    pre: str,
    box: tuple[float, float, float, float],
) -> list[str]:
    """The markers of the points in ``box`` and the ``labels``, each with a halo."""
    by_name = {lab.names[0]: lab for lab in labels}
    out = []
    for names, xy in scene.points:
        if not (box[0] <= xy[0] <= box[1] and box[2] <= xy[1] <= box[3]):
            continue
        x, y = m.xy(xy)
        small = names[0] in scene.small
        marker = (
            f'<circle cx="{x:.3f}" cy="{y:.3f}" r="{_SMALL_R if small else _MARKER_R:.4f}" '
            f'fill="{"white" if small else COLORS["point"]}" stroke="{COLORS["point"]}"/>'
        )
        lab = by_name.get(names[0])
        text = ""
        if lab is not None:  # a break point too, when labelled on request
            text = _leader(lab, m) + _label_text(lab, m, lab.join(_label_svg))
        out.append(
            f'<g id={quoteattr(pre + names[0])} class="point">{tip(names[0])}{marker}{text}</g>'
        )
    return out


def to_svg(
    construction: Construction,
    title: str | None = None,
    step: int | None = None,
    break_points: bool = False,
) -> str:
    """The SVG document of ``construction`` (numeric parameters) as text.

    ``step`` draws the picture after that step of the protocol
    (:meth:`graspcompass.scene.picture.Scene.upto`): in the whole construction's
    frame, nothing made after it drawn or named.  Where points crowd, a zoomed
    inset of each crowd (:attr:`Scene.insets`) stands right of the diagram, one above
    the other, with the labels that have no room in the whole view.  ``break_points`` labels the
    break points on the envelope (:func:`graspcompass.scene.picture.build_scene`).

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> text = to_svg(internal_force_diagram(Grasp.preset("fig6")))
    >>> text.startswith("<?xml") and 'viewBox="0 0 ' in text and 'id="envelope"' in text
    True
    """
    scene = scene_of(construction, title, break_points).upto(step)
    m = _Map(scene.box)
    steps = {s.name: s for s in construction.steps}

    def tip(name: str) -> str:
        s = steps[name]
        text = f"{s.index} {name}: {s.caption} [{s.ref}] = {exact_text(s.obj)}"
        return f"<title>{escape(text)}</title>"

    insets = scene.insets
    width = _SIZE + (_GAP + _INSET if insets else 0.0)
    # the insets one above the other right of the diagram, each with its caption under it
    step_down = _INSET + _CAPTION
    height = _MARGIN_TOP + max(_SIZE, len(insets) * step_down)
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" viewBox="0 0 {width:.0f} '
        f'{height:.0f}" width="{160 * width / _SIZE:.1f}mm" '
        f'height="{160 * height / _SIZE:.1f}mm" font-family="DejaVu Serif, Times, serif">',
        f"<title>{escape(scene.title or 'internal force diagram')}</title>",
        f'<rect x="0" y="0" width="{width:.0f}" height="{height:.0f}" fill="white"/>',
        f'<text x="{_SIZE / 2:.0f}" y="26" text-anchor="middle" font-size="17">'
        f"{escape(scene.title)}</text>",
        '<g class="panel" id="main">',
    ]
    out += _drawing(scene, m, tip, "")
    for k, inset in enumerate(insets):
        (a, b), (c, d) = m.xy((inset.box[0], inset.box[3])), m.xy((inset.box[1], inset.box[2]))
        out.append(
            f'<rect class="region" x="{a:.3f}" y="{b:.3f}" width="{c - a:.3f}" '
            f'height="{d - b:.3f}" fill="none" stroke="{COLORS["axis"]}" '
            'stroke-width="0.8" stroke-dasharray="3,2"/>'
        )
        if inset.number is not None:  # the squares numbered as their insets
            nx, ny = m.xy(inset.number)
            out.append(
                f'<text class="region-number" x="{nx:.3f}" y="{ny:.3f}" '
                f'text-anchor="middle" dominant-baseline="central" '
                f'font-size="{NUMBER_SCALE * _FONT:.2f}" font-family="{FONT_STACK}" '
                f'fill="{COLORS["axis"]}">{k + 1}</text>'
            )
    out += _points(scene, m, scene.labels if not insets else insets[0].main, tip, "", scene.box)
    out.append("</g>")
    for k, inset in enumerate(insets):
        left, top = _SIZE + _GAP, _MARGIN_TOP + k * step_down
        z = _Map(inset.box, _INSET, left, top)
        key = "inset" if k == 0 else f"inset{k + 1}"
        out.append(
            f'<clipPath id="{key}-clip"><rect x="{left:.3f}" y="{top:.3f}" '
            f'width="{_INSET:.3f}" height="{_INSET:.3f}"/></clipPath>'
        )
        out.append(
            f'<g class="panel" id="{key}">'
            f'<g id="{key}-drawing" class="drawing" clip-path="url(#{key}-clip)">'
            f'<rect x="{left:.3f}" y="{top:.3f}" width="{_INSET:.3f}" '
            f'height="{_INSET:.3f}" fill="white"/>'
        )
        out += _drawing(scene, z, tip, f"{key}-")
        out.append("</g>")
        out += _points(scene, z, inset.labels, tip, f"{key}-", inset.box)
        out.append(
            f'<rect x="{left:.3f}" y="{top:.3f}" width="{_INSET:.3f}" '
            f'height="{_INSET:.3f}" fill="none" stroke="{COLORS["axis"]}" '
            'stroke-width="0.8"/>'
        )
        which = "the dashed square" if len(insets) == 1 else f"dashed square {k + 1}"
        out.append(
            f'<text x="{left + _INSET / 2:.1f}" y="{top + _INSET + 22:.1f}" '
            f'text-anchor="middle" font-size="14">{which}, '
            f"{z.s / m.s:.1f}"
            "× larger</text></g>"
        )
    out.insert(
        2,
        f"<defs><style>{font_face()}</style>"
        '<marker id="head" viewBox="0 0 10 10" refX="10" refY="5" '
        'markerWidth="6" markerHeight="6" orient="auto-start-reverse">'
        f'<path d="M0,0 L10,5 L0,10 z" fill="{COLORS["length"]}"/></marker></defs>',
    )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def write_svg(
    construction: Construction, path: Any, title: str | None = None, break_points: bool = False
) -> Path:
    """Write :func:`to_svg` to ``path`` (UTF-8); returns the path.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``path`` cannot be written (its folder must exist; it is not made), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from ..boundary._output import write_output

    return write_output(path, lambda: to_svg(construction, title, break_points=break_points))
