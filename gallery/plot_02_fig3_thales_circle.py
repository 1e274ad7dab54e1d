"""
Fig. 3 — the Thales circle of one k_n
=====================================

Each friction inequality (8)–(11) gives a lower limit :math:`k_n(\\theta)` of the internal
force, eqs. (18)–(21).  The paper's key observation (§3.2) is that each is an inner
product with a fixed point :math:`V_n = (S_n, C_n)`, eqs. (27)–(30):

.. math::

    k_n(\\theta) = S_n \\sin\\theta - C_n \\cos\\theta = V_n \\cdot e(\\theta).

So :math:`k_n(\\theta)` is the signed length :math:`\\overline{OH_n}` of the projection of
:math:`V_n` on the direction :math:`e(\\theta)`: drop the perpendicular from :math:`V_n` to
the line through :math:`O` along :math:`e(\\theta)`, its foot is :math:`H_n`, eq. (31).  The
angle :math:`O H_n V_n` is a right angle, so by Thales' theorem :math:`H_n` lies on the
circle with diameter :math:`O V_n` for every :math:`\\theta`: the polar graph of
:math:`k_n` *is* that circle.

Here :math:`n = 1` for the grasp of Fig. 6, with :math:`H_1` for a few directions.
"""

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import graspcompass as gc
from graspcompass.geometry import ORIGIN, foot, is_on, line_with_direction
from graspcompass.render import DEFAULT_THEME

grasp = gc.Grasp.preset("fig6")
construction = gc.internal_force_diagram(grasp)
V1 = construction["V1"]  # drawn by ruler and compass, §3.3
circle1 = construction["circle1"]  # the circle on the diameter O V1
print("V1 =", V1)
print("circle1 =", circle1)

# %%
# An exact check of Fig. 3
# ------------------------
# For θ = π/6 the foot of the perpendicular from V1 on the line along e(θ) is computed
# with the exact kernel; it equals k1(θ)·e(θ) and lies on the circle on O V1.
theta = sp.pi / 6
e = gc.Point(sp.sin(theta), -sp.cos(theta))
H1 = foot(V1, line_with_direction(ORIGIN, e))
k1 = grasp.k(theta)[0]
print("H1 =", H1)
print("k1(π/6) =", k1)
print("H1 == k1(π/6)·e(π/6):", H1 == e.scale(k1))
print("H1 on the circle on O V1:", is_on(H1, circle1))

# %%
# The drawing
# -----------
# Directions with :math:`k_1(\theta) > 0` put :math:`H_1` on the ray along
# :math:`e(\theta)`; where :math:`k_1(\theta) < 0` the foot falls behind :math:`O` (grey),
# and that limit does not bind: :math:`k_\mathrm{grasp}` takes the largest :math:`k_n`
# and 0, eq. (25).
th = DEFAULT_THEME
v = np.array(V1.evalf())
centre, radius = np.array(circle1.center.evalf()), float(circle1.radius)
theta_v = np.arctan2(v[0], -v[1])  # the direction of V1: there H1 = V1, k1 = |V1|

fig, ax = plt.subplots(figsize=(6.4, 6.4), layout="constrained")
ax.axhline(0, color=th.axis_color, lw=0.8)
ax.axvline(0, color=th.axis_color, lw=0.8)
ax.add_patch(
    plt.Circle(
        tuple(centre),
        radius,
        fill=False,
        ls="--",
        lw=1.4,
        color=th.circle_color(1),
        label=r"circle on $OV_1$: polar graph of $k_1$",
    )
)
degrees = [-110, -75, np.degrees(theta_v), 0, 30, 80]
for d in degrees:
    t = np.radians(d)
    e_t = np.array([np.sin(t), -np.cos(t)])
    k = float(grasp.k(t)[0])
    h = k * e_t
    positive = k > 0
    color = th.highlight_color if positive else "#9a9a9a"
    ax.plot(*np.array([-1.2 * e_t, 4.6 * e_t]).T, color=color, lw=0.7, ls=":")
    ax.annotate(
        "",
        xy=tuple(1.0 * e_t),
        xytext=(0, 0),
        arrowprops=dict(arrowstyle="-|>", color=color, lw=1.2),
    )
    ax.plot(*np.array([v, h]).T, color=color, lw=0.8, ls="--")
    ax.plot(*h, "o", color=color, ms=5, zorder=5)
    to_v = v - h
    if np.linalg.norm(to_v) > 0.3:  # the right angle O H_1 V_1 (Thales), a small square
        a, b = 0.16 * e_t * np.sign(k or 1.0), 0.16 * to_v / np.linalg.norm(to_v)
        assert abs(float(np.dot(a, b))) < 1e-9  # H_1 is the foot: e_t is normal to V_1 H_1
        ax.plot(*np.array([h - a, h - a + b, h + b]).T, color=color, lw=0.8)
    out = (h - centre) / np.linalg.norm(h - centre)  # label outside the circle
    ax.annotate(
        f"$\\theta = {d:.0f}°$\n$k_1 = {k:.2f}$",
        h,
        xytext=tuple(14 * out),
        textcoords="offset points",
        fontsize=8.5,
        color=color,
        ha="left" if out[0] > 0.3 else "right" if out[0] < -0.3 else "center",
        va="bottom" if out[1] > 0.3 else "top" if out[1] < -0.3 else "center",
        bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8),
    )
ax.plot(*v, "o", color="black", ms=6, zorder=6)
ax.annotate("$V_1 = H_1$", v, xytext=(8, 8), textcoords="offset points", fontsize=12)
ax.annotate("$O$", (0, 0), xytext=(4, 4), textcoords="offset points", fontsize=12)
ax.set_aspect("equal")
ax.set_xlim(-4.4, 2.2)
ax.set_ylim(-4.6, 2.0)
ax.legend(loc="upper left", fontsize=9)
ax.set_title("Fig. 3: $k_1(\\theta) = \\overline{OH_1}$, $H_1$ on the circle on $OV_1$")
plt.show()
