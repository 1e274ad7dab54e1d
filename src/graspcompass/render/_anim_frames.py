"""The frames of the construction animation with a camera (a mixin of
:class:`~graspcompass.render.animate.ConstructionAnimation`).

A segment whose view is at rest is blitted on a base drawn for that view, over a
running layer of the earlier steps dimmed; a segment whose view moves is drawn in full.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.artist import Artist

from ._anim_camera import camera_box
from ._anim_ink import _fade, _restore
from .timeline import blend, smoothstep

__all__: list[str] = []

#: The final hold's cross-fade, a fraction of the hold (then the finished diagram at rest).
FADE = 0.2


class _CameraFrames:
    """``iter_frames`` and ``_background`` of the construction animation."""

    # set by ConstructionAnimation
    camera: bool
    timeline: Any
    construction: Any
    figure: Any
    _canvas: Any
    _dynamic: list[Artist]
    _keys: list[Any]
    _layer: Any
    _boxes: Any
    _whole: Any
    _items: Any
    _views: Any
    _caption: Any
    _dimf: Any
    _apply: Any
    _buffer: Any
    _crossfade: Any
    _draw: Any
    _movers: Any
    _still: Any
    _panel: Any

    def _panel_artists(self) -> list[Artist]:
        return [] if self._panel is None else list(self._panel.artists)

    def iter_frames(self) -> Any:
        """Every frame in order.  With the camera, a segment whose view is at rest is
        blitted on a base drawn for that view; a segment whose view moves (and the title
        card) is drawn in full; the stills repeated; the final hold a cross-fade."""
        if not self.camera:
            yield from super().iter_frames()  # type: ignore[misc]  # FrameAnimation, next in the MRO
            return
        tl, canvas, last = self.timeline, self._canvas, None
        dynamic = list(self._dynamic)
        view: Any = None
        base: Any = None

        def full(f: int) -> np.ndarray:
            for a in dynamic:
                a.set_animated(False)
            self._keys = [None] * len(self._keys)
            self._apply(f)
            canvas.draw()
            for a in dynamic:
                a.set_animated(True)
            return self._buffer()

        for a in dynamic:
            a.set_animated(True)
        try:
            for i, seg in enumerate(tl.segments):
                frames = tl.segment_range(i)
                rows = self._crossfade(i)
                if rows is not None and last is not None:
                    # a short cross-fade, then the finished diagram at rest: the labels of
                    # the drawing and those of the whole view are on screen together only
                    # while it fades (:data:`FADE`)
                    end = full(frames[-1])
                    n = max(1, round(FADE * len(frames)))
                    for k in range(len(frames) - 1):
                        yield blend(last, end, smoothstep(min(1.0, (k + 1) / n)), rows)
                    yield end
                    last, view = end, None
                    continue
                before = self._boxes[seg.step - 1] if seg.step > 0 else self._whole
                glide = frames  # the frames whose view moves: drawn in full
                under = any(r in ("fill", "cone") for _, r, _ in self._items[seg.step])
                if seg.kind == "draw" and before != self._boxes[seg.step] and not under:
                    # the camera glides over the first part of the stroke, then rests: the
                    # rest of the segment is blitted on a base of the view it rests on (not
                    # a step filling an area under what is drawn: blitted, it would cover it)
                    end = self._boxes[seg.step]
                    moved = [
                        f
                        for f in frames
                        if camera_box(self._boxes, self._whole, seg.step, "draw", tl.at(f).raw)
                        != end
                    ]
                    glide = range(frames.start, frames.start + len(moved))
                elif seg.kind not in ("title", "inset") and not (
                    seg.kind == "draw" and before != self._boxes[seg.step]
                ):
                    glide = range(frames.start, frames.start)
                for f in glide:
                    if last is not None and self._still(f) and f > frames.start:
                        yield last
                        continue
                    last = full(f)
                    yield last
                if glide:
                    view = None
                frames = range(glide.stop, frames.stop)
                if not frames:
                    continue
                box = camera_box(self._boxes, self._whole, seg.step, seg.kind, 1.0)
                if box != view:  # a new base: the static artists in this view
                    self._apply(frames.start)
                    canvas.draw()
                    base, view, self._layer = canvas.copy_from_bbox(self.figure.bbox), box, None
                moving = {id(a) for a in self._movers(i)}
                resting = [a for a in dynamic if id(a) not in moving]
                # the step's inputs and the labels are drawn on each frame with what moves,
                # in z-order: a stroke drawn later must not cover a label or a marker above it
                on_top = self._on_top(i)
                movers = [a for a in dynamic if id(a) in moving] + on_top
                background = self._background(i, frames, resting, base)
                for f in frames:
                    if (
                        last is not None
                        and self._still(f)
                        and (f > frames.start or seg.kind == "rest")
                    ):
                        yield last
                        continue
                    self._apply(f)
                    canvas.restore_region(background)
                    self._draw(movers)
                    last = self._buffer()
                    yield last
        finally:
            for a in dynamic:
                a.set_animated(False)

    def _background(self, segment: int, frames: range, resting: list[Artist], base: Any) -> Any:
        """Base, the earlier steps dimmed, the current step's inputs bright, the caption.

        The dimmed steps are a running layer: each step is drawn dimmed once on top of it.
        """
        canvas, bbox = self._canvas, self.figure.bbox
        step = self.timeline.segments[segment].step
        if self._layer is None or self._layer[0] is not base or self._layer[1] > step:
            self._layer = (base, 0, base)
        _, done, layer = self._layer
        if done < step:
            canvas.restore_region(layer)
            k = sum(len(items) for items in self._items[:done])
            for items in self._items[done:step]:
                for a, _, snap in items:
                    _restore(a, snap)
                    _fade(a, snap, self._dimf[k])
                    k += 1
                self._draw([a for a, _, _ in items])
            self._keys = [None] * len(self._keys)
            layer = canvas.copy_from_bbox(bbox)
            self._layer = (base, step, layer)
        self._apply(frames.start)
        canvas.restore_region(layer)
        moving = {id(a) for a in self._movers(segment)}
        self._draw([self._caption] + [a for a in self._panel_artists() if id(a) not in moving])
        return canvas.copy_from_bbox(bbox)

    def _on_top(self, segment: int) -> list[Artist]:
        """What a blitted frame draws with the step's strokes, in z-order: the inputs of the
        step (bright over their dimmed selves) and the labels at rest."""
        step = self.timeline.segments[segment].step
        inputs = set(self.construction.steps[step].inputs)
        moving = {id(a) for a in self._movers(segment)}
        return [
            a
            for s in self.construction.steps[:step]
            if s.name in inputs
            for a, _, _ in self._items[s.index]
        ] + [a for a in ([] if self._views is None else self._views.artists) if id(a) not in moving]
