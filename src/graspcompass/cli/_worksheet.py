"""The ``worksheet`` sub-command of the command line.

``graspcompass worksheet -o FILE.pdf`` writes a printable worksheet for
drawing the internal force diagram by hand (§3.3 of Ito, Tanaka, Sasaki,
Robotica 2012): page 1 the grasp and its friction cones at a stated scale
with the steps as numbered instructions, page 2 the solution at the same
scale (:func:`graspcompass.render.handdrawing.worksheet`).  The module only adds
the sub-parser and runs it; :mod:`graspcompass.cli` reports errors (a
``ValueError`` is one line on stderr, exit status 2).

Examples
--------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="graspcompass")
>>> sub = parser.add_subparsers(dest="command")
>>> register(sub, lambda p: p.add_argument("--preset", default="fig6"))
>>> args = parser.parse_args(["worksheet", "--steps", "V2", "--scale", "20"])
>>> args.steps, args.scale, args.given
('V2', 20.0, 'grasp')
"""

from __future__ import annotations

import argparse
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["register", "run"]

_STEPS = ("all", "V1", "V2", "V3", "V4")
_LEVELS = ("grasp", "feet", "sides", "perpendiculars")
#: Bounds of ``--scale`` in mm per unit (as :data:`graspcompass.render.handdrawing.SCALE_RANGE`).
SCALE_MIN, SCALE_MAX = 1e-6, 1e6
#: Longest ``--given`` text.
MAX_GIVEN = 200


def _scale(text: str) -> float:
    """An argparse ``type``: millimetres per unit, a finite number in the allowed range."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected millimetres per unit, a number such as 40, got {text[:40]!r}"
        ) from None
    if not (math.isfinite(value) and SCALE_MIN <= value <= SCALE_MAX):
        raise argparse.ArgumentTypeError(
            f"the scale is from {SCALE_MIN:g} to {SCALE_MAX:g} mm per unit, got {text[:40]!r}"
        )
    return value


def _given(text: str) -> str:
    """An argparse ``type``: a level name or step names separated by commas."""
    if len(text) > MAX_GIVEN:
        raise argparse.ArgumentTypeError(f"at most {MAX_GIVEN} characters, got {len(text)}")
    if text.strip() in _LEVELS:
        return text.strip()
    names = [t.strip() for t in text.split(",")]
    if not names or not all(re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]{0,15}", n) for n in names):
        raise argparse.ArgumentTypeError(
            f"expected one of {', '.join(_LEVELS)} or step names separated by commas (as "
            f"graspcompass steps prints them, e.g. P1x,P2x,O_M,X1), got {text[:40]!r}"
        )
    return ",".join(names)


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``worksheet`` sub-command to ``subparsers``.

    ``add_grasp_options`` adds the common ``--preset`` and parameter options.
    """
    w = subparsers.add_parser(
        "worksheet",
        help="a printable PDF worksheet: draw the diagram by hand",
        description="Write a two-page A4 PDF: page 1 the grasp with its friction cones at a "
        "stated scale, with room to draw and the steps of §3.3 as numbered "
        "instructions (numbered as graspcompass steps prints them); page 2 the "
        "solution at the same scale, with the signed lengths to check.",
        epilog="--given: grasp (O, the axes, P1, P2, the cones), feet (also P1x, P2x, O_M), "
        "sides (also the extended cone sides and X_n), perpendiculars (also the "
        "perpendiculars and Y_n), or step names such as P1x,P2x,O_M. "
        "The folder of -o must exist; the path is checked before any work. "
        "exit status: 0, or 2 for a user error.",
    )
    add_grasp_options(w)
    w.add_argument(
        "-o",
        "--output",
        metavar="FILE.pdf",
        help="output file (default: PRESET-worksheet.pdf in the current folder)",
    )
    w.add_argument(
        "--steps",
        choices=_STEPS,
        default="all",
        help="instructions for every step or for one V_n (default: all)",
    )
    w.add_argument(
        "--given",
        type=_given,
        default="grasp",
        metavar="WHAT",
        help=f"what page 1 already shows: {', '.join(_LEVELS)}, or step names "
        "separated by commas (default: grasp)",
    )
    w.add_argument(
        "--scale",
        type=_scale,
        metavar="MM_PER_UNIT",
        help="millimetres on paper per unit of the grasp (default: the largest "
        "round value that fits the page, whole mm from 10 mm up)",
    )
    w.add_argument(
        "-q",
        "--quiet",
        action="store_true",
        default=argparse.SUPPRESS,
        help="print nothing but errors",
    )


def run(args: argparse.Namespace, grasp: Grasp | None = None) -> int:
    """Run ``graspcompass worksheet``; returns the exit status (0).

    ``grasp`` defaults to the one the common options name
    (:func:`graspcompass.cli.grasp_from_args`).

    Raises
    ------
    ValueError
        For an output name that is not a ``.pdf``, a bad ``--given``, or a
        ``--scale`` at which the drawing does not fit the page;
        :class:`~graspcompass.errors.OutputError` for a path that cannot be
        written (checked before any work).
    """
    from ..boundary._output import check_target, writing

    name = args.output if args.output is not None else f"{args.preset}-worksheet.pdf"
    if Path(name).suffix.lower() != ".pdf":
        raise ValueError(f"a worksheet is a PDF: name the output FILE.pdf, got {name!r}")
    path = check_target(name)
    from ..construction import internal_force_diagram
    from ..render.handdrawing import worksheet_pages

    if grasp is None:
        from ._common import grasp_from_args

        grasp = grasp_from_args(args)
    ws = worksheet_pages(
        internal_force_diagram(grasp), steps=args.steps, given=args.given, scale=args.scale
    )
    with writing(path):
        ws.save(path)
    if not getattr(args, "quiet", False):
        print(f"wrote {path} (2 A4 pages; steps {args.steps}; 1 unit = {ws.scale:g} mm)")
    return 0
