"""The ``recipe`` sub-command of the command line.

``graspcompass recipe`` prints the paper's drawing recipe (§3.3, §3.2 of Ito,
Tanaka, Sasaki, Robotica 2012) as it ships, a file in the construction
language (``docs/language.md``) with symbolic parameters; ``-o FILE.gc``
writes it to a file instead, a starting point for a construction of one's own.
The module only adds the sub-parser and runs it; :mod:`graspcompass.cli`
reports errors (a ``ValueError`` is one line on stderr, exit status 2).

Examples
--------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="graspcompass")
>>> sub = parser.add_subparsers(dest="command")
>>> register(sub, lambda p: p.add_argument("--preset", default="fig6"))
>>> args = parser.parse_args(["recipe", "-o", "mine.gc"])
>>> args.output
'mine.gc'
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import Any

__all__ = ["register", "run"]


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``recipe`` sub-command to ``subparsers``.

    The recipe does not depend on a grasp, so ``add_grasp_options`` is not used;
    it is taken for the same signature as the other sub-command modules.
    """
    del add_grasp_options  # the shipped file holds symbols, not one grasp's values
    r = subparsers.add_parser(
        "recipe",
        help="print the paper's recipe as a file of the construction language",
        description="Print the drawing recipe of §3.3 (V_n) and §3.2 (the circles) as it "
        "ships: one step a line (NAME = OPERATION INPUTS (VALUES) ...), symbolic "
        "parameters with their domains, condition (1) as a named hypothesis, and "
        "the closed form (27)-(39) as claims. The language is described in "
        "docs/language.md.",
        epilog="The folder of -o must exist; the path is checked before any work. "
        "exit status: 0, or 2 for a user error.",
    )
    r.add_argument(
        "-o",
        "--output",
        metavar="FILE.gc",
        help="write the recipe to this file instead of printing it",
    )
    r.add_argument(
        "-q",
        "--quiet",
        action="store_true",
        default=argparse.SUPPRESS,
        help="print nothing but errors (with -o)",
    )


def run(args: argparse.Namespace) -> int:
    """Run ``graspcompass recipe``; returns the exit status (0).

    Raises
    ------
    OutputError
        For a path of ``-o`` that cannot be written (checked before any work).
    """
    from ..boundary._output import check_target, writing

    path = None if args.output is None else check_target(args.output)
    from ..construction.language import paper_text

    text = paper_text()
    if path is None:
        print(text, end="")
        return 0
    with writing(path):
        path.write_text(text, encoding="utf-8")
    if not getattr(args, "quiet", False):
        print(f"wrote {path} ({len(text.splitlines())} lines)")
    return 0
