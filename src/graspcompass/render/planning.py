"""The picture of a contact plan (issue 13 §3): outline, best pairs with friction cones, heat map.

:func:`figure_plan` draws a :class:`graspcompass.planning.PlanResult` on a
matplotlib :class:`~matplotlib.figure.Figure` (no pyplot): on the left the
outline, its centre of mass and the best pairs of contacts, each contact with
its friction cone (half angle ξ, tan ξ = μ, eq. (22)) opening into the part, the
line through the two contacts (condition (1): each cone contains the other
contact); on the right the squeeze of every pair as a heat map over the
contacts' indices along the outline (blank where the pair is not force-closure).
The proved optima along the best edge pairs (:attr:`PlanResult.exact`), when
there are any, are drawn dashed with star markers.

Examples
--------
>>> from graspcompass.planning import plan_contacts
>>> plan = plan_contacts([(0, 0), (0.1, 0), (0.1, 0.06), (0, 0.06)], mu=0.5, samples=16)
>>> fig = figure_plan(plan, top=3)
>>> [ax.get_title().split(":")[0] for ax in fig.axes[:2]]
['Best contact pairs', 'Worst-case squeeze of every pair']
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.figure import Figure

if TYPE_CHECKING:
    from ..planning import PlanResult

__all__ = ["draw_plan_heatmap", "draw_plan_outline", "figure_plan"]

_COLOURS = (
    "#d62728",
    "#1f77b4",
    "#2ca02c",
    "#9467bd",
    "#ff7f0e",
    "#8c564b",
    "#e377c2",
    "#7f7f7f",
    "#bcbd22",
    "#17becf",
)


def draw_plan_outline(
    ax: Any, plan: PlanResult, top: int = 5, cone_length: float | None = None
) -> None:
    """Draw the outline, the centre of mass and the ``top`` best pairs with their cones.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    plan : graspcompass.planning.PlanResult
    top : int
        How many of the best pairs (at most 10 colours; more repeat them).
    cone_length : float, optional
        Length of the cones' sides in metres (default 12 % of the outline's size).
    """
    ring = np.asarray(plan.outline)
    mm = 1e3
    ax.fill(ring[:, 0] * mm, ring[:, 1] * mm, facecolor="#eeeeee", edgecolor="#333333", lw=1.2)
    ax.plot(
        plan.points[:, 0] * mm,
        plan.points[:, 1] * mm,
        ".",
        color="#999999",
        ms=2,
        label="sampled contacts",
    )
    ax.plot(plan.com[0] * mm, plan.com[1] * mm, "k+", ms=10, mew=2, label="centre of mass")
    size = float(np.ptp(ring, axis=0).max())
    r = (0.12 * size if cone_length is None else cone_length) * mm
    xi = math.atan(plan.mu)
    for rank, pair in enumerate(plan.top(top)):
        colour = _COLOURS[rank % len(_COLOURS)]
        (a, b), (na, nb) = np.asarray(pair.contacts) * mm, np.asarray(pair.normals)
        ax.plot(
            [a[0], b[0]],
            [a[1], b[1]],
            "-",
            color=colour,
            lw=1.4 if rank else 2.2,
            label=f"#{pair.rank}: {pair.squeeze:.3g} N",
        )
        for p, n in ((a, na), (b, nb)):
            base = math.atan2(n[1], n[0])
            sides = [
                p + r * np.array([math.cos(base + s * xi), math.sin(base + s * xi)])
                for s in (-1, 1)
            ]
            ax.fill(
                [p[0], sides[0][0], sides[1][0]],
                [p[1], sides[0][1], sides[1][1]],
                color=colour,
                alpha=0.18,
                lw=0,
            )
            for q in sides:
                ax.plot([p[0], q[0]], [p[1], q[1]], color=colour, lw=0.8)
            ax.plot(*p, "o", color=colour, ms=5)
    for pair in getattr(plan, "exact", ()):
        (a, b) = np.asarray(pair.contacts) * mm
        ax.plot(
            [a[0], b[0]],
            [a[1], b[1]],
            "--",
            color="black",
            lw=1.0,
            marker="*",
            ms=9,
            mfc="gold",
            label=f"proved best on edges {pair.edges[0]},{pair.edges[1]}: {pair.squeeze:.4g} N",
        )
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(
        f"Best contact pairs: μ = {plan.mu:.3g}, friction cones (half angle "
        f"{math.degrees(xi):.1f}°)",
        fontsize=9,
    )
    ax.legend(fontsize=6, loc="upper left", framealpha=0.8)


def draw_plan_heatmap(ax: Any, plan: PlanResult, cmap: str = "viridis") -> Any:
    """The squeeze of every pair as an N × N heat map over the contacts' indices.

    Contacts are numbered counter-clockwise along the outline; the matrix is
    symmetric, blank where condition (1) fails.  The best pair is circled.

    Returns
    -------
    matplotlib.image.AxesImage
        For a colour bar.
    """
    m = plan.matrix()
    from matplotlib.colors import LogNorm

    finite = m[np.isfinite(m) & (m > 0)]
    norm = LogNorm(float(finite.min()), float(finite.max())) if finite.size else None
    im = ax.imshow(m, origin="lower", cmap=cmap, norm=norm, interpolation="nearest")
    if len(plan.order):
        k = int(plan.order[0])
        for a, b in ((plan.i[k], plan.j[k]), (plan.j[k], plan.i[k])):
            ax.plot(b, a, "o", mfc="none", mec="red", ms=9, mew=1.5)
    ax.set_xlabel("contact index along the outline")
    ax.set_ylabel("contact index along the outline")
    unit = "N per jaw" if plan.per == "jaw" else "N, both jaws"
    ax.set_title(
        f"Worst-case squeeze of every pair: {unit}\n(log scale; blank: not force-closure)",
        fontsize=9,
    )
    return im


def figure_plan(plan: PlanResult, top: int = 5, size: tuple[float, float] = (11.0, 4.8)) -> Figure:
    """A figure of a contact plan: the best pairs (left) and the heat map (right).

    Parameters
    ----------
    plan : graspcompass.planning.PlanResult
    top : int
        How many of the best pairs to draw.
    size : (float, float)
        Figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = Figure(figsize=size, layout="constrained")
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.2, 1]})
    draw_plan_outline(left, plan, top)
    im = draw_plan_heatmap(right, plan)
    unit = "N per jaw" if plan.per == "jaw" else "N (both jaws)"
    fig.colorbar(im, ax=right, label=f"squeeze, {unit} ({plan.mass:.3g} kg)", shrink=0.9)
    return fig
