"""Fig. 1 as an animation: the object turning under gravity, with the gripping force.

Private to :mod:`graspcompass.render.anim_physics`, which re-exports
:class:`OrientationAnimation` and :func:`animate_orientation` (their ``__module__``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import FancyArrowPatch, Rectangle
from matplotlib.transforms import Affine2D

from ._anim_turning import _Turning, theta_of_orientation
from .theme import DEFAULT_THEME, Theme

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

__all__ = ["OrientationAnimation", "animate_orientation"]


class OrientationAnimation(_Turning):
    """The object turning under gravity (Fig. 1); see :func:`animate_orientation`."""

    def __init__(
        self,
        construction: Grasp | Construction,
        weight: float = 1.0,
        frames: int = 120,
        fps: float = 20,
        theme: Theme = DEFAULT_THEME,
        figsize: tuple[float, float] = (9.6, 5.0),
        dpi: float = 80,
    ) -> None:
        super().__init__(construction, frames, fps, theme, figsize, dpi)
        g, th, ax, a, hl = self.grasp, theme, self.axes, self.artists, theme.highlight_color
        self.weight, self.alpha = float(weight), self.angle
        self.theta = theta_of_orientation(self.alpha)
        self.k_grasp = np.asarray(g.k_grasp(self.theta), dtype=float)
        self.force = np.asarray(g.internal_force(self.theta, self.weight), dtype=float)
        d, vmax = float(g.x1 + g.x2), max(math.hypot(*v) for v in self.V)
        self.force_max = vmax / d * self.weight  # max over θ of k_grasp is max|V_n| (§5)
        shape: tuple[Any, ...] = getattr(g, "shape", None) or ("",)
        size = (
            float(shape[1])
            if shape[0] == "circle"
            else math.hypot(float(shape[1]), float(shape[2])) / 2
            if shape[0] == "rectangle"
            else 0.0
        )
        R = 1.1 * max(vmax, size, *(math.hypot(*self.num[p]) for p in ("P1", "P2")))
        ax.set(xlim=(-R, R), ylim=(-R, R), xticks=[], yticks=[])
        self._rot = Affine2D()
        turning: list[Artist] = [x for lst in self.kept.values() for x in lst]
        r = 0.06 * d
        for p, phi, sgn in (
            (self.num["P1"], float(g.phi1), -1),
            (self.num["P2"], float(g.phi2), 1),
        ):
            inward = np.array([sgn * math.sin(phi), -math.cos(phi)])  # the normal n_i
            tip = np.asarray(p) - r * inward  # a fingertip pressing along the normal
            turning += ax.plot(
                *np.array([tip, tip - 5 * r * inward]).T,
                color="#8d8d8d",
                lw=6,
                solid_capstyle="round",
                zorder=3.9,
            )
            turning.append(
                ax.add_patch(CirclePatch(tuple(tip), r, fc="#8d8d8d", ec="black", lw=0.6, zorder=4))
            )
        for x, y, lab in ((0.35 * R, 0.0, "x"), (0.0, 0.35 * R, "y")):
            turning += ax.plot([0, x], [0, y], color=th.axis_color, lw=th.thin_width)
            turning.append(
                ax.text(
                    1.12 * x,
                    1.12 * y,
                    lab,
                    style="italic",
                    ha="center",
                    va="center",
                    fontsize=th.font_size * 0.9,
                )
            )
        for art in turning:
            art.set_transform(self._rot + ax.transData)
        a["gravity"] = ax.add_patch(
            FancyArrowPatch(
                (0, 0),
                (0, -0.3 * R),
                arrowstyle="-|>",
                mutation_scale=14,
                color="black",
                lw=1.8,
                zorder=7,
            )
        )
        ax.text(0.04 * R, -0.3 * R, "W", fontsize=th.font_size, va="top", zorder=7)
        a["radius"] = ax.plot([], [], color=hl, lw=2.4, zorder=6)[0]
        a["point"] = ax.plot([], [], "o", color=hl, mec="white", ms=2 * th.point_size, zorder=6.5)[
            0
        ]
        top = 1.15 * self.force_max if self.force_max > 0 else 1.0
        gax = self.figure.add_axes((0.58, 0.74, 0.38, 0.07))
        gax.set(xlim=(0, top), ylim=(0, 1), yticks=[])
        gax.tick_params(labelsize=th.font_size * 0.75)
        gax.axvline(self.force_max, color=th.envelope_color, ls="--", lw=1.2)
        gax.set_title(
            r"gripping force $F_{int}$ for the weight $W$, eq. (17)", fontsize=th.font_size * 0.9
        )
        a["gauge"] = gax.add_patch(Rectangle((0, 0.15), 0, 0.7, color=hl, zorder=3))
        fax = self.force_axes = self.figure.add_axes((0.58, 0.32, 0.38, 0.3))
        fine = np.linspace(0, 2 * np.pi, 721)
        fax.plot(
            np.degrees(fine),
            g.internal_force(theta_of_orientation(fine), self.weight),
            color=th.envelope_color,
            lw=1.6,
        )
        fax.axhline(
            self.force_max,
            color=th.envelope_color,
            ls="--",
            lw=1.0,
            label="max |V_n|/(x1 + x2)·W: any orientation (§5)",
        )
        fax.set(xlim=(0, 360), xticks=np.arange(0, 361, 90), ylim=(0, top))
        fax.tick_params(labelsize=th.font_size * 0.75)
        fax.set_xlabel(r"object turned by $\alpha$ [deg]", fontsize=th.font_size * 0.8)
        fax.set_ylabel(r"$F_{int}$", fontsize=th.font_size * 0.8)
        fax.legend(fontsize=th.font_size * 0.7, loc="upper right", frameon=False)
        a["cursor"] = fax.axvline(0.0, color=hl, lw=1.2)
        a["fpoint"] = fax.plot([], [], "o", color=hl, mec="white", ms=th.point_size * 1.8)[0]
        a["status"] = self._text(0.2)
        self._dynamic = turning + list(a.values())

    def status_at(self, frame: int) -> str:
        """α, θ = −α, k_grasp(θ) and F_int = k_grasp/(x1 + x2)·W (eq. (17))."""
        f = self.timeline.check(frame)
        return (
            f"object turned by α = {math.degrees(self.alpha[f]):5.1f}°\n"
            f"gravity in the object frame: θ = −α = {math.degrees(self.theta[f]):5.1f}°\n"
            f"k_grasp(θ) = {self.k_grasp[f]:.3f}\n"
            f"F_int = k_grasp/(x1 + x2)·W = {self.force[f]:.3f}   (W = {self.weight:g})"
        )

    def world_point(self, frame: int) -> tuple[float, float]:
        """Where the downward ray from O meets the turned envelope: (0, −k_grasp(θ))."""
        return (0.0, -float(self.k_grasp[self.timeline.check(frame)]))

    def _apply(self, frame: int) -> None:
        f, a = self.timeline.check(frame), self.artists
        self._rot.clear().rotate(float(self.alpha[f]))
        x, y = self.world_point(f)
        a["radius"].set_data([0.0, x], [0.0, y])
        a["point"].set_data([x], [y])
        a["gauge"].set_width(float(self.force[f]))
        deg = math.degrees(self.alpha[f])
        a["cursor"].set_xdata([deg, deg])
        a["fpoint"].set_data([deg], [self.force[f]])
        a["status"].set_text(self.status_at(f))


def animate_orientation(
    grasp_or_construction: Grasp | Construction,
    weight: float = 1.0,
    frames: int = 120,
    fps: float = 20,
    theme: Theme = DEFAULT_THEME,
    figsize: tuple[float, float] = (9.6, 5.0),
    dpi: float = 80,
) -> OrientationAnimation:
    """Animate the grasped object turning under gravity, as in Fig. 1.

    Gravity (the weight ``W``) stays downward while the object, its contacts
    (fingertips pressing along the normals) and the internal force diagram
    turn counter-clockwise by α = 2π·frame/frames.  In the object frame
    gravity points along e(θ) with θ = −α (module docstring), so the downward
    ray from O meets the turned envelope at the distance k_grasp(θ) (eq. (25));
    the gauge and the side plot show F_int = k_grasp(θ)/(x1 + x2)·W (eq. (17))
    and max|V_n|/(x1 + x2)·W, enough for every orientation (§5).

    Returns
    -------
    OrientationAnimation
        With ``.alpha``, ``.theta``, ``.k_grasp``, ``.force`` (F_int per frame),
        ``.force_max``, ``.world_point(frame)`` and the moving ``.artists``.
    """
    return OrientationAnimation(
        grasp_or_construction,
        weight=weight,
        frames=frames,
        fps=fps,
        theme=theme,
        figsize=figsize,
        dpi=dpi,
    )


# documented and pickled as graspcompass.render.anim_physics's (which re-exports them)
OrientationAnimation.__module__ = "graspcompass.render.anim_physics"
animate_orientation.__module__ = "graspcompass.render.anim_physics"
