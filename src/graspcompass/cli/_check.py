"""The ``check`` sub-command: prove a construction file's steps and claims, grade it.

``graspcompass check FILE`` parses a file of the construction language
(``docs/language.md``), replays it with symbolic parameters, certifies every
step, proves every claim (:func:`graspcompass.proof.program_check.check_program`)
and prints a table; ``--json`` and ``--markdown FILE`` write the same report
for other tools and for the docs.  ``--against paper`` also grades every object
named like a point of the paper (X_n, Y_n, V_n, the circles, O_M, P1x, P2x) and
``--draw OUT.png`` draws the first refuted one at its counterexample next to
the paper's.  Exit status: 0 all proved, 1 something refuted, 3 something
undecided, 2 a usage or parse error (one line on stderr).

The module imports nothing heavy at its top: the file and the outputs are
checked before sympy is loaded.

Examples
--------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="graspcompass")
>>> sub = parser.add_subparsers(dest="command")
>>> register(sub, lambda p: None)
>>> args = parser.parse_args(["check", "mine.gc", "--against", "paper", "--json"])
>>> args.file, args.against, args.json
('mine.gc', 'paper', True)
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["DEFAULT_TIMEOUT", "MAX_FILE_BYTES", "CheckTimeout", "read_file", "register", "run"]

#: Largest construction file read (bytes).
MAX_FILE_BYTES = 1_000_000
#: Default bound on the time of one check (seconds).
DEFAULT_TIMEOUT = 600.0


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number of seconds, got {text!r}") from None
    if not 1 <= value <= 86_400:
        raise argparse.ArgumentTypeError(f"must be from 1 to 86400 seconds, got {text!r}")
    return value


class CheckTimeout(BaseException):
    """The check ran out of time: nothing is decided (exit status 3).  A
    :class:`BaseException`, like :class:`KeyboardInterrupt`, so that no
    ``except Exception`` on the way can swallow it."""


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``check`` sub-command (``add_grasp_options`` is not used: a file has its
    own parameters)."""
    del add_grasp_options
    c = subparsers.add_parser(
        "check",
        help="prove a construction file's steps and claims; grade it against the paper",
        description="Replay a file of the construction language (docs/language.md) with "
        "symbolic parameters, certify every step, prove every claim for all "
        "admissible parameters and print a table: status, hypotheses, "
        "non-degeneracy conditions, time. PROVED is an exact argument; REFUTED "
        "comes with a counterexample, a point of the model at which the file, "
        "replayed exactly, contradicts the statement.",
        epilog="exit status: 0 all proved, 1 something refuted, 3 something undecided, 2 a "
        f"usage or parse error. A file is at most {MAX_FILE_BYTES} bytes.",
    )
    c.add_argument("file", metavar="FILE", help="the construction file ('-' reads stdin)")
    c.add_argument(
        "--against",
        choices=["paper"],
        help="also prove that each object named like a point of the paper (X1..X4, "
        "Y1..Y4, V1..V4, circle1..circle4, O_M, P1x, P2x) is the paper's, for "
        "every grasp satisfying condition (1)",
    )
    c.add_argument("--json", action="store_true", help="print the report as JSON")
    c.add_argument("--markdown", metavar="FILE.md", help="also write the report as Markdown")
    c.add_argument(
        "--draw",
        metavar="OUT.png",
        help="draw the first refuted object at its counterexample, the file's and "
        "the paper's side by side (PNG, SVG or PDF)",
    )
    c.add_argument(
        "--steps",
        action="store_true",
        help="list every step in the table (default: only the steps not proved)",
    )
    c.add_argument(
        "--timeout",
        type=_seconds,
        default=DEFAULT_TIMEOUT,
        metavar="S",
        help=f"stop after S seconds (default {DEFAULT_TIMEOUT:g}; a file can make the "
        "symbolic replay arbitrarily long): the verdicts reached by then are "
        "kept, the rest are UNDECIDED (timed out, exit status 3)",
    )
    c.add_argument(
        "-q", "--quiet", action="store_true", default=argparse.SUPPRESS, help="no progress bar"
    )


def read_file(name: str) -> tuple[str, str]:
    """``(text, name shown in messages)`` of a construction file, bounded in size.

    Raises
    ------
    graspcompass.errors.InputTooLargeError
        Beyond :data:`MAX_FILE_BYTES`.
    graspcompass.errors.InputError
        A file that cannot be read, or is not UTF-8 text.
    """
    from ..boundary._infiles import read_bounded
    from ..boundary.errors import InputError

    data = read_bounded(name, MAX_FILE_BYTES)
    try:
        return data.decode("utf-8"), "<stdin>" if name == "-" else name
    except UnicodeDecodeError as exc:
        raise InputError(f"{name!r} is not UTF-8 text (byte {exc.start})") from None


def _draw(program: Any, report: Any, path: Path) -> str:
    from ..render import save_figure
    from ..render.grading import figure_counterexample

    row = next(
        (r for r in (*report.targets, *report.claims) if r.kind == "target" and r.counterexample),
        None,
    )
    if row is None:
        return "nothing to draw: no object of the file was refuted against the paper"
    save_figure(figure_counterexample(program, row.name, row.counterexample), path)
    return f"drew {row.name} at its counterexample to {path}"


def run(args: argparse.Namespace) -> int:
    """Run ``graspcompass check``; returns the report's exit status (0, 1 or 3).

    A check that runs longer than ``--timeout`` seconds keeps the verdicts
    reached by then; the rest are UNDECIDED (timed out: one line on stderr, exit
    status 3 unless something is REFUTED).

    Raises
    ------
    ValueError
        A file that cannot be read or parsed
        (:class:`~graspcompass.construction.program.ConstructionSyntaxError`,
        ``FILE:LINE:COL: what``), an output that cannot be written, ``--draw``
        without ``--against paper``; the command line prints one line, exit 2.
    """
    from ..boundary._output import check_target, writing

    markdown = check_target(args.markdown) if args.markdown is not None else None
    draw = check_target(args.draw) if args.draw is not None else None
    if draw is not None:
        if args.against != "paper":
            raise ValueError(
                "--draw needs --against paper (it draws a refuted object next to the paper's)"
            )
        if draw.suffix.lower() not in (".png", ".svg", ".pdf"):
            raise ValueError(f"--draw writes .png, .svg or .pdf, got {str(draw)!r}")
    text, shown = read_file(args.file)
    from ..construction.language import parse
    from ..progress import Progress
    from ..proof._budget import TIMED_OUT
    from ..proof.program_check import check_program
    from ..proof.program_report import to_json, to_markdown, to_table

    program = parse(text, shown)
    quiet = getattr(args, "quiet", False) or args.json
    from ..boundary._deadline import deadline

    stop = args.timeout
    # the check keeps every verdict reached within --timeout; this alarm, a little
    # later, only stops a run that the check's own budget could not interrupt
    alarm = deadline(
        stop + max(5.0, stop / 10),
        lambda: CheckTimeout(f"the check took longer than {stop:g} s (--timeout)"),
    )
    bar_size = len(program.steps) + len(program.claims)
    try:
        with alarm, Progress(bar_size, "check", quiet=quiet) as bar:
            report = check_program(
                program,
                args.against,
                progress=lambda done, total, name: bar.update(note=name),
                timeout=stop,
            )
    except CheckTimeout as exc:
        print(f"graspcompass: {exc}: nothing decided", file=sys.stderr)
        return 3
    if markdown is not None:
        with writing(markdown):
            markdown.write_text(to_markdown(report), encoding="utf-8")
    print(to_json(report) if args.json else to_table(report, steps=args.steps))
    late = sum(r.result.method == TIMED_OUT for r in report.rows)
    if late:
        print(
            f"graspcompass: {late} of {len(report.rows)} rows timed out after {stop:g} s "
            "(--timeout): UNDECIDED; the other verdicts stand",
            file=sys.stderr,
        )
    if draw is not None:
        with writing(draw):
            note = _draw(program, report, draw)
        print(note, file=sys.stderr)
    return report.exit_status
