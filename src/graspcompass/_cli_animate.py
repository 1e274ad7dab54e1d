"""The ``graspcompass animate`` sub-command and the main job's construction animation.

``graspcompass animate [PRESET] [grasp options] --kind construction|sweep|orientation
-o FILE.gif|.mp4|.html [--fps N]`` writes one of the animations of
:mod:`graspcompass.render.animate`: the ruler-and-compass construction of §3.3
step by step, the external force sweeping round (Fig. 3), or the object
turning under gravity (Fig. 1).  matplotlib is imported only when it runs.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import Any

from .grasp import PRESETS

__all__ = ["KINDS", "MAIN_ANIMATION", "register", "run", "write_main_animation"]

#: The kinds of animation.
KINDS = ("construction", "sweep", "orientation")
#: File name of the main job's animation.
MAIN_ANIMATION = "fig6-construction.gif"


def _positive(kind: type) -> Callable[[str], Any]:
    def parse(text: str) -> Any:
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a positive number, got {text!r}") from None
        if not value > 0:
            raise argparse.ArgumentTypeError(f"must be a positive number, got {text!r}")
        return value

    parse.__name__ = kind.__name__
    return parse


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
                    "under gravity (Fig. 1), as GIF, MP4 (needs ffmpeg) or HTML.")
    p.add_argument("preset", nargs="?", type=_preset, default=argparse.SUPPRESS,
                   metavar="PRESET", help=f"a preset ({', '.join(sorted(PRESETS))}); same as "
                                          "--preset")
    add_grasp_options(p)
    p.add_argument("--kind", choices=KINDS, default="construction",
                   help="what to animate (default: construction)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="output .gif, .mp4 or .html file (default: PRESET-KIND.gif)")
    p.add_argument("--fps", type=_positive(float), default=20.0, metavar="N",
                   help="frames per second (default: 20)")
    p.add_argument("--frames", type=_positive(int), default=120, metavar="N",
                   help="frames of one turn, for --kind sweep and orientation (default: 120)")
    p.add_argument("--frames-per-step", type=_positive(int), default=8, metavar="N",
                   help="frames drawing each protocol step, for --kind construction "
                        "(default: 8)")
    p.add_argument("--weight", type=_positive(float), default=1.0, metavar="W",
                   help="weight of the object, for --kind orientation (default: 1)")
    p.add_argument("--dpi", type=_positive(float), default=80.0, metavar="N",
                   help="resolution (default: 80)")
    p.add_argument("--theme", choices=("default", "paper"), default="default",
                   help="colour theme (default: default)")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="print nothing but errors (no progress bar)")
    return p


def run(args: argparse.Namespace, grasp: Any) -> int:
    """Run ``graspcompass animate`` for ``grasp``; returns the exit status.

    Raises
    ------
    ValueError
        :class:`~graspcompass.render.timeline.UnsupportedFormatError` for an
        unknown extension, :class:`~graspcompass.render.timeline.FFmpegNotFoundError`
        for ``.mp4`` without ffmpeg, and the errors of the grasp and the construction;
        the command line prints them on one line.
    """
    from .construction import internal_force_diagram
    from .render.anim_physics import animate_orientation, animate_sweep
    from .render.animate import animate_construction
    from .render.theme import THEMES
    from .render.timeline import check_output

    path = Path(args.output or f"{args.preset}-{args.kind}.gif")
    check_output(path)
    theme = THEMES[args.theme]
    c = internal_force_diagram(grasp)
    anim: Any
    if args.kind == "construction":
        anim = animate_construction(c, fps=args.fps, frames_per_step=args.frames_per_step,
                                    theme=theme, dpi=args.dpi)
    elif args.kind == "sweep":
        anim = animate_sweep(c, frames=args.frames, fps=args.fps, theme=theme, dpi=args.dpi)
    else:
        anim = animate_orientation(c, weight=args.weight, frames=args.frames, fps=args.fps,
                                   theme=theme, dpi=args.dpi)
    anim.save(path, fps=args.fps, quiet=args.quiet)
    if not args.quiet:
        print(f"wrote {path} ({anim.frame_count} frames at {args.fps:g} fps)")
    return 0


def write_main_animation(construction: Any, out_dir: str | Path, quiet: bool = False) -> Path:
    """Write the construction animation of ``construction`` to ``out_dir/fig6-construction.gif``.

    Small and fast for the main job: 8 frames per step at 20 fps, 4.5 × 5 inches at 64 dpi.
    """
    from .render.animate import animate_construction

    anim = animate_construction(construction, figsize=(4.5, 5.0), dpi=64)
    return anim.save(Path(out_dir) / MAIN_ANIMATION, quiet=quiet)
