"""Writing animation frames to files (GIF, MP4, HTML, PNG) and the errors of animations.

The writers of :mod:`graspcompass.render.timeline`, which re-exports every public
name (their ``__module__`` is that module's: documented and pickled there).
Frames are ``(height, width, 3)`` uint8 arrays.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
from collections.abc import Iterable, Iterator
from itertools import chain
from pathlib import Path
from typing import Any

import numpy as np

from ..boundary._output import check_folder, check_target, writing
from ..boundary.errors import GraspCompassError

__all__ = [
    "OUTPUT_FORMATS",
    "AnimationError",
    "FFmpegNotFoundError",
    "UnsupportedFormatError",
    "blend",
    "check_fps",
    "check_output",
    "find_ffmpeg",
    "jshtml",
    "palette_sample",
    "save_frames",
    "write_gif",
    "write_mp4",
    "write_png",
]

#: File extensions an animation is written to.
OUTPUT_FORMATS = (".gif", ".mp4", ".html")


class AnimationError(GraspCompassError):
    """A user error while making or writing an animation (one-line message)."""


class UnsupportedFormatError(AnimationError):
    """The output file's extension is not one an animation can be written to."""


class FFmpegNotFoundError(AnimationError):
    """MP4 output needs the ``ffmpeg`` program, which is not installed."""


def check_fps(fps: float) -> float:
    """``fps`` as a float; :class:`AnimationError` unless it is positive and finite."""
    try:
        value = float(fps)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise AnimationError(f"fps must be a positive number, got {fps!r}")
    return value


def find_ffmpeg() -> str:
    """The ``ffmpeg`` program, or :class:`FFmpegNotFoundError`.

    rcParams ``animation.ffmpeg_path`` when set to another program than its
    default ``ffmpeg``; else the one of the ``mp4`` extra (``pip install
    'graspcompass[mp4]'``: the ``imageio-ffmpeg`` wheel, which carries an ffmpeg
    build) if installed; else ``ffmpeg`` on the PATH.
    """
    import matplotlib as mpl

    chosen = str(mpl.rcParams["animation.ffmpeg_path"])
    if chosen == "ffmpeg":
        try:
            import imageio_ffmpeg
        except ImportError:
            pass
        else:
            try:
                return str(imageio_ffmpeg.get_ffmpeg_exe())
            except RuntimeError:  # the wheel has no binary for this platform
                pass
    exe = shutil.which(chosen)
    if exe is None:
        raise FFmpegNotFoundError(
            "cannot write MP4: no ffmpeg (pip install "
            "'graspcompass[mp4]', or a system ffmpeg; or write .gif or "
            ".html)"
        )
    return exe


def check_output(path: str | os.PathLike[str]) -> str:
    """The extension of ``path`` if an animation can be written there (ffmpeg for .mp4).

    >>> check_output("construction.GIF")
    '.gif'
    >>> check_output("construction.avi")
    Traceback (most recent call last):
    ...
    graspcompass.render.timeline.UnsupportedFormatError: cannot write an animation to ...
    """
    p = Path(path)
    ext = p.suffix.lower()
    if ext not in OUTPUT_FORMATS:
        what = f"extension {p.suffix!r}" if p.suffix else "a path without extension"
        raise UnsupportedFormatError(
            f"cannot write an animation to {str(p)!r}: {what} is not supported; use "
            f"{', '.join(OUTPUT_FORMATS)} (save_frames() writes PNG frames)"
        )
    if ext == ".mp4":
        find_ffmpeg()
    return ext


def blend(a: np.ndarray, b: np.ndarray, w: float, rows: slice = slice(None)) -> np.ndarray:
    """The cross-fade ``(1 − w)·a + w·b`` on ``rows`` (``b`` elsewhere), as uint8."""
    if w >= 1.0:
        return b
    out = b.copy()
    mixed = a[rows].astype(np.float32) * (1.0 - w) + b[rows].astype(np.float32) * w
    out[rows] = np.rint(mixed).astype(np.uint8)
    return out


def write_gif(
    frames: Iterable[np.ndarray],
    path: str | os.PathLike[str],
    fps: float,
    palette_sample: np.ndarray | None = None,
) -> int:
    """Write RGB frames as a looping GIF with Pillow; returns the number of GIF frames.

    One 256-colour palette, from ``palette_sample`` (default: the first frame),
    serves every frame, without dithering, so the file is deterministic.
    Pillow merges a frame identical to the one before into it (adding the
    durations), so the GIF may hold fewer frames, playing for the same time.
    """
    from PIL import Image

    it = iter(frames)
    first = next(it)
    palette = _palette(first if palette_sample is None else palette_sample)
    images: list[Image.Image] = []
    distinct, previous, last = 0, b"", None
    for rgb in chain([first], it):
        if rgb is last:  # the same frame again (a still): nothing to quantize
            images.append(images[-1])
            continue
        last = rgb
        im = Image.fromarray(rgb).quantize(palette=palette, dither=Image.Dither.NONE)
        data = im.tobytes()
        distinct += data != previous
        previous = data
        images.append(im)
    images[0].save(
        path,
        save_all=True,
        append_images=images[1:],
        loop=0,
        optimize=False,
        duration=1000.0 / check_fps(fps),
        disposal=1,
    )
    return distinct


def write_mp4(
    frames: Iterator[np.ndarray],
    path: str | os.PathLike[str],
    fps: float,
    ffmpeg: str | None = None,
) -> int:
    """Pipe RGB frames to ``ffmpeg`` (H.264, yuv420p); returns the number of frames."""
    exe = ffmpeg or find_ffmpeg()
    first = next(frames)
    h, w = first.shape[:2]
    cmd = [
        exe,
        "-y",
        "-loglevel",
        "error",
        "-f",
        "rawvideo",
        "-vcodec",
        "rawvideo",
        "-s",
        f"{w}x{h}",
        "-pix_fmt",
        "rgb24",
        "-r",
        f"{check_fps(fps):g}",
        "-i",
        "-",
        "-an",
        "-vcodec",
        "libx264",
        # a diagram: x264's veryfast preset is a third quicker than its default and, for
        # these flat colours and still frames, no larger
        "-preset",
        "veryfast",
        "-pix_fmt",
        "yuv420p",
        "-vf",
        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
        str(path),
    ]
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdin is not None
    count = 0
    last: Any = None
    data = b""
    try:
        for rgb in chain([first], frames):
            if rgb is not last:  # a still is the frame before again: its bytes made once
                last, data = rgb, np.ascontiguousarray(rgb, dtype=np.uint8).tobytes()
            proc.stdin.write(data)
            count += 1
    except BrokenPipeError:
        pass
    _, err = proc.communicate()
    if proc.returncode:
        lines = (err or b"").decode(errors="replace").strip().splitlines()
        raise AnimationError(
            f"ffmpeg failed writing {str(path)!r}: "
            f"{lines[-1] if lines else f'exit status {proc.returncode}'}"
        )
    return count


def palette_sample(anim: Any) -> np.ndarray:
    """Three frames of ``anim`` (a third in, two thirds in, the last) stacked: the colours."""
    n = anim.frame_count
    return np.concatenate([anim.render(f) for f in sorted({n // 3, 2 * n // 3, n - 1})])


def _palette(sample: np.ndarray) -> Any:
    from PIL import Image

    return Image.fromarray(sample).quantize(256, method=Image.Quantize.MEDIANCUT)


class _Frames:
    """Stands in for the figure in matplotlib's HTMLWriter: savefig writes the current frame."""

    def __init__(self, size: Any, dpi: float, palette: Any) -> None:
        self.size, self.dpi, self.palette = size, dpi, palette
        self.rgb = np.zeros((1, 1, 3), np.uint8)

    def get_size_inches(self) -> Any:
        return self.size

    def set_size_inches(self, *args: Any, **kwargs: Any) -> None:
        """The frames are already drawn: their size does not change."""

    def savefig(self, fname: Any, format: str = "png", **kwargs: Any) -> None:
        from PIL import Image

        im = Image.fromarray(self.rgb)
        if self.palette is not None and format.lower() == "png":
            im = im.quantize(palette=self.palette, dither=Image.Dither.NONE)
        im.save(fname, format=format.upper())


#: The stand-in data of a frame equal to an earlier one (``_SAME.format(k)``); the
#: finished page sets ``frames[i] = frames[k]`` instead.
_SAME = "=same{}="
_SAME_LINE = re.compile(r'frames\[(\d+)\] = "data:image/\w+;base64,=same(\d+)="')


def jshtml(
    frames: Iterable[np.ndarray],
    size: Any,
    dpi: float,
    fps: float,
    palette_sample: np.ndarray | None = None,
) -> str:
    """Self-contained interactive HTML of RGB frames, the player that ``to_jshtml`` makes.

    matplotlib's :class:`~matplotlib.animation.HTMLWriter` embeds the frames
    (at most ``rcParams["animation.embed_limit"]`` MB, past which it drops
    them); ``size`` and ``dpi`` are the figure's.  A frame equal to an earlier
    one (a still: a caption being read, a rest on a key step) is stored once
    and shown again by reference (``frames[i] = frames[k]``), so only the
    distinct frames count against the limit.  With ``palette_sample`` the PNG
    frames have 256 colours, like the GIF, and take about a third of the room.
    """
    import hashlib
    from tempfile import TemporaryDirectory

    from matplotlib.animation import HTMLWriter

    source = _Frames(size, dpi, None if palette_sample is None else _palette(palette_sample))
    # the stubs ask an int fps and a Figure: the writer takes any rate, and of the figure
    # only what _Frames has (its size, dpi and savefig)
    writer = HTMLWriter(
        fps=check_fps(fps),  # type: ignore[arg-type]
        embed_frames=True,
        default_mode="loop",
    )
    seen: dict[bytes, int] = {}  # a frame's digest -> the first frame showing it
    stored: list[int] = []  # frame i shows the image of frame stored[i]
    with TemporaryDirectory() as tmp:
        out = Path(tmp, "animation.html")
        with writer.saving(source, out, dpi):  # type: ignore[arg-type]
            last = None
            for rgb in frames:
                if rgb is last:  # a still: the frame before again
                    first: int | None = stored[-1]
                else:
                    key = hashlib.blake2b(np.ascontiguousarray(rgb).data, digest_size=16).digest()
                    first = seen.setdefault(key, len(stored))
                    first = None if first == len(stored) else first
                last = rgb
                if getattr(writer, "_hit_limit", False):  # past the limit it drops every frame
                    break
                if first is None:
                    source.rgb = rgb
                    writer.grab_frame()
                    stored.append(len(stored))
                else:  # into the writer's own list: a reference instead of the image
                    writer._saved_frames.append(_SAME.format(first))  # type: ignore[attr-defined]
                    stored.append(first)
        page = out.read_text(encoding="utf-8")
    return _SAME_LINE.sub(r"frames[\1] = frames[\2]", page)


def write_png(rgb: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write one RGB frame as a PNG file."""
    from PIL import Image

    Image.fromarray(rgb).save(path, format="PNG")
    return Path(path)


def save_frames(
    anim: Any, folder: str | os.PathLike[str], frames: Iterable[int] | None = None, prefix: str = ""
) -> list[Path]:
    """Write PNG frames of ``anim`` into ``folder``; by default ``anim.key_frames()``.

    For the construction: one PNG per protocol step, the frame at the end of
    the step (after its pause); for the sweep and orientation: one every 30°.

    Raises
    ------
    graspcompass.errors.OutputError
        If ``folder`` does not exist (it is not made) or is not writable, checked
        before any frame is drawn, or if a write fails (that file is removed).
    """
    out = check_folder(folder)
    picks = anim.key_frames() if frames is None else [(f, f"frame-{f:04d}") for f in frames]
    written = []
    for f, name in picks:
        target = check_target(out / f"{prefix}{name}.png")
        rgb = anim.render(f)
        with writing(target):
            written.append(write_png(rgb, target))
    return written


# documented and pickled as graspcompass.render.timeline's (which re-exports them)
for _public in (
    AnimationError,
    UnsupportedFormatError,
    FFmpegNotFoundError,
    check_fps,
    find_ffmpeg,
    check_output,
    blend,
    write_gif,
    write_mp4,
    palette_sample,
    jshtml,
    write_png,
    save_frames,
):
    _public.__module__ = "graspcompass.render.timeline"
