"""Construction files on ``steps``, ``draw``, ``animate``, ``export`` and ``explore``.

``graspcompass draw FILE.gc`` (or ``--file FILE.gc``; ``-`` reads stdin) reads a
file of the construction language (``docs/language.md``) with the bounded
reader of ``check`` (:func:`graspcompass.cli._check.read_file`), parses it and
replays it (:func:`graspcompass.construction.language.replay`) in place of the
paper's recipe.  Its parameters get their values so:

- a parameter named like one of the grasp's (``x1 x2 y phi1 phi2 mu1 mu2 xi1
  xi2``) takes the grasp's value, from ``--preset`` and ``--x1`` ... as usual;
- any other parameter takes the value of ``--set NAME=EXPR`` (repeatable; the
  value read exactly by the safe parser :func:`graspcompass.expr.parse_exact`,
  never ``eval``), and must be within its declared domain.

A parameter without a value, ``--set`` of a name the file does not declare (or
of a grasp parameter, which has its own option), and ``--set`` without a file
are user errors: one line, exit status 2.  When every parameter of the file is
a grasp parameter the construction keeps the grasp (its title, the object's
outline); otherwise it has none.

The pictures that show the paper's own objects (``draw``'s computer plot of
k_grasp, the HTML explorer, ``explore``, the ``sweep`` and ``orientation``
animations) are drawn only for the paper's recipe itself (the steps of
``graspcompass recipe``, whatever the file's comments and claims): a file with
other steps gets no overlay in ``draw`` and is refused by the others, rather
than drawn next to a k_grasp it does not construct.  The GeoGebra export of
such a file has no sliders (the sliders drive the paper's P1, P2 and cone
sides by name): its free objects are the file's given points, at their values.

Nothing heavy is imported at the top of this module: the file is read before
sympy is loaded, and the parse comes after the outputs are checked.

Examples
--------
>>> import argparse
>>> p = argparse.ArgumentParser(prog="draw")
>>> add_file_options(p)
>>> args = p.parse_args(["thales.gc", "--set", "a=2", "--set", "t = 1/3"])
>>> file_name(args), args.set, output_stem(args, "fig6")
('thales.gc', [('a', '2'), ('t', '1/3')], 'thales')
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import PurePath
from typing import Any

__all__ = [
    "GRASP_PARAMS",
    "MAX_SETS",
    "FileConstruction",
    "add_file_options",
    "construction",
    "file_name",
    "output_stem",
    "paper_only",
    "without_sliders",
]

#: Parameters whose values come from the grasp options (``--preset``, ``--x1`` ...).
GRASP_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")
#: Most ``--set`` options on one command line.
MAX_SETS = 64
_SET = re.compile(r"\s*([A-Za-z_][A-Za-z_0-9]{0,31})\s*=(.*)", re.S)


def _assignment(text: str) -> tuple[str, str]:
    """An argparse ``type``: ``NAME=EXPR`` -> ``(NAME, EXPR)`` (the value is read later)."""
    m = _SET.fullmatch(text)
    if m is None or not m.group(2).strip():
        shown = text if len(text) <= 40 else text[:30] + "..."
        raise argparse.ArgumentTypeError(
            f"write NAME=VALUE (a parameter of the file and an "
            f"exact expression such as 2, sqrt(3)/2 or pi/3), "
            f"got {shown!r}"
        )
    return m.group(1), m.group(2).strip()


def add_file_options(p: argparse.ArgumentParser, positional: bool = True) -> None:
    """Add ``[FILE]``, ``--file FILE`` and ``--set NAME=EXPR`` to a sub-command's parser.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The sub-command's parser.
    positional : bool, optional
        Also take the file as an optional positional argument (``animate`` has
        its preset there, and takes ``--file`` only).
    """
    g = p.add_argument_group(
        "construction file",
        "replay a file of the construction language (docs/language.md) "
        "instead of the paper's recipe; parameters named x1, x2, y, phi1, phi2, mu1, mu2, "
        "xi1, xi2 take the grasp's values, the others --set values",
    )
    if positional:
        g.add_argument(
            "file",
            nargs="?",
            default=None,
            metavar="FILE",
            help="a construction file ('-' reads stdin); same as --file",
        )
    g.add_argument(
        "--file",
        dest="file_option",
        default=None,
        metavar="FILE",
        help="a construction file ('-' reads stdin)",
    )
    g.add_argument(
        "--set",
        action="append",
        type=_assignment,
        default=None,
        metavar="NAME=EXPR",
        help="the value of a parameter of the file that is not a grasp parameter, "
        "an exact expression (repeat for each)",
    )


def file_name(args: argparse.Namespace) -> str | None:
    """The construction file named on the command line, or None.

    Raises
    ------
    ValueError
        For a file given both as ``FILE`` and ``--file``.
    """
    positional, option = getattr(args, "file", None), getattr(args, "file_option", None)
    if positional is not None and option is not None:
        raise ValueError(f"two construction files: {positional!r} and --file {option!r}; give one")
    return positional if positional is not None else option


def output_stem(args: argparse.Namespace, preset: str) -> str:
    """The stem of a default output name: the file's (``construction`` for stdin), or ``preset``."""
    name = file_name(args)
    if name is None:
        return preset
    stem = PurePath(name).stem if name != "-" else ""
    return stem if stem and stem.isprintable() else "construction"


@dataclass(frozen=True)
class FileConstruction:
    """A construction from the command line and what it is.

    Attributes
    ----------
    construction : Construction
        The replayed construction (the paper's recipe without a file).
    paper : bool
        Whether it is the paper's recipe (no file, or a file with its steps).
    shown : str
        The file's name in messages (``"paper.gc"`` without a file).
    """

    construction: Any
    paper: bool
    shown: str
    #: The parsed file and its parameters' values (sliders and claims of a .ggb).
    program: Any = None
    values: Any = None


def paper_only(made: FileConstruction, what: str) -> None:
    """Refuse ``what`` for a construction that is not the paper's recipe.

    Raises
    ------
    ValueError
        One line naming the file and what to use instead.
    """
    if not made.paper:
        raise ValueError(
            f"{what} shows the paper's recipe (its four circles, k_grasp); "
            f"{made.shown} has other steps: draw it with draw, animate or export "
            "--format svg, ggb, tikz, json, png or pdf"
        )


def construction(args: argparse.Namespace, grasp: Callable[[], Any]) -> FileConstruction:
    """The construction a command works on: the file's, replayed, or the paper's recipe.

    Parameters
    ----------
    args : argparse.Namespace
        With the options of :func:`add_file_options` and the grasp options; a
        grasp option given (``--x1`` ...) is refused for a file that has no
        grasp parameter, which would not use it.
    grasp : callable
        Makes the grasp of the grasp options (called only when it is needed).

    Returns
    -------
    FileConstruction

    Raises
    ------
    ValueError
        A file that cannot be read or parsed (``FILE:LINE:COL: what``), a
        parameter without a value, a ``--set`` the file does not take, a value
        outside its parameter's domain, a degenerate step; one line, exit 2.
    """
    from ._check import read_file

    name = file_name(args)
    sets = getattr(args, "set", None) or []
    from ._ncontact import wants_contacts

    if wants_contacts(args):
        if name is not None:
            raise ValueError(
                "--contact and a construction file: give one (the n-contact "
                "recipe is written from the contacts)"
            )
        from ..construction.language import parse, replay
        from ..construction.ncontact_recipe import ncontact_recipe
        from ._ncontact import grasp_from_args as contacts_grasp

        program = parse(ncontact_recipe(contacts_grasp(args)), "<contacts>")
        return FileConstruction(replay(program), False, "ncontact.gc")
    if name is None:
        if sets:
            raise ValueError(
                f"--set {sets[0][0]}=...: --set gives values to the parameters "
                "of a construction file; give the file (FILE or --file)"
            )
        from ..construction import internal_force_diagram

        return FileConstruction(internal_force_diagram(grasp()), True, "paper.gc")
    if len(sets) > MAX_SETS:
        raise ValueError(f"at most {MAX_SETS} --set options, got {len(sets)}")
    text, shown = read_file(name)
    from ..boundary.expr import ExpressionError, parse_exact
    from ..construction.language import paper_program, parse, replay

    program = parse(text, shown)
    declared = [p.name for p in program.params]
    values: dict[str, Any] = {}
    for key, value in sets:
        if key in values:
            raise ValueError(f"--set {key} is given twice")
        if key in GRASP_PARAMS:
            raise ValueError(
                f"--set {key}: {key} is a grasp parameter; give it with --{key} (or --preset)"
            )
        if key not in declared:
            listed = ", ".join(declared) if declared else "none"
            raise ValueError(
                f"--set {key}: {shown} has no parameter {key!r} (its parameters: {listed})"
            )
        try:
            values[key] = parse_exact(value)
        except ExpressionError as exc:
            raise type(exc)(f"--set {key}: {exc}") from None
    own = [p for p in program.params if p.name not in GRASP_PARAMS]
    for p in own:
        if p.name not in values:
            raise ValueError(
                f"{shown}:{p.line}:1: no value for the parameter {p.name!r}: give "
                f"--set {p.name}=VALUE"
            )
    uses_grasp = len(own) < len(program.params)
    given = [k for k in GRASP_PARAMS if getattr(args, k, None) is not None]
    if not uses_grasp and given:
        raise ValueError(
            f"--{given[0]} is not used: {shown} has no grasp parameter (its "
            f"parameters: {', '.join(declared) or 'none'}; give them with --set)"
        )
    paper = paper_program()
    is_paper = program.steps == paper.steps and program.params == paper.params
    if not own:
        c = replay(program, grasp())
    else:
        g = grasp() if uses_grasp else None
        for p in program.params:
            if p.name in GRASP_PARAMS and g is not None:  # g is None: no grasp parameter
                values[p.name] = g.params[p.name]
        c = replay(program, values)
    return FileConstruction(c, is_paper, shown, program, dict(values))


def without_sliders(made: FileConstruction) -> Any:
    """The construction to write to GeoGebra: a foreign file's without its grasp.

    GeoGebra's sliders drive the paper's P1, P2 and cone sides by name
    (:mod:`graspcompass.export.geogebra`); for a file with other steps they
    would move some objects and leave the others at the grasp's values.
    """
    c = made.construction
    return c if made.paper or c.grasp is None else replace(c, grasp=None)
