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
import contextlib
import gc
import json
import os
import sys
import textwrap
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn

from .. import __version__
from ..boundary import limits
from ..boundary._output import check_folder, check_target, writing
from ..boundary.errors import GraspCompassError, InputError, OutputError
from ..presets import PRESETS
from . import _check, _export, _file, _plan, _recipe, _size, _worksheet
from ._animate import MAIN_ANIMATION, bounded, quiet_option, write_main_animation
from ._animate import register as _register_animate

if TYPE_CHECKING:  # the model (sympy, numpy) is loaded by the commands that use it
    from ..construction import Construction
    from ..grasp import Grasp

__all__ = ["EXIT_STATUSES", "build_parser", "console", "grasp_from_args", "main"]

#: What each exit status of ``graspcompass`` means.
EXIT_STATUSES = {
    0: "done",
    1: "a check found a problem (verify, crosscheck; check: a claim refuted)",
    2: "a user error: a bad option or value, an input refused, an output that cannot be "
       "written (one line on stderr)",
    3: "undecided (check: a claim neither proved nor refuted, or --timeout reached)",
    4: "an internal error, a bug (one line on stderr; GRASPCOMPASS_DEBUG=1 shows the "
       "traceback)",
    130: "interrupted",
}
#: Bounds of ``crosscheck``: random grasps, θ grid size, and their product (linprog runs).
CROSSCHECK_GRASPS, CROSSCHECK_THETAS, CROSSCHECK_RUNS = 200, 3600, 36_000

_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")
_FORMATS = ("png", "svg", "pdf")


#: Longest error message printed (exact values can have thousands of digits).
MAX_MESSAGE = 400


def one_line(text: str, first: bool = True) -> str:
    """``text`` on one line, unprintable characters escaped, cut at :data:`MAX_MESSAGE`.

    Parameters
    ----------
    text : str
        A message.
    first : bool, optional
        Keep only the first line (exception messages); otherwise escape the
        line breaks too (argparse messages quoting the command line).
    """
    lines = text.strip().splitlines() if first else [text.strip()]
    line = "".join(c if c.isprintable() else repr(c)[1:-1] for c in (lines[0] if lines else ""))
    if len(line) > MAX_MESSAGE:
        line = f"{line[:MAX_MESSAGE - 40]} ... ({len(line)} characters in all)"
    return line


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2, no usage block).

    An option that takes a value also takes one that starts with ``-``:
    ``--p2 -50mm,0``, ``--phi1 -pi/4+pi`` and ``--x1 --`` read as
    ``--p2=-50mm,0``, ``--phi1=-pi/4+pi`` and ``--x1=--`` (plain argparse
    reads only negative numbers that way).  A value that is itself one of the
    command's options (``--output -q``) is left an option.
    """

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {one_line(message, first=False)} (see --help)\n")

    def parse_known_args(self, args: Sequence[str] | None = None,  # type: ignore[override]
                         namespace: argparse.Namespace | None = None
                         ) -> tuple[argparse.Namespace, list[str]]:
        argv = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(self._join_dash_values(argv), namespace)

    def _join_dash_values(self, argv: list[str]) -> list[str]:
        """``--opt -value`` as ``--opt=-value`` for this parser's one-value options."""
        takes_value = {s for s, a in self._option_string_actions.items()
                       if a.nargs is None and s.startswith("--")}
        nested = any(isinstance(a, argparse._SubParsersAction) for a in self._actions)
        out: list[str] = []
        i = 0
        while i < len(argv):
            token = argv[i]
            if token == "--" or (nested and not token.startswith("-")):
                return out + argv[i:]  # the rest belongs to positionals or a sub-command
            if token in takes_value and i + 1 < len(argv) and self._dash_value(argv[i + 1]):
                out.append(f"{token}={argv[i + 1]}")
                i += 2
                continue
            out.append(token)
            i += 1
        return out

    def _dash_value(self, token: str) -> bool:
        """Whether ``token`` is a value starting with ``-`` rather than an option."""
        if token == "--":
            return True
        if not token.startswith("-") or token.startswith("--") or len(token) < 2:
            return False
        return token[:2] not in self._option_string_actions

    def _get_values(self, action: argparse.Action, arg_strings: list[str]) -> Any:
        if action.option_strings and action.nargs is None and arg_strings == ["--"]:
            value = self._get_value(action, "--")  # argparse would drop it and give a list
            self._check_value(action, value)
            return value
        return super()._get_values(action, arg_strings)  # type: ignore[misc]


def _add_grasp_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group(
        "grasp", "a preset, optionally with parameters overridden; values are exact "
        "expressions such as sqrt(3)/2, pi/3, 60deg or 1.2 (= 6/5)")
    g.add_argument("--preset", default="fig6", choices=sorted(PRESETS),
                   help="start from one of the paper's examples (default: fig6)")
    for name in _PARAMS:
        g.add_argument(f"--{name}", metavar="EXPR", help=f"set {name}")


#: The commands that take ``--timeout`` (``check`` and ``verify`` have their own, which
#: keep the verdicts reached in time; ``explore`` is a window).
TIMED = ("draw", "steps", "k", "animate", "export", "worksheet", "size", "plan",
         "crosscheck")


def _seconds(text: str) -> float:
    from ._check import _seconds as check_seconds

    return check_seconds(text)


def _add_timeout(p: argparse.ArgumentParser) -> None:
    p.add_argument("--timeout", type=_seconds, default=limits.COMMAND_SECONDS, metavar="S",
                   help=f"stop after S seconds, 1 to 86400, with exit status 2 (default "
                        f"{limits.COMMAND_SECONDS:g}: a construction file or a value can make "
                        "the work arbitrarily long)")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``graspcompass`` command."""
    p = _Parser(
        prog="graspcompass", formatter_class=argparse.RawDescriptionHelpFormatter,
        description=(
            "Ruler-and-compass internal force diagram of a two-point grasp "
            "(Ito, Tanaka, Sasaki, Robotica 2012). Without a command: the main job on "
            "the paper's Fig. 6 grasp."),
        epilog="exit status:\n" + "\n".join(
            textwrap.fill(v, 78, initial_indent=f"  {k:<4} ", subsequent_indent=" " * 7)
            for k, v in EXIT_STATUSES.items())
        + "\n\n" + textwrap.fill(
            "outputs: every option value and output path is checked before any work; a "
            "missing folder is refused (only the main job's --out folder itself is made, and "
            "it says so).", 78))
    p.add_argument("--version", action="version", version=f"graspcompass {__version__}")
    p.add_argument("--out", default="graspcompass-out", metavar="DIR",
                   help="output folder of the main job (default: ./graspcompass-out; made if "
                        "missing, in an existing folder)")
    p.add_argument("-q", "--quiet", action="store_true", default=False,
                   help="print nothing but errors")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    d = sub.add_parser(
        "draw", help="draw the diagram to a PNG, SVG or PDF file",
        description="Draw the internal force diagram (Fig. 6): the friction cones, the "
                    "construction of V1-V4 (§3.3), the four circles and their outer envelope, "
                    "with the computer plot of k_grasp over the paper's recipe; or the "
                    "drawing of a construction file, or the state after one step.",
        epilog="exit status: 0, or 2 for a user error.")
    _add_grasp_options(d)
    _file.add_file_options(d)
    d.add_argument("-o", "--output", metavar="FILE",
                   help="output file, in an existing folder (default: PRESET.png, or the "
                        "construction file's name with .png)")
    d.add_argument("--format", choices=_FORMATS, help="file format (default: from the extension)")
    d.add_argument("--step", type=int, metavar="N",
                   help="draw the state after protocol step N (default: the whole diagram)")
    d.add_argument("--no-overlay", action="store_true",
                   help="leave out the computer plot of k_grasp (Fig. 6(b); drawn only over "
                        "the paper's recipe)")
    quiet_option(d)
    from ._ncontact import add_options as _add_ncontact_draw

    _add_ncontact_draw(d)

    s = sub.add_parser(
        "steps", help="print the construction protocol",
        description="Print the construction protocol of §3.3 (or of a construction file): "
                    "each step's name, instrument, the paper's reference and its exact value.",
        epilog="exit status: 0, or 2 for a user error.")
    _add_grasp_options(s)
    _file.add_file_options(s)
    s.add_argument("--json", action="store_true", help="print the steps as JSON")

    k = sub.add_parser(
        "k", help="k_n(θ), k_grasp(θ) and F_int (eqs. (17)-(25))",
        description="k_n(θ), k_grasp(θ) and F_int for a list of directions θ of the external "
                    "force.",
        epilog=f"limits: --theta is at most {limits.MAX_LIST_LENGTH} characters and gives at "
               f"most {limits.MAX_ANGLES} angles. Up to {limits.EXACT_ANGLES} angles are read "
               "exactly (the θ column shows pi/6); more are made in double precision from the "
               "exact start and step of each range (a note on stderr says so) and the rows "
               f"stream out as they are computed. --exact: at most {limits.EXACT_VALUES} "
               "angles. Values that overflow a double (above 1.8e308) are refused. "
               "exit status: 0, or 2 for a user error.")
    _add_grasp_options(k)
    k.add_argument("--theta", default="0:360:30deg", metavar="ANGLES",
                   help="angles: a list and/or ranges start:stop:step (stop excluded), radians "
                        "unless suffixed with deg (default: 0:360:30deg)")
    k.add_argument("--external-force", default="1", metavar="EXPR",
                   help="magnitude F_e of the external force, finite and >= 0 (default: 1)")
    k.add_argument("--exact", action="store_true",
                   help=f"also print exact values (at most {limits.EXACT_VALUES} angles)")
    k.add_argument("--json", action="store_true", help="print JSON")
    from ._ncontact import add_options as _add_ncontact

    _add_ncontact(k)

    sub.add_parser("presets", help="list the built-in grasps of the paper",
                   description="List the built-in grasps of the paper (Fig. 6, Table I "
                               "(a)-(c)), for --preset.")
    _register_animate(sub, _add_grasp_options)
    _export.register(sub, _add_grasp_options)
    _worksheet.register(sub, _add_grasp_options)
    _recipe.register(sub, _add_grasp_options)
    _check.register(sub, _add_grasp_options)
    _size.register(sub, _add_grasp_options)
    _plan.register(sub, _add_grasp_options)

    v = sub.add_parser(
        "verify", help="machine-check every claim of the paper (symbolic)",
        description="Check every claim of the paper for general symbolic parameters under "
        "condition (1) (and μ = tan ξ where both appear); print each claim's status, "
        "hypotheses and non-degeneracy conditions.",
        epilog="exit status: 0 when every claim is decided (none UNDECIDED) and every REFUTED "
        "claim names a correction that is PROVED (with --certify: and every construction "
        "step holds); 1 otherwise; 2 for a usage error.")
    v.add_argument("--json", action="store_true",
                   help="print the results as JSON (with hypotheses, conditions, certificates)")
    v.add_argument("--markdown", metavar="FILE",
                   help="write the report as a Markdown page (its folder must exist)")
    v.add_argument("--certify", action="store_true",
                   help="also certify the symbolic construction (every admissible grasp) and, "
                   "if grasp options are given, that grasp's construction")
    v.add_argument("--timeout", type=_check._seconds, default=None, metavar="S",
                   help="stop after S seconds for the whole run (catalogue and --certify; "
                        "default: no limit): the verdicts reached by then are kept, the rest "
                        "are UNDECIDED (timed out, exit status 1)")
    _add_grasp_options(v)
    quiet_option(v, "no progress bar")

    x = sub.add_parser(
        "crosscheck", help="closed form vs scipy linprog on random grasps",
        description="Compare the closed form k_grasp(θ) (eq. (25)) with the least internal "
                    "force found by scipy's linprog on random grasps and directions "
                    "(needs scipy: pip install 'graspcompass[crosscheck]').",
        epilog=f"limits: --grasps × --thetas at most {CROSSCHECK_RUNS} linprog problems. "
               "exit status: 0 when they agree to 1e-7, 1 otherwise, 2 for a usage error.")
    x.add_argument("--grasps", type=bounded(int, 1, CROSSCHECK_GRASPS), default=20,
                   metavar="N", help=f"random grasps, 1 to {CROSSCHECK_GRASPS} (20)")
    x.add_argument("--thetas", type=bounded(int, 1, CROSSCHECK_THETAS), default=36,
                   metavar="M", help=f"θ grid size, 1 to {CROSSCHECK_THETAS} (36)")
    x.add_argument("--seed", type=bounded(int, 0, 2**63 - 1), default=0,
                   help="random seed, 0 to 2**63 - 1 (0)")
    quiet_option(x, "no progress bar")
    for name in TIMED:
        _add_timeout(sub.choices[name])
    return p


def grasp_from_args(args: argparse.Namespace) -> Grasp:
    """The grasp named by ``--preset`` with any parameter options applied.

    Each option's text is read by the safe parser first, with the message the
    grasp would give: text the parser refuses is refused before the model
    (and numpy) is loaded.
    """
    from ..boundary.expr import ExpressionError, parse_exact

    given = {k: getattr(args, k) for k in _PARAMS if getattr(args, k, None) is not None}
    for name, text in given.items():
        try:
            parse_exact(text)
        except ExpressionError as exc:
            raise type(exc)(f"{name}: {exc}") from None
    from ..grasp import Grasp

    params: dict[str, Any] = dict(PRESETS[args.preset]["params"])
    for i in ("1", "2"):  # a given mu replaces the preset's xi and vice versa
        if f"mu{i}" in given:
            params.pop(f"xi{i}", None)
        if f"xi{i}" in given:
            params.pop(f"mu{i}", None)
    params.update(given)
    if not given:
        return Grasp.preset(args.preset)
    return Grasp(**params)


def protocol_table(c: Construction) -> str:
    """The protocol as a text table with exact values."""
    from ..construction import describe
    from ._k import table

    rows = [[str(s.index), s.name, s.instrument, s.ref, describe(s.obj)] for s in c.steps]
    return table(rows, ["#", "name", "instrument", "paper", "exact value"])


def _draw(c: Construction, path: Path, fmt: str | None, step: int | None,
          overlay: bool, title: str | None = None) -> Path:
    from ..render import figure_diagram, save_figure

    fig = figure_diagram(c, step=step, overlay=overlay, title=title)
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
    png, svg, steps, gif = (check_target(out / name) for name in (
        "fig6-diagram.png", "fig6-diagram.svg", "fig6-steps.json", MAIN_ANIMATION))
    from ..construction import internal_force_diagram, to_records
    from ..grasp import Grasp

    c = internal_force_diagram(Grasp.preset("fig6"))
    _draw(c, png, None, None, True)
    _draw(c, svg, None, None, True)
    with writing(steps):
        steps.write_text(json.dumps(to_records(c), indent=1) + "\n")
    if not args.quiet:
        print(f"{c.grasp.title}\n")
        print(protocol_table(c))
    with writing(gif):
        write_main_animation(c, out, args.quiet)
    if not args.quiet:
        print(f"\nwrote {png}, {svg}, {steps} and {gif}")
    return 0


def _cmd_draw(args: argparse.Namespace) -> int:
    if getattr(args, "contact", None):
        from . import _ncontact

        return _ncontact.draw(args)
    stem = _file.output_stem(args, args.preset)
    name = args.output if args.output is not None else f"{stem}.{args.format or 'png'}"
    fmt = args.format
    if fmt is None and Path(name).suffix.lower().lstrip(".") not in _FORMATS:
        raise ValueError(f"cannot tell the format of {name!r}: use a .png, .svg or .pdf "
                         "file name or --format")
    path = check_target(name)
    made = _file.construction(args, lambda: grasp_from_args(args))
    c = made.construction
    if args.step is not None and not 0 <= args.step < len(c):
        raise ValueError(f"--step {args.step} is out of range: the protocol has {len(c)} "
                         f"steps, 0 to {len(c) - 1}")
    title = None if made.paper else Path(made.shown).name + (
        f": {c.grasp.title}" if getattr(c.grasp, "title", None) else "")
    _draw(c, path, fmt, args.step, made.paper and not args.no_overlay, title)
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
    from . import _k

    if getattr(args, "contact", None):
        from . import _ncontact

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


def _certify_table(title: str, c: Construction, budget: Any = None) -> tuple[str, bool]:
    from .. import proof

    certs = proof.certify(c, budget=budget)
    lines = [title]
    from ..proof._budget import TIMED_OUT

    for cert in certs:
        what = TIMED_OUT if cert.result.method == TIMED_OUT else "; ".join(cert.facts)
        lines.append(f"{cert.step:9} {cert.result.status.value:9} {what}")
    return "\n".join(lines), all(x.result.holds for x in certs)


def _cmd_verify(args: argparse.Namespace) -> int:
    markdown = check_target(args.markdown) if args.markdown is not None else None
    from .. import proof
    from ..construction import internal_force_diagram
    from ..grasp import Grasp

    if args.certify and (any(getattr(args, k, None) is not None for k in _PARAMS)
                         or args.preset != "fig6"):
        grasp_from_args(args)  # a bad grasp option is refused before the long run
    from ..proof._budget import TIMED_OUT, Budget

    budget = Budget(args.timeout)
    if args.certify:  # the symbolic construction is made before the clock starts
        symbolic = internal_force_diagram(Grasp.symbolic("mu"))
    reports = proof.run_catalogue(quiet=args.quiet or args.json, budget=budget)
    status = proof.exit_status(reports)
    late = sum(r.result.method == TIMED_OUT for r in reports)
    if markdown is not None:
        with writing(markdown):
            markdown.write_text(proof.to_markdown(reports))
    if args.json:
        print(proof.to_json(reports))
    elif not args.markdown or not args.quiet:
        from ._verify import table

        print(table(reports))
    if args.certify:
        out = sys.stderr if args.json else sys.stdout
        text, ok = _certify_table("certify: the symbolic construction (all admissible grasps)",
                                  symbolic, budget)
        print("\n" + text, file=out)
        given = any(getattr(args, k, None) is not None for k in _PARAMS)
        if given or args.preset != "fig6":
            t2, ok2 = _certify_table(f"certify: {args.preset} with the options given",
                                     internal_force_diagram(grasp_from_args(args)), budget)
            print("\n" + t2, file=out)
            ok = ok and ok2
        status = status or (0 if ok else 1)
        late += sum(TIMED_OUT in line for line in text.splitlines())
    if late:
        print(f"graspcompass: {late} claims or steps timed out after {args.timeout:g} s "
              "(--timeout): UNDECIDED; the other verdicts stand", file=sys.stderr)
    return status


def _cmd_crosscheck(args: argparse.Namespace) -> int:
    import importlib.util

    if importlib.util.find_spec("scipy") is None:
        raise InputError("crosscheck needs scipy: pip install 'graspcompass[crosscheck]'")
    from ..proof.crosscheck import run_crosscheck

    if args.grasps * args.thetas > CROSSCHECK_RUNS:
        raise ValueError(f"--grasps × --thetas = {args.grasps * args.thetas} linprog problems; "
                         f"at most {CROSSCHECK_RUNS}")
    r = run_crosscheck(args.grasps, args.thetas, args.seed, quiet=args.quiet)
    print(f"{r.grasps} random grasps × {r.thetas} directions: largest |k_grasp − linprog| = "
          f"{r.max_abs_diff:.3e}")
    return 0 if r.max_abs_diff < 1e-7 else 1


_COMMANDS = {None: _cmd_main, "draw": _cmd_draw, "steps": _cmd_steps, "k": _cmd_k,
             "presets": _cmd_presets, "animate": _cmd_animate, "verify": _cmd_verify,
             "crosscheck": _cmd_crosscheck, "export": _cmd_export, "explore": _cmd_explore,
             "worksheet": _worksheet.run, "recipe": _recipe.run,
             "check": _check.run, "size": _size.run,
             "plan": _plan.run}


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
    from ..boundary._deadline import OutOfTime, deadline

    seconds = getattr(args, "timeout", None) if args.command in TIMED else None
    alarm = contextlib.nullcontext() if seconds is None else deadline(
        seconds, lambda: OutOfTime(f"the command took longer than {seconds:g} s (--timeout "
                                   "S allows more): its input makes too much work"))
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
        print(f"graspcompass: internal error: {type(exc).__name__}: {_message(exc)} (a bug; "
              "please report it with the command line)", file=sys.stderr)
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
