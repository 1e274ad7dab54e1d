"""The values of the scene's labels and envelope: :class:`Arc`, :class:`Label`, :class:`Inset`.

Immutable records of the one picture model (:mod:`graspcompass.scene.picture`, which
re-exports them), read by every painter.  Nothing here imports matplotlib.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from . import labelling
from .layout import label_tex

__all__ = ["INSET_PT", "INSET_SHRINK", "LEAST_INSET", "MAX_INSETS", "Arc", "Inset", "Label"]

XY = tuple[float, float]
Box = tuple[float, float, float, float]

#: Side in points of the zoomed inset's square frame (the main one is
#: :data:`graspcompass.scene.labelling.FRAME_PT`), its labels at the same font size.
INSET_PT = 1.25 * labelling.FRAME_PT
#: The sides of the inset tried, as fractions of the crowded region's
#: (:func:`graspcompass.scene.fit.crowded_region`): a smaller one zooms in further where
#: a label has no place that keeps every rule.
INSET_SHRINK = (1.0, 0.8, 0.64, 0.5, 0.4)
#: The least side of an inset about points whose labels have no place in the whole view
#: (not the crowded region), as a fraction of the whole view's.
LEAST_INSET = 0.15
#: At most this many insets (the crowded region, then the other crowds, most points first).
MAX_INSETS = 4


@dataclass(frozen=True)
class Arc:
    """One piece of the envelope: from ``start`` about ``center``, radius ``radius``.

    Angles in degrees, counter-clockwise; ``delta == 0`` marks the zero region (O).
    """

    n: int
    start: XY
    end: XY
    center: XY
    radius: float
    start_angle: float
    delta: float


@dataclass(frozen=True)
class Label:
    """Where the label of one group of points goes (:func:`graspcompass.labelling.place`).

    ``at`` is the label's anchor in the frame of the paper, ``direction`` its
    side ``(dx, dy)`` of the point (1, 1: the label's lower left corner at
    ``at``, above right of the point; 0: centred), ``box`` its estimated extent
    ``(xmin, ymin, xmax, ymax)``, for text of :data:`graspcompass.labelling.FONT_PT`
    points in a picture :data:`graspcompass.labelling.FRAME_PT` points wide.
    """

    names: tuple[str, ...]
    at: XY
    direction: tuple[int, int]
    box: Box
    #: from the point to the anchor, in points of the placement's frame (the PNG's)
    offset: XY = (0.0, 0.0)
    #: the labelled point, in the frame of the paper
    point: XY = (0.0, 0.0)
    #: a thin line from the point to the label (a label set far from a crowded point)
    leader: bool = False
    #: per name, the group of coinciding points it belongs to: names of one group are
    #: joined by an equals sign, points apart but closer than a marker (one place to
    #: the eye) by a comma (empty: all coincide)
    groups: tuple[int, ...] = ()
    #: every rule holds at this place (no label or marker under it, nearer its own point
    #: than any other); False: set where it breaks the fewest, for want of a better place
    ok: bool = True

    def join(self, text: Any = label_tex) -> str:
        """The names, each written by ``text``, joined as they coincide."""
        out = text(self.names[0])
        for i in range(1, len(self.names)):
            same = not self.groups or self.groups[i] == self.groups[i - 1]
            out += (" = " if same else ", ") + text(self.names[i])
        return out

    def tex(self) -> str:
        """The label's TeX math body, ``O = O_M = Y_4`` (``P_1, P_{1x}`` when only near)."""
        return self.join()


@dataclass(frozen=True)
class Inset:
    """A zoomed view of the crowded region (:func:`graspcompass.scene.fit.crowded_region`).

    ``box`` ``(xmin, xmax, ymin, ymax)`` is the region in the frame of the paper;
    ``labels`` are placed in a frame of :data:`INSET_PT` points on its side.
    """

    box: Box
    labels: tuple[Label, ...]
    #: the labels of the whole view when the inset is shown beside it: those of the
    #: crowded points that break a rule there are left to the inset
    main: tuple[Label, ...] = ()
    #: with two insets or more, the centre of its square's number in the whole view (the
    #: frame of the paper), just outside the square where it covers nothing
    number: XY | None = None

    @property
    def zoom(self) -> float:
        """Points per unit of the inset."""
        return INSET_PT / (self.box[1] - self.box[0])
