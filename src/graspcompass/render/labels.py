"""Greedy placement of point labels so that they do not cover each other.

Each label tries eight positions around its point (NE, NW, SE, SW, N, S, E,
W); the one with the least overlap with the labels already placed, the point
markers and the drawn curves wins.  Sizes are estimated from the font size,
which is enough to keep the paper's labels (Fig. 4-6) readable.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.text import Text

__all__ = ["place_labels"]

_OFFSETS = ((1, 1), (-1, 1), (1, -1), (-1, -1), (0, 1), (0, -1), (1, 0), (-1, 0))
_HA = {1: "left", -1: "right", 0: "center"}
_VA = {1: "bottom", -1: "top", 0: "center"}
_SUB = re.compile(r"_\{([^}]*)\}|_(\w)")


def _text_size(text: str, font_size: float) -> tuple[float, float]:
    """Estimated (width, height) in points of a mathtext label."""
    body = text.replace("$", "")
    subs = "".join(a or b for a, b in _SUB.findall(body))
    main = _SUB.sub("", body).replace("\\", "")
    width = 0.68 * font_size * len(main.replace(" ", "")) + 0.3 * font_size * main.count(" ")
    width += 0.5 * font_size * len(subs)
    return width + 2.0, 1.35 * font_size


def _overlap(a: np.ndarray, boxes: np.ndarray) -> float:
    if len(boxes) == 0:
        return 0.0
    w = np.clip(np.minimum(a[2], boxes[:, 2]) - np.maximum(a[0], boxes[:, 0]), 0, None)
    h = np.clip(np.minimum(a[3], boxes[:, 3]) - np.maximum(a[1], boxes[:, 1]), 0, None)
    return float((w * h).sum())


def _box_distance(box: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Distance from each point of ``pts`` to the rectangle ``box``."""
    dx = np.maximum(np.maximum(box[0] - pts[:, 0], pts[:, 0] - box[2]), 0.0)
    dy = np.maximum(np.maximum(box[1] - pts[:, 1], pts[:, 1] - box[3]), 0.0)
    return np.hypot(dx, dy)


def _resample(curves: Sequence[np.ndarray], step: float) -> np.ndarray:
    """Points every ``step`` (display units) along each polyline."""
    out = [np.zeros((0, 2))]
    for c in curves:
        c = c[np.all(np.isfinite(c), axis=1)]
        if len(c) < 2:
            out.append(c)
            continue
        s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(c, axis=0).T))])
        t = np.arange(0.0, s[-1] + step, step)
        out.append(np.column_stack([np.interp(t, s, c[:, 0]), np.interp(t, s, c[:, 1])]))
    return np.vstack(out)


def place_labels(ax: Axes, items: Sequence[tuple[tuple[float, float], str]],
                 curves: Sequence[np.ndarray] = (), avoid: Sequence[Text] = (),
                 font_size: float = 10.0, marker_size: float = 4.0, gap: float = 2.5,
                 **text_kw: Any) -> list[Text]:
    """Add one text per ``(xy, label)`` of ``items`` at a free place around ``xy``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes whose limits are already set.
    items : sequence of ((x, y), str)
        Points in data coordinates and their labels, most important first.
    curves : sequence of (N, 2) arrays
        Drawn polylines, in data coordinates, that labels should not cross.
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
    """
    fig = ax.figure
    ax.apply_aspect()
    to_pt = 72.0 / fig.dpi
    trans = ax.transData

    def disp(xy: Any) -> np.ndarray:
        return np.asarray(trans.transform(np.asarray(xy, dtype=float))) * to_pt

    frame = ax.bbox.extents * to_pt
    anchors = disp([xy for xy, _ in items]) if items else np.zeros((0, 2))
    r = marker_size / 2 + 1.0
    markers = np.array([[x - r, y - r, x + r, y + r] for x, y in anchors]).reshape(-1, 4)
    curve = _resample([disp(c) for c in curves if len(c)], 1.5)
    labels: list[np.ndarray] = [np.asarray(t.get_window_extent().extents) * to_pt
                                for t in avoid]
    texts = []
    for i, ((xy, label), (px, py)) in enumerate(zip(items, anchors)):
        w, h = _text_size(label, font_size)
        others = np.delete(anchors, i, axis=0)
        best, best_score, best_box = (0.0, 0.0, 1, 1), np.inf, np.zeros(4)
        rank = 0
        for far in (1.0, 2.0):
            for dx, dy in _OFFSETS:
                d = (marker_size / 2 + gap) * far
                x0 = px + dx * d - (w if dx < 0 else w / 2 if dx == 0 else 0)
                y0 = py + dy * d - (h if dy < 0 else h / 2 if dy == 0 else 0)
                box = np.array([x0, y0, x0 + w, y0 + h])
                score = 20.0 * _overlap(box, np.array(labels).reshape(-1, 4))
                score += 60.0 * _overlap(box, markers)
                if len(curve):
                    inside = ((curve[:, 0] > box[0]) & (curve[:, 0] < box[2])
                              & (curve[:, 1] > box[1]) & (curve[:, 1] < box[3]))
                    score += 3.0 * float(inside.sum())
                if len(others):
                    c = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
                    own = float(np.hypot(px - c[0], py - c[1]))
                    near = np.hypot(others[:, 0] - c[0], others[:, 1] - c[1]) < own
                    score += 300.0 * float(near.sum())
                out_w = max(0.0, frame[0] - box[0]) + max(0.0, box[2] - frame[2])
                out_h = max(0.0, frame[1] - box[1]) + max(0.0, box[3] - frame[3])
                score += 50.0 * (out_w + out_h) * h + 2.0 * rank
                rank += 1
                if score < best_score:
                    best, best_score, best_box = (dx * d, dy * d, dx, dy), score, box
        labels.append(best_box)
        ox, oy, dx, dy = best
        texts.append(ax.annotate(
            label, xy, xytext=(ox, oy), textcoords="offset points",
            ha=_HA[dx], va=_VA[dy], fontsize=font_size, annotation_clip=False, **text_kw))
    return texts
