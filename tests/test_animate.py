"""Tests of the animations: the construction step by step, the force sweep, the turning object.

Expected values are computed here from the paper's equations (17), (25)-(39)
with numpy, never taken from the code under test.  Small figures, low dpi and
few frames keep the whole file fast.
"""

from __future__ import annotations

import io
import re
import stat
import sys
from dataclasses import replace
from itertools import pairwise

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from _small_anim import small_animation
from graspcompass import Grasp, internal_force_diagram
from graspcompass.cli import _add_grasp_options, _Parser, grasp_from_args
from graspcompass.cli._animate import (
    MAIN_ANIMATION,
    main_animation,
    register,
    run,
    write_main_animation,
)
from graspcompass.render import draw_construction
from graspcompass.render.anim_physics import (
    SLIP,
    animate_orientation,
    animate_sweep,
    theta_of_orientation,
)
from graspcompass.render.animate import animate_construction, save_frames
from graspcompass.render.theme import QUALITIES
from graspcompass.render.timeline import (
    AnimationError,
    FFmpegNotFoundError,
    Progress,
    Timeline,
    UnsupportedFormatError,
)

PI = np.pi
#: The paper's numbers, typed in from §4.1 and Table I: x1, x2, y, φ1, φ2, ξ1, ξ2.
PAPER = {
    "fig6": (np.sqrt(3) / 2, np.sqrt(3) / 2, 0.5, PI / 3, PI / 3, PI / 4, PI / 3),
    "table1a": (2.0, 2.0, 1.0, PI / 2, PI / 2, np.arctan(1.0), np.arctan(1.2)),
    "table1c": (2.0, 2.0, 2.0, PI / 2, PI / 2, np.arctan(0.5), np.arctan(1.4)),
}
SMALL = dict(figsize=(3.0, 3.4), dpi=40)
#: Tiny construction frames (fast): the text rule of the GIF (14 px) and the camera are
#: tested apart (tests/test_anim_camera.py).
CSMALL = dict(
    SMALL,
    min_text_px=0,
    camera=False,
    quality=replace(QUALITIES["standard"], caption_size=8.5, scale=1.0),
)


def paper_k(preset: str, theta: np.ndarray) -> np.ndarray:
    """k_n(θ) = S_n sin θ − C_n cos θ, (4, N), with S_n, C_n of eqs. (28)-(29), (34)-(39)."""
    x1, x2, y, p1, p2, k1, k2 = PAPER[preset]
    h = (x1 + x2) / 2
    t = {1: np.tan(p1 + k1), 2: np.tan(p2 + k2), 3: np.tan(p1 - k1), 4: np.tan(p2 - k2)}
    S = np.array([-h + y * t[1], h - y * t[2], -h + y * t[3], h - y * t[4]])
    C = np.array([x2 * t[1], x1 * t[2], x2 * t[3], x1 * t[4]])
    return S[:, None] * np.sin(theta)[None, :] - C[:, None] * np.cos(theta)[None, :]


def paper_k_grasp(preset: str, theta: np.ndarray) -> np.ndarray:
    """max(k_1, .., k_4, 0), eq. (25)."""
    return np.maximum(paper_k(preset, theta).max(axis=0), 0.0)


@pytest.fixture(scope="module")
def c1a():
    return internal_force_diagram(Grasp.preset("table1a"))


@pytest.fixture(scope="module")
def anim(c1a):
    return animate_construction(
        c1a, frames_per_step=3, pause_frames=2, hold_frames=3, caption_seconds=0, **CSMALL
    )


@pytest.fixture(scope="module")
def frames(anim):
    return list(anim.iter_frames())


# -- the timeline ---------------------------------------------------------------------------
def test_frame_counts_per_step(c1a, anim):
    tl = anim.timeline
    keys = [s.index for s in c1a.steps if s.key]
    assert [c1a.steps[i].name for i in keys] == [
        "V1",
        "V2",
        "V3",
        "V4",
        "circle1",
        "circle2",
        "circle3",
        "circle4",
        "envelope",
    ]
    last = len(c1a.steps) - 1
    for s in c1a.steps:
        expected = 3 + (2 if s.key else 0) + (3 if s.index == last else 0)
        assert len(tl.frames_of_step(s.index)) == expected, s.name
    assert anim.frame_count == 3 * len(c1a.steps) + 2 * len(keys) + 3
    # default: at least 8 frames per protocol step
    assert len(animate_construction(c1a, **CSMALL).timeline.frames_of_step(0)) >= 8


def test_every_step_appears_in_order(c1a, anim):
    tl = anim.timeline
    seq = [tl.at(f).step for f in range(anim.frame_count)]
    runs = [s for i, s in enumerate(seq) if i == 0 or s != seq[i - 1]]
    assert runs == list(range(len(c1a.steps)))
    for s in c1a.steps:  # the caption gives the paper's reference
        text = anim.caption_at(tl.frames_of_step(s.index)[0])
        plain = re.sub(r"[$_{}]", "", text).replace("\n", " ").replace("\u00a0", " ")
        assert s.ref.replace(" step ", " ") in plain
    perp1 = anim.caption_at(tl.frames_of_step(c1a.step("perp1").index)[0]).replace("\n", " ")
    assert (
        "§3.3 $V_1$ (2): perpendicular from $P_{2x}$ to the upper side of the cone at $P_1$"
        in perp1
    )


def test_timeline_progress_and_rates():
    tl = Timeline.from_keys([False, True, False], frames_per_step=4, pause_frames=3, hold_frames=2)
    drawn = [tl.at(f).progress for f in tl.frames_of_step(0)]
    assert drawn == sorted(drawn) and drawn[-1] == 1.0 and drawn[0] > 0
    assert [tl.at(f).kind for f in tl.frames_of_step(1)] == ["draw"] * 4 + ["pause"] * 3
    assert tl.at(-1).kind == "hold" and tl.at(-1).step == 2
    lin = Timeline.from_keys([False], frames_per_step=4, hold_frames=0, rate="linear")
    assert [lin.at(f).progress for f in range(4)] == [0.25, 0.5, 0.75, 1.0]
    with pytest.raises(IndexError):
        tl.at(tl.frame_count)
    with pytest.raises(AnimationError, match="unknown rate"):
        Timeline.from_keys([True], rate="bounce")


def test_visibility_follows_the_protocol(c1a, anim):
    """At the end of each step, its objects and the earlier ones are drawn, none later."""
    tl = anim.timeline
    for s in c1a.steps[::5]:
        anim.render(tl.last_frame_of_step(s.index))
        for t in c1a.steps:
            shown = [a.get_visible() for a in anim.artists[t.name]]
            if t.index > s.index:
                assert not any(shown[:1]), (s.name, t.name)
            elif t.index == s.index:
                assert shown[0], (s.name, t.name)


def test_geometry_is_not_mutated(c1a, anim):
    before = [(s.name, s.obj) for s in c1a.steps]
    anim.render(anim.frame_count // 2)
    assert [(s.name, s.obj) for s in c1a.steps] == before
    assert c1a.steps[-1].obj.V == tuple(c1a[f"V{n}"] for n in (1, 2, 3, 4))


# -- frames ---------------------------------------------------------------------------------
def static_reference(c, anim) -> np.ndarray:
    fig = Figure(figsize=anim.figure.get_size_inches(), dpi=anim.figure.dpi)
    ax = fig.add_axes(anim.axes.get_position().bounds)
    draw_construction(c, ax=ax, theme=anim.theme)
    ax.tick_params(labelsize=anim.theme.font_size * 0.7)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    return np.asarray(canvas.buffer_rgba())[..., :3]


def test_last_frame_is_the_static_figure(c1a, anim, frames):
    ref = static_reference(c1a, anim)
    x0, y0, x1, y1 = anim.axes.get_window_extent().extents
    h = ref.shape[0]
    crop = (slice(int(h - y1) + 3, int(h - y0) - 3), slice(int(x0) + 3, int(x1) - 3))
    for last in (frames[-1], anim.render(-1)):
        assert last.shape == ref.shape
        diff = np.abs(last[crop].astype(int) - ref[crop].astype(int))
        assert diff.mean() < 1.0 and (diff.max(axis=2) > 40).mean() < 0.005
    # and a mid frame differs from it: things are dimmed and hidden
    assert np.abs(frames[len(frames) // 2][crop].astype(int) - ref[crop]).mean() > 2


def test_blitted_frames_match_full_draws(anim, frames):
    assert len(frames) == anim.frame_count
    for f in (0, 7, anim.timeline.frames_of_step(17)[-1], anim.frame_count - 2):
        diff = np.abs(frames[f].astype(int) - anim.render(f).astype(int))
        assert (diff.max(axis=2) > 60).mean() < 0.01, f


def test_deterministic(c1a, frames):
    again = animate_construction(
        c1a, frames_per_step=3, pause_frames=2, hold_frames=3, caption_seconds=0, **CSMALL
    )
    assert all(np.array_equal(a, b) for a, b in zip(again.iter_frames(), frames, strict=True))


def test_live_funcanimation_leaves_rendering_intact(c1a):
    sweep = animate_sweep(c1a, frames=3, figsize=(3.2, 2), dpi=25)  # even pixel sizes
    before = sweep.render(1)
    live = sweep.animation
    assert live is sweep.animation and live._blit  # the sweep blits its movers
    assert "<script" in live.to_jshtml()
    assert all(a in sweep.update(2) for a in sweep.artists.values())
    assert np.array_equal(sweep.render(1), before)
    diff = np.abs(list(sweep.iter_frames())[1].astype(int) - before)  # blitted: same picture
    assert (diff.max(axis=2) > 60).mean() < 0.01


# -- output files ---------------------------------------------------------------------------
def test_gif_opens_with_the_frames(anim, frames, tmp_path):
    out = anim.save(tmp_path / "construction.gif", quiet=True)
    w, h = (anim.figure.get_size_inches() * anim.figure.dpi).round().astype(int)
    distinct = 1 + sum(not np.array_equal(a, b) for a, b in pairwise(frames))
    with Image.open(out) as im:
        assert im.size == (w, h)
        assert im.n_frames == distinct >= 0.9 * anim.frame_count
        durations = []
        for i in range(im.n_frames):
            im.seek(i)
            durations.append(im.info["duration"])
    assert sum(durations) == pytest.approx(anim.frame_count * 1000 / anim.fps, abs=1)
    assert out.read_bytes() == anim.save(tmp_path / "again.gif", quiet=True).read_bytes()


def test_png_frames_per_step(c1a, anim, tmp_path):
    (tmp_path / "png").mkdir()  # an output's folder must exist (issue 10)
    files = save_frames(anim, tmp_path / "png")
    assert len(files) == len(c1a.steps)
    assert files[17].name == "step-17-V1.png"
    with Image.open(files[-1]) as im:
        assert im.size == (120, 136)


def test_html_is_self_contained(tmp_path, c1a):
    # each caption 0.3 s: a few stills per step; no zoom
    small = small_animation(
        c1a, pause_frames=1, figsize=(2, 2), caption_seconds=0.3, camera=False, min_text_px=None
    )
    html = small._repr_html_()
    assert "<script" in html and "<img" in html
    # every frame is in the player: each distinct picture once, a repeat by reference
    frames = [f.tobytes() for f in small.iter_frames()]
    assert html.count("data:image/png;base64,") == len(set(frames)) < small.frame_count
    assert len(re.findall(r"^\s*frames\[\d+\] = ", html, re.M)) == small.frame_count
    out = small.save(tmp_path / "c.html", quiet=True)
    assert out.read_text().count("data:image/png;base64,") == len(set(frames))


def test_errors_are_one_line_value_errors(anim, tmp_path, monkeypatch):
    with pytest.raises(UnsupportedFormatError, match=r"'\.avi' is not supported") as e:
        anim.save(tmp_path / "x.avi")
    assert isinstance(e.value, ValueError) and "\n" not in str(e.value)
    for fps in (0, -2, float("nan")):
        with pytest.raises(AnimationError, match="fps must be a positive number"):
            anim.save(tmp_path / "x.gif", fps=fps)
    with pytest.raises(AnimationError, match="fps"):
        animate_sweep(Grasp.preset("table1a"), frames=4, fps=0)
    monkeypatch.setitem(matplotlib.rcParams, "animation.ffmpeg_path", str(tmp_path / "none"))
    with pytest.raises(FFmpegNotFoundError, match="no ffmpeg"):
        anim.save(tmp_path / "x.mp4")
    assert not list(tmp_path.iterdir())


def test_mp4_pipes_raw_frames_to_ffmpeg(tmp_path, monkeypatch, c1a):
    """A stand-in ffmpeg records its arguments and the bytes it was sent."""
    fake = tmp_path / "ffmpeg"
    fake.write_text(
        f"#!{sys.executable}\nimport sys\ndata = sys.stdin.buffer.read()\n"
        "open(sys.argv[-1], 'w').write(' '.join(sys.argv[1:]) + '\\n' + "
        "str(len(data)))\n"
    )
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setitem(matplotlib.rcParams, "animation.ffmpeg_path", str(fake))
    small = animate_sweep(c1a, frames=6, figsize=(3, 2), dpi=30)
    out = small.save(tmp_path / "s.mp4", fps=12, quiet=True)
    args, size = out.read_text().splitlines()
    assert "-s 90x60" in args and "-r 12" in args and "libx264" in args
    assert int(size) == 90 * 60 * 3 * 6


def test_mp4_with_real_ffmpeg(tmp_path, c1a):
    """MP4 through the ffmpeg of the ``mp4`` extra (imageio-ffmpeg, in the test extra too).

    The file is read back by that ffmpeg: as many frames as were drawn, of the drawn size.
    """
    imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg", reason="the test extra brings it")
    small = animate_sweep(c1a, frames=4, figsize=(3, 2), dpi=30)
    path = small.save(tmp_path / "s.mp4", fps=4, quiet=True)
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(path))
    reader = imageio_ffmpeg.read_frames(str(path))
    meta = next(reader)
    reader.close()
    assert frames == 4 and tuple(meta["size"]) == (90, 60)


def test_progress_bar_only_on_a_terminal():
    class Tty(io.StringIO):
        def isatty(self):
            return True

    for stream, quiet, shown in (
        (Tty(), False, True),
        (Tty(), True, False),
        (io.StringIO(), False, False),
    ):
        bar = Progress(4, "writing x.gif", quiet=quiet, stream=stream)
        for _ in range(4):
            bar.update()
        bar.close()
        assert ("4/4" in stream.getvalue()) is shown


# -- the sweep of the external force (Fig. 3) -----------------------------------------------
@pytest.mark.parametrize("preset", ["table1a", "fig6"])
def test_sweep_traces_k_grasp(preset):
    sweep = animate_sweep(Grasp.preset(preset), frames=24, **SMALL)
    theta = 2 * PI * np.arange(24) / 24
    assert np.allclose(sweep.theta, theta)
    assert np.allclose(sweep.k_grasp, paper_k_grasp(preset, theta), atol=1e-9)
    sweep.render(23)
    xy = sweep.artists["trace"].get_xydata()
    th = np.mod(np.arctan2(xy[:, 0], -xy[:, 1]), 2 * PI)  # e(θ) = (sin θ, −cos θ)
    r = np.hypot(xy[:, 0], xy[:, 1])
    k = paper_k_grasp(preset, th)
    assert len(xy) > 600 and np.allclose(r, k, atol=1e-9)
    pt = sweep.artists["point"].get_xydata()[0]
    e = np.array([np.sin(theta[23]), -np.cos(theta[23])])
    assert np.allclose(pt, paper_k_grasp(preset, theta[23:])[0] * e)
    for n in (1, 2, 3, 4):  # the feet H_n: O H_n = k_n along e(θ), on the circle on O V_n
        h = sweep.artists[f"H{n}"].get_xydata()[0]
        assert np.allclose(h, paper_k(preset, theta[23:])[n - 1, 0] * e)


def test_sweep_names_the_slipping_contact():
    sweep = animate_sweep(Grasp.preset("table1a"), frames=36, **SMALL)
    ks = paper_k("table1a", sweep.theta)
    expected = np.where(ks.max(axis=0) > 0, ks.argmax(axis=0) + 1, 0)
    assert np.array_equal(sweep.binding, expected)
    assert [s.step for s in sweep.timeline.segments] == [
        int(n) for i, n in enumerate(expected) if i == 0 or n != expected[i - 1]
    ]
    for f in range(0, 36, 5):
        assert SLIP[int(expected[f])] in sweep.status_at(f)
    assert "contact 1" in SLIP[1] and "upper" in SLIP[1] and "(8)" in SLIP[1]
    assert "contact 2" in SLIP[2] and "upper" in SLIP[2] and "(9)" in SLIP[2]
    assert "contact 1" in SLIP[3] and "lower" in SLIP[3] and "(10)" in SLIP[3]
    assert "contact 2" in SLIP[4] and "lower" in SLIP[4] and "(11)" in SLIP[4]


def test_binding_inequality_holds_with_equality():
    """With k = k_grasp the contact forces F = F_T + k F_N (eqs. (13), (15), (16)) make the
    inequality (8)-(11) named by the sweep an equality, and keep the others."""
    x1, x2, y, p1, p2, k1, k2 = PAPER["table1a"]
    m1, m2, D = np.tan(k1), np.tan(k2), x1 + x2
    s1, c1, s2, c2 = np.sin(p1), np.cos(p1), np.sin(p2), np.cos(p2)
    sweep = animate_sweep(Grasp.preset("table1a"), frames=24, **SMALL)
    for f, th in enumerate(sweep.theta):
        s, c = np.sin(th), np.cos(th)
        a, b = y * s - x2 * c, y * s + x1 * c
        FT = np.array(
            [
                D * s1 * s + 2 * a * c1,
                D * c1 * s - 2 * a * s1,
                -D * s2 * s - 2 * b * c2,
                -D * c2 * s + 2 * b * s2,
            ]
        ) / (2 * D)
        N1, F1, N2, F2 = (
            FT + paper_k_grasp("table1a", np.array([th]))[0] * np.array([s1, c1, s2, c2]) / D
        )
        ineq = np.array([m1 * N1 - F1, m2 * N2 - F2, m1 * N1 + F1, m2 * N2 + F2])
        assert ineq.min() > -1e-9
        n = int(sweep.binding[f])
        if n:
            assert abs(ineq[n - 1]) < 1e-9, (th, n, ineq)


# -- the object turning under gravity (Fig. 1) ----------------------------------------------
def test_orientation_gravity_direction_and_force(tmp_path):
    turn = animate_orientation(Grasp.preset("table1c"), weight=2.5, frames=12, **SMALL)
    alpha = 2 * PI * np.arange(12) / 12
    theta = np.mod(-alpha, 2 * PI)
    assert np.allclose(turn.theta, theta) and np.allclose(theta_of_orientation(alpha), theta)
    for a, t in zip(alpha, theta):  # gravity (0, −1) seen from the object turned by α is e(θ)
        rot = np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]])  # R(−α)
        assert np.allclose(rot @ [0.0, -1.0], [np.sin(t), -np.cos(t)])
    k = paper_k_grasp("table1c", theta)
    assert np.allclose(turn.force, k / 4.0 * 2.5)  # eq. (17), x1 + x2 = 4
    f = 4
    turn.render(f)
    assert turn.artists["gauge"].get_width() == pytest.approx(k[f] / 4 * 2.5)
    assert np.allclose(turn.world_point(f), (0.0, -k[f]))
    # the envelope point at θ, turned by α with the object, is straight below O
    e = np.array([np.sin(theta[f]), -np.cos(theta[f])])
    envelope = turn.kept["envelope"][0]
    to_world = envelope.get_transform() - turn.axes.transData
    assert np.allclose(to_world.transform(k[f] * e), (0.0, -k[f]))
    V = np.column_stack([np.hypot(*turn.V[n]) for n in range(4)])
    assert turn.force_max == pytest.approx(V.max() / 4 * 2.5)
    assert len(save_frames(turn, tmp_path)) == 12


# -- command line ---------------------------------------------------------------------------
def parser():
    """The command line as cli.py wires it: its grasp options and its one-line-error parser."""
    p = _Parser(prog="graspcompass")
    register(p.add_subparsers(dest="command", parser_class=_Parser), _add_grasp_options)
    return p


def test_cli_animate(tmp_path, capsys):
    out = tmp_path / "s.gif"
    args = parser().parse_args(
        [
            "animate",
            "table1a",
            "--kind",
            "sweep",
            "-o",
            str(out),
            "--frames",
            "6",
            "--fps",
            "10",
            "--dpi",
            "20",
        ]
    )
    assert args.preset == "table1a" and args.kind == "sweep"
    assert run(args, grasp_from_args(args)) == 0
    assert "wrote" in capsys.readouterr().out
    with Image.open(out) as im:
        assert im.n_frames >= 5 and im.info["duration"] == 100
    args = parser().parse_args(
        ["animate", "--preset", "table1b", "--mu1", "0.8", "-o", str(tmp_path / "x")]
    )
    assert (
        args.preset == "table1b"
        and grasp_from_args(args).mu1 == Grasp(2, 2, 3, "pi/2", "pi/2", mu1="0.8", mu2="1.2").mu1
    )
    with pytest.raises(UnsupportedFormatError, match="without extension"):
        run(args, grasp_from_args(args))
    for bad in (["--fps", "0"], ["--fps", "x"], ["nopreset"], ["--kind", "spin"]):
        with pytest.raises(SystemExit) as e:
            parser().parse_args(["animate", *bad])
        assert e.value.code == 2
        assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_main_job_animation(tmp_path, c1a, monkeypatch):
    """The main job's GIF: at least 640 pixels wide (issue 12), every frame in the file.

    The frames are the main job's first frame, drawn in full at its size, marked in corner
    pixels by the number of their timeline segment: Pillow merges equal neighbours into
    one GIF frame and adds their durations, so the file must hold one GIF frame per
    segment and the duration of every frame.  Drawing all ~1000 frames (15-20 s) is what
    tests/test_lecture_animation.py and test_gif_opens_with_the_frames check on small
    animations; here the main job's own size, pace and frame count."""
    from graspcompass.render.animate import ConstructionAnimation

    def marked(self):
        first = self.render(0)
        tl, rgb = self.timeline, None
        for f in range(self.frame_count):
            if rgb is None or f in tl.starts:  # segment k in binary, black on white
                k = tl.segment_of(f)
                rgb = first.copy()
                bits = [(k >> b) & 1 for b in range(12)]
                rgb[0, :12] = np.array([[0, 0, 0] if bit else [255, 255, 255] for bit in bits])
            yield rgb

    monkeypatch.setattr(ConstructionAnimation, "iter_frames", marked)
    out = write_main_animation(c1a, tmp_path, quiet=True)
    assert out == tmp_path / MAIN_ANIMATION
    main = main_animation(c1a)
    with Image.open(out) as im:
        assert im.size[0] >= 640
        durations = []
        for i in range(im.n_frames):
            im.seek(i)
            durations.append(im.info["duration"])
    assert len(durations) == len(main.timeline.segments)
    assert sum(durations) == pytest.approx(main.frame_count * 1000 / main.fps, abs=1)
    assert main.frame_count > 8 * len(c1a.steps)
