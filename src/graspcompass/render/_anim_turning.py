"""The common part of the animations of the finished diagram: one turn of the direction θ.

:class:`_Turning` draws the diagram without its construction lines and keeps the
artists that turn or move; :func:`theta_of_orientation` and :func:`binding` are
public in :mod:`graspcompass.render.anim_physics` (their ``__module__``), which
re-exports them.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.figure import Figure
from matplotlib.text import Text

from ..scene.layout import numeric_objects
from .animate import FrameAnimation
from .figure import draw_construction
from .theme import Theme
from .timeline import AnimationError, Timeline

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

__all__ = ["binding", "theta_of_orientation"]

_KEEP = (
    "object",
    "cone1",
    "cone2",
    "O",
    "P1",
    "P2",
    "V1",
    "V2",
    "V3",
    "V4",
    "circle1",
    "circle2",
    "circle3",
    "circle4",
    "envelope",
)


def theta_of_orientation(alpha: Any) -> Any:
    """Direction θ of gravity in the object frame, the object turned counter-clockwise by α.

    θ = −α mod 2π (module docstring; eq. (26)).

    >>> float(theta_of_orientation(np.pi / 2) / np.pi)
    1.5
    """
    return np.mod(-np.asarray(alpha, dtype=float), 2 * np.pi)


def binding(ks: np.ndarray) -> np.ndarray:
    """Index n of the largest k_n (1-4), 0 where every k_n ≤ 0 (eq. (25)); ``ks`` is (4, N).

    >>> binding(np.array([[1.0, -1.0], [2.0, -2.0], [0.0, -1.0], [0.5, -0.5]])).tolist()
    [2, 0]
    """
    ks = np.asarray(ks, dtype=float)
    return np.where(ks.max(axis=0) > 0, np.argmax(ks, axis=0) + 1, 0)


class _Turning(FrameAnimation):
    """Common part: one turn in ``frames`` frames, the diagram without construction lines."""

    _blit_live = True

    def __init__(
        self,
        construction: Grasp | Construction,
        frames: int,
        fps: float,
        theme: Theme,
        figsize: tuple[float, float],
        dpi: float,
    ) -> None:
        from ..construction.protocol import Construction

        if not isinstance(construction, Construction):
            from ..construction import internal_force_diagram

            construction = internal_force_diagram(construction)
        if construction.grasp is None:
            raise AnimationError(
                "this animation needs the construction of a grasp (its "
                "k_grasp(θ)); a file replayed without one has none"
            )
        self.construction, self.grasp, self.theme = construction, construction.grasp, theme
        n = Timeline.uniform(frames).frame_count
        self.angle = 2 * np.pi * np.arange(n) / n
        super().__init__(Figure(figsize=figsize, dpi=dpi), self._timeline(), fps)
        self.figure.text(
            0.5,
            0.985,
            getattr(self.grasp, "title", None) or "",
            ha="center",
            va="top",
            fontsize=theme.font_size * 0.85,
        )
        self.axes = self.figure.add_axes((0.04, 0.07, 0.44, 0.84))
        self.num = numeric_objects(construction)
        self.V = [self.num[f"V{i}"] for i in (1, 2, 3, 4)]
        arts = draw_construction(construction, ax=self.axes, theme=theme, labels=False)
        self.kept: dict[str, list[Artist]] = {}
        for name, lst in arts.items():
            for a in lst:
                if name in _KEEP and not isinstance(a, Text):
                    self.kept.setdefault(name, []).append(a)
                else:
                    a.remove()
        self.artists: dict[str, Any] = {}

    def _timeline(self) -> Timeline:
        return Timeline.uniform(len(self.angle))

    def _text(self, y: float, **kw: Any) -> Text:
        """A text of the side panel, at the figure height ``y``.

        It lives in an invisible axes, not on the figure: matplotlib's blitting (the live
        ``FuncAnimation`` and its ``to_jshtml``, which the gallery shows) draws and saves
        only artists of an axes, so a figure text set animated stayed blank there.
        """
        if getattr(self, "text_axes", None) is None:
            self.text_axes = self.figure.add_axes((0.56, 0.0, 0.44, 0.3))
            self.text_axes.set_axis_off()
        return self.text_axes.text(
            0.58,
            y,
            "",
            fontsize=self.theme.font_size * 0.85,
            va="top",
            linespacing=1.45,
            transform=self.figure.transFigure,
            **kw,
        )

    def key_frames(self) -> list[tuple[int, str]]:
        """One frame every 30° of the turn."""
        n, name = self.frame_count, type(self).__name__[:5].lower()
        picks = sorted({round(k * n / 12) % n for k in range(12)})
        return [(f, f"{name}-{round(math.degrees(self.angle[f])):03d}") for f in picks]


theta_of_orientation.__module__ = binding.__module__ = "graspcompass.render.anim_physics"
