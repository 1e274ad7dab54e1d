"""Tests of graspcompass.export: GeoGebra, TikZ (real pdflatex), SVG, JSON round trip, CLI.

Expected values come from the paper (§4.1: V2 = (√3, −3/2) for Fig. 6; the
closed form (28)-(39) re-typed in ``conftest.py``) or from the geometry of the
friction cones written out here, never from the code under test.
"""

from __future__ import annotations

import argparse
import math
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings

from conftest import PRESET_NAMES, closed_form_SC, exact_params, float_params, k_paper
from graspcompass import Grasp, internal_force_diagram, parse_exact
from graspcompass.cli import _add_grasp_options
from graspcompass.cli._export import register, run_explore, run_export
from graspcompass.construction import diagram_specs, replay
from graspcompass.export import FORMATS, SCHEMA, dumps, export, guess_format, loads
from graspcompass.export.geogebra import ggb_xml, read_ggb_xml, to_ggb
from graspcompass.export.json import to_document
from graspcompass.export.svg import to_svg
from graspcompass.export.tikz import to_tikz

SRC = Path(__file__).resolve().parents[1] / "src"
LABEL = {"x-axis": "axisX", "y-axis": "axisY", "envelope": "kGrasp"}
SLIDERS = ["x_1", "x_2", "y_P", "φ_1", "φ_2", "μ_1", "μ_2"]
# child tags documented for geogebra.xml ("Common XML tags and types", GeoGebra manual)
CONSTRUCTION_TAGS = {"command", "element", "expression", "cascell"}
COMMAND_TAGS = {"input", "output", "outputSizes", "casMap"}
ELEMENT_TAGS = {
    "show",
    "objColor",
    "labelMode",
    "lineStyle",
    "pointSize",
    "coords",
    "caption",
    "breakpoint",
    "value",
    "slider",
    "animation",
    "layer",
    "fixed",
    "auxiliary",
    "labelOffset",
    "angleStyle",
}
#: Objects the .ggb adds to the protocol's steps: the friction cones and the compass
#: transfers of V_n (issue 23).
EXTRAS = {
    "cone1",
    "cone2",
    *(f"{k}V{n}{a}" for n in (1, 2, 3, 4) for k in ("", "arc") for a in "xy"),
    # k_grasp (25) in short named functions: k_n (32), the larger of two, the largest and 0
    *(f"k_{n}" for n in (1, 2, 3, 4)),
    *(f"m_{i}" for i in (1, 2, 3)),
    "kg",
}
ROOT_TAGS = {"gui", "euclidianView", "kernel", "construction", "algebraView", "scripting"}


@pytest.fixture(scope="module")
def fig6():
    return internal_force_diagram(Grasp.preset("fig6"))


# ---------------------------------------------------------------------------
# GeoGebra
# ---------------------------------------------------------------------------
def _ggb_root(data: bytes) -> ET.Element:
    with zipfile.ZipFile(__import__("io").BytesIO(data)) as z:
        assert "geogebra.xml" in z.namelist()
        return ET.fromstring(z.read("geogebra.xml"))


def _protocol(root: ET.Element) -> list[tuple[str, str, str, tuple[str, ...], ET.Element]]:
    """(label, how, command name or exp, inputs, element) in document order."""
    out, pending = [], None
    for child in root.find("construction"):
        assert child.tag in CONSTRUCTION_TAGS
        if child.tag == "command":
            assert {c.tag for c in child} <= COMMAND_TAGS
            (inp,), (outp,) = child.findall("input"), child.findall("output")
            args = tuple(inp.attrib[f"a{i}"] for i in range(len(inp.attrib)))
            pending = (outp.attrib["a0"], "command", child.attrib["name"], args)
        elif child.tag == "expression":
            pending = (child.attrib["label"], "expression", child.attrib["exp"], ())
        else:
            assert {c.tag for c in child} <= ELEMENT_TAGS, {c.tag for c in child}
            label = child.attrib["label"]
            if pending is not None:
                assert pending[0] == label, "a definition is followed by its element"
                out.append((*pending, child))
            else:
                out.append((label, "free", child.attrib["type"], (), child))
            pending = None
    return out


def test_ggb_every_object_is_defined_by_a_command_in_protocol_order(fig6):
    root = _ggb_root(to_ggb(fig6))
    assert root.tag == "geogebra" and root.attrib["format"] == "5.0"
    assert {c.tag for c in root} <= ROOT_TAGS
    proto = _protocol(root)
    free = [p for p in proto if p[1] == "free"]
    # the only free objects are the seven number sliders, first
    assert [p[0] for p in free] == SLIDERS == [p[0] for p in proto[:7]]
    for label, _, kind, _, el in free:  # φ in degrees: angle sliders; none over the drawing
        assert kind == ("angle" if label.startswith("φ") else "numeric")
        assert el.find("slider") is not None and el.find("show").attrib["object"] == "false"
    assert root.find("kernel/angleUnit").attrib["val"] == "degree"
    assert root.find("gui/consProtNavigationBar").attrib["playButton"] == "true"
    extras = [p for p in proto[7:] if p[0] in EXTRAS]
    assert {p[0] for p in extras} == EXTRAS
    defined = [p for p in proto[7:] if p[0] not in EXTRAS]
    assert [p[0] for p in defined] == [LABEL.get(n, n) for n in fig6.names]
    captions = [p[4].find("caption").attrib["val"] for p in defined]
    assert captions == [s.caption for s in fig6.steps]
    breakpoints = [p[0] for p in defined if p[4].find("breakpoint") is not None]
    assert breakpoints == [LABEL.get(s.name, s.name) for s in fig6.steps if s.key]
    # no object is a fixed coordinate pair, and each uses only earlier objects
    known = set(SLIDERS) | {"xAxis", "yAxis"}
    words = re.compile(r"[^\W\d]\w*")
    builtins = {
        "sin",
        "cos",
        "abs",
        "x",
        "y",
        "t",
        "pi",
        "Midpoint",
        "Line",
        "Center",
        "Translate",
        "Vector",
        "OrthogonalLine",
        "Distance",
        "UnitVector",
    }
    for label, how, what, args, _ in proto[7:]:
        text = " ".join(args) if how == "command" else what
        text = text.removeprefix(f"{label}(t) = ")  # a function's definition names it
        assert not re.fullmatch(r"\(\s*-?[\d.]+\s*,\s*-?[\d.]+\s*\)", text)
        assert set(words.findall(text)) - builtins <= known, (label, text)
        known.add(label)


def test_ggb_commands_follow_the_paper_recipe(fig6):
    d = {p[0]: p for p in _protocol(_ggb_root(to_ggb(fig6)))}
    assert d["O"][2:4] == ("Intersect", ("xAxis", "yAxis"))
    assert d["P1"][1:3] == ("expression", "(x_1, y_P)")  # dragging P1 moves x_1, y_P
    assert d["P2"][1:3] == ("expression", "(-x_2, y_P)")
    assert d["P1x"][2:4] == ("ClosestPoint", ("axisX", "P1"))
    assert d["O_M"][2:4] == ("Midpoint", ("P1x", "P2x"))
    for n in (1, 2, 3, 4):  # §3.3: the foot of the *other* contact
        foot = "P2x" if n in (1, 3) else "P1x"
        assert d[f"X{n}"][2:4] == ("Intersect", (f"side{n}", "axisX"))
        assert d[f"perp{n}"][2:4] == ("OrthogonalLine", (foot, f"side{n}"))  # PerpendicularLine
        assert d[f"Y{n}"][2:4] == ("Intersect", (f"perp{n}", "axisY"))
        assert d[f"OMX{n}"][2] == f"x(X{n}) - x(O_M)"
        assert d[f"OY{n}"][2] == f"y(Y{n}) - y(O)"
        # V_n = (−O_M X_n, −O Y_n) by compass: O_M X_n carried to O and reversed, Y_n
        # mirrored in O, each on its circle about O; V_n where the perpendiculars meet
        assert d[f"V{n}x"][2:4] == ("Mirror", (f"Translate[X{n}, Vector[O_M, O]]", "O"))
        assert d[f"V{n}y"][2:4] == ("Mirror", (f"Y{n}", "O"))
        assert d[f"arcV{n}x"][2:4] == ("Circle", ("O", f"V{n}x"))
        assert d[f"V{n}"][2:4] == (
            "Intersect",
            (f"OrthogonalLine[V{n}x, axisX]", f"OrthogonalLine[V{n}y, axisY]"),
        )
        assert d[f"circle{n}"][2:4] == ("Circle", (f"Midpoint[O, V{n}]", "O"))
    assert d["B12"][2:4] == ("Mirror", ("O", "Line[Center[circle1], Center[circle2]]"))
    for i, sides in ((1, (1, 3)), (2, (2, 4))):  # each cone once its sides exist (Fig. 2)
        cmd, (arg,) = d[f"cone{i}"][2:4]
        assert cmd == "Polygon" and arg.startswith(f"{{P{i}, P{i} + 0.6 Distance[P1, P2]")
        order = list(d)
        assert order.index(f"cone{i}") > max(order.index(f"side{n}") for n in sides)
    assert d["kGrasp"][2:4] == (
        "CurveCartesian",
        ("kg(t) sin(t)", "-kg(t) cos(t)", "t", "0", "2 pi"),
    )


def _ggb_functions(root: ET.Element) -> dict[str, str]:
    """label -> the right-hand side of each function the .ggb defines (``f(t) = ...``)."""
    out = {}
    for e in root.find("construction").findall("expression"):
        m = re.fullmatch(r"(\w+)\(t\) = (.+)", e.attrib["exp"])
        if m:
            assert m[1] == e.attrib["label"]
            out[m[1]] = m[2]
    return out


@pytest.mark.parametrize("params", [None, (1.1, 0.7, 0.4, 1.2, 1.4, 0.9, 1.1)])
def test_ggb_envelope_is_short_named_functions_of_k_grasp(fig6, params):
    """k_grasp (25) in GeoGebra: one short line per function (the envelope was one
    formula of 3 kB), k_n(t) = x(V_n) sin t - y(V_n) cos t (32), the larger of two, and
    kg = max(..., 0); evaluated here with the V_n of the closed form (28)-(39), kg equals
    max(k1, ..., k4, 0) of eqs. (18)-(21) at every θ."""
    c = (
        fig6
        if params is None
        else internal_force_diagram(Grasp(*params[:5], mu1=params[5], mu2=params[6]))
    )
    root = _ggb_root(to_ggb(c))
    funcs = _ggb_functions(root)
    assert set(funcs) == {"k_1", "k_2", "k_3", "k_4", "m_1", "m_2", "m_3", "kg"}
    assert all(len(body) < 60 for body in funcs.values()), funcs
    for el in root.find("construction"):  # no definition is a giant formula
        for inp in el.findall("input"):
            assert all(len(v) < 250 for v in inp.attrib.values()), inp.attrib
    g = c.grasp
    x1, x2, y = (float(g.params[k]) for k in ("x1", "x2", "y"))
    phi = [float(g.params[k]) for k in ("phi1", "phi2")]
    xi = [float(g.params[k]) for k in ("xi1", "xi2")]
    S, C = closed_form_SC(x1, x2, y, *phi, math.tan(xi[0]), math.tan(xi[1]), lib=np)
    V = {f"V{n}": (float(S[n - 1]), float(C[n - 1])) for n in (1, 2, 3, 4)}
    mu = [math.tan(v) for v in xi]
    for theta in np.linspace(0, 2 * math.pi, 37):
        env: dict = {}  # each function's value at this θ, in protocol order
        for label, body in funcs.items():
            expr = re.sub(r"\b(x|y)\((V\d)\)", lambda m: repr(V[m[2]][m[1] == "y"]), body)
            expr = re.sub(r"\b(k_\d|m_\d|kg)\(t\)", lambda m: f"env[{m[1]!r}]", expr)
            expr = re.sub(r"(\d)\s+(sin|cos)\b", r"\1 * \2", expr)  # GeoGebra's "a sin(t)"
            env[label] = eval(  # the .ggb text with the test's own numbers and names only
                expr,
                {"__builtins__": {}},
                {"sin": math.sin, "cos": math.cos, "abs": abs, "t": theta, "env": env},
            )
        k = k_paper(theta, x1, x2, y, *phi, *mu, lib=math)  # eqs. (18)-(21), μ form
        assert env["kg"] == pytest.approx(max(*k, 0.0), abs=1e-9)


def test_ggb_protocol_navigation_opens_on_the_whole_construction(fig6):
    """GeoGebra 4 shows the navigation bar only with show="true" and, at consStep -1,
    none of the construction: the bar is shown on the last step; angle sliders move by 1°."""
    root = _ggb_root(to_ggb(fig6))
    bar = root.find("gui/consProtNavigationBar")
    steps = len(root.find("construction").findall("element"))
    assert bar.attrib["show"] == "true" and bar.attrib["consStep"] == str(steps - 1)
    for el in root.find("construction").findall("element"):
        if el.attrib["type"] == "angle":
            assert float(el.find("animation").attrib["step"]) == pytest.approx(math.pi / 180)


def _split_pair(text: str) -> tuple[str, str]:
    depth = 0
    for i, ch in enumerate(text):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "," and depth == 1:
            return text[1:i], text[i + 1 : -1]
    raise AssertionError(text)


def test_ggb_cone_sides_point_along_phi_plus_minus_xi():
    """side n through P_i along the cone side at φ ± ξ from −y (Fig. 2), in the sliders."""
    phi1, phi2, mu1, mu2 = 1.2, 1.9, 0.7, 1.3
    g = Grasp(1.0, 1.5, 0.5, phi1, phi2, mu1=mu1, mu2=mu2)
    d = {p[0]: p for p in _protocol(_ggb_root(to_ggb(internal_force_diagram(g))))}
    vals = {"φ_1": phi1, "φ_2": phi2, "μ_1": mu1, "μ_2": mu2}
    syms = {k: sp.Float(v) for k, v in vals.items()}
    xi1, xi2 = math.atan(mu1), math.atan(mu2)
    expected = {
        1: (-math.sin(phi1 + xi1), -math.cos(phi1 + xi1)),  # clockwise at P1
        3: (-math.sin(phi1 - xi1), -math.cos(phi1 - xi1)),
        2: (math.sin(phi2 + xi2), -math.cos(phi2 + xi2)),  # counter-clockwise at P2
        4: (math.sin(phi2 - xi2), -math.cos(phi2 - xi2)),
    }
    for n, (ex, ey) in expected.items():
        through, direction = d[f"side{n}"][3]
        assert through == ("P1" if n in (1, 3) else "P2")
        assert direction.startswith(through + " + ")
        dx, dy = (
            float(parse_exact(t, symbols=syms)) for t in _split_pair(direction[len(through) + 3 :])
        )
        assert abs(dx * ey - dy * ex) < 1e-12 and dx * ex + dy * ey > 0


def test_ggb_refuses_symbolic_constructions():
    c = replay(diagram_specs(Grasp.symbolic("mu"))[:6], Grasp.symbolic("mu"))
    with pytest.raises(ValueError, match="symbolic"):
        ggb_xml(c)


GEOGEBRA = shutil.which("geogebra")
XVFB = shutil.which("xvfb-run")


@pytest.mark.skipif(
    GEOGEBRA is None or XVFB is None,
    reason="GeoGebra or xvfb-run not installed (Debian packages geogebra, xvfb, "
    "xauth: .ci/apt-packages.txt); the .ggb is then checked structurally",
)
def test_real_geogebra_recomputes_the_construction_from_moved_sliders(fig6, tmp_path):
    """GeoGebra opens the fig6 file with its sliders moved to another grasp and
    recomputes every object; its values match the closed form (28)-(39)."""
    new = {"x_1": 1.1, "x_2": 0.7, "y_P": 0.4, "φ_1": 1.2, "φ_2": 1.4, "μ_1": 0.9, "μ_2": 1.1}
    xml = read_ggb_xml(to_ggb(fig6))
    for label, v in new.items():
        xml, count = re.subn(
            rf'(<element type="(?:numeric|angle)" label="{label}">\s*'
            r'<caption[^>]*/>\s*<value val=")[^"]*"',
            rf'\g<1>{v!r}"',
            xml,
        )
        assert count == 1
    src = tmp_path / "moved.ggb"
    with zipfile.ZipFile(src, "w") as z:
        z.writestr("geogebra.xml", xml.encode("utf-8"))
    out = tmp_path / "values.txt"
    run = subprocess.run(
        [XVFB, "-a", GEOGEBRA, "--showSplash=false", f"--regressionFile={out}", str(src)],
        check=False,
        timeout=240,
        capture_output=True,
        text=True,
        env={"HOME": str(tmp_path), "PATH": "/usr/bin:/bin"},
    )
    assert out.exists(), f"GeoGebra wrote no values:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}"
    text = out.read_text(encoding="utf-8")
    pts = {
        m[1]: (float(m[2]), float(m[3]))
        for m in re.finditer(r"^Point (\S+) = .* == (\S+) (\S+)$", text, re.M)
    }
    S, C = closed_form_SC(1.1, 0.7, 0.4, 1.2, 1.4, 0.9, 1.1, lib=np)
    for n in (1, 2, 3, 4):
        assert pts[f"V{n}"] == pytest.approx((S[n - 1], C[n - 1]), abs=2e-6, rel=2e-6)
    mine = internal_force_diagram(Grasp(1.1, 0.7, 0.4, 1.2, 1.4, mu1=0.9, mu2=1.1))
    for s in mine.steps:
        if s.kind == "point":
            assert pts[s.name] == pytest.approx(
                (float(s.obj.x), float(s.obj.y)), abs=2e-6, rel=2e-6
            ), s.name
    assert "Curve kGrasp" in text


# ---------------------------------------------------------------------------
# TikZ through a real pdflatex
# ---------------------------------------------------------------------------
PDFLATEX = shutil.which("pdflatex")
NEEDS_TEX = pytest.mark.skipif(
    PDFLATEX is None,
    reason="pdflatex not found: CI installs Debian's texlive-latex-base and "
    "texlive-pictures from .ci/apt-packages.txt",
)


def _pdflatex(tex: Path) -> Path:
    r = subprocess.run(
        [PDFLATEX, "-interaction=nonstopmode", "-halt-on-error", tex.name],
        cwd=tex.parent,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stdout[-3000:]
    pdf = tex.with_suffix(".pdf")
    assert pdf.read_bytes()[:5] == b"%PDF-"
    return pdf


@NEEDS_TEX
@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_tikz_of_the_presets_compiles_with_pdflatex(preset, tmp_path):
    tex = tmp_path / f"{preset}.tex"
    export(internal_force_diagram(Grasp.preset(preset)), tex)
    _pdflatex(tex)


@NEEDS_TEX
@pytest.mark.parametrize("title", [None, "Mine: 100% {x_1} & $#~^\\ φ = π/3, √3 ≈ 1.7 ✓"])
def test_tikz_standalone_page_has_title_and_legend_and_no_overfull_box(title, tmp_path):
    """A page cut to the picture (not Letter or A4), its title (escaped: any text) above and
    a legend of the styles below, compiled without an overfull box (issue 23)."""
    own = internal_force_diagram(
        Grasp(
            x1="6/5",
            x2="3/10",
            y="2/5",
            phi1="61*pi/180",
            phi2="118*pi/180",
            xi1="67*pi/180",
            xi2="49*pi/180",
        )
    )
    tex = tmp_path / "own.tex"
    tex.write_text(to_tikz(own, title=title), encoding="utf-8")
    pdf = _pdflatex(tex)
    log = tex.with_suffix(".log").read_text("latin-1")
    # again with the PDF objects uncompressed, to read the page's MediaBox from the bytes
    r = subprocess.run(
        [
            PDFLATEX,
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-jobname=plain",
            "\\pdfobjcompresslevel=0\\input{own.tex}",
        ],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stdout[-2000:]
    assert "Overfull" not in log and "mktexpk" not in log  # no bitmap font either
    boxes = re.findall(
        rb"/MediaBox\s*\[\s*([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)",
        (tmp_path / "plain.pdf").read_bytes(),
    )
    assert len(boxes) == 1
    w, h = float(boxes[0][2]) - float(boxes[0][0]), float(boxes[0][3]) - float(boxes[0][1])
    # 11 cm of picture + 0.4 cm + a 4 pt border each side (and, where points crowd, 0.5 cm
    # and the zoomed inset, INSET_PT / FRAME_PT of the diagram's width); taller than the
    # picture for the title and legend
    from graspcompass.scene.labelling import FRAME_PT
    from graspcompass.scene.picture import INSET_PT, scene_of

    inset = 0.5 + 11 * INSET_PT / FRAME_PT if scene_of(own).inset is not None else 0.0
    assert w == pytest.approx((11.4 + inset) / 2.54 * 72 + 8, abs=2.0)
    assert 11.4 / 2.54 * 72 + 9 < h < 792 and (w, h) != (612, 792)
    text = tex.read_text("utf-8")
    head = re.search(r"\{\\large\\bfseries (.*)\\par\}", text).group(1)
    if title is None:  # a grasp of one's own gets its values as title, as every picture
        assert head == (
            r"x1 = 1.2, x2 = 0.3, y = 0.4, $\varphi$1 = 61$^\circ$, $\varphi$2 = 118$^\circ$, "
            r"$\xi$1 = 67$^\circ$, $\xi$2 = 49$^\circ$"
        )
    else:
        assert r"100\% \{x\_{}1\} \& \$\#\~{}\^{}\textbackslash{}" in head
        assert r"$\varphi$ = $\pi$/3, $\sqrt{3}$ $\approx$ 1.7 ?" in head
    for entry in (
        "perpendicular to a side",
        "signed length",
        "break point",
        "envelope",
        "friction cone",
        "compass arcs",
        "right angle",
    ):
        assert entry in text
    if shutil.which("pdftoppm"):  # the page as a picture: something is drawn on it
        subprocess.run(
            ["pdftoppm", "-r", "30", "-png", pdf.name, "page"], cwd=tmp_path, check=True, timeout=60
        )
        assert list(tmp_path.glob("page*.png"))


def _page_size(pdf: Path) -> tuple[float, float]:
    """The page's size in points, as pdfinfo reads it."""
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, timeout=60)
    m = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", info.stdout)
    assert m, info.stdout
    return float(m[1]), float(m[2])


@NEEDS_TEX
@pytest.mark.skipif(shutil.which("pdfinfo") is None, reason="pdfinfo (poppler-utils) not found")
def test_tikz_uses_the_standalone_class_where_installed(fig6, tmp_path):
    """The standalone page is made by the ``standalone`` class where TeX has it, and by
    ``article`` with the page cut to the same box where not (Debian's texlive-latex-base):
    the same page either way, 4 pt round the box, no overfull box, nothing added to the
    left of the box by the class's horizontal mode (line ends)."""
    text = to_tikz(fig6)
    assert text.count("\\documentclass") == 2  # one of two, by \IfFileExists
    sizes = {}
    for name, which in (("with", "standalone.cls"), ("without", "no-such-class-here.cls")):
        tex = tmp_path / f"{name}.tex"
        tex.write_text(text.replace("{standalone.cls}", "{" + which + "}", 1), encoding="utf-8")
        _pdflatex(tex)
        log = tex.with_suffix(".log").read_text("latin-1")
        assert "Overfull" not in log and "Underfull" not in log
        has_class = subprocess.run(["kpsewhich", "standalone.cls"], capture_output=True).stdout
        if name == "with" and has_class.strip():
            assert "Document Class: standalone" in log
        if name == "without":
            assert "Document Class: standalone" not in log
        sizes[name] = _page_size(tex.with_suffix(".pdf"))
    assert sizes["with"] == pytest.approx(sizes["without"], abs=0.5)


@NEEDS_TEX
def test_tikz_fragment_compiles_inside_a_document(fig6, tmp_path):
    (tmp_path / "pic.tex").write_text(to_tikz(fig6, standalone=False), encoding="utf-8")
    doc = tmp_path / "doc.tex"
    doc.write_text(
        "\\documentclass{article}\\usepackage{tikz}\\begin{document}\n"
        "\\input{pic.tex}\n\\end{document}\n",
        encoding="utf-8",
    )
    _pdflatex(doc)


def test_tikz_writes_decimals_and_the_exact_form(fig6):
    text = to_tikz(fig6)
    # §4.1: V2 = (√3, −3/2) and V1 = (−1 − √3, −3/2 − √3)
    m = re.search(r"\\coordinate \(V2\) at \((\S+), (\S+)\);", text)
    assert abs(float(m[1]) - math.sqrt(3)) < 1e-10 and float(m[2]) == -1.5
    assert "% exact: (sqrt(3), -3/2)" in text
    assert "% exact: (-sqrt(3) - 1, -sqrt(3) - 3/2)" in text
    assert "e-" not in re.sub(r"%.*", "", text)  # no exponent notation for TeX
    assert text.count("arc[start angle=") >= 2  # the envelope as exact arcs


# ---------------------------------------------------------------------------
# SVG, PNG, PDF
# ---------------------------------------------------------------------------
def test_svg_is_standalone_labelled_and_flipped(fig6):
    root = ET.fromstring(to_svg(fig6).encode("utf-8"))
    ns = {"s": "http://www.w3.org/2000/svg"}
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    assert root.attrib["viewBox"].startswith("0 0 ") and root.attrib["width"].endswith("mm")
    groups = {g.attrib["id"]: g for g in root.iter("{http://www.w3.org/2000/svg}g")}
    for name in ("P1", "P2", "V1", "V2", "X1", "circle1", "side1", "perp1", "envelope"):
        assert name in groups
    texts = ["".join(t.itertext()) for t in root.iterfind(".//s:text", ns)]
    assert "V2" in texts and "P1" in texts
    assert "Circle on the diameter O V1" in groups["circle1"].find("s:title", ns).text

    def cy(name: str) -> float:
        return float(groups[name].find("s:circle", ns).attrib["cy"])

    # V1 = (−1 − √3, −3/2 − √3) lies below O and V2 = (√3, −3/2) too: larger screen y
    assert cy("V1") > cy("V2") > cy("O")
    assert cy("P1") < cy("O")  # the contacts are above O (y = 1/2)


def test_png_and_pdf_go_through_the_renderer(fig6, tmp_path):
    assert export(fig6, tmp_path / "d.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert export(fig6, tmp_path / "d.pdf").read_bytes()[:5] == b"%PDF-"


def test_export_does_not_import_matplotlib():
    code = (
        "import sys, graspcompass.export as e; from graspcompass import Grasp, "
        "internal_force_diagram as d; c = d(Grasp.preset('table1a')); e.to_svg(c); "
        "e.to_tikz(c); e.to_ggb(c); e.dumps(c); assert 'matplotlib' not in sys.modules"
    )
    r = subprocess.run(
        [sys.executable, "-c", code],
        env={"PYTHONPATH": str(SRC)},
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stderr


def test_formats_and_extensions(tmp_path):
    assert FORMATS == ("ggb", "tikz", "svg", "json", "png", "pdf", "html")
    assert [
        guess_format(f"a.{e}") for e in ("ggb", "tex", "svg", "json", "png", "pdf", "html")
    ] == ["ggb", "tikz", "svg", "json", "png", "pdf", "html"]
    with pytest.raises(ValueError, match="cannot tell the format"):
        guess_format("a.docx")


# ---------------------------------------------------------------------------
# JSON
# ---------------------------------------------------------------------------
def assert_same(a, b) -> None:
    assert b.grasp == a.grasp and b.skipped == a.skipped
    assert [s.spec for s in b.steps] == [s.spec for s in a.steps]
    for s, t in zip(a.steps, b.steps):
        assert (t.index, t.obj, t.conditions, t.kind) == (s.index, s.obj, s.conditions, s.kind)


def test_json_schema_and_exact_strings(fig6):
    doc = to_document(fig6)
    assert doc["schema"] == SCHEMA == "graspcompass.construction/1"
    assert doc["grasp"]["friction"] == {"1": "mu", "2": "mu"}
    v2 = next(s for s in doc["steps"] if s["name"] == "V2")
    # §4.1 by hand: V2 = (√3, −3/2)
    assert parse_exact(v2["value"]["x"]) == sp.sqrt(3)
    assert parse_exact(v2["value"]["y"]) == sp.Rational(-3, 2)
    assert v2["inputs"] == ["OMX2", "OY2"] and v2["ref"].startswith("§3.3")
    assert_same(fig6, loads(dumps(fig6)))


@settings(
    max_examples=6, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)
@given(exact_params())
def test_json_round_trip_exact_grasps(p):
    c = internal_force_diagram(p.grasp())
    assert_same(c, loads(dumps(c)))


@settings(
    max_examples=10, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)
@given(float_params())
def test_json_round_trip_float_grasps(p):
    c = internal_force_diagram(p.grasp())
    assert_same(c, loads(dumps(c)))


def test_json_round_trip_symbolic_and_partial():
    g = Grasp.symbolic("xi")
    c = replay(diagram_specs(g)[:12], g)
    back = loads(dumps(c))
    assert_same(c, back) and back.conditions == c.conditions
    assert "tan(xi1)" in dumps(c)


def test_json_refuses_bad_documents(fig6):
    with pytest.raises(ValueError, match=r"not a graspcompass\.construction/1"):
        loads('{"schema": "other"}')
    with pytest.raises(ValueError, match="not JSON"):
        loads("{")
    doc = to_document(fig6)
    doc["steps"][17]["value"]["x"] = "0"
    with pytest.raises(ValueError, match="does not match its replay"):
        loads(__import__("json").dumps(doc))
    doc = to_document(fig6)
    doc["steps"][5]["op"] = "eval"
    with pytest.raises(ValueError, match="unknown operation"):
        loads(__import__("json").dumps(doc))


# ---------------------------------------------------------------------------
# the command line sub-commands
# ---------------------------------------------------------------------------
def _parse(*argv: str) -> argparse.Namespace:
    p = argparse.ArgumentParser()
    register(p.add_subparsers(dest="command"), _add_grasp_options)
    return p.parse_args(list(argv))


@pytest.mark.parametrize("fmt", ["ggb", "tikz", "svg", "json"])
def test_cli_export_writes_each_format(fmt, tmp_path, capsys):
    out = tmp_path / f"t.{ {'tikz': 'tex'}.get(fmt, fmt) }"
    args = _parse("export", "--preset", "table1b", "--format", fmt, "-o", str(out))
    assert run_export(args, Grasp.preset("table1b")) == 0
    assert f"wrote {out}" in capsys.readouterr().out and out.stat().st_size > 1000


def test_cli_export_step_and_errors(tmp_path):
    args = _parse("export", "-o", str(tmp_path / "s.json"), "--step", "8", "-q")
    run_export(args, Grasp.preset("fig6"))
    assert len(loads((tmp_path / "s.json").read_text())) == 9
    with pytest.raises(ValueError, match="out of range"):
        run_export(
            _parse("export", "-o", str(tmp_path / "s.json"), "--step", "999"), Grasp.preset("fig6")
        )
    with pytest.raises(ValueError, match="TikZ only"):
        run_export(
            _parse("export", "-o", str(tmp_path / "s.svg"), "--fragment"), Grasp.preset("fig6")
        )


def test_cli_explore_without_display_is_a_one_line_error():
    import matplotlib

    matplotlib.use("Agg")
    with pytest.raises(ValueError) as err:
        run_explore(_parse("explore"), Grasp.preset("fig6"))
    assert "\n" not in str(err.value) and "cannot open the explorer window" in str(err.value)


# ---------------------------------------------------------------------------
# JSON files written by the command line, read back (issue 10, item 4)
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_cli_json_files_reload_and_refuse_a_tampered_grasp(preset, tmp_path):
    from graspcompass.errors import InputError
    from graspcompass.export.json import InconsistentDocumentError

    out = tmp_path / "c.json"
    run_export(_parse("export", "--preset", preset, "-o", str(out), "-q"), Grasp.preset(preset))
    text = out.read_text(encoding="utf-8")
    assert dumps(loads(text)).strip() == text.strip()  # the same file again
    doc = __import__("json").loads(text)
    doc["grasp"]["x2"] = "7/5"  # the contact P2 moved, its steps not
    with pytest.raises(InconsistentDocumentError) as err:
        loads(__import__("json").dumps(doc))
    assert isinstance(err.value, InputError) and str(err.value).startswith("steps[4] (P2)")


# ---------------------------------------------------------------------------
# symbolic records, and dumps refusing what loads refuses (issue 10)
# ---------------------------------------------------------------------------
def test_float_readouts_of_symbolic_values_are_not_evaluated(monkeypatch):
    import importlib

    describe = importlib.import_module("graspcompass.construction.describe")

    evalf = sp.N

    def no_evalf(expr, *args, **kwargs):
        if getattr(expr, "free_symbols", None):
            raise AssertionError(f"{expr}, an expression in symbols, was evaluated")
        return evalf(expr, *args, **kwargs)

    monkeypatch.setattr(sp, "N", no_evalf)
    x = sp.Symbol("x")
    assert describe._num(sp.sqrt(x**2 + 1) + sp.pi) is None
    point = describe._value(__import__("graspcompass").geometry.Point(x, 1))
    assert point["float"] == [None, 1.0]
    g = Grasp.symbolic("mu")
    text = dumps(replay(diagram_specs(g)[:12], g))  # every readout None, none evaluated
    assert dumps(loads(text)) == text


def _beyond_limits():
    from graspcompass.export.json import MAX_MAGNITUDE, MAX_TITLE

    half = dict(phi1="pi/2", phi2="pi/2", mu2=1)
    return {
        "four square roots": (
            dict(x1="sqrt(2)", x2="sqrt(3)", y="sqrt(5)", mu1="sqrt(7)", **half),
            "4 distinct irrational numbers",
        ),
        "a large length": (
            dict(x1=int(MAX_MAGNITUDE) * 10, x2=1, y=0, mu1=1, **half),
            "grasp.x1: expected a number at most 1e+15",
        ),
        "a long title": (
            dict(x1=1, x2=1, y=0, mu1=1, title="t" * (MAX_TITLE + 1), **half),
            "grasp.title: a text of 1001 characters",
        ),
        "a wide float": (
            dict(x1=sp.Float("1.1", 400), x2=1.0, y=0.0, phi1=1.5, phi2=1.5, mu1=1.0, mu2=1.0),
            "grasp.x1.bits: expected an integer",
        ),
        "a large radicand": (
            dict(x1=f"sqrt({2**70 + 1})", x2=1, y=0, mu1=1, **half),
            "a square root of a number of more than 64 bits",
        ),
    }


@pytest.mark.parametrize("case", list(_beyond_limits()))
def test_dumps_refuses_what_loads_refuses(case):
    from graspcompass.export.json import JSONTooLargeError, _grasp_record, from_document

    kw, message = _beyond_limits()[case]
    g = Grasp(**kw)
    with pytest.raises(JSONTooLargeError, match=re.escape(message)) as written:
        dumps(internal_force_diagram(g))
    # the same error and message as the loader's, on the document dumps would have written
    doc = {"schema": SCHEMA, "grasp": _grasp_record(g), "skipped": [], "steps": []}
    with pytest.raises(JSONTooLargeError) as read:
        from_document(doc)
    assert str(read.value) == str(written.value)


def test_dumps_refuses_a_text_loads_cannot_read(fig6, monkeypatch):
    from graspcompass.export import json as gj

    monkeypatch.setattr(gj, "MAX_BYTES", 1000)
    with pytest.raises(gj.JSONTooLargeError, match=r"the JSON text has \d+ bytes, more than 1000"):
        dumps(fig6)


@NEEDS_TEX
def test_tikz_fig6_has_the_zoomed_inset_and_compiles(fig6, tmp_path):
    """Fig. 6's crowded centre (issue 23): a second picture beside the diagram, zoomed on
    the scene's inset, naming the points left to it; compiled by pdflatex, the right part
    of the page is drawn on (pdftoppm)."""
    from graspcompass.scene.picture import scene_of

    inset = scene_of(fig6).inset
    assert inset is not None
    text = to_tikz(fig6)
    assert text.count("\\begin{tikzpicture}") == 2
    main, zoom = text.split("zoomed inset of the crowded region", 1)
    for lab in inset.labels:
        assert f"{{${lab.tex()}$}};" in zoom, lab.names
    for lab in inset.main:
        assert f"{{${lab.tex()}$}};" in main, lab.names
    # O = O_M = Y4 crowds in the diagram: it is named in the inset only
    assert "{$O = O_M = Y_4$}" in zoom and "{$O = O_M = Y_4$}" not in main
    tex = tmp_path / "fig6.tex"
    tex.write_text(text, encoding="utf-8")
    pdf = _pdflatex(tex)
    assert "Overfull" not in tex.with_suffix(".log").read_text("latin-1")
    if shutil.which("pdftoppm"):
        subprocess.run(
            ["pdftoppm", "-r", "20", "-gray", pdf.name, "page"],
            cwd=tmp_path,
            check=True,
            timeout=60,
        )
        (pgm,) = tmp_path.glob("page*.pgm")
        raw = pgm.read_bytes()
        head = raw.split(b"\n", 3)
        w, h = (int(v) for v in head[1].split())
        pixels = head[3]
        right = [pixels[r * w + c] for r in range(h) for c in range(int(0.6 * w), w)]
        assert sum(p < 128 for p in right) > 0.01 * len(right)


def _labelled_points(svg: str) -> set[str]:
    """The ids of the point groups of an SVG that hold a label (``<text>``)."""
    root = ET.fromstring(svg.encode("utf-8"))
    ns = "{http://www.w3.org/2000/svg}"
    return {
        re.sub(r"^inset\d*-", "", g.get("id"))
        for g in root.iter(f"{ns}g")
        if g.get("class") == "point" and g.find(f"{ns}text") is not None
    }


def test_svg_labels_the_break_points_on_request(fig6):
    # Fig. 6's envelope runs on circles 2, 4, 3, 1 in turn: its cusps, where it passes
    # from circle i to circle j, are B24, B34, B13, B12; B14 and B23 lie off it
    on = {"B12", "B13", "B24", "B34"}
    plain = _labelled_points(to_svg(fig6))
    lit = _labelled_points(to_svg(fig6, break_points=True))
    assert not any(n.startswith("B") for n in plain)
    assert {n for n in lit if n.startswith("B")} == on
    assert lit - on == plain  # the other labels stay
    tikz = to_tikz(fig6, break_points=True)
    assert set(re.findall(r"\$(B)_\{(\d\d)\}\$", tikz)) == {("B", n[1:]) for n in on}
    assert not re.findall(r"\$B_\{\d\d\}\$", to_tikz(fig6))


def test_export_cli_break_points(tmp_path, capsys):
    parser = argparse.ArgumentParser()
    register(parser.add_subparsers(dest="command"), _add_grasp_options)
    for flag in ([], ["--break-points"]):
        out = tmp_path / f"f{len(flag)}.svg"
        args = parser.parse_args(["export", "--preset", "fig6", "-o", str(out), "-q", *flag])
        assert run_export(args, Grasp.preset("fig6")) == 0
        named = {n for n in _labelled_points(out.read_text()) if n.startswith("B")}
        assert named == ({"B12", "B13", "B24", "B34"} if flag else set())
    args = parser.parse_args(
        ["export", "--preset", "fig6", "-o", str(tmp_path / "f.json"), "--break-points"]
    )
    with pytest.raises(ValueError, match="--break-points is for"):
        run_export(args, Grasp.preset("fig6"))
