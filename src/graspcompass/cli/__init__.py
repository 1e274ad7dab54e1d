"""Command line: ``graspcompass [draw|steps|k|presets] ...``.

With no sub-command, runs the main job on the paper's Fig. 6 grasp: replays
the construction, writes the diagram to ``./graspcompass-out/`` and prints the
protocol with exact coordinates.

Exit statuses (:data:`EXIT_STATUSES`): 0 done; 1 a check found a problem
(``verify``, ``crosscheck``, ``check``: refuted); 2 a user error: a bad option
or value, an input refused, an output that cannot be written, with one line on
stderr and never a traceback; 3 undecided (``check``: a claim neither proved
nor refuted, or ``--timeout`` reached); 4 an internal error (a bug), also one
line (``GRASPCOMPASS_DEBUG=1`` shows the traceback); 130 interrupted.  Every
option value is checked before any work starts, and every output path before
anything is computed: a missing folder is refused (only the main job's
``--out`` folder itself is made, and it says so).
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import sys
import textwrap
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from .._version import __version__
from ..boundary import limits
from ..boundary._output import check_folder, check_target, writing
from ..boundary.errors import GraspCompassError, OutputError
from ..presets import PRESETS
from . import _check, _crosscheck, _export, _file, _plan, _recipe, _size, _verify, _worksheet
from ._animate import MAIN_ANIMATION, quiet_option, write_main_animation
from ._animate import register as _register_animate
from ._common import (  # noqa: F401  (MAX_MESSAGE: cli's names of before the split)
    MAX_MESSAGE,
    TIMED,
    _add_grasp_options,
    _add_timeout,
    _Parser,
    grasp_from_args,
    one_line,
    protocol_table,
)
from ._crosscheck import CROSSCHECK_GRASPS, CROSSCHECK_RUNS, CROSSCHECK_THETAS  # noqa: F401

if TYPE_CHECKING:  # the model (sympy, numpy) is loaded by the commands that use it
    from ..construction import Construction

__all__ = ["EXIT_STATUSES", "build_parser", "console", "grasp_from_args", "main"]

#: What each exit status of ``graspcompass`` means.
EXIT_STATUSES = {
    0: "done",
    1: "a check found a problem (verify, crosscheck; check: a claim refuted)",
    2: "a user error: a bad option or value, an input refused, an output that cannot be "
    "written (one line on stderr)",
    3: "undecided (check: a claim neither proved nor refuted, or --timeout reached)",
    4: "an internal error, a bug (one line on stderr; GRASPCOMPASS_DEBUG=1 shows the traceback)",
    130: "interrupted",
}
_FORMATS = ("png", "svg", "pdf")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``graspcompass`` command."""
    p = _Parser(
        prog="graspcompass",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=(
            "Ruler-and-compass internal force diagram of a two-point grasp "
            "(Ito, Tanaka, Sasaki, Robotica 2012). Without a command: the main job on "
            "the paper's Fig. 6 grasp."
        ),
        epilog="exit status:\n"
        + "\n".join(
            textwrap.fill(v, 78, initial_indent=f"  {k:<4} ", subsequent_indent=" " * 7)
            for k, v in EXIT_STATUSES.items()
        )
        + "\n\n"
        + textwrap.fill(
            "outputs: every option value and output path is checked before any work; a "
            "missing folder is refused (only the main job's --out folder itself is made, and "
            "it says so).",
            78,
        ),
    )
    p.add_argument("--version", action="version", version=f"graspcompass {__version__}")
    p.add_argument(
        "--out",
        default="graspcompass-out",
        metavar="DIR",
        help="output folder of the main job (default: ./graspcompass-out; made if "
        "missing, in an existing folder)",
    )
    p.add_argument(
        "-q", "--quiet", action="store_true", default=False, help="print nothing but errors"
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    d = sub.add_parser(
        "draw",
        help="draw the diagram to a PNG, SVG or PDF file",
        description="Draw the internal force diagram (Fig. 6): the friction cones, the "
        "construction of V1-V4 (§3.3), the four circles and their outer envelope, "
        "with the computer plot of k_grasp over the paper's recipe; or the "
        "drawing of a construction file, or the state after one step.",
        epilog="exit status: 0, or 2 for a user error.",
    )
    _add_grasp_options(d)
    _file.add_file_options(d)
    d.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="output file, in an existing folder (default: PRESET.png, or the "
        "construction file's name with .png)",
    )
    d.add_argument("--format", choices=_FORMATS, help="file format (default: from the extension)")
    d.add_argument(
        "--step",
        type=int,
        metavar="N",
        help="draw the state after protocol step N (default: the whole diagram)",
    )
    d.add_argument(
        "--no-overlay",
        action="store_true",
        help="leave out the computer plot of k_grasp (Fig. 6(b); drawn only over "
        "the paper's recipe)",
    )
    d.add_argument(
        "--break-points",
        action="store_true",
        help="label the break points B12...B34 that lie on the envelope (default: "
        "small unlabelled markers)",
    )
    quiet_option(d)
    from ._ncontact import add_options as _add_ncontact_draw

    _add_ncontact_draw(d)

    s = sub.add_parser(
        "steps",
        help="print the construction protocol",
        description="Print the construction protocol of §3.3 (or of a construction file): "
        "each step's name, instrument, the paper's reference and its exact value.",
        epilog="exit status: 0, or 2 for a user error.",
    )
    _add_grasp_options(s)
    _file.add_file_options(s)
    s.add_argument("--json", action="store_true", help="print the steps as JSON")
    from ._ncontact import add_options as _add_ncontact_steps

    _add_ncontact_steps(s)

    k = sub.add_parser(
        "k",
        help="k_n(θ), k_grasp(θ) and F_int (eqs. (17)-(25))",
        description="k_n(θ), k_grasp(θ) and F_int for a list of directions θ of the external "
        "force.",
        epilog=f"limits: --theta is at most {limits.MAX_LIST_LENGTH} characters and gives at "
        f"most {limits.MAX_ANGLES} angles. Up to {limits.EXACT_ANGLES} angles are read "
        "exactly (the θ column shows pi/6); more are made in double precision from the "
        "exact start and step of each range (a note on stderr says so) and the rows "
        f"stream out as they are computed. --exact: at most {limits.EXACT_VALUES} "
        "angles. Values that overflow a double (above 1.8e308) are refused. "
        "exit status: 0, or 2 for a user error.",
    )
    _add_grasp_options(k)
    k.add_argument(
        "--theta",
        default="0:360:30deg",
        metavar="ANGLES",
        help="angles: a list and/or ranges start:stop:step (stop excluded), radians "
        "unless suffixed with deg (default: 0:360:30deg)",
    )
    k.add_argument(
        "--external-force",
        default="1",
        metavar="EXPR",
        help="magnitude F_e of the external force, finite and >= 0 (default: 1)",
    )
    k.add_argument(
        "--exact",
        action="store_true",
        help=f"also print exact values (at most {limits.EXACT_VALUES} angles)",
    )
    k.add_argument("--json", action="store_true", help="print JSON")
    from ._ncontact import add_options as _add_ncontact

    _add_ncontact(k)

    sub.add_parser(
        "presets",
        help="list the built-in grasps of the paper",
        description="List the built-in grasps of the paper (Fig. 6, Table I "
        "(a)-(c)), for --preset.",
    )
    _register_animate(sub, _add_grasp_options)
    _export.register(sub, _add_grasp_options)
    _worksheet.register(sub, _add_grasp_options)
    _recipe.register(sub, _add_grasp_options)
    _check.register(sub, _add_grasp_options)
    _size.register(sub, _add_grasp_options)
    _plan.register(sub, _add_grasp_options)

    _verify.register(sub, _add_grasp_options)
    _crosscheck.register(sub)
    for name in TIMED:
        _add_timeout(sub.choices[name])
    _add_timeout(
        sub.choices["explore"],
        "until the window opens (reading a file, the first "
        "drawing); the window itself stays open as long as you like",
    )
    return p


def _draw(
    c: Construction,
    path: Path,
    fmt: str | None,
    step: int | None,
    overlay: bool,
    title: str | None = None,
    break_points: bool = False,
) -> Path:
    from ..render import figure_diagram, save_figure

    fig = figure_diagram(c, step=step, overlay=overlay, title=title, break_points=break_points)
    save_figure(fig, path, format=fmt)
    return path


def _out_folder(text: str, quiet: bool) -> Path:
    """The main job's ``--out`` folder: made if missing (its parent must exist), and said so."""
    out = Path(text)
    if not text.strip() or "\0" in text:
        raise OutputError(f"--out {text!r} is not a folder name")
    try:
        exists = out.exists()
    except OSError as exc:
        raise OutputError(f"cannot use the folder {text!r}: {exc.strerror or exc}") from None
    if not exists:
        check_folder(out.parent, out)
        with writing(out):
            out.mkdir()
        if not quiet:
            print(f"made the folder {str(out)!r}")
    return check_folder(out)


def _cmd_main(args: argparse.Namespace) -> int:
    out = _out_folder(args.out, args.quiet)
    png, svg, steps, gif = (
        check_target(out / name)
        for name in ("fig6-diagram.png", "fig6-diagram.svg", "fig6-steps.json", MAIN_ANIMATION)
    )
    from ..construction import internal_force_diagram, to_records
    from ..grasp import Grasp

    grasp = Grasp.preset("fig6")
    c = internal_force_diagram(grasp)
    _draw(c, png, None, None, True)
    _draw(c, svg, None, None, True)
    with writing(steps):
        steps.write_text(json.dumps(to_records(c), indent=1) + "\n")
    if not args.quiet:
        print(f"{grasp.title}\n")
        print(protocol_table(c))
    with writing(gif):
        write_main_animation(c, out, args.quiet)
    if not args.quiet:
        print(f"\nwrote {png}, {svg}, {steps} and {gif}")
    return 0


def _cmd_draw(args: argparse.Namespace) -> int:
    from . import _ncontact

    if _ncontact.wants_contacts(args) and args.step is None:
        return _ncontact.draw(args)
    stem = (
        "ncontact-steps" if _ncontact.wants_contacts(args) else _file.output_stem(args, args.preset)
    )
    name = args.output if args.output is not None else f"{stem}.{args.format or 'png'}"
    fmt = args.format
    if fmt is None and Path(name).suffix.lower().lstrip(".") not in _FORMATS:
        raise ValueError(
            f"cannot tell the format of {name!r}: use a .png, .svg or .pdf file name or --format"
        )
    path = check_target(name)
    made = _file.construction(args, lambda: grasp_from_args(args))
    c = made.construction
    if args.step is not None and not 0 <= args.step < len(c):
        raise ValueError(
            f"--step {args.step} is out of range: the protocol has {len(c)} "
            f"steps, 0 to {len(c) - 1}"
        )
    title = (
        None
        if made.paper
        else Path(made.shown).name
        + (f": {c.grasp.title}" if getattr(c.grasp, "title", None) else "")
    )
    bp = getattr(args, "break_points", False)
    _draw(c, path, fmt, args.step, made.paper and not args.no_overlay, title, bp)
    if not args.quiet:
        print(f"wrote {path}")
    return 0


def _cmd_steps(args: argparse.Namespace) -> int:
    from ..construction import to_records

    c = _file.construction(args, lambda: grasp_from_args(args)).construction
    if args.json:
        print(json.dumps(to_records(c), indent=1))
    else:
        print(protocol_table(c))
    return 0


def _cmd_k(args: argparse.Namespace) -> int:
    from . import _k, _ncontact

    if _ncontact.wants_contacts(args):
        return _ncontact.run(args)
    return _k.run(args, lambda: grasp_from_args(args))


def _cmd_presets(args: argparse.Namespace) -> int:
    for name, p in PRESETS.items():
        print(f"{name:8}  {p['title']}")
    return 0


def _cmd_animate(args: argparse.Namespace) -> int:
    from ._animate import run

    return run(args, lambda: grasp_from_args(args))


def _cmd_export(args: argparse.Namespace) -> int:
    return _export.run_export(args, lambda: grasp_from_args(args))


def _cmd_explore(args: argparse.Namespace) -> int:
    return _export.run_explore(args, grasp_from_args(args))


_COMMANDS = {
    None: _cmd_main,
    "draw": _cmd_draw,
    "steps": _cmd_steps,
    "k": _cmd_k,
    "presets": _cmd_presets,
    "animate": _cmd_animate,
    "verify": _verify.run,
    "crosscheck": _crosscheck.run,
    "export": _cmd_export,
    "explore": _cmd_explore,
    "worksheet": _worksheet.run,
    "recipe": _recipe.run,
    "check": _check.run,
    "size": _size.run,
    "plan": _plan.run,
}


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (see :data:`EXIT_STATUSES`).

    Never raises: argparse's exits (``--help``, a usage error) come back as
    their status, and a user error (a :class:`ValueError`, which includes every
    :class:`~graspcompass.errors.GraspCompassError`, or an :class:`OSError`) is
    one line on stderr and status 2.  Anything else is a bug: one line and
    status 4 (``GRASPCOMPASS_DEBUG=1`` re-raises it, with the traceback); status 3
    is ``check``'s "undecided".
    """
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else 2
    from ..boundary._deadline import OutOfTime, command_deadline

    alarm = command_deadline(getattr(args, "timeout", None) if args.command in TIMED else None)
    try:
        with warnings.catch_warnings(), alarm:
            warnings.simplefilter("ignore", SyntaxWarning)  # from text the parser refuses
            return _COMMANDS[args.command](args)
    except OutOfTime as exc:
        print(f"graspcompass: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. piped into head: stop quietly
        _silence_stdout()
        return 0
    except KeyboardInterrupt:
        print("graspcompass: interrupted", file=sys.stderr)
        return 130
    except (GraspCompassError, ValueError, OSError) as exc:
        if os.environ.get("GRASPCOMPASS_DEBUG"):
            raise
        print(f"graspcompass: error: {_message(exc)}", file=sys.stderr)
        return 2
    except Exception as exc:  # a bug: one line, not a traceback
        if os.environ.get("GRASPCOMPASS_DEBUG"):
            raise
        print(
            f"graspcompass: internal error: {type(exc).__name__}: {_message(exc)} (a bug; "
            "please report it with the command line)",
            file=sys.stderr,
        )
        return 4


def console() -> NoReturn:
    """The ``graspcompass`` program: :func:`main` on ``sys.argv``, then exit with its status.

    Before exiting it freezes the garbage collector (:func:`gc.freeze`): the
    interpreter's teardown would otherwise scan the millions of objects that
    sympy makes at import, which takes about 0.3 s and frees nothing a process
    about to end needs freed.
    """
    status = main()
    gc.freeze()
    sys.exit(status)


def _message(exc: BaseException) -> str:
    if isinstance(exc, OSError) and not isinstance(exc, GraspCompassError) and exc.strerror:
        where = f"{str(exc.filename)!r}: " if exc.filename else ""
        return one_line(f"{where}{exc.strerror}")
    return one_line(str(exc)) or type(exc).__name__


def _silence_stdout() -> None:
    """Point stdout at /dev/null so that Python's flush at exit does not complain."""
    try:
        sys.stdout.flush()
    except (OSError, ValueError):
        pass
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # stdout without a file descriptor
        pass


if __name__ == "__main__":  # pragma: no cover
    console()
