"""The default animation legible at its size, the camera, the title card, MP4 (issue 23).

Sizes from the frame itself (font size in points × dpi / 72), durations from frame counts
and fps, where the camera looks from the axes' limits after a frame is set; the points'
places from the paper's printed numbers of Fig. 6 (§4.1)."""

from __future__ import annotations

import math
import os
from itertools import pairwise

import matplotlib

matplotlib.use("Agg")

import pytest
from matplotlib.text import Text

from _shown import shown
from _small_anim import small_animation
from graspcompass import Grasp, internal_force_diagram
from graspcompass.render.animate import animate_construction

S3 = math.sqrt(3)
#: Fig. 6 (§4.1): V1 = (−1 − √3, −3/2 − √3), V3 = (1 − √3, √3 − 3/2), X3, Y3 near O.
V1 = (-1 - S3, -1.5 - S3)
V3 = (1 - S3, S3 - 1.5)


@pytest.fixture(scope="module")
def fig6():
    return internal_force_diagram(Grasp.preset("fig6"))


@pytest.fixture(scope="module")
def gif(fig6):
    return animate_construction(fig6)  # the default: the main job's GIF


def _texts(anim):
    fig = anim.figure
    out = [t for t in fig.findobj(Text) if t.get_text().strip()]
    return out


def test_default_gif_text_is_at_least_14_px(gif):
    fig = gif.figure
    w, h = fig.get_size_inches() * fig.dpi
    assert w >= 600 and h >= 600
    gif.render(gif.timeline.last_frame_of_step(29))  # ticks, labels and caption all set
    texts = _texts(gif)
    assert len(texts) > 10
    for t in texts:
        px = t.get_fontsize() * fig.dpi / 72.0
        assert px >= 14.0 - 1e-9, (t.get_text(), px)


def test_default_gif_shows_each_caption_two_seconds(fig6, gif):
    for s in fig6.steps:
        assert gif.caption_seconds_of_step(s.index) >= 2.0 - 1e-9, s.name


def _view(anim, frame):
    anim._apply(frame)
    (x0, x1), (y0, y1) = anim.axes.get_xlim(), anim.axes.get_ylim()
    return x0, x1, y0, y1


def test_camera_zooms_in_on_v3_and_out_for_v1(fig6, gif):
    whole = _view(gif, gif.frame_count - 1)  # the hold: the whole diagram
    span = whole[1] - whole[0]
    for name, point in (("X3", None), ("Y3", None), ("V3", V3), ("V1", V1)):
        f = gif.timeline.last_frame_of_step(fig6.step(name).index)
        b = _view(gif, f)
        if point is None:
            point = tuple(float(c) for c in (fig6[name].x, fig6[name].y))
        assert b[0] < point[0] < b[1] and b[2] < point[1] < b[3], name
        zoom = span / (b[1] - b[0])
        if name == "V1":
            assert zoom == pytest.approx(1.0)  # out: V1 is far from O
        else:
            assert zoom >= 2.0, (name, zoom)  # in: X3, Y3, V3 lie within one unit of O


def test_camera_glides_without_jumps(fig6, gif):
    tl = gif.timeline
    step = fig6.step("V3").index
    frames = [f for f in range(tl.frames_of_step(step - 1)[0], tl.frames_of_step(step)[-1])]
    widths = [(lambda b: b[1] - b[0])(_view(gif, f)) for f in frames]
    ratios = [max(a, b) / min(a, b) for a, b in pairwise(widths)]
    assert max(ratios) < 1.6


def test_lecture_starts_with_a_title_card(fig6):
    lec = animate_construction(fig6, quality="lecture", frames_per_step=2)
    tl = lec.timeline
    assert tl.segments[0].kind == "title"
    assert tl.segments[0].frames / lec.fps >= 3.0
    lec._apply(0)
    card = [t for t in lec.figure.texts if t.get_visible() and "ruler and compass" in t.get_text()]
    assert card
    drawn = [a for items in lec._items for a, _, _ in items if a.get_visible()]
    assert not drawn
    # paced by step: each caption stays its reading time (2.5 s, or 15 characters a
    # second: issue 12), a key step (V_n, a circle, the envelope) 3 s longer
    for st in fig6.steps:
        text = lec.caption_at(tl.frames_of_step(st.index)[0])
        read = max(2.5, len(shown(text)) / 15.0) + (3.0 if st.key else 0.0)
        assert (
            lec.caption_seconds_of_step(st.index) == pytest.approx(read, abs=1.01 / lec.fps)
            or st.index == len(fig6.steps) - 1
        ), st.name


def test_mp4_without_a_system_ffmpeg(fig6, tmp_path, monkeypatch):
    imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg", reason="the mp4/test extra")
    empty = tmp_path / "bin"
    empty.mkdir()
    monkeypatch.setenv("PATH", str(empty))  # no ffmpeg on the PATH
    anim = small_animation(fig6, dpi=40)
    path = anim.save(tmp_path / "c.mp4", quiet=True)
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(path))
    assert frames == anim.frame_count
    assert os.path.getsize(path) > 1000


def test_the_frames_written_are_full_renders(fig6):
    """Every frame as the player writes it (stills repeated, a view that moves drawn in
    full, the rest of a step blitted on a base of the view the camera rests on) is the frame
    rendered alone (but for a few pixels where blitted strokes overlap), the zooms on the
    crowds after the hold too; there the camera rests on each crowd, several times closer,
    and ends on the whole view."""
    import numpy as np

    anim = small_animation(fig6, frames_per_step=3, inset_seconds=2.0)
    tl = anim.timeline
    segments = [tl.segment_range(i) for i, s in enumerate(tl.segments) if s.kind == "inset"]
    assert len(segments) == len(anim._zooms) >= 1  # one zoom per crowd
    assert all(len(r) == round(2.0 * anim.fps) for r in segments)
    frames = list(anim.iter_frames())
    assert len(frames) == anim.frame_count
    # every eighth frame, and each zoom's (blitting draws a few pixels of overlap in another
    # order)
    zooms = {f for r in segments for f in r}
    for f in sorted(set(range(0, len(frames), 8)) | zooms):
        far = np.abs(frames[f].astype(int) - anim.render(f).astype(int)).max(axis=2) > 40
        assert far.mean() < 0.005, (f, tl.at(f))
    for r, z in zip(segments, anim._zooms):
        whole, rest = _view(anim, r[-1]), _view(anim, r[len(r) // 2])
        assert rest == pytest.approx(z)
        assert (whole[1] - whole[0]) / (rest[1] - rest[0]) > 2.0
        assert whole == pytest.approx(anim._whole)


#: a grasp of a hostile run whose blitted frames drew the envelope over "P_2x, X_4"
COVERED = Grasp("0.3", "2.4", "0.9", "100deg", "40deg", xi1="20deg", xi2="55deg")


def test_blitted_frames_keep_labels_on_top():
    """In the frames as written (blitted), a label is as in the frame rendered alone: a
    stroke drawn later (the envelope, a circle, a line) does not cover a label above it
    in z-order.  Compared inside each visible label's box at the end of every step."""
    import numpy as np

    anim = small_animation(
        internal_force_diagram(COVERED), frames_per_step=2, figsize=(6, 6.6), dpi=50
    )
    frames = list(anim.iter_frames())
    tl = anim.timeline
    h = frames[0].shape[0]
    checked, bad = 0, []
    for step in range(len(anim.construction.steps)):
        f = tl.last_frame_of_step(step)
        if tl.at(f).kind == "hold":
            continue
        full = anim.render(f)
        renderer = anim.figure.canvas.get_renderer()
        for t in anim.axes.texts:
            if not (t.get_visible() and t.get_text().startswith("$")):
                continue
            b = t.get_window_extent(renderer)
            x0, x1 = max(int(b.x0) + 1, 0), min(int(b.x1) - 1, frames[f].shape[1])
            y0, y1 = max(int(h - b.y1) + 1, 0), min(int(h - b.y0) - 1, h)
            if x1 - x0 < 3 or y1 - y0 < 3:
                continue
            a, c = frames[f][y0:y1, x0:x1].astype(int), full[y0:y1, x0:x1].astype(int)
            checked += 1
            differ = (np.abs(a - c).max(axis=2) > 40).mean()
            if differ > 0.02:
                bad.append((step, t.get_text(), round(float(differ), 3)))
    assert checked > 100
    assert not bad, bad


def test_the_hold_comes_to_rest(fig6):
    """The final hold cross-fades for a fifth of its length, then shows the finished
    diagram still (it faded for the whole hold, two label layouts on screen at once)."""
    import numpy as np

    anim = small_animation(fig6, hold_frames=30)
    frames = list(anim.iter_frames())
    hold = [f for f in range(len(frames)) if anim.timeline.at(f).kind == "hold"]
    assert len(hold) == 30
    moving = [f for f in hold if not np.array_equal(frames[f], frames[hold[-1]])]
    assert 1 <= len(moving) <= 7, len(moving)
