"""The computer plots: k_grasp(θ) in polar form (Fig. 6(b)) and k_n(θ) against θ.

Both are computed numerically from the closed form of the grasp
(:meth:`graspcompass.Grasp.k_grasp`, eq. (25); :meth:`graspcompass.Grasp.k`,
eqs. (27), (32)), independently of the ruler-and-compass construction, so
that drawing them over the construction checks it, as §4.1 does.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from .theme import DEFAULT_THEME, Theme

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["draw_k_polar", "figure_k_plot", "polar_points"]


def polar_points(theta: np.ndarray, k: np.ndarray) -> np.ndarray:
    """The polar points ``k·e(θ)`` with ``e(θ) = (sin θ, −cos θ)`` (eq. (26)), shape (N, 2)."""
    return np.column_stack([k * np.sin(theta), -k * np.cos(theta)])


def draw_k_polar(
    grasp: Grasp,
    ax: Axes | None = None,
    samples: int = 2000,
    theme: Theme = DEFAULT_THEME,
    components: bool = False,
    label: str | None = "computer plot, eq. (25)",
) -> dict[str, list[Artist]]:
    """Draw the computer plot of Fig. 6(b): the polar curve θ ↦ k_grasp(θ)·e(θ).

    Parameters
    ----------
    grasp : Grasp
        A grasp with numeric parameters.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new :class:`~matplotlib.figure.Figure` is made if None.
    samples : int
        Number of values of θ, evenly spaced over [0, 2π] (both ends included).
    theme : Theme
        Colours and widths (``computer_color``, ``computer_width``).
    components : bool
        Also draw the four k_n(θ) of eqs. (27), (32) thin where k_n > 0: each
        is the circle on the diameter O V_n (eq. (31), Fig. 3).
    label : str or None
        Legend label of the k_grasp curve.

    Returns
    -------
    dict of str to list of Artist
        ``"k_grasp"`` (one Line2D in the object frame), and ``"k1"``..``"k4"``
        when ``components`` is true.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> arts = draw_k_polar(Grasp.preset("fig6"), samples=5)
    >>> arts["k_grasp"][0].get_xydata().shape
    (5, 2)
    """
    if ax is None:
        ax = Figure(figsize=(6, 6)).add_subplot()
        ax.set_aspect("equal")
    theta = np.linspace(0.0, 2 * np.pi, samples)
    out: dict[str, list[Artist]] = {}
    if components:
        ks = grasp.k(theta)
        for n in (1, 2, 3, 4):
            k = np.where(ks[n - 1] > 0, ks[n - 1], np.nan)
            xy = polar_points(theta, k)
            out[f"k{n}"] = list(
                ax.plot(
                    xy[:, 0],
                    xy[:, 1],
                    color=theme.circle_color(n),
                    lw=theme.thin_width,
                    zorder=4.4,
                    label=f"$k_{n}(\\theta)$",
                )
            )
    xy = polar_points(theta, np.asarray(grasp.k_grasp(theta), dtype=float))
    out["k_grasp"] = list(
        ax.plot(
            xy[:, 0],
            xy[:, 1],
            color=theme.computer_color,
            ls=theme.computer_style,
            lw=theme.computer_width,
            zorder=4.5,
            label=label if label is not None else "_nolegend_",
        )
    )
    return out


def figure_k_plot(
    grasp: Grasp,
    samples: int = 2000,
    theme: Theme = DEFAULT_THEME,
    title: str | None = None,
    figsize: tuple[float, float] = (8.0, 4.5),
) -> Figure:
    """A cartesian plot of k_1..k_4(θ) and k_grasp(θ) for θ in [0, 2π] (degrees).

    k_n(θ) = S_n sin θ − C_n cos θ (eqs. (27), (32)) are drawn thin and
    k_grasp(θ) = max(k_1, .., k_4, 0) (eq. (25)) bold: the cartesian view of
    the envelope of Fig. 5.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> fig = figure_k_plot(Grasp.preset("table1a"), samples=50)
    >>> len(fig.axes[0].lines)
    6
    """
    fig = Figure(figsize=figsize, layout="constrained")
    ax = fig.add_subplot()
    theta = np.linspace(0.0, 2 * np.pi, samples)
    deg = np.degrees(theta)
    ks = grasp.k(theta)
    for n in (1, 2, 3, 4):
        ax.plot(
            deg,
            ks[n - 1],
            color=theme.circle_color(n),
            ls=theme.circle_style(n),
            lw=theme.line_width,
            label=f"$k_{n}(\\theta)$",
        )
    ax.plot(
        deg,
        grasp.k_grasp(theta),
        color=theme.envelope_color,
        lw=theme.envelope_width * 0.8,
        label=r"$k_{grasp}(\theta)$, eq. (25)",
    )
    ax.axhline(0.0, color=theme.axis_color, lw=theme.thin_width)
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xlabel(r"direction of the external force $\theta$ [deg]")
    ax.set_ylabel(r"$k$")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=theme.font_size * 0.85)
    ax.set_title(
        title if title is not None else (getattr(grasp, "title", None) or ""),
        fontsize=theme.font_size,
    )
    return fig
