"""The explorer's fast update (issue 12 §1): float closed form, moved artists, blitting.

An explorer changed by slider events, drags and ``set_params`` must show what a
new explorer opened on the changed grasp shows (every artist's data to 1e-9),
its V_n must be the closed form (28)-(39) written out below, a change must not
build a Grasp or a construction (while the grasp is comfortably valid), and the
blitted canvas must be the pixels of a full render.  No timings here: see
``bench/bench_explorer.py``.
"""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent

from graspcompass import Grasp
from graspcompass.grasp import InvalidGraspError
from graspcompass.render import _explorer_scene, explorer
from graspcompass.render.explorer import Explorer

SAMPLES = 181


def closed_form_V(p: dict[str, float]) -> np.ndarray:
    """V_n = (S_n, C_n), eqs. (28)-(39), with tan(φ ± ξ) in the μ form of eq. (23)."""

    def tan_pm(phi: float, mu: float) -> tuple[float, float]:
        s, c = math.sin(phi), math.cos(phi)
        return (s + mu * c) / (c - mu * s), (s - mu * c) / (c + mu * s)

    t1p, t1m = tan_pm(p["phi1"], p["mu1"])
    t2p, t2m = tan_pm(p["phi2"], p["mu2"])
    x1, x2, y = p["x1"], p["x2"], p["y"]
    h = (x1 + x2) / 2
    S = [-h + y * t1p, h - y * t2p, -h + y * t1m, h - y * t2m]  # (28), (34), (36), (38)
    C = [x2 * t1p, x1 * t2p, x2 * t1m, x1 * t2m]  # (29), (35), (37), (39)
    return np.column_stack([S, C])


def picture(ex: Explorer) -> dict[str, np.ndarray]:
    """Every moving artist's data."""
    out: dict[str, np.ndarray] = {
        "points": np.asarray(ex.points.get_xydata()),
        "contacts": np.asarray(ex.contacts.get_xydata()),
        "envelope": np.asarray(ex.envelope_line.get_xydata()),
        "fill": np.asarray(ex.fill.get_xy()),
        "worst": np.asarray(ex.worst_mark.get_xydata()),
        "best": np.asarray(ex.best_mark.get_xydata()),
        "direction": np.asarray(ex.direction.get_xydata()),
        "H": np.asarray(ex.h_mark.get_xydata()),
        "centres": np.array([c.get_center() for c in ex.circles]),
        "radii": np.array([c.get_radius() for c in ex.circles]),
        "labels": np.array([t.get_position() for t in ex.labels.values()]),
    }
    for i in range(4):
        out[f"side{i + 1}"] = np.asarray(ex.sides[i].get_xydata())
        out[f"perp{i + 1}"] = np.asarray(ex.perps[i].get_xydata())
    for i in range(2):
        out[f"cone{i + 1}"] = np.asarray(ex.cones[i].get_xy())
    return out


def mouse(ex: Explorer, name: str, xy: tuple[float, float]) -> None:
    ev = MouseEvent(name, ex.fig.canvas, float(xy[0]), float(xy[1]), button=1)
    ex.fig.canvas.callbacks.process(name, ev)


def slide(ex: Explorer, name: str, value: float) -> None:
    px = ex.sliders[name].ax.transData.transform((value, 0.5))
    mouse(ex, "button_press_event", px)
    mouse(ex, "button_release_event", px)


def pixels(ex: Explorer) -> np.ndarray:
    return np.asarray(ex.fig.canvas.buffer_rgba()).copy()


@pytest.fixture(scope="module")
def ex():
    e = Explorer(Grasp.preset("table1a"), samples=SAMPLES)
    e.fig.canvas.draw()
    return e


def test_a_changed_explorer_draws_what_a_new_one_draws(ex):
    slide(ex, "mu2", 1.5)
    slide(ex, "phi1", 80.0)
    slide(ex, "theta", 135.0)
    to = ex.ax.transData.transform
    mouse(ex, "button_press_event", to((ex.params["x1"], ex.params["y"])))
    mouse(ex, "motion_notify_event", to((1.6, 1.3)))
    mouse(ex, "button_release_event", to((1.6, 1.3)))
    ex.set_params(x2=2.5)
    p = dict(ex.params)
    assert p["x1"] == pytest.approx(1.6, abs=0.05) and p["theta"] == pytest.approx(
        math.radians(135), abs=0.02
    )
    fresh = Explorer(
        Grasp(*(p[k] for k in ("x1", "x2", "y", "phi1", "phi2")), mu1=p["mu1"], mu2=p["mu2"]),
        samples=SAMPLES,
        theta=p["theta"],
    )
    got, want = picture(ex), picture(fresh)
    for name in want:
        np.testing.assert_allclose(got[name], want[name], rtol=0, atol=1e-9, err_msg=name)
    assert ex.info.get_text() == fresh.info.get_text()
    # V1..V4 and the circles on O V_n against the closed form written out above
    V = closed_form_V(p)
    np.testing.assert_allclose(got["points"][-4:], V, rtol=0, atol=1e-9)
    np.testing.assert_allclose(got["centres"], V / 2, rtol=0, atol=1e-9)
    np.testing.assert_allclose(got["radii"], np.hypot(*V.T) / 2, rtol=0, atol=1e-9)
    # the envelope k_grasp(θ) e(θ), eq. (25), and H at the slider's θ
    t = np.linspace(0, 2 * np.pi, SAMPLES)
    k = np.maximum(0, (np.outer(V[:, 0], np.sin(t)) - np.outer(V[:, 1], np.cos(t))).max(0))
    np.testing.assert_allclose(
        got["envelope"], np.column_stack([k * np.sin(t), -k * np.cos(t)]), rtol=0, atol=1e-9
    )
    th = p["theta"]
    kt = max(0.0, *(s * math.sin(th) - c * math.cos(th) for s, c in V))
    np.testing.assert_allclose(got["H"][0], [kt * math.sin(th), -kt * math.cos(th)], atol=1e-9)
    assert f"k = {kt:.4g}" in ex.info.get_text()


@pytest.mark.parametrize("seed", range(2))
def test_V_is_the_closed_form_on_random_grasps(seed):
    rng = np.random.default_rng(seed)
    ex = Explorer(samples=SAMPLES)
    for _ in range(5):
        p = dict(x1=rng.uniform(-0.5, 3), x2=rng.uniform(0.6, 3), y=rng.uniform(0, 2))
        for i in (1, 2):
            phi = rng.uniform(0.3, math.pi - 0.3)
            xi = rng.uniform(abs(phi - math.pi / 2) + 0.02, math.pi / 2 - 0.02)
            p[f"phi{i}"], p[f"mu{i}"] = phi, math.tan(xi)
        ex.set_params(**p)
        assert ex.error is None
        np.testing.assert_allclose(
            ex.points.get_xydata()[-4:], closed_form_V(p), rtol=1e-9, atol=1e-9
        )


def test_near_a_bound_of_condition_1_the_grasp_computes():
    """φ1 + ξ1 = π/2 + 1e-8: doubles cancel, the correctly rounded float path is used."""
    mu1 = math.tan(math.pi / 2 - math.radians(60) + 1e-8)
    p = dict(x1=1.0, x2=1.0, y=0.5, phi1=math.radians(60), phi2=math.pi / 2, mu1=mu1, mu2=1.0)
    grid = _explorer_scene.ThetaGrid(SAMPLES)
    assert _explorer_scene.float_scene(p, grid) is None
    ex = Explorer(samples=SAMPLES)
    ex.set_params(**p)
    assert ex.error is None
    g = Grasp(**p)
    V = np.array([(float(v.x), float(v.y)) for v in g.V])
    np.testing.assert_allclose(ex.points.get_xydata()[-4:], V, rtol=1e-12)


def test_no_grasp_and_no_construction_per_change(monkeypatch):
    ex = Explorer(Grasp.preset("fig6"), samples=SAMPLES)
    ex.fig.canvas.draw()
    calls = []
    monkeypatch.setattr(explorer, "Grasp", lambda *a, **k: calls.append(a) or Grasp(*a, **k))
    monkeypatch.setattr(explorer, "grasp_scene", lambda *a: calls.append(a))
    for i, (name, value) in enumerate(
        (("x1", 1.1), ("y", 0.8), ("phi2", 1.1), ("mu1", 1.3), ("theta", 2.0), ("x2", 0.7))
    ):
        ex.set_params(**{name: value})
        ex.drag("P1", 0.9 + 0.05 * i, 0.4)
    assert calls == [] and ex.error is None


def test_invalid_parameters_show_the_grasps_message_and_recover(ex):
    good = dict(ex.params)
    before = picture(ex)
    ex.set_params(phi1=math.radians(20.0), mu1=0.1)
    with pytest.raises(InvalidGraspError) as err:
        Grasp(
            ex.params["x1"],
            ex.params["x2"],
            ex.params["y"],
            math.radians(20.0),
            ex.params["phi2"],
            mu1=0.1,
            mu2=ex.params["mu2"],
        )
    text = ex.message.get_text()
    assert ex.message.get_visible() and ex.error == str(err.value)
    assert "condition (1)" in text and "φ1 + ξ1" in text
    assert ex.info.get_text() == "(no diagram: see the message)"
    ex.set_params(theta=1.0)  # θ alone: still the message
    assert ex.message.get_visible()
    ex.set_params(phi1=good["phi1"], mu1=good["mu1"], theta=good["theta"])
    assert not ex.message.get_visible() and ex.error is None
    after = picture(ex)
    for name in before:
        np.testing.assert_allclose(after[name], before[name], atol=1e-12, err_msg=name)


def test_the_blitted_canvas_is_a_full_render(ex):
    """Regions restored and moving artists drawn in zorder: the same pixels as draw()."""
    ex.set_params(mu2=1.9, theta=0.8)
    ex.drag("P1", 1.5, 1.2)
    slide(ex, "phi2", 75.0)
    blitted = pixels(ex)
    ex.fig.canvas.draw()
    assert np.array_equal(blitted, pixels(ex))
    ex.set_params(phi1=math.radians(20.0), mu1=0.1)  # the message, faded diagram
    blitted = pixels(ex)
    ex.fig.canvas.draw()
    assert np.array_equal(blitted, pixels(ex))
    ex.set_params(phi1=math.pi / 2, mu1=1.0)
    ex.fit()  # new limits: the background is rendered again
    ex.set_params(y=0.9)
    blitted = pixels(ex)
    ex.fig.canvas.draw()
    assert np.array_equal(blitted, pixels(ex))


def test_png_is_the_canvas(ex):
    from io import BytesIO

    from PIL import Image

    ex.set_params(mu1=1.1)
    data = ex.png()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    img = np.asarray(Image.open(BytesIO(data)).convert("RGBA"))
    assert np.array_equal(img, pixels(ex))


def test_without_blitting_the_canvas_renders():
    ex = Explorer(Grasp.preset("table1a"), samples=SAMPLES, blit=False)
    drawn = []
    ex.fig.canvas.mpl_connect("draw_event", lambda e: drawn.append(e))
    ex.set_params(y=1.5)
    assert drawn and ex.params["y"] == 1.5
