"""A construction animation small and quick enough to render every frame in a test.

One frame per step, no pause, one hold frame, no reading time and no zoom after the hold,
4 × 4.4 inches at 30 dpi with no least text size; a test gives what it needs otherwise.
"""

from __future__ import annotations

from typing import Any

from graspcompass.render.animate import animate_construction

#: The settings of :func:`small_animation`.
SMALL: dict[str, Any] = dict(
    frames_per_step=1,
    pause_frames=0,
    hold_frames=1,
    caption_seconds=0,
    figsize=(4, 4.4),
    dpi=30,
    min_text_px=0,
    inset_seconds=0,
)


def small_animation(construction: Any, **settings: Any) -> Any:
    """:func:`animate_construction` of ``construction`` with :data:`SMALL`, ``settings``
    over them."""
    return animate_construction(construction, **{**SMALL, **settings})
