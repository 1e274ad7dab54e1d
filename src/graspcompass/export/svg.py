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
from typing import Any
from xml.sax.saxutils import escape, quoteattr

from ..scene.labelling import FONT_PT, FRAME_PT
from ..scene.picture import COLORS, Label, Scene, exact_text, label_tex, scene_of

__all__ = ["to_svg", "write_svg"]

_SIZE = 800.0  # user units of the square picture
_MARGIN_TOP = 40.0
#: Label font in user units: the ratio font / picture width of the placement
#: (:data:`graspcompass.labelling.FONT_PT` in :data:`~graspcompass.labelling.FRAME_PT`).
_FONT = FONT_PT * _SIZE / FRAME_PT
_ANCHOR = {1: "start", -1: "end", 0: "middle"}


def _label_svg(name: str) -> str:
    """``<tspan>`` markup of a point label with its subscript."""
    body = label_tex(name).replace("{", "").replace("}", "")
    head, _, sub = body.partition("_")
    if not sub:
        return escape(head)
    return f'{escape(head)}<tspan baseline-shift="sub" font-size="70%">{escape(sub)}</tspan>'


class _Map:
    def __init__(self, scene: Scene) -> None:
        self.x0, self.x1, self.y0, self.y1 = scene.box
        self.s = _SIZE / (self.x1 - self.x0)

    def __call__(self, xy: tuple[float, float]) -> str:
        return f"{(xy[0] - self.x0) * self.s:.3f},{(self.y1 - xy[1]) * self.s + _MARGIN_TOP:.3f}"


def _label_text(lab: Label, m: _Map, label: str) -> str:
    """The ``<text>`` of a label at its place (:attr:`Scene.labels`): its side of the point.

    The placement's box is ``1.35`` font sizes high; the baseline sits ``0.3`` of
    the font size above its bottom (room for the subscripts).
    """
    x, y = (float(v) for v in m(lab.at).split(","))
    dy = lab.direction[1]
    h = 1.35 * _FONT
    bottom = y if dy == 1 else y + h if dy == -1 else y + h / 2  # SVG's y points down
    return (f'<text x="{x:.3f}" y="{bottom - 0.3 * _FONT:.3f}" '
            f'text-anchor="{_ANCHOR[lab.direction[0]]}" font-size="{_FONT:.2f}" '
            f'font-style="italic">{label}</text>')


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


def to_svg(construction: Any, title: str | None = None, step: int | None = None) -> str:
    """The SVG document of ``construction`` (numeric parameters) as text.

    ``step`` draws the picture after that step of the protocol
    (:meth:`graspcompass.scene.picture.Scene.upto`): in the whole construction's
    frame, nothing made after it drawn or named.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> text = to_svg(internal_force_diagram(Grasp.preset("fig6")))
    >>> text.startswith("<?xml") and 'viewBox="0 0 800' in text and 'id="envelope"' in text
    True
    """
    scene = scene_of(construction, title).upto(step)
    m = _Map(scene)
    steps = {s.name: s for s in construction.steps}

    def tip(name: str) -> str:
        s = steps[name]
        text = f"{s.index} {name}: {s.caption} [{s.ref}] = {exact_text(s.obj)}"
        return f"<title>{escape(text)}</title>"

    height = _SIZE + _MARGIN_TOP
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" viewBox="0 0 {_SIZE:.0f} '
           f'{height:.0f}" width="160mm" height="{160 * height / _SIZE:.1f}mm" '
           'font-family="DejaVu Serif, Times, serif">',
           f"<title>{escape(scene.title or 'internal force diagram')}</title>",
           f'<rect x="0" y="0" width="{_SIZE:.0f}" height="{height:.0f}" fill="white"/>',
           f'<text x="{_SIZE / 2:.0f}" y="26" text-anchor="middle" font-size="17">'
           f"{escape(scene.title)}</text>"]
    if scene.outline is not None:
        kind, dims = scene.outline
        style = f'fill="{COLORS["objectfill"]}" stroke="{COLORS["object"]}" stroke-width="1.2"'
        if kind == "circle":
            out.append(f'<circle id="object" cx="{m((0, 0)).split(",")[0]}" '
                       f'cy="{m((0, 0)).split(",")[1]}" r="{dims[0] * m.s:.3f}" {style}/>')
        else:
            w, h = dims
            x, y = m((-w / 2, h / 2)).split(",")
            out.append(f'<rect id="object" x="{x}" y="{y}" width="{w * m.s:.3f}" '
                       f'height="{h * m.s:.3f}" {style}/>')
    for i, cone in enumerate(scene.cones, start=1):
        pts = " ".join(m(p) for p in cone)
        out.append(f'<polygon id="cone{i}" points="{pts}" fill="{COLORS["cone"]}" '
                   'fill-opacity="0.35" stroke="none"/>')
    path = _arc_path(scene, m)
    if path:
        out.append(f'<g id="envelope" class="envelope">{tip("envelope")}<path d="{path}" '
                   f'fill="{COLORS["fill"]}" fill-opacity="0.35" stroke="{COLORS["envelope"]}" '
                   'stroke-width="3" stroke-linejoin="round"/></g>')
    for name, role, a, b in scene.lines:
        dash = ' stroke-dasharray="6,3"' if role == "perp" else ""
        width = 1.0 if role == "perp" else 1.4
        (x0, y0), (x1, y1) = m(a).split(","), m(b).split(",")
        out.append(f'<g id={quoteattr(name)} class="line {role}">{tip(name)}<line x1="{x0}" '
                   f'y1="{y0}" x2="{x1}" y2="{y1}" stroke="{COLORS[role]}" '
                   f'stroke-width="{width}"{dash}/></g>')
    for name, a, b in scene.lengths:
        (x0, y0), (x1, y1) = m(a).split(","), m(b).split(",")
        out.append(f'<g id={quoteattr(name)} class="length">{tip(name)}<line x1="{x0}" y1="{y0}" '
                   f'x2="{x1}" y2="{y1}" stroke="{COLORS["length"]}" stroke-width="0.8" '
                   'marker-end="url(#head)"/></g>')
    for name, n, c, r in scene.circles:
        x, y = m(c).split(",")
        out.append(f'<g id={quoteattr(name)} class="circle">{tip(name)}<circle cx="{x}" cy="{y}" '
                   f'r="{r * m.s:.3f}" fill="none" stroke="{COLORS.get(f"circle{n}", "black")}" '
                   'stroke-width="1.4" stroke-dasharray="8,4"/></g>')
    for names, xy in scene.points:
        x, y = m(xy).split(",")
        small = names[0] in scene.small
        label = " = ".join(_label_svg(n) for n in names)
        marker = (f'<circle cx="{x}" cy="{y}" r="{2.2 if small else 3.2}" '
                  f'fill="{"white" if small else COLORS["point"]}" stroke="{COLORS["point"]}"/>')
        lab = scene.label_of(names[0])
        text = "" if small or lab is None else _label_text(lab, m, label)
        out.append(f'<g id={quoteattr(names[0])} class="point">{tip(names[0])}{marker}{text}</g>')
    out.insert(2, '<defs><marker id="head" viewBox="0 0 10 10" refX="10" refY="5" '
               'markerWidth="6" markerHeight="6" orient="auto-start-reverse">'
               f'<path d="M0,0 L10,5 L0,10 z" fill="{COLORS["length"]}"/></marker></defs>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def write_svg(construction: Any, path: Any, title: str | None = None) -> Any:
    """Write :func:`to_svg` to ``path`` (UTF-8); returns the path.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``path`` cannot be written (its folder must exist; it is not made), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from .._output import write_output

    return write_output(path, lambda: to_svg(construction, title))
