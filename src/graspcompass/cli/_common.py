"""What the sub-commands of ``graspcompass`` share: the parser, the grasp options, errors.

:class:`_Parser` is argparse with one-line errors; :func:`grasp_from_args` reads the
grasp options (``--preset``, ``--x1`` ...) through the safe parser;
:func:`protocol_table` prints a construction's protocol; :func:`one_line` is how
every error reaches stderr.  Each sub-command's module imports from here, never
from :mod:`graspcompass.cli` itself (which registers them).

Examples
--------
>>> one_line("  a message  ")
'a message'
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, NoReturn

from ..boundary import limits
from ..presets import PRESETS

if TYPE_CHECKING:  # the model (sympy, numpy) is loaded by the commands that use it
    from ..construction import Construction
    from ..grasp import Grasp

__all__ = ["MAX_MESSAGE", "TIMED", "grasp_from_args", "one_line", "protocol_table"]

#: The grasp options every grasp command takes (after ``--preset``).
_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")

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
        line = f"{line[: MAX_MESSAGE - 40]} ... ({len(line)} characters in all)"
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

    def parse_known_args(  # type: ignore[override]
        self,
        args: Sequence[str] | None = None,
        namespace: argparse.Namespace | None = None,
    ) -> tuple[argparse.Namespace, list[str]]:
        argv = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(self._join_dash_values(argv), namespace)

    def _join_dash_values(self, argv: list[str]) -> list[str]:
        """``--opt -value`` as ``--opt=-value`` for this parser's one-value options."""
        takes_value = {
            s
            for s, a in self._option_string_actions.items()
            if a.nargs is None and s.startswith("--")
        }
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
        "grasp",
        "a preset, optionally with parameters overridden; values are exact "
        "expressions such as sqrt(3)/2, pi/3, 60deg or 1.2 (= 6/5)",
    )
    g.add_argument(
        "--preset",
        default="fig6",
        choices=sorted(PRESETS),
        help="start from one of the paper's examples (default: fig6)",
    )
    for name in _PARAMS:
        g.add_argument(f"--{name}", metavar="EXPR", help=f"set {name}")


#: The commands that take ``--timeout`` (``check`` and ``verify`` have their own, which
#: keep the verdicts reached in time; ``explore``'s bounds the work before its window opens).
TIMED = ("draw", "steps", "k", "animate", "export", "worksheet", "size", "plan", "crosscheck")


def _seconds(text: str) -> float:
    from ._check import _seconds as check_seconds

    return check_seconds(text)


def _add_timeout(p: argparse.ArgumentParser, what: str = "") -> None:
    p.add_argument(
        "--timeout",
        type=_seconds,
        default=limits.COMMAND_SECONDS,
        metavar="S",
        help=f"stop after S seconds, 1 to 86400, with exit status 2 (default "
        f"{limits.COMMAND_SECONDS:g}: a construction file or a value can make "
        f"the work arbitrarily long){'; ' + what if what else ''}",
    )


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
