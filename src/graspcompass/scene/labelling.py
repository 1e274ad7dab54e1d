"""Greedy placement of point labels so that they do not cover each other, in points.

One algorithm for every painter: the matplotlib adapter
(:func:`graspcompass.render.labels.place_labels`) and the neutral scene of the SVG
and TikZ writers (:func:`graspcompass.export._scene.build_scene`).  Nothing here
imports matplotlib; every size is in points (1/72 in) of a frame whose y axis
points up.

Each label tries eight positions around its point (NE, NW, SE, SW, N, S, E, W),
close and then twice as far; the one with the least overlap with the labels
already placed, the point markers and the drawn curves wins.  Sizes are
estimated from the font size, which is enough to keep the paper's labels
(Fig. 4-6) readable.

Examples
--------
>>> import numpy as np
>>> (p,) = place([(100.0, 100.0)], ["$O$"], frame=(0.0, 0.0, 200.0, 200.0))
>>> p.direction, p.offset
((1, 1), (4.5, 4.5))
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = [
    "FAR",
    "FONT_PT",
    "FRAME_PT",
    "GAP_PT",
    "LABEL_ORDER",
    "MARKER_PT",
    "OFFSETS",
    "RESAMPLE_PT",
    "SIZE_RULE",
    "SMALL_MARKER",
    "WEIGHTS",
    "Placement",
    "label_order",
    "place",
    "resample",
    "spec",
    "text_size",
]

#: The eight directions tried, in order of preference (NE, NW, SE, SW, N, S, E, W).
OFFSETS = ((1, 1), (-1, 1), (1, -1), (-1, -1), (0, 1), (0, -1), (1, 0), (-1, 0))

#: Side in points of the square picture the labels are placed in: the axes of
#: :func:`graspcompass.render.draw_construction`'s own 7 in figure (matplotlib's
#: default subplot, 0.77 of the height).  The SVG and TikZ writers size their text
#: so that the label font keeps the ratio :data:`FONT_PT` / :data:`FRAME_PT`.
FRAME_PT = 0.77 * 7.0 * 72.0
#: Label font, marker size and gap to the marker in points (the default theme's).
FONT_PT = 10.0
MARKER_PT = 4.0
GAP_PT = 2.5
#: A break point's marker (drawn hollow, unlabelled unless asked), as a fraction of a
#: point's, in every picture.
SMALL_MARKER = 0.6
#: Labels are placed in the order of the first letters of their names (V, P, O, X, Y).
LABEL_ORDER = "VPOXY"

#: The score of a candidate position: area (pt²) of overlap with the labels placed and
#: with the markers, number of curve samples inside, number of other points nearer to the
#: label's centre than its own point, area outside the frame, rank of the position tried.
WEIGHTS: dict[str, float] = {
    "label": 20.0,
    "marker": 60.0,
    "curve": 3.0,
    "near": 300.0,
    "frame": 50.0,
    "rank": 2.0,
}
#: Distance (pt) between the samples of the drawn curves that the labels avoid.
RESAMPLE_PT = 1.5
#: The distances tried, in units of the marker's radius plus the gap: close, then far.
FAR = (1.0, 2.0)
#: The text size estimate of :func:`text_size`, in units of the font size (and ``pad`` in
#: points): width per character, per space and per subscript character, height.
SIZE_RULE: dict[str, float] = {"char": 0.68, "space": 0.3, "sub": 0.5, "pad": 2.0, "height": 1.35}

_SUB = re.compile(r"_\{([^}]*)\}|_(\w)")


def label_order(names: Sequence[str]) -> int:
    """The rank of a group of point names in the order of placement (:data:`LABEL_ORDER`)."""
    return min(LABEL_ORDER.find(n[0]) % 9 for n in names)


def text_size(text: str, font_size: float) -> tuple[float, float]:
    """Estimated (width, height) in points of a mathtext label.

    Examples
    --------
    >>> text_size("$O$", 10.0)
    (8.8, 13.5)
    """
    body = text.replace("$", "")
    subs = "".join(a or b for a, b in _SUB.findall(body))
    main = _SUB.sub("", body).replace("\\", "")
    r = SIZE_RULE
    width = r["char"] * font_size * len(main.replace(" ", "")) + r[
        "space"
    ] * font_size * main.count(" ")
    width += r["sub"] * font_size * len(subs)
    return round(width + r["pad"], 9), round(r["height"] * font_size, 9)


def _overlap(a: np.ndarray, boxes: np.ndarray) -> float:
    if len(boxes) == 0:
        return 0.0
    w = np.clip(np.minimum(a[2], boxes[:, 2]) - np.maximum(a[0], boxes[:, 0]), 0, None)
    h = np.clip(np.minimum(a[3], boxes[:, 3]) - np.maximum(a[1], boxes[:, 1]), 0, None)
    return float((w * h).sum())


def resample(
    curves: Sequence[Any], step: float, window: tuple[float, float, float, float] | None = None
) -> np.ndarray:
    """Points every ``step`` along each segment of each polyline (an (N, 2) array).

    Each segment ``a -> b`` of length ``L`` gives ``a + (i step / L)(b - a)`` for
    ``0 <= i step < L`` (``a`` alone if ``L = 0``, nothing if ``L`` overflows); each
    polyline adds its last vertex.  Non-finite vertices are dropped.  With ``window``
    ``(x0, y0, x1, y1)`` only the points of the segments' parts in it are made (a few
    just outside too): a huge curve (a circle near a bound of condition (1)) costs what
    the window holds, and a segment too long for floats to space its points by
    ``step`` in the window (more than 2^53 steps from its start) has none there.

    Examples
    --------
    >>> resample([[(0.0, 0.0), (3.0, 0.0)]], 1.5).tolist()
    [[0.0, 0.0], [1.5, 0.0], [3.0, 0.0]]
    """
    out = [np.zeros((0, 2))]
    for c in curves:
        c = np.asarray(c, dtype=float).reshape(-1, 2)
        c = c[np.all(np.isfinite(c), axis=1)]
        if len(c) < 2:
            out.append(c)
            continue
        a = c[:-1]
        with np.errstate(over="ignore", invalid="ignore"):
            d = np.diff(c, axis=0)
            length = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1])  # as the page's port
            # a segment too long for floats (an overflowing length) has no samples
            count = np.where(
                np.isfinite(length), np.where(length > 0, np.ceil(length / step), 1.0), 0.0
            )
        lo, hi = np.zeros_like(count), count
        if window is not None:
            lo, hi = _in_window(a, d, length, step, window, count)
        n = np.clip(hi - lo, 0, None).astype(np.int64)
        if n.sum():
            seg = np.repeat(np.arange(len(a)), n)
            i = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)).astype(float)
            u = (i + np.repeat(lo, n)) * step
            f = np.divide(u, length[seg], out=np.zeros_like(u), where=length[seg] > 0)
            out.append(np.column_stack([a[seg, 0] + f * d[seg, 0], a[seg, 1] + f * d[seg, 1]]))
        out.append(c[-1:])
    return np.vstack(out)


def _in_window(
    a: np.ndarray,
    d: np.ndarray,
    length: np.ndarray,
    step: float,
    window: tuple[float, float, float, float],
    count: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """The range ``lo <= i < hi`` of the samples of each segment that may lie in
    ``window`` (Liang-Barsky on ``a + t d``, the window widened by ``step``)."""
    x0, y0, x1, y1 = window
    t0, t1 = np.zeros(len(a)), np.ones(len(a))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for p, q, lo_, hi_ in (
            (a[:, 0], d[:, 0], x0 - step, x1 + step),
            (a[:, 1], d[:, 1], y0 - step, y1 + step),
        ):
            flat = q == 0
            ta, tb = (lo_ - p) / q, (hi_ - p) / q
            ta, tb = np.minimum(ta, tb), np.maximum(ta, tb)
            out = flat & ((p < lo_) | (p > hi_))
            t0 = np.where(flat, t0, np.maximum(t0, ta))
            t1 = np.where(flat, t1, np.minimum(t1, tb))
            t1 = np.where(out, -1.0, t1)
        lo = np.clip(np.floor(t0 * length / step) - 1, 0, count)
        hi = np.clip(np.ceil(t1 * length / step) + 2, 0, count)
    # more samples than the window can hold: the segment is so long that floats cannot
    # space its points by ``step`` near the window (|a| / step > 2^53); it has none
    cap = 4.0 + np.ceil(2.0 * ((x1 - x0) + (y1 - y0)) / step)
    empty = ~(t0 <= t1) | ~np.isfinite(lo) | ~np.isfinite(hi) | (hi - lo > cap)
    return np.where(empty, 0.0, lo), np.where(empty, 0.0, hi)


@dataclass(frozen=True)
class Placement:
    """Where one label goes, in points.

    ``offset`` is from the point to the label's anchor, ``direction`` the side
    ``(dx, dy)`` in {-1, 0, 1}² (1, 1: the label's lower left corner at the
    anchor, above right of the point), ``box`` ``(x0, y0, x1, y1)`` the
    estimated extent of the label.
    """

    offset: tuple[float, float]
    direction: tuple[int, int]
    box: tuple[float, float, float, float]


def place(
    anchors: Sequence[tuple[float, float]] | np.ndarray,
    texts: Sequence[str],
    curves: Sequence[Any] = (),
    frame: tuple[float, float, float, float] | None = None,
    avoid: Sequence[tuple[float, float, float, float]] = (),
    font_size: float = FONT_PT,
    marker_size: float = MARKER_PT,
    gap: float = GAP_PT,
    obstacles: Sequence[tuple[float, float]] | np.ndarray = (),
) -> list[Placement]:
    """One :class:`Placement` per label ``texts[i]`` of the point ``anchors[i]``.

    Parameters
    ----------
    anchors : sequence of (x, y)
        The points, in points (y up), most important first.
    texts : sequence of str
        Their labels (mathtext, for the size estimate :func:`text_size`).
    curves : sequence of (N, 2) arrays
        Drawn polylines, in points, that labels should not cross.
    frame : (x0, y0, x1, y1), optional
        The visible frame; labels outside it are penalised.
    avoid : sequence of (x0, y0, x1, y1)
        Boxes of texts already drawn that labels should not cover.
    font_size, marker_size, gap : float
        In points: the label size, the marker size and the gap to the marker.
    obstacles : sequence of (x, y)
        Unlabelled markers (the envelope's break points), in points, that labels
        should not cover, as the labelled ones.
    """
    pts = np.asarray(anchors, dtype=float).reshape(-1, 2)
    r = marker_size / 2 + 1.0
    every = np.vstack([pts, np.asarray(obstacles, dtype=float).reshape(-1, 2)])
    markers = np.array([[x - r, y - r, x + r, y + r] for x, y in every]).reshape(-1, 4)
    sizes = [text_size(t, font_size) for t in texts]
    window = _reach(pts, sizes, marker_size, gap)
    curve = (
        resample([c for c in curves if len(c)], RESAMPLE_PT, window=window)
        if window is not None
        else np.zeros((0, 2))
    )
    wt = WEIGHTS
    labels: list[np.ndarray] = [np.asarray(b, dtype=float) for b in avoid]
    out: list[Placement] = []
    for i, (px, py) in enumerate(pts[: len(texts)]):
        w, h = sizes[i]
        others = np.delete(pts, i, axis=0)
        best, best_score, best_box = (0.0, 0.0, 1, 1), np.inf, np.zeros(4)
        rank = 0
        for far in FAR:
            for dx, dy in OFFSETS:
                d = (marker_size / 2 + gap) * far
                x0 = px + dx * d - (w if dx < 0 else w / 2 if dx == 0 else 0)
                y0 = py + dy * d - (h if dy < 0 else h / 2 if dy == 0 else 0)
                box = np.array([x0, y0, x0 + w, y0 + h])
                score = wt["label"] * _overlap(box, np.array(labels).reshape(-1, 4))
                score += wt["marker"] * _overlap(box, markers)
                if len(curve):
                    inside = (
                        (curve[:, 0] > box[0])
                        & (curve[:, 0] < box[2])
                        & (curve[:, 1] > box[1])
                        & (curve[:, 1] < box[3])
                    )
                    score += wt["curve"] * float(inside.sum())
                if len(others):
                    c = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
                    # squared distances: the same rounding in numpy and in the page's port
                    own = (px - c[0]) * (px - c[0]) + (py - c[1]) * (py - c[1])
                    ox_, oy_ = others[:, 0] - c[0], others[:, 1] - c[1]
                    near = ox_ * ox_ + oy_ * oy_ < own
                    score += wt["near"] * float(near.sum())
                if frame is not None:
                    out_w = max(0.0, frame[0] - box[0]) + max(0.0, box[2] - frame[2])
                    out_h = max(0.0, frame[1] - box[1]) + max(0.0, box[3] - frame[3])
                    score += wt["frame"] * (out_w + out_h) * h
                score += wt["rank"] * rank
                rank += 1
                if score < best_score:
                    best, best_score, best_box = (dx * d, dy * d, dx, dy), score, box
        labels.append(best_box)
        ox, oy, dx, dy = best
        out.append(
            Placement(
                (float(ox), float(oy)),
                (int(dx), int(dy)),
                tuple(float(v) for v in best_box),  # type: ignore[arg-type]
            )
        )
    return out


def _reach(
    pts: np.ndarray, sizes: list[tuple[float, float]], marker_size: float, gap: float
) -> tuple[float, float, float, float] | None:
    """A window holding every box tried: each point widened by the largest label size
    and the far distance (only curve samples in it can fall in a box)."""
    pts = pts[np.all(np.isfinite(pts), axis=1)]  # a box about a nan point holds nothing
    if not len(pts):
        return None
    r = max([max(w, h) for w, h in sizes] + [0.0]) + (marker_size / 2 + gap) * max(FAR) + 1.0
    return (
        float(pts[:, 0].min() - r),
        float(pts[:, 1].min() - r),
        float(pts[:, 0].max() + r),
        float(pts[:, 1].max() + r),
    )


def spec() -> dict[str, Any]:
    """The algorithm's constants as JSON data, for its port in the web page.

    The page (:mod:`graspcompass.export.html`) places its labels with a JavaScript
    port of :func:`place` (``graspcompass.placeLabels``) that reads these numbers, so
    that both run one rule; ``tests/test_web_labels.py`` checks them equal.

    Examples
    --------
    >>> spec()["offsets"][:2], spec()["weights"]["near"]
    ([[1, 1], [-1, 1]], 300.0)
    """
    return {
        "offsets": [list(o) for o in OFFSETS],
        "order": LABEL_ORDER,
        "frame": FRAME_PT,
        "font": FONT_PT,
        "marker": MARKER_PT,
        "gap": GAP_PT,
        "resample": RESAMPLE_PT,
        "far": list(FAR),
        "weights": dict(WEIGHTS),
        "size": dict(SIZE_RULE),
    }
