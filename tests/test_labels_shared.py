"""One label placement for every painter (issue 12 §4): the SVG and TikZ of Fig. 6 and
Table I place the labels around O apart, on the same sides as the PNG
(:mod:`graspcompass.labelling`, shared by :mod:`graspcompass.render.labels` and the scene)."""

from __future__ import annotations

import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from _label_rules import overlap
from graspcompass import Grasp, internal_force_diagram, labelling
from graspcompass.export import to_svg, to_tikz
from graspcompass.export._scene import build_scene
from graspcompass.export.tikz import ANCHORS

PRESETS = ["fig6", "table1a", "table1b", "table1c"]
NS = {"s": "http://www.w3.org/2000/svg"}


def _svg_labels(text: str) -> tuple[dict[str, tuple[float, ...]], dict[str, tuple[float, ...]]]:
    """Label boxes (x0, y0, x1, y1, SVG units, y down) and markers (cx, cy, r) by point.

    Every marker, the envelope's break points (small, unlabelled) included: the placement
    avoids them, in the PNG as in the SVG.
    """
    root = ET.fromstring(text.encode())
    boxes, markers = {}, {}
    for g in root.iterfind(".//s:g[@class='point']", NS):
        c = g.find("s:circle", NS)
        t = g.find("s:text", NS)
        markers[g.get("id")] = (float(c.get("cx")), float(c.get("cy")), float(c.get("r")))
        if t is None:
            continue
        f = float(t.get("font-size"))
        main = (t.text or "") + "".join(s.tail or "" for s in t)
        subs = "".join(s.text or "" for s in t)
        # glyph widths of an italic sans: ~0.6 em, subscripts at 70 % (anchor: start unless said)
        width = 0.6 * f * len(main.replace(" ", "")) + 0.25 * f * main.count(" ")
        width += 0.6 * 0.7 * f * len(subs)
        x, y = float(t.get("x")), float(t.get("y"))
        x0 = {"start": x, "end": x - width, "middle": x - width / 2}[t.get("text-anchor", "start")]
        boxes[g.get("id")] = (x0, y - 0.75 * f, x0 + width, y + 0.25 * f)
    return boxes, markers


@pytest.fixture(scope="module", params=PRESETS)
def construction(request):
    return internal_force_diagram(Grasp.preset(request.param))


def test_svg_labels_do_not_overlap_each_other_or_markers(construction) -> None:
    boxes, markers = _svg_labels(to_svg(construction))
    assert len(boxes) >= 10
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert overlap(boxes[a], boxes[b]) == 0.0, (a, b)
        for p, (cx, cy, r) in markers.items():
            if p != a:
                assert overlap(boxes[a], (cx - r, cy - r, cx + r, cy + r)) == 0.0, (a, p)


def test_fig6_labels_around_O_apart() -> None:
    """The clause of issue 12 §4: O = O_M = Y4, P1x = V4, Y1, X1 ... readable."""
    c = internal_force_diagram(Grasp.preset("fig6"))
    boxes, _ = _svg_labels(to_svg(c))
    o = "O" if "O" in boxes else "inset-O"  # named in the zoomed inset where they crowd
    assert o in boxes
    near = [
        n
        for n, b in boxes.items()
        if n != o and abs(b[0] - boxes[o][0]) < 120 and abs(b[1] - boxes[o][1]) < 120
    ]
    assert near  # labels crowd around O, and none covers O's
    assert all(overlap(boxes[o], boxes[n]) == 0.0 for n in near)


def test_tikz_labels_have_the_svg_anchors(construction) -> None:
    scene = build_scene(construction)
    svg = to_svg(construction)
    tikz = to_tikz(construction)
    root = ET.fromstring(svg.encode())
    boxes, markers = _svg_labels(svg)
    found = 0
    for lab in scene.labels:
        g = root.find(f".//s:g[@id='{lab.names[0]}']", NS)
        if g.find("s:text", NS) is None:  # named in the SVG's zoomed inset only
            assert scene.inset is not None and lab not in scene.inset.main
            continue
        # the SVG's text on the side of its point that the label's direction says
        (bx0, by0, bx1, by1), (cx, cy, _) = boxes[lab.names[0]], markers[lab.names[0]]
        mx, my = (bx0 + bx1) / 2, (by0 + by1) / 2
        dx, dy = lab.direction
        if dx:
            assert (mx - cx) * dx > 0, lab.names
        if dy:
            assert (cy - my) * dy > 0, lab.names  # SVG's y points down
        node = re.search(
            rf"\\node\[label, anchor=([a-z ]+)\] at \(([-\d.]+), ([-\d.]+)\) "
            rf"\{{\${re.escape(_tex(lab.names))}\$\}};",
            tikz,
        )
        assert node is not None, lab.names
        assert node.group(1) == ANCHORS[lab.direction]
        assert (float(node.group(2)), float(node.group(3))) == pytest.approx(lab.at, abs=1e-9)
        found += 1
    assert found >= 8


def _tex(names: tuple[str, ...]) -> str:
    from graspcompass.export._scene import label_tex

    return " = ".join(label_tex(n) for n in names)


@pytest.mark.parametrize("preset", PRESETS)
def test_png_and_svg_labels_on_the_same_sides(preset: str) -> None:
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    from matplotlib.text import Annotation

    from graspcompass.render.figure import draw_construction

    c = internal_force_diagram(Grasp.preset(preset))
    arts = draw_construction(c)
    ax = arts["O"][0].axes
    scene = build_scene(c)
    assert ax.get_xlim() == pytest.approx(scene.box[:2])
    # the placement's frame is this axes' size in points
    side_pt = ax.bbox.width * 72.0 / ax.figure.dpi
    assert side_pt == pytest.approx(labelling.FRAME_PT, rel=1e-6)
    ha = {"left": 1, "right": -1, "center": 0}
    va = {"bottom": 1, "top": -1, "center": 0}
    for lab in scene.labels:
        (t,) = [a for a in arts[lab.names[0]] if isinstance(a, Annotation)]
        assert (ha[t.get_ha()], va[t.get_va()]) == lab.direction, lab.names
        assert t.get_text() == f"${_tex(lab.names)}$"


def test_the_shared_sizes_are_the_default_theme() -> None:
    pytest.importorskip("matplotlib")
    from graspcompass.render.figure import _LABEL_ORDER
    from graspcompass.render.theme import DEFAULT_THEME

    assert labelling.FONT_PT == DEFAULT_THEME.font_size
    assert labelling.MARKER_PT == DEFAULT_THEME.point_size
    assert labelling.LABEL_ORDER == _LABEL_ORDER


def test_labelling_and_scene_do_not_import_matplotlib() -> None:
    code = (
        "import sys, graspcompass.labelling, graspcompass.layout; "
        "import graspcompass.export._scene as s; "
        "from graspcompass import Grasp, internal_force_diagram; "
        "s.build_scene(internal_force_diagram(Grasp.preset('fig6'))); "
        "assert 'matplotlib' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)


@pytest.mark.parametrize("radius", [1e6, 1e12, 1e300])
def test_huge_curves_cost_what_the_frame_holds(radius: float) -> None:
    """A circle near a bound of condition (1) is huge (|V_n| grows like 1/cos(φ ± ξ)):
    only its samples near the labels count, so placing labels beside it is as quick as
    beside a small one and gives the same answer as its part near the labels alone."""
    import math

    import numpy as np

    from _hang import no_hang

    anchors = [(100.0, 100.0), (140.0, 100.0), (120.0, 130.0)]
    texts = ["$V_1$", "$X_2$", "$O = O_M$"]
    t = np.linspace(0.0, 2 * math.pi, 100)
    # a circle through (120, 95) with its centre far below: nearly a line under the points
    centre = (120.0, 95.0 - radius)
    huge = np.column_stack([centre[0] + radius * np.sin(t), centre[1] + radius * np.cos(t)])
    with no_hang("label placement beside a huge circle", 10):
        placed = labelling.place(anchors, texts, curves=[huge], frame=(0, 0, 388.08, 388.08))
    assert len(placed) == 3
    # what the labels see of it: the horizontal line y = 95 (the circle's chord near the
    # top is the segment from its first vertex, (120, 95), along t: a line at this scale)
    near = np.array([[120.0 - 400.0, 95.0], [120.0, 95.0], [120.0 + 400.0, 95.0]])
    if radius >= 1e12:  # the 100-gon's first edge: from (120, 95) to the right, level
        assert [p.direction for p in placed] == [
            p.direction
            for p in labelling.place(
                anchors, texts, curves=[near[1:]], frame=(0, 0, 388.08, 388.08)
            )
        ]
