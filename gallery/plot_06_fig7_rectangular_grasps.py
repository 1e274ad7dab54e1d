"""
Fig. 7 (a)(b)(c) — rectangular grasps of Table I
================================================

§4.2 varies the shape of the diagram with a rectangular object held on its two vertical
sides (:math:`\\varphi_1 = \\varphi_2 = \\pi/2`), moving the contacts and changing the
friction (Table I):

=====  ===========  =========  =========  ============  ==========  =========
case   :math:`P_1`  φ1         μ1         :math:`P_2`   φ2          μ2
=====  ===========  =========  =========  ============  ==========  =========
(a)    (2, 1)       π/2        1.0        (−2, 1)       π/2         1.2
(b)    (2, 3)       π/2        1.0        (−2, 3)       π/2         1.2
(c)    (2, 2)       π/2        0.5        (−2, 2)       π/2         1.4
=====  ===========  =========  =========  ============  ==========  =========

These are the presets ``table1a``, ``table1b`` and ``table1c``
(``graspcompass draw --preset table1c``).  The paper notes: "The directions of vectors
:math:`V_3` and :math:`V_4` are switched in case (a) and case (b).  In case (c), both
:math:`V_3` and :math:`V_4` face to the right."  The printout below checks this on the
exact points.
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.geometry import decide_sign
from graspcompass.render import draw_construction

cases = {tag: gc.internal_force_diagram(gc.Grasp.preset(f"table1{tag}")) for tag in "abc"}

# %%
# V3 and V4, exactly
# ------------------
for tag, c in cases.items():
    v3, v4 = c["V3"], c["V4"]
    side = {1: "right (x > 0)", -1: "left (x < 0)", 0: "on the y-axis"}
    print(
        f"({tag})  V3 = {v3}: {side[decide_sign(v3.x)]:14}   V4 = {v4}: {side[decide_sign(v4.x)]}"
    )

# %%
# The three diagrams
# ------------------
# Each panel is the complete construction with the computer plot of eq. (25) on top.
fig, axes = plt.subplots(1, 3, figsize=(15, 6), layout="constrained")
for (tag, c), ax in zip(cases.items(), axes):
    draw_construction(c, ax=ax, show_computer_plot=True)
    ax.set_title(c.grasp.title.split(": ", 1)[-1], fontsize=10)
    ax.text(
        0.02, 0.98, f"({tag})", transform=ax.transAxes, fontsize=14, va="top", fontweight="bold"
    )
handles, labels = axes[0].get_legend_handles_labels()
fig.legend(handles, labels, loc="outside lower center", ncol=4, fontsize=9, frameon=False)
fig.suptitle("Fig. 7: several shapes of the internal force diagram, rectangular object grasps")
plt.show()
