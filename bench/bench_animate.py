"""Benchmark: the Fig. 6 construction animation written as GIF, against a naive full redraw.

Ito, Tanaka, Sasaki (Robotica 2012), §4.1, Fig. 6.  The animation has the
default 8 frames per protocol step at the default 20 fps (plus the pauses on
V_n, the circles and the envelope, and the final hold).  Measured in one run:

- ``graspcompass``: :func:`graspcompass.render.animate.animate_construction` and
  ``.save("fig6.gif")`` (artists made once, blitting, Pillow GIF);
- rendering only (``iter_frames``), to compare like with like;
- naive: for each frame, clear the axes, call
  :func:`graspcompass.render.draw_construction` for the state of that step and
  draw the whole figure (timed on every ``--naive-every``-th frame; the time
  per frame is what counts).

Also the main job's GIF (640 × 720 pixels since issue 12) against the naive
redraw at its own size, and with ``--lecture`` the lecture-quality animation
(1280 × 720, about 4450 frames of which about 990 are drawn: the still frames
that keep a caption on screen repeat the frame before) rendered, not encoded.

Run ``PYTHONPATH=src python bench/bench_animate.py [--naive-every N] [--out DIR] [--lecture]``.
The target: the GIF in under 20 s on a 2-core machine.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from graspcompass import Grasp, internal_force_diagram
from graspcompass.cli._animate import main_animation
from graspcompass.render import draw_construction
from graspcompass.render.animate import animate_construction


def naive_frames(c, anim, frames: list[int]) -> float:
    """Seconds per frame of a full redraw: clear, draw_construction(step), draw the figure."""
    fig = Figure(figsize=anim.figure.get_size_inches(), dpi=anim.figure.dpi)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_axes(anim.axes.get_position().bounds)
    start = time.perf_counter()
    for f in frames:
        ax.cla()
        draw_construction(c, step=anim.timeline.at(f).step, ax=ax, highlight_last=True)
        fig.suptitle(anim.caption_at(f), y=0.12, fontsize=8)
        canvas.draw()
        np.array(canvas.buffer_rgba())
    return (time.perf_counter() - start) / len(frames)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument(
        "--naive-every",
        type=int,
        default=10,
        metavar="N",
        help="time the naive redraw on every N-th frame (default: 10; 1 = all)",
    )
    p.add_argument("--out", metavar="DIR", help="keep the GIF in DIR")
    p.add_argument(
        "--quick", action="store_true", help="time the naive redraw on every 40th frame only"
    )
    p.add_argument(
        "--lecture",
        action="store_true",
        help="also render the lecture-quality animation (about a minute)",
    )
    args = p.parse_args(argv)

    t0 = time.perf_counter()
    c = internal_force_diagram(Grasp.preset("fig6"))
    t_construct = time.perf_counter() - t0

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(args.out or tmp) / "fig6-construction.gif"
        t0 = time.perf_counter()
        anim = animate_construction(c)
        anim.save(out, quiet=True)
        t_gif = time.perf_counter() - t0
        n = anim.frame_count
        with Image.open(out) as im:
            gif_frames, size = im.n_frames, im.size
        per_step = len(anim.timeline.frames_of_step(0))

        t0 = time.perf_counter()
        for _ in anim.iter_frames():
            pass
        t_render = time.perf_counter() - t0

        every = 40 if args.quick else args.naive_every
        sample = list(range(0, n, max(1, every)))
        t_naive = naive_frames(c, anim, sample)

        t0 = time.perf_counter()
        main = main_animation(c)
        main.save(Path(args.out or tmp) / "main-job.gif", quiet=True)
        t_main = time.perf_counter() - t0
        main_size = tuple(round(v) for v in main.figure.get_size_inches() * main.figure.dpi)
        t_main_naive = naive_frames(c, main, list(range(0, main.frame_count, 40)))

        if args.lecture:
            t0 = time.perf_counter()
            lecture = animate_construction(c, quality="lecture")
            for _ in lecture.iter_frames():
                pass
            t_lecture = time.perf_counter() - t0

    fps_gif, fps_render, fps_naive = n / t_gif, n / t_render, 1.0 / t_naive
    print(
        f"Fig. 6 construction: {len(c.steps)} steps (replayed in {t_construct:.2f} s), "
        f"{n} frames ({per_step} per step, {anim.fps:g} fps), {size[0]}x{size[1]} px, "
        f"{gif_frames} GIF frames"
    )
    print(
        f"graspcompass GIF     : {t_gif:6.2f} s  {fps_gif:7.1f} frames/s  "
        f"(target < 20 s: {'ok' if t_gif < 20 else 'MISSED'})"
    )
    print(
        f"graspcompass render  : {t_render:6.2f} s  {fps_render:7.1f} frames/s  "
        "(iter_frames, no encoding)"
    )
    print(
        f"naive full redraw    : {t_naive * n:6.2f} s  {fps_naive:7.1f} frames/s  "
        f"(estimated for {n} frames from {len(sample)})"
    )
    print(
        f"speed-up vs naive    : {fps_render / fps_naive:6.1f}x rendering, "
        f"{t_naive * n / t_gif:.1f}x including the GIF encoding"
    )
    naive_main = t_main_naive * main.frame_count
    print(
        f"main job GIF         : {t_main:6.2f} s  {main.frame_count} frames of "
        f"{main_size[0]}x{main_size[1]} px; naive at that size "
        f"{naive_main:6.2f} s: {naive_main / t_main:.1f}x"
    )
    if args.lecture:
        print(
            f"lecture render       : {t_lecture:6.2f} s  {lecture.frame_count} frames "
            f"({lecture.drawn_frames} drawn), {lecture.frame_count / lecture.fps:.0f} s of "
            f"animation; naive estimate {t_main_naive * lecture.frame_count * 2:6.1f} s "
            "(2x the main job's pixels per frame)"
        )
    return 0 if t_gif < 20 else 1


if __name__ == "__main__":
    sys.exit(main())
