"""Hang detection for the hostile-input tests: one alarm, shared by every test file.

A call still running after ``seconds`` raises :class:`TimeoutError`; the bound is far
above the time a call may take, so it detects hangs, it is not a speed test.  Off the
main thread, or where there is no ``SIGALRM`` (Windows), it does nothing.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator


@contextlib.contextmanager
def no_hang(what: str, seconds: float) -> Iterator[None]:
    """Raise ``TimeoutError`` naming ``what`` if the block runs longer than ``seconds``."""
    if not hasattr(signal, "setitimer") or threading.current_thread() is not \
            threading.main_thread():  # pragma: no cover
        yield
        return

    def _hang(*_: object) -> None:
        raise TimeoutError(f"{what} still running after {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, _hang)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
