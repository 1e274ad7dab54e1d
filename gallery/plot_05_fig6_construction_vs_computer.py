"""
Fig. 6 — the construction and the computer plot, overlaid
=========================================================

§4.1 of the paper validates the drawing method on a circular object grasped at
:math:`P_1 = (\\sqrt{3}/2, 1/2)`, :math:`P_2 = (-\\sqrt{3}/2, 1/2)` with
:math:`\\varphi_1 = \\varphi_2 = \\pi/3`, :math:`\\xi_1 = \\pi/4`, :math:`\\xi_2 = \\pi/3`:
Fig. 6(a) is drawn by the method, Fig. 6(b) is computed from eq. (25), and "the two
figures are identical".

Here (a) is the ruler-and-compass construction replayed exactly, (b) the computer plot of
:math:`k_\\mathrm{grasp}(\\theta)` evaluated from the closed form (:meth:`Grasp.k_grasp
<graspcompass.Grasp.k_grasp>`), independently of the construction; the third figure
overlays them.  The largest difference between the envelope read off the construction
and the computer plot, over a million directions, is printed below; at the break points
of the envelope the two are compared exactly.
"""

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import graspcompass as gc
from graspcompass.geometry import ORIGIN, decide_zero, distance
from graspcompass.render import DEFAULT_THEME, draw_construction, draw_k_polar, figure_diagram

grasp = gc.Grasp.preset("fig6")
construction = gc.internal_force_diagram(grasp)
envelope = construction["envelope"]

# %%
# The largest difference
# ----------------------
# ``envelope.k(θ)`` reads k_grasp off the drawn envelope (the winning circle's
# :math:`V_n \cdot e(\theta)` with the drawn :math:`V_n`); ``grasp.k_grasp(θ)`` is eq. (25)
# from the closed-form :math:`S_n, C_n`.  A million directions:
theta = np.linspace(0.0, 2 * np.pi, 1_000_001)
drawn = envelope.k(theta)
computed = grasp.k_grasp(theta)
difference = np.abs(drawn - computed)
print(
    f"largest |construction − computer plot| over {theta.size} directions: {difference.max():.3e}"
)
print(f"largest k_grasp: {computed.max():.6f}")

# %%
# The difference is nil, not just small: the construction draws the points V_n
# *exactly* (the same numbers as eqs. (28)-(39)), and the envelope picks, for every θ,
# the same circle as the maximum of eq. (25).
print(
    "drawn V_n == closed-form V_n:",
    all(construction[f"V{n}"] == grasp.V[n - 1] for n in (1, 2, 3, 4)),
)

# %%
# At the break points of the envelope the check is exact: the distance from O to the
# break point equals eq. (25) at its exact angle.
for arc in envelope.arcs:
    exact = grasp.k_grasp(arc.theta_start)
    same = decide_zero(exact - distance(ORIGIN, arc.start))
    print(
        f"θ = {arc.theta_start}:  k_grasp = {sp.radsimp(exact)} ≈ {float(exact):.6f},"
        f"  equal to |O B|: {same}"
    )

# %%
# (a) drawn, (b) computed
# -----------------------
fig, (ax_a, ax_b) = plt.subplots(1, 2, figsize=(11, 5.8), layout="constrained")
draw_construction(construction, ax=ax_a)
ax_a.set_title("(a) manual draw: the construction of §3.3")
draw_k_polar(
    grasp,
    ax=ax_b,
    components=True,
    theme=DEFAULT_THEME.with_(computer_color="black", computer_width=2.0),
)
ax_b.set_aspect("equal")
ax_b.set_xlim(ax_a.get_xlim())
ax_b.set_ylim(ax_a.get_ylim())
ax_b.axhline(0, color="0.3", lw=0.6)
ax_b.axvline(0, color="0.3", lw=0.6)
ax_b.legend(loc="upper left", fontsize=8)
ax_b.set_title("(b) computer plot of eq. (25)")
fig.suptitle("Fig. 6: minimum internal force for grasping a circular object")
plt.show()

# %%
# Overlaid
# --------
# :func:`~graspcompass.render.figure_diagram` draws the construction with the computer
# plot on top (the thin yellow curve inside the bold envelope).
plt.figure(figure_diagram(construction))
plt.show()
# sphinx_gallery_thumbnail_number = 2
