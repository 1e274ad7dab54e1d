"""Right-angle marks in the zoomed inset keep their size on the page (issue 23).

The marks are sized by the diagram's view; an inset drawn 5x larger used to draw
them 5x larger too.  Each painter's output is measured on its own terms: the SVG's
user units, TikZ's centimetres, the PNG's pixels.  The expected size is the mark's
size in the diagram beside it, measured in the same output.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from graspcompass import Grasp, internal_force_diagram
from graspcompass.export import to_svg, to_tikz
from graspcompass.scene.picture import scene_of
from test_svg_labels_browser import random_grasps

NS = {"s": "http://www.w3.org/2000/svg"}


def _grasps() -> list[Grasp]:
    out = [Grasp.preset(p) for p in ("fig6", "table1a", "table1b", "table1c")]
    return out + random_grasps(6, seed=2312)


def _side(points: list[tuple[float, float]]) -> float:
    return math.dist(points[0], points[1])


def _svg_sides(svg: str) -> tuple[list[float], list[float]]:
    root = ET.fromstring(svg)
    inset = root.find(".//s:g[@id='inset']", NS)
    inner = set() if inset is None else {id(e) for e in inset.iter()}
    main, zoomed = [], []
    for e in root.iter("{http://www.w3.org/2000/svg}polyline"):
        if "right_angle" not in e.get("class", ""):
            continue
        pts = [tuple(map(float, p.split(","))) for p in e.get("points").split()]
        (zoomed if id(e) in inner else main).append(_side(pts))
    return main, zoomed


@pytest.mark.parametrize("grasp", _grasps(), ids=lambda g: g.title or "random")
def test_svg_inset_right_angles_keep_their_size(grasp: Grasp) -> None:
    c = internal_force_diagram(grasp)
    main, zoomed = _svg_sides(to_svg(c))
    assert main, "the diagram has right-angle marks"
    if scene_of(c).inset is None:
        assert not zoomed
        return
    assert zoomed, "the inset shows the right-angle marks of its region"
    ref = max(main)
    assert max(zoomed) <= 1.01 * ref and min(zoomed) >= 0.99 * ref, (ref, zoomed)


def _tikz_sides(tex: str) -> tuple[list[float], list[float]]:
    """Mark sides in cm: the pictures' units are read from their options."""
    pictures = tex.split("\\begin{tikzpicture}")[1:]
    out = []
    for pic in pictures:
        unit = re.search(r"x=([0-9.]+)cm", pic)
        if unit is None:  # the styles before the picture set the unit (\tikzset)
            unit = re.search(r"x=([0-9.]+)cm", tex[: tex.index(pic)])
        u = float(unit.group(1))
        sides = []
        for line in re.findall(r"\\draw\[instrument[^\]]*\] (.*?); % right_angle", pic):
            pts = [tuple(map(float, p)) for p in re.findall(r"\(([-0-9.e]+), ([-0-9.e]+)\)", line)]
            sides.append(u * _side(pts))
        out.append(sides)
    return out[0], out[1] if len(out) > 1 else []


@pytest.mark.parametrize("standalone", [False, True])
@pytest.mark.parametrize("preset", ["fig6", "table1c"])
def test_tikz_inset_right_angles_keep_their_size(preset: str, standalone: bool) -> None:
    c = internal_force_diagram(Grasp.preset(preset))
    assert scene_of(c).inset is not None
    main, zoomed = _tikz_sides(to_tikz(c, standalone=standalone))
    assert main and zoomed
    ref = max(main)
    assert max(zoomed) <= 1.01 * ref and min(zoomed) >= 0.99 * ref, (ref, zoomed)


@pytest.mark.parametrize("grasp", _grasps()[:1] + _grasps()[4:6], ids=lambda g: g.title or "rnd")
def test_png_inset_right_angles_keep_their_size(grasp: Grasp) -> None:
    pytest.importorskip("matplotlib")
    import numpy as np

    from graspcompass.render import figure_diagram

    c = internal_force_diagram(grasp)
    if scene_of(c).inset is None:
        pytest.skip("no inset for this grasp")
    fig = figure_diagram(c)
    fig.canvas.draw()
    sides: dict[int, list[float]] = {}
    for i, ax in enumerate(fig.axes[:2]):
        for line in ax.get_lines():
            if line.get_gid() == "instrument:right_angle":
                xy = ax.transData.transform(np.column_stack(line.get_data()))
                sides.setdefault(i, []).append(_side([tuple(p) for p in xy]))
    main, zoomed = sides[0], sides.get(1, [])
    assert zoomed, "the inset shows the right-angle marks of its region"
    ref = max(main)
    assert max(zoomed) <= 1.02 * ref and min(zoomed) >= 0.98 * ref, (ref, zoomed)
