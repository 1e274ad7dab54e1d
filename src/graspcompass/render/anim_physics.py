"""Animations of the finished diagram: the external force sweeping round, the object turning.

:func:`animate_sweep` turns the direction θ of the external force F_e at the
centre of mass O, e(θ) = (sin θ, −cos θ) (eq. (26)): the foot H_n of the
perpendicular from V_n to the line along e(θ) runs on the circle on the
diameter O V_n (Thales, Fig. 3, eq. (31)), the envelope point traces
k_grasp(θ)·e(θ) (eq. (25)), and a side panel shows k_1..k_4(θ) and k_grasp(θ)
against θ with a moving cursor and names the contact about to slip.

:func:`animate_orientation` is Fig. 1: gravity stays downward while the
object, its two contacts and the diagram turn by α; a gauge shows the
gripping force F_int = k_grasp(θ)/(x1 + x2)·W of eq. (17).

Direction of gravity in the object frame: the object turned counter-clockwise
by α carries its frame along, so a world vector v has the object coordinates
R(−α)v.  Gravity (0, −1) has the object coordinates (−sin α, −cos α) =
(sin θ, −cos θ) = e(θ) with **θ = −α** (mod 2π).
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import TYPE_CHECKING

import numpy as np
from matplotlib.artist import Artist
from matplotlib.patches import FancyArrowPatch

from ._anim_orientation import OrientationAnimation, animate_orientation
from ._anim_turning import _Turning, binding, theta_of_orientation
from .labels import place_labels
from .theme import DEFAULT_THEME, Theme
from .timeline import AnimationError, Segment, Timeline

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

__all__ = [
    "SLIP",
    "OrientationAnimation",
    "SweepAnimation",
    "animate_orientation",
    "animate_sweep",
    "binding",
    "theta_of_orientation",
]

#: What the largest k_n means (§2.2.4): which friction inequality (8)-(11) becomes an
#: equality, i.e. which contact's force reaches which side of its friction cone.
SLIP = {
    0: "k_grasp = 0: no internal force is needed,\nevery k_n(θ) ≤ 0 (25)",
    **{
        n: f"k_{n} binds: contact {i} is about to slip, its force on\nthe {side} side of its "
        f"friction cone: μ{i}N{i} {sign} F{i} = 0 ({eq})"
        for n, i, side, sign, eq in (
            (1, 1, "upper", "−", 8),
            (2, 2, "upper", "−", 9),
            (3, 1, "lower", "+", 10),
            (4, 2, "lower", "+", 11),
        )
    },
}


class SweepAnimation(_Turning):
    """The external force sweeping round (Fig. 3); see :func:`animate_sweep`."""

    def __init__(
        self,
        construction: Grasp | Construction,
        frames: int = 120,
        fps: float = 20,
        theme: Theme = DEFAULT_THEME,
        figsize: tuple[float, float] = (9.6, 5.0),
        dpi: float = 80,
        samples: int = 720,
        circle: int | None = None,
    ) -> None:
        if circle is not None and circle not in (1, 2, 3, 4):
            raise AnimationError(f"circle must be 1, 2, 3 or 4 (or None), got {circle!r}")
        self.circle = circle
        super().__init__(construction, frames, fps, theme, figsize, dpi)
        g, th, ax, a, hl = self.grasp, theme, self.axes, self.artists, theme.highlight_color
        env = self.construction["envelope"]
        self._tt = np.linspace(0.0, 2 * np.pi, samples + 1)
        self._rr, self._env_k = env.k(self._tt), env.k(self.theta)
        self.kept["envelope"][0].set_alpha(0.35 if circle is None else 0.15)
        shown = (1, 2, 3, 4) if circle is None else (circle,)
        if circle is not None:  # one circle: the others and their V_n go
            for i in (1, 2, 3, 4):
                if i != circle:
                    for name in (f"circle{i}", f"V{i}"):
                        for art in self.kept.pop(name, []):
                            art.remove()
            self._rr = np.asarray(g.k(self._tt), dtype=float)[circle - 1]
        self._len = 0.15 * (ax.get_xlim()[1] - ax.get_xlim()[0])
        circles = []
        for v in self.V:  # the circle on O V_n, to keep the labels off it
            t = np.linspace(0, 2 * np.pi, 90)
            circles.append(
                np.column_stack(
                    [
                        v[0] / 2 + math.hypot(*v) / 2 * np.cos(t),
                        v[1] / 2 + math.hypot(*v) / 2 * np.sin(t),
                    ]
                )
            )
        pts = [(v, f"$V_{i}$") for i, v in enumerate(self.V, 1) if i in shown]
        place_labels(
            ax,
            [*pts, (self.num["P1"], "$P_1$"), (self.num["P2"], "$P_2$"), ((0.0, 0.0), "$O$")],
            circles,
            font_size=th.font_size * 0.9,
            marker_size=th.point_size,
            color=th.label_color,
            zorder=6,
            bbox=dict(boxstyle="round,pad=0.08", fc="white", ec="none", alpha=0.65),
        )
        a["ray"] = ax.plot([], [], color=th.axis_color, lw=th.thin_width, ls=":", zorder=4.6)[0]
        a["trace"] = ax.plot([], [], color=hl, lw=th.envelope_width * 0.8, zorder=4.7)[0]
        for i in (1, 2, 3, 4):
            col = th.circle_color(i)
            a[f"VH{i}"] = ax.plot(
                [], [], color=col, lw=th.thin_width, ls="--", zorder=4.8, visible=i in shown
            )[0]
            a[f"H{i}"] = ax.plot(
                [], [], "o", color=col, ms=th.point_size * 1.2, zorder=5.5, visible=i in shown
            )[0]
        if circle is not None:  # Fig. 3: the right angle at H_n (Thales), H_n named
            a["right"] = ax.plot([], [], color=hl, lw=th.line_width * 1.2, zorder=5.4)[0]
            a["H_label"] = ax.text(
                0,
                0,
                f"$H_{circle}$",
                fontsize=th.font_size,
                zorder=6,
                color=th.label_color,
                ha="center",
                va="center",
            )
        a["radius"] = ax.plot([], [], color=hl, lw=2.2, zorder=4.9)[0]
        a["point"] = ax.plot([], [], "o", color=hl, mec="white", ms=2 * th.point_size, zorder=6.5)[
            0
        ]
        a["force"] = ax.add_patch(
            FancyArrowPatch(
                (0, 0),
                (0, -1),
                arrowstyle="-|>",
                lw=1.8,
                mutation_scale=14,
                color="black",
                zorder=7,
            )
        )
        a["force_label"] = ax.text(
            0, 0, "$F_e$", fontsize=th.font_size, zorder=7, ha="center", va="center"
        )
        kax = self.k_axes = self.figure.add_axes(
            (0.58, 0.4, 0.39, 0.48) if circle is None else (0.58, 0.56, 0.39, 0.32)
        )
        deg = np.degrees(self._tt)
        for i, k in enumerate(g.k(self._tt), 1):
            one = circle is None or i == circle
            kax.plot(
                deg,
                k,
                color=th.circle_color(i),
                ls=th.circle_style(i),
                label=f"$k_{i}$",
                lw=th.line_width * (1 if circle is None else 2.0 if one else 0.6),
                alpha=1.0 if one else 0.35,
            )
            a[f"k{i}"] = kax.plot(
                [], [], "o", color=th.circle_color(i), ms=th.point_size, zorder=5, visible=one
            )[0]
        kax.plot(
            deg, g.k_grasp(self._tt), color=th.envelope_color, lw=2.4, label=r"$k_{grasp}$ (25)"
        )
        kax.axhline(0.0, color=th.axis_color, lw=th.thin_width)
        kax.set(xlim=(0, 360), xticks=np.arange(0, 361, 90))
        kax.tick_params(labelsize=th.font_size * 0.75)
        kax.set_xlabel(
            r"direction of the external force $\theta$ [deg]", fontsize=th.font_size * 0.8
        )
        kax.legend(
            fontsize=th.font_size * 0.85,
            ncol=5,
            loc="lower center",
            bbox_to_anchor=(0.5, 1.0),
            frameon=False,
            handlelength=1.5,
        )
        a["cursor"] = kax.axvline(0.0, color=hl, lw=1.2, zorder=4)
        a["kpoint"] = kax.plot(
            [], [], "o", color=hl, mec="white", ms=th.point_size * 1.8, zorder=6
        )[0]
        if circle is not None:
            self.text_axes = self.figure.add_axes((0.56, 0.0, 0.44, 0.46))
            self.text_axes.set_axis_off()
        a["status"] = self._text(0.25 if circle is None else 0.43)
        a["slip"] = self._text(0.13, color=hl)
        self._dynamic = list(a.values())

    def _timeline(self) -> Timeline:
        """One segment per run of frames with the same binding k_n (an arc of the envelope)."""
        n = len(self.angle)
        self.theta = self.angle
        self.k = np.asarray(self.grasp.k(self.theta), dtype=float)
        self.k_grasp = np.asarray(self.grasp.k_grasp(self.theta), dtype=float)
        self.binding = binding(self.k)
        cuts = [0, *(np.flatnonzero(np.diff(self.binding)) + 1), n]
        return Timeline(
            tuple(Segment(int(self.binding[a]), int(b - a)) for a, b in pairwise(cuts)), "linear"
        )

    def _movers(self, segment: int) -> list[Artist]:
        return [a for a in self._dynamic if a is not self.artists["slip"]]

    def status_at(self, frame: int) -> str:
        """θ, k_grasp(θ), F_int per unit F_e (eq. (17)) and the binding inequality (8)-(11);
        with one circle n, also k_n(θ) = O H_n and the right angle at H_n (Fig. 3)."""
        f = self.timeline.check(frame)
        d = float(self.grasp.x1 + self.grasp.x2)
        head = (
            f"θ = {math.degrees(self.theta[f]):5.1f}°    k_grasp(θ) = {self.k_grasp[f]:.3f}\n"
            f"F_int = k_grasp/(x1 + x2)·F_e = {self.k_grasp[f] / d:.3f}·F_e (17)\n"
        )
        if self.circle is not None:
            n = self.circle
            head += (
                f"k_{n}(θ) = O H_{n} = {self.k[n - 1, f]:.3f}: H_{n} is the foot of the\n"
                f"perpendicular from V_{n}, ∠O H_{n} V_{n} = 90°, so H_{n} runs on\n"
                f"the circle on the diameter O V_{n} (Thales, Fig. 3)\n"
            )
        return head + SLIP[int(self.binding[f])]

    def right_angle_at(self, frame: int) -> np.ndarray | None:
        """The mark of the right angle O H_n V_n (one circle n): three points, its corner
        H_n in the middle; None where H_n is too close to O or V_n to show it."""
        if self.circle is None:
            return None
        f = self.timeline.check(frame)
        t, n = float(self.theta[f]), self.circle
        e = np.array([math.sin(t), -math.cos(t)])
        h, v = float(self.k[n - 1, f]) * e, np.asarray(self.V[n - 1], dtype=float)
        size = 0.3 * self._len
        if abs(self.k[n - 1, f]) < 1.5 * size or np.linalg.norm(v - h) < 1.5 * size:
            return None
        u1 = -np.sign(self.k[n - 1, f]) * e  # from H_n towards O
        u2 = (v - h) / np.linalg.norm(v - h)  # from H_n towards V_n
        return np.array([h + size * u1, h + size * (u1 + u2), h + size * u2])

    def _apply(self, frame: int) -> None:
        f = self.timeline.check(frame)
        a, t, th = self.artists, float(self.theta[f]), self.theme
        e = np.array([math.sin(t), -math.cos(t)])
        a["ray"].set_data(
            [-10 * self._len * e[0], 10 * self._len * e[0]],
            [-10 * self._len * e[1], 10 * self._len * e[1]],
        )
        a["force"].set_positions((0.0, 0.0), tuple(self._len * e))
        a["force_label"].set_position(tuple(1.3 * self._len * e))
        r = float(self._env_k[f])
        m = int(np.searchsorted(self._tt, t, side="right"))
        end = r if self.circle is None else float(self.k[self.circle - 1, f])
        rr, tt = np.append(self._rr[:m], end), np.append(self._tt[:m], t)
        a["trace"].set_data(rr * np.sin(tt), -rr * np.cos(tt))  # H_n's path with one circle
        a["radius"].set_data([0.0, end * e[0]], [0.0, end * e[1]])  # O H_n with one circle
        a["point"].set_data([end * e[0]], [end * e[1]])
        win = int(self.binding[f])
        for i, v in enumerate(self.V, 1):
            k = float(self.k[i - 1, f])
            h = k * e  # the foot H_n of the perpendicular from V_n: O H_n = k_n (Fig. 3)
            a[f"H{i}"].set(data=([h[0]], [h[1]]), mfc=th.circle_color(i) if k > 0 else "white")
            a[f"VH{i}"].set(
                data=([v[0], h[0]], [v[1], h[1]]),
                ls="-" if i == win else "--",
                lw=1.6 if i == win else th.thin_width,
            )
            a[f"k{i}"].set_data([math.degrees(t)], [k])
        if self.circle is not None:
            h = float(self.k[self.circle - 1, f]) * e
            mark = self.right_angle_at(f)
            a["right"].set(data=(mark[:, 0], mark[:, 1]) if mark is not None else ([], []))
            side = np.array([e[1], -e[0]])  # beside the line along e(θ), away from V_n
            if np.dot(side, np.asarray(self.V[self.circle - 1]) - h) > 0:
                side = -side
            a["H_label"].set_position(tuple(h + 0.35 * self._len * side))
        a["cursor"].set_xdata([math.degrees(t)] * 2)
        a["kpoint"].set_data([math.degrees(t)], [self.k_grasp[f]])
        lines = self.status_at(f).split("\n")
        a["status"].set_text("\n".join(lines[:-2]))
        a["slip"].set_text("\n".join(lines[-2:]))


def animate_sweep(
    grasp_or_construction: Grasp | Construction,
    frames: int = 120,
    fps: float = 20,
    theme: Theme = DEFAULT_THEME,
    figsize: tuple[float, float] = (9.6, 5.0),
    dpi: float = 80,
    circle: int | None = None,
) -> SweepAnimation:
    """Animate the external force direction θ going once round (Fig. 3, eqs. (25)-(32)).

    The force arrow at the centre of mass O turns along e(θ) (26); the foot
    H_n of the perpendicular from V_n to the line along e(θ) moves on the
    circle on the diameter O V_n (Thales, eq. (31)), filled where
    k_n(θ) = O H_n > 0; the envelope point k_grasp(θ)·e(θ) traces the outer
    envelope (25); the side panel draws k_1..k_4 and k_grasp against θ with a
    cursor and names the binding friction inequality (8)-(11) (:data:`SLIP`).
    Frame ``f`` shows θ = 2π·f/frames; the timeline has one segment per arc.

    With ``circle=n`` (1-4) only the circle on O V_n is drawn, as in Fig. 3:
    the line through O along e(θ), the perpendicular from V_n, its foot H_n
    with the right angle O H_n V_n marked (``.right_angle_at(frame)``), and
    the path of H_n, which is that circle (Thales); the side panel stresses k_n.

    Returns
    -------
    SweepAnimation
        With ``.theta``, ``.k`` (4, frames), ``.k_grasp``, ``.binding``,
        ``.status_at(frame)`` (the text panel) and the moving ``.artists``
        (``"trace"``: the traced envelope, or H_n's path with one circle;
        ``"status"``, ``"slip"``: the texts of the panel).
    """
    return SweepAnimation(
        grasp_or_construction,
        frames=frames,
        fps=fps,
        theme=theme,
        figsize=figsize,
        dpi=dpi,
        circle=circle,
    )
