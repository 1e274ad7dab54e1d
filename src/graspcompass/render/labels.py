"""Point labels of the matplotlib drawings: a thin adapter of :mod:`graspcompass.labelling`.

The placement itself (eight positions around each point, scored against the
other labels, the markers and the drawn curves, in points) is the one of every
painter, :func:`graspcompass.labelling.place`; here only the matplotlib
transforms turn data coordinates into points and the result into annotations.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.text import Text

from ..scene.labelling import place

__all__ = ["place_labels"]

_HA = {1: "left", -1: "right", 0: "center"}
_VA = {1: "bottom", -1: "top", 0: "center"}


def place_labels(
    ax: Axes,
    items: Sequence[tuple[tuple[float, float], str]],
    curves: Sequence[np.ndarray] = (),
    avoid: Sequence[Text] = (),
    obstacles: Sequence[tuple[float, float]] | np.ndarray = (),
    font_size: float = 10.0,
    marker_size: float = 4.0,
    gap: float = 2.5,
    **text_kw: Any,
) -> list[Text]:
    """Add one text per ``(xy, label)`` of ``items`` at a free place around ``xy``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes whose limits are already set.
    items : sequence of ((x, y), str)
        Points in data coordinates and their labels, most important first.
    curves : sequence of (N, 2) arrays
        Drawn polylines, in data coordinates, that labels should not cross.
    obstacles : sequence of (x, y)
        Unlabelled markers in data coordinates (break points) labels should not cover.
    avoid : sequence of Text
        Texts already drawn that labels should not cover.
    font_size, marker_size, gap : float
        In points: the label size, the marker size and the gap to the marker.
    **text_kw
        Passed on to :meth:`~matplotlib.axes.Axes.annotate`.

    Returns
    -------
    list of matplotlib.text.Text
        One text per item, in the same order.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot()
    >>> (t,) = place_labels(ax, [((0.5, 0.5), "$O$")])
    >>> t.get_ha(), t.get_va()
    ('left', 'bottom')
    """
    fig = ax.figure
    ax.apply_aspect()
    to_pt = 72.0 / fig.dpi
    trans = ax.transData

    def disp(xy: Any) -> np.ndarray:
        return np.asarray(trans.transform(np.asarray(xy, dtype=float))) * to_pt

    anchors = disp([xy for xy, _ in items]) if items else np.zeros((0, 2))
    placed = place(
        anchors,
        [label for _, label in items],
        curves=[disp(c) for c in curves if len(c)],
        frame=tuple(np.asarray(ax.bbox.extents) * to_pt),
        avoid=[tuple(np.asarray(t.get_window_extent().extents) * to_pt) for t in avoid],
        font_size=font_size,
        marker_size=marker_size,
        gap=gap,
        obstacles=disp(list(obstacles)) if len(obstacles) else (),
    )
    return [
        ax.annotate(
            label,
            xy,
            xytext=p.offset,
            textcoords="offset points",
            ha=_HA[p.direction[0]],
            va=_VA[p.direction[1]],
            fontsize=font_size,
            annotation_clip=False,
            **text_kw,
        )
        for (xy, label), p in zip(items, placed)
    ]
