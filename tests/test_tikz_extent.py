"""TikZ of grasps with zoomed insets stays inside TeX's lengths (16383.99 pt).

Found by a hostile run of issue 23: an inset drawn at 200 or 1400 times the diagram's
scale wrote the scene's lines (thousands of units long) in its own unit, and pdflatex
stopped with "! Dimension too large" on 15 of 64 wide random grasps.  The measure here
is the file's text: every number of every ``tikzpicture`` times that picture's unit
(``x=...cm``), in points, and a real pdflatex on the grasps that failed.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram
from graspcompass.export import to_svg, to_tikz

TEX_LIMIT_PT = 16383.99
PT_PER_CM = 72.27 / 2.54

#: grasps of the hostile run whose TikZ did not compile (two or three insets)
FAILED = [
    Grasp("3.79", "0.093", "2.1", "89*pi/180", "89deg", xi1="pi/6", xi2="1.1deg"),
    Grasp("0.67", "1.506", "0.02", "90deg", "121deg", xi1="77*pi/180", xi2="25*pi/144"),
    Grasp("0.737", "0.0756", "0.6632", "pi/18", "93deg", xi1="80.1deg", xi2="4.25deg"),
    Grasp("2.11", "0.4901", "0.0146", "10deg", "89*pi/90", xi1="88.5deg", xi2="59*pi/120"),
]

_PICTURE = re.compile(r"\\begin\{tikzpicture\}\[([^\]]*)\](.*?)\\end\{tikzpicture\}", re.S)
_UNIT = re.compile(r"\bx=([0-9.]+)cm")
_NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?")


def largest_pt(tex: str) -> float:
    """The largest number of a picture's coordinates and radii times its unit, in pt."""
    worst = 0.0
    for head, body in _PICTURE.findall(tex):
        unit = _UNIT.search(head)
        if unit is None:  # the legend's samples (x=1cm given as a style), a few mm
            continue
        scale = float(unit.group(1)) * PT_PER_CM
        code = "\n".join(ln for ln in body.splitlines() if not ln.lstrip().startswith("%"))
        # radii as (r); the arcs' angles are degrees, not lengths
        code = re.sub(r"(?:arc|circle)\[[^\]]*radius=([-0-9.]+)\]", r"(\1)", code)
        code = re.sub(r"\[[^\]]*\]", "", code)  # styles and options
        for m in re.finditer(r"\(([^()]*)\)", code):
            for v in _NUMBER.findall(m.group(1)):
                worst = max(worst, abs(float(v)) * scale)
    return worst


def _insets(g: Grasp) -> int:
    return to_svg(internal_force_diagram(g)).count('class="panel"') - 1


@pytest.mark.parametrize("k", range(len(FAILED)))
def test_the_failed_grasps_stay_inside_tex(k: int) -> None:
    tex = to_tikz(internal_force_diagram(FAILED[k]))
    assert tex.count("\\begin{tikzpicture}[") >= 2  # the diagram and at least one inset
    assert largest_pt(tex) < TEX_LIMIT_PT / 2


def test_the_measure_sees_a_picture_too_large() -> None:
    bad = "\\begin{tikzpicture}[x=3cm, y=3cm]\n\\draw (-2930, 0) -- (1, 2);\n\\end{tikzpicture}"
    assert largest_pt(bad) > TEX_LIMIT_PT
    ok = "\\begin{tikzpicture}[x=3cm, y=3cm]\n% (-2930, 0) a comment\n\\draw (1, 2);\n"
    assert largest_pt(ok + "\\end{tikzpicture}") < 200
    arc = "\\draw (0, 0) arc[start angle=9000, delta angle=30, radius=2000];\n"
    assert largest_pt(ok + arc + "\\end{tikzpicture}") > TEX_LIMIT_PT


@settings(max_examples=6, deadline=None, suppress_health_check=list(HealthCheck))
@given(
    st.integers(5, 400),
    st.integers(5, 400),
    st.integers(0, 300),
    st.integers(2, 178),
    st.integers(2, 178),
    st.data(),
)
def test_wide_random_grasps_stay_inside_tex(x1, x2, y, p1, p2, data) -> None:
    k1 = data.draw(st.integers(abs(p1 - 90) + 1, 89))
    k2 = data.draw(st.integers(abs(p2 - 90) + 1, 89))
    g = Grasp(x1 / 100, x2 / 100, y / 100, f"{p1}deg", f"{p2}deg", xi1=f"{k1}deg", xi2=f"{k2}deg")
    assert largest_pt(to_tikz(internal_force_diagram(g))) < TEX_LIMIT_PT / 2


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex not found")
def test_a_grasp_with_three_insets_compiles(tmp_path: Path) -> None:
    g = FAILED[0]
    assert _insets(g) >= 2
    tex = tmp_path / "three.tex"
    tex.write_text(to_tikz(internal_force_diagram(g)), encoding="utf-8")
    r = subprocess.run(
        ["pdflatex", "-interaction=nonstopmode", "-halt-on-error", tex.name],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stdout[-2000:]
    assert (tmp_path / "three.pdf").stat().st_size > 10_000
