"""One alarm: raise an exception when a block runs longer than a bound (POSIX, main thread).

Used by ``graspcompass check --timeout`` and by the tests' hang detection
(``tests/_hang.py``).  Off the main thread, or without ``SIGALRM`` (Windows), it
does nothing.

Examples
--------
>>> with deadline(5.0, lambda: TimeoutError("too slow")):
...     pass
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Callable, Iterator

__all__ = ["OutOfTime", "deadline"]


class OutOfTime(BaseException):
    """A command ran past its ``--timeout``.  A :class:`BaseException`, like
    :class:`KeyboardInterrupt`, so that no ``except Exception`` on the way swallows it."""


@contextlib.contextmanager
def deadline(seconds: float, error: Callable[[], BaseException]) -> Iterator[None]:
    """Raise ``error()`` inside the block if it is still running after ``seconds``.

    Alarms nest: inside a block with an earlier alarm this one does nothing; inside one
    with a later alarm, the enclosing alarm gets back what is left of its time on exit.
    """
    if not hasattr(signal, "setitimer") or threading.current_thread() is not \
            threading.main_thread():  # pragma: no cover
        yield
        return

    def _ring(*_: object) -> None:
        raise error()

    outer = signal.getitimer(signal.ITIMER_REAL)[0]
    if 0 < outer <= seconds:  # an enclosing alarm rings first: leave it in charge
        yield
        return
    import time

    start = time.monotonic()
    previous = signal.signal(signal.SIGALRM, _ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer > 0:  # an enclosing alarm: give it back what is left of its time
            signal.setitimer(signal.ITIMER_REAL, max(outer - (time.monotonic() - start), 1e-3))
