"""Exports of a construction to files that other tools open.

- :mod:`~graspcompass.export.geogebra`: GeoGebra ``.ggb``, a live construction
  on sliders x1, x2, y, φ1, φ2, μ1, μ2 with draggable P1, in protocol order;
- :mod:`~graspcompass.export.tikz`: plain TikZ (standalone ``article`` or a
  ``tikzpicture`` to ``\\input``), exact values in comments;
- :mod:`~graspcompass.export.svg`: a standalone, labelled, scalable SVG;
- :mod:`~graspcompass.export.json`: the protocol as JSON (schema
  ``graspcompass.construction/1``), which :func:`~graspcompass.export.json.loads`
  reads back into the same construction;
- PNG and PDF through :mod:`graspcompass.render` (matplotlib, imported only then).

Nothing here imports matplotlib except :func:`export` for ``png``/``pdf``.

Examples
--------
>>> from graspcompass import Grasp, internal_force_diagram
>>> from graspcompass.export import export, guess_format
>>> guess_format("diagram.tex"), guess_format("a.GGB")
('tikz', 'ggb')
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._lazy import attach
from ..boundary._output import check_target, writing

if TYPE_CHECKING:
    from ..construction import Construction
    from . import json
    from .geogebra import read_ggb_xml, to_ggb, write_ggb
    from .json import SCHEMA, dumps, loads
    from .svg import to_svg, write_svg
    from .tikz import to_tikz, write_tikz

__all__ = [
    "FORMATS",
    "SCHEMA",
    "dumps",
    "export",
    "guess_format",
    "json",
    "loads",
    "read_ggb_xml",
    "to_ggb",
    "to_svg",
    "to_tikz",
    "write_ggb",
    "write_svg",
    "write_tikz",
]

#: Where each writer lives; imported on first use, so that :func:`guess_format` and
#: the command line's checks load no writer (:mod:`graspcompass._lazy`).
__getattr__, __dir__ = attach(
    __name__,
    {
        "json": "json",
        "SCHEMA": "json",
        "dumps": "json",
        "loads": "json",
        "read_ggb_xml": "geogebra",
        "to_ggb": "geogebra",
        "write_ggb": "geogebra",
        "to_svg": "svg",
        "write_svg": "svg",
        "to_tikz": "tikz",
        "write_tikz": "tikz",
    },
)

#: The formats :func:`export` writes.
FORMATS = ("ggb", "tikz", "svg", "json", "png", "pdf", "html")
_EXTENSIONS = {
    ".ggb": "ggb",
    ".tex": "tikz",
    ".tikz": "tikz",
    ".svg": "svg",
    ".json": "json",
    ".png": "png",
    ".pdf": "pdf",
    ".html": "html",
    ".htm": "html",
}


def guess_format(path: Any) -> str:
    """The format of ``path`` from its extension.

    Raises
    ------
    ValueError
        For an unknown extension.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in _EXTENSIONS:
        raise ValueError(
            f"cannot tell the format of {str(path)!r}: use one of "
            f"{', '.join(_EXTENSIONS)} or give the format ({', '.join(FORMATS)})"
        )
    return _EXTENSIONS[suffix]


def export(
    construction: Construction,
    path: Any,
    format: str | None = None,
    title: str | None = None,
    break_points: bool = False,
) -> Path:
    """Write ``construction`` to ``path`` as ``format`` (default: from the extension).

    Parameters
    ----------
    construction : Construction
        Numeric parameters for every format but ``json``, which also takes a
        symbolic construction.
    path : str or path-like
    format : {"ggb", "tikz", "svg", "json", "png", "pdf", "html"}, optional
    title : str, optional
        Title of the picture (default: the grasp's title).
    break_points : bool
        Label the break points on the envelope (svg, tikz, png, pdf;
        :func:`graspcompass.scene.picture.build_scene`).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For an unknown format, or a symbolic construction in a drawing format.
    graspcompass.errors.OutputError
        Before any work if the folder of ``path`` does not exist (it is not
        made), ``path`` is a folder or is not writable; after, if the write
        fails (a full disk).
    """
    fmt = (format or guess_format(path)).lower()
    if fmt not in FORMATS:
        raise ValueError(f"unknown export format {format!r}: choose one of {', '.join(FORMATS)}")
    p = check_target(path)
    with writing(p):
        return _write(construction, p, fmt, title, break_points)


def _write(
    construction: Construction, p: Path, fmt: str, title: str | None, break_points: bool = False
) -> Path:
    from .geogebra import write_ggb
    from .json import dumps
    from .svg import write_svg
    from .tikz import write_tikz

    if fmt == "ggb":
        return write_ggb(construction, p, title)
    if fmt == "tikz":
        return write_tikz(construction, p, title=title, break_points=break_points)
    if fmt == "svg":
        return write_svg(construction, p, title, break_points)
    if fmt == "json":
        p.write_text(dumps(construction) + "\n", encoding="utf-8")
        return p
    if fmt == "html":
        from .html import write_html  # the self-contained web explorer (JSXGraph)

        return write_html(construction, p, title=title)
    if fmt in ("png", "pdf"):
        from ..render import figure_diagram, save_figure  # matplotlib, only here

        fig = figure_diagram(construction, title=title, break_points=break_points)
        return save_figure(fig, p, format=fmt)
    raise AssertionError(fmt)  # pragma: no cover - FORMATS is checked first
