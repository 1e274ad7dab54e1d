"""``graspcompass verify``: the paper's claims machine-checked, and the table it prints.

:func:`register` and :func:`run` are the sub-command; :func:`table` is its table,
fitted to the terminal's width.

The columns and the lines after them are those of
:func:`graspcompass.proof.to_table`; here the seconds come before the method,
and the method and every longer line are wrapped to the terminal's width
(``COLUMNS``, else the terminal's, else 100 characters), continuation lines
indented, so that nothing is cut and no line is 450 characters wide.

Examples
--------
>>> print(fit_line("  eq5: " + "x > 0, " * 12, 40))
  eq5: x > 0, x > 0, x > 0, x > 0, x >
      0, x > 0, x > 0, x > 0, x > 0, x >
      0, x > 0, x > 0,
"""

from __future__ import annotations

import argparse
import shutil
import sys
import textwrap
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from ..boundary._output import check_target, writing
from ._animate import quiet_option
from ._common import _PARAMS, grasp_from_args

if TYPE_CHECKING:
    from ..construction import Construction

__all__ = ["MIN_WIDTH", "fit_line", "register", "run", "table", "width"]

#: The narrowest table: below it the lines are wrapped at this width anyway.
MIN_WIDTH = 60


def width() -> int:
    """The terminal's width (``COLUMNS`` first; 100 when not a terminal), at least MIN_WIDTH."""
    return max(MIN_WIDTH, shutil.get_terminal_size((100, 24)).columns)


def fit_line(line: str, cols: int) -> str:
    """``line`` wrapped at ``cols``, its continuation lines indented 4 more than it."""
    if len(line) <= cols:
        return line
    indent = " " * (len(line) - len(line.lstrip()) + 4)
    return (
        "\n".join(textwrap.wrap(line, cols, subsequent_indent=indent, break_on_hyphens=False))
        or line
    )


def table(reports: Sequence[Any], cols: int | None = None) -> str:
    """The verify report as :func:`graspcompass.proof.to_table` has it, fitted to ``cols``."""
    from ..proof import to_table

    cols = width() if cols is None else max(MIN_WIDTH, cols)
    rows = [
        (r.claim.id, r.claim.ref, r.result.status.value, f"{r.result.seconds:.2f}", r.result.method)
        for r in reports
    ]
    head = ("id", "paper", "status", "s", "method")
    w = [max(len(str(x[i])) for x in [head, *rows]) for i in range(4)]
    start = sum(w) + 2 * 4
    if cols - start < 24:  # too narrow beside the columns: the method on lines of its own
        start = 4
    room = cols - start
    lines = []
    for row in [head, *rows]:
        left = "  ".join(str(x).ljust(w[i]) for i, x in enumerate(row[:4]))
        method = textwrap.wrap(row[4], room, break_on_hyphens=False) or [""]
        if start == 4:
            lines += [fit_line(left.rstrip(), cols), *("    " + m for m in method)]
            continue
        lines.append(f"{left}  {method[0]}".rstrip())
        lines += [" " * start + more for more in method[1:]]
    tail = to_table(reports).split("\n")[1 + len(rows) :]
    return "\n".join(lines + [fit_line(line, cols) for line in tail])


def register(sub: Any, _add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``verify`` sub-command to ``sub`` (argparse's sub-parsers)."""
    from . import _check

    v = sub.add_parser(
        "verify",
        help="machine-check every claim of the paper (symbolic)",
        description="Check every claim of the paper for general symbolic parameters under "
        "condition (1) (and μ = tan ξ where both appear); print each claim's status, "
        "hypotheses and non-degeneracy conditions.",
        epilog="exit status: 0 when every claim is decided (none UNDECIDED) and every REFUTED "
        "claim names a correction that is PROVED (with --certify: and every construction "
        "step holds); 1 otherwise; 2 for a usage error.",
    )
    v.add_argument(
        "--json",
        action="store_true",
        help="print the results as JSON (with hypotheses, conditions, certificates)",
    )
    v.add_argument(
        "--markdown",
        metavar="FILE",
        help="write the report as a Markdown page (its folder must exist)",
    )
    v.add_argument(
        "--ncontact",
        action="store_true",
        help="also prove the n-contact claims (docs/ncontact.md): V1..V4 as dual "
        "vertices of the n-contact LP, their dual feasibility, complementary "
        "slackness, the shorter recipe, a symbolic three-finger grasp (about "
        "20 s more)",
    )
    v.add_argument(
        "--certify",
        action="store_true",
        help="also certify the symbolic construction (every admissible grasp) and, "
        "if grasp options are given, that grasp's construction",
    )
    v.add_argument(
        "--timeout",
        type=_check._seconds,
        default=None,
        metavar="S",
        help="stop after S seconds for the whole run (catalogue and --certify; "
        "default: no limit): the verdicts reached by then are kept, the rest "
        "are UNDECIDED (timed out, exit status 1)",
    )
    _add_grasp_options(v)
    quiet_option(v, "no progress bar")


def _certify_table(title: str, c: Construction, budget: Any = None) -> tuple[str, bool]:
    from .. import proof

    certs = proof.certify(c, budget=budget)
    lines = [title]
    from ..proof._budget import TIMED_OUT

    for cert in certs:
        what = TIMED_OUT if cert.result.method == TIMED_OUT else "; ".join(cert.facts)
        lines.append(f"{cert.step:9} {cert.result.status.value:9} {what}")
    return "\n".join(lines), all(x.result.holds for x in certs)


def run(args: argparse.Namespace) -> int:
    markdown = check_target(args.markdown) if args.markdown is not None else None
    from .. import proof
    from ..construction import internal_force_diagram
    from ..grasp import Grasp

    if args.certify and (
        any(getattr(args, k, None) is not None for k in _PARAMS) or args.preset != "fig6"
    ):
        grasp_from_args(args)  # a bad grasp option is refused before the long run
    from ..proof._budget import TIMED_OUT, Budget

    budget = Budget(args.timeout)
    if args.certify:  # the symbolic construction is made before the clock starts
        symbolic = internal_force_diagram(Grasp.symbolic("mu"))
    from ..proof.catalogue import CLAIMS, ncontact_extra

    claims = (*CLAIMS, *ncontact_extra()) if args.ncontact else CLAIMS
    reports = proof.run_catalogue(claims, quiet=args.quiet or args.json, budget=budget)
    status = proof.exit_status(reports)
    late = sum(r.result.method == TIMED_OUT for r in reports)
    if markdown is not None:
        with writing(markdown):
            markdown.write_text(proof.to_markdown(reports))
    if args.json:
        print(proof.to_json(reports))
    elif not args.markdown or not args.quiet:
        print(table(reports))
    if args.certify:
        out = sys.stderr if args.json else sys.stdout
        text, ok = _certify_table(
            "certify: the symbolic construction (all admissible grasps)", symbolic, budget
        )
        print("\n" + text, file=out)
        given = any(getattr(args, k, None) is not None for k in _PARAMS)
        if given or args.preset != "fig6":
            t2, ok2 = _certify_table(
                f"certify: {args.preset} with the options given",
                internal_force_diagram(grasp_from_args(args)),
                budget,
            )
            print("\n" + t2, file=out)
            ok = ok and ok2
        status = status or (0 if ok else 1)
        late += sum(TIMED_OUT in line for line in text.splitlines())
    if late:
        print(
            f"graspcompass: {late} claims or steps timed out after {args.timeout:g} s "
            "(--timeout): UNDECIDED; the other verdicts stand",
            file=sys.stderr,
        )
    return status
