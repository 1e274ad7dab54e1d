"""Issue 23 (b): the lecture video fills its right panel.

The panel is found and measured from what matplotlib draws, not from the animation's
own layout numbers: the right panel is the part of the 1280 × 720 frame right of the
diagram's drawn box (its axes with tick labels, ``get_tightbbox``), and what fills it is
the union of the drawn boxes (``get_window_extent``, ``get_tightbbox``) of the visible
figure texts and axes there, and, separately, the rows of the rendered frame that have
ink.  Before issue 23 only the caption was there.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.axes import Axes

from graspcompass import Grasp, internal_force_diagram
from graspcompass.render.animate import animate_construction

#: the brief's own grasp, beside the paper's Fig. 6
OWN = Grasp(1.2, 0.3, 0.4, "61*pi/180", "118*pi/180", xi1="67*pi/180", xi2="49*pi/180")


@pytest.fixture(scope="module", params=["fig6", "own"])
def lecture(request):
    grasp = Grasp.preset("fig6") if request.param == "fig6" else OWN
    c = internal_force_diagram(grasp)
    return c, animate_construction(c, quality="lecture")


def _panel(anim) -> tuple[float, float, float, float]:
    """The right panel in pixels ``(x0, x1, y0, y1)``: right of the diagram as drawn, over
    the diagram's height."""
    r = anim._canvas.get_renderer()
    d = anim.axes.get_tightbbox(r)
    W, _ = anim._canvas.get_width_height()
    return d.x1, float(W), d.y0, d.y1


def _boxes(anim, panel) -> list:
    r = anim._canvas.get_renderer()
    x0 = panel[0]
    out = []
    for t in anim.figure.texts:
        if t.get_visible() and t.get_text().strip():
            b = t.get_window_extent(r)
            if b.x0 >= x0 - 1:
                out.append(b)
    for ax in anim.figure.axes:
        if ax is not anim.axes and isinstance(ax, Axes) and ax.get_visible():
            b = ax.get_tightbbox(r)
            if b is not None and b.x0 >= x0 - 1:
                out.append(b)
    return out


def _cover(boxes, panel) -> tuple[float, float]:
    """The fraction of the panel's area that the boxes cover, and the fraction of its
    height from the top of the highest box to the foot of the lowest."""
    x0, x1, y0, y1 = (round(float(v)) for v in panel)
    mask = np.zeros((y1 - y0, x1 - x0), bool)
    for b in boxes:
        a, c = max(int(b.x0) - x0, 0), min(int(np.ceil(b.x1)) - x0, x1 - x0)
        e, f = max(int(b.y0) - y0, 0), min(int(np.ceil(b.y1)) - y0, y1 - y0)
        if a < c and e < f:
            mask[e:f, a:c] = True
    rows = np.flatnonzero(mask.any(axis=1))
    span = (rows[-1] - rows[0] + 1) / mask.shape[0] if len(rows) else 0.0
    return float(mask.mean()), float(span)


def _ink_span(rgb: np.ndarray, panel) -> float:
    """The fraction of the panel's height from its highest to its lowest pixel row with
    ink (darker than the background), read from the rendered frame."""
    H = rgb.shape[0]
    x0, x1, y0, y1 = (round(float(v)) for v in panel)
    # image rows run from the top; the panel's y from the bottom
    band = rgb[H - y1 : H - y0, x0 + 2 : x1].astype(int)
    rows = np.flatnonzero((band.min(axis=2) < 200).any(axis=1))
    return float((rows[-1] - rows[0] + 1) / band.shape[0]) if len(rows) else 0.0


#: (area, height) of the panel used at least; before issue 23 the caption alone used 13 %
#: of the area and 20 % of the height at V3, 30 % and 40 % at the end (both grasps)
USED = {"V3": (0.2, 0.6), "end": (0.45, 0.85)}


@pytest.mark.parametrize("moment", USED)
def test_the_right_panel_is_used(lecture, moment):
    c, anim = lecture
    least = USED[moment]
    last = anim.frame_count - 1
    f = last if moment == "end" else anim.timeline.last_frame_of_step(c.step(moment).index)
    rgb = anim.render(f)
    assert rgb.shape == (720, 1280, 3)
    panel = _panel(anim)
    assert panel[1] - panel[0] > 0.3 * 1280  # a panel worth the name beside the diagram
    boxes = _boxes(anim, panel)
    area, span = _cover(boxes, panel)
    assert area >= least[0] and span >= least[1], (moment, area, span)
    assert _ink_span(rgb, panel) >= least[1] - 0.05, moment
    # nothing of the panel spills outside the frame
    for b in boxes:
        assert b.x1 <= 1280 + 1 and b.y0 >= 0 and b.y1 <= 720, b


def test_the_panel_lists_the_contacts_once_made(lecture):
    """Once the contacts are placed (step P2), both are listed under the caption, with the
    grasp's own coordinates to two decimals."""
    c, anim = lecture
    anim.render(anim.timeline.last_frame_of_step(c.step("P2").index))
    texts = [t.get_text() for t in anim.figure.texts if t.get_visible() and t is not anim._caption]
    for name in ("P1", "P2"):
        x, y = (float(v) for v in getattr(c.grasp, name))
        want = f"{abs(x):.2f}, {y:.2f})"
        assert [t for t in texts if t.startswith(f"${name[0]}_{name[1]}") and want in t], texts


def test_diagram_labels_do_not_cover_each_other(lecture):
    """The point labels of the lecture's diagram, drawn 1.6 times the PNG's size against
    their axes, are placed at that size: at the last frame two labels' boxes, measured
    from matplotlib's renderer, overlap only where one of them is a label the scene
    could place nowhere without breaking a rule (a crowded centre with no inset, shown
    zoomed by the camera at its step).  On Fig. 6 none overlap (before: X2 over
    P2x = X4)."""
    from matplotlib.text import Annotation

    from graspcompass.scene import labelling
    from graspcompass.scene.picture import scene_of

    c, anim = lecture
    anim.render(anim.frame_count - 1)
    r = anim._canvas.get_renderer()
    boxes = [
        (t.get_text(), t.get_window_extent(r))
        for t in anim.axes.texts
        if isinstance(t, Annotation) and t.get_visible() and t.get_text().startswith("$")
    ]
    assert len(boxes) >= 10
    bad = [
        (a, b)
        for i, (a, p) in enumerate(boxes)
        for b, q in boxes[i + 1 :]
        if min(p.x1, q.x1) - max(p.x0, q.x0) > 1 and min(p.y1, q.y1) - max(p.y0, q.y0) > 1
    ]
    if c.grasp.title and "Fig. 6" in c.grasp.title:
        assert bad == []
    frame_pt = anim.axes.bbox.width * 72.0 / anim.figure.dpi
    scene = scene_of(c, font_pt=anim.theme.font_size * labelling.FRAME_PT / frame_pt)
    kept = scene.labels if scene.inset is None else scene.inset.main
    placed = {f"${lab.tex()}$" for lab in kept}
    assert [(a, b) for a, b in bad if a in placed and b in placed] == []
