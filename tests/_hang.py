"""Hang detection for the hostile-input tests: one alarm, shared by every test file.

A call still running after ``seconds`` raises :class:`TimeoutError`; the bound is far
above the time a call may take, so it detects hangs, it is not a speed test.  Off the
main thread, or where there is no ``SIGALRM`` (Windows), it does nothing.
"""

from __future__ import annotations

from contextlib import AbstractContextManager

from graspcompass.boundary._deadline import deadline


def no_hang(what: str, seconds: float) -> AbstractContextManager[None]:
    """Raise ``TimeoutError`` naming ``what`` if the block runs longer than ``seconds``."""
    return deadline(seconds, lambda: TimeoutError(f"{what} still running after {seconds:g} s"))
