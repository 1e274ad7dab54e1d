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
import sys

from .errors import InputError, InputTooLargeError

__all__ = ["read_bounded"]


def read_bounded(path: str | os.PathLike[str], limit: int) -> bytes:
    """The bytes of ``path`` (``"-"``: standard input), at most ``limit`` of them.

    Raises
    ------
    graspcompass.errors.InputTooLargeError
        Beyond ``limit`` bytes (never more than ``limit + 1`` are read).
    graspcompass.errors.InputError
        A file that cannot be read, with the system's reason.
    """
    name = os.fspath(path)
    try:
        if name == "-":
            data = sys.stdin.buffer.read(limit + 1)
        else:
            with open(name, "rb") as f:
                data = f.read(limit + 1)
    except OSError as exc:
        raise InputError(f"cannot read {str(name)!r}: {exc.strerror or exc}") from None
    if len(data) > limit:
        raise InputTooLargeError(f"{str(name)!r} is larger than {limit} bytes")
    return data
