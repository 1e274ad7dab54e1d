"""The one picture model (issue 23): :mod:`graspcompass.scene`, built once, read by
every painter, and free of matplotlib."""

from __future__ import annotations

import subprocess
import sys

from graspcompass import Grasp, internal_force_diagram


def test_old_import_paths_are_the_scene_modules() -> None:
    import graspcompass.export._scene as old_scene
    import graspcompass.labelling as old_labelling
    import graspcompass.layout as old_layout
    import graspcompass.palette as old_palette
    from graspcompass.scene import labelling, layout, palette, picture

    assert old_layout is layout and old_labelling is labelling
    assert old_palette is palette and old_scene is picture


def test_one_group_points_wedge_and_label_tex() -> None:
    from graspcompass.scene import layout, picture

    assert picture.group_points is layout.group_points
    assert picture.label_tex is layout.label_tex
    assert layout.group_points([("O", (0.0, 0.0)), ("O_M", (0.0, 1e-12))], 1e-9) == [
        (("O", "O_M"), (0.0, 0.0))
    ]


def test_numeric_objects_and_the_scene_are_computed_once(monkeypatch) -> None:
    from graspcompass.scene import layout, picture

    c = internal_force_diagram(Grasp.preset("table1a"))
    calls = []
    real = layout._numeric
    monkeypatch.setattr(layout, "_numeric", lambda k: calls.append(1) or real(k))
    a = layout.numeric_objects(c)
    a["O"] = "spoiled"  # a copy: the remembered values stay
    b = layout.numeric_objects(c)
    assert b["O"] == (0.0, 0.0) and len(calls) == 1
    assert picture.scene_of(c) is picture.scene_of(c)


def test_png_svg_and_tikz_build_one_scene(monkeypatch) -> None:
    import matplotlib

    matplotlib.use("Agg")
    from graspcompass.export import to_svg, to_tikz
    from graspcompass.render.figure import draw_construction
    from graspcompass.scene import layout

    c = internal_force_diagram(Grasp.preset("fig6"))
    calls = []
    real = layout._numeric
    monkeypatch.setattr(layout, "_numeric", lambda k: calls.append(1) or real(k))
    draw_construction(c)
    draw_construction(c, step=17)
    to_svg(c)
    to_tikz(c)
    assert len(calls) == 1


def test_scene_does_not_import_matplotlib() -> None:
    code = (
        "import sys, graspcompass.scene as s; "
        "from graspcompass import Grasp, internal_force_diagram; "
        "s.scene_of(internal_force_diagram(Grasp.preset('fig6'))).upto(17); "
        "assert 'matplotlib' not in sys.modules, 'matplotlib imported'"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=120)


# the break points labelled on request: which lie on the envelope is found here from
# first principles, not from the envelope's arcs: on the circle on the diameter O V_n
# the point in the direction θ is at k_n(θ) = V_n · e(θ), and k_grasp = max(0, max k_n)
BREAK_GRASPS = {
    "fig6": lambda: Grasp.preset("fig6"),
    "table1b": lambda: Grasp.preset("table1b"),
    "table1c": lambda: Grasp.preset("table1c"),
    "own": lambda: Grasp(0.8, 1.6, 0.9, 1.5, 1.3, mu1=0.8, mu2=0.6),
}


def _on_envelope(c) -> set[str]:
    import math

    from graspcompass.scene import layout

    num = layout.numeric_objects(c)
    V = [num[f"V{n}"] for n in range(1, 5)]
    on = set()
    for s in c.steps:
        if s.role == "break_point":
            x, y = num[s.name]
            r, t = math.hypot(x, y), math.atan2(y, x)
            k = max(0.0, *(v[0] * math.cos(t) + v[1] * math.sin(t) for v in V))
            if abs(k - r) <= 1e-9 * max(1.0, r):
                on.add(s.name)
    return on


def _to_box(p, b) -> float:
    import math

    return math.hypot(max(b[0] - p[0], 0.0, p[0] - b[2]), max(b[1] - p[1], 0.0, p[1] - b[3]))


def test_break_points_on_the_envelope_labelled_on_request() -> None:
    import math

    from graspcompass.scene.picture import scene_of

    for name, make in BREAK_GRASPS.items():
        c = internal_force_diagram(make())
        on = _on_envelope(c)
        assert len(on) >= 3, name  # the envelope of four circles has 3 or 4 cusps here
        plain, lit = scene_of(c), scene_of(c, break_points=True)
        assert scene_of(c, break_points=True) is lit and scene_of(c) is plain  # cached apart
        assert not any(n.startswith("B") for lab in plain.labels for n in lab.names), name
        # the labels painted: the whole view's (or, beside an inset, those it leaves
        # there) and the inset's, each with the points of its panel
        views = [(lit.labels if lit.inset is None else lit.inset.main, lit.box)]
        if lit.inset is not None:
            views.append((lit.inset.labels, lit.inset.box))
        named = {n for labels, _ in views for lab in labels for n in lab.names}
        assert {n for n in named if n.startswith("B")} == on, name
        for labels, (x0, x1, y0, y1) in views:
            shown = [xy for _, xy in lit.points if x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1]
            for lab in labels:
                if not lab.names[0].startswith("B"):
                    continue
                own = _to_box(lab.point, lab.box)
                for xy in shown:  # every other point, the small markers too
                    if math.dist(xy, lab.point) > 1e-9:
                        assert own < _to_box(xy, lab.box), (name, lab.names)
                for other in labels:  # no label over another
                    if other is not lab:
                        b, o = lab.box, other.box
                        assert min(b[2], o[2]) <= max(b[0], o[0]) or min(b[3], o[3]) <= max(
                            b[1], o[1]
                        ), (name, lab.names, other.names)
        # a step before the break points names none of them
        first = min(s.index for s in c.steps if s.role == "break_point")
        cut = lit.upto(first - 1)
        assert not any(n.startswith("B") for lab in cut.labels for n in lab.names)
        assert {n for lab in lit.upto(first).labels for n in lab.names if n[0] == "B"} <= on
