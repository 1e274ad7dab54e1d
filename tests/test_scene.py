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
