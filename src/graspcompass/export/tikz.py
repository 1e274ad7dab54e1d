"""Plain TikZ/pgf of a construction: a standalone document or a ``tikzpicture``.

Only ``tikz`` (with the ``xcolor`` it loads) is needed: no TikZ library.  The
document uses the ``standalone`` class (``border=4pt``) where it is installed (Debian
ships it in ``texlive-latex-extra``) and ``article`` where not: the title, the picture
and its legend are set in one box, which the class crops to, and which the ``article``
fallback ships out on a page cut to that box with a 4 pt border, as the class does; so
the document also compiles with Debian's ``texlive-latex-base`` and ``texlive-pictures``,
with no overfull box and no Letter or A4 page round it.  The labels have a white
background, so that the envelope and the lines do not run through them.  Every
step of the protocol is one commented block: its index, name, kernel operation, instrument, the
paper's reference, its caption, the exact value (sympy text) and then the
TikZ code with the value as a decimal with 12 significant digits.  The points
are ``\\coordinate``\\ s named after the steps (``O_M`` -> ``OM``); points
outside the picture are kept as comments.  The envelope k_grasp (eq. (25)) is
one path of exact circular arcs (``arc[start angle, delta angle, radius]``).

Every length stays far inside TeX's 16383.99 pt (:mod:`._tikz_frame`): the lines are cut
a little beyond the picture's clip, and a zoomed inset far from O is written about its
square's centre (a comment gives the shift) with, where a circle or an arc is still
too large at its scale, the polyline of its visible part.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..scene.labelling import FRAME_PT, SMALL_MARKER
from ..scene.picture import COLORS, INSET_PT, Label, Scene, exact_text, scene_of
from ._tikz_frame import Frame, arc_points

#: A point's dot (``dot`` style), and a break point's: the scene's one ratio.
_DOT_PT = 3.0
_SMALL_DOT = f"{_DOT_PT * SMALL_MARKER:.2f}pt"

if TYPE_CHECKING:
    from ..construction import Construction

__all__ = ["tex_text", "to_tikz", "write_tikz"]

_WIDTH_CM = 11.0
#: TikZ anchor of a label on the side ``(dx, dy)`` of its point (:attr:`Scene.labels`).
ANCHORS = {
    (1, 1): "south west",
    (-1, 1): "south east",
    (1, -1): "north west",
    (-1, -1): "north east",
    (0, 1): "south",
    (0, -1): "north",
    (1, 0): "west",
    (-1, 0): "east",
    (0, 0): "center",
}


def _num(v: float) -> str:
    """A decimal with 12 significant digits, never in exponent notation."""
    text = f"{v:.12g}"
    if "e" in text or "E" in text:
        text = f"{v:.12f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _cname(name: str) -> str:
    return name.replace("_", "").replace("-", "")


def _comment(text: str) -> str:
    return "% " + " ".join(str(text).split())


#: TeX of the non-ASCII characters of the grasps' titles; any other one prints as "?".
_TEX_CHARS = {
    "φ": r"$\varphi$",
    "ϕ": r"$\varphi$",
    "ξ": r"$\xi$",
    "μ": r"$\mu$",
    "π": r"$\pi$",
    "θ": r"$\theta$",
    "≈": r"$\approx$",
    "≤": r"$\le$",
    "≥": r"$\ge$",
    "−": "-",
    "–": "--",
    "—": "---",
    "×": r"$\times$",
    "°": r"$^\circ$",
    "·": r"$\cdot$",
    "₁": r"$_1$",
    "₂": r"$_2$",
}
_TEX_SPECIAL = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "^": r"\^{}",
    "_": r"\_{}",
    "%": r"\%",
    "~": r"\~{}",
}


def tex_text(text: str) -> str:
    """Any text as TeX that pdflatex typesets: its specials escaped, the paper's symbols
    (φ, ξ, μ, π, √3, ...) in math, other non-ASCII characters as "?".

    Examples
    --------
    >>> print(tex_text("P1 = (√3/2, 1/2), φ = π/3 & 50%"))
    P1 = ($\\sqrt{3}$/2, 1/2), $\\varphi$ = $\\pi$/3 \\& 50\\%
    """
    out = []
    i = 0
    while i < len(text):
        ch = text[i]
        if ch == "√":
            j = i + 1
            while j < len(text) and (text[j].isascii() and text[j].isalnum()):
                j += 1
            out.append(f"$\\sqrt{{{text[i + 1 : j]}}}$" if j > i + 1 else r"$\surd$")
            i = j
            continue
        if ch in _TEX_SPECIAL:
            out.append(_TEX_SPECIAL[ch])
        elif ch.isascii() and ch.isprintable():
            out.append(ch)
        elif ch.isspace():
            out.append(" ")
        else:
            out.append(_TEX_CHARS.get(ch, "?"))
        i += 1
    return "".join(out)


#: The legend below a standalone picture: a sample of each style and what it draws.
_LEGEND = (
    (r"\draw[side] (0,0) -- (0.6,0);", "cone side, extended"),
    (r"\fill[cone] (0,-0.1) rectangle (0.6,0.1);", "friction cone"),
    (r"\draw[perp] (0,0) -- (0.6,0);", "perpendicular to a side"),
    (r"\draw[length] (0,0) -- (0.6,0);", r"signed length $\overline{O_MX_n}$, $\overline{OY_n}$"),
    (
        r"\draw[thales, draw=gccircle1] (0,0) -- (0.6,0);",
        r"circle on $OV_n$: $k_n(\theta)$, eq. (31)",
    ),
    (r"\draw[envelope, fill=none] (0,0) -- (0.6,0);", r"envelope $k_{grasp}(\theta)$, eq. (25)"),
    (r"\node[dot] at (0.3,0) {};", "point of the construction"),
    (
        r"\node[dot, fill=white, draw=gcpoint, minimum size=" + _SMALL_DOT + "] at (0.3,0) {};",
        r"break point $B_{nm}$",
    ),
)


def _title(scene: Scene, construction: Construction) -> str:
    """The scene's title (a grasp of one's own: its parameters, as every picture's)."""
    return scene.title or "The internal force diagram"


#: Legend entries of what only some pictures draw: (drawn when, sample, text).
_LEGEND_IF = (
    (
        "object",
        r"\filldraw[object] (0,-0.1) rectangle (0.6,0.1);",
        "the object",
    ),
    (
        "arcs",
        r"\draw[instrument] (0.1,-0.12) arc[start angle=-40, end angle=40, radius=0.19];",
        "compass arcs: bisection, lengths taken and carried to $O$",
    ),
    (
        "right_angle",
        r"\draw[instrument] (0.2,0.15) -- (0.2,0) -- (0.35,0);",
        "right angle",
    ),
    (
        "coordinate",
        r"\draw[instrument, dotted, draw=gccircle1] (0,0) -- (0.6,0);",
        r"$V_n$ from its coordinates $-\overline{O_MX_n}$, $-\overline{OY_n}$",
    ),
)


def _legend(scene: Scene) -> str:
    """The legend below the picture: every style drawn, with what it draws."""
    roles = {i.role for i in scene.instruments}
    if roles & {"bisection_arc", "measure_arc", "transfer_arc"}:
        roles.add("arcs")
    if scene.outline is not None:
        roles.add("object")
    entries = [*_LEGEND, *((code, text) for when, code, text in _LEGEND_IF if when in roles)]
    items = [
        f"\\mbox{{\\tikz[baseline=-0.6ex, x=1cm, y=1cm]{{{code}}}~{text}}}"
        for code, text in entries
    ]
    return "{\\small " + "\\hskip 1em plus 0.5em\n".join(items) + "\\par}"


def _styles(scene: Scene) -> list[str]:
    colors = [
        f"\\definecolor{{gc{k}}}{{HTML}}{{{v.lstrip('#').upper()}}}" for k, v in COLORS.items()
    ]
    unit = _WIDTH_CM / (scene.box[1] - scene.box[0])
    return [
        *colors,
        f"\\begin{{tikzpicture}}[x={_num(unit)}cm, y={_num(unit)}cm, line cap=round,",
        "  axis/.style={draw=gcaxis, line width=0.7pt},",
        "  side/.style={draw=gcside, line width=0.8pt},",
        "  perp/.style={draw=gcperp, line width=0.4pt, dash pattern=on 3pt off 1.5pt},",
        "  instrument/.style={draw=gcperp, line width=0.3pt},",
        "  length/.style={draw=gclength, line width=0.4pt, ->},",
        "  thales/.style={line width=0.8pt, dash pattern=on 4pt off 2pt},",
        "  envelope/.style={draw=gcenvelope, line width=1.6pt, line join=round,",
        "    fill=gcfill, fill opacity=0.35, draw opacity=1},",
        "  cone/.style={fill=gccone, fill opacity=0.35},",
        "  object/.style={draw=gcobject, fill=gcobjectfill, line width=0.6pt},",
        f"  dot/.style={{circle, fill=gcpoint, inner sep=0pt, minimum size={_DOT_PT:g}pt}},",
        # 8 pt in 11 cm: the ratio font / width of the placement (10 pt in 388 pt)
        "  label/.style={inner sep=0pt, font=\\fontsize{8}{9.6}\\selectfont,",
        "    fill=white, fill opacity=0.8, text opacity=1}]",
    ]


def _style_defs(scene: Scene) -> list[str]:
    """The styles as one global ``\\tikzset`` (standalone: the legend's samples use them)."""
    lines = _styles(scene)
    opts = lines[len(COLORS) :]
    body = "\n".join(opts).split("line cap=round,", 1)[1].rstrip("]")
    head = opts[0].split("[", 1)[1].split("line cap=round", 1)[0]
    return [
        *lines[: len(COLORS)],
        "\\tikzset{" + body.strip() + "}",
        f"\\begin{{tikzpicture}}[{head}line cap=round]",
    ]


def _envelope_path(scene: Scene, frame: Frame) -> list[str]:
    """The envelope as one path of exact arcs; where an arc is too large for TeX in this
    picture (a zoomed inset), the polygon of its visible part."""
    arcs = scene.envelope
    if all(a.n == 0 or frame.fits(a.center, a.radius) for a in arcs) and all(
        frame.fits(a.start, 0.0) and frame.fits(a.end, 0.0) for a in arcs
    ):
        parts = [frame.xy(arcs[0].start)]
        for a in arcs:
            if a.n == 0:
                parts.append(f"-- {frame.xy(a.end)}")
            else:
                parts.append(
                    f"arc[start angle={_num(a.start_angle)}, delta angle={_num(a.delta)}, "
                    f"radius={_num(a.radius)}]"
                )
        return ["\\filldraw[envelope] " + " ".join(parts) + " -- cycle;"]
    outline: list[tuple[float, float]] = []
    for a in arcs:
        if a.n == 0:
            outline += [a.start, a.end]
        else:
            outline += arc_points(a.center, a.radius, a.start_angle, a.delta)
    return [f"\\filldraw[envelope] {frame.path(q, closed=True)};" for q in frame.polygons(outline)]


def _circle(frame: Frame, style: str, center: tuple[float, float], radius: float) -> list[str]:
    """A circle, or the polyline of its visible part where TeX cannot hold it."""
    if frame.fits(center, radius):
        return [f"\\draw[{style}] {frame.xy(center)} circle[radius={_num(radius)}];"]
    ring = arc_points(center, radius, 0.0, 360.0)
    return [f"\\draw[{style}] {frame.path(q)};" for q in frame.polylines(ring)]


def _body(
    scene: Scene,
    construction: Construction,
    frame: Frame,
    pad: float,
    zoom: float | None = None,
) -> list[str]:
    """The drawing of every object, clipped to the frame's box (the diagram, or the inset
    drawn at ``zoom`` points per unit), in the frame's coordinates."""
    out: list[str] = []
    box = frame.box
    corners = f"{frame.xy((box[0], box[2]))} rectangle {frame.xy((box[1], box[3]))}"
    out += [f"\\path[use as bounding box] {corners};", f"\\clip {corners};"]
    if scene.outline is not None:
        kind, dims = scene.outline
        out.append(_comment("the grasped object (given)"))
        if kind == "circle" and frame.fits((0.0, 0.0), dims[0]):
            out.append(f"\\filldraw[object] {frame.xy((0.0, 0.0))} circle[radius={_num(dims[0])}];")
        else:
            w, h = dims[0] / 2, dims[1] / 2
            shape = (
                arc_points((0.0, 0.0), dims[0], 0.0, 360.0)
                if kind == "circle"
                else [(-w, -h), (w, -h), (w, h), (-w, h)]
            )
            out += [
                f"\\filldraw[object] {frame.path(q, closed=True)};" for q in frame.polygons(shape)
            ]
    for i, cone in enumerate(scene.cones, start=1):
        out.append(_comment(f"friction cone at P{i} (given, Fig. 2)"))
        out += [f"\\fill[cone] {frame.path(q, closed=True)};" for q in frame.polygons(cone)]
    lines = {n: (a, b) for n, _, a, b in scene.lines}
    roles = {n: r for n, r, _, _ in scene.lines}
    lengths = {n: (a, b) for n, a, b in scene.lengths}
    circles = {n: (k, c, r) for n, k, c, r in scene.circles}
    points = {n: xy for names, xy in scene.points for n in names}
    tools: dict[str, list[str]] = {}  # the compass arcs, right angles, guides of each step
    for ins in scene.instruments_at(zoom):
        dash = {
            "bisector": ", dotted",
            "coordinate": f", dotted, draw=gccircle{ins.n}",
            "drop": ", dashed",
        }.get(ins.role, "")
        tools.setdefault(ins.step, []).extend(
            f"\\draw[instrument{dash}] {frame.path(q)}; % {ins.role}"
            for q in frame.polylines(ins.points)
        )
    for s in construction.steps:
        out.append(_comment(f"[{s.index}] {s.name} ({s.op}, {s.instrument}; {s.ref}): {s.caption}"))
        if s.kind != "envelope":
            out.append(_comment(f"exact: {exact_text(s.obj)}"))
        if s.name in lines:
            style = roles[s.name]
            out += [f"\\draw[{style}] {frame.path(q)};" for q in frame.polylines(lines[s.name])]
        elif s.name in lengths:
            out += [f"\\draw[length] {frame.path(q)};" for q in frame.polylines(lengths[s.name])]
        elif s.name in circles:
            k, c, r = circles[s.name]
            out += _circle(frame, f"thales, draw=gccircle{k}", c, r)
        elif s.name in points and frame.fits(points[s.name], 0.0):
            out.append(f"\\coordinate ({_cname(s.name)}) at {frame.xy(points[s.name])};")
        elif s.kind == "point":
            out.append(
                _comment(
                    f"outside the picture (view box {box[0] - pad:.3g} .. "
                    f"{box[1] + pad:.3g}): not drawn"
                )
            )
        elif s.kind == "envelope" and scene.envelope:
            out.append(_comment("exact arcs: " + exact_text(s.obj)))
            out += _envelope_path(scene, frame)
        out += tools.get(s.name, [])
    return out


def _top_aligned(out: list[str]) -> None:
    """The last ``tikzpicture`` begun in ``out`` set on the baseline of its top edge."""
    k = max(i for i, line in enumerate(out) if line.startswith("\\begin{tikzpicture}["))
    out[k] = out[k].replace("[", "[baseline=(current bounding box.north), ", 1)


def _points(scene: Scene, labels: tuple[Label, ...], frame: Frame) -> list[str]:
    """The markers of the points in the frame's box and the ``labels`` (white behind the
    glyphs)."""
    box = frame.box
    by_name = {lab.names[0]: lab for lab in labels}
    out = [_comment("points and their labels (coincident points share one label)")]
    for names, xy in scene.points:
        if not (box[0] <= xy[0] <= box[1] and box[2] <= xy[1] <= box[3]):
            continue
        small = names[0] in scene.small
        style = f"dot, fill=white, draw=gcpoint, minimum size={_SMALL_DOT}" if small else "dot"
        out.append(f"\\node[{style}] at ({_cname(names[0])}) {{}};")
        lab = by_name.get(names[0])
        if lab is not None:  # a break point too, when labelled on request
            out.append(
                f"\\node[label, anchor={ANCHORS[lab.direction]}] at {frame.xy(lab.at)} "
                f"{{${lab.tex()}$}};"
            )
    return out


def to_tikz(
    construction: Construction,
    standalone: bool = True,
    title: str | None = None,
    break_points: bool = False,
) -> str:
    """TikZ code of ``construction`` (numeric parameters).

    Parameters
    ----------
    construction : Construction
    standalone : bool
        A complete document if true: the title, the picture and a legend of its styles
        on one page cut to their size, by the ``standalone`` class where it is installed
        and by ``article`` with the page set to the box where not; else only the
        ``tikzpicture`` (for ``\\input`` in a document that loads tikz).
    title : str, optional
        Comment line at the top; defaults to the grasp's title.
    break_points : bool
        Label the break points on the envelope
        (:func:`graspcompass.scene.picture.build_scene`).

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> text = to_tikz(internal_force_diagram(Grasp.preset("fig6")))
    >>> "\\\\begin{tikzpicture}" in text and "% exact: (sqrt(3), -3/2)" in text
    True
    """
    scene = scene_of(construction, title, break_points)
    box = scene.box
    pad = 0.1 * (box[1] - box[0])
    out = [
        _comment(f"graspcompass: {scene.title or 'internal force diagram'}"),
        _comment(
            "Ito, Tanaka, Sasaki, Robotica 30(5) 2012: internal force diagram, "
            "ruler-and-compass construction (sec. 3.3)"
        ),
    ]
    grasp = construction.grasp
    if grasp is not None:
        out.append(_comment("grasp: " + ", ".join(f"{k} = {v}" for k, v in grasp.params.items())))
    width = _WIDTH_CM + 0.4
    if scene.insets:  # the insets beside the diagram
        width += 0.5 + _WIDTH_CM * INSET_PT / FRAME_PT
    if standalone:
        out += [
            _comment(
                "the standalone class (TeX Live's latex-extra) when installed, else article "
                "with the page cut to the picture as the class cuts it: title, picture and "
                "legend in one box, on a page of its size with a 4 pt border"
            ),
            "\\IfFileExists{standalone.cls}{\\documentclass[border=4pt]{standalone}}"
            "{\\documentclass{article}}",
            "\\usepackage{tikz}",
        ]
        styles = _style_defs(scene)
        out += styles[:-1]  # the colours and styles in the preamble: the legend uses them
        out += [
            "\\newsavebox{\\gcpage}",
            # the class sets the page in a box from here on: no line end may add a space
            "\\begin{document}%",
        ]
        out += [
            f"\\savebox{{\\gcpage}}{{\\vbox{{\\hsize={_num(width)}cm \\parindent=0pt "
            "\\parskip=0pt \\raggedright",
            f"{{\\large\\bfseries {tex_text(_title(scene, construction))}\\par}}",
            "\\smallskip{\\small Internal force diagram (Ito, Tanaka, Sasaki, Robotica 30(5), "
            "2012), ruler-and-compass construction of Sec.~3.3\\par}\\medskip",
            "\\hbox to \\hsize{\\hss",
            styles[-1],
        ]
    else:
        out += _styles(scene)
    main = Frame(box, _WIDTH_CM / (box[1] - box[0]))
    insets = scene.insets
    if insets:  # the diagram and the column of insets beside it aligned at their tops
        _top_aligned(out)
    out += _body(scene, construction, main, pad)
    out += _points(scene, scene.labels if not insets else insets[0].main, main)
    for k, inset in enumerate(insets):  # the regions of the insets, dashed
        z = inset.box
        out.append(
            f"\\draw[axis, line width=0.4pt, dash pattern=on 2pt off 1pt] "
            f"{main.xy((z[0], z[2]))} rectangle {main.xy((z[1], z[3]))};"
        )
        if inset.number is not None:  # numbered as their insets, where it covers nothing
            number = f"{{{k + 1}}};"
            at = main.xy(inset.number)
            out.append(f"\\node[anchor=center, inner sep=0pt, font=\\scriptsize] at {at} {number}")
    out.append("\\end{tikzpicture}")
    main_unit = _WIDTH_CM / (box[1] - box[0])
    if insets:  # the zoomed insets, one above the other right of the diagram
        out.append("\\hskip 0.5cm\\vtop{")
    for k, inset in enumerate(insets):
        z = inset.box
        # its labels were placed in a frame INSET_PT / FRAME_PT times the diagram's
        # width, at the same font size
        unit = _WIDTH_CM * INSET_PT / FRAME_PT / (z[1] - z[0])
        times = unit / main_unit
        out.append(_comment(f"zoomed inset of the crowded region, {times:.1f} times larger"))
        if k:
            out.append("\\vskip 0.3cm")
        out.append("\\hbox{")
        if standalone:  # the styles are global (\tikzset)
            out.append(
                f"\\begin{{tikzpicture}}[x={_num(unit)}cm, y={_num(unit)}cm, line cap=round]"
            )
        else:  # the styles of the diagram's picture, in the inset's unit
            out += (
                "\n".join(_styles(scene)[len(COLORS) :])
                .replace(
                    f"x={_num(main_unit)}cm, y={_num(main_unit)}cm",
                    f"x={_num(unit)}cm, y={_num(unit)}cm",
                    1,
                )
                .split("\n")
            )
        if not k:
            _top_aligned(out)
        frame = Frame(z, unit)
        if frame.origin != (0.0, 0.0):
            cx, cy = (_num(v) for v in frame.origin)
            out.append(
                _comment(
                    f"coordinates about ({cx}, {cy}), the square's centre, for TeX's lengths: "
                    f"the point (x, y) of the paper is written (x - {cx}, y - {cy})"
                )
            )
        out += _body(scene, construction, frame, pad, inset.zoom)
        out += _points(scene, inset.labels, frame)
        out.append(
            f"\\draw[axis, line width=0.4pt] {frame.xy((z[0], z[2]))} rectangle "
            f"{frame.xy((z[1], z[3]))};"
        )
        which = "the dashed square" if len(insets) == 1 else f"dashed square {k + 1}"
        out.append("\\end{tikzpicture}}")  # the caption under it, outside its clip
        out.append(
            f"\\hbox to {_num(_WIDTH_CM * INSET_PT / FRAME_PT)}cm{{\\hss\\small "
            f"{which}, {times:.1f}$\\times$ larger\\hss}}"
        )
    if insets:
        out.append("}")
    if standalone:
        out += [
            "\\hss}\\medskip",
            _legend(scene),
            "}}%",
            "\\makeatletter%",
            "\\@ifclassloaded{standalone}{\\usebox{\\gcpage}}{%",
            "\\pdfpagewidth=\\wd\\gcpage \\advance\\pdfpagewidth by 8pt",
            "\\pdfpageheight=\\ht\\gcpage \\advance\\pdfpageheight by \\dp\\gcpage",
            "\\advance\\pdfpageheight by 8pt",
            "\\hoffset=-1in \\voffset=-1in",
            "\\shipout\\vbox{\\vskip 4pt\\moveright 4pt\\box\\gcpage\\vskip 4pt}}",
            "\\makeatother",
            "\\end{document}",
        ]
    return "\n".join(out) + "\n"


def write_tikz(
    construction: Construction,
    path: Any,
    standalone: bool = True,
    title: str | None = None,
    break_points: bool = False,
) -> Path:
    """Write :func:`to_tikz` to ``path`` (UTF-8); returns the path.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``path`` cannot be written (its folder must exist; it is not made), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from ..boundary._output import write_output

    return write_output(path, lambda: to_tikz(construction, standalone, title, break_points))
