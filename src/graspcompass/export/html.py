"""The self-contained web explorer: one HTML page with JSXGraph (issue 12; stub)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["write_html"]


def write_html(construction: Any, path: Any, title: str | None = None) -> Path:
    """Write the interactive web explorer of ``construction`` to ``path`` (not yet built)."""
    raise NotImplementedError("the web explorer is being built (issue 12)")
