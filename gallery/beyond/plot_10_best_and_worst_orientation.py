"""
The orientation that needs the least and the most gripping force
================================================================

The paper's motivation (§1, Fig. 1): under gravity the gripping force depends on how the
grasped object is turned, and "the problem of finding an object orientation that requires
the maximum internal force cannot be solved analytically".  The diagram answers it by
ruler and compass, §5: if the internal force is greater than the largest :math:`|V_n|`,
the object is held in *any* orientation.

Gravity :math:`W` points down in the world.  Turn the object counter-clockwise by
:math:`\\alpha`: in the object's frame gravity then points along :math:`e(\\theta)` with
:math:`\\theta = -\\alpha` (:func:`~graspcompass.render.theta_of_orientation`), and the
gripping force needed is :math:`F_\\mathrm{int} = k_\\mathrm{grasp}(\\theta)\\,W/(x_1 + x_2)`
(eq. (17)).  Both extremes are exact points of the drawing:

- **worst** (most force): :math:`\\max_\\theta k_\\mathrm{grasp}(\\theta) = \\max_n |V_n|`,
  reached where :math:`e(\\theta)` points at the farthest :math:`V_n`, the far end of its
  circle's diameter;
- **best** (least force): the envelope is a union of circle arcs bulging outwards, so its
  point nearest to :math:`O` is one of the break points where two arcs meet
  (:math:`B_{nm}`), or :math:`O` itself if some directions need no force at all.
"""

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import graspcompass as gc
from graspcompass.geometry import ORIGIN, angle_of, distance
from graspcompass.render import animate_orientation, draw_construction, theta_of_orientation
from graspcompass.scene.palette import PALETTE


def extremes(construction):
    """Exact (θ, k) of the largest and of the smallest k_grasp, from the drawing."""
    V = [construction[f"V{n}"] for n in (1, 2, 3, 4)]
    n = max(range(4), key=lambda i: float(distance(ORIGIN, V[i])))
    worst = (sp.Mod(angle_of(V[n]), 2 * sp.pi), distance(ORIGIN, V[n]), f"V{n + 1}")
    env = construction["envelope"]
    arc = min(env.arcs, key=lambda a: float(distance(ORIGIN, a.start)))
    best = (
        sp.Mod(arc.theta_start, 2 * sp.pi),
        distance(ORIGIN, arc.start),
        "O" if arc.start == ORIGIN else "a break point",
    )
    return worst, best


# %%
# The four grasps of the paper
# ----------------------------
# Worst and best direction θ of the weight in the object's frame, the orientation
# α = −θ that puts it there, and the gripping force per unit weight (eq. (17)).
for name in gc.PRESETS:
    g = gc.Grasp.preset(name)
    (tw, kw, at), (tb, kb, bt) = extremes(gc.internal_force_diagram(g))
    d = float(g.x1 + g.x2)
    print(
        f"{name:8} worst: θ = {float(tw) * 180 / np.pi:6.1f}° (at {at}), "
        f"α = {float(-tw % (2 * sp.pi)) * 180 / np.pi:6.1f}°, F_int = {float(kw) / d:.3f}·W"
        f"   best: θ = {float(tb) * 180 / np.pi:6.1f}° ({bt}), "
        f"F_int = {float(kb) / d:.3f}·W"
    )

# %%
# Exactly, for the grasp of Fig. 6
# --------------------------------
grasp = gc.Grasp.preset("fig6")
construction = gc.internal_force_diagram(grasp)
(theta_w, k_w, at_w), (theta_b, k_b, at_b) = extremes(construction)
for word, t, kk in (("worst", theta_w, k_w), ("best ", theta_b, k_b)):
    kk = sp.sqrtdenest(kk)
    print(f"{word}: θ = {t},  k_grasp = {kk},  F_int/W = {sp.radsimp(kk / grasp.D)}")
# a numeric check against eq. (25) on a fine grid
theta = np.linspace(0, 2 * np.pi, 200_001)
k = grasp.k_grasp(theta)
print(
    f"grid: max k_grasp = {k.max():.6f} (exact {float(k_w):.6f}), "
    f"min k_grasp = {k.min():.6f} (exact {float(k_b):.6f})"
)

# %%
# In the diagram
# --------------
fig, ax = plt.subplots(figsize=(6.5, 6.5), layout="constrained")
draw_construction(construction, ax=ax, labels=False)
for t, kk, color, word, off in (
    (theta_w, k_w, PALETTE["worst"], "worst", (10, -12)),
    (theta_b, k_b, PALETTE["best"], "best", (40, 50)),
):
    t, kk = float(t), float(kk)
    e = np.array([np.sin(t), -np.cos(t)])
    ax.annotate(
        "",
        xy=tuple(kk * e),
        xytext=(0, 0),
        arrowprops=dict(arrowstyle="-|>", color=color, lw=2.5),
        zorder=8,
    )
    ax.plot(*(kk * e), "o", color=color, ms=8, zorder=9)
    ax.annotate(
        f"{word}: θ = {np.degrees(t):.1f}°\nk = {kk:.3f}",
        kk * e,
        xytext=off,
        textcoords="offset points",
        arrowprops=dict(arrowstyle="-", color=color),
        color=color,
        fontsize=10,
        fontweight="bold",
        bbox=dict(fc="white", ec="none", alpha=0.8),
    )
ax.set_title(
    "Fig. 6 grasp: the worst (magenta) and the best (cyan) direction of the weight", fontsize=10
)
plt.show()

# %%
# Against the object's orientation
# --------------------------------
# The gripping force for the weight W = 1 as the object turns (Fig. 1), with the level
# max|V_n|/(x1 + x2) that holds it in every orientation (§5).
alpha = np.linspace(0, 2 * np.pi, 2001)
force = grasp.internal_force(theta_of_orientation(alpha), 1.0)
fig, ax = plt.subplots(figsize=(8, 3.6), layout="constrained")
ax.plot(np.degrees(alpha), force, color="#0b1f4b", lw=2)
d = float(grasp.D)
ax.axhline(
    float(k_w) / d, color="#e63946", ls="--", lw=1, label="max |V_n| / (x1 + x2): any orientation"
)
for t, kk, color in ((theta_w, k_w, "#e63946"), (theta_b, k_b, "#2a9d8f")):
    a = np.degrees(float(theta_of_orientation(float(t))))
    ax.plot([a], [float(kk) / d], "o", color=color, ms=8)
ax.set(
    xlim=(0, 360),
    xticks=np.arange(0, 361, 45),
    ylim=(0, None),
    xlabel=r"object turned counter-clockwise by $\alpha$ [deg]",
    ylabel=r"$F_{int}$ for $W = 1$",
)
ax.legend(loc="upper right", fontsize=9)
ax.grid(alpha=0.3)
plt.show()

# %%
# The object held in its best and its worst orientation
# -----------------------------------------------------
# Frames of :func:`~graspcompass.render.animate_orientation` (the object turning under
# gravity, Fig. 1) at the turns nearest to the best and the worst orientation.
turning = animate_orientation(construction, frames=720, dpi=90)
fig, axes = plt.subplots(2, 1, figsize=(9.6, 10), layout="constrained")
for t, ax in zip((theta_b, theta_w), axes):
    a = float(theta_of_orientation(float(t)))
    frame = int(np.argmin(np.abs(np.angle(np.exp(1j * (turning.alpha - a))))))
    ax.imshow(turning.render(frame))
    ax.set_axis_off()
plt.show()
