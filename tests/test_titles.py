"""The title of a grasp of one's own (issue 23): its parameters as typed, on the page.

Found by a hostile run: the PNG's title of a grasp with long decimals started left of the
figure (its "x" cut off), and 179.75° read "179.8°".  The figure's edges and the title's
box are matplotlib's own layout (Agg renderer); the values are the typed text."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram
from graspcompass.render.figure import figure_diagram
from graspcompass.scene.picture import grasp_title

LONG = Grasp("4.1318", "2.2846", "3.9932", "179.75deg", "0.25deg", xi1="89.875deg", xi2="89.875deg")


def test_the_title_gives_the_typed_values() -> None:
    text = grasp_title(LONG)
    for typed in ("4.1318", "2.2846", "3.9932", "179.75°", "0.25°", "89.875°"):
        assert typed in text, (typed, text)
    assert "179.8" not in text


@settings(max_examples=30, deadline=None)
@given(
    st.integers(1, 500000),
    st.integers(1, 4000),
    st.integers(0, 99),
)
def test_the_title_reads_back_as_the_grasp(x1: int, deg: int, frac: int) -> None:
    """x1 typed with up to 5 places and φ1 in hundredths of a degree read back exactly."""
    phi = deg % 170 + 5 + frac / 100
    xi = 89.99 if abs(phi - 90) >= 89 else 89
    g = Grasp(f"{x1 / 10**5}", "0.5", "0.5", f"{phi}deg", "90deg", xi1=f"{xi}deg", xi2="30deg")
    text = grasp_title(g)
    parts = dict(p.split(" = ") for p in text.split(", "))
    assert float(parts["x1"]) == x1 / 10**5
    assert float(parts["φ1"].rstrip("°")) == pytest.approx(phi, abs=1e-12)


def test_a_long_title_stays_on_the_page() -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = figure_diagram(internal_force_diagram(LONG))
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    renderer = canvas.get_renderer()
    width = fig.bbox.width
    for ax in fig.axes:
        t = ax.title
        if t.get_text():
            box = t.get_window_extent(renderer)
            assert box.x0 >= 0 and box.x1 <= width, (t.get_text(), box.x0, box.x1, width)
    assert "4.1318" in fig.axes[0].title.get_text()
