"""Colours, line widths and fonts of the drawings (plain data, no matplotlib import).

A :class:`Theme` is a frozen record read by :mod:`graspcompass.render.figure`.
:data:`DEFAULT_THEME` is a colour theme; :data:`PAPER_THEME` is black on white,
in the style of the paper's hand drawings (Figs. 4-7 of Ito, Tanaka and
Sasaki, Robotica 2012), where the four circles are told apart by their dashes.

The animations come in two :class:`Quality` presets (:data:`QUALITIES`):
``standard`` (the main job, notebooks: 640 × 720 pixels, every text at least
14 pixels high, each caption on screen at least 2 s) and ``lecture`` (for a
projector: 1280 × 720 pixels, a title card, captions in a side panel at 20 pt,
each caption on screen for at least 2.5 s and longer by its length, key steps
3 s longer, lines and labels 1.6 × larger).  Both have a camera that follows
the step being drawn.  The earlier steps of the construction are dimmed, but never below
the contrast of :data:`MIN_CONTRAST` against the background (WCAG 2.1:
3 : 1 for lines and markers, 4.5 : 1 for text; :func:`contrast_ratio`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from ..scene.palette import PALETTE

if TYPE_CHECKING:
    import numpy as np

__all__ = [
    "DEFAULT_THEME",
    "MIN_CONTRAST",
    "PAPER_THEME",
    "QUALITIES",
    "THEMES",
    "Quality",
    "Theme",
    "contrast_ratio",
    "relative_luminance",
]

#: Least contrast ratio against the background of a dimmed element (WCAG 2.1: non-text
#: contrast 1.4.11, 3 : 1; text contrast 1.4.3, 4.5 : 1).
MIN_CONTRAST = {"graphics": 3.0, "text": 4.5}


def relative_luminance(rgb: Sequence[float] | np.ndarray) -> float:
    """WCAG 2.1 relative luminance of an sRGB colour with channels in [0, 1].

    >>> relative_luminance((1.0, 1.0, 1.0)), relative_luminance((0.0, 0.0, 0.0))
    (1.0, 0.0)
    """
    lin = [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in rgb[:3]]
    return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]


def contrast_ratio(a: Sequence[float] | np.ndarray, b: Sequence[float] | np.ndarray) -> float:
    """WCAG 2.1 contrast ratio (L_light + 0.05) / (L_dark + 0.05) of two sRGB colours.

    >>> round(contrast_ratio((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)), 6)
    21.0
    >>> round(contrast_ratio((0.5, 0.5, 0.5), (1.0, 1.0, 1.0)), 2)
    3.98
    """
    la, lb = relative_luminance(a), relative_luminance(b)
    return (max(la, lb) + 0.05) / (min(la, lb) + 0.05)


@dataclass(frozen=True)
class Theme:
    """Drawing style of the internal force diagram.

    Attributes
    ----------
    object_face, object_edge : str
        Fill and outline of the grasped object (circle or rectangle).
    cone_face, cone_alpha : str, float
        Fill colour and opacity of the friction cones (Fig. 2).
    side_color : str
        The extended cone sides (the lines through P_i and X_n, §3.3 step (1)).
    axis_color : str
        The x- and y-axes.
    construction_color : str
        Perpendiculars, feet and the signed lengths (§3.3 step (2)).
    circle_colors : tuple of 4 str
        Colour of the circle on the diameter O V_n, n = 1..4 (eq. (31)-(32)).
    circle_styles : tuple of 4 str or dash tuples
        Matplotlib line styles of those circles.
    envelope_color, envelope_fill, envelope_alpha : str, str, float
        The outer envelope k_grasp (eq. (25), Fig. 5) and its light filling.
    computer_color, computer_style : str
        The computer plot of Fig. 6(b) drawn over the construction.
    point_color, label_color, highlight_color : str
        Point markers, their labels, and the object of the last step.
    line_width, thin_width, envelope_width, computer_width : float
        Line widths in points.
    point_size : float
        Marker size of the points, in points.
    font_size : float
        Label font size, in points.
    """

    object_face: str = PALETTE["objectfill"]
    object_edge: str = PALETTE["object"]
    cone_face: str = PALETTE["cone"]
    cone_alpha: float = 0.35
    side_color: str = PALETTE["side"]
    axis_color: str = PALETTE["axis"]
    construction_color: str = PALETTE["perp"]
    circle_colors: tuple[str, str, str, str] = tuple(  # type: ignore[assignment]
        PALETTE[f"circle{n}"] for n in (1, 2, 3, 4)
    )
    circle_styles: tuple[Any, ...] = ("--", "--", "--", "--")
    envelope_color: str = PALETTE["envelope"]
    envelope_fill: str = PALETTE["fill"]
    envelope_alpha: float = 0.18
    computer_color: str = PALETTE["computer"]
    computer_style: str = "-"
    point_color: str = PALETTE["point"]
    label_color: str = PALETTE["point"]
    highlight_color: str = PALETTE["highlight"]
    line_width: float = 1.1
    thin_width: float = 0.6
    envelope_width: float = 3.2
    computer_width: float = 1.0
    point_size: float = 4.0
    font_size: float = 10.0

    def circle_color(self, n: int) -> str:
        """Colour of the circle on O V_n (n = 1..4; other n cycle)."""
        return self.circle_colors[(n - 1) % len(self.circle_colors)]

    def circle_style(self, n: int) -> Any:
        """Line style of the circle on O V_n (n = 1..4; other n cycle)."""
        return self.circle_styles[(n - 1) % len(self.circle_styles)]

    def scaled(self, factor: float) -> Theme:
        """A copy with fonts, line widths and point sizes multiplied by ``factor``.

        >>> DEFAULT_THEME.scaled(2).line_width
        2.2
        """
        k = float(factor)
        return replace(
            self,
            line_width=self.line_width * k,
            thin_width=self.thin_width * k,
            envelope_width=self.envelope_width * k,
            computer_width=self.computer_width * k,
            point_size=self.point_size * k,
            font_size=self.font_size * k,
        )

    def with_(self, **changes: Any) -> Theme:
        """A copy with some fields changed.

        Examples
        --------
        >>> DEFAULT_THEME.with_(font_size=14).font_size
        14
        """
        return replace(self, **changes)


#: The colour theme used by default.
DEFAULT_THEME = Theme()

#: Black on white, like the paper's hand drawings.
PAPER_THEME = Theme(
    object_face="white",
    object_edge="black",
    cone_face="#bdbdbd",
    cone_alpha=0.45,
    side_color="black",
    axis_color="black",
    construction_color="#555555",
    circle_colors=("black", "black", "black", "black"),
    circle_styles=("--", "-.", ":", (0, (6, 2, 1, 2, 1, 2))),
    envelope_color="black",
    envelope_fill="#d9d9d9",
    envelope_alpha=0.25,
    computer_color="#a0a0a0",
    computer_style="-",
    point_color="black",
    label_color="black",
    highlight_color="black",
    computer_width=0.8,
)

#: Themes by name, for command lines.
THEMES: dict[str, Theme] = {"default": DEFAULT_THEME, "paper": PAPER_THEME}


@dataclass(frozen=True)
class Quality:
    """Size, pace and type of an animation (plain data; see :data:`QUALITIES`).

    Attributes
    ----------
    name : str
        ``standard`` or ``lecture``.
    figsize : (float, float)
        Frame size in inches of the construction animation; pixels = inches × ``dpi``.
    sweep_figsize : (float, float)
        Frame size of the sweep and orientation animations.
    dpi, fps : float
        Resolution and frames per second.
    frames_per_step : int
        Frames drawing one protocol step.
    pause_seconds, hold_seconds : float
        Rest on each key result (V_n, the circles, the envelope) and on the finished
        diagram.
    caption_seconds : float
        Least time each caption stays on screen (0: no rule).
    reading_rate : float
        Characters per second: a caption stays ``len(caption) / reading_rate`` seconds
        if that is longer (0: no rule).
    layout : {"below", "side"}
        Caption under the diagram or in a panel on its right.
    caption_size : float
        Caption font size in points (its head is 1.15 × larger in the side panel).
    scale : float
        Factor of the theme's fonts, lines and points (:meth:`Theme.scaled`).
    """

    name: str
    figsize: tuple[float, float]
    sweep_figsize: tuple[float, float]
    dpi: float
    fps: float
    frames_per_step: int
    pause_seconds: float
    hold_seconds: float
    caption_seconds: float
    reading_rate: float
    layout: str
    caption_size: float
    scale: float
    #: a title card this long before the first step (0: none)
    title_seconds: float = 0.0
    #: the camera follows the step being drawn (zooms in on a crowded step)
    camera: bool = True
    #: least height in pixels of every text of the frame (captions, labels, ticks)
    min_text_px: float = 14.0
    #: after the hold, the camera's zoom on the crowded region of the finished diagram,
    #: where each crowded point is named, and back (0: none; only with the camera)
    inset_seconds: float = 5.0

    def frames(self, seconds: float, fps: float | None = None) -> int:
        """``seconds`` as a whole number of frames at ``fps`` (default: this quality's).

        >>> QUALITIES["standard"].fps
        10.0
        >>> QUALITIES["standard"].frames(0.6), QUALITIES["standard"].frames(0.6, fps=20)
        (6, 12)
        """
        return max(0, round(float(seconds) * (self.fps if fps is None else float(fps))))


#: The animation presets by name (``graspcompass animate --quality``).
QUALITIES: dict[str, Quality] = {
    "standard": Quality(
        "standard",
        figsize=(8.0, 9.0),
        sweep_figsize=(9.6, 5.0),
        dpi=80.0,
        fps=10.0,
        frames_per_step=8,
        pause_seconds=1.0,
        hold_seconds=3.0,
        caption_seconds=2.0,
        reading_rate=0.0,
        layout="below",
        caption_size=13.0,
        scale=1.3,
    ),
    "lecture": Quality(
        "lecture",
        figsize=(12.8, 7.2),
        sweep_figsize=(12.8, 7.2),
        dpi=100.0,
        fps=15.0,
        frames_per_step=12,
        pause_seconds=3.0,
        hold_seconds=6.0,
        caption_seconds=2.5,
        reading_rate=15.0,
        layout="side",
        caption_size=20.0,
        scale=1.6,
        title_seconds=4.0,
        inset_seconds=8.0,
    ),
}
