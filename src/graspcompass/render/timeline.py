"""Time base of the animations (a :class:`Timeline` of segments) and writing frames to files.

A :class:`Timeline` is plain data: consecutive :class:`Segment` s
``(step, frames, kind)``, ``kind`` being ``"draw"`` (a step's object is being
drawn), ``"pause"`` (resting on a key result: V_n, a circle on O V_n of
eq. (31), the envelope of eq. (25)), ``"rest"`` (the finished step stays on
screen, unchanged, until its caption has been read: :func:`reading_frames`),
``"hold"`` (the finished diagram), ``"inset"`` (after the hold, the camera's zoom on
the crowded region of the finished diagram and back) or ``"title"`` (a title card
before the first step).
:meth:`Timeline.at` maps a frame to a :class:`FrameState` (step, kind,
progress in [0, 1], eased by a rate function of :data:`RATES` while drawing).
It knows nothing of matplotlib or of the geometry, so the same timeline gives
the same frames.

The writers take frames as ``(height, width, 3)`` uint8 arrays: GIF with
Pillow (:func:`write_gif`), MP4 by piping raw frames to ``ffmpeg``
(:func:`write_mp4`), PNG (:func:`write_png`).
"""

from __future__ import annotations

import bisect
import math
import os
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..boundary._output import check_target, writing
from ..progress import Progress
from . import _anim_files
from ._anim_files import (
    AnimationError,
    FFmpegNotFoundError,
    UnsupportedFormatError,
    blend,
    check_fps,
    check_output,
    find_ffmpeg,
    jshtml,
    palette_sample,
    save_frames,
    write_gif,
    write_mp4,
    write_png,
)

__all__ = [
    "KINDS",
    "OUTPUT_FORMATS",
    "RATES",
    "AnimationError",
    "FFmpegNotFoundError",
    "FrameState",
    "Segment",
    "Timeline",
    "UnsupportedFormatError",
    "blend",
    "check_fps",
    "check_output",
    "find_ffmpeg",
    "jshtml",
    "palette_sample",
    "reading_frames",
    "save_frames",
    "smoothstep",
    "write_animation",
    "write_gif",
    "write_mp4",
    "write_png",
]

#: Kinds of segment.
KINDS = ("draw", "pause", "rest", "hold", "inset", "title")
#: File extensions an animation is written to.
OUTPUT_FORMATS = _anim_files.OUTPUT_FORMATS


def smoothstep(t: float) -> float:
    """``3t² − 2t³`` on [0, 1]: starts and ends at rest.

    >>> smoothstep(0.0), smoothstep(0.5), smoothstep(1.0)
    (0.0, 0.5, 1.0)
    """
    t = min(max(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


#: Rate functions ``[0, 1] -> [0, 1]`` by name, as in Manim.
RATES: dict[str, Callable[[float], float]] = {
    "linear": lambda t: min(max(t, 0.0), 1.0),
    "smoothstep": smoothstep,
    "smootherstep": lambda t: (lambda u: u**3 * (u * (6 * u - 15) + 10))(min(max(t, 0.0), 1.0)),
}


def reading_frames(
    text: str, fps: float, least_seconds: float = 0.0, chars_per_second: float = 0.0
) -> int:
    """Frames a caption must stay on screen to be read: ``least_seconds``, or longer by
    its length at ``chars_per_second`` (0: no length rule).

    >>> reading_frames("x" * 60, fps=20, least_seconds=2.5, chars_per_second=15)
    80
    >>> reading_frames("short", fps=20, least_seconds=2.5, chars_per_second=15)
    50
    """
    seconds = max(
        float(least_seconds), len(text) / chars_per_second if chars_per_second > 0 else 0.0
    )
    return math.ceil(round(seconds * check_fps(fps), 9))


@dataclass(frozen=True)
class Segment:
    """``frames`` consecutive frames of one step, of kind draw, pause or hold."""

    step: int
    frames: int
    kind: str = "draw"


@dataclass(frozen=True)
class FrameState:
    """Where a frame is: segment, step, kind and progress.

    ``raw`` goes linearly from ``1/n`` to 1 over the ``n`` frames of the
    segment (the last frame of a draw segment shows the finished object);
    ``progress`` is ``raw`` eased by the timeline's rate in draw segments, 1
    in rest segments.
    """

    frame: int
    segment: int
    step: int
    kind: str
    progress: float
    raw: float


@dataclass(frozen=True)
class Timeline:
    """The frames of an animation as consecutive segments (pure data).

    Examples
    --------
    >>> tl = Timeline.from_keys([False, True], frames_per_step=4, pause_frames=2,
    ...                         hold_frames=3)
    >>> tl.frame_count, [s.kind for s in tl.segments]
    (13, ['draw', 'draw', 'pause', 'hold'])
    >>> tl.at(3).step, tl.at(3).progress, tl.at(4).step
    (0, 1.0, 1)
    >>> len(tl.frames_of_step(1)), tl.last_frame_of_step(1)
    (9, 9)
    """

    segments: tuple[Segment, ...]
    rate: str = "smoothstep"
    starts: tuple[int, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.rate not in RATES:
            raise AnimationError(f"unknown rate {self.rate!r}; use one of {', '.join(RATES)}")
        if not self.segments:
            raise AnimationError("a timeline needs at least one segment")
        for s in self.segments:
            if s.kind not in KINDS or s.frames < 1:
                raise AnimationError(f"bad segment {s}: kind one of {KINDS}, frames >= 1")
        sizes = [s.frames for s in self.segments]
        object.__setattr__(self, "starts", tuple(int(v) for v in np.cumsum([0, *sizes[:-1]])))

    @classmethod
    def from_keys(
        cls,
        keys: Sequence[bool],
        frames_per_step: int = 8,
        pause_frames: int = 12,
        hold_frames: int = 20,
        rate: str = "smoothstep",
        least_frames: Sequence[int] | None = None,
        title_frames: int = 0,
    ) -> Timeline:
        """A draw segment per step, a pause after each key step, a hold at the end.

        ``title_frames`` (optional): a title card of that many frames first (kind
        ``"title"``, of step 0, nothing of the construction drawn).

        ``least_frames[i]`` (optional): the fewest frames step ``i`` lasts (its caption's
        reading time, :func:`reading_frames`); a rest segment makes up the difference.

        >>> tl = Timeline.from_keys([False, True], 4, 2, 3, least_frames=[10, 5])
        >>> [(s.kind, s.frames) for s in tl.segments]
        [('draw', 4), ('rest', 6), ('draw', 4), ('pause', 2), ('hold', 3)]
        """
        if frames_per_step < 1 or pause_frames < 0 or hold_frames < 0:
            raise AnimationError("frames_per_step must be >= 1, pause_frames and hold_frames >= 0")
        if least_frames is not None and len(least_frames) != len(keys):
            raise AnimationError(
                f"least_frames has {len(least_frames)} entries for {len(keys)} steps"
            )
        segs = [Segment(0, int(title_frames), "title")] if title_frames > 0 and keys else []
        for i, key in enumerate(keys):
            segs.append(Segment(i, frames_per_step, "draw"))
            pause = pause_frames if key else 0
            if pause:
                segs.append(Segment(i, pause, "pause"))
            rest = 0 if least_frames is None else int(least_frames[i]) - frames_per_step - pause
            if rest > 0:
                segs.append(Segment(i, rest, "rest"))
        if hold_frames and keys:
            segs.append(Segment(len(keys) - 1, hold_frames, "hold"))
        return cls(tuple(segs), rate)

    @classmethod
    def uniform(cls, frames: int, rate: str = "linear") -> Timeline:
        """One draw segment of ``frames`` frames."""
        if int(frames) < 1:
            raise AnimationError(f"frames must be at least 1, got {frames}")
        return cls((Segment(0, int(frames)),), rate)

    @property
    def frame_count(self) -> int:
        """Total number of frames."""
        return self.starts[-1] + self.segments[-1].frames

    def check(self, frame: int) -> int:
        """``frame`` in ``range(frame_count)`` (negative counts from the end), or IndexError."""
        n = self.frame_count
        if not -n <= frame < n:
            raise IndexError(f"frame {frame} out of range for a timeline of {n} frames")
        return int(frame) % n

    def segment_of(self, frame: int) -> int:
        """Index of the segment holding ``frame``."""
        return bisect.bisect_right(self.starts, self.check(frame)) - 1

    def segment_range(self, i: int) -> range:
        """The frames of segment ``i``."""
        return range(self.starts[i], self.starts[i] + self.segments[i].frames)

    def at(self, frame: int) -> FrameState:
        """The :class:`FrameState` of ``frame``."""
        f = self.check(frame)
        i = self.segment_of(f)
        seg = self.segments[i]
        raw = (f - self.starts[i] + 1) / seg.frames
        progress = (
            RATES[self.rate](raw) if seg.kind == "draw" else 1.0 if seg.kind == "rest" else raw
        )
        return FrameState(f, i, seg.step, seg.kind, progress, raw)

    def with_inset(self, frames: int) -> Timeline:
        """This timeline with an ``"inset"`` segment of ``frames`` frames at the end (after
        the hold; none if ``frames`` < 1).

        >>> tl = Timeline.from_keys([False], 4, 0, 3).with_inset(5)
        >>> [(s.kind, s.frames) for s in tl.segments]
        [('draw', 4), ('hold', 3), ('inset', 5)]
        """
        if frames < 1:
            return self
        last = self.segments[-1].step
        return Timeline((*self.segments, Segment(last, int(frames), "inset")), self.rate)

    def frames_of_step(self, step: int) -> range:
        """Every frame of ``step``: its draw, pause and (last step) hold segments (not the
        zoom on the crowded region after the hold, an ``"inset"`` segment)."""
        idx = [
            i
            for i, s in enumerate(self.segments)
            if s.step == step and s.kind not in ("title", "inset")
        ]
        if not idx:
            raise AnimationError(f"step {step} is not on this timeline")
        return range(self.starts[idx[0]], self.segment_range(idx[-1]).stop)

    def seconds_of_step(self, step: int, fps: float) -> float:
        """How long ``step`` (its caption) is on screen at ``fps``: its frames / fps."""
        return len(self.frames_of_step(step)) / check_fps(fps)

    def last_frame_of_step(self, step: int) -> int:
        """The last frame of the step's draw and pause segments (before a hold)."""
        idx = [
            i
            for i, s in enumerate(self.segments)
            if s.step == step and s.kind not in ("hold", "inset", "title")
        ]
        return self.segment_range(idx[-1]).stop - 1 if idx else self.frames_of_step(step)[-1]


def write_animation(
    anim: Any, path: str | os.PathLike[str], fps: float | None = None, quiet: bool = False
) -> Path:
    """Write ``anim`` (a :class:`~graspcompass.render.animate.FrameAnimation`) to ``path``.

    ``.gif`` with Pillow, ``.mp4`` with ffmpeg, ``.html`` self-contained
    (``anim.to_html``).  A progress bar goes to stderr when it is a terminal
    and ``quiet`` is false.  Errors (:class:`UnsupportedFormatError`,
    :class:`FFmpegNotFoundError`, :class:`AnimationError` for fps <= 0) are
    ValueErrors with one-line messages; so is :class:`~graspcompass.errors.OutputError`
    for a path that cannot be written (its folder must exist: it is not made),
    checked before any frame is drawn, or a write that fails (the half-written
    file is removed).
    """
    p = Path(path)
    ext = check_output(p)
    rate = anim.fps if fps is None else check_fps(fps)
    p = check_target(p)
    sample = palette_sample(anim) if ext != ".mp4" else None
    bar = Progress(anim.frame_count, f"writing {p.name}", quiet)

    def frames() -> Iterator[np.ndarray]:
        for rgb in anim.iter_frames():
            bar.update()
            yield rgb

    existed = os.path.lexists(p)
    try:
        with writing(p):
            if ext == ".gif":
                write_gif(frames(), p, rate, palette_sample=sample)
            elif ext == ".html":
                size = anim.figure.get_size_inches()
                text = jshtml(frames(), size, anim.figure.dpi, rate, sample)
                p.write_text(text, encoding="utf-8")
            else:
                write_mp4(frames(), p, rate)
    except BaseException:  # ffmpeg failed, Ctrl-C: no half-written animation is left behind
        if not existed and p.is_file():
            p.unlink(missing_ok=True)
        raise
    finally:
        bar.close()
    return p
