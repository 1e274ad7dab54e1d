"""One picture everywhere (issue 12 §4, issue 11 §1): one view box for the matplotlib
drawing and the SVG/TikZ scene, and every painter reads a step's role as data, never its
name (a construction with every object renamed draws the same picture)."""

from __future__ import annotations

import dataclasses

import pytest

from graspcompass import Grasp, internal_force_diagram
from graspcompass.construction.language import paper_program, replay
from graspcompass.export._scene import build_scene
from graspcompass.render.figure import draw_construction

pytest.importorskip("matplotlib")


@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1b", "table1c"])
def test_png_and_svg_share_the_view_box(preset: str) -> None:
    c = internal_force_diagram(Grasp.preset(preset))
    ax = draw_construction(c)["O"][0].axes
    box = build_scene(c).box
    assert ax.get_xlim() == pytest.approx(box[:2]) and ax.get_ylim() == pytest.approx(box[2:])


def _renamed(program):
    """The paper's program with every object renamed (roles and indices kept)."""
    new = {s.name: f"obj{i}" for i, s in enumerate(program.steps)}
    steps = tuple(
        dataclasses.replace(s, name=new[s.name], inputs=tuple(new.get(n, n) for n in s.inputs))
        for s in program.steps
    )
    return dataclasses.replace(program, steps=steps, claims=()), new


def test_renamed_construction_draws_the_same_picture() -> None:
    g = Grasp.preset("table1c")
    prog, new = _renamed(paper_program())
    a, b = internal_force_diagram(g), replay(prog, g)
    arts_a, arts_b = draw_construction(a), draw_construction(b)
    for key in ("cone1", "cone2"):  # the friction cones, from the roles contact / cone_side
        assert key in arts_a and key in arts_b
    ax_a, ax_b = arts_a["O"][0].axes, arts_b[new["O"]][0].axes
    assert ax_a.get_xlim() == ax_b.get_xlim() and ax_a.get_ylim() == ax_b.get_ylim()
    # break points small and unlabelled, axes labelled x and y, by role
    for name in ("B12", "B34"):
        if name in a.names:
            assert arts_a[name][0].get_markersize() == pytest.approx(
                arts_b[new[name]][0].get_markersize()
            )
    texts = lambda ax: sorted(t.get_text() for t in ax.texts)  # noqa: E731
    assert {"x", "y"} <= set(texts(ax_b))
    sa, sb = build_scene(a), build_scene(b)
    assert sa.box == pytest.approx(sb.box)
    assert len(sa.cones) == len(sb.cones) == 2
    assert {new[n] for n in sa.small} == set(sb.small)
    assert [r for _, r, *_ in sa.lines] == [r for _, r, *_ in sb.lines]
    assert [n for _, n, *_ in sa.circles] == [n for _, n, *_ in sb.circles] == [1, 2, 3, 4]


def test_renamed_construction_gives_the_same_geogebra_file() -> None:
    """The sliders drive the contacts and the cone sides found by role, whatever their names."""
    import re

    from graspcompass.export.geogebra import read_ggb_xml, to_ggb

    g = Grasp.preset("table1a")
    prog, new = _renamed(paper_program())
    xa = read_ggb_xml(to_ggb(internal_force_diagram(g)))
    xb = read_ggb_xml(to_ggb(replay(prog, g)))
    # every command and expression, with the names mapped back
    back = {v: k for k, v in new.items()}

    def defs(xml: str, rename: dict[str, str]) -> list[str]:
        items = re.findall(r'<(?:command name|expression label)="([^"]*)"', xml)
        body = re.findall(r'(?:exp|a\d)="([^"]*)"', xml)
        words = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
        return [words.sub(lambda m: rename.get(m.group(), m.group()), t) for t in items + body]

    from graspcompass.export._ggb_defs import ggb_label

    rename = {ggb_label(k): ggb_label(v) for k, v in back.items()}
    assert defs(xb, rename) == defs(xa, {})
    assert "(x_1, y_P)" in xb and "(-x_2, y_P)" in xb


def test_one_palette_for_png_svg_tikz_and_geogebra() -> None:
    """The theme, the SVG/TikZ scene and the GeoGebra writer read one palette."""
    from graspcompass.export import _scene, geogebra
    from graspcompass.palette import PALETTE, rgb
    from graspcompass.render.theme import DEFAULT_THEME

    assert _scene.COLORS is PALETTE
    assert DEFAULT_THEME.circle_colors == tuple(PALETTE[f"circle{n}"] for n in (1, 2, 3, 4))
    assert (DEFAULT_THEME.side_color, DEFAULT_THEME.axis_color, DEFAULT_THEME.envelope_fill) == (
        PALETTE["side"],
        PALETTE["axis"],
        PALETTE["fill"],
    )
    for role, (r, g, b) in geogebra._RGB.items():
        assert f"#{r:02x}{g:02x}{b:02x}" == PALETTE[role] and rgb(role) == (r, g, b)
    svg = __import__("graspcompass.export.svg", fromlist=["to_svg"]).to_svg(
        internal_force_diagram(Grasp.preset("fig6"))
    )
    for n in (1, 2, 3, 4):
        assert PALETTE[f"circle{n}"] in svg


@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1b", "table1c"])
def test_geogebra_labels_where_the_svg_puts_them(preset: str) -> None:
    """GeoGebra draws a point's name with its baseline's left end at (x + 4, y − 2 s) plus
    ``labelOffset`` (DrawPoint.update, GeoGebra's source); rebuilt from the file alone,
    each label sits on its side of the point as in the scene, and none covers another."""
    import re
    import xml.etree.ElementTree as ET

    from graspcompass.export.geogebra import ggb_xml

    c = internal_force_diagram(Grasp.preset(preset))
    root = ET.fromstring(ggb_xml(c).encode())
    cs = root.find("euclidianView/coordSystem").attrib
    x0, y0, scale = float(cs["xZero"]), float(cs["yZero"]), float(cs["scale"])
    font = float(root.find("gui/font").attrib["size"])
    boxes = {}
    for el in root.iterfind("construction/element[@type='point']"):
        off = el.find("labelOffset")
        if el.find("show").attrib["label"] != "true":
            continue
        assert off is not None, el.attrib["label"]
        co = el.find("coords").attrib
        sx, sy = x0 + float(co["x"]) * scale, y0 - float(co["y"]) * scale
        size = float(el.find("pointSize").attrib["val"])
        bx = sx + 4 + float(off.attrib["x"])
        by = sy - 2 * size + float(off.attrib["y"])  # the baseline, y down
        name = el.attrib["label"]
        main, subs = name[0], re.sub(r"^.", "", name).replace("_", "")
        width = 0.6 * font * len(main) + 0.45 * font * len(subs)  # a sans-serif, subscripts
        boxes[name] = ((bx, by - 0.75 * font, bx + width, by + 0.25 * font), (sx, sy))
    scene = build_scene(c)
    assert len(boxes) == sum(len(lab.names) for lab in scene.labels)
    for lab in scene.labels:
        (bx0, by0, bx1, by1), (sx, sy) = boxes[lab.names[0]]
        dx, dy = lab.direction
        cx, cy = (bx0 + bx1) / 2, (by0 + by1) / 2
        if dx:
            assert (cx - sx) * dx > 0, (lab.names, lab.direction)
        if dy:
            assert (sy - cy) * dy > 0, (lab.names, lab.direction)  # screen y points down
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            (a0, a1, a2, a3), _ = boxes[a]
            (b0, b1, b2, b3), _ = boxes[b]
            w, h = min(a2, b2) - max(a0, b0), min(a3, b3) - max(a1, b1)
            assert w <= 1.0 or h <= 1.0, (preset, a, b)
