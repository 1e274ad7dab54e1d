"""Matplotlib drawings of the internal force diagram (Ito, Tanaka, Sasaki, Robotica 2012).

The only part of :mod:`graspcompass` that imports matplotlib, and it never uses
pyplot: figures are :class:`matplotlib.figure.Figure` objects, which work
without a display.

- :func:`draw_construction`: the state of the ruler-and-compass construction
  after any step (§3.3, Figs. 3-5);
- :func:`figure_diagram`: the complete diagram with the computer plot of
  Fig. 6(b) on top (eq. (25));
- :func:`draw_k_polar`, :func:`figure_k_plot`: the computer plots of k_grasp;
- :func:`save_figure`: PNG, SVG or PDF;
- :class:`Theme`, :data:`DEFAULT_THEME`, :data:`PAPER_THEME`: the styles;
- :func:`animate_construction`, :func:`animate_sweep`, :func:`animate_orientation`:
  step-by-step and sweeping animations (GIF, MP4, HTML, PNG frames).

Examples
--------
>>> from graspcompass import Grasp, internal_force_diagram
>>> from graspcompass.render import figure_diagram
>>> fig = figure_diagram(internal_force_diagram(Grasp.preset("fig6")))
>>> fig.axes[0].get_title()[:6]
'Fig. 6'
"""

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:
    from .anim_physics import (
        SLIP,
        OrientationAnimation,
        SweepAnimation,
        animate_orientation,
        animate_sweep,
        theta_of_orientation,
    )
    from .animate import ConstructionAnimation, FrameAnimation, animate_construction, save_frames
    from .explorer import Explorer, explore, explore_notebook
    from .figure import (
        EXTRA_KEYS,
        FORMATS,
        draw_construction,
        draw_k_polar,
        figure_diagram,
        figure_k_plot,
        save_figure,
    )
    from .handdrawing import worksheet
    from .theme import DEFAULT_THEME, PAPER_THEME, THEMES, Theme
    from .timeline import AnimationError, FFmpegNotFoundError, Timeline, UnsupportedFormatError

__all__ = [
    "DEFAULT_THEME",
    "EXTRA_KEYS",
    "FORMATS",
    "PAPER_THEME",
    "SLIP",
    "THEMES",
    "AnimationError",
    "ConstructionAnimation",
    "Explorer",
    "FFmpegNotFoundError",
    "FrameAnimation",
    "OrientationAnimation",
    "SweepAnimation",
    "Theme",
    "Timeline",
    "UnsupportedFormatError",
    "animate_construction",
    "animate_orientation",
    "animate_sweep",
    "draw_construction",
    "draw_k_polar",
    "explore",
    "explore_notebook",
    "figure_diagram",
    "figure_k_plot",
    "save_figure",
    "save_frames",
    "theta_of_orientation",
    "worksheet",
]

#: Where each name lives; matplotlib is imported with the first drawing name used.
__getattr__, __dir__ = attach(
    __name__,
    {
        "SLIP": "anim_physics",
        "OrientationAnimation": "anim_physics",
        "SweepAnimation": "anim_physics",
        "animate_orientation": "anim_physics",
        "animate_sweep": "anim_physics",
        "theta_of_orientation": "anim_physics",
        "ConstructionAnimation": "animate",
        "FrameAnimation": "animate",
        "animate_construction": "animate",
        "save_frames": "animate",
        "Explorer": "explorer",
        "explore": "explorer",
        "explore_notebook": "explorer",
        "EXTRA_KEYS": "figure",
        "FORMATS": "figure",
        "draw_construction": "figure",
        "draw_k_polar": "figure",
        "figure_diagram": "figure",
        "figure_k_plot": "figure",
        "save_figure": "figure",
        "DEFAULT_THEME": "theme",
        "PAPER_THEME": "theme",
        "THEMES": "theme",
        "Theme": "theme",
        "AnimationError": "timeline",
        "FFmpegNotFoundError": "timeline",
        "Timeline": "timeline",
        "UnsupportedFormatError": "timeline",
        "worksheet": "handdrawing",
    },
)
