"""The interactive explorer, driven headless (Agg) by simulated mouse events.

The expected envelope is computed here from the closed form (28)-(39) re-typed in
``conftest.py``: k_grasp(θ) = max(S_n sin θ − C_n cos θ, 0) (eqs. (25), (27)),
drawn at k_grasp(θ) e(θ) with e(θ) = (sin θ, −cos θ) (26).
"""

from __future__ import annotations

import math
import sys

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent

from conftest import closed_form_SC
from graspcompass import Grasp
from graspcompass.render.explorer import Explorer, explore, explore_notebook


def expected_envelope(p: dict[str, float], samples: int) -> np.ndarray:
    S, C = closed_form_SC(
        p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], p["mu1"], p["mu2"], lib=np
    )
    t = np.linspace(0.0, 2 * np.pi, samples)
    k = np.max([np.zeros_like(t), *(s * np.sin(t) - c * np.cos(t) for s, c in zip(S, C))], axis=0)
    return np.column_stack([k * np.sin(t), -k * np.cos(t)])


def drawn_envelope(ex: Explorer) -> np.ndarray:
    return np.asarray(ex.envelope_line.get_xydata())


def mouse(ex: Explorer, name: str, xy_px: tuple[float, float]) -> None:
    ev = MouseEvent(name, ex.fig.canvas, float(xy_px[0]), float(xy_px[1]), button=1)
    ex.fig.canvas.callbacks.process(name, ev)


def slide(ex: Explorer, name: str, value: float) -> None:
    """Press and release the mouse on slider ``name`` at ``value``."""
    sax = ex.sliders[name].ax
    px = sax.transData.transform((value, 0.5))
    mouse(ex, "button_press_event", px)
    mouse(ex, "button_release_event", px)


@pytest.fixture
def ex():
    e = Explorer(Grasp.preset("table1a"), samples=361)
    e.fig.canvas.draw()
    return e


def test_starts_on_the_grasp_and_draws_its_envelope(ex):
    p = ex.params
    assert (p["x1"], p["x2"], p["y"], p["mu1"], p["mu2"]) == (2.0, 2.0, 1.0, 1.0, 1.2)
    assert p["phi1"] == pytest.approx(math.pi / 2)
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(p, 361), abs=1e-9)
    assert not ex.message.get_visible() and ex.error is None
    # Table I(a): k_grasp(0) = 2 (the upper sides: C1 = x2 tan(φ1 + ξ1) = −2)
    assert ex.worst[1] >= 2.0 - 1e-12 and ex.best[1] <= ex.worst[1]


def test_slider_event_redraws_the_envelope_for_the_new_value(ex):
    slide(ex, "y", 2.5)
    y = ex.sliders["y"].val
    assert y == pytest.approx(2.5, abs=0.05)  # one pixel of the slider
    assert ex.params["y"] == y
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(ex.params, 361), abs=1e-9)
    slide(ex, "phi2", 80.0)  # degrees on the slider, radians in the model
    assert ex.params["phi2"] == pytest.approx(math.radians(ex.sliders["phi2"].val))
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(ex.params, 361), abs=1e-9)


def test_dragging_p1_moves_x1_and_y_and_the_envelope(ex):
    before = drawn_envelope(ex).copy()
    to = ex.ax.transData.transform
    start = to((2.0, 1.0))  # P1 = (x1, y)
    target = to((2.6, 1.7))
    mouse(ex, "button_press_event", start)
    mouse(ex, "motion_notify_event", (start + target) / 2)
    mouse(ex, "motion_notify_event", target)
    mouse(ex, "button_release_event", target)
    x, y = ex.ax.transData.inverted().transform(target)
    assert (ex.params["x1"], ex.params["y"]) == pytest.approx((x, y), abs=1e-9)
    assert ex.params["x2"] == 2.0  # P2 = (−x2, y) keeps x2, follows y
    assert ex.sliders["x1"].val == pytest.approx(x) and ex.sliders["y"].val == pytest.approx(y)
    after = drawn_envelope(ex)
    assert after == pytest.approx(expected_envelope(ex.params, 361), abs=1e-9)
    assert np.abs(after - before).max() > 0.1


def test_dragging_p2_and_the_headless_api(ex):
    ex.drag("P2", -1.5, 0.5)
    assert (ex.params["x2"], ex.params["y"]) == (1.5, 0.5)
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(ex.params, 361), abs=1e-9)
    ex.set_params(mu1=0.8, phi1=1.4)
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(ex.params, 361), abs=1e-9)
    with pytest.raises(ValueError, match="unknown parameter"):
        ex.set_params(psi=1.0)
    with pytest.raises(ValueError, match="only P1 and P2"):
        ex.drag("V1", 0.0, 0.0)


def test_a_click_away_from_the_contacts_drags_nothing(ex):
    px = ex.ax.transData.transform((0.0, -3.0))
    mouse(ex, "button_press_event", px)
    mouse(ex, "motion_notify_event", px + 40)
    mouse(ex, "button_release_event", px + 40)
    assert (ex.params["x1"], ex.params["y"]) == (2.0, 1.0)


def test_invalid_position_shows_the_failing_inequality(ex):
    good = drawn_envelope(ex).copy()
    to = ex.ax.transData.transform
    mouse(ex, "button_press_event", to((2.0, 1.0)))
    mouse(ex, "motion_notify_event", to((-2.5, 1.0)))  # P1 left of P2 (x1 + x2 < 0)
    assert ex.message.get_visible()
    assert "x1 + x2 = " in ex.message.get_text() and "must be positive" in ex.message.get_text()
    mouse(ex, "motion_notify_event", to((2.0, 1.0)))  # back: the message goes
    mouse(ex, "button_release_event", to((2.0, 1.0)))
    assert not ex.message.get_visible()
    assert drawn_envelope(ex) == pytest.approx(good, abs=1e-9)
    # condition (1): φ1 + ξ1 = 20° + atan(0.1) < 90°, P2 outside the cone at P1
    ex.set_params(phi1=math.radians(20.0), mu1=0.1)
    text = ex.message.get_text()
    assert ex.message.get_visible() and "condition (1)" in text and "φ1 + ξ1" in text
    ex.fig.canvas.draw()  # drawing the message does not fail either


def test_explore_needs_a_display():
    with pytest.raises(ValueError, match="cannot open the explorer window"):
        explore(Grasp.preset("fig6"))


def test_explore_notebook_without_ipywidgets(monkeypatch):
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    with pytest.raises(ImportError, match="pip install ipywidgets"):
        explore_notebook()


def test_explore_notebook_with_ipywidgets():
    pytest.importorskip("ipywidgets", reason="ipywidgets is optional (not installed)")
    box = explore_notebook(Grasp.preset("table1a"))
    ex = box.explorer
    controls = [c for col in box.children[0].children for c in col.children]
    assert len(controls) == 7
    controls[2].value = 2.0  # y
    assert ex.params["y"] == 2.0
    assert drawn_envelope(ex) == pytest.approx(expected_envelope(ex.params, 720), abs=1e-9)
    assert box.children[1].value[:8] == b"\x89PNG\r\n\x1a\n"
