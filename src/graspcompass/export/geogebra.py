"""GeoGebra ``.ggb`` of a construction: a live construction on sliders, in protocol order.

A ``.ggb`` file is a zip archive holding ``geogebra.xml``.  The construction
written here starts with seven free sliders ``x_1, x_2, y_P, φ_1, φ_2, μ_1, μ_2``
(φ angle sliders shown in degrees, μ = tan ξ), holding the grasp's values and shown in
the Algebra view, not over the drawing; then every
step of the protocol, in order, as a GeoGebra command (``Intersect``,
``OrthogonalLine``, ``ClosestPoint``, ``Midpoint``, ``Circle``, ``Mirror``,
``CurveCartesian``) or a dependent expression (``P1 = (x_1, y_P)``,
``OMX1 = x(X1) - x(O_M)``, ``V1 = (-1 * OMX1, -1 * OY1)``), never as fixed
coordinates.  Moving a slider, or dragging P1 (which moves x_1 and y_P),
updates the whole construction, the friction cones (``Polygon`` on the cone sides,
added once both sides exist), V_n by compass transfer (O_M X_n carried to O and
reversed, ``Mirror[Translate[X_n, Vector[O_M, O]], O]``, and ``Mirror[Y_n, O]``, each
on its ``Circle`` about O; V_n where the perpendiculars to the axes there meet), the
four circles and the envelope
``kGrasp`` (the curve of k_grasp(θ) e(θ), eq. (25), with k_grasp in short hidden
functions, one line each: ``k_n(t) = x(V_n) sin(t) - y(V_n) cos(t)`` (32), the larger
of two, ``kg(t)`` the largest and 0).  Each object carries its
step's caption (``<caption>``), shown in GeoGebra's construction protocol, whose
navigation bar (play, protocol button) is switched on; the key steps (V_n, the
circles, the envelope) are breakpoints of the protocol's navigation, which opens on the
last step (the whole construction).  Labels are
the step names, except ``x-axis`` -> ``axisX``,
``y-axis`` -> ``axisY`` and ``envelope`` -> ``kGrasp``.  The view is the one view box
of every picture (:func:`graspcompass.layout.view_box`), the colours the one palette
(:mod:`graspcompass.palette`), and each point's name sits where the one label placement
(:mod:`graspcompass.labelling`, through the SVG/TikZ scene) puts it: a ``labelOffset``
from GeoGebra's own place for it, in a label font of the same size relative to the view.

The XML follows the tags documented for ``geogebra.xml`` (``<geogebra
format="5.0">``, ``<euclidianView>``, ``<kernel>``, ``<construction>`` with
``<element>``, ``<command>`` with ``<input a0=...>``/``<output a0=...>`` and
``<expression label= exp=>``); GeoGebra's published schema (``ggb.xsd``) could not
be obtained here, so the tests check the structure against those documented tags.
"""

from __future__ import annotations

import io
import math
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING, Any
from xml.sax.saxutils import quoteattr

import sympy as sp

from ..geometry import Line, Point
from ..geometry.numeric import to_float
from ..scene import labelling
from ..scene.palette import rgb
from ..scene.picture import build_scene, label_tex
from . import _ggb_program as _prog
from ._ggb_defs import _SIDE, SLIDERS, definition, envelope_functions, ggb_label

if TYPE_CHECKING:
    from ..construction import Construction
    from ..construction.program import Program
    from ..construction.protocol import Step
    from ..grasp import Grasp
    from ..scene.picture import Scene

__all__ = ["SLIDERS", "ggb_xml", "read_ggb_xml", "to_ggb", "write_ggb"]

_W, _H = 960, 720  # graphics view, pixels
_LEFT = 0  # the sliders are in the Algebra view, not over the drawing (issue 23)
_POINT_SIZE = 4  # of the labelled points (GeoGebra's pointSize, pixels)
_RGB = {
    role: rgb(role)
    for role in (
        "axis",
        "side",
        "perp",
        "point",
        "envelope",
        "circle1",
        "circle2",
        "circle3",
        "circle4",
    )
}


def _f(v: Any) -> float:
    return to_float(v, 17)


def _a(**attrs: Any) -> str:
    return " ".join(f"{k}={quoteattr(str(v))}" for k, v in attrs.items())


def _slider_range(param: str, value: float) -> tuple[float, float]:
    if param.startswith("phi"):
        return 0.01, round(math.pi, 6)
    low = 0.0 if param == "y" else 0.01
    return low, float(max(3.0 if param.startswith("mu") else 4.0, math.ceil(2 * value)))


def _sliders(grasp: Grasp) -> list[str]:
    """The sliders: shown in the Algebra view only (not over the drawing); φ_1, φ_2 are
    angle sliders, shown in degrees (GeoGebra keeps an angle's value in radians)."""
    out = []
    for i, (label, param, caption) in enumerate(SLIDERS):
        value = _f(grasp.params[param])
        lo, hi = _slider_range(param, value)
        angle = param.startswith("phi")
        extra = [f"\t<angleStyle {_a(val=3)}/>"] if angle else []  # any angle, no reflex
        out += [
            f"<element {_a(type='angle' if angle else 'numeric', label=label)}>",
            f"\t<caption {_a(val=caption.replace('(rad)', '(°)'))}/>",
            f"\t<value {_a(val=repr(value))}/>",
            f"\t<slider {_a(min=repr(lo), max=repr(hi), width=180, x=20, y=30 + 36 * i)} "
            f"{_a(fixed='true', horizontal='true', showAlgebra='true')} "
            f"{_a(absoluteScreenLocation='true')}/>",
            *extra,
            f"\t<show {_a(object='false', label='true')}/>",
            f"\t<labelMode {_a(val=1)}/>",
            # a step of 1° for the angles (kept in radians), 0.01 for the others
            f"\t<animation {_a(step=repr(math.pi / 180) if angle else '0.01')} "
            f"{_a(speed=1, type=0, playing='false')}/>",
            "</element>",
        ]
    return out


def _style(step: Step, offset: tuple[int, int] | None = None) -> list[str]:
    kind = step.kind
    small = step.role == "break_point"  # roles as data, never names
    n = step.n[0] if step.n else 1
    role = (
        "axis"
        if step.role == "axis"
        else "perp"
        if step.op == "perpendicular"
        else "side"
        if kind == "line"
        else f"circle{n}"
        if kind == "circle"
        else "envelope"
        if kind == "envelope"
        else "point"
    )
    r, g, b = _RGB.get(role, (17, 17, 17))
    shown = kind != "length"
    label = kind == "point" and not small
    out = [
        f"<show {_a(object=str(shown).lower(), label=str(label).lower())}/>",
        f"<objColor {_a(r=r, g=g, b=b, alpha=0.12 if kind == 'envelope' else 0)}/>",
        f"<labelMode {_a(val=0)}/>",
    ]
    if kind in ("line", "circle", "envelope"):
        thick = {"perp": 2, "axis": 3, "envelope": 7}.get(role, 4)
        dashed = role == "perp" or kind == "circle"
        out.append(f"<lineStyle {_a(thickness=thick, type=15 if dashed else 0)}/>")
    if kind == "point":
        out.append(f"<pointSize {_a(val=2 if small else _POINT_SIZE)}/>")
    if label and offset is not None:
        out.append(f"<labelOffset {_a(x=offset[0], y=offset[1])}/>")
    obj = step.obj
    if isinstance(obj, Point):
        out.append(f"<coords {_a(x=repr(_f(obj.x)), y=repr(_f(obj.y)), z='1.0')}/>")
    elif isinstance(obj, Line):
        a, b_, c = (repr(_f(v)) for v in obj.coefficients())
        out.append(f"<coords {_a(x=a, y=b_, z=c)}/>")
    elif kind == "length":
        out.append(f"<value {_a(val=repr(_f(obj)))}/>")
    return out


def _frame(box: tuple[float, float, float, float]) -> tuple[float, float, float]:
    """GeoGebra's ``xZero``, ``yZero`` and ``scale`` (pixels per unit) of the view box."""
    xs, ys = [box[0], box[1]], [box[2], box[3]]
    scale = min((_W - _LEFT) / (max(xs) - min(xs) + 1e-6), _H / (max(ys) - min(ys) + 1e-6)) / 1.1
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    return _LEFT + (_W - _LEFT) / 2 - cx * scale, _H / 2 + cy * scale, scale


def _font_px(box: tuple[float, float, float, float], scale: float) -> int:
    """The label font in pixels: labelling.FONT_PT in a frame FRAME_PT wide, as everywhere."""
    return max(8, round(labelling.FONT_PT * scale * (box[1] - box[0]) / labelling.FRAME_PT))


def _label_offsets(scene: Scene, frame: tuple[float, float, float]) -> dict[str, tuple[int, int]]:
    """``labelOffset`` (pixels, y down) of each labelled point: its label where the one
    placement (:mod:`graspcompass.labelling`, the scene's labels) puts it.

    GeoGebra draws a point's name with its baseline's left end at (x + 4, y − 2 s) for a
    point of size s at (x, y) on the screen, plus the offset.  Points that coincide share
    one label in the other pictures ("O = O_M"); here each keeps its own, side by side in
    the group's place, so that each follows its point when a slider separates them.
    """
    x_zero, y_zero, scale = frame
    px_per_pt = scale * (scene.box[1] - scene.box[0]) / labelling.FRAME_PT
    font = labelling.FONT_PT
    where = {names[0]: xy for names, xy in scene.points}
    out = {}
    for lab in scene.labels:
        x0, y0 = lab.box[0], lab.box[1]
        left = x_zero + x0 * scale
        base = y_zero - y0 * scale - 0.3 * 1.35 * font * px_per_pt  # above the box's bottom
        px, py = where[lab.names[0]]
        sx, sy = x_zero + px * scale, y_zero - py * scale
        for name in lab.names:
            out[name] = (round(left - (sx + 4)), round(base - (sy - 2 * _POINT_SIZE)))
            width = labelling.text_size("$" + label_tex(name) + " $", font)[0]
            left += width * px_per_pt
    return out


def _view(construction: Construction, scene: Scene) -> list[str]:
    # the one view box of every picture (layout.view_box, objects chosen by role)
    x0, y0, scale = _frame(scene.box)
    return [
        "<gui>",
        f"\t<window {_a(width=_W + 300, height=_H + 160)}/>",
        f"\t<font {_a(size=_font_px(scene.box, scale))}/>",
        # the construction protocol, with its navigation bar (play, and the protocol
        # button) under the drawing; the key steps are its breakpoints
        f"\t<consProtColumns {_a(col0='true', col1='true', col2='false', col3='true')} "
        f"{_a(col4='true', col5='true', col6='true')}/>",
        f"\t<consProtocol {_a(useColors='true', addIcons='false')} "
        f"{_a(showOnlyBreakpoints='false')}/>",
        # (show: GeoGebra 4 reads it; id: the view GeoGebra 5 puts the bar under)
        f"\t<consProtNavigationBar {_a(show='true', id=1, playButton='true')} "
        f"{_a(playDelay='2.0', protButton='true', consStep='-1')}/>",
        "</gui>",
        "<euclidianView>",
        f"\t<size {_a(width=_W, height=_H)}/>",
        f"\t<coordSystem {_a(xZero=repr(x0), yZero=repr(y0))}"
        f" {_a(scale=repr(scale), yscale=repr(scale))}/>",
        f"\t<evSettings {_a(axes='false', grid='false', gridIsBold='false')} "
        f"{_a(pointCapturing=3, rightAngleStyle=1, checkboxSize=13, gridType=0)}/>",
        # the construction draws its own axes (steps 1, 2): GeoGebra's stay hidden, in
        # GeoGebra 4 (axis tags) as in 5 (evSettings)
        *(
            f"\t<axis {_a(id=i, show='false', label='', unitLabel='', tickStyle=1)} "
            f"{_a(showNumbers='true')}/>"
            for i in (0, 1)
        ),
        "</euclidianView>",
    ]


def ggb_xml(
    construction: Construction,
    title: str | None = None,
    program: Program | None = None,
    values: Any = None,
) -> str:
    """The ``geogebra.xml`` text of ``construction`` (numeric parameters).

    With the construction file's ``program`` and its parameters' ``values`` (the
    replay's), the parameters are sliders and each claim is a ``Prove``
    (:mod:`graspcompass.export._ggb_program`).

    Raises
    ------
    ValueError
        For a symbolic construction (sliders need numbers) or an unknown operation.
    """
    grasp = construction.grasp
    steps = {s.name: s for s in construction.steps}
    if grasp is not None and any(_has_symbols(v) for v in grasp.params.values()):
        raise ValueError(
            "cannot write a symbolic construction to GeoGebra: its sliders need "
            "numbers; substitute values first (Grasp.subs)"
        )
    text = title if title is not None else (getattr(grasp, "title", None) or "")
    scene = build_scene(construction)
    offsets = _label_offsets(scene, _frame(scene.box))
    out = [
        '<?xml version="1.0" encoding="utf-8"?>',
        f"<geogebra {_a(format='5.0', version='5.0.0.0', app='classic', platform='d')} "
        'xsi:noNamespaceSchemaLocation="http://www.geogebra.org/apps/xsd/ggb.xsd" '
        'xmlns="" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">',
        *_view(construction, scene),
        "<kernel>",
        f"\t<continuous {_a(val='false')}/>",
        f"\t<decimals {_a(val=4)}/>",
        f"\t<angleUnit {_a(val='degree')}/>",
        f"\t<coordStyle {_a(val=0)}/>",
        "</kernel>",
        f"<construction {_a(title=text, author='graspcompass', date='')}>",
    ]
    if grasp is not None:
        out += _sliders(grasp)
    live = {}
    if program is not None and values is not None and grasp is None:
        out += _prog.sliders(program, values)
        live = _prog.symbolic_values(program)
    sides_done: dict[int, int] = {1: 0, 2: 0}
    for s in construction.steps:
        d = definition(s, steps, grasp is not None)
        if s.name in live:
            d = _prog.live(d, s, live[s.name])
        label = ggb_label(s.name)
        transfer = _transfer(s, steps) if grasp is not None else None
        if s.op == "envelope" and d.command is not None:  # k_n, their maxima: one line each
            for flabel, body, caption in envelope_functions(s, steps):
                out += [
                    f"<expression {_a(label=flabel, exp=f'{flabel}(t) = {body}')}/>",
                    f"<element {_a(type='function', label=flabel)}>",
                    f"\t<show {_a(object='false', label='false')}/>",
                    f"\t<caption {_a(val=caption)}/>",
                    "</element>",
                ]
        if transfer is not None:  # V_n by compass (Mirror, Circle), not by coordinates
            out += transfer
            d = type(d)("point", "Intersect")
        elif d.command is None:
            out.append(
                f"<expression {_a(label=label, exp=d.exp)}"
                + (f" {_a(type='point')}" if d.element == "point" else "")
                + "/>"
            )
        else:
            args = _a(**{f"a{i}": v for i, v in enumerate(d.inputs)})
            var = f" {_a(var=d.var)}" if d.var else ""
            out += [
                f"<command {_a(name=d.command)}{var}>",
                f"\t<input {args}/>",
                f"\t<output {_a(a0=label)}/>",
                "</command>",
            ]
        out.append(f"<element {_a(type=d.element, label=label)}>")
        out += ["\t" + line for line in _style(s, offsets.get(s.name))]
        out.append(f"\t<caption {_a(val=s.caption)}/>")
        if s.key:
            out.append(f"\t<breakpoint {_a(val='true')}/>")
        out.append("</element>")
        if grasp is not None and s.role == "cone_side" and s.n and s.n[0] in _SIDE:
            i = 1 if s.n[0] in (1, 3) else 2
            sides_done[i] += 1
            contacts = {
                t.n[0]: ggb_label(t.name) for t in construction.steps if t.role == "contact" and t.n
            }
            if sides_done[i] == 2 and {1, 2} <= set(contacts):  # once both sides exist
                out += _cone(i, contacts)
    if program is not None and grasp is None:
        out += _prog.claim_statements(program)
    out += ["</construction>", "</geogebra>"]
    # the navigation bar opens on the last step, the whole construction (GeoGebra 4 shows
    # none at -1); its steps are the construction's elements, counted from 0
    steps_made = sum(line.startswith("<element ") for line in out)
    text = "\n".join(out).replace('consStep="-1"', f'consStep="{max(steps_made - 1, 0)}"', 1)
    return text + "\n"


def _element(
    kind: str,
    label: str,
    caption: str,
    style: list[str],
    command: str | None = None,
    inputs: tuple[str, ...] = (),
) -> list[str]:
    """One GeoGebra object made by ``command`` (or an expression when None)."""
    args = _a(**{f"a{i}": v for i, v in enumerate(inputs)})
    head = (
        [
            f"<command {_a(name=command)}>",
            f"\t<input {args}/>",
            f"\t<output {_a(a0=label)}/>",
            "</command>",
        ]
        if command
        else []
    )
    return [
        *head,
        f"<element {_a(type=kind, label=label)}>",
        *("\t" + x for x in style),
        f"\t<caption {_a(val=caption)}/>",
        "</element>",
    ]


_FAINT = [
    f"<objColor {_a(r=150, g=150, b=150, alpha=0)}/>",
    f"<lineStyle {_a(thickness=1, type=10)}/>",
]


def _transfer(s: Step, steps: dict[str, Any]) -> list[str] | None:
    """V_n = (−O_M X_n, −O Y_n) (eq. (30)/(33)) built as the compass does it: O_M X_n
    carried to O (``Translate`` by O_M → O) and reversed (``Mirror`` in O), Y_n mirrored in
    O, each on its compass circle about O, and V_n where the perpendiculars to the axes
    there meet.  None when the step is not such a transfer (then its expression stays)."""
    if s.op != "point_from_lengths" or len(s.inputs) != 2:
        return None
    a, b = (steps.get(n) for n in s.inputs)
    if (
        a is None
        or b is None
        or a.op != "signed_length"
        or b.op != "signed_length"
        or tuple(sp.sympify(p) for p in s.params[:2]) != (-1, -1)
    ):
        return None
    ax, ay, o = (steps.get(n) for n in (a.inputs[2], b.inputs[2], b.inputs[0]))
    # the axes and the origin by role and value (roles as data, never names)
    if (
        ax is None
        or ay is None
        or o is None
        or ax.role != "axis"
        or ay.role != "axis"
        or tuple(map(sp.sympify, ax.params)) != (1, 0)
        or tuple(map(sp.sympify, ay.params)) != (0, 1)
        or o.op != "point"
        or any(sp.sympify(p) != 0 for p in o.params)
    ):
        return None
    om, xn, yn = (ggb_label(n) for n in (a.inputs[0], a.inputs[1], b.inputs[1]))
    org, axis_x, axis_y = (ggb_label(n) for n in (b.inputs[0], a.inputs[2], b.inputs[2]))
    v = ggb_label(s.name)
    aux = f"V{s.n[0]}" if s.n else v  # the helpers' labels from the role's n, not the name
    hidden = [
        f"<show {_a(object='true', label='false')}/>",
        f"<pointSize {_a(val=2)}/>",
        f"<objColor {_a(r=150, g=150, b=150, alpha=0)}/>",
    ]
    return [
        *_element(
            "point",
            f"{aux}x",
            f"{a.name} carried to O with the compass and reversed "
            f"(mirror in O): the x-coordinate of {s.name}",
            hidden,
            "Mirror",
            (f"Translate[{xn}, Vector[{om}, {org}]]", org),
        ),
        *_element(
            "conic",
            f"arc{aux}x",
            f"compass circle about O through {aux}x",
            _FAINT,
            "Circle",
            (org, f"{aux}x"),
        ),
        *_element(
            "point",
            f"{aux}y",
            f"{yn} mirrored in O: the y-coordinate of {s.name}",
            hidden,
            "Mirror",
            (yn, org),
        ),
        *_element(
            "conic",
            f"arc{aux}y",
            f"compass circle about O through {aux}y",
            _FAINT,
            "Circle",
            (org, f"{aux}y"),
        ),
        f"<command {_a(name='Intersect')}>",
        f"\t<input {_a(a0=f'OrthogonalLine[{aux}x, {axis_x}]')} "
        f"{_a(a1=f'OrthogonalLine[{aux}y, {axis_y}]')}/>",
        f"\t<output {_a(a0=v)}/>",
        "</command>",
    ]


def _cone(i: int, contacts: dict[int, str]) -> list[str]:
    """The friction cone at P_i (Fig. 2) as a filled triangle on its two sides, 0.6 |P1P2|
    long, following the sliders (``contacts``: the labels of P1, P2, found by role)."""
    p, p1, p2 = contacts[i], contacts[1], contacts[2]
    ends = [
        f"{p} + 0.6 Distance[{p1}, {p2}] UnitVector[Vector[{_SIDE[n]}]]"
        for n in ((1, 3) if i == 1 else (2, 4))
    ]
    r, g, b = rgb("cone")
    style = [
        f"<show {_a(object='true', label='false')}/>",
        f"<objColor {_a(r=r, g=g, b=b, alpha=0.3)}/>",
        f"<lineStyle {_a(thickness=0, type=0)}/>",
    ]
    return _element(
        "polygon",
        f"cone{i}",
        f"friction cone at P{i} (given, Fig. 2): sides at "
        f"φ{i} ± ξ{i} from −y, {'clockwise' if i == 1 else 'counter-clockwise'}",
        style,
        "Polygon",
        ("{" + ", ".join([p, *ends]) + "}",),
    )


def _has_symbols(v: Any) -> bool:
    return bool(getattr(v, "free_symbols", ()))


def to_ggb(
    construction: Construction,
    title: str | None = None,
    program: Program | None = None,
    values: Any = None,
) -> bytes:
    """The ``.ggb`` archive (zip bytes) of ``construction``.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> data = to_ggb(internal_force_diagram(Grasp.preset("fig6")))
    >>> "<command name=\\"OrthogonalLine\\">" in read_ggb_xml(data)
    True
    """
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("geogebra_javascript.js", "function ggbOnInit() {}\n")
        z.writestr("geogebra.xml", ggb_xml(construction, title, program, values).encode("utf-8"))
    return buf.getvalue()


def write_ggb(
    construction: Construction,
    path: Any,
    title: str | None = None,
    program: Program | None = None,
    values: Any = None,
) -> Path:
    """Write :func:`to_ggb` to ``path``; returns the path.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``path`` cannot be written (its folder must exist; it is not made), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from ..boundary._output import write_output

    return write_output(path, lambda: to_ggb(construction, title, program, values))


def read_ggb_xml(source: Any) -> str:
    """The ``geogebra.xml`` text of a ``.ggb`` file (path or bytes)."""
    data = source if isinstance(source, (bytes, bytearray)) else Path(source).read_bytes()
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        return z.read("geogebra.xml").decode("utf-8")
