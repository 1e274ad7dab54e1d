"""
Fig. 2 — a two-point grasp and its friction cones
=================================================

The object is held by two fingertips at :math:`P_1 = (x_1, y)` and :math:`P_2 = (-x_2, y)`.
The frame is the object's: the origin :math:`O` is its centre of mass, and the
:math:`y`-axis is perpendicular to the line through the contacts (§2.2.1).  At each contact
the inward normal makes the angle :math:`\\varphi_1` (clockwise) or :math:`\\varphi_2`
(counter-clockwise) with the negative :math:`y`-axis, and friction with coefficient
:math:`\\mu_i` allows any contact force inside the *friction cone* of half-angle
:math:`\\xi_i = \\arctan \\mu_i` around the normal (eq. (22)).

The grasp can hold the object when each cone contains the other contact, condition (1):

.. math::

    -\\frac{\\pi}{2} < \\varphi_i - \\xi_i < \\frac{\\pi}{2} < \\varphi_i + \\xi_i
    < \\frac{3\\pi}{2} \\qquad (i = 1, 2).

The external force :math:`F_e` (gravity, for instance) acts at :math:`O` in the direction
:math:`e(\\theta) = (\\sin\\theta, -\\cos\\theta)`, the angle :math:`\\theta` measured from the
negative :math:`y`-axis (eq. (26)).  This is the circular object of the paper's Fig. 6.
"""

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp
from matplotlib.patches import Arc, FancyArrowPatch

import graspcompass as gc
from graspcompass.render import DEFAULT_THEME, draw_construction

grasp = gc.Grasp.preset("fig6")
construction = gc.internal_force_diagram(grasp)

# %%
# Condition (1), checked exactly
# ------------------------------
# :class:`~graspcompass.Grasp` refuses parameters that violate condition (1), naming the
# inequality; here are its four angles for each contact, in multiples of π.
for i, (phi, xi) in enumerate(((grasp.phi1, grasp.xi1), (grasp.phi2, grasp.xi2)), 1):
    low, up = sp.nsimplify((phi - xi) / sp.pi), sp.nsimplify((phi + xi) / sp.pi)
    print(
        f"contact {i}: φ{i} − ξ{i} = {low}·π  (in (−1/2, 1/2)),   "
        f"φ{i} + ξ{i} = {up}·π  (in (1/2, 3/2))"
    )

# %%
# The drawing
# -----------
# :func:`~graspcompass.render.draw_construction` up to the step that marks :math:`P_2`
# draws the given data: the object, the two friction cones, the axes and the contacts.
# The normals, the angles and the external force are added from the grasp's parameters.
fig, ax = plt.subplots(figsize=(6.4, 6.4), layout="constrained")
draw_construction(construction, step=construction.step("P2").index, ax=ax)

p1 = np.array(grasp.P1.evalf())
p2 = np.array(grasp.P2.evalf())
phi1, phi2 = float(grasp.phi1), float(grasp.phi2)
xi1, xi2 = float(grasp.xi1), float(grasp.xi2)
n1 = np.array([-np.sin(phi1), -np.cos(phi1)])  # inward normal at P1, φ1 clockwise
n2 = np.array([np.sin(phi2), -np.cos(phi2)])  # inward normal at P2, φ2 counter-clockwise
ink = DEFAULT_THEME.axis_color
for p, n, name in ((p1, n1, "n_1"), (p2, n2, "n_2")):
    ax.add_patch(
        FancyArrowPatch(
            tuple(p),
            tuple(p + 0.55 * n),
            arrowstyle="-|>",
            mutation_scale=12,
            color=ink,
            lw=1.2,
            zorder=6,
        )
    )
    ax.annotate(f"${name}$", p + 0.6 * n, ha="center", va="center", fontsize=11)
    ax.plot(*np.array([p, p + np.array([0, -0.45])]).T, color=ink, lw=0.7, ls=":")

# the angles φ (from the negative y-axis to the normal) and ξ (normal to cone side)
deg1, deg2 = np.degrees([phi1, xi1]), np.degrees([phi2, xi2])
ax.add_patch(Arc(tuple(p1), 0.5, 0.5, theta1=-90 - deg1[0], theta2=-90, color=ink, lw=0.8))
ax.add_patch(Arc(tuple(p2), 0.5, 0.5, theta1=-90, theta2=-90 + deg2[0], color=ink, lw=0.8))
ax.annotate(
    r"$\varphi_1$",
    p1 + 0.33 * np.array([-np.sin(phi1 / 2), -np.cos(phi1 / 2)]),
    ha="center",
    va="center",
    fontsize=11,
)
ax.annotate(
    r"$\varphi_2$",
    p2 + 0.33 * np.array([np.sin(phi2 / 2), -np.cos(phi2 / 2)]),
    ha="center",
    va="center",
    fontsize=11,
)
for p, sgn, phi, xi, name in ((p1, -1, phi1, xi1, r"\xi_1"), (p2, 1, phi2, xi2, r"\xi_2")):
    a = phi + xi / 2  # between the normal and the upper side of the cone
    ax.add_patch(
        Arc(
            tuple(p),
            0.7,
            0.7,
            theta1=min(-90 + sgn * np.degrees(phi), -90 + sgn * np.degrees(phi + xi)),
            theta2=max(-90 + sgn * np.degrees(phi), -90 + sgn * np.degrees(phi + xi)),
            color=DEFAULT_THEME.side_color,
            lw=0.8,
        )
    )
    ax.annotate(
        f"${name}$",
        p + 0.45 * np.array([sgn * np.sin(a), -np.cos(a)]),
        ha="center",
        va="center",
        fontsize=11,
        color=DEFAULT_THEME.side_color,
    )

# the external force at O along e(θ), eq. (26)
theta = np.radians(35)
e = np.array([np.sin(theta), -np.cos(theta)])
ax.add_patch(
    FancyArrowPatch(
        (0, 0),
        tuple(0.8 * e),
        arrowstyle="-|>",
        mutation_scale=14,
        color=DEFAULT_THEME.highlight_color,
        lw=2,
        zorder=7,
    )
)
ax.annotate(
    r"$F_e\,e(\theta)$",
    0.9 * e,
    color=DEFAULT_THEME.highlight_color,
    fontsize=11,
    ha="left",
    va="top",
)
ax.add_patch(
    Arc((0, 0), 0.7, 0.7, theta1=-90, theta2=-90 + 35, color=DEFAULT_THEME.highlight_color, lw=0.8)
)
ax.annotate(
    r"$\theta$",
    0.42 * np.array([np.sin(theta / 2), -np.cos(theta / 2)]),
    color=DEFAULT_THEME.highlight_color,
    fontsize=11,
    ha="center",
    va="center",
)
ax.plot(*np.array([p1, p2]).T, color=ink, lw=0.8, ls="--")  # the segment P1 P2
ax.set_xlim(-1.6, 1.6)
ax.set_ylim(-1.4, 1.6)
ax.set_title("Fig. 2: the grasp of Fig. 6, each friction cone contains the other contact")
plt.show()
