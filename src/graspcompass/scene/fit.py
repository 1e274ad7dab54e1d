"""Labels that name their point: placement under hard rules, and the crowded region.

:func:`fit` places point labels, in points of a frame (y up), so that no label
covers another label or any point marker (break points and the envelope's cusps
too) and each label is nearer its own point than any other point; where the
eight places next to a point are taken it tries farther ones (a thin leader
line then joins label and point).  A label that no place satisfies is left out
(:func:`crowded_region` then shows it in a zoomed inset) or, outside the region,
set where it breaks the fewest rules.  :func:`crowded_region` chooses the inset
from the geometry: the points that crowd within a fraction of the view.
Nothing here imports matplotlib.

Examples
--------
>>> (p,) = fit([(100.0, 100.0)], ["$O$"], frame=(0.0, 0.0, 200.0, 200.0))
>>> p.direction, p.leader
((0, 1), False)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from . import metrics
from .labelling import FONT_PT, GAP_PT, MARKER_PT, OFFSETS, RESAMPLE_PT, resample

__all__ = [
    "CROWD",
    "DIRECTIONS",
    "FITS",
    "LEADER",
    "MARGIN",
    "REORDER",
    "Fit",
    "crowded_region",
    "fit",
    "label_box",
    "leader",
    "spec",
]

#: The directions from the point to the label's box tried, in order of preference: the
#: eight of :data:`~.labelling.OFFSETS` (NE, NW, SE, SW, N, S, E, W), then every 15°
#: between them (the steeper ones first).
DIRECTIONS = tuple(
    (dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)) for dx, dy in OFFSETS
) + tuple(
    (math.cos(math.radians(a)), math.sin(math.radians(a)))
    for a in sorted(
        set(range(0, 360, 15)) - set(range(0, 360, 45)),
        key=lambda a: (abs(math.sin(math.radians(a))) < 0.5, a),
    )
)

#: The distances tried from the point to the label's box, in units of the marker's radius
#: plus the gap.
FITS = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.5, 6.5, 9.0)
#: From this distance of :data:`FITS` on a leader line joins label and point.
LEADER = 3.0
#: The crowd rule of :func:`crowded_region`: a point is crowded when ``count`` other
#: markers lie within ``radius`` of the frame's side from it.
CROWD: dict[str, float] = {"radius": 0.04, "count": 2, "pad": 0.1, "largest": 0.45}
#: Safety margins (points) of the rules: a label's box is grown by ``grow`` on each side
#: against the others and the markers (a marker's by ``marker``); a label must be nearer
#: its own point than any other by ``nearer``.
#: How many times :func:`fit` places the labels again, those that found no place first.
REORDER = 1
MARGIN: dict[str, float] = {"grow": 1.0, "nearer": 1.0, "marker": 0.75}

# the candidates of one label as arrays, (FITS, DIRECTIONS) in the order they are tried
_UX = np.array([[u for u, _ in DIRECTIONS]])
_UY = np.array([[v for _, v in DIRECTIONS]])
_NZX, _NZY = _UX != 0, _UY != 0
_FARS = np.array(FITS)
_SOFT = (10.0 * np.arange(len(FITS))[:, None] + 0.5 * np.arange(len(DIRECTIONS))[None, :]).ravel()


@dataclass(frozen=True)
class Fit:
    """Where one label goes, in points: as :class:`~.labelling.Placement`, plus
    ``leader`` (a line from the point to the label) and ``ok`` (every rule holds)."""

    offset: tuple[float, float]
    direction: tuple[int, int]
    box: tuple[float, float, float, float]
    leader: bool
    ok: bool


def _hits_many(box: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Per row of ``box`` (K, 4): whether it overlaps any of ``boxes`` (M, 4)."""
    if not len(boxes):
        return np.zeros(len(box), dtype=bool)
    return np.any(
        (
            np.minimum(box[:, None, 2], boxes[None, :, 2])
            > np.maximum(box[:, None, 0], boxes[None, :, 0])
        )
        & (
            np.minimum(box[:, None, 3], boxes[None, :, 3])
            > np.maximum(box[:, None, 1], boxes[None, :, 1])
        ),
        axis=1,
    )


def _dist_from_boxes(pts: np.ndarray, box: np.ndarray) -> np.ndarray:
    """Distances (K, N) from the points ``pts`` (N, 2) to each box of ``box`` (K, 4)."""
    x, y = pts[None, :, 0], pts[None, :, 1]
    dx = np.maximum(np.maximum(box[:, 0, None] - x, 0.0), x - box[:, 2, None])
    dy = np.maximum(np.maximum(box[:, 1, None] - y, 0.0), y - box[:, 3, None])
    return np.hypot(dx, dy)


def fit(
    anchors: Sequence[tuple[float, float]] | np.ndarray,
    texts: Sequence[str],
    curves: Sequence[Any] = (),
    frame: tuple[float, float, float, float] | None = None,
    obstacles: Sequence[tuple[float, float]] | np.ndarray = (),
    font_size: float = FONT_PT,
    marker_size: float = MARKER_PT,
    gap: float = GAP_PT,
    optional: Sequence[bool] = (),
    avoid: Sequence[tuple[float, float, float, float]] = (),
    marker_sizes: Sequence[float] = (),
    clear: Sequence[tuple[float, float]] | np.ndarray = (),
) -> list[Fit | None]:
    """One :class:`Fit` per label ``texts[i]`` of the point ``anchors[i]`` (or None).

    Parameters
    ----------
    anchors, texts
        The labelled points (in points, y up) and their mathtext labels.
    curves
        Drawn polylines (in points) that labels should rather not cross.
    frame
        ``(x0, y0, x1, y1)``: labels stay inside it.
    obstacles
        Other markers (break points, the envelope's cusps) that no label covers and
        that count as other points for the nearness rule.
    optional
        Per label: True leaves it out (None) when no place keeps every rule.
    avoid
        Boxes ``(x0, y0, x1, y1)`` of labels already placed.
    marker_sizes
        Per point of ``anchors`` then ``obstacles``, its marker's size where it is not
        ``marker_size``: two points are one place when their markers touch.
    clear
        Points (in points) that no label may cover, as a marker: the strokes of the
        envelope next to its cusps (:func:`graspcompass.scene.picture.build_scene`).
    """
    pts = np.asarray(anchors, dtype=float).reshape(-1, 2)
    every = np.vstack([pts, np.asarray(obstacles, dtype=float).reshape(-1, 2)])
    msize = np.full(len(every), float(marker_size))
    msize[: len(marker_sizes)] = np.asarray(marker_sizes, dtype=float)[: len(every)]
    r = msize / 2 + MARGIN["marker"]
    markers = (
        np.column_stack([every[:, 0] - r, every[:, 1] - r, every[:, 0] + r, every[:, 1] + r])
        if len(every)
        else np.zeros((0, 4))
    )
    sizes = [label_box(t, font_size) for t in texts]
    # only the curves' samples that some box tried can hold (a huge circle near a bound
    # of condition (1) costs what this window holds)
    fin = pts[np.all(np.isfinite(pts), axis=1)]
    reach = max([max(w, h) for w, h in sizes] + [0.0]) + (marker_size / 2 + gap) * max(FITS) + 1.0
    window = (
        (
            float(fin[:, 0].min() - reach),
            float(fin[:, 1].min() - reach),
            float(fin[:, 0].max() + reach),
            float(fin[:, 1].max() + reach),
        )
        if len(fin)
        else None
    )
    curves = [c for c in curves if len(c)]
    curve = resample(curves, RESAMPLE_PT, window=window) if curves and window else np.zeros((0, 2))
    keep = np.asarray(clear, dtype=float).reshape(-1, 2)
    crowd = [int(np.sum(np.hypot(*(every - p).T) < 40.0)) for p in pts]
    order = sorted(range(len(texts)), key=lambda i: -crowd[i])
    best_out: list[Fit | None] | None = None
    for _ in range(REORDER + 1):  # the labels that found no place first, again
        out = _greedy(
            order, pts, every, markers, sizes, curve, frame, msize, gap, optional, avoid, keep
        )
        fails = [i for i in order if out[i] is None or not out[i].ok]  # type: ignore[union-attr]
        if best_out is None or len(fails) < sum(f is None or not f.ok for f in best_out):
            best_out = out
        if not fails:
            break
        order = fails + [i for i in order if i not in fails]
    assert best_out is not None  # REORDER >= 0: the loop ran
    return best_out


def _greedy(
    order: list[int],
    pts: np.ndarray,
    every: np.ndarray,
    markers: np.ndarray,
    sizes: list[tuple[float, float]],
    curve: np.ndarray,
    frame: tuple[float, float, float, float] | None,
    msize: np.ndarray,
    gap: float,
    optional: Sequence[bool],
    avoid: Sequence[tuple[float, float, float, float]],
    clear: np.ndarray | None = None,
) -> list[Fit | None]:
    """The labels placed one by one in ``order``, each where it breaks the fewest rules."""
    placed: list[np.ndarray] = [np.asarray(b, dtype=float) for b in avoid]
    out: list[Fit | None] = [None] * len(sizes)
    g = MARGIN["grow"]
    for i in order:
        px, py = pts[i]
        w, h = sizes[i]
        # a marker over the point's own marker is its place too (one place to the eye)
        others = every[np.hypot(every[:, 0] - px, every[:, 1] - py) >= (msize + msize[i]) / 2]
        # every candidate at once, in the order they are tried (FITS, then DIRECTIONS):
        # the first of the lowest scores wins, as one by one
        tx, ty = np.full(_UX.shape, math.inf), np.full(_UY.shape, math.inf)
        tx[_NZX] = w / 2 / np.abs(_UX[_NZX])
        ty[_NZY] = h / 2 / np.abs(_UY[_NZY])
        t = np.minimum(tx, ty)
        d = ((msize[i] / 2 + gap) * _FARS)[:, None]
        cx, cy = (px + _UX * (d + t)).ravel(), (py + _UY * (d + t)).ravel()
        box = np.column_stack([cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2])
        big = box + np.array([-g, -g, g, g])
        bad = 100.0 * _hits_many(big, np.array(placed).reshape(-1, 4))
        bad = bad + 100.0 * _hits_many(big, markers)
        if clear is not None and len(clear):  # the envelope's strokes at its cusps
            near = clear[
                (clear[:, 0] > big[:, 0].min())
                & (clear[:, 0] < big[:, 2].max())
                & (clear[:, 1] > big[:, 1].min())
                & (clear[:, 1] < big[:, 3].max())
            ]
            if len(near):
                bad = bad + 100.0 * (
                    (near[None, :, 0] > big[:, 0, None])
                    & (near[None, :, 0] < big[:, 2, None])
                    & (near[None, :, 1] > big[:, 1, None])
                    & (near[None, :, 1] < big[:, 3, None])
                ).any(axis=1)
        if len(others):
            own = _dist_from_boxes(np.array([[px, py]]), big)[:, 0]
            near = _dist_from_boxes(others, big).min(axis=1)
            bad = bad + 100.0 * (near < own + MARGIN["nearer"])
        if frame is not None:
            bad = bad + 100.0 * (
                (box[:, 0] < frame[0])
                | (box[:, 1] < frame[1])
                | (box[:, 2] > frame[2])
                | (box[:, 3] > frame[3])
            )
        soft = _SOFT.copy()
        held = curve[
            (curve[:, 0] > box[:, 0].min())
            & (curve[:, 0] < box[:, 2].max())
            & (curve[:, 1] > box[:, 1].min())
            & (curve[:, 1] < box[:, 3].max())
        ]  # the samples some candidate box can hold
        if len(held):
            inside = (
                (held[None, :, 0] > box[:, 0, None])
                & (held[None, :, 0] < box[:, 2, None])
                & (held[None, :, 1] > box[:, 1, None])
                & (held[None, :, 1] < box[:, 3, None])
            )
            soft = soft + 1.5 * inside.sum(axis=1)
        j = int(np.argmin(bad * 1000.0 + soft))
        b = box[j]
        # the side of the point the whole box is on (0: across it)
        dx = 1 if b[0] >= px else -1 if b[2] <= px else 0
        dy = 1 if b[1] >= py else -1 if b[3] <= py else 0
        ax = b[0] if dx > 0 else b[2] if dx < 0 else cx[j]
        ay = b[1] if dy > 0 else b[3] if dy < 0 else cy[j]
        far = FITS[j // len(DIRECTIONS)]
        f = Fit(
            (float(ax - px), float(ay - py)),
            (dx, dy),
            tuple(float(v) for v in b),  # type: ignore[arg-type]
            far >= LEADER,
            bool(bad[j] == 0.0),
        )
        if not f.ok and i < len(optional) and optional[i]:
            continue
        placed.append(np.asarray(f.box))
        out[i] = f
    return out


def label_box(text: str, font_size: float) -> tuple[float, float]:
    """``(width, height)`` of a label's box: its drawn text (:mod:`.metrics`), in points.

    Examples
    --------
    >>> [round(v, 2) for v in label_box("$O$", 10.0)]
    [7.87, 11.64]
    """
    w, up, down = metrics.extent(text, font_size)
    return w, up + down


def crowded_region(
    anchors: Sequence[tuple[float, float]] | np.ndarray,
    markers: Sequence[tuple[float, float]] | np.ndarray,
    side: float,
) -> tuple[float, float, float, float] | None:
    """The square ``(x0, y0, x1, y1)`` of the points that crowd, in the frame's units.

    A point is crowded when :data:`CROWD` ``count`` other markers lie within
    ``radius · side`` of it; the region holds the crowded points and their near
    neighbours, widened by ``pad`` of its size (and at least the radius), square.
    None when nothing crowds or the region would exceed ``largest · side`` (no zoom).

    Examples
    --------
    >>> crowded_region([(0, 0), (5, 0), (0, 5), (5, 5)], [], 400.0)
    (-8.0, -8.0, 13.0, 13.0)
    >>> crowded_region([(0, 0), (300, 0)], [], 400.0) is None
    True
    """
    pts = np.asarray(anchors, dtype=float).reshape(-1, 2)
    every = np.vstack([pts, np.asarray(markers, dtype=float).reshape(-1, 2)])
    if len(pts) < 2:
        return None
    radius = CROWD["radius"] * side
    dist = np.hypot(every[:, None, 0] - pts[None, :, 0], every[:, None, 1] - pts[None, :, 1])
    crowded = (dist < radius).sum(axis=0) - 1 >= CROWD["count"]
    if not crowded.any():
        return None
    keep = (dist[:, crowded] < radius).any(axis=1)
    sel = every[keep]
    (x0, y0), (x1, y1) = sel.min(axis=0), sel.max(axis=0)
    size = max(x1 - x0, y1 - y0)
    size += max(2 * CROWD["pad"] * size, radius)
    if size > CROWD["largest"] * side:
        return None
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    return (float(cx - size / 2), float(cy - size / 2), float(cx + size / 2), float(cy + size / 2))


def leader(
    point: tuple[float, float], box: tuple[float, float, float, float]
) -> tuple[tuple[float, float], tuple[float, float]]:
    """The leader line from ``point`` to the nearest point of ``box`` (same units)."""
    x = min(max(point[0], box[0]), box[2])
    y = min(max(point[1], box[1]), box[3])
    end = (float(x), float(y)) if math.hypot(x - point[0], y - point[1]) > 0 else point
    return point, end


def spec() -> dict[str, Any]:
    """The constants of :func:`fit` as JSON data, for its port in the web page
    (``GCLabelling.fit`` in ``labelling.js``; ``tests/test_web_labels.py`` checks both).

    Examples
    --------
    >>> spec()["fits"][0], spec()["metrics"]["widths"][0]
    (1.0, 651)
    """
    return {
        "directions": [list(d) for d in DIRECTIONS],
        "fits": list(FITS),
        "leader": LEADER,
        "reorder": REORDER,
        "margin": dict(MARGIN),
        "font": FONT_PT,
        "marker": MARKER_PT,
        "gap": GAP_PT,
        "resample": RESAMPLE_PT,
        "metrics": {
            "widths": list(metrics.WIDTHS),
            "ascent": metrics.ASCENT,
            "descent": metrics.DESCENT,
            "sub_scale": metrics.SUB_SCALE,
            "sub_shift": metrics.SUB_SHIFT,
            "family": metrics.FAMILY,
        },
    }
