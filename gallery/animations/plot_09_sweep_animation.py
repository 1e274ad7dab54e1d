"""
The external force sweeping round (animated)
============================================

Fig. 3 in motion: :func:`~graspcompass.render.animate_sweep` turns the direction
:math:`\\theta` of the external force once round the grasp of Fig. 6.  For every
:math:`n` the foot :math:`H_n` of the perpendicular from :math:`V_n` runs on the circle on
:math:`OV_n` (Thales, eq. (31)), filled while :math:`k_n(\\theta) = \\overline{OH_n} > 0`; the
bold point traces the envelope :math:`k_\\mathrm{grasp}(\\theta)\\,e(\\theta)` (eq. (25)).
The panel on the right draws :math:`k_1, \\dots, k_4` and :math:`k_\\mathrm{grasp}` against
:math:`\\theta` with a cursor, gives :math:`F_\\mathrm{int}` per unit external force
(eq. (17)) and names the friction inequality (8)–(11) that binds: which contact is about
to slip (see also :doc:`../beyond/plot_12_which_contact_slips`).

The command line writes it at full size, or with one circle at a time (the Thales view of
Fig. 3, below)::

    graspcompass animate fig6 --kind sweep -o fig6-sweep.gif
    graspcompass animate fig6 --kind sweep --circle 1 --quality lecture -o fig6-thales.gif
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.render import animate_sweep

construction = gc.internal_force_diagram(gc.Grasp.preset("fig6"))
# small and light for the web page: one frame every 7.5°, 60 dpi
animation = animate_sweep(construction, frames=48, fps=8, dpi=60)

# %%
# What the caption says, every 45°
# --------------------------------
for frame in range(0, animation.frame_count, 6):
    print(animation.status_at(frame), end="\n\n")

# %%
# Two frames at full resolution
# -----------------------------
# :meth:`~graspcompass.render.SweepAnimation.render` draws any frame as an image; a second,
# sharper copy of the animation (it is only drawn for these two frames) gives θ = 0 and
# θ = 90°.
sharp = animate_sweep(construction, frames=4, dpi=100)
fig, axes = plt.subplots(2, 1, figsize=(9.6, 10), layout="constrained")
for frame, ax in zip((0, 1), axes):
    ax.imshow(sharp.render(frame))
    ax.set_axis_off()
plt.show()

# %%
# The animation
# -------------
# Registered with pyplot by ``plt.figure``; its ``FuncAnimation`` plays in a script and is
# embedded here.
plt.figure(animation.figure)
sweep_animation = animation.animation
plt.show()

# %%
# One circle at a time: the right angle at :math:`H_1` (Fig. 3)
# --------------------------------------------------------------
# With ``circle=1`` only the circle on :math:`OV_1` is drawn.  The foot :math:`H_1` of the
# perpendicular from :math:`V_1` on the line through :math:`O` along
# :math:`e(\theta) = (\sin\theta, -\cos\theta)` makes a right angle
# :math:`OH_1V_1` (marked), so :math:`H_1` runs on the circle on the diameter
# :math:`OV_1` (Thales), and :math:`k_1(\theta)` is the signed length :math:`OH_1`.
thales = animate_sweep(construction, frames=48, fps=8, dpi=60, circle=1)
print(thales.status_at(40))
plt.figure(thales.figure)
thales_animation = thales.animation
plt.show()
