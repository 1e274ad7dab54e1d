"""The player of the animations: frames drawn by blitting, written as GIF, MP4 or HTML.

:class:`~graspcompass.render.animate.FrameAnimation` sets the artists of a frame
from a :class:`~graspcompass.render.timeline.Timeline` and draws only what moves
on a saved background; the construction (:mod:`graspcompass.render.animate`) and
the physics (:mod:`graspcompass.render.anim_physics`) animations share it.  The
class is documented, pickled and shown as ``graspcompass.render.animate.FrameAnimation``.
Private to :mod:`graspcompass.render.animate`, which re-exports it.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.animation import FuncAnimation
from matplotlib.artist import Artist
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from .timeline import (
    Timeline,
    blend,
    check_fps,
    jshtml,
    palette_sample,
    write_animation,
    write_gif,
)


class _Player(FuncAnimation):
    """The :class:`~matplotlib.animation.FuncAnimation` of a :class:`FrameAnimation`: shown
    live as any, but its HTML (``to_jshtml``, which sphinx-gallery and Jupyter embed) is
    the player's own (:meth:`FrameAnimation.to_html`): drawn by blitting, 256 colours, each
    still stored once, so the whole animation embeds under ``animation.embed_limit``."""

    def __init__(self, owner: FrameAnimation, *args: Any, **kwargs: Any) -> None:
        self._owner = owner
        self._page: str | None = None
        super().__init__(owner.figure, *args, **kwargs)

    def _start(self, *args: Any) -> None:
        """Start playing on the first draw of the figure, unless the owner drew it (a frame
        rendered into a file or a page: the live animation must not set the artists then)."""
        event = args[0] if args else None
        if getattr(event, "renderer", None) is getattr(self._owner._canvas, "renderer", 0):
            return
        super()._start(*args)  # type: ignore[misc]

    def save(  # type: ignore[override]
        self, filename: Any, writer: Any = None, fps: Any = None, dpi: Any = None, **kwargs: Any
    ) -> None:
        """A GIF with the player's own writer (drawn by blitting; sphinx-gallery's
        thumbnail), its frames scaled by ``dpi`` / the figure's; anything else as
        :meth:`FuncAnimation.save <matplotlib.animation.Animation.save>` does."""
        if Path(filename).suffix.lower() != ".gif" or kwargs or not isinstance(writer, str | None):
            return super().save(filename, writer, fps, dpi, **kwargs)
        owner = self._owner
        scale = 1.0 if dpi in (None, "figure") else float(dpi) / owner.figure.dpi
        w, h = owner._canvas.get_width_height()
        size = (max(1, round(w * scale)), max(1, round(h * scale)))

        def fit(rgb: np.ndarray) -> np.ndarray:
            if size == (rgb.shape[1], rgb.shape[0]):
                return rgb
            return np.asarray(Image.fromarray(rgb).resize(size, Image.Resampling.LANCZOS))

        def frames() -> Iterator[np.ndarray]:
            last: Any = None
            fitted: Any = None
            for rgb in owner.iter_frames():
                if rgb is not last:  # a still is the same frame again: resized once
                    last, fitted = rgb, fit(rgb)
                yield fitted

        sample = palette_sample(owner)
        n = sample.shape[0] // h  # the sample's frames, stacked
        parts = [fit(sample[i * h : (i + 1) * h]) for i in range(n)]
        write_gif(frames(), filename, owner.fps if fps is None else fps, np.concatenate(parts))
        self._draw_was_started = True
        return None

    def to_jshtml(
        self, fps: float | None = None, embed_frames: bool = True, default_mode: Any = None
    ) -> str:
        """The player's HTML of every frame (``fps``: the owner's by default).

        ``embed_frames`` and ``default_mode`` are those of the owner's player: every frame
        embedded, looping."""
        if fps is None and self._page is not None:
            return self._page
        html = self._owner.to_html(fps)
        self._draw_was_started = True  # rendered: no warning when it is deleted
        if fps is None:
            self._page = html
        return html


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

    def _crossfade(self, segment: int) -> Any:
        """The image region (an index of the RGB array) shown as a cross-fade of the frames
        around the segment, or None."""
        return None

    def _still(self, frame: int) -> bool:
        """True if ``frame`` is the same picture as the frame before it (nothing moves)."""
        return False

    def key_frames(self) -> list[tuple[int, str]]:
        """``(frame, name)`` of the frames :func:`save_frames` writes by default."""
        return [(f, f"frame-{f:04d}") for f in range(self.frame_count)]

    @property
    def frame_count(self) -> int:
        """Number of frames."""
        return self.timeline.frame_count

    @property
    def drawn_frames(self) -> int:
        """Frames that are drawn: all but the stills, which repeat the frame before."""
        tl = self.timeline
        return sum(
            1
            for i, seg in enumerate(tl.segments)
            for f in tl.segment_range(i)
            if f == tl.starts[i] or not self._still(f)
        )

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
            return blend(
                self.render(rng.start - 1), self.render(rng.stop - 1), tl.at(f).progress, rows
            )
        for a in self._dynamic:  # a live blitting FuncAnimation may have left them animated
            a.set_animated(False)
        self._apply(f)
        self._canvas.draw()
        return self._buffer()

    def _buffer(self) -> np.ndarray:
        """The canvas as a new RGB array (Pillow drops the alpha channel twice as fast as a
        strided numpy copy)."""
        w, h = self._canvas.get_width_height(physical=True)
        rgba = Image.frombuffer("RGBA", (w, h), self._canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        return np.asarray(rgba.convert("RGB"))

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
                    if last is not None and f > frames.start and self._still(f):
                        yield last
                        continue
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
        """Draw ``artists`` in the order the figure draws them (z-order, then as added)."""
        place = {
            id(a): k for k, a in enumerate(c for ax in self.figure.axes for c in ax.get_children())
        }
        # on this player's canvas, not the figure's (pyplot may have given it another one)
        renderer = self._canvas.get_renderer()
        for a in sorted(artists, key=lambda a: (a.get_zorder(), place.get(id(a), -1))):
            if a.get_visible():
                a.draw(renderer)

    def save(
        self, path: str | os.PathLike[str], fps: float | None = None, quiet: bool = False
    ) -> Path:
        """Write ``.gif``, ``.mp4`` or ``.html``; see :func:`~.timeline.write_animation`."""
        return write_animation(self, path, fps, quiet)

    @property
    def animation(self) -> FuncAnimation:
        """A :class:`~matplotlib.animation.FuncAnimation` of the frames, for live display
        (blitting in the sweep and orientation animations)."""
        if self._anim is None:
            self._anim = _Player(
                self,
                self.update,
                frames=self.frame_count,
                init_func=lambda: self.update(0),
                repeat=True,
                interval=1000.0 / self.fps,
                blit=self._blit_live,
                cache_frame_data=False,
            )
        return self._anim

    def to_html(self, fps: float | None = None) -> str:
        """Self-contained interactive HTML of every frame, the player of ``to_jshtml``."""
        rate = self.fps if fps is None else check_fps(fps)
        return jshtml(
            self.iter_frames(),
            self.figure.get_size_inches(),
            self.figure.dpi,
            rate,
            palette_sample(self),
        )

    def _repr_html_(self) -> str:
        return self.to_html()


FrameAnimation.__module__ = "graspcompass.render.animate"  # documented and pickled there
