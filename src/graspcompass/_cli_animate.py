"""The ``graspcompass animate`` sub-command and the main job's construction animation.

``graspcompass animate [PRESET] [grasp options] --kind construction|sweep|orientation
-o FILE.gif|.mp4|.html [--fps N]`` writes one of the animations of
:mod:`graspcompass.render.animate`: the ruler-and-compass construction of §3.3
step by step, the external force sweeping round (Fig. 3), or the object
turning under gravity (Fig. 1).  matplotlib is imported only when it runs.

Every option is bounded and checked when the command line is read, before any
work: ``--fps`` in (0, :data:`MAX_FPS`] (at least :data:`MIN_FPS`, the slowest a
GIF frame can last), ``--dpi`` in [:data:`MIN_DPI`, :data:`MAX_DPI`], ``--frames``
in [1, :data:`MAX_FRAMES`], ``--frames-per-step`` in [1, :data:`MAX_FRAMES_PER_STEP`],
``--weight`` in [:data:`MIN_WEIGHT`, :data:`MAX_WEIGHT`]; the output path (its
folder must exist) before the grasp is built; and the size of the whole
animation (frames × pixels per frame, at most :data:`MAX_PIXELS`) before the
first frame is drawn.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import Any

from .presets import PRESETS

__all__ = ["KINDS", "MAIN_ANIMATION", "MAX_DPI", "MAX_FPS", "MAX_FRAMES",
           "MAX_FRAMES_PER_STEP", "MAX_PIXELS", "MAX_WEIGHT", "MIN_DPI", "MIN_FPS", "MIN_WEIGHT",
           "bounded", "quiet_option", "register", "run", "write_main_animation"]

#: The kinds of animation.
KINDS = ("construction", "sweep", "orientation")
#: File name of the main job's animation.
MAIN_ANIMATION = "fig6-construction.gif"
#: Bounds of ``--fps`` (a GIF frame lasts at most 655.35 s; 120 fps is beyond any screen).
MIN_FPS, MAX_FPS = 0.01, 120.0
#: Bounds of ``--dpi`` (below 10 the fonts have no pixels; 600 is print quality).
MIN_DPI, MAX_DPI = 10.0, 600.0
#: Most frames of one turn (``--frames``) and per protocol step (``--frames-per-step``).
MAX_FRAMES, MAX_FRAMES_PER_STEP = 3600, 120
#: Bounds of ``--weight`` (the picture is the same up to the scale of the force axis).
MIN_WEIGHT, MAX_WEIGHT = 1e-6, 1e6
#: Most pixels in all the frames of one animation (about two minutes of drawing).
MAX_PIXELS = 2_000_000_000


def bounded(kind: type, low: float, high: float, *, low_open: bool = False
            ) -> Callable[[str], Any]:
    """An argparse ``type`` reading ``kind`` (int or float) within ``[low, high]``.

    nan, infinities and text are refused with a one-line message naming the
    bounds.

    Parameters
    ----------
    kind : type
        ``int`` or ``float``.
    low, high : float
        The bounds, both included unless ``low_open``.
    low_open : bool, optional
        Exclude the lower bound.

    Returns
    -------
    callable
        A function of the option's text that returns the value or raises
        :class:`argparse.ArgumentTypeError`.

    Examples
    --------
    >>> bounded(float, 0, 120, low_open=True)("20")
    20.0
    >>> bounded(float, 0, 120, low_open=True)("nan")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: must be a number above 0 and at most 120, got 'nan'
    """
    if kind is int:
        what = f"an integer from {low} to {high}"
    elif low_open:
        what = f"a number above {low:g} and at most {high:g}"
    else:
        what = f"a number from {low:g} to {high:g}"

    def parse(text: str) -> Any:
        shown = text if len(text) <= 40 else text[:30] + "..."
        try:
            value = kind(text)
        except (ValueError, OverflowError):
            raise argparse.ArgumentTypeError(f"must be {what}, got {shown!r}") from None
        inside = low < value <= high if low_open else low <= value <= high
        if not inside:  # also nan
            raise argparse.ArgumentTypeError(f"must be {what}, got {shown!r}")
        return value

    parse.__name__ = kind.__name__
    return parse


def quiet_option(p: argparse.ArgumentParser, text: str = "print nothing but errors") -> None:
    """Add ``-q``/``--quiet`` to a sub-command without hiding the root's ``graspcompass -q``.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The sub-command's parser.
    text : str, optional
        The option's help.
    """
    p.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS, help=text)


def _preset(name: str) -> str:
    if name == argparse.SUPPRESS or name in PRESETS:
        return name
    raise argparse.ArgumentTypeError(f"unknown preset {name!r}; choose one of "
                                     f"{', '.join(sorted(PRESETS))}")


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]
             ) -> argparse.ArgumentParser:
    """Add the ``animate`` sub-command to ``subparsers``; returns its parser."""
    p = subparsers.add_parser(
        "animate", help="animate the construction, the force sweep or the turning object",
        description="Write an animation: the ruler-and-compass construction step by step "
                    "(§3.3), the external force sweeping round (Fig. 3) or the object turning "
                    "under gravity (Fig. 1), as GIF, MP4 (needs ffmpeg) or HTML.",
        epilog="limits: every option is checked before any work; the output folder must "
               f"exist; an animation has at most {MAX_PIXELS:.0e} pixels in all its frames "
               "(lower --dpi or --frames). exit status: 0, or 2 for a user error.")
    p.add_argument("preset", nargs="?", type=_preset, default=argparse.SUPPRESS,
                   metavar="PRESET", help=f"a preset ({', '.join(sorted(PRESETS))}); same as "
                                          "--preset")
    add_grasp_options(p)
    p.add_argument("--kind", choices=KINDS, default="construction",
                   help="what to animate (default: construction)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="output .gif, .mp4 or .html file (default: PRESET-KIND.gif)")
    p.add_argument("--fps", type=bounded(float, MIN_FPS, MAX_FPS), default=20.0, metavar="N",
                   help=f"frames per second, {MIN_FPS:g} to {MAX_FPS:g} (default: 20)")
    p.add_argument("--frames", type=bounded(int, 1, MAX_FRAMES), default=120, metavar="N",
                   help=f"frames of one turn, for --kind sweep and orientation, 1 to {MAX_FRAMES} "
                        "(default: 120)")
    p.add_argument("--frames-per-step", type=bounded(int, 1, MAX_FRAMES_PER_STEP), default=8,
                   metavar="N", help="frames drawing each protocol step, for --kind "
                                     f"construction, 1 to {MAX_FRAMES_PER_STEP} (default: 8)")
    p.add_argument("--weight", type=bounded(float, MIN_WEIGHT, MAX_WEIGHT), default=1.0,
                   metavar="W", help="weight of the object, for --kind orientation, "
                                     f"{MIN_WEIGHT:g} to {MAX_WEIGHT:g} (default: 1)")
    p.add_argument("--dpi", type=bounded(float, MIN_DPI, MAX_DPI), default=80.0, metavar="N",
                   help=f"resolution, {MIN_DPI:g} to {MAX_DPI:g} (default: 80)")
    p.add_argument("--theme", choices=("default", "paper"), default="default",
                   help="colour theme (default: default)")
    quiet_option(p, "print nothing but errors (no progress bar)")
    return p


def run(args: argparse.Namespace, grasp: Any) -> int:
    """Run ``graspcompass animate`` for ``grasp``; returns the exit status.

    ``grasp`` is a :class:`~graspcompass.Grasp`, or a function that makes it,
    called once the output is checked.

    Raises
    ------
    ValueError
        :class:`~graspcompass.render.timeline.UnsupportedFormatError` for an
        unknown extension, :class:`~graspcompass.render.timeline.FFmpegNotFoundError`
        for ``.mp4`` without ffmpeg, :class:`~graspcompass.errors.OutputError` for
        a path that cannot be written, :class:`~graspcompass.errors.InputTooLargeError`
        for an animation beyond :data:`MAX_PIXELS`, and the errors of the grasp and
        the construction; the command line prints them on one line.
    """
    from ._output import check_target, writing
    from .render.timeline import check_output

    name = args.output if args.output is not None else f"{args.preset}-{args.kind}.gif"
    check_output(name)
    path = check_target(name)
    from .construction import internal_force_diagram
    from .errors import InputTooLargeError
    from .render.anim_physics import animate_orientation, animate_sweep
    from .render.animate import animate_construction
    from .render.theme import THEMES

    quiet = getattr(args, "quiet", False)
    theme = THEMES[args.theme]
    c = internal_force_diagram(grasp() if callable(grasp) else grasp)
    anim: Any
    if args.kind == "construction":
        anim = animate_construction(c, fps=args.fps, frames_per_step=args.frames_per_step,
                                    theme=theme, dpi=args.dpi)
    elif args.kind == "sweep":
        anim = animate_sweep(c, frames=args.frames, fps=args.fps, theme=theme, dpi=args.dpi)
    else:
        anim = animate_orientation(c, weight=args.weight, frames=args.frames, fps=args.fps,
                                   theme=theme, dpi=args.dpi)
    width, height = anim.figure.get_size_inches() * anim.figure.dpi
    pixels = anim.frame_count * round(width) * round(height)
    if pixels > MAX_PIXELS:
        raise InputTooLargeError(
            f"the animation would have {anim.frame_count} frames of {round(width)}×"
            f"{round(height)} pixels ({pixels:.2e} in all); at most {MAX_PIXELS:.0e}: lower "
            "--dpi or --frames")
    with writing(path):
        anim.save(path, fps=args.fps, quiet=quiet)
    if not quiet:
        print(f"wrote {path} ({anim.frame_count} frames at {args.fps:g} fps)")
    return 0


def write_main_animation(construction: Any, out_dir: str | Path, quiet: bool = False) -> Path:
    """Write the construction animation of ``construction`` to ``out_dir/fig6-construction.gif``.

    Small and fast for the main job: 8 frames per step at 20 fps, 4.5 × 5 inches at 64 dpi.
    """
    from .render.animate import animate_construction

    anim = animate_construction(construction, figsize=(4.5, 5.0), dpi=64)
    return anim.save(Path(out_dir) / MAIN_ANIMATION, quiet=quiet)
