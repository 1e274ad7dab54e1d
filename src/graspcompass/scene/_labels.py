"""Label placement of the scene (:func:`labels_of`): the main frame and the inset.

Part of the one picture model (:mod:`graspcompass.scene.picture`, issue 23): the labels
of the groups of points are placed by :func:`graspcompass.scene.fit.fit` in points of a
frame :data:`~graspcompass.scene.labelling.FRAME_PT` wide, and those of a crowded region
again in a zoomed inset.  Nothing here imports matplotlib.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from . import fit as fitting
from . import labelling, layout
from ._numbers import numbered
from ._values import INSET_PT, INSET_SHRINK, LEAST_INSET, MAX_INSETS, Arc, Inset, Label
from .layout import label_tex

__all__ = ["labels_of"]

#: Points whose labels have no place in the whole view, closer than this fraction of
#: its side, share one inset.
_LINK = 0.12

XY = tuple[float, float]
Box = tuple[float, float, float, float]


def _arc_points(a: Arc) -> np.ndarray:
    if a.n == 0:
        return np.array([a.start, a.end])
    t = np.radians(a.start_angle + a.delta * np.linspace(0.0, 1.0, max(2, int(abs(a.delta)))))
    return np.column_stack([a.center[0] + a.radius * np.cos(t), a.center[1] + a.radius * np.sin(t)])


#: The envelope's strokes this far from a cusp (a joint of two arcs), in points (about a
#: label's height), are kept clear of labels: a label's box hid the cusp at O (issue 23).
CUSP_CLEAR_PT = 14.0


def _cusp_strokes(envelope: tuple[Arc, ...], frame: Box, scale: float) -> np.ndarray:
    """Points a point apart along the envelope's strokes within :data:`CUSP_CLEAR_PT` of
    each joint of its arcs, in points of ``frame`` at ``scale`` points per unit.

    >>> a = Arc(1, (1.0, 0.0), (0.0, 1.0), (0.0, 0.0), 1.0, 0.0, 90.0)
    >>> pts = _cusp_strokes((a,), (-1.0, 1.0, -1.0, 1.0), 100.0)
    >>> ends = np.array([[200.0, 100.0], [100.0, 200.0]])  # the arc's ends, in points
    >>> near = np.hypot(*(pts[:, None, :] - ends[None]).transpose(2, 0, 1)).min(axis=1)
    >>> len(pts), bool(near.max() <= CUSP_CLEAR_PT + 1e-9)
    (30, True)
    """
    out = []
    n = int(CUSP_CLEAR_PT) + 1
    for a in envelope:
        if a.n == 0 or a.radius <= 0.0:
            (x0, y0), (x1, y1) = a.start, a.end
            length = math.hypot(x1 - x0, y1 - y0) * scale
            if length == 0.0:
                continue
            for t in np.linspace(0.0, min(1.0, CUSP_CLEAR_PT / length), n):
                out += [(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t)]
                out += [(x1 + (x0 - x1) * t, y1 + (y0 - y1) * t)]
            continue
        span = math.radians(abs(a.delta))
        reach = min(span, CUSP_CLEAR_PT / (a.radius * scale))
        sign = 1.0 if a.delta >= 0 else -1.0
        t0 = math.radians(a.start_angle)
        for u in np.linspace(0.0, reach, n):
            for t in (t0 + sign * u, t0 + sign * (span - u)):
                out.append(
                    (a.center[0] + a.radius * math.cos(t), a.center[1] + a.radius * math.sin(t))
                )
    if not out:
        return np.zeros((0, 2))
    xy = np.asarray(out, dtype=float)
    return np.column_stack([(xy[:, 0] - frame[0]) * scale, (xy[:, 1] - frame[2]) * scale])


def labels_of(
    box: Box,
    groups: list[tuple[tuple[str, ...], XY]],
    lines: list[Any],
    lengths: list[Any],
    circles: list[Any],
    envelope: tuple[Arc, ...],
    obstacles: list[XY],
    font_pt: float = labelling.FONT_PT,
    with_insets: bool = True,
    small: frozenset[str] = frozenset(),
) -> tuple[tuple[Label, ...], tuple[Inset, ...]]:
    """The labels of ``groups`` in the main frame and, where points crowd, in insets.

    The main frame's labels name every point (a painter without the insets reads
    them); :attr:`Inset.main` are those of the main frame beside the insets.

    Placed by :func:`graspcompass.scene.fit.fit` in points of a frame of
    :data:`~graspcompass.scene.labelling.FRAME_PT` (the PNG's axes).  The first inset
    is the crowded region the geometry gives (:func:`graspcompass.scene.fit.crowded_region`),
    if any; each other crowd of points whose labels have no place keeping every rule
    in the main frame gets an inset of its own (at most :data:`MAX_INSETS`).  A point
    whose label breaks a rule in the main frame is named in its inset only.
    ``with_insets`` false: the main frame's labels only (for a painter that zooms on its
    own, an animation).  ``small``: the names of the points drawn small (break points).
    """
    side = labelling.FRAME_PT
    s = side / (box[1] - box[0])
    t = np.linspace(0, 2 * np.pi, 100)
    curves = [np.asarray([a, b], dtype=float) for _, _, a, b in lines]
    curves += [
        np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)]) for _, _, c, r in circles
    ]
    curves += [np.asarray([a, b], dtype=float) for _, a, b in lengths]
    if envelope:
        curves.append(np.vstack([_arc_points(a) for a in envelope]))
    order = sorted(groups, key=lambda g: labelling.label_order(g[0]))
    anchors = [xy for _, xy in order]
    # each point's marker as drawn: a break point's small
    size = [
        labelling.MARKER_PT * (labelling.SMALL_MARKER if set(names) <= small else 1.0)
        for names, _ in order
    ]

    def to_pt(xy: Any, frame: Box, scale: float) -> np.ndarray:
        a = np.asarray(xy, dtype=float).reshape(-1, 2)
        return np.column_stack([(a[:, 0] - frame[0]) * scale, (a[:, 1] - frame[2]) * scale])

    region = fitting.crowded_region(to_pt(anchors, box, s), to_pt(obstacles, box, s), side)
    within = [False] * len(order)
    if region is not None:
        within = [
            region[0] <= x <= region[2] and region[1] <= y <= region[3]
            for x, y in to_pt(anchors, box, s)
        ]

    def placed(
        frame: Box,
        scale: float,
        keep: list[bool],
        optional: list[bool],
        height: float,
        avoid: tuple[Label, ...] = (),
    ) -> tuple[Label, ...]:
        idx = [i for i, k in enumerate(keep) if k]
        # groups closer than a marker are one place to the eye: one label names them all
        near = layout.group_points(
            [(str(i), (anchors[i][0] * scale, anchors[i][1] * scale)) for i in idx],
            labelling.MARKER_PT,
        )
        joined = {int(g[0]): [int(j) for j in g] for g, _ in near}
        idx = [i for i in idx if i in joined]
        names_of = {i: tuple(n for j in joined[i] for n in order[j][0]) for i in idx}
        group_of = {i: tuple(k for k, j in enumerate(joined[i]) for _ in order[j][0]) for i in idx}
        text_of = {
            i: "$"
            + ", ".join(" = ".join(label_tex(n) for n in order[j][0]) for j in joined[i])
            + "$"
            for i in idx
        }
        # the other points of a label's group, and the points in the frame left to
        # another placement: markers no label covers
        others = [j for i in idx for j in joined[i] if j != i]
        others += [
            j
            for j, (x, y) in enumerate(anchors)
            if not keep[j] and frame[0] <= x <= frame[1] and frame[2] <= y <= frame[3]
        ]
        members = [anchors[j] for j in others]
        fits = fitting.fit(
            to_pt([anchors[i] for i in idx], frame, scale),
            [text_of[i] for i in idx],
            curves=[to_pt(c, frame, scale) for c in curves],
            frame=(0.0, 0.0, (frame[1] - frame[0]) * scale, height),
            obstacles=np.vstack([to_pt(obstacles, frame, scale), to_pt(members, frame, scale)]),
            optional=[optional[i] for i in idx],
            font_size=font_pt,
            # the break points and cusps are drawn small
            marker_sizes=[size[i] for i in idx]
            + [labelling.MARKER_PT * labelling.SMALL_MARKER] * len(obstacles)
            + [size[j] for j in others],
            clear=_cusp_strokes(envelope, frame, scale),
            avoid=[
                (
                    (b[0] - frame[0]) * scale,
                    (b[1] - frame[2]) * scale,
                    (b[2] - frame[0]) * scale,
                    (b[3] - frame[2]) * scale,
                )
                for b in (lab.box for lab in avoid)
            ],
        )
        out = []
        broken.append(sum(p is not None and not p.ok for p in fits))
        for i, p in zip(idx, fits):
            if p is None:
                continue
            xy, (x0, y0, x1, y1) = order[i][1], p.box
            out.append(
                Label(
                    names_of[i],
                    (xy[0] + p.offset[0] / scale, xy[1] + p.offset[1] / scale),
                    p.direction,
                    (
                        frame[0] + x0 / scale,
                        frame[2] + y0 / scale,
                        frame[0] + x1 / scale,
                        frame[2] + y1 / scale,
                    ),
                    p.offset,
                    xy,
                    p.leader,
                    group_of[i],
                    p.ok,
                )
            )
        return tuple(out)

    broken: list[int] = []  # per call of placed: how many labels break a rule
    every = [True] * len(order)
    height = (box[3] - box[2]) * s
    beside = placed(box, s, every, within, height)
    named = {n for lab in beside if lab.ok for n in lab.names}
    failing = [order[i][0][0] not in named for i in range(len(order))]
    if region is None and not any(failing):
        return beside, ()
    # the labels left out of the whole view, set where they break the fewest rules, for
    # the painters without an inset
    dropped = {n for lab in beside for n in lab.names}
    rest = [order[i][0][0] not in dropped for i in range(len(order))]
    more = placed(box, s, rest, [False] * len(order), height, avoid=beside) if any(rest) else ()
    main = tuple(sorted(beside + more, key=lambda lab: labelling.label_order(lab.names)))
    if not with_insets:
        return main, ()
    # the insets: the crowded region (the geometry's), and a square about each crowd of
    # the other points whose labels have no place keeping the rules in the whole view
    pts = to_pt(anchors, box, s)
    Area = tuple[float, float, float, float] | None
    # (the crowded region or None, the points left to the inset, the side of the view
    # the crowd is in: the whole view's, or an inset's for a crowd within it)
    queue: list[tuple[Area, list[bool], float]] = []
    if region is not None:
        queue.append((region, [within[i] and failing[i] for i in range(len(order))], side))
    queue += _crowds([failing[i] and not within[i] for i in range(len(order))], pts, side)
    insets: list[Inset] = []
    while queue and len(insets) < MAX_INSETS:
        area, left, around = queue.pop(0)
        ins = _inset(area, left, pts, anchors, box, s, around, placed, broken)
        if around < side and (ins.box[1] - ins.box[0]) * s * 1.5 > around:
            continue  # no closer than the inset it is in
        insets.append(ins)
        # a crowd within it whose labels break a rule there: a closer inset of its own
        bad = {n for lab in ins.labels if not lab.ok for n in lab.names}
        inner = [order[i][0][0] in bad for i in range(len(order))]
        queue += _crowds(inner, pts, (ins.box[1] - ins.box[0]) * s)

    def later(k: int, lab: Label) -> bool:
        """Whether an inset after the ``k``-th (-1: the whole view) names ``lab``'s points."""
        names = {n for ins in insets[k + 1 :] for one in ins.labels for n in one.names}
        return set(lab.names) <= names

    # the whole view beside the insets, and each inset: a label breaking a rule is left
    # to a later inset that names its points
    keep = tuple(lab for lab in beside if lab.ok or not later(-1, lab))
    shown = tuple(
        replace(ins, main=keep, labels=tuple(x for x in ins.labels if x.ok or not later(k, x)))
        for k, ins in enumerate(insets)
    )
    markers = [(xy, size[i]) for i, xy in enumerate(anchors)]
    markers += [(xy, labelling.MARKER_PT * labelling.SMALL_MARKER) for xy in obstacles]
    return main, numbered(shown, box, s, keep, markers, font_pt)


def _crowds(
    flags: list[bool], pts: np.ndarray, side: float
) -> list[tuple[None, list[bool], float]]:
    """The points ``flags`` picks, in crowds (closer than :data:`_LINK` of ``side``, the
    side of the view they are in), the most points first: one inset each."""
    idx = [i for i, f in enumerate(flags) if f]
    sets = [{idx[j] for j in g} for g in _clusters([tuple(pts[i]) for i in idx], _LINK * side)]
    return [
        (None, [i in g for i in range(len(flags))], side)
        for g in sorted(sets, key=len, reverse=True)
    ]


def _clusters(pts: list[tuple[float, float]], link: float) -> list[list[int]]:
    """Indices of ``pts`` in groups: two points closer than ``link`` are in one group."""
    groups: list[list[int]] = []
    for i, p in enumerate(pts):
        near = [g for g in groups if any(math.dist(p, pts[j]) <= link for j in g)]
        groups = [g for g in groups if all(g is not h for h in near)]
        groups.append([i, *(j for g in near for j in g)])
    return groups


def _inset(
    area: tuple[float, float, float, float] | None,
    left: list[bool],
    pts: np.ndarray,
    anchors: list[XY],
    box: Box,
    s: float,
    side: float,
    placed: Any,
    broken: list[int],
) -> Inset:
    """The zoomed inset of a crowd: ``area`` (the crowded region, in points of the
    frame) or a square about the points ``left`` to it, zoomed further about those
    points while some label breaks a rule there, as long as it holds them all; a point
    named in the whole view is named in the inset only where a place keeps every rule."""
    mine = np.array([xy for xy, k in zip(anchors, left) if k]).reshape(-1, 2)
    if area is None:  # a square about the points left to it, at least LEAST_INSET wide
        lo, hi = pts[np.array(left)].min(axis=0), pts[np.array(left)].max(axis=0)
        size = max(float((hi - lo).max()) * (1 + 2 * fitting.CROWD["pad"]), LEAST_INSET * side)
        c = (lo + hi) / 2
        area = (c[0] - size / 2, c[1] - size / 2, c[0] + size / 2, c[1] + size / 2)
    best: tuple[tuple[int, float], Inset] | None = None
    for shrink in INSET_SHRINK:
        half = (area[2] - area[0]) * shrink / 2 / s
        if len(mine):
            lo, hi = mine.min(axis=0), mine.max(axis=0)
            half = max(half, float((hi - lo).max()) / 2 * 1.25)
            cx, cy = (lo + hi) / 2
        else:
            cx = box[0] + (area[0] + area[2]) / 2 / s
            cy = box[2] + (area[1] + area[3]) / 2 / s
        sub = (cx - half, cx + half, cy - half, cy + half)
        inside = [sub[0] <= x <= sub[1] and sub[2] <= y <= sub[3] for x, y in anchors]
        optional = [a and not b for a, b in zip(inside, left)]
        z = INSET_PT / (sub[1] - sub[0])
        labs = placed(sub, z, inside, optional, INSET_PT)
        key = (broken[-1], shrink and -shrink)
        if best is None or key < best[0]:
            best = (key, Inset(sub, labs))
        if broken[-1] == 0:
            break
    assert best is not None
    return best[1]
