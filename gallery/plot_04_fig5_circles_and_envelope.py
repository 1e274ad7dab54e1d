"""
Fig. 5 — the four circles and their outer envelope
==================================================

With :math:`V_1, \\dots, V_4` drawn (Fig. 4), the compass draws the four circles on the
diameters :math:`OV_n` (eqs. (31)–(32), Fig. 3).  In the direction :math:`e(\\theta)` of the
external force the distance from :math:`O` to circle :math:`n` is :math:`k_n(\\theta)`, so
the least internal force, eq. (25),

.. math::

    k_\\mathrm{grasp}(\\theta) = \\max\\{k_1(\\theta), k_2(\\theta), k_3(\\theta),
    k_4(\\theta), 0\\},

is the distance from :math:`O` to the *outermost* circle: "extract the outside of these
circles" (§3.3).  The arcs of the envelope meet where two circles cross a second time
(besides :math:`O`), points that the compass also gives; ``graspcompass`` names them
``B12`` … ``B34`` and keeps the envelope as exact arcs with exact break points.

Same generic grasp as in Fig. 4.  The paper says its Fig. 5 is an example of the case
where :math:`O_M` lies inside exactly one friction cone (Fig. 8(c)); so is this grasp.
"""

import matplotlib.pyplot as plt
import numpy as np

import graspcompass as gc
from graspcompass.render import draw_construction, figure_k_plot

grasp = gc.Grasp(
    "6/5",
    "4/5",
    "3/5",
    "5*pi/12",
    "pi/2",
    mu1="3/5",
    mu2="2/5",
    title="generic grasp: P1 = (6/5, 3/5), P2 = (−4/5, 3/5), φ1 = 75°, φ2 = 90°, "
    "μ1 = 0.6, μ2 = 0.4",
)
construction = gc.internal_force_diagram(grasp)
envelope = construction["envelope"]

# %%
# The envelope, exactly
# ---------------------
# Each arc: which circle is outermost, for which directions θ (exact), and where it
# starts.  An arc of "circle 0" would be a direction range where no internal force is
# needed at all (k_grasp = 0).
for arc in envelope.arcs:
    start, end = np.degrees(float(arc.theta_start)), np.degrees(float(arc.theta_end))
    print(
        f"circle {arc.n}:  θ from {arc.theta_start}  (≈ {start:6.1f}°)  to {end:6.1f}°,"
        f"  starting at {arc.start}"
    )

# %%
# The drawing
# -----------
fig, ax = plt.subplots(figsize=(7, 7), layout="constrained")
draw_construction(construction, ax=ax)
handles, labels = ax.get_legend_handles_labels()
ax.legend(handles, labels, loc="upper left", fontsize=8, framealpha=0.9)
ax.set_title("Fig. 5: the circles on $OV_n$ and their outer envelope $k_{grasp}$")
plt.show()

# %%
# The same four limits against θ
# ------------------------------
# :func:`~graspcompass.render.figure_k_plot` draws :math:`k_1, \dots, k_4` and their upper
# envelope :math:`k_\mathrm{grasp}` on a cartesian θ axis; each sinusoid there is one of
# the circles above.  ``plt.figure(fig)`` shows a library figure with pyplot.
plt.figure(figure_k_plot(grasp, title="k_n(θ) and k_grasp(θ), eqs. (18)-(21), (25)"))
plt.show()
