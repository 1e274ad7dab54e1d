"""Label placement of the scene (:func:`labels_of`): the main frame and the inset.

Part of the one picture model (:mod:`graspcompass.scene.picture`, issue 23): the labels
of the groups of points are placed by :func:`graspcompass.scene.fit.fit` in points of a
frame :data:`~graspcompass.scene.labelling.FRAME_PT` wide, and those of a crowded region
again in a zoomed inset.  Nothing here imports matplotlib.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import fit as fitting
from . import labelling, layout
from ._values import INSET_PT, INSET_SHRINK, Arc, Inset, Label
from .layout import label_tex

__all__ = ["labels_of"]

XY = tuple[float, float]
Box = tuple[float, float, float, float]


def _arc_points(a: Arc) -> np.ndarray:
    if a.n == 0:
        return np.array([a.start, a.end])
    t = np.radians(a.start_angle + a.delta * np.linspace(0.0, 1.0, max(2, int(abs(a.delta)))))
    return np.column_stack([a.center[0] + a.radius * np.cos(t), a.center[1] + a.radius * np.sin(t)])


def labels_of(
    box: Box,
    groups: list[tuple[tuple[str, ...], XY]],
    lines: list[Any],
    lengths: list[Any],
    circles: list[Any],
    envelope: tuple[Arc, ...],
    obstacles: list[XY],
    font_pt: float = labelling.FONT_PT,
) -> tuple[tuple[Label, ...], Inset | None]:
    """The labels of ``groups`` in the main frame and, where points crowd, in an inset.

    The main frame's labels name every point (a painter without the inset reads
    them); :attr:`Inset.main` are those of the main frame beside the inset.

    Placed by :func:`graspcompass.scene.fit.fit` in points of a frame of
    :data:`~graspcompass.scene.labelling.FRAME_PT` (the PNG's axes).  A point of the
    crowded region whose label breaks a rule in the main frame is named in the inset only.
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
        members = [anchors[j] for i in idx for j in joined[i] if j != i]
        members += [
            xy
            for j, xy in enumerate(anchors)
            if not keep[j] and frame[0] <= xy[0] <= frame[1] and frame[2] <= xy[1] <= frame[3]
        ]
        fits = fitting.fit(
            to_pt([anchors[i] for i in idx], frame, scale),
            [text_of[i] for i in idx],
            curves=[to_pt(c, frame, scale) for c in curves],
            frame=(0.0, 0.0, (frame[1] - frame[0]) * scale, height),
            obstacles=np.vstack([to_pt(obstacles, frame, scale), to_pt(members, frame, scale)]),
            optional=[optional[i] for i in idx],
            font_size=font_pt,
            # the break points and cusps are drawn small
            marker_sizes=[labelling.MARKER_PT] * len(idx)
            + [labelling.MARKER_PT * labelling.SMALL_MARKER] * len(obstacles)
            + [labelling.MARKER_PT] * len(members),
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
    beside = placed(box, s, every, within, (box[3] - box[2]) * s)
    if region is None:
        return beside, None
    # the labels left to the inset, set where they break the fewest rules, for the
    # painters without the inset
    done = {n for lab in beside for n in lab.names}
    rest = [not (within[i] and order[i][0][0] not in done) for i in range(len(order))]
    rest = [not r for r in rest]
    more = placed(box, s, rest, [False] * len(order), (box[3] - box[2]) * s, avoid=beside)
    main = tuple(sorted(beside + more, key=lambda lab: labelling.label_order(lab.names)))
    # the inset: the region, zoomed further (about the points left to it) while some
    # label breaks a rule there, as long as it holds every point left to it; a point
    # named in the whole view is named in the inset only where a place keeps every rule
    left = [within[i] and order[i][0][0] not in done for i in range(len(order))]
    mine = np.array([xy for xy, k in zip(anchors, left) if k]).reshape(-1, 2)
    best: tuple[tuple[int, float], Inset] | None = None
    for shrink in INSET_SHRINK:
        half = (region[2] - region[0]) * shrink / 2 / s
        if len(mine):
            lo, hi = mine.min(axis=0), mine.max(axis=0)
            half = max(half, float((hi - lo).max()) / 2 * 1.25)
            cx, cy = (lo + hi) / 2
        else:
            cx = box[0] + (region[0] + region[2]) / 2 / s
            cy = box[2] + (region[1] + region[3]) / 2 / s
        sub = (cx - half, cx + half, cy - half, cy + half)
        inside = [sub[0] <= x <= sub[1] and sub[2] <= y <= sub[3] for x, y in anchors]
        optional = [a and not b for a, b in zip(inside, left)]
        z = INSET_PT / (sub[1] - sub[0])
        labs = placed(sub, z, inside, optional, INSET_PT)
        key = (broken[-1], shrink and -shrink)
        if best is None or key < best[0]:
            best = (key, Inset(sub, labs, beside))
        if broken[-1] == 0:
            break
    assert best is not None
    return main, best[1]
