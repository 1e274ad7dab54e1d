"""The internal force diagram of an n-contact grasp, drawn with matplotlib.

The contacts with their friction cones, the polygon Q (its vertices q and the
redundant dual vertices, greyed), the Thales circles on O q (Fig. 3) and their
outer envelope, the polar plot of the least effort v(θ) (Fig. 5): the point
``v(θ) e(θ)``, ``e(θ) = (sin θ, -cos θ)`` (eq. (26)).  Without force closure the
envelope is drawn on the arc of θ where the load can be held, and the recession
directions of Q are drawn as arrows from O.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..scene.palette import PALETTE

if TYPE_CHECKING:
    from ..ncontact.model import NContactGrasp

__all__ = ["draw_ncontact"]

_CIRCLES = ["circle1", "circle2", "circle3", "circle4"]


def draw_ncontact(
    grasp: NContactGrasp, ax: Any = None, n_theta: int = 1441, title: str | None = None
) -> Any:
    """Draw the n-contact diagram of ``grasp`` (a :class:`~graspcompass.ncontact.NContactGrasp`).

    Parameters
    ----------
    grasp : NContactGrasp
        The grasp; its Q is computed (exactly when the grasp is exact).
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: a new figure).
    n_theta : int, optional
        Directions θ sampled for the envelope.
    title : str, optional
        The axes' title (default: the number of contacts and the effort).

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Polygon

    if ax is None:
        fig, ax = plt.subplots(figsize=(7, 7))
    else:
        fig = ax.figure
    Q = grasp.polygon()
    V = Q.float_vertices()
    ox, oy = (float(v) for v in grasp.com)
    # Q itself, lightly filled, and the Thales circles on O q (centred at O + q/2)
    if len(V) >= 3 and Q.bounded:
        ax.add_patch(
            Polygon(
                V + np.array([ox, oy]),
                closed=True,
                facecolor=PALETTE["fill"],
                edgecolor="none",
                alpha=0.25,
                zorder=1,
            )
        )
    for i, (qx, qy) in enumerate(V):
        color = PALETTE[_CIRCLES[i % 4]]
        ax.add_patch(
            Circle(
                (ox + qx / 2, oy + qy / 2),
                math.hypot(qx, qy) / 2,
                fill=False,
                lw=0.9,
                color=color,
                alpha=0.8,
                zorder=2,
            )
        )
        ax.plot([ox, ox + qx], [oy, oy + qy], color=color, lw=0.6, ls=":", zorder=2)
        ax.plot(ox + qx, oy + qy, "o", ms=5, color=color, zorder=5)
        ax.annotate(
            f"q{i + 1}",
            (ox + qx, oy + qy),
            textcoords="offset points",
            xytext=(4, 4),
            fontsize=8,
            color=color,
        )
    for c in Q.redundant:
        qx, qy = c.floats()
        ax.add_patch(
            Circle(
                (ox + qx / 2, oy + qy / 2),
                math.hypot(qx, qy) / 2,
                fill=False,
                lw=0.6,
                ls="--",
                color="#9a9a9a",
                zorder=2,
            )
        )
        ax.plot(ox + qx, oy + qy, "x", ms=5, color="#9a9a9a", zorder=5)
    # the envelope: v(θ) e(θ), where finite
    t = np.linspace(0.0, 2 * math.pi, n_theta)
    v = np.asarray(grasp.k(t), dtype=float)
    x, y = ox + v * np.sin(t), oy - v * np.cos(t)
    ok = np.isfinite(v)
    x[~ok] = np.nan
    y[~ok] = np.nan
    ax.plot(x, y, color=PALETTE["envelope"], lw=2.0, zorder=4, label="least effort v(θ)")
    # recession directions of Q (no force closure)
    scale = max([1.0] + [float(np.hypot(*q)) for q in V])
    for k, r in enumerate(Q._float_rays()):
        rr = r / np.hypot(*r) * 0.5 * scale
        ax.arrow(
            ox,
            oy,
            rr[0],
            rr[1],
            width=0.004 * scale,
            head_width=0.03 * scale,
            length_includes_head=True,
            color=PALETTE["highlight"],
            zorder=6,
            label="recession directions of Q" if k == 0 else None,
        )
    # the contacts and their friction cones (edges drawn into the object)
    spread = max(
        [0.0] + [math.hypot(float(c.p[0]) - ox, float(c.p[1]) - oy) for c in grasp.contacts]
    )
    reach = 0.3 * (spread or scale)
    for i, contact in enumerate(grasp.contacts):
        px, py = (float(v) for v in contact.p)
        for d in contact.edges():
            dx, dy = float(d[0]), float(d[1])
            n = math.hypot(dx, dy)
            ax.plot(
                [px, px + reach * dx / n],
                [py, py + reach * dy / n],
                color=PALETTE["side"],
                lw=1.2,
                zorder=3,
            )
        ax.plot(px, py, "s", ms=6, color=PALETTE["contact"], zorder=6)
        ax.annotate(
            f"P{i + 1}",
            (px, py),
            textcoords="offset points",
            xytext=(5, -10),
            fontsize=9,
            color=PALETTE["contact"],
        )
    ax.plot(ox, oy, "+", ms=10, color=PALETTE["point"], zorder=6)
    ax.annotate("O", (ox, oy), textcoords="offset points", xytext=(-10, -10), fontsize=9)
    ax.set_aspect("equal")
    ax.grid(True, color="#eeeeee", lw=0.5)
    closure = "force closure" if grasp.force_closure else "no force closure"
    ax.set_title(
        title
        or f"{grasp.n} contacts, effort {grasp.effort.name}: {len(V)} vertices "
        f"of Q, {len(Q.redundant)} redundant; {closure}",
        fontsize=10,
    )
    ax.legend(loc="lower right", fontsize=8)
    return fig
