"""A small terminal progress bar: on stderr, only on a TTY, silent with ``quiet``.

Examples
--------
>>> import io
>>> bar = Progress(3, "proofs", stream=io.StringIO())  # not a TTY: prints nothing
>>> for _ in range(3):
...     bar.update()
>>> bar.close()
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

__all__ = ["Progress"]


class Progress:
    """Progress of ``total`` units of work, drawn in place as ``label [####----] 3/8``.

    Parameters
    ----------
    total : int
        Number of units.
    label : str
        Text before the bar.
    quiet : bool
        Draw nothing.
    stream : file, optional
        Where to draw (default ``sys.stderr``); nothing is drawn unless it is a TTY.
    """

    def __init__(
        self, total: int, label: str = "", quiet: bool = False, stream: TextIO | None = None
    ) -> None:
        self.total, self.label, self.done = max(total, 1), label, 0
        self.stream = sys.stderr if stream is None else stream
        isatty = getattr(self.stream, "isatty", lambda: False)
        self.enabled = not quiet and bool(isatty())
        self._t0 = time.perf_counter()
        self._last = 0.0

    def update(self, n: int = 1, note: str = "") -> None:
        """Advance by ``n`` units; ``note`` is shown after the counter."""
        self.done = min(self.done + n, self.total)
        now = time.perf_counter()
        if not self.enabled or (now - self._last < 0.05 and self.done < self.total):
            return
        self._last = now
        width = 28
        fill = int(width * self.done / self.total)
        bar = "#" * fill + "-" * (width - fill)
        text = f"\r{self.label} [{bar}] {self.done}/{self.total} {now - self._t0:5.1f}s {note}"
        self.stream.write(text[:120].ljust(120))
        self.stream.flush()

    def close(self) -> None:
        """Erase the bar."""
        if self.enabled:
            self.stream.write("\r" + " " * 120 + "\r")
            self.stream.flush()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
