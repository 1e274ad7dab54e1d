"""Step-by-step animation of the ruler-and-compass construction (§3.3, Figs. 3-5).

As in Manim, the drawn object (every artist of the finished construction, made
once by :func:`~graspcompass.render.draw_construction`), the
:class:`~graspcompass.render.timeline.Timeline` (pure data) and the animation
(which sets the artists for a frame from the two) are kept apart.  A ruler
line grows from its anchor point, a compass arc sweeps round, a point is
marked; the new element is highlighted, the earlier ones dimmed (those the
step uses stay bright); a caption gives the step's text and the paper's
reference; the animation pauses on each V_n (eq. (30)), each circle on O V_n
(eq. (31)) and the envelope (eq. (25)).  The geometry is only read; the same
input gives the same frames.  :class:`FrameAnimation` is the player shared
with :mod:`graspcompass.render.anim_physics`: it draws frames by blitting and
writes GIF, MP4 or HTML; in Jupyter an animation shows itself (``_repr_html_``).

Examples
--------
>>> from graspcompass import Grasp, internal_force_diagram
>>> c = internal_force_diagram(Grasp.preset("table1a"))
>>> anim = animate_construction(c, frames_per_step=2, pause_frames=1, hold_frames=1)
>>> anim.frame_count == 2 * len(c.steps) + 9 + 1
True
>>> print(anim.caption_at(anim.timeline.frames_of_step(13)[0]))
Step 14/47 · perpendicular
§3.3 V1 (2): perpendicular from P2x to the upper side of the cone at P1
"""

from __future__ import annotations

import math
import os
import textwrap
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.animation import FuncAnimation
from matplotlib.artist import Artist
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle
from matplotlib.text import Annotation, Text

from ..layout import numeric_objects
from .figure import draw_construction
from .theme import DEFAULT_THEME, Theme
from .timeline import (
    Timeline,
    blend,
    check_fps,
    jshtml,
    palette_sample,
    save_frames,
    write_animation,
)

__all__ = ["AX_RECT", "ConstructionAnimation", "FrameAnimation", "animate_construction",
           "save_frames"]

#: Position of the diagram axes in the construction animation (figure fraction).
AX_RECT = (0.1, 0.2, 0.86, 0.72)
_CAPTION_Y = 0.125


class FrameAnimation:
    """A figure whose artists are set for each frame of a timeline; renders and saves it.

    Subclasses set ``_dynamic`` (every artist they change, in drawing order)
    and implement ``_apply(frame)`` (set the artists for that frame, whatever
    came before); they may override ``_movers(segment)`` (the artists changing
    within a segment), ``_group_key(segment)`` (consecutive segments with one
    key leave the other dynamic artists alone) and ``_crossfade(segment)``.
    """

    _blit_live = False  # blitting of the live FuncAnimation

    def __init__(self, figure: Figure, timeline: Timeline, fps: float) -> None:
        self.figure, self.timeline, self.fps = figure, timeline, check_fps(fps)
        self._canvas = FigureCanvasAgg(figure)
        self._anim: FuncAnimation | None = None
        self._dynamic: list[Artist] = []

    def _apply(self, frame: int) -> None:
        raise NotImplementedError

    def _movers(self, segment: int) -> list[Artist]:
        return self._dynamic

    def _group_key(self, segment: int) -> Any:
        return segment

    def _crossfade(self, segment: int) -> slice | None:
        """Image rows shown as a cross-fade of the frames around the segment, or None."""
        return None

    def key_frames(self) -> list[tuple[int, str]]:
        """``(frame, name)`` of the frames :func:`save_frames` writes by default."""
        return [(f, f"frame-{f:04d}") for f in range(self.frame_count)]

    @property
    def frame_count(self) -> int:
        """Number of frames."""
        return self.timeline.frame_count

    def update(self, frame: int) -> list[Artist]:
        """Set the artists for ``frame``; the function of :attr:`animation`."""
        self._apply(int(frame))
        return self._dynamic if self._blit_live else []

    def render(self, frame: int) -> np.ndarray:
        """Frame ``frame`` as an RGB array ``(height, width, 3)``, drawn in full."""
        tl = self.timeline
        f = tl.check(frame)
        rng = tl.segment_range(tl.segment_of(f))
        rows = self._crossfade(tl.segment_of(f))
        if rows is not None and rng.start > 0 and f != rng.stop - 1:
            return blend(self.render(rng.start - 1), self.render(rng.stop - 1),
                         tl.at(f).progress, rows)
        for a in self._dynamic:  # a live blitting FuncAnimation may have left them animated
            a.set_animated(False)
        self._apply(f)
        self._canvas.draw()
        return self._buffer()

    def _buffer(self) -> np.ndarray:
        return np.ascontiguousarray(np.asarray(self._canvas.buffer_rgba())[..., :3])

    def iter_frames(self) -> Iterator[np.ndarray]:
        """Every frame in order as RGB arrays, drawn in layers by blitting.

        The artists that never change are drawn once; the dynamic artists that
        rest during a group of segments once per group; the movers every frame.
        """
        canvas, tl, dynamic = self._canvas, self.timeline, list(self._dynamic)
        for a in dynamic:
            a.set_animated(True)
        try:
            self._apply(0)
            canvas.draw()
            base = canvas.copy_from_bbox(self.figure.bbox)
            last, i, n = None, 0, len(tl.segments)
            while i < n:
                j = i
                while j + 1 < n and self._group_key(j + 1) == self._group_key(i):
                    j += 1
                frames = range(tl.starts[i], tl.segment_range(j).stop)
                rows = self._crossfade(i)
                if rows is not None and last is not None:
                    self._apply(frames[-1])
                    canvas.restore_region(base)
                    self._draw(dynamic)
                    end = self._buffer()
                    yield from (blend(last, end, tl.at(f).progress, rows) for f in frames[:-1])
                    yield end
                    i = j + 1
                    continue
                moving = {id(a) for s in range(i, j + 1) for a in self._movers(s)}
                resting = [a for a in dynamic if id(a) not in moving]
                movers = [a for a in dynamic if id(a) in moving]
                background = self._background(i, frames, resting, base)
                for f in frames:
                    self._apply(f)
                    canvas.restore_region(background)
                    self._draw(movers)
                    last = self._buffer()
                    yield last
                i = j + 1
        finally:
            for a in dynamic:
                a.set_animated(False)

    def _background(self, segment: int, frames: range, resting: list[Artist], base: Any) -> Any:
        """The background of a group of frames: ``base`` and the resting artists."""
        self._apply(frames.start)
        self._canvas.restore_region(base)
        self._draw(resting)
        return self._canvas.copy_from_bbox(self.figure.bbox)

    def _draw(self, artists: list[Artist]) -> None:
        for a in sorted(artists, key=lambda a: a.get_zorder()):
            if a.get_visible():
                self.figure.draw_artist(a)

    def save(self, path: str | os.PathLike[str], fps: float | None = None,
             quiet: bool = False) -> Path:
        """Write ``.gif``, ``.mp4`` or ``.html``; see :func:`~.timeline.write_animation`."""
        return write_animation(self, path, fps, quiet)

    @property
    def animation(self) -> FuncAnimation:
        """A :class:`~matplotlib.animation.FuncAnimation` of the frames, for live display
        (blitting in the sweep and orientation animations)."""
        if self._anim is None:
            self._anim = FuncAnimation(self.figure, self.update, frames=self.frame_count,
                                       init_func=lambda: self.update(0), repeat=True,
                                       interval=1000.0 / self.fps, blit=self._blit_live,
                                       cache_frame_data=False)
        return self._anim

    def to_html(self, fps: float | None = None) -> str:
        """Self-contained interactive HTML of every frame, the player of ``to_jshtml``."""
        rate = self.fps if fps is None else check_fps(fps)
        return jshtml(self.iter_frames(), self.figure.get_size_inches(), self.figure.dpi, rate,
                      palette_sample(self))

    def _repr_html_(self) -> str:
        return self.to_html()


# -- artists' states ----------------------------------------------------------------------------
def _snap(a: Artist) -> dict[str, Any]:
    """What :func:`_restore` needs to put ``a`` back as :func:`draw_construction` drew it."""
    s: dict[str, Any] = {"visible": a.get_visible(), "alpha": a.get_alpha()}
    if isinstance(a, Line2D):
        s.update(color=a.get_color(), lw=a.get_linewidth(), ms=a.get_markersize(),
                 mfc=a.get_markerfacecolor(), mec=a.get_markeredgecolor(),
                 data=(np.array(a.get_xdata(), float), np.array(a.get_ydata(), float)))
    elif isinstance(a, Patch):  # colours as given: "none" stays invisible under any alpha
        s.update(lw=a.get_linewidth(), ec=getattr(a, "_original_edgecolor", a.get_edgecolor()),
                 fc=getattr(a, "_original_facecolor", a.get_facecolor()))
    if isinstance(a, Text):
        s["color"] = a.get_color()
    if isinstance(a, Annotation):
        s["xy"] = tuple(a.xy)
        if a.arrow_patch is not None:
            s["arrow"] = _snap(a.arrow_patch)
    return s


def _restore(a: Any, s: dict[str, Any]) -> None:
    a.set_visible(s["visible"])
    a.set_alpha(s["alpha"])
    if isinstance(a, Line2D):
        a.set(color=s["color"], lw=s["lw"], ms=s["ms"], mfc=s["mfc"], mec=s["mec"])
        a.set_data(*s["data"])
    elif isinstance(a, Patch):
        a.set(edgecolor=s["ec"], facecolor=s["fc"], lw=s["lw"])
    if isinstance(a, Text):
        a.set_color(s["color"])
    if isinstance(a, Annotation):
        a.xy = s["xy"]
        if "arrow" in s:
            _restore(a.arrow_patch, s["arrow"])
        a.stale = True


def _fade(a: Any, s: dict[str, Any], factor: float) -> None:
    a.set_alpha((1.0 if s["alpha"] is None else s["alpha"]) * factor)
    if "arrow" in s:
        _fade(a.arrow_patch, s["arrow"], factor)


def _tint(a: Any, s: dict[str, Any], color: Any, widen: float) -> None:
    """Colour ``a`` as the new object and widen its lines by ``widen``."""
    if isinstance(a, Line2D):
        a.set(color=color, mec=color, lw=s["lw"] * widen)
        if to_rgba(s["mfc"]) != to_rgba("white"):
            a.set_markerfacecolor(color)
    elif isinstance(a, Patch):
        a.set(edgecolor=color, lw=s["lw"] * widen)
    if "arrow" in s:
        a.arrow_patch.set_color(color)


# -- the construction ---------------------------------------------------------------------------
class ConstructionAnimation(FrameAnimation):
    """The construction of §3.3 replayed step by step; see :func:`animate_construction`."""

    def __init__(self, construction: Any, fps: float = 20, frames_per_step: int = 8,
                 pause_frames: int = 12, hold_frames: int = 20, theme: Theme = DEFAULT_THEME,
                 figsize: tuple[float, float] = (5.0, 5.6), dpi: float = 80,
                 labels: bool = True, rate: str = "smoothstep", dim: float = 0.3) -> None:
        self.construction, self.theme, self.dim = construction, theme, float(dim)
        steps = construction.steps
        timeline = Timeline.from_keys([s.key for s in steps], frames_per_step, pause_frames,
                                      hold_frames, rate)
        super().__init__(Figure(figsize=figsize, dpi=dpi), timeline, fps)
        fig = self.figure
        self.axes = ax = fig.add_axes(AX_RECT)
        self.artists = arts = draw_construction(construction, ax=ax, theme=theme, labels=labels)
        ax.tick_params(labelsize=theme.font_size * 0.7)
        self._num = numeric_objects(construction)
        # each artist belongs to the first step naming it (a shared label "O = O_M" to O)
        self._items: list[list[tuple[Artist, str, dict[str, Any]]]] = [[] for _ in steps]
        seen: set[int] = set()
        for s in steps:
            for a in arts.get(s.name, []):
                if id(a) not in seen:
                    seen.add(id(a))
                    self._items[s.index].append((a, self._role(a, s), _snap(a)))
        hl, thin = theme.highlight_color, theme.thin_width
        self._aid = ax.plot([], [], color=hl, lw=thin * 1.5, ls=(0, (3, 2)), zorder=6)[0]
        self._arc = ax.plot([], [], color=hl, zorder=6)[0]
        self._arm = ax.plot([], [], color=hl, lw=thin * 1.5, marker="o", ms=3, markevery=[0],
                            zorder=6.5)[0]
        self._halo = ax.plot([], [], "o", mfc="none", mec=hl, zorder=7)[0]
        self._aids = (self._aid, self._arc, self._arm, self._halo)
        fig.text(0.5, 0.985, getattr(construction.grasp, "title", None) or "", ha="center",
                 va="top", fontsize=theme.font_size * 0.8)
        self._caption = fig.text(0.03, _CAPTION_Y, "", va="top", linespacing=1.4,
                                 fontsize=theme.font_size * 0.85)
        self._bar = fig.add_artist(Rectangle((0, 0), 0, 0.012, transform=fig.transFigure,
                                             color=hl, zorder=10))
        self._wrap = max(30, int(figsize[0] * 72 / (0.56 * theme.font_size * 0.85)))
        self._keys: list[Any] = [None] * len(seen)
        self._layer: tuple[Any, int, Any] | None = None
        self._dynamic = [a for items in self._items for a, _, _ in items]
        self._dynamic += [*self._aids, self._caption, self._bar]

    @staticmethod
    def _role(a: Artist, s: Any) -> str:
        if isinstance(a, Annotation) and a.arrow_patch is not None:
            return "arrow"
        if isinstance(a, Text):
            return "label"
        if isinstance(a, Patch):
            return "circle" if s.kind == "circle" else "fill"
        if s.kind == "envelope":
            return "trace"
        return "line" if s.kind == "line" and a.get_linestyle() != "None" else "marker"

    def caption_at(self, frame: int) -> str:
        """The caption of ``frame``: step, instrument, the paper's reference and the text."""
        st = self.timeline.at(frame)
        steps = self.construction.steps
        if st.kind == "hold":
            head = "The internal force diagram (Fig. 5)"
            body = ("in the direction e(θ) of the external force, the distance from O to the "
                    "envelope is k_grasp(θ), eq. (25); F_int = k_grasp/(x1 + x2)·F_e, eq. (17)")
        else:
            s = steps[st.step]
            head = f"Step {s.index + 1}/{len(steps)} · {s.instrument}"
            text = s.caption[0].lower() + s.caption[1:] if s.caption[1:2].islower() else s.caption
            body = f"{s.ref.replace(' step ', ' ')}: {text}"
        return head + "\n" + textwrap.fill(body, self._wrap)

    def key_frames(self) -> list[tuple[int, str]]:
        """The frame at the end of each protocol step, named ``step-NN-name``."""
        return [(self.timeline.last_frame_of_step(s.index), f"step-{s.index:02d}-{s.name}")
                for s in self.construction.steps]

    def _movers(self, segment: int) -> list[Artist]:
        return [a for a, _, _ in self._items[self.timeline.segments[segment].step]] + \
            [*self._aids, self._bar]

    def _group_key(self, segment: int) -> Any:
        seg = self.timeline.segments[segment]
        return (seg.step, seg.kind) if seg.kind == "hold" else seg.step

    def _crossfade(self, segment: int) -> slice | None:
        """The final hold: the elements fade back to their colours, the caption does not."""
        if self.timeline.segments[segment].kind != "hold":
            return None
        return slice(0, int(self._canvas.get_width_height()[1] * (0.99 - _CAPTION_Y)))

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
            for items in self._items[done:step]:
                for a, _, snap in items:
                    _restore(a, snap)
                    _fade(a, snap, self.dim)
                self._draw([a for a, _, _ in items])
            self._keys = [None] * len(self._keys)
            layer = canvas.copy_from_bbox(bbox)
            self._layer = (base, step, layer)
        self._apply(frames.start)
        canvas.restore_region(layer)
        inputs = set(self.construction.steps[step].inputs)
        self._draw([a for s in self.construction.steps[:step] if s.name in inputs
                    for a, _, _ in self._items[s.index]] + [self._caption])
        return canvas.copy_from_bbox(bbox)

    def _apply(self, frame: int) -> None:
        st = self.timeline.at(frame)
        steps = self.construction.steps
        inputs = set(steps[st.step].inputs)
        for a in self._aids:
            a.set_visible(False)
        k = 0
        for i, items in enumerate(self._items):
            key: Any = None  # the current step: set at every frame, never cached
            if i > st.step:
                key = "hidden"
            elif i < st.step or st.kind == "hold":  # the hold shows the finished figure
                key = 1.0 if steps[i].name in inputs or st.kind == "hold" else self.dim
            for a, role, snap in items:
                if key is None or self._keys[k] != key:
                    self._keys[k] = key
                    _restore(a, snap)
                    if key is None:
                        self._set_current(a, role, snap, steps[st.step], st.kind, st.progress,
                                          st.raw)
                    elif key == "hidden":
                        a.set_visible(False)
                    elif key < 1.0:
                        _fade(a, snap, key)
                k += 1
        self._caption.set_text(self.caption_at(frame))
        self._bar.set_width((st.frame + 1) / self.frame_count)

    def _set_current(self, a: Any, role: str, snap: dict[str, Any], step: Any, kind: str,
                     p: float, raw: float) -> None:
        if role not in ("fill", "label"):
            pulse = 1.0 + 0.5 * math.sin(math.pi * raw) if kind == "pause" else 1.0
            _tint(a, snap, self.theme.highlight_color, (1.0 if role == "marker" else 1.6) * pulse)
        if kind == "pause":
            if role == "marker" and step.kind == "point":  # a ripple round the key point
                ripple = (2 * raw) % 1.0
                self._halo.set(data=snap["data"], ms=snap["ms"] * (1.5 + 3.5 * ripple),
                               alpha=1.0 - ripple, visible=True)
        elif role == "marker":  # marked: the marker pops up
            a.set_markersize(snap["ms"] * p * (1.0 + 0.8 * math.sin(math.pi * p)))
            self._draw_aid(step, p)
        elif role == "label":
            a.set_visible(snap["visible"] and p >= 0.6)
        elif role == "line" and len(snap["data"][0]) == 2:  # the ruler, from its anchor
            (x0, x1), (y0, y1) = snap["data"]
            ax_, ay_ = next((v for v in (self._num[n] for n in step.inputs)
                             if isinstance(v, tuple) and isinstance(v[0], float)), (0.0, 0.0))
            a.set_data([ax_ + p * (x0 - ax_), ax_ + p * (x1 - ax_)],
                       [ay_ + p * (y0 - ay_), ay_ + p * (y1 - ay_)])
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

    def _draw_aid(self, step: Any, p: float) -> None:
        """Dashed helper lines of a point: the dropped perpendicular, the bisected
        segment, the two coordinates of V_n (§3.3 step (3))."""
        v, num = self._num[step.name], self._num
        if step.op in ("foot", "midpoint"):
            a = num[step.inputs[0]]
            b = v if step.op == "foot" else num[step.inputs[1]]
            xs, ys = [a[0], a[0] + p * (b[0] - a[0])], [a[1], a[1] + p * (b[1] - a[1])]
        elif step.op == "point_from_lengths":
            xs, ys = [v[0], v[0], np.nan, 0.0, p * v[0]], [0.0, p * v[1], np.nan, v[1], v[1]]
        else:
            return
        self._aid.set(data=(xs, ys), visible=True)


def animate_construction(construction: Any, fps: float = 20, frames_per_step: int = 8,
                         pause_frames: int = 12, hold_frames: int = 20,
                         theme: Theme = DEFAULT_THEME, figsize: tuple[float, float] = (5.0, 5.6),
                         dpi: float = 80, labels: bool = True,
                         rate: str = "smoothstep") -> ConstructionAnimation:
    """Animate the ruler-and-compass drawing of the internal force diagram (§3.3).

    Parameters
    ----------
    construction : Construction
        From :func:`graspcompass.internal_force_diagram` with numbers; only read.
    fps : float
        Frames per second of the saved files.
    frames_per_step, pause_frames, hold_frames : int
        Frames drawing each step; resting on each key result (V_n, eq. (30);
        the circles on O V_n, eq. (31), Fig. 3; the envelope, eq. (25),
        Fig. 5); and holding the finished diagram, into which the dimmed
        elements fade back: the last frame is the static figure of
        :func:`~graspcompass.render.draw_construction`.
    theme, figsize, dpi, labels
        Style, size in inches, resolution, point labels on or off.
    rate : {"smoothstep", "linear", "smootherstep"}
        Easing of the drawing.

    Returns
    -------
    ConstructionAnimation
        With ``.save(path)``, ``.to_html()``, ``.frame_count``, ``.timeline``,
        ``.figure``, ``.caption_at(frame)`` and ``_repr_html_``.
    """
    return ConstructionAnimation(construction, fps=fps, frames_per_step=frames_per_step,
                                 pause_frames=pause_frames, hold_frames=hold_frames,
                                 theme=theme, figsize=figsize, dpi=dpi, labels=labels, rate=rate)
