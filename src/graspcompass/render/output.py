"""Writing figures to PNG, SVG or PDF files."""

from __future__ import annotations

import io
import os
from pathlib import Path

from matplotlib.figure import Figure

from ..boundary._output import check_target, writing

__all__ = ["FORMATS", "save_figure"]

#: File formats :func:`save_figure` writes.
FORMATS = ("png", "svg", "pdf")


def save_figure(
    fig: Figure, path: str | os.PathLike[str], format: str | None = None, dpi: float = 150
) -> Path:
    """Write ``fig`` as PNG, SVG or PDF into an existing folder.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    path : str or path-like
        Target file; its extension gives the format unless ``format`` is given.
    format : {"png", "svg", "pdf"}, optional
    dpi : float
        Resolution of a PNG.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For an extension or format other than png, svg or pdf.
    graspcompass.errors.OutputError
        If the file cannot be written (its folder does not exist: folders are
        never made; no permission, checked before any work; a full disk): the figure
        is rendered in memory first, so a failed write leaves no half-written
        matplotlib state behind.

    Examples
    --------
    >>> save_figure(Figure(), "diagram.gif")
    Traceback (most recent call last):
    ...
    ValueError: cannot save a figure to 'diagram.gif': extension '.gif' is not supported; ...
    """
    p = Path(path)
    fmt = (format or p.suffix.lstrip(".")).lower()
    if fmt not in FORMATS:
        what = (
            f"format {format!r}"
            if format
            else f"extension {p.suffix!r}"
            if p.suffix
            else "a path without extension"
        )
        raise ValueError(
            f"cannot save a figure to {str(p)!r}: {what} is not supported; "
            f"use one of {', '.join('.' + f for f in FORMATS)}"
        )
    p = check_target(p)
    buffer = io.BytesIO()
    fig.savefig(buffer, format=fmt, dpi=dpi)
    with writing(p):
        p.write_bytes(buffer.getvalue())
    return p
