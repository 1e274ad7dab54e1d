"""Files from outside, read once and bounded: the one reader of the input boundary.

Imports only :mod:`graspcompass.errors`, so the command line reads (and refuses) a
file before loading sympy.

Examples
--------
>>> import tempfile, pathlib
>>> p = pathlib.Path(tempfile.mkdtemp()) / "a.gc"
>>> _ = p.write_text("A = point (0, 0)")
>>> read_bounded(p, 100)
b'A = point (0, 0)'
"""

from __future__ import annotations

import os
import stat
import sys

from .errors import InputError, InputTooLargeError, WrongTypeError

__all__ = ["read_bounded"]


def read_bounded(path: str | os.PathLike[str], limit: int) -> bytes:
    """The bytes of ``path`` (``"-"``: standard input), at most ``limit`` of them.

    Raises
    ------
    graspcompass.errors.InputTooLargeError
        Beyond ``limit`` bytes (never more than ``limit + 1`` are read).
    graspcompass.errors.InputError
        A file that cannot be read, with the system's reason; anything but a
        regular file (a folder, a FIFO, a device), refused before it is read,
        so that a FIFO without a writer cannot block the reader.
    graspcompass.errors.WrongTypeError
        ``path`` is not a file name (``str`` or :class:`os.PathLike` of one).
    """
    if not isinstance(path, (str, os.PathLike)) or not isinstance(os.fspath(path), str):
        raise WrongTypeError(
            f"expected a file name (str or pathlib.Path), got {type(path).__name__}"
        )
    name = os.fspath(path)
    try:
        if name == "-":
            data = sys.stdin.buffer.read(limit + 1)
        else:
            fd = os.open(name, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
            with os.fdopen(fd, "rb") as f:
                mode = os.fstat(f.fileno()).st_mode
                if not stat.S_ISREG(mode):
                    what = (
                        "a folder"
                        if stat.S_ISDIR(mode)
                        else ("a FIFO" if stat.S_ISFIFO(mode) else "not a regular file")
                    )
                    raise InputError(f"cannot read {name!r}: it is {what}; give a file")
                data = f.read(limit + 1)
    except OSError as exc:
        raise InputError(f"cannot read {str(name)!r}: {exc.strerror or exc}") from None
    if len(data) > limit:
        raise InputTooLargeError(f"{str(name)!r} is larger than {limit} bytes")
    return data
