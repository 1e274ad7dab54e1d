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
#: Labels are placed in the order of the first letters of their names (V, P, O, X, Y).
LABEL_ORDER = "VPOXY"

#: The score of a candidate position: area (pt²) of overlap with the labels placed and
#: with the markers, number of curve samples inside, number of other points nearer to the
#: label's centre than its own point, area outside the frame, rank of the position tried.
WEIGHTS: dict[str, float] = {"label": 20.0, "marker": 60.0, "curve": 3.0, "near": 300.0,
                             "frame": 50.0, "rank": 2.0}
#: Distance (pt) between the samples of the drawn curves that the labels avoid.
RESAMPLE_PT = 1.5
#: The distances tried, in units of the marker's radius plus the gap: close, then far.
FAR = (1.0, 2.0)
#: The text size estimate of :func:`text_size`, in units of the font size (and ``pad`` in
#: points): width per character, per space and per subscript character, height.
SIZE_RULE: dict[str, float] = {"char": 0.68, "space": 0.3, "sub": 0.5, "pad": 2.0,
                               "height": 1.35}

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
    width = (r["char"] * font_size * len(main.replace(" ", ""))
             + r["space"] * font_size * main.count(" "))
    width += r["sub"] * font_size * len(subs)
    return round(width + r["pad"], 9), round(r["height"] * font_size, 9)


def _overlap(a: np.ndarray, boxes: np.ndarray) -> float:
    if len(boxes) == 0:
        return 0.0
    w = np.clip(np.minimum(a[2], boxes[:, 2]) - np.maximum(a[0], boxes[:, 0]), 0, None)
    h = np.clip(np.minimum(a[3], boxes[:, 3]) - np.maximum(a[1], boxes[:, 1]), 0, None)
    return float((w * h).sum())


def resample(curves: Sequence[Any], step: float) -> np.ndarray:
    """Points every ``step`` along each polyline (an (N, 2) array)."""
    out = [np.zeros((0, 2))]
    for c in curves:
        c = np.asarray(c, dtype=float).reshape(-1, 2)
        c = c[np.all(np.isfinite(c), axis=1)]
        if len(c) < 2:
            out.append(c)
            continue
        d = np.diff(c, axis=0)  # sqrt of squares, not hypot: the page's port rounds alike
        s = np.concatenate([[0.0], np.cumsum(np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1]))])
        t = np.arange(0.0, s[-1] + step, step)
        out.append(np.column_stack([np.interp(t, s, c[:, 0]), np.interp(t, s, c[:, 1])]))
    return np.vstack(out)


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


def place(anchors: Sequence[tuple[float, float]], texts: Sequence[str],
          curves: Sequence[Any] = (), frame: tuple[float, float, float, float] | None = None,
          avoid: Sequence[tuple[float, float, float, float]] = (),
          font_size: float = FONT_PT, marker_size: float = MARKER_PT,
          gap: float = GAP_PT, obstacles: Sequence[tuple[float, float]] = ()
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
    curve = resample([c for c in curves if len(c)], RESAMPLE_PT)
    wt = WEIGHTS
    labels: list[np.ndarray] = [np.asarray(b, dtype=float) for b in avoid]
    out: list[Placement] = []
    for i, (label, (px, py)) in enumerate(zip(texts, pts)):
        w, h = text_size(label, font_size)
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
                    inside = ((curve[:, 0] > box[0]) & (curve[:, 0] < box[2])
                              & (curve[:, 1] > box[1]) & (curve[:, 1] < box[3]))
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
        out.append(Placement((float(ox), float(oy)), (int(dx), int(dy)),
                             tuple(float(v) for v in best_box)))  # type: ignore[arg-type]
    return out


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
    return {"offsets": [list(o) for o in OFFSETS], "order": LABEL_ORDER, "frame": FRAME_PT,
            "font": FONT_PT, "marker": MARKER_PT, "gap": GAP_PT, "resample": RESAMPLE_PT,
            "far": list(FAR), "weights": dict(WEIGHTS), "size": dict(SIZE_RULE)}
