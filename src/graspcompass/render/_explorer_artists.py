"""The Explorer's artists: made once, then only moved (a mixin of the Explorer's state).

:class:`_Artists` makes every artist of the diagram, orders the moving ones by the
region they are blitted in, and moves them to a :class:`~._explorer_scene.Scene`,
a direction θ or a message.  Private to :mod:`graspcompass.render.explorer`.
"""

from __future__ import annotations

import math
import textwrap
from typing import Any

import numpy as np
from matplotlib.font_manager import FontProperties
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import Polygon
from matplotlib.transforms import Bbox, TransformedBbox

from ..scene.layout import wedge
from ..scene.palette import PALETTE
from ._explorer_scene import GRASP_KEYS, Scene
from ._pathtext import PathText
from .theme import DEFAULT_THEME

_LABELS = ("P1", "P2", "V1", "V2", "V3", "V4")


class _Artists:
    """The Explorer's artists (a mixin: the Explorer holds the state)."""

    params: dict[str, float]
    sliders: dict[str, Any]
    ax: Any
    fig: Any
    info: Any
    _info_box: Bbox
    scene: Scene | None
    error: str | None
    envelope_xy: np.ndarray
    worst: tuple[float, float]
    best: tuple[float, float]

    def _make_artists(self) -> None:
        ax, th = self.ax, DEFAULT_THEME
        self.axis_lines = [
            ax.axhline(0, color=th.axis_color, lw=0.8),
            ax.axvline(0, color=th.axis_color, lw=0.8),
        ]
        self.cones = [
            ax.add_patch(
                Polygon(
                    np.zeros((3, 2)), facecolor=th.cone_face, alpha=th.cone_alpha, edgecolor="none"
                )
            )
            for _ in range(2)
        ]
        self.sides = [ax.plot([], [], color=th.side_color, lw=1.0)[0] for _ in range(4)]
        self.perps = [
            ax.plot([], [], color=th.construction_color, lw=0.7, ls="--")[0] for _ in range(4)
        ]
        self.circles = [
            ax.add_patch(
                CirclePatch((0, 0), 1, fill=False, ls="--", lw=1.2, edgecolor=th.circle_color(n))
            )
            for n in (1, 2, 3, 4)
        ]
        # a circle much larger than the view (near a bound of condition (1), |V_n| grows
        # like 1/cos(φ ± ξ)) is drawn as its arc through O instead: Agg dashes a whole
        # path before clipping it, seconds for a radius of 1e5 pixels
        self.arcs = [
            ax.plot([], [], ls="--", lw=1.2, color=th.circle_color(n), zorder=1)[0]
            for n in (1, 2, 3, 4)
        ]
        self.fill = ax.add_patch(
            Polygon(
                np.zeros((3, 2)),
                facecolor=th.envelope_fill,
                alpha=0.25,
                edgecolor="none",
                zorder=0.5,
            )
        )
        (self.envelope_line,) = ax.plot(
            [], [], color=th.envelope_color, lw=2.2, label=r"envelope $k_{grasp}(\theta)$, eq. (25)"
        )
        (self.points,) = ax.plot([], [], "o", ms=3.5, color=th.point_color)
        (self.contacts,) = ax.plot([], [], "o", ms=9, color=th.highlight_color)
        (self.direction,) = ax.plot(
            [],
            [],
            color=PALETTE["force"],
            lw=1.0,
            ls=":",
            label=r"direction $e(\theta)$ of $F_e$, eq. (26)",
        )
        (self.h_mark,) = ax.plot(
            [],
            [],
            "o",
            ms=6,
            mfc=PALETTE["markerfill"],
            mec=PALETTE["marker"],
            label=r"$H = k_{grasp}(\theta)\,e(\theta)$",
        )
        (self.worst_mark,) = ax.plot([], [], "*", ms=14, color=PALETTE["worst"], label="worst case")
        (self.best_mark,) = ax.plot([], [], "D", ms=8, color=PALETTE["best"], label="best case")
        prop = FontProperties(size=9)
        self.labels = {
            n: ax.add_artist(
                PathText(
                    n,
                    (0, 0),
                    ax.transData,
                    self.fig.dpi_scale_trans,
                    prop=prop,
                    offset=(4, 4),
                    zorder=3,
                )
            )
            for n in _LABELS
        }
        self.message = ax.text(
            0.5,
            0.5,
            "",
            transform=ax.transAxes,
            ha="center",
            va="center",
            fontsize=10,
            color=PALETTE["error"],
            visible=False,
            zorder=10,
            bbox=dict(boxstyle="round", fc=PALETTE["errorfill"], ec=PALETTE["error"]),
        )
        self._alphas = {
            a: a.get_alpha()
            for a in (
                *self.sides,
                *self.perps,
                *self.circles,
                *self.arcs,
                *self.cones,
                self.fill,
                self.envelope_line,
                self.points,
                self.worst_mark,
                self.best_mark,
                self.direction,
                self.h_mark,
            )
        }

    def _draw_order(self) -> dict[str, list[Any]]:
        """The moving artists by region (``main``, ``slider:NAME``, ``info``), each
        list in the order a full draw paints them: by zorder, ties in the axes'
        child order, as :meth:`matplotlib.axes.Axes.draw` does."""
        groups = {
            "main": {
                *self.axis_lines,
                *self.cones,
                *self.sides,
                *self.perps,
                *self.circles,
                *self.arcs,
                self.fill,
                self.envelope_line,
                self.points,
                self.contacts,
                self.direction,
                self.h_mark,
                self.worst_mark,
                self.best_mark,
                *self.labels.values(),
                self.message,
                *self.ax.spines.values(),
            }
        }
        axes = {"main": self.ax}
        for name, s in self.sliders.items():
            # ``_handle``: the knob, private (not in the stubs) but the slider's own artist
            groups[f"slider:{name}"] = {
                s.poly,
                s.vline,
                s._handle,  # type: ignore[attr-defined]
                s.valtext,
            }
            axes[f"slider:{name}"] = s.ax
        out = {
            g: sorted(
                (a for a in axes[g].get_children() if a in arts), key=lambda a: a.get_zorder()
            )
            for g, arts in groups.items()
        }
        out["info"] = [self.info]
        return out

    def _region(self, group: str) -> Bbox:
        """The pixels of a group's artists (display coordinates, after a draw)."""
        if group == "main":
            return self.ax.bbox.expanded(1.0, 1.0).padded(2)
        if group == "info":
            return TransformedBbox(self._info_box, self.fig.transFigure).frozen()
        b = self.sliders[group[7:]].ax.bbox
        return Bbox.from_extents(b.x0 - 12, b.y0 - 4, self.fig.bbox.x1, b.y1 + 4)

    def _show_scene(self, sc: Scene) -> None:
        p = self.params
        self.scene, self.error = sc, None
        self.message.set_visible(False)
        span = 100.0 * (1.0 + max(abs(p[k]) for k in GRASP_KEYS))
        for i in range(4):
            for line, (pt, d) in ((self.sides[i], sc.sides[i]), (self.perps[i], sc.perps[i])):
                line.set_data(
                    pt[0] + span * np.array([-d[0], d[0]]), pt[1] + span * np.array([-d[1], d[1]])
                )
            self.circles[i].set_center((float(sc.S[i]) / 2, float(sc.C[i]) / 2))
            self.circles[i].set_radius(float(math.hypot(sc.S[i], sc.C[i])) / 2)
            self._arc(i, float(sc.S[i]), float(sc.C[i]))
        reach = 0.6 * math.dist(sc.P1, sc.P2)
        for i, (a, b) in enumerate(((0, 2), (1, 3))):
            self.cones[i].set_xy(wedge((sc.P1, sc.P2)[i], sc.sides[a][1], sc.sides[b][1], reach))
        self.points.set_data(sc.points[:, 0], sc.points[:, 1])
        self.contacts.set_data([sc.P1[0], sc.P2[0]], [sc.P1[1], sc.P2[1]])
        for name, text in self.labels.items():
            text.set_position(sc.point(name))
        self.envelope_xy = sc.envelope
        self.envelope_line.set_data(sc.envelope[:, 0], sc.envelope[:, 1])
        self.fill.set_xy(sc.envelope)
        k, theta = sc.k, sc.theta
        iw, ib = int(np.argmax(k)), int(np.argmin(k))
        self.worst, self.best = (float(theta[iw]), float(k[iw])), (float(theta[ib]), float(k[ib]))
        self.worst_mark.set_data([sc.envelope[iw, 0]], [sc.envelope[iw, 1]])
        self.best_mark.set_data([sc.envelope[ib, 0]], [sc.envelope[ib, 1]])
        self._set_faded(False)

    def _arc(self, i: int, vx: float, vy: float) -> None:
        """Circle i as a patch, or as its arc near O when it is far larger than the view."""
        (x0, x1), (y0, y1) = self.ax.get_xlim(), self.ax.get_ylim()
        reach = 4 * math.hypot(x1 - x0, y1 - y0) + 4 * max(abs(x0), abs(x1), abs(y0), abs(y1))
        r = math.hypot(vx, vy) / 2
        big = r > reach
        self.circles[i].set_visible(not big)
        if not big:
            self.arcs[i].set_data([], [])
            return
        # points c + r (cos a, sin a) within ``reach`` of O (a0: the angle of O from c)
        a0, half = math.atan2(-vy, -vx), 2 * math.asin(min(1.0, reach / (2 * r)))
        a = a0 + np.linspace(-half, half, 721)
        self.arcs[i].set_data(vx / 2 + r * np.cos(a), vy / 2 + r * np.sin(a))

    def _show_theta(self) -> None:
        """Direction e(θ), the point H and the info text, for the current θ."""
        sc, p = self.scene, self.params
        assert sc is not None
        t = p["theta"]
        e = (math.sin(t), -math.cos(t))
        kt = sc.k_grasp(t)
        far = 1.15 * max(float(sc.k.max()), 0.6 * math.dist(sc.P1, sc.P2))
        self.direction.set_data([0.0, far * e[0]], [0.0, far * e[1]])
        self.h_mark.set_data([kt * e[0]], [kt * e[1]])
        d = p["x1"] + p["x2"]
        self.info.set_text(
            f"θ = {math.degrees(t):.1f}° (slider):\n"
            f"  k = {kt:.4g}, F_int/F_e = {kt / d:.4g}\n"
            f"worst case: θ = {math.degrees(self.worst[0]):.1f}°\n"
            f"  k = {self.worst[1]:.4g}, F_int/F_e = {self.worst[1] / d:.4g}\n"
            f"best case:  θ = {math.degrees(self.best[0]):.1f}°\n"
            f"  k = {self.best[1]:.4g}, F_int/F_e = {self.best[1] / d:.4g}"
        )

    def _show_error(self, text: str) -> None:
        self.error = text
        self.message.set_text("Not a valid grasp:\n" + textwrap.fill(text, 58))
        self.message.set_visible(True)
        self.info.set_text("(no diagram: see the message)")
        self._set_faded(True)

    def _set_faded(self, faded: bool) -> None:
        for a, alpha in self._alphas.items():
            a.set_alpha(0.15 * (alpha or 1.0) if faded else alpha)
