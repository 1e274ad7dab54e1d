"""The point labels of a construction animation, placed for each view of its camera.

The static pictures place their labels once, for the whole view
(:mod:`graspcompass.scene.picture`); an animation's camera zooms in and out
(``_anim_camera.py``), and labels placed for the whole view, kept at their offsets in
points, crowd or stray from their points in a zoomed one.  So here the steps are cut
into *runs* over which the camera rests on one box, and the labels of the points made
by the end of a run are placed in that box, at the size they are drawn, by the rules
of every picture (:func:`graspcompass.scene.picture.build_scene`: no label over
another or over a marker, each nearer its own point than any other).  Within a run
no label moves.  The final hold has the whole construction's labels in the whole
view; after it the camera zooms on each crowd of points whose labels have no place there,
and each zoom has its own.  A label that no place in its view allows (``ok`` false)
is shown only while its point is the step's new object, and in the final hold only if
no zoom names it.  Private to :mod:`graspcompass.render.animate`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.text import Annotation

from ..scene import labelling
from ..scene.layout import label_tex
from ..scene.picture import build_scene, scene_of
from ._anim_ink import _fade, _inks, _restore, _snap, dim_alpha
from .figure import label_artists
from .theme import MIN_CONTRAST

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ..construction.protocol import Construction
    from ..scene._values import Label
    from .theme import Theme

__all__: list[str] = []

Box = tuple[float, float, float, float]
XY = tuple[float, float]

#: The sides of a final zoom tried, as fractions of the first, until every label in it
#: keeps the rules; the first holds its points padded by :data:`_PAD` of their extent
#: on each side, and is at least :data:`_LEAST` of the whole view.
_SHRINK = (1.0, 0.8, 0.64, 0.5)
_PAD = 0.35
_LEAST = 0.2
#: Points of labels the whole view cannot place closer than this fraction of the view
#: are one crowd, shown by one zoom.
_CROWD = 0.2
#: The sides tried, as fractions of a step's box, about a new point whose label has no
#: place keeping the rules in that box.
_CLOSER = (0.7, 0.5, 0.35, 0.25, 0.18, 0.12, 0.08, 0.05, 0.03, 0.02, 0.012, 0.008)
#: At most this many final zooms (a crowd, a closer one in it, another crowd, ...).
_ZOOMS = 4
#: At most this many rounds of bringing the camera closer.
_ROUNDS = 3
#: The largest font, as a fraction of the placement's frame, for which the camera comes
#: closer or zooms on a crowd (labels larger than that have no room at any zoom: a frame
#: drawn at a few dozen dpi with text at least 14 pixels high).
_LARGEST = 0.08


@dataclass
class ViewLabel:
    """One label of one view: its text, its leader line, the parts it names."""

    view: int
    text: Annotation
    leader: Line2D | None
    #: (the step making the name, the separator before it and its TeX)
    parts: list[tuple[int, str]]
    ok: bool
    point: XY
    #: the leader's far end from the point, in points of the axes
    end_pt: XY
    snap: dict[str, Any]
    dimf: float


@dataclass(frozen=True)
class View:
    """A box of the camera and the labels placed in it."""

    box: Box
    labels: tuple[Label, ...]
    kind: str  # "run", "hold" or "zoom"


class ViewLabels:
    """The labels of every view of an animation, drawn hidden on ``ax``; :meth:`apply`
    shows those of a frame.

    Parameters
    ----------
    construction : Construction
        The construction animated.
    ax : Axes
        The diagram's axes (their size sets the labels' size against the frame).
    theme : Theme
        The animation's theme (font size, label colour).
    boxes : list of Box
        The camera's box of every step (all the whole view without a camera).
    whole : Box
        The whole view.
    num : dict
        The numbers of the construction's objects.
    font_pt, k : float
        The labels' size in points of the placement's frame, and the axes' width over
        that frame's.
    zoom : bool
        Whether the final hold zooms on the crowded region (a camera).
    dim : float
        The least opacity of an earlier step's label (as the other dimmed elements).
    break_points : bool
        Whether the finished figure names the break points on the envelope (each break
        point is named at its own step in any case).
    """

    def __init__(
        self,
        construction: Construction,
        ax: Axes,
        theme: Theme,
        boxes: list[Box],
        whole: Box,
        num: dict[str, Any],
        font_pt: float,
        k: float,
        zoom: bool,
        dim: float = 0.3,
        break_points: bool = False,
    ) -> None:
        self.ax, self.theme, self.k, self.dim = ax, theme, k, dim
        steps = construction.steps
        self._index = {s.name: s.index for s in steps}
        self.views: list[View] = []
        self.step_view: list[int] = []

        placed: dict[tuple[int, Box, bool | str], tuple[Label, ...]] = {}

        def place(last: int, box: Box, named: bool | str = "all") -> tuple[Label, ...]:
            """The labels of the points made by step ``last`` placed in ``box`` (once); the
            break points named as ``named`` says (``"all"``: each at its step)."""
            if (last, box, named) not in placed:
                cut = construction.upto(last)
                scene = build_scene(
                    cut, box=box, font_pt=font_pt, num=num, break_points=named, with_insets=False
                )
                placed[last, box, named] = scene.labels
            return placed[last, box, named]

        runs = self._runs(boxes, place)
        # labels so large against the frame that no zoom gives them room: no closer camera
        zoom = zoom and font_pt <= _LARGEST * labelling.FRAME_PT
        for _ in range(_ROUNDS if zoom else 0):  # the camera closer where a new point's
            # label has no place; a run cut in two is placed again, and may need it too
            closer = self._closer(construction, boxes, runs, place, num)
            if closer == boxes:
                break
            boxes = closer
            runs = self._runs(boxes, place)
        #: the camera's box of every step, closer than asked where a label needs it
        self.boxes = boxes
        for first, last, labs in runs:
            self.step_view += [len(self.views)] * (last - first + 1)
            self.views.append(View(boxes[first], labs, "run"))
        whole_scene = scene_of(construction, break_points=break_points, font_pt=font_pt)
        self.hold = len(self.views)
        self.views.append(View(whole, whole_scene.labels, "hold"))
        #: the views of the final zooms, one per crowd of labels the whole view cannot place
        self.zooms: list[int] = []
        pending = [(pts, whole) for pts in _crowds(whole_scene.labels, whole)] if zoom else []
        while pending and len(self.zooms) < _ZOOMS:
            pts, around = pending.pop(0)
            view = self._zoom_view(construction, pts, around, place, break_points)
            if around != whole and (view.box[1] - view.box[0]) * 1.5 > around[1] - around[0]:
                continue  # no closer than the zoom it is in
            self.zooms.append(len(self.views))
            self.views.append(view)
            # a crowd still too close in this zoom: a closer zoom on it
            pending += [(p, view.box) for p in _crowds(view.labels, view.box)]
        bg = ax.get_facecolor()
        self.labels: list[ViewLabel] = []
        for v, view in enumerate(self.views):
            for one in view.labels:
                self.labels.append(self._draw(v, view, one, bg))
        self.artists: list[Any] = [
            a for x in self.labels for a in (x.text, x.leader) if a is not None
        ]
        self._by_view: list[list[ViewLabel]] = [[] for _ in self.views]
        for x in self.labels:
            self._by_view[x.view].append(x)
        steps_by_index = [s.name for s in steps]
        self._names = {id(x): {steps_by_index[i] for i, _ in x.parts} for x in self.labels}
        self._shown: int | None = None

    @staticmethod
    def _runs(boxes: list[Box], place: Any) -> list[tuple[int, int, tuple[Label, ...]]]:
        """The runs of steps with one box, each with the labels of the points made by its
        end placed in that box."""
        out = []
        start = 0
        for i in range(1, len(boxes) + 1):
            if i == len(boxes) or boxes[i] != boxes[start]:
                out.append((start, i - 1, place(i - 1, boxes[start])))
                start = i
        return out

    @staticmethod
    def _closer(
        construction: Construction,
        boxes: list[Box],
        runs: list[tuple[int, int, tuple[Label, ...]]],
        place: Any,
        num: dict[str, Any],
    ) -> list[Box]:
        """``boxes`` with the box of each step whose new point's label finds no place
        keeping the rules in its run made smaller about that point (:data:`_CLOSER`),
        while that helps."""
        out = list(boxes)
        steps = construction.steps
        for first, last, labs in runs:
            for i in range(first, last + 1):
                name = steps[i].name
                lab = next((x for x in labs if name in x.names), None)
                if lab is None or lab.ok or steps[i].kind != "point":
                    continue
                px, py = num[name]
                box = boxes[i]
                for f in _CLOSER:
                    hx, hy = (box[1] - box[0]) * f / 2, (box[3] - box[2]) * f / 2
                    sub = (px - hx, px + hx, py - hy, py + hy)
                    mine = next((x for x in place(i, sub) if name in x.names), None)
                    if mine is not None and mine.ok:
                        out[i] = sub
                        break
        return out

    @staticmethod
    def _zoom_view(
        construction: Construction,
        pts: list[XY],
        around: Box,
        place: Any,
        named: bool,
    ) -> View:
        """A final zoom on the points ``pts`` (:func:`_crowds` of the view ``around``): a
        square about them, smaller (:data:`_SHRINK`) while a label in it breaks a rule and
        it still holds them; the break points named as in the finished figure (``named``)."""
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
        need = max(max(xs) - min(xs), max(ys) - min(ys))
        span = around[1] - around[0]
        side = max(need * (1 + 2 * _PAD), _LEAST * span)
        last = len(construction.steps) - 1
        best: View | None = None
        for f in _SHRINK:
            h = max(side * f, need * (1 + _PAD)) / 2
            sub = (cx - h, cx + h, cy - h, cy + h)
            view = View(sub, place(last, sub, named), "zoom")
            if best is None or sum(not x.ok for x in view.labels) < sum(
                not x.ok for x in best.labels
            ):
                best = view
            if all(x.ok for x in view.labels) or h * 2 <= need * (1 + _PAD):
                break
        assert best is not None
        return best

    def _draw(self, v: int, view: View, lab: Label, bg: Any) -> ViewLabel:
        ax = self.ax
        text, leader = label_artists(ax, lab, self.theme, self.k, clip=True)
        text.set_visible(False)
        end = (0.0, 0.0)
        if leader is not None:  # its far end in points: the same length at any zoom
            leader.set_visible(False)
            xy = np.asarray(leader.get_xydata(), dtype=float)  # the point, the near end
            per = ax.bbox.width * 72.0 / ax.figure.dpi / (view.box[1] - view.box[0])  # type: ignore[union-attr]
            end = (float(xy[1, 0] - xy[0, 0]) * per, float(xy[1, 1] - xy[0, 1]) * per)
        # each name with the separator before it, as Label.join writes them
        pieces = lab.join(lambda n: label_tex(n) + "\0").split("\0")[:-1]
        parts = [(self._index[n], p) for n, p in zip(lab.names, pieces)]
        snap = _snap(text)
        dimf = dim_alpha(_inks(text, snap), bg, MIN_CONTRAST["text"], self.dim)
        return ViewLabel(v, text, leader, parts, lab.ok, lab.point, end, snap, dimf)

    # -- frames ---------------------------------------------------------------------------
    def view_at(
        self, step: int, kind: str, raw: float, moving: bool, zoom: int | None = None
    ) -> int | None:
        """The view whose labels a frame shows: none on the title card; while the camera
        glides to a new box, the last one's until half way (``raw`` 0.3: the glide takes
        the first 60 % of the stroke); in an ``"inset"`` segment the ``zoom``-th final
        zoom's (None: the whole view's, while the camera glides in or out)."""
        if kind == "title":
            return None
        if kind == "inset":
            return self.hold if zoom is None else self.zooms[zoom]
        if kind == "hold":
            return self.hold
        if kind == "draw" and moving and step > 0 and raw < 0.3:
            return self.step_view[step - 1]
        return self.step_view[step]

    def apply(
        self,
        view: int | None,
        step: int,
        kind: str,
        progress: float,
        inputs: set[str],
        span: float,
    ) -> None:
        """Show the labels of ``view`` at a frame of ``step``: each names the points made
        so far (the current step's after its stroke), dimmed unless made now or used now;
        ``span``: the width of the camera's box (a leader keeps its length in points)."""
        if self._shown is not None and self._shown != view:
            for lab in self._by_view[self._shown]:
                lab.text.set_visible(False)
                if lab.leader is not None:
                    lab.leader.set_visible(False)
        self._shown = view
        if view is None:
            return
        zoom = view in self.zooms
        final = zoom or view == self.hold
        done = kind != "draw" or progress >= 1.0
        per = self.ax.bbox.width * 72.0 / self.ax.figure.dpi / span  # type: ignore[union-attr]
        for lab in self._by_view[view]:
            now = any(i == step for i, _ in lab.parts)
            shown = [p for i, p in lab.parts if final or i < step or (i == step and done)]
            if shown and not lab.ok:
                # the hold and a zoom leave it to a later zoom that names it; a run shows
                # it at its step
                if (final and self.zoomed(lab.point, view)) or (not final and not now):
                    shown = []
            _restore(lab.text, lab.snap)
            lab.text.set_visible(bool(shown))
            if not shown:
                if lab.leader is not None:
                    lab.leader.set_visible(False)
                continue
            lab.text.set_text("$" + "".join(shown).lstrip(" =,") + "$")
            dim = not final and not now and not (self._names[id(lab)] & inputs)
            if dim:
                _fade(lab.text, lab.snap, lab.dimf)
            if lab.leader is not None:
                px, py = lab.point
                lab.leader.set_data([px, px + lab.end_pt[0] / per], [py, py + lab.end_pt[1] / per])
                lab.leader.set_alpha(lab.dimf if dim else None)
                lab.leader.set_visible(True)

    def zoomed(self, point: XY, after: int) -> bool:
        """Whether ``point`` is in the box of a final zoom after the view ``after`` (the
        hold is before every zoom)."""
        x, y = point
        later = [z for z in self.zooms if z > after]
        return any(
            b[0] <= x <= b[1] and b[2] <= y <= b[3] for b in (self.views[z].box for z in later)
        )

    def movers(self, step: int) -> list[Any]:
        """The labels that change during the frames of ``step``: those naming its point."""
        return [
            a
            for lab in self.labels
            if any(i == step for i, _ in lab.parts)
            for a in (lab.text, lab.leader)
            if a is not None
        ]

    @property
    def zoom_boxes(self) -> list[Box]:
        """The boxes of the final zooms (none where every label has a place in the whole
        view)."""
        return [self.views[z].box for z in self.zooms]


def _crowds(labels: tuple[Label, ...], view: Box) -> list[list[XY]]:
    """The points of the labels that break a rule in a view (``ok`` false), in crowds:
    points closer than :data:`_CROWD` of the view are in one crowd."""
    pts = [lab.point for lab in labels if not lab.ok]
    link = _CROWD * (view[1] - view[0])
    crowds: list[list[XY]] = []
    for p in pts:
        near = [c for c in crowds if any(abs(p[0] - q[0]) + abs(p[1] - q[1]) <= link for q in c)]
        merged = [p] + [q for c in near for q in c]
        crowds = [c for c in crowds if all(c is not d for d in near)] + [merged]
    return crowds
