"""The labels of a worksheet kept to the rules of every picture, measured as drawn.

No label over another label, over the marker of another point or over the lines it must
keep clear of (the cone sides of page 1), and each nearer its own point than any other
(the distance from the point to the label's box): :func:`mend_labels` moves a label
that breaks one to the first of eight places round its point that keeps them all.
Private to :mod:`graspcompass.render.handdrawing`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any, Literal, cast

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.text import Annotation

__all__ = ["PLACES", "mend_labels"]


def _hits(bb: Any, pts: np.ndarray) -> bool:
    return bool(
        np.any(
            (pts[:, 0] > bb.x0) & (pts[:, 0] < bb.x1) & (pts[:, 1] > bb.y0) & (pts[:, 1] < bb.y1)
        )
    )


def _renderer(ax: Axes) -> Any:
    """The renderer of the axes' (Agg) canvas; the stubs' FigureCanvasBase has none."""
    return ax.figure.canvas.get_renderer()  # type: ignore[attr-defined]


def _markers(ax: Axes) -> list[tuple[np.ndarray, float]]:
    """Centre (display pixels) and radius of every round point marker drawn in ``ax``."""
    out = []
    for ln in ax.lines:
        if ln.get_visible() and ln.get_marker() == "o" and ln.get_linestyle() in ("None", "none"):
            xy = np.column_stack([ln.get_xdata(), ln.get_ydata()]).astype(float)
            rad = ln.get_markersize() * ax.figure.dpi / 72.0 / 2  # type: ignore[union-attr]
            out += [(p, rad) for p in ax.transData.transform(xy)]
    return out


def _near_box(p: np.ndarray, bb: Any) -> float:
    """Distance from the display point ``p`` to the box ``bb`` (0 inside)."""
    dx = max(bb.x0 - p[0], 0.0, p[0] - bb.x1)
    dy = max(bb.y0 - p[1], 0.0, p[1] - bb.y1)
    return math.hypot(dx, dy)


_Place = tuple[
    tuple[float, float], Literal["left", "center", "right"], Literal["bottom", "center", "top"]
]
#: The places round a point a label is tried at (offset in points, alignment): eight
#: beside it, then eight a little farther.
PLACES: tuple[_Place, ...] = tuple(
    cast(_Place, ((k * dx, k * dy), ha, va))
    for k in (1.0, 2.0)
    for (dx, dy), ha, va in (
        ((5, 4), "left", "bottom"),
        ((-5, 4), "right", "bottom"),
        ((0, 6), "center", "bottom"),
        ((5, -4), "left", "top"),
        ((-5, -4), "right", "top"),
        ((0, -6), "center", "top"),
        ((7, 0), "left", "center"),
        ((-7, 0), "right", "center"),
    )
)


def mend_labels(
    ax: Axes,
    labels: Sequence[Annotation],
    lines: Sequence[Line2D] = (),
    others: Sequence[Artist] = (),
    near: bool = False,
    drop: Callable[[Annotation], bool] | None = None,
) -> tuple[list[Annotation], list[Annotation]]:
    """Keep the rules of every picture for the point ``labels`` of ``ax`` (annotations in
    offset points), measured as drawn: no label over another label, over ``others``, over
    ``lines`` (the cone sides of page 1) or over the marker of another point, and each
    nearer its own point than any other (the distance from a point to the label's box).

    A label that breaks one goes to the first place that keeps them all, of where it is
    and the :data:`PLACES` round its point (``near``: those first, so that a label
    placed far away in the finished drawing comes back beside its point).  A label
    with no such place is removed when ``drop(label)`` is true (the inset names its
    point), else it stays where it breaks the fewest.  Returns the labels removed and
    those that still break a rule.
    """
    renderer = _renderer(ax)

    def dense(ln: Line2D) -> np.ndarray:  # 60 points along the line's first segment
        (x0, x1), (y0, y1) = (
            np.asarray(v, dtype=float)[:2] for v in (ln.get_xdata(), ln.get_ydata())
        )
        return np.column_stack([np.linspace(x0, x1, 60), np.linspace(y0, y1, 60)])

    pts = [ax.transData.transform(dense(ln)) for ln in lines]
    cloud = np.vstack(pts) if pts else np.zeros((0, 2))
    marks = _markers(ax)
    fixed = [a.get_window_extent(renderer) for a in others]
    live = list(  # each once (a group's label is every name's), text only (not the arrows)
        {id(t): t for t in labels if t.get_visible() and t.axes is ax and t.get_text()}.values()
    )
    removed: list[Annotation] = []
    boxes = {id(t): t.get_window_extent(renderer) for t in live}  # as placed, kept up to date

    def faults(t: Annotation) -> int:
        bb = boxes[id(t)] = t.get_window_extent(renderer)
        own = ax.transData.transform(t.xy)
        d_own = _near_box(own, bb)
        wide = bb.expanded(1.05, 1.1)
        n = int(_hits(wide, cloud)) + sum(wide.overlaps(o) for o in fixed)
        n += sum(bb.overlaps(boxes[id(u)]) for u in live if u is not t)
        for p, r in marks:
            if math.hypot(*(p - own)) > 0.5:  # another point's marker
                d = _near_box(p, bb)
                n += int(d < r) + int(d <= d_own)
        return n

    def put(t: Annotation, where: _Place) -> None:
        t.xyann, ha, va = where
        t.set_horizontalalignment(ha)
        t.set_verticalalignment(va)

    for _ in range(3):  # a label moved can free another: until nothing moves
        moved = False
        for t in list(live):
            start = cast(_Place, (t.xyann, t.get_horizontalalignment(), t.get_verticalalignment()))
            if faults(t) == 0 and not near:
                continue
            tries = [*PLACES, start] if near else [start, *PLACES]
            scored = []
            for where in tries:
                put(t, where)
                scored.append((faults(t), where))
                if scored[-1][0] == 0:
                    break
            best = min(scored, key=lambda x: x[0])
            if best[0] > 0 and drop is not None and drop(t):
                t.remove()
                live.remove(t)
                removed.append(t)
                moved = True
                continue
            put(t, best[1])
            boxes[id(t)] = t.get_window_extent(renderer)
            moved |= best[1] != start
        near = False  # the first pass seats them; later ones only mend
        if not moved:
            break
    return removed, [t for t in live if faults(t) > 0]
