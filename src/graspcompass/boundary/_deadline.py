"""One alarm: raise an exception when a block runs longer than a bound (POSIX, main thread).

Used by ``graspcompass check --timeout`` and by the tests' hang detection
(``tests/_hang.py``).  Off the main thread, or without ``SIGALRM`` (Windows), it
does nothing.  Deadlines nest: an inner block gets the earlier of its own bound
and the outer one's, the exception of whichever bound is reached, and the outer
alarm is re-armed for the time it has left when the inner block ends.

Examples
--------
>>> with deadline(5.0, lambda: TimeoutError("too slow")):
...     with deadline(1.0, lambda: TimeoutError("inner too slow")):
...         pass
"""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from collections.abc import Callable, Iterator
from types import FrameType

__all__ = ["OutOfTime", "command_deadline", "deadline"]


class OutOfTime(BaseException):
    """A command ran past its ``--timeout``.  A :class:`BaseException`, like
    :class:`KeyboardInterrupt`, so that no ``except Exception`` on the way swallows it."""


_EARLY = 0.005  # an alarm may ring this much before the monotonic clock agrees


@contextlib.contextmanager
def deadline(seconds: float, error: Callable[[], BaseException]) -> Iterator[None]:
    """Raise ``error()`` inside the block if it is still running after ``seconds``."""
    if (
        not hasattr(signal, "setitimer")
        or threading.current_thread() is not threading.main_thread()
    ):  # pragma: no cover
        yield
        return
    now = time.monotonic()
    end = now + seconds
    previous = signal.getsignal(signal.SIGALRM)
    outer_left = signal.getitimer(signal.ITIMER_REAL)[0]
    outer_end = now + outer_left if outer_left > 0 else None

    def _ring(signum: int, frame: FrameType | None) -> None:
        if time.monotonic() < end - _EARLY and callable(previous):
            previous(signum, frame)  # the outer bound came first: its exception
        raise error()

    signal.signal(signal.SIGALRM, _ring)
    signal.setitimer(
        signal.ITIMER_REAL,
        max(min(seconds, outer_left) if outer_end is not None else seconds, 1e-4),
    )
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer_end is not None:
            signal.setitimer(signal.ITIMER_REAL, max(outer_end - time.monotonic(), 1e-4))


def command_deadline(seconds: float | None) -> contextlib.AbstractContextManager[None]:
    """The ``--timeout`` of a command: :class:`OutOfTime` after ``seconds`` (None: none)."""
    if seconds is None:
        return contextlib.nullcontext()
    return deadline(
        seconds,
        lambda: OutOfTime(
            f"the command took longer than {seconds:g} s (--timeout S allows more): its input "
            "makes too much work"
        ),
    )
