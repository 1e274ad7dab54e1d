"""The label rules measured in a browser, shared by the SVG and web-page tests.

Rectangles are ``[x0, y0, x1, y1]`` from ``getBoundingClientRect``; each point is a
dict with its marker's rectangle ``m`` and its label's ``t`` (None: no label).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def overlap(a: Any, b: Any) -> float:
    """The area two rectangles share (0 when apart or only touching)."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return max(w, 0.0) * max(h, 0.0)


def cover_faults(pts: list[dict[str, Any]], where: str, name: Callable[[dict], str]) -> list[str]:
    """Every label over another label, and every label over a point's marker."""
    bad = []
    labelled = [p for p in pts if p["t"] is not None]
    for i, p in enumerate(labelled):
        for q in labelled[i + 1 :]:
            if overlap(p["t"], q["t"]) > 0.0:
                bad.append(f"{where}: label {name(p)} over label {name(q)}")
        for q in pts:
            if overlap(p["t"], q["m"]) > 0.0:
                bad.append(f"{where}: label {name(p)} over the marker of {name(q)}")
    return bad
