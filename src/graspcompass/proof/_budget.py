"""A time budget shared by the rows of one run (``--timeout`` of check, verify, certify).

:class:`Budget` runs one piece of work (a step, a claim, a target, a catalogue
entry) at a time under the seconds the whole run has left: a verdict reached
before the end is kept, and every piece not finished by then is reported as
timed out (UNDECIDED) by the caller's ``on_timeout``.  The alarm is
:func:`graspcompass.boundary._deadline.deadline` (POSIX, main thread); elsewhere the
budget is checked between pieces only.

Examples
--------
>>> b = Budget(None)
>>> b.run(lambda: "done", lambda: "timed out")
'done'
>>> Budget(0.0).run(lambda: "done", lambda: "timed out")
'timed out'
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TypeVar

from ..boundary._deadline import deadline

__all__ = ["TIMED_OUT", "Budget"]

T = TypeVar("T")

#: The method of a row the run had no time left for.
TIMED_OUT = "timed out: the run reached its time limit (--timeout) before deciding it"


class _Expired(BaseException):
    """The budget ran out inside one piece of work (a BaseException: never swallowed)."""


class Budget:
    """Seconds left for a run; ``None`` for no limit."""

    def __init__(self, seconds: float | None) -> None:
        if seconds is not None and not seconds >= 0:
            raise ValueError(f"a timeout is a number of seconds >= 0, got {seconds!r}")
        self.seconds = seconds
        self.end = None if seconds is None else time.monotonic() + seconds

    def left(self) -> float | None:
        """Seconds left (``None``: no limit)."""
        return None if self.end is None else self.end - time.monotonic()

    @property
    def expired(self) -> bool:
        """True when no time is left."""
        left = self.left()
        return left is not None and left <= 0

    def run(self, work: Callable[..., T], on_timeout: Callable[..., T]) -> T:
        """``work()`` if it ends before the budget, else ``on_timeout()``."""
        left = self.left()
        if left is None:
            return work()
        if left <= 0:
            return on_timeout()
        try:
            with deadline(left, _Expired):
                return work()
        except _Expired:
            return on_timeout()
