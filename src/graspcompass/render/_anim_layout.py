"""The layout of a construction animation: title, caption, progress bar and diagram.

The caption goes below the diagram (``standard``) or in a panel beside it
(``lecture``); every caption is wrapped at spaces to the width it is given, as
drawn (:func:`_wrap`, :func:`_text_width`), and the diagram is placed so that the
longest fits whole.  Private to :mod:`graspcompass.render.animate`, which
re-exports these names.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.patches import Rectangle

from .timeline import AnimationError

if TYPE_CHECKING:
    from .animate import ConstructionAnimation


def _wrap(text: str, width: float, measure: Any) -> str:
    """``text`` broken at spaces into lines no wider than ``width`` pixels; ``measure(s)``
    is the width of ``s`` as drawn."""
    lines: list[str] = []
    for para in text.split("\n"):
        line = ""
        for word in para.split(" "):
            trial = f"{line} {word}" if line else word
            if line and measure(trial) > width:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return "\n".join(lines)


def _text_width(renderer: Any, prop: Any) -> Any:
    """A fast measure of text widths in pixels: the sum of the characters' advances
    (measured once each), 3 % wider for kerning and hinting."""
    cache: dict[str, float] = {}

    def measure(s: str) -> float:
        total = 0.0
        for ch in s:
            if ch not in cache:
                cache[ch] = (
                    renderer.get_text_width_height_descent(f"|{ch}|", prop, False)[0]
                    - renderer.get_text_width_height_descent("||", prop, False)[0]
                )
            total += cache[ch]
        return 1.03 * total

    return measure


def _layout(anim: ConstructionAnimation, layout: str, caption_pt: float) -> None:
    """Place the title, the caption, the progress bar and the diagram of ``anim`` so that
    the longest caption fits whole (measured as drawn)."""
    fig, ax, th = anim.figure, anim.axes, anim.theme
    if layout not in ("below", "side"):
        raise AnimationError(f"unknown layout {layout!r}; use 'below' or 'side'")
    anim.layout = layout
    W, H = fig.get_size_inches() * fig.dpi
    renderer = anim._canvas.get_renderer()
    px = fig.dpi / 72.0
    title_pt = max(
        th.font_size * 0.8 * (1.3 if layout == "side" else 1.0), getattr(anim, "_least_pt", 0.0)
    )
    title = fig.text(
        0.5,
        1 - 0.012 * W / H,
        getattr(anim.construction.grasp, "title", None) or "",
        ha="center",
        va="top",
        fontsize=title_pt,
    )
    bar_h = max(0.012, 4.0 / H) if layout == "side" else 0.012
    anim._bar = Rectangle(
        (0, 0), 0, bar_h, transform=fig.transFigure, color=th.highlight_color, zorder=10
    )
    fig.add_artist(anim._bar)
    margin = max(0.03 * W, 4.0)
    tick = th.font_size * 0.7 * px * 1.6  # the tick labels' room
    title_h = title_pt * px * 1.5 + 0.012 * W
    if layout == "below":
        width = W - 2 * margin
        x_cap = margin
    else:
        side = H - title_h - bar_h * H - tick - 2 * margin  # a square diagram on the left
        ax.set_position(
            (margin * 1.6 / W + tick / W, (bar_h * H + tick + margin) / H, side / W, side / H)
        )
        x_cap = margin * 1.6 + tick + side + 2.5 * margin
        width = W - x_cap - margin
    anim._caption = fig.text(
        x_cap / W, 0.5, "", va="top", linespacing=1.4, fontsize=caption_pt, fontweight="normal"
    )
    measure = _text_width(renderer, anim._caption.get_fontproperties())
    anim._wrapped = [_wrap(t, width, measure) for t in anim._texts]
    anim._hold_wrapped = _wrap(anim._hold_text, width, measure)
    tallest = 0.0
    for t in {*anim._wrapped, anim._hold_wrapped}:
        anim._caption.set_text(t)
        tallest = max(tallest, anim._caption.get_window_extent(renderer).height)
    anim._caption.set_text("")
    if layout == "below":
        top = bar_h * H + 0.6 * margin + tallest  # the caption's top, in pixels
        anim._caption.set_y(top / H)
        bottom = top + 0.4 * margin + tick
        ax.set_position((0.1, bottom / H, 0.86, max(0.05, 1 - bottom / H - title_h / H)))
        anim._fade_region = np.s_[: int(H - top - 2)]
    else:
        anim._caption.set_y(1 - title_h / H - margin / H)
        anim._fade_region = np.s_[:, : int(x_cap - margin)]
    anim._title = title
