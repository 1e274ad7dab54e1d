"""The table ``graspcompass verify`` prints, fitted to the terminal's width.

The columns and the lines after them are those of
:func:`graspcompass.proof.to_table`; here the seconds come before the method,
and the method and every longer line are wrapped to the terminal's width
(``COLUMNS``, else the terminal's, else 100 characters), continuation lines
indented, so that nothing is cut and no line is 450 characters wide.

Examples
--------
>>> print(fit_line("  eq5: " + "x > 0, " * 12, 40))
  eq5: x > 0, x > 0, x > 0, x > 0, x >
      0, x > 0, x > 0, x > 0, x > 0, x >
      0, x > 0, x > 0,
"""

from __future__ import annotations

import shutil
import textwrap
from collections.abc import Sequence
from typing import Any

__all__ = ["MIN_WIDTH", "fit_line", "table", "width"]

#: The narrowest table: below it the lines are wrapped at this width anyway.
MIN_WIDTH = 60


def width() -> int:
    """The terminal's width (``COLUMNS`` first; 100 when not a terminal), at least MIN_WIDTH."""
    return max(MIN_WIDTH, shutil.get_terminal_size((100, 24)).columns)


def fit_line(line: str, cols: int) -> str:
    """``line`` wrapped at ``cols``, its continuation lines indented 4 more than it."""
    if len(line) <= cols:
        return line
    indent = " " * (len(line) - len(line.lstrip()) + 4)
    return "\n".join(textwrap.wrap(line, cols, subsequent_indent=indent,
                                   break_on_hyphens=False)) or line


def table(reports: Sequence[Any], cols: int | None = None) -> str:
    """The verify report as :func:`graspcompass.proof.to_table` has it, fitted to ``cols``."""
    from ..proof import to_table

    cols = width() if cols is None else max(MIN_WIDTH, cols)
    rows = [(r.claim.id, r.claim.ref, r.result.status.value, f"{r.result.seconds:.2f}",
             r.result.method) for r in reports]
    head = ("id", "paper", "status", "s", "method")
    w = [max(len(str(x[i])) for x in [head, *rows]) for i in range(4)]
    start = sum(w) + 2 * 4
    if cols - start < 24:  # too narrow beside the columns: the method on lines of its own
        start = 4
    room = cols - start
    lines = []
    for row in [head, *rows]:
        left = "  ".join(str(x).ljust(w[i]) for i, x in enumerate(row[:4]))
        method = textwrap.wrap(row[4], room, break_on_hyphens=False) or [""]
        if start == 4:
            lines += [fit_line(left.rstrip(), cols), *("    " + m for m in method)]
            continue
        lines.append(f"{left}  {method[0]}".rstrip())
        lines += [" " * start + more for more in method[1:]]
    tail = to_table(reports).split("\n")[1 + len(rows):]
    return "\n".join(lines + [fit_line(line, cols) for line in tail])
