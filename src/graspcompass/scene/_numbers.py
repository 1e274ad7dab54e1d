"""The numbers of the dashed squares (:attr:`Inset.number`), where they cover nothing.

With two insets or more the whole view numbers each square as its inset.  A number sits
just outside a corner or the middle of a side of its square, at the first of those
places where it covers no label, no point marker and no other number, inside the
view, and crosses no dashed square; where none is free next to the square (a square
nested in a small one), farther out; where nothing is free, where it covers least.
Found by a hostile run of issue 23: set always above the upper left corner, the
numbers covered labels in 45 and markers in 51 of 244 SVGs of random grasps.
Nothing here imports matplotlib.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from . import labelling
from ._values import Box, Inset, Label

__all__ = ["NUMBER_SCALE", "numbered"]

#: The numbers' font, a fraction of the labels'.
NUMBER_SCALE = 0.8

#: Sides of the square tried, in order: (corner or middle of a side, outward direction).
_PLACES = (
    ((0, 1), (-1, 1)),  # above the upper left corner, to its left
    ((1, 1), (1, 1)),
    ((0, 0), (-1, -1)),
    ((1, 0), (1, -1)),
    ((0, 0.5), (-1, 0)),
    ((1, 0.5), (1, 0)),
    ((0.5, 1), (0, 1)),
    ((0.5, 0), (0, -1)),
)

#: Distances tried beyond the gap, in the number's size: next to the square first.
_RINGS = (0.0, 0.75, 1.5, 2.5, 4.0)

XY = tuple[float, float]


def _overlap(a: Sequence[float], b: Sequence[float]) -> float:
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return max(w, 0.0) * max(h, 0.0)


def _crosses(a: Sequence[float], sq: Box) -> bool:
    """Whether the box ``a`` (x0, y0, x1, y1) crosses an edge of the square ``sq``."""
    inside = a[0] > sq[0] and a[2] < sq[1] and a[1] > sq[2] and a[3] < sq[3]
    outside = a[2] < sq[0] or a[0] > sq[1] or a[3] < sq[2] or a[1] > sq[3]
    return not (inside or outside)


def numbered(
    insets: tuple[Inset, ...],
    view: Box,
    scale: float,
    labels: Sequence[Label],
    markers: Sequence[tuple[XY, float]],
    font_pt: float = labelling.FONT_PT,
) -> tuple[Inset, ...]:
    """``insets`` with their :attr:`Inset.number` placed in the whole ``view`` (``scale``
    points per unit): its centre, in the frame of the paper.

    Parameters
    ----------
    insets
        The insets; with fewer than two, none is numbered.
    view
        ``(xmin, xmax, ymin, ymax)`` of the whole view.
    scale
        Points per unit of the whole view.
    labels
        The labels drawn in the whole view beside the insets.
    markers
        Each point's centre and marker size in points.

    Examples
    --------
    >>> a = Inset((0.0, 1.0, 0.0, 1.0), ())
    >>> b = Inset((4.0, 5.0, 4.0, 5.0), ())
    >>> one, two = numbered((a, b), (-10.0, 10.0, -10.0, 10.0), 20.0, [], [])
    >>> one.number[0] < 0.0 < 1.0 < one.number[1]  # above left of the first square
    True
    >>> numbered((a,), (-10.0, 10.0, -10.0, 10.0), 20.0, [], [])[0].number is None
    True
    """
    if len(insets) < 2:
        return insets
    gap = labelling.GAP_PT / 2 / scale
    taken: list[Box] = [lab.box for lab in labels]
    taken += [
        (x - r / 2 / scale, y - r / 2 / scale, x + r / 2 / scale, y + r / 2 / scale)
        for (x, y), r in markers
    ]
    out = []
    for k, inset in enumerate(insets):
        w, h = labelling.text_size(str(k + 1), font_pt * NUMBER_SCALE)
        w, h = w / scale, h / scale
        sq = inset.box
        best: tuple[float, XY, Box] | None = None
        for ring in _RINGS:
            d = gap + ring * max(w, h)
            for (fx, fy), (dx, dy) in _PLACES:
                x = sq[0] + fx * (sq[1] - sq[0]) + dx * (d + w / 2)
                y = sq[2] + fy * (sq[3] - sq[2]) + dy * (d + h / 2)
                box = (x - w / 2, y - h / 2, x + w / 2, y + h / 2)
                bad = 100 * sum(_overlap(box, t) > 0.0 for t in taken)
                bad += 100 * (
                    not (view[0] <= box[0] <= box[2] <= view[1])
                    or not (view[2] <= box[1] <= box[3] <= view[3])
                )
                bad += sum(_crosses(box, other.box) for other in insets)  # dashes: soft
                if best is None or bad < best[0]:
                    best = (bad, (x, y), box)
            if best is not None and best[0] == 0:
                break
        assert best is not None
        taken.append(best[2])
        out.append(replace(inset, number=best[1]))
    return tuple(out)
