"""Tests of graspcompass.render: the matplotlib drawings of the internal force diagram.

Expected numbers are computed here from the paper's equations (26)-(39) with
numpy, never taken from the code under test.
"""

from __future__ import annotations

import copy
import os
import subprocess
import sys
from dataclasses import FrozenInstanceError
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.image as mpimg
import numpy as np
import pytest
import sympy
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Circle as CirclePatch
from matplotlib.text import Text

from graspcompass import Grasp, internal_force_diagram
from graspcompass.errors import OutputError
from graspcompass.render import (
    DEFAULT_THEME,
    EXTRA_KEYS,
    PAPER_THEME,
    draw_construction,
    draw_k_polar,
    figure_diagram,
    figure_k_plot,
    save_figure,
)

SRC = Path(__file__).resolve().parents[1] / "src"
PRESETS = ("fig6", "table1a", "table1b", "table1c")
PI = np.pi

#: The paper's numbers, typed in from §4.1 and Table I: x1, x2, y, φ1, φ2, ξ1, ξ2.
PAPER = {
    "fig6": (np.sqrt(3) / 2, np.sqrt(3) / 2, 0.5, PI / 3, PI / 3, PI / 4, PI / 3),
    "table1a": (2.0, 2.0, 1.0, PI / 2, PI / 2, np.arctan(1.0), np.arctan(1.2)),
    "table1b": (2.0, 2.0, 3.0, PI / 2, PI / 2, np.arctan(1.0), np.arctan(1.2)),
    "table1c": (2.0, 2.0, 2.0, PI / 2, PI / 2, np.arctan(0.5), np.arctan(1.4)),
}


def paper_SC(preset: str) -> tuple[np.ndarray, np.ndarray]:
    """S_n, C_n of eqs. (28)-(29), (34)-(39) with tan(φ ± ξ)."""
    x1, x2, y, p1, p2, k1, k2 = PAPER[preset]
    h = (x1 + x2) / 2
    t = {1: np.tan(p1 + k1), 2: np.tan(p2 + k2), 3: np.tan(p1 - k1), 4: np.tan(p2 - k2)}
    S = np.array([-h + y * t[1], h - y * t[2], -h + y * t[3], h - y * t[4]])
    C = np.array([x2 * t[1], x1 * t[2], x2 * t[3], x1 * t[4]])
    return S, C


def paper_k_grasp(preset: str, theta: np.ndarray) -> np.ndarray:
    """max(0, S_n sin θ − C_n cos θ), eqs. (25), (27), (32)."""
    S, C = paper_SC(preset)
    ks = S[:, None] * np.sin(theta)[None, :] - C[:, None] * np.cos(theta)[None, :]
    return np.maximum(ks.max(axis=0), 0.0)


@pytest.fixture(scope="module")
def constructions():
    return {p: internal_force_diagram(Grasp.preset(p)) for p in PRESETS}


def new_ax():
    return Figure(figsize=(6, 6)).add_subplot()


def lines_of(artists):
    return [a for a in artists if isinstance(a, Line2D)]


# -- files --------------------------------------------------------------------------------
@pytest.mark.parametrize("preset", PRESETS)
def test_each_preset_renders_and_saves(constructions, preset, tmp_path):
    fig = figure_diagram(constructions[preset])
    for ext in ("png", "svg", "pdf"):
        out = save_figure(fig, tmp_path / f"{preset}.{ext}")
        assert out == tmp_path / f"{preset}.{ext}"
        assert out.is_file() and out.stat().st_size > 0
    image = mpimg.imread(tmp_path / f"{preset}.png")
    # 7.4 in × 150 dpi high, 7 in wide; where points crowd wider by a zoomed inset and
    # taller by its excess over the diagram's side (INSET_PT / FRAME_PT of it)
    from graspcompass.scene.labelling import FRAME_PT
    from graspcompass.scene.picture import INSET_PT, scene_of

    extra = (
        0.0
        if scene_of(constructions[preset]).inset is None
        else max(0.0, (INSET_PT - FRAME_PT) / 72.0)
    )
    assert image.shape[0] == round((7.4 + extra) * 150) and image.shape[1] >= 1050
    assert image.shape[2] in (3, 4)
    assert (tmp_path / f"{preset}.svg").read_text().lstrip().startswith("<?xml")
    assert (tmp_path / f"{preset}.pdf").read_bytes()[:5] == b"%PDF-"


def test_save_refuses_missing_folder_and_format_override(constructions, tmp_path):
    fig = figure_k_plot(Grasp.preset("fig6"), samples=200)
    with pytest.raises(OutputError, match=r"the folder '.*a/b' does not exist"):
        save_figure(fig, tmp_path / "a" / "b" / "k.png")  # folders are never made
    assert not (tmp_path / "a").exists()
    out = save_figure(fig, tmp_path / "k.png")
    assert mpimg.imread(out).shape[:2] == (675, 1200)  # 8 × 4.5 in at 150 dpi
    svg = save_figure(fig, tmp_path / "k.data", format="SVG")
    assert "<svg" in svg.read_text()


@pytest.mark.parametrize("name", ["x.gif", "x.jpeg", "x", "x.png.bak"])
def test_unknown_extension_raises(tmp_path, name):
    with pytest.raises(ValueError, match="not supported"):
        save_figure(Figure(), tmp_path / name)
    assert not (tmp_path / name).exists()


def test_unknown_format_raises(tmp_path):
    with pytest.raises(ValueError, match="format 'jpg'"):
        save_figure(Figure(), tmp_path / "x.png", format="jpg")


# -- which objects are drawn --------------------------------------------------------------
@pytest.mark.parametrize("preset", PRESETS)
def test_artists_for_every_object(constructions, preset):
    c = constructions[preset]
    arts = draw_construction(c, ax=new_ax())
    assert set(arts) - set(EXTRA_KEYS) == set(c.names)
    assert all(arts[name] for name in c.names)
    assert {"object", "cone1", "cone2"} <= set(arts)


@pytest.mark.parametrize("k", [0, 4, 8, 11, 17, 35, 36, 39, 45, -1])
def test_step_draws_only_the_state(constructions, k):
    c = constructions["fig6"]
    ax = new_ax()
    arts = draw_construction(c, step=k, ax=ax)
    state = c.upto(k)
    assert set(arts) - set(EXTRA_KEYS) == set(state.names)
    drawn = {id(a) for a in ax.get_children()}
    for name in state.names:
        for a in arts[name]:
            assert a.axes is ax and id(a) in drawn
    circles = [p for p in ax.patches if isinstance(p, CirclePatch) and not p.get_fill()]
    assert len(circles) == sum(1 for s in state.steps if s.kind == "circle")


def test_view_box_is_the_same_for_every_step(constructions):
    c = constructions["table1c"]
    limits = set()
    for k in (0, 10, 30, len(c) - 1):
        ax = new_ax()
        draw_construction(c, step=k, ax=ax)
        limits.add((ax.get_xlim(), ax.get_ylim()))
    assert len(limits) == 1


@pytest.mark.parametrize("preset", PRESETS)
def test_view_box_holds_the_key_points(constructions, preset):
    c = constructions[preset]
    ax = new_ax()
    draw_construction(c, ax=ax)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    S, C = paper_SC(preset)
    xs, ys, *_ = PAPER[preset]
    pts = [
        (0, 0),
        (xs, ys),
        (-PAPER[preset][1], ys),
        *zip(S, C),
        *((-s, 0) for s in S),
        *((0, -cc) for cc in C),
    ]
    for px, py in pts:  # X_n = (-S_n, 0) since O_M = O here; Y_n = (0, -C_n)
        assert x0 < px < x1 and y0 < py < y1
    # no more than 3 × the largest of |V_n| and the object size each way, plus margins
    size = max(np.hypot(S, C).max(), 4.0)
    assert max(x1 - x0, y1 - y0) < 2 * 3.0 * size * 1.2


# -- what is drawn ------------------------------------------------------------------------
@pytest.mark.parametrize("preset", PRESETS)
def test_envelope_line_is_the_polyline(constructions, preset):
    c = constructions[preset]
    arts = draw_construction(c, ax=new_ax())
    (line,) = lines_of(arts["envelope"])
    np.testing.assert_allclose(line.get_xydata(), c["envelope"].polyline(), rtol=0, atol=1e-9)


@pytest.mark.parametrize("preset", PRESETS)
def test_points_and_circles_match_the_paper(constructions, preset):
    c = constructions[preset]
    arts = draw_construction(c, ax=new_ax())
    S, C = paper_SC(preset)
    for n in (1, 2, 3, 4):
        marker = lines_of(arts[f"V{n}"])[0]
        np.testing.assert_allclose(marker.get_xydata()[0], (S[n - 1], C[n - 1]), atol=1e-9)
        (patch,) = arts[f"circle{n}"]
        (cx, cy), r = patch.center, patch.radius
        assert np.hypot(cx, cy) == pytest.approx(r, abs=1e-9)  # through O
        assert np.hypot(S[n - 1] - cx, C[n - 1] - cy) == pytest.approx(r, abs=1e-9)  # and V_n


@pytest.mark.parametrize("preset", PRESETS)
def test_computer_plot_radius_is_k_grasp(preset):
    samples = 1500
    theta = np.linspace(0.0, 2 * PI, samples)
    expect = paper_k_grasp(preset, theta)
    arts = draw_k_polar(Grasp.preset(preset), ax=new_ax(), samples=samples)
    xy = arts["k_grasp"][0].get_xydata()
    np.testing.assert_allclose(np.hypot(xy[:, 0], xy[:, 1]), expect, rtol=0, atol=1e-9)
    # and in the direction e(θ) = (sin θ, −cos θ), eq. (26)
    np.testing.assert_allclose(
        xy, np.column_stack([expect * np.sin(theta), -expect * np.cos(theta)]), atol=1e-9
    )


def test_computer_plot_overlay_and_components(constructions):
    c = constructions["fig6"]
    arts = draw_construction(c, ax=new_ax(), show_computer_plot=True)
    xy = arts["computer plot"][0].get_xydata()
    theta = np.linspace(0.0, 2 * PI, 2000)
    np.testing.assert_allclose(np.hypot(*xy.T), paper_k_grasp("fig6", theta), atol=1e-9)
    comp = draw_k_polar(c.grasp, ax=new_ax(), samples=400, components=True)
    S, C = paper_SC("fig6")
    t = np.linspace(0.0, 2 * PI, 400)
    for n in (1, 2, 3, 4):
        k = S[n - 1] * np.sin(t) - C[n - 1] * np.cos(t)
        data = comp[f"k{n}"][0].get_xydata()
        ok = k > 0
        assert np.all(np.isnan(data[~ok, 0]))
        np.testing.assert_allclose(np.hypot(*data[ok].T), k[ok], atol=1e-9)


def test_k_plot_curves():
    fig = figure_k_plot(Grasp.preset("table1c"), samples=361)
    lines = fig.axes[0].lines
    theta = np.linspace(0.0, 2 * PI, 361)
    S, C = paper_SC("table1c")
    for n in (1, 2, 3, 4):
        np.testing.assert_allclose(lines[n - 1].get_xdata(), np.degrees(theta))
        np.testing.assert_allclose(
            lines[n - 1].get_ydata(), S[n - 1] * np.sin(theta) - C[n - 1] * np.cos(theta), atol=1e-9
        )
    np.testing.assert_allclose(lines[4].get_ydata(), paper_k_grasp("table1c", theta), atol=1e-9)


def test_labels_are_the_papers(constructions):
    c = constructions["fig6"]
    arts = draw_construction(c, ax=new_ax())
    text = {n: [a.get_text() for a in arts[n] if isinstance(a, Text)] for n in c.names}
    assert text["V1"] == ["$V_1$"] and text["P1"] == ["$P_1$"] and text["X2"] == ["$X_2$"]
    # coincident points share one label: O = O_M = Y_4, P_{1x} = V_4, P_{2x} = X_4 (fig6)
    assert text["O"] == text["O_M"] == text["Y4"] == ["$O = O_M = Y_4$"]
    assert text["P1x"] == text["V4"] == ["$P_{1x} = V_4$"]
    assert text["P2x"] == text["X4"] == ["$P_{2x} = X_4$"]
    bare = draw_construction(c, ax=new_ax(), labels=False)
    assert not any(isinstance(a, Text) for n in ("V1", "P1", "O") for a in bare[n])


def test_highlight_last_and_themes(constructions):
    c = constructions["fig6"]
    arts = draw_construction(c, step=17, ax=new_ax(), highlight_last=True)
    marker = lines_of(arts["V1"])[0]
    assert matplotlib.colors.same_color(marker.get_markerfacecolor(), DEFAULT_THEME.highlight_color)
    arts = draw_construction(c, ax=new_ax(), theme=PAPER_THEME)
    assert matplotlib.colors.same_color(arts["circle2"][0].get_edgecolor(), "black")
    with pytest.raises(FrozenInstanceError):
        DEFAULT_THEME.font_size = 3  # type: ignore[misc]


def test_figure_diagram_title_legend_aspect(constructions):
    c = constructions["table1a"]
    fig = figure_diagram(c, title="custom", overlay=False)
    ax = fig.axes[0]
    assert ax.get_title() == "custom" and ax.get_aspect() == 1.0
    assert fig.legends and not any(a.get_visible() for a in ax.get_xgridlines())
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert not any("computer" in t for t in labels)
    fig = figure_diagram(c)
    assert fig.axes[0].get_title() == c.grasp.title
    assert any("computer" in t.get_text() for t in fig.legends[0].get_texts())


# -- purity -------------------------------------------------------------------------------
@pytest.mark.parametrize("preset", ["fig6", "table1c"])
def test_geometry_not_mutated(preset, tmp_path):
    c = internal_force_diagram(Grasp.preset(preset))
    before = copy.deepcopy(c.objects)
    reprs = {k: repr(v) for k, v in c.objects.items()}
    grasp = copy.deepcopy(c.grasp)
    fig = figure_diagram(c, overlay=True)
    draw_construction(c, step=20, ax=new_ax(), highlight_last=True)
    save_figure(fig, tmp_path / "out.svg")
    assert c.objects == before
    assert {k: repr(v) for k, v in c.objects.items()} == reprs
    assert c.grasp == grasp and c.grasp.shape == grasp.shape


def test_grasp_without_shape_and_with_floats(tmp_path):
    c = internal_force_diagram(Grasp(1.0, 2.0, 0.0, 1.2, 1.0, mu1=0.6, mu2=0.9))
    arts = draw_construction(c, ax=new_ax(), show_computer_plot=True)
    assert "object" not in arts and set(arts) - set(EXTRA_KEYS) == set(c.names)
    # y = 0: the contacts lie on the x-axis, P_1 = P_{1x} = X_1 = X_3 share one label
    (label,) = [a.get_text() for a in arts["P1"] if isinstance(a, Text)]
    assert label == "$P_1 = P_{1x} = X_1 = X_3$"
    assert save_figure(figure_diagram(c), tmp_path / "f.pdf").stat().st_size > 0


def test_symbolic_construction_is_refused():
    a = sympy.Symbol("a", positive=True)
    c = internal_force_diagram(Grasp(a, 1, 1, "pi/2", "pi/2", mu1=1, mu2=1))
    with pytest.raises(ValueError, match="symbolic"):
        draw_construction(c, ax=new_ax())


def test_import_graspcompass_does_not_import_matplotlib():
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    code = "import graspcompass, sys; assert 'matplotlib' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True, env=env)


def test_render_does_not_import_pyplot():
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    code = (
        "import graspcompass.render, sys; from graspcompass import Grasp, "
        "internal_force_diagram as d; graspcompass.render.figure_diagram(d(Grasp.preset("
        "'fig6'))); assert 'matplotlib.pyplot' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True, env=env)


def test_figure_labels_the_break_points_on_request(constructions):
    # Fig. 6's envelope passes from circle 2 to 4, 4 to 3, 3 to 1, 1 to 2: its cusps
    # are B24, B34, B13, B12 (B14 and B23 lie off it)
    def break_labels(fig) -> list[str]:
        return sorted(
            t.get_text() for ax in fig.axes for t in ax.texts if t.get_text().startswith("$B_")
        )

    c = constructions["fig6"]
    assert break_labels(figure_diagram(c)) == []
    got = break_labels(figure_diagram(c, break_points=True))
    assert set(got) == {f"$B_{{{n}}}$" for n in ("12", "13", "24", "34")}
