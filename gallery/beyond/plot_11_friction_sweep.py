"""
How the diagram changes as the friction coefficient sweeps
==========================================================

The rectangular grasp of Table I(a) (contacts :math:`(\\pm 2, 1)` on the vertical sides,
:math:`\\varphi_1 = \\varphi_2 = \\pi/2`) with the same friction coefficient :math:`\\mu` at
both contacts, from slippery to very rough.  With :math:`\\varphi = \\pi/2`,
:math:`\\tan(\\varphi \\pm \\xi) = \\mp 1/\\mu`, so eqs. (28)–(39) give

.. math::

    V_{1,2} = \\Big(\\mp\\big(2 + \\tfrac{1}{\\mu}\\big), -\\tfrac{2}{\\mu}\\Big), \\qquad
    V_{3,4} = \\Big(\\mp\\big(2 - \\tfrac{1}{\\mu}\\big), \\tfrac{2}{\\mu}\\Big).

- Less friction: the points :math:`V_n` run away like :math:`1/\\mu` and the whole diagram
  grows; the gripping force needed grows in every direction.
- At :math:`\\mu = y/x_1 = 1/2` the midpoint :math:`O_M = O` enters both friction cones:
  :math:`V_3` and :math:`V_4` cross the :math:`y`-axis and swap sides, from case (b) of
  Fig. 8 to case (a).
- Very rough contacts: :math:`V_{1,3} \\to (-2, 0)`, :math:`V_{2,4} \\to (2, 0)` and
  :math:`k_\\mathrm{grasp}(\\theta) \\to 2|\\sin\\theta|`: a force along the line of the
  contacts must always be balanced by squeezing, however rough the fingertips.
"""

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.animation import FuncAnimation
from matplotlib.cm import ScalarMappable
from matplotlib.colors import LogNorm

import graspcompass as gc
from graspcompass.render import draw_construction


def grasp(mu: str) -> gc.Grasp:
    """Table I(a) with μ1 = μ2 = mu (an exact decimal such as "0.7")."""
    return gc.Grasp(
        2,
        2,
        1,
        "pi/2",
        "pi/2",
        mu1=mu,
        mu2=mu,
        shape=("rectangle", 4, 8),
        title=f"Table I(a) geometry, μ1 = μ2 = {mu}",
    )


# %%
# The envelopes for a few μ
# -------------------------
mus = ["0.3", "0.4", "0.5", "0.7", "1", "1.5", "3", "10"]
norm = LogNorm(0.3, 10)
cmap = plt.get_cmap("viridis")
fig, ax = plt.subplots(figsize=(7, 7), layout="constrained")
for mu in mus:
    c = gc.internal_force_diagram(grasp(mu))
    xy = c["envelope"].polyline()
    ax.plot(xy[:, 0], xy[:, 1], color=cmap(norm(float(mu))), lw=2, label=f"μ = {mu}")
    v3, v4 = c["V3"].evalf(), c["V4"].evalf()
    ax.plot([v3[0], v4[0]], [v3[1], v4[1]], "o", color=cmap(norm(float(mu))), ms=4)
    print(
        f"μ = {mu:4}:  V3 = {c['V3']},  V4 = {c['V4']},  max k_grasp = max|V_n| = "
        f"{max(float(abs(complex(*c[f'V{n}'].evalf()))) for n in (1, 2, 3, 4)):.3f}"
    )
t = np.linspace(0, 2 * np.pi, 721)
limit = 2 * np.abs(np.sin(t))  # μ → ∞
ax.plot(
    limit * np.sin(t),
    -limit * np.cos(t),
    color="black",
    ls="--",
    lw=1,
    label=r"μ → ∞: $2|\sin\theta|$",
)
ax.axhline(0, color="0.4", lw=0.6)
ax.axvline(0, color="0.4", lw=0.6)
ax.set_aspect("equal")
ax.set(xlim=(-9, 9), ylim=(-9, 9), title="envelope k_grasp(θ) for μ1 = μ2 = μ (dots: V3, V4)")
ax.legend(loc="upper right", fontsize=8, ncol=2)
fig.colorbar(ScalarMappable(norm, cmap), ax=ax, label="μ", shrink=0.7)
plt.show()

# %%
# The largest and the smallest force against μ
# --------------------------------------------
# On the float path (Python floats select numpy evaluation), for 200 values of μ.
mu_axis = np.geomspace(0.2, 20, 200)
theta = np.linspace(0, 2 * np.pi, 3601)
largest, smallest = [], []
for m in mu_axis:
    k = gc.Grasp(2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, mu1=float(m), mu2=float(m)).k_grasp(theta)
    largest.append(k.max())
    smallest.append(k.min())
fig, ax = plt.subplots(figsize=(8, 3.8), layout="constrained")
ax.loglog(mu_axis, np.array(largest) / 4, label="worst orientation: max k_grasp / (x1 + x2)")
ax.loglog(mu_axis, np.array(smallest) / 4, label="best orientation: min k_grasp / (x1 + x2)")
ax.axvline(0.5, color="#e63946", ls=":", label="μ = 1/2: $O_M$ enters both cones")
ax.axhline(0.5, color="black", ls="--", lw=0.8, label="μ → ∞: 1/2")
ax.set(xlabel="friction coefficient μ", ylabel="$F_{int}$ / $F_e$")
ax.legend(fontsize=8)
ax.grid(alpha=0.3, which="both")
plt.show()

# %%
# Animated
# --------
# A plain matplotlib ``FuncAnimation`` redraws the whole construction for each μ
# (exact every time); sphinx-gallery embeds it.
frames = [f"{m:.2f}" for m in np.geomspace(0.3, 5, 16)]
fig, ax = plt.subplots(figsize=(5.2, 5.2), dpi=60, layout="constrained")


def show(i: int) -> list:
    ax.clear()
    draw_construction(
        gc.internal_force_diagram(grasp(frames[i])), ax=ax, labels=False, show_computer_plot=False
    )
    ax.set(xlim=(-8, 8), ylim=(-8, 8))
    ax.set_title(f"μ1 = μ2 = {frames[i]}")
    return []


friction_animation = FuncAnimation(fig, show, frames=len(frames), interval=400)
plt.show()
