"""Plain TikZ/pgf of a construction: a standalone document or a ``tikzpicture``.

Only ``tikz`` (with the ``xcolor`` it loads) is needed: no TikZ library and no
``standalone`` class, so the document compiles with Debian's
``texlive-latex-base`` and ``texlive-pictures``.  Every step of the protocol is
one commented block: its index, name, kernel operation, instrument, the
paper's reference, its caption, the exact value (sympy text) and then the
TikZ code with the value as a decimal with 12 significant digits.  The points
are ``\\coordinate``\\ s named after the steps (``O_M`` -> ``OM``); points
outside the picture are kept as comments.  The envelope k_grasp (eq. (25)) is
one path of exact circular arcs (``arc[start angle, delta angle, radius]``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..scene.picture import COLORS, Scene, exact_text, scene_of

__all__ = ["to_tikz", "write_tikz"]

_WIDTH_CM = 11.0
#: TikZ anchor of a label on the side ``(dx, dy)`` of its point (:attr:`Scene.labels`).
ANCHORS = {(1, 1): "south west", (-1, 1): "south east", (1, -1): "north west",
           (-1, -1): "north east", (0, 1): "south", (0, -1): "north", (1, 0): "west",
           (-1, 0): "east", (0, 0): "center"}


def _num(v: float) -> str:
    """A decimal with 12 significant digits, never in exponent notation."""
    text = f"{v:.12g}"
    if "e" in text or "E" in text:
        text = f"{v:.12f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _xy(p: tuple[float, float]) -> str:
    return f"({_num(p[0])}, {_num(p[1])})"


def _cname(name: str) -> str:
    return name.replace("_", "").replace("-", "")


def _comment(text: str) -> str:
    return "% " + " ".join(str(text).split())


def _styles(scene: Scene) -> list[str]:
    colors = [f"\\definecolor{{gc{k}}}{{HTML}}{{{v.lstrip('#').upper()}}}"
              for k, v in COLORS.items()]
    unit = _WIDTH_CM / (scene.box[1] - scene.box[0])
    return [
        *colors,
        f"\\begin{{tikzpicture}}[x={_num(unit)}cm, y={_num(unit)}cm, line cap=round,",
        "  axis/.style={draw=gcaxis, line width=0.7pt},",
        "  side/.style={draw=gcside, line width=0.8pt},",
        "  perp/.style={draw=gcperp, line width=0.4pt, dash pattern=on 3pt off 1.5pt},",
        "  length/.style={draw=gclength, line width=0.4pt, ->},",
        "  thales/.style={line width=0.8pt, dash pattern=on 4pt off 2pt},",
        "  envelope/.style={draw=gcenvelope, line width=1.6pt, line join=round,",
        "    fill=gcfill, fill opacity=0.35, draw opacity=1},",
        "  cone/.style={fill=gccone, fill opacity=0.35},",
        "  object/.style={draw=gcobject, fill=gcobjectfill, line width=0.6pt},",
        "  dot/.style={circle, fill=gcpoint, inner sep=0pt, minimum size=3pt},",
        # 8 pt in 11 cm: the ratio font / width of the placement (10 pt in 388 pt)
        "  label/.style={inner sep=0pt, font=\\fontsize{8}{9.6}\\selectfont}]",
    ]


def _envelope_path(scene: Scene) -> str:
    parts = [_xy(scene.envelope[0].start)]
    for a in scene.envelope:
        if a.n == 0:
            parts.append(f"-- {_xy(a.end)}")
        else:
            parts.append(f"arc[start angle={_num(a.start_angle)}, delta angle={_num(a.delta)}, "
                         f"radius={_num(a.radius)}]")
    return "\\filldraw[envelope] " + " ".join(parts) + " -- cycle;"


def to_tikz(construction: Any, standalone: bool = True, title: str | None = None) -> str:
    """TikZ code of ``construction`` (numeric parameters).

    Parameters
    ----------
    construction : Construction
    standalone : bool
        A complete ``article`` document (``\\pagestyle{empty}``) if true, else
        only the ``tikzpicture`` (for ``\\input`` in a document that loads tikz).
    title : str, optional
        Comment line at the top; defaults to the grasp's title.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> text = to_tikz(internal_force_diagram(Grasp.preset("fig6")))
    >>> "\\\\begin{tikzpicture}" in text and "% exact: (sqrt(3), -3/2)" in text
    True
    """
    scene = scene_of(construction, title)
    box = scene.box
    pad = 0.1 * (box[1] - box[0])
    out = [_comment(f"graspcompass: {scene.title or 'internal force diagram'}"),
           _comment("Ito, Tanaka, Sasaki, Robotica 30(5) 2012: internal force diagram, "
                    "ruler-and-compass construction (sec. 3.3)")]
    grasp = construction.grasp
    if grasp is not None:
        out.append(_comment("grasp: " + ", ".join(f"{k} = {v}" for k, v in grasp.params.items())))
    if standalone:
        out += ["\\documentclass{article}", "\\usepackage{tikz}", "\\pagestyle{empty}",
                "\\begin{document}", "\\noindent"]
    out += _styles(scene)
    corners = f"{_xy((box[0], box[2]))} rectangle {_xy((box[1], box[3]))}"
    out += [f"\\path[use as bounding box] {corners};", f"\\clip {corners};"]
    if scene.outline is not None:
        kind, dims = scene.outline
        out.append(_comment("the grasped object (given)"))
        out.append(f"\\filldraw[object] (0, 0) circle[radius={_num(dims[0])}];" if kind == "circle"
                   else f"\\filldraw[object] {_xy((-dims[0] / 2, -dims[1] / 2))} rectangle "
                   f"{_xy((dims[0] / 2, dims[1] / 2))};")
    for i, cone in enumerate(scene.cones, start=1):
        out.append(_comment(f"friction cone at P{i} (given, Fig. 2)"))
        out.append("\\fill[cone] " + " -- ".join(_xy(p) for p in cone) + " -- cycle;")
    lines = {n: (a, b) for n, _, a, b in scene.lines}
    roles = {n: r for n, r, _, _ in scene.lines}
    lengths = {n: (a, b) for n, a, b in scene.lengths}
    circles = {n: (k, c, r) for n, k, c, r in scene.circles}
    points = {n: xy for names, xy in scene.points for n in names}
    for s in construction.steps:
        out.append(_comment(f"[{s.index}] {s.name} ({s.op}, {s.instrument}; {s.ref}): {s.caption}"))
        if s.kind != "envelope":
            out.append(_comment(f"exact: {exact_text(s.obj)}"))
        if s.name in lines:
            a, b = lines[s.name]
            out.append(f"\\draw[{roles[s.name]}] {_xy(a)} -- {_xy(b)};")
        elif s.name in lengths:
            a, b = lengths[s.name]
            out.append(f"\\draw[length] {_xy(a)} -- {_xy(b)};")
        elif s.name in circles:
            k, c, r = circles[s.name]
            out.append(f"\\draw[thales, draw=gccircle{k}] {_xy(c)} circle[radius={_num(r)}];")
        elif s.name in points:
            out.append(f"\\coordinate ({_cname(s.name)}) at {_xy(points[s.name])};")
        elif s.kind == "point":
            out.append(_comment(f"outside the picture (view box {box[0] - pad:.3g} .. "
                                f"{box[1] + pad:.3g}): not drawn"))
        elif s.kind == "envelope" and scene.envelope:
            out.append(_comment("exact arcs: " + exact_text(s.obj)))
            out.append(_envelope_path(scene))
    out.append(_comment("points and their labels (coincident points share one label)"))
    for names, _ in scene.points:
        small = names[0] in scene.small
        style = "dot, fill=white, draw=gcpoint, minimum size=2.5pt" if small else "dot"
        out.append(f"\\node[{style}] at ({_cname(names[0])}) {{}};")
        if not small:
            text = ""
            lab = scene.label_of(names[0])
            text = lab.tex() if lab is not None else text
            if lab is not None:
                out.append(f"\\node[label, anchor={ANCHORS[lab.direction]}] at {_xy(lab.at)} "
                           f"{{${text}$}};")
    out.append("\\end{tikzpicture}")
    if standalone:
        out.append("\\end{document}")
    return "\n".join(out) + "\n"


def write_tikz(construction: Any, path: Any, standalone: bool = True,
               title: str | None = None) -> Path:
    """Write :func:`to_tikz` to ``path`` (UTF-8); returns the path.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``path`` cannot be written (its folder must exist; it is not made), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from .._output import write_output

    return write_output(path, lambda: to_tikz(construction, standalone, title))
