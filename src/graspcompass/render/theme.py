"""Colours, line widths and fonts of the drawings (plain data, no matplotlib import).

A :class:`Theme` is a frozen record read by :mod:`graspcompass.render.figure`.
:data:`DEFAULT_THEME` is a colour theme; :data:`PAPER_THEME` is black on white,
in the style of the paper's hand drawings (Figs. 4-7 of Ito, Tanaka and
Sasaki, Robotica 2012), where the four circles are told apart by their dashes.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

__all__ = ["DEFAULT_THEME", "PAPER_THEME", "THEMES", "Theme"]


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

    object_face: str = "#f2f2f2"
    object_edge: str = "#7f7f7f"
    cone_face: str = "#f4a261"
    cone_alpha: float = 0.35
    side_color: str = "#b5651d"
    axis_color: str = "#404040"
    construction_color: str = "#6c757d"
    circle_colors: tuple[str, str, str, str] = ("#1f77b4", "#2ca02c", "#9467bd", "#d62728")
    circle_styles: tuple[Any, ...] = ("--", "--", "--", "--")
    envelope_color: str = "#0b1f4b"
    envelope_fill: str = "#9ecae1"
    envelope_alpha: float = 0.18
    computer_color: str = "#ffd60a"
    computer_style: str = "-"
    point_color: str = "#111111"
    label_color: str = "#111111"
    highlight_color: str = "#e63946"
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
