"""The ``export`` and ``explore`` sub-commands of the command line.

``graspcompass export --format ggb|tikz|svg|json|png|pdf -o FILE`` writes the
construction of the grasp in one of :data:`graspcompass.export.FORMATS`;
``graspcompass explore`` opens the interactive explorer window.  Both take a
construction file (``export FILE.gc``, :mod:`graspcompass.cli._file`): ``export``
writes any file's construction (GeoGebra without sliders unless it is the
paper's recipe); ``--format html`` and ``explore`` redraw the paper's recipe
live and refuse a file with other steps; ``--format html`` with ``--contact``
writes the n-contact page (:mod:`graspcompass.export.ncontact_html`).  The module
only adds sub-parsers and runs them; :mod:`graspcompass.cli` builds the grasp
from the common options and reports errors (a ``ValueError`` is one line on
stderr, exit status 2).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from . import _file

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["register", "run_explore", "run_export"]

_FORMATS = ("ggb", "tikz", "svg", "json", "png", "pdf", "html")
#: Longest ``--title``.
MAX_TITLE = 200
_EXT = {
    "ggb": "ggb",
    "tikz": "tex",
    "svg": "svg",
    "json": "json",
    "png": "png",
    "pdf": "pdf",
    "html": "html",
}


def _title(text: str) -> str:
    """An argparse ``type``: a title of printable characters, at most :data:`MAX_TITLE`."""
    if len(text) > MAX_TITLE:
        raise argparse.ArgumentTypeError(
            f"a title has at most {MAX_TITLE} characters, got {len(text)}"
        )
    bad = next((c for c in text if not c.isprintable()), None)
    if bad is not None:
        raise argparse.ArgumentTypeError(
            f"a title has printable characters only, got {bad!r} in {text[:40]!r}"
        )
    return text


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``export`` and ``explore`` sub-commands to ``subparsers``.

    ``add_grasp_options`` adds the common ``--preset`` and parameter options.
    """
    e = subparsers.add_parser(
        "export",
        help="export the construction: GeoGebra, TikZ, SVG, JSON, PNG or PDF",
        description="Write the construction of the grasp to a file: a live GeoGebra .ggb "
        "(sliders x1, x2, y, φ1, φ2, μ1, μ2, draggable P1), TikZ for pdflatex, a "
        "standalone SVG, the protocol as JSON (schema graspcompass.construction/1),"
        " or PNG/PDF through the renderer.",
        epilog="The folder of -o must exist; the path is checked before any work. "
        "exit status: 0, or 2 for a user error.",
    )
    add_grasp_options(e)
    _file.add_file_options(e)
    from ._ncontact import add_options as _add_ncontact

    _add_ncontact(e)
    e.add_argument(
        "--format", choices=_FORMATS, help="file format (default: from the extension of -o)"
    )
    e.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="output file, in an existing folder (default: PRESET.EXT, or the "
        "construction file's name with .EXT, in the current folder)",
    )
    e.add_argument(
        "--step",
        type=int,
        metavar="N",
        help="export the state after protocol step N (default: every step)",
    )
    e.add_argument(
        "--title",
        metavar="TEXT",
        type=_title,
        help=f"title of the picture, at most {MAX_TITLE} printable characters "
        "(default: the grasp's)",
    )
    e.add_argument(
        "--fragment",
        action="store_true",
        help="TikZ only: write the tikzpicture alone, for \\input in a document",
    )
    e.add_argument(
        "--break-points",
        action="store_true",
        help="label the break points B12...B34 that lie on the envelope (svg, tikz, png, pdf; "
        "default: small unlabelled markers)",
    )
    e.add_argument(
        "-q",
        "--quiet",
        action="store_true",
        default=argparse.SUPPRESS,
        help="print nothing but errors",
    )

    x = subparsers.add_parser(
        "explore",
        help="open the interactive explorer (sliders, draggable contacts)",
        description="A window with sliders for x1, x2, y, φ1, φ2, μ1, μ2 and draggable P1 and "
        "P2; the construction, circles, envelope and worst/best case follow live.",
    )
    add_grasp_options(x)
    _file.add_file_options(x)


def _format_and_path(args: argparse.Namespace) -> tuple[str, str | Path]:
    from ..export import guess_format

    if args.output is None:
        fmt = args.format or "svg"
        return fmt, Path(f"{_file.output_stem(args, args.preset)}.{_EXT[fmt]}")
    return (args.format or guess_format(args.output)), args.output


def run_export(args: argparse.Namespace, grasp: Grasp | Callable[[], Grasp]) -> int:
    """Run ``graspcompass export`` for ``grasp``; returns the exit status (0).

    ``grasp`` is a :class:`~graspcompass.Grasp`, or a function that makes it,
    called once the output is checked (the command line reads its options then).
    With a construction file (:mod:`graspcompass.cli._file`) the file is
    replayed instead of the paper's recipe.

    Raises
    ------
    ValueError
        For a bad ``--step``, an unknown extension, or a format the
        construction cannot be written in (a symbolic grasp in a drawing format);
        :class:`~graspcompass.errors.OutputError` for a path that cannot be
        written (checked before any work).
    """
    from ..boundary._output import check_target, writing

    fmt, path = _format_and_path(args)
    if args.fragment and fmt != "tikz":
        raise ValueError(f"--fragment is for TikZ only, not for {fmt}")
    bp = bool(getattr(args, "break_points", False))
    if bp and fmt not in ("svg", "tikz", "png", "pdf"):
        raise ValueError(f"--break-points is for svg, tikz, png and pdf, not for {fmt}")
    path = check_target(path)
    from ..export import export
    from ..export.tikz import write_tikz
    from ._ncontact import wants_contacts

    if fmt == "html" and wants_contacts(args):  # the n-contact page (draggable contacts)
        from ..export.ncontact_html import write_ncontact_html
        from ._ncontact import grasp_from_args

        if args.step is not None:
            raise ValueError("--step does not apply to the n-contact page (it redraws Q live)")
        write_ncontact_html(grasp_from_args(args), path, title=args.title)
        if not getattr(args, "quiet", False):
            print(f"wrote {path} (html, n-contact page)")
        return 0
    made = _file.construction(args, grasp if callable(grasp) else lambda: grasp)
    if fmt == "html":
        _file.paper_only(made, "export --format html (the explorer page)")
    c = made.construction
    title = args.title
    if fmt == "ggb" and not made.paper:
        if title is None and c.grasp is not None:
            title = c.grasp.title
        c = _file.without_sliders(made)
    if args.step is not None:
        if not -len(c) <= args.step < len(c):
            raise ValueError(
                f"--step {args.step} is out of range: the protocol has {len(c)} "
                f"steps, 0 to {len(c) - 1}"
            )
        c = c.upto(args.step)
    with writing(path):
        if fmt == "tikz" and args.fragment:
            write_tikz(c, path, standalone=False, title=title, break_points=bp)
        elif (
            fmt == "ggb"
            and not made.paper
            and made.program is not None
            and c.grasp is None
            and args.step is None
            and all(p.name in (made.values or {}) for p in made.program.params)
        ):
            from ..export.geogebra import write_ggb  # the file's sliders and Prove per claim

            write_ggb(c, path, title, made.program, made.values)
        else:
            export(c, path, fmt, title=title, break_points=bp)
    if not getattr(args, "quiet", False):
        print(f"wrote {path} ({fmt}, {len(c)} steps)")
    return 0


def run_explore(args: argparse.Namespace, grasp: Grasp | Callable[[], Grasp]) -> int:
    """Run ``graspcompass explore`` for ``grasp``: the window until it is closed.

    Raises
    ------
    ValueError
        Without a display (matplotlib has no interactive backend), in one line;
        a construction file that is not the paper's recipe (the explorer
        redraws the recipe as the sliders move).
    """
    from ..boundary._deadline import command_deadline

    seconds = getattr(args, "timeout", None)
    with command_deadline(seconds):  # the work before the window: a file, a grasp
        if _file.file_name(args) is not None or getattr(args, "set", None):
            made = _file.construction(args, grasp if callable(grasp) else lambda: grasp)
            _file.paper_only(made, "explore")
            grasp = made.construction.grasp
        grasp = grasp() if callable(grasp) else grasp
    from ..render.explorer import explore

    explore(grasp, timeout=seconds)
    return 0
