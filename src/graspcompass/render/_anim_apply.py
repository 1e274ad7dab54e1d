"""Frames of the construction animation: each frame's state set from the timeline.

The mixin :class:`_ApplyFrames` of :class:`~graspcompass.render.animate.ConstructionAnimation`
(split from it for size): which artists a frame shows, how far the current step's stroke
has come, and the instruments' aid while a step is drawn.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..scene.labelling import SMALL_MARKER
from ..scene.picture import scene_of
from ._anim_camera import camera_box, zoomed
from ._anim_ink import _fade, _restore, _tint

if TYPE_CHECKING:
    from ..construction import Step

__all__: list[str] = []


class _ApplyFrames:
    """What a frame shows (mixin of the construction animation)."""

    # set by ConstructionAnimation
    _aid: Any
    _aids: Any
    _arc: Any
    _arm: Any
    _bar: Any
    _boxes: Any
    _caption: Any
    _card: Any
    _dimf: Any
    _halo: Any
    _items: Any
    _keys: Any
    _num: Any
    _panel: Any
    _views: Any
    _whole: Any
    _zoom_frames: Any
    _zoom_of: Any
    _zooms: Any
    axes: Any
    camera: Any
    caption_at: Any
    construction: Any
    theme: Any
    timeline: Any

    def _apply(self, frame: int) -> None:
        st = self.timeline.at(frame)
        steps = self.construction.steps
        inputs = set(steps[st.step].inputs)
        hold = st.kind in ("hold", "inset")  # the finished figure (and its zoom)
        title = st.kind == "title"
        self._card.set_visible(title)
        b = self._whole
        k = self._zoom_of.get(st.segment)  # the final zoom of an "inset" segment
        if self.camera:
            z = None if k is None else self._zooms[k]
            b = camera_box(self._boxes, self._whole, st.step, st.kind, st.raw, z)
            self.axes.set_xlim(b[0], b[1])
            self.axes.set_ylim(b[2], b[3])
        for frame_of_zoom in self._zoom_frames:
            frame_of_zoom.set_visible(hold)
        for aid in self._aids:
            aid.set_visible(False)
        n = 0
        for i, items in enumerate(self._items):
            key: Any = None  # the current step: set at every frame, never cached
            if i > st.step or title:
                key = "hidden"
            elif i < st.step or hold:  # the hold shows the finished figure
                key = "bright" if steps[i].name in inputs or hold else "dim"
            for a, role, snap in items:
                if key is None or self._keys[n] != key:
                    self._keys[n] = key
                    _restore(a, snap)
                    if key is None:
                        self._set_current(
                            a, role, snap, steps[st.step], st.kind, st.progress, st.raw
                        )
                    elif key == "hidden":
                        a.set_visible(False)
                    elif key == "dim":
                        _fade(a, snap, self._dimf[n])
                n += 1
        if self._views is not None:
            i = st.step
            moving = self.camera and i > 0 and self._boxes[i - 1] != self._boxes[i]
            view = self._views.view_at(
                st.step, st.kind, st.raw, moving, k if k is not None and zoomed(st.raw) else None
            )
            self._views.apply(view, st.step, st.kind, st.progress, inputs, b[1] - b[0])
        self._caption.set_text("" if title else self.caption_at(frame))
        if self._panel is not None:
            self._panel.apply(st.step, st.kind, st.progress, hold, title)
        made = (
            1.0 if hold else 0.0 if title else st.step + (st.progress if st.kind == "draw" else 1.0)
        )
        self._bar.set_width(made if hold else made / len(steps))

    def _set_current(
        self, a: Any, role: str, snap: dict[str, Any], step: Step, kind: str, p: float, raw: float
    ) -> None:
        if role == "instrument":  # the compass or the square drawn along its stroke
            x, y = snap["data"]
            m = max(1, math.ceil(min(p, 1.0) * len(x))) if kind == "draw" else len(x)
            a.set_data(x[:m], y[:m])
            return
        if role == "cone":  # after the stroke of its second side
            a.set_visible(snap["visible"] and (kind != "draw" or p >= 1.0))
            return
        if role not in ("fill", "label"):
            pulse = 1.0 + 0.5 * math.sin(math.pi * raw) if kind == "pause" else 1.0
            _tint(a, snap, self.theme.highlight_color, (1.0 if role == "marker" else 1.6) * pulse)
        if kind == "pause":
            if role == "marker" and step.kind == "point":  # a ripple round the key point
                ripple = (2 * raw) % 1.0
                self._halo.set(
                    data=snap["data"],
                    ms=snap["ms"] * (1.5 + 3.5 * ripple),
                    alpha=1.0 - ripple,
                    visible=True,
                )
        elif role == "marker":  # marked: the marker pops up (a break point as large as
            # any point while it is the new one, named beside it)
            ms = snap["ms"] / SMALL_MARKER if step.role == "break_point" else snap["ms"]
            a.set_markersize(ms * p * (1.0 + 0.8 * math.sin(math.pi * p)))
            self._draw_aid(step, p)
        elif role == "label":
            a.set_visible(snap["visible"] and p >= 1.0)  # after its object's stroke
        elif role == "line" and len(snap["data"][0]) == 2:  # the ruler, from its anchor
            (x0, x1), (y0, y1) = snap["data"]
            ax_, ay_ = next(
                (
                    v
                    for v in (self._num[n] for n in step.inputs)
                    if isinstance(v, tuple) and isinstance(v[0], float)
                ),
                (0.0, 0.0),
            )
            a.set_data(
                [ax_ + p * (x0 - ax_), ax_ + p * (x1 - ax_)],
                [ay_ + p * (y0 - ay_), ay_ + p * (y1 - ay_)],
            )
        elif role == "arrow":  # a signed length laid off with the compass
            (x0, y0), (x1, y1) = a.xyann, snap["xy"]
            a.xy = (x0 + p * (x1 - x0), y0 + p * (y1 - y0))
        elif role == "fill":
            _fade(a, snap, p)
        elif role == "trace":  # the envelope traced in θ, with its radius k_grasp(θ)
            x, y = snap["data"]
            m = max(2, math.ceil(p * len(x)))
            a.set_data(x[:m], y[:m])
            self._arm.set(data=([0.0, x[m - 1]], [0.0, y[m - 1]]), visible=p < 1.0)
        elif role == "circle":
            self._sweep(a, snap, p)

    def _sweep(self, a: Any, snap: dict[str, Any], p: float) -> None:
        """The compass arc round the circle on O V_n from O (eq. (31)), with the compass arm."""
        (cx, cy), r = a.center, a.radius
        t = math.atan2(-cy, -cx) + 2 * math.pi * p * np.linspace(0.0, 1.0, 181)
        xs, ys = cx + r * np.cos(t), cy + r * np.sin(t)
        done = p >= 1.0
        self._arc.set(data=(xs, ys), ls=a.get_linestyle(), lw=snap["lw"] * 1.6, visible=not done)
        self._arm.set(data=([cx, xs[-1]], [cy, ys[-1]]), visible=not done)
        a.set_visible(done)

    def _draw_aid(self, step: Step, p: float) -> None:
        """Dashed helper lines of a point: the dropped perpendicular, the bisected
        segment, the two coordinates of V_n (§3.3 step (3))."""
        v, num = self._num[step.name], self._num
        if any(i.step == step.name for i in scene_of(self.construction).instruments):
            return  # its instruments show it (graspcompass.scene.instruments)
        if step.op in ("foot", "midpoint"):
            a = num[step.inputs[0]]
            b = v if step.op == "foot" else num[step.inputs[1]]
            xs, ys = [a[0], a[0] + p * (b[0] - a[0])], [a[1], a[1] + p * (b[1] - a[1])]
        elif step.op == "point_from_lengths":
            xs, ys = [v[0], v[0], np.nan, 0.0, p * v[0]], [0.0, p * v[1], np.nan, v[1], v[1]]
        else:
            return
        self._aid.set(data=(xs, ys), visible=True)
