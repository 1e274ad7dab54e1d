"""The artists of an animated construction: their states, dimming, highlighting.

An artist's state as :func:`~graspcompass.render.draw_construction` drew it is
snapped once (:func:`_snap`) and put back for every frame (:func:`_restore`);
an earlier step is dimmed (:func:`_fade`) no further than :func:`dim_alpha`
allows, so that it keeps its contrast against the background (WCAG 2.1,
:data:`~graspcompass.render.theme.MIN_CONTRAST`); the current step is tinted
(:func:`_tint`).  Private to :mod:`graspcompass.render.animate`, which
re-exports these names.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.colors import to_rgb, to_rgba
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.text import Annotation, Text

from .theme import QUALITIES, Quality, contrast_ratio
from .timeline import AnimationError


def _snap(a: Artist) -> dict[str, Any]:
    """What :func:`_restore` needs to put ``a`` back as :func:`draw_construction` drew it."""
    s: dict[str, Any] = {"visible": a.get_visible(), "alpha": a.get_alpha()}
    if isinstance(a, Line2D):
        s.update(
            color=a.get_color(),
            lw=a.get_linewidth(),
            ms=a.get_markersize(),
            mfc=a.get_markerfacecolor(),
            mec=a.get_markeredgecolor(),
            data=(np.array(a.get_xdata(), float), np.array(a.get_ydata(), float)),
        )
    elif isinstance(a, Patch):  # colours as given: "none" stays invisible under any alpha
        s.update(
            lw=a.get_linewidth(),
            ec=getattr(a, "_original_edgecolor", a.get_edgecolor()),
            fc=getattr(a, "_original_facecolor", a.get_facecolor()),
        )
    if isinstance(a, Text):
        s["color"] = a.get_color()
    if isinstance(a, Annotation):
        s["xy"] = tuple(a.xy)
        if a.arrow_patch is not None:
            s["arrow"] = _snap(a.arrow_patch)
    return s


def _restore(a: Any, s: dict[str, Any]) -> None:
    a.set_visible(s["visible"])
    a.set_alpha(s["alpha"])
    if isinstance(a, Line2D):
        a.set(color=s["color"], lw=s["lw"], ms=s["ms"], mfc=s["mfc"], mec=s["mec"])
        a.set_data(*s["data"])
    elif isinstance(a, Patch):
        a.set(edgecolor=s["ec"], facecolor=s["fc"], lw=s["lw"])
    if isinstance(a, Text):
        a.set_color(s["color"])
    if isinstance(a, Annotation):
        a.xy = s["xy"]
        if "arrow" in s:
            _restore(a.arrow_patch, s["arrow"])
        a.stale = True


def _fade(a: Any, s: dict[str, Any], factor: float) -> None:
    a.set_alpha((1.0 if s["alpha"] is None else s["alpha"]) * factor)
    if "arrow" in s:
        _fade(a.arrow_patch, s["arrow"], factor)


def _tint(a: Any, s: dict[str, Any], color: Any, widen: float) -> None:
    """Colour ``a`` as the new object and widen its lines by ``widen``."""
    if isinstance(a, Line2D):
        a.set(color=color, mec=color, lw=s["lw"] * widen)
        if to_rgba(s["mfc"]) != to_rgba("white"):
            a.set_markerfacecolor(color)
    elif isinstance(a, Patch):
        a.set(edgecolor=color, lw=s["lw"] * widen)
    if "arrow" in s:
        a.arrow_patch.set_color(color)


def _inks(a: Any, s: dict[str, Any]) -> list[Any]:
    """The colours ``a`` draws lines, markers or glyphs with (not its fills)."""
    out: list[Any] = []
    if isinstance(a, Line2D):
        if a.get_linestyle() not in ("None", "none", "", " "):
            out.append(s["color"])
        if a.get_marker() not in (None, "None", "none", "", " "):
            out += [s["mec"]] + (
                [s["mfc"]]
                if to_rgba(s["mfc"])[3] > 0 and to_rgb(s["mfc"]) != (1.0, 1.0, 1.0)
                else []
            )
    elif isinstance(a, Patch):
        if s["lw"] > 0 and to_rgba(s["ec"])[3] > 0:
            out.append(s["ec"])
    if isinstance(a, Text) and a.get_text():
        out.append(s["color"])
    if "arrow" in s:
        out += _inks(a.arrow_patch, s["arrow"])
    return out


def dim_alpha(colors: list[Any], background: Any, ratio: float, floor: float) -> float:
    """The least opacity in [``floor``, 1] at which every colour of ``colors``, laid over
    ``background``, keeps the contrast ``ratio`` (WCAG 2.1) against it; 1 if one of them
    has less even when opaque.

    >>> round(dim_alpha(["black"], "white", 3.0, 0.3), 2)
    0.42
    >>> dim_alpha(["#ffd60a"], "white", 3.0, 0.3)  # too light to start with
    1.0
    """
    bg = np.array(to_rgb(background))
    alpha = float(floor)
    for c in colors:
        rgba = to_rgba(c)
        rgb, own = np.array(rgba[:3]), rgba[3]
        if contrast_ratio(own * rgb + (1 - own) * bg, bg) < ratio:
            return 1.0
        lo, hi = alpha, 1.0
        if contrast_ratio(lo * own * rgb + (1 - lo * own) * bg, bg) >= ratio:
            continue
        for _ in range(40):  # the contrast grows with the opacity
            mid = (lo + hi) / 2
            if contrast_ratio(mid * own * rgb + (1 - mid * own) * bg, bg) >= ratio:
                hi = mid
            else:
                lo = mid
        alpha = hi
    return alpha


def _quality(quality: str | Quality) -> Quality:
    if isinstance(quality, Quality):
        return quality
    if quality not in QUALITIES:
        raise AnimationError(f"unknown quality {quality!r}; use one of {', '.join(QUALITIES)}")
    return QUALITIES[quality]
