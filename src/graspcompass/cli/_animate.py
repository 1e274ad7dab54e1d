"""The ``graspcompass animate`` sub-command and the main job's construction animation.

``graspcompass animate [PRESET] [grasp options] --kind construction|sweep|orientation
-o FILE.gif|.mp4|.html [--quality standard|lecture] [--fps N] [--dpi N] [--pause S]
[--hold S] [--zoom S] [--caption-seconds S] [--circle N]`` writes one of the animations of
:mod:`graspcompass.render.animate`: the ruler-and-compass construction of §3.3
step by step, the external force sweeping round (Fig. 3), or the object
turning under gravity (Fig. 1).  matplotlib is imported only when it runs.
``--file FILE.gc [--set NAME=EXPR]`` animates the construction of a file of the
construction language (:mod:`graspcompass.cli._file`); ``sweep`` and
``orientation`` need the paper's four circles and take the paper's recipe only.

``--quality lecture`` is for a projector (:data:`~graspcompass.render.theme.QUALITIES`):
1280 × 720 pixels (at the default ``--dpi 100``; ``--dpi 150`` gives 1920 × 1080),
captions at 20 pt beside the diagram, each on screen at least 2.5 s and
longer by its length.  The options left out take the quality's values.

Every option is bounded and checked when the command line is read, before any
work: ``--fps`` in (0, :data:`MAX_FPS`] (at least :data:`MIN_FPS`, the slowest a
GIF frame can last), ``--dpi`` in [:data:`MIN_DPI`, :data:`MAX_DPI`] (at least
:data:`MIN_LECTURE_DPI` with ``--quality lecture``: 1280 pixels wide), ``--frames``
in [1, :data:`MAX_FRAMES`], ``--frames-per-step`` in [1, :data:`MAX_FRAMES_PER_STEP`],
``--pause``, ``--hold``, ``--zoom`` and ``--caption-seconds`` in [0, :data:`MAX_SECONDS`],
``--weight`` in [:data:`MIN_WEIGHT`, :data:`MAX_WEIGHT`]; the output path (its
folder must exist) before the grasp is built; and the size of the whole
animation (frames drawn × pixels per frame, at most :data:`MAX_PIXELS`; a still frame,
which repeats the one before, is not drawn again) before the
first frame is drawn.  Nothing heavy is imported before these checks.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..presets import PRESETS
from . import _file

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp
    from ..render.animate import ConstructionAnimation

__all__ = [
    "KINDS",
    "MAIN_ANIMATION",
    "MAIN_DPI",
    "MAIN_FIGSIZE",
    "MAX_ANIMATION_FRAMES",
    "MAX_DPI",
    "MAX_FPS",
    "MAX_FRAMES",
    "MAX_FRAMES_PER_STEP",
    "MAX_PIXELS",
    "MAX_SECONDS",
    "MAX_WEIGHT",
    "MIN_DPI",
    "MIN_FPS",
    "MIN_LECTURE_DPI",
    "MIN_WEIGHT",
    "QUALITY_NAMES",
    "bounded",
    "main_animation",
    "quiet_option",
    "register",
    "run",
    "write_main_animation",
]

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
#: Most frames of one animation, stills included (each is kept until the file is written;
#: the lecture quality's construction has about 4,500).
MAX_ANIMATION_FRAMES = 20_000
#: The presets of ``--quality`` (the keys of :data:`graspcompass.render.theme.QUALITIES`).
QUALITY_NAMES = ("standard", "lecture")
#: Least ``--dpi`` with ``--quality lecture``: its 12.8-inch frame is then 1280 pixels wide.
MIN_LECTURE_DPI = 100.0
#: Most seconds of ``--pause``, ``--hold``, ``--zoom`` and ``--caption-seconds``.
MAX_SECONDS = 60.0
#: Frame of the main job's GIF: 6.4 × 7.2 inches at 100 dpi, 640 × 720 pixels.
MAIN_FIGSIZE, MAIN_DPI = (6.4, 7.2), 100.0


def bounded(kind: type, low: float, high: float, *, low_open: bool = False) -> Callable[[str], Any]:
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


def _preset_or_file(name: str) -> str:
    """An argparse ``type``: a preset's name, or a construction file (as ``draw FILE``)."""
    import os

    if name is argparse.SUPPRESS or name in PRESETS or name == "-" or os.path.lexists(name):
        return name
    raise argparse.ArgumentTypeError(
        f"{name!r} is neither a preset ({', '.join(sorted(PRESETS))}) nor a file: give a "
        "preset, or a construction file (FILE or --file FILE)"
    )


class _PresetOrFile(argparse.Action):
    """Stores a preset's name as ``preset``, a file's as ``file`` (as ``draw FILE``: beside
    ``--file`` it is refused as two files)."""

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: Any,
        option_string: str | None = None,
    ) -> None:
        setattr(namespace, "preset" if values in PRESETS else "file", values)


class _Checked(argparse.Action):
    """Stores the option, then refuses ``--quality lecture`` with ``--dpi`` below
    :data:`MIN_LECTURE_DPI` (whichever of the two comes last), as a usage error."""

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: Any,
        option_string: str | None = None,
    ) -> None:
        setattr(namespace, self.dest, values)
        dpi = getattr(namespace, "dpi", None)
        if (
            getattr(namespace, "quality", None) == "lecture"
            and dpi is not None
            and dpi < MIN_LECTURE_DPI
        ):
            parser.error(
                f"--quality lecture needs --dpi {MIN_LECTURE_DPI:g} or more (1280 "
                f"pixels wide), got --dpi {dpi:g}"
            )


def register(
    subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]
) -> argparse.ArgumentParser:
    """Add the ``animate`` sub-command to ``subparsers``; returns its parser."""
    p = subparsers.add_parser(
        "animate",
        help="animate the construction, the force sweep or the turning object",
        description="Write an animation: the ruler-and-compass construction step by step "
        "(§3.3), the external force sweeping round (Fig. 3) or the object turning "
        "under gravity (Fig. 1), as GIF, MP4 (pip install 'graspcompass[mp4]', or a "
        "system ffmpeg) or HTML.",
        epilog="limits: every option is checked before any work; the output folder must "
        f"exist; an animation has at most {MAX_PIXELS:.0e} pixels in all its drawn frames "
        f"(lower --dpi or --frames) and at most {MAX_ANIMATION_FRAMES} frames in all. "
        "exit status: 0, or 2 for a user error.",
    )
    p.add_argument(
        "target",
        nargs="?",
        type=_preset_or_file,
        default=argparse.SUPPRESS,
        metavar="PRESET|FILE",
        help=f"a preset ({', '.join(sorted(PRESETS))}; same as --preset) or a "
        "construction file ('-' reads stdin; same as --file)",
        action=_PresetOrFile,
    )
    add_grasp_options(p)
    _file.add_file_options(p, positional=False)
    from ._ncontact import add_options as _add_ncontact

    _add_ncontact(p)
    p.add_argument(
        "--kind",
        choices=KINDS,
        default="construction",
        help="what to animate (default: construction)",
    )
    p.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="output .gif, .mp4 or .html file (default: PRESET-KIND.gif, or "
        "the construction file's name for PRESET)",
    )
    p.add_argument(
        "--quality",
        choices=QUALITY_NAMES,
        default="standard",
        action=_Checked,
        help="standard: 640x720 pixels, 10 fps, every text at least 14 pixels, "
        "each caption at least 2 s; lecture: for a projector, 1280x720 "
        "pixels, a title card, captions at 20 pt beside the diagram, each on "
        "screen at least 2.5 s and longer by its length, key steps 3 s "
        "longer; both zoom to the step being drawn; the options below left "
        "out take the quality's values (default: standard)",
    )
    p.add_argument(
        "--fps",
        type=bounded(float, MIN_FPS, MAX_FPS),
        default=None,
        metavar="N",
        help=f"frames per second, {MIN_FPS:g} to {MAX_FPS:g} (default: 10; lecture: 15)",
    )
    p.add_argument(
        "--frames",
        type=bounded(int, 1, MAX_FRAMES),
        default=120,
        metavar="N",
        help=f"frames of one turn, for --kind sweep and orientation, 1 to {MAX_FRAMES} "
        "(default: 120)",
    )
    p.add_argument(
        "--frames-per-step",
        type=bounded(int, 1, MAX_FRAMES_PER_STEP),
        default=None,
        metavar="N",
        help="frames drawing each protocol step, for --kind "
        f"construction, 1 to {MAX_FRAMES_PER_STEP} (default: 8; "
        "lecture: 12)",
    )
    seconds = bounded(float, 0, MAX_SECONDS)
    p.add_argument(
        "--pause",
        type=seconds,
        default=None,
        metavar="S",
        help="seconds resting on each key result (V1-V4, the circles, the "
        f"envelope), for --kind construction, 0 to {MAX_SECONDS:g} "
        "(default: 1; lecture: 3)",
    )
    p.add_argument(
        "--hold",
        type=seconds,
        default=None,
        metavar="S",
        help="seconds holding the finished diagram at the end, for --kind "
        f"construction, 0 to {MAX_SECONDS:g} (default: 3; lecture: 6, and "
        "long enough to read its caption)",
    )
    p.add_argument(
        "--zoom",
        type=seconds,
        default=None,
        metavar="S",
        help="seconds of each zoom after the hold on a crowd of points whose labels have "
        f"no room in the whole view, for --kind construction, 0 to {MAX_SECONDS:g} "
        "(default: 5; lecture: 8; 0: no zoom)",
    )
    p.add_argument(
        "--caption-seconds",
        type=seconds,
        default=None,
        metavar="S",
        help="least seconds each step's caption stays on screen (a still frame "
        f"makes up the time), for --kind construction, 0 to {MAX_SECONDS:g} "
        "(default: 2; lecture: 2.5, and 1 s per 15 characters)",
    )
    p.add_argument(
        "--break-points",
        action="store_true",
        help="for --kind construction: the finished diagram names the break points on "
        "the envelope too (each break point is named at its own step in any case)",
    )
    p.add_argument(
        "--circle",
        type=bounded(int, 1, 4),
        default=None,
        metavar="N",
        help="for --kind sweep: only the circle on O V_N, 1 to 4, with the foot "
        "H_N and its right angle (Thales, Fig. 3) (default: all four)",
    )
    p.add_argument(
        "--weight",
        type=bounded(float, MIN_WEIGHT, MAX_WEIGHT),
        default=1.0,
        metavar="W",
        help="weight of the object, for --kind orientation, "
        f"{MIN_WEIGHT:g} to {MAX_WEIGHT:g} (default: 1)",
    )
    p.add_argument(
        "--dpi",
        type=bounded(float, MIN_DPI, MAX_DPI),
        default=None,
        metavar="N",
        action=_Checked,
        help=f"resolution in dots per inch, {MIN_DPI:g} to {MAX_DPI:g}; pixels = "
        "inches x dpi (default: 80, 8x9 inches; lecture: 100, 12.8x7.2 "
        f"inches, and at least {MIN_LECTURE_DPI:g})",
    )
    p.add_argument(
        "--theme",
        choices=("default", "paper"),
        default="default",
        help="colour theme (default: default)",
    )
    quiet_option(p, "print nothing but errors (no progress bar)")
    return p


def run(args: argparse.Namespace, grasp: Grasp | Callable[[], Grasp]) -> int:
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
    from ..boundary._output import check_target, writing
    from ..render.timeline import check_output

    stem = _file.output_stem(args, args.preset)
    name = args.output if args.output is not None else f"{stem}-{args.kind}.gif"
    check_output(name)
    path = check_target(name)
    from ..boundary.errors import InputTooLargeError
    from ..render.anim_physics import animate_orientation, animate_sweep
    from ..render.animate import animate_construction
    from ..render.theme import QUALITIES, THEMES

    quiet = getattr(args, "quiet", False)
    q = QUALITIES[getattr(args, "quality", "standard")]
    fps = q.fps if getattr(args, "fps", None) is None else args.fps
    dpi = q.dpi if getattr(args, "dpi", None) is None else args.dpi
    theme = THEMES[args.theme]
    made = _file.construction(args, grasp if callable(grasp) else lambda: grasp)
    if args.kind != "construction":
        _file.paper_only(made, f"animate --kind {args.kind}")
    c = made.construction
    anim: Any
    if args.kind == "construction":
        pause, hold = getattr(args, "pause", None), getattr(args, "hold", None)
        anim = animate_construction(
            c,
            fps=fps,
            frames_per_step=getattr(args, "frames_per_step", None),
            theme=theme,
            dpi=dpi,
            quality=q,
            pause_frames=None if pause is None else q.frames(pause, fps),
            hold_frames=None if hold is None else q.frames(hold, fps),
            caption_seconds=getattr(args, "caption_seconds", None),
            inset_seconds=getattr(args, "zoom", None),
            break_points=getattr(args, "break_points", False),
        )
    else:
        look = theme.scaled(q.scale) if q.scale != 1 else theme
        if args.kind == "sweep":
            anim = animate_sweep(
                c,
                frames=args.frames,
                circle=getattr(args, "circle", None),
                fps=fps,
                dpi=dpi,
                figsize=q.sweep_figsize,
                theme=look,
            )
        else:
            anim = animate_orientation(
                c,
                weight=args.weight,
                frames=args.frames,
                fps=fps,
                dpi=dpi,
                figsize=q.sweep_figsize,
                theme=look,
            )
    width, height = anim.figure.get_size_inches() * anim.figure.dpi
    pixels = anim.drawn_frames * round(width) * round(height)  # a still repeats a frame
    if pixels > MAX_PIXELS:
        raise InputTooLargeError(
            f"the animation would draw {anim.drawn_frames} frames of {round(width)}×"
            f"{round(height)} pixels ({pixels:.2e} in all); at most {MAX_PIXELS:.0e}: lower "
            "--dpi or --frames"
        )
    if anim.frame_count > MAX_ANIMATION_FRAMES:
        raise InputTooLargeError(
            f"the animation would have {anim.frame_count} frames; at most "
            f"{MAX_ANIMATION_FRAMES}: lower --fps, --hold, --zoom, --pause, --caption-seconds, "
            "--frames-per-step or --frames"
        )
    with writing(path):
        anim.save(path, fps=fps, quiet=quiet)
    if not quiet:
        print(
            f"wrote {path} ({anim.frame_count} frames of {round(width)}×{round(height)} "
            f"pixels at {fps:g} fps, {anim.frame_count / fps:.1f} s)"
        )
    return 0


def main_animation(construction: Construction) -> ConstructionAnimation:
    """The main job's construction animation of ``construction`` (not yet written).

    The standard quality: 8 frames per step at 10 fps, :data:`MAIN_FIGSIZE` inches at
    :data:`MAIN_DPI` dpi: 640 × 720 pixels, the captions laid out whole under the diagram,
    the camera following the step and, after the hold, zooming on each crowd of points.
    """
    from ..render.animate import animate_construction

    return animate_construction(construction, figsize=MAIN_FIGSIZE, dpi=MAIN_DPI)


def write_main_animation(
    construction: Construction, out_dir: str | Path, quiet: bool = False
) -> Path:
    """Write :func:`main_animation` of ``construction`` to ``out_dir/fig6-construction.gif``."""
    return main_animation(construction).save(Path(out_dir) / MAIN_ANIMATION, quiet=quiet)
