"""
The construction, step by step (animated)
=========================================

The whole ruler-and-compass drawing of §3.3 for the grasp of Fig. 6, replayed by
:func:`~graspcompass.render.animate_construction`: the axes and the contacts, the
extended cone sides, the feet :math:`P_{1x}`, :math:`P_{2x}` and the midpoint :math:`O_M`,
then for each :math:`n` the point :math:`X_n`, the perpendicular that gives :math:`Y_n`, the
two signed lengths and :math:`V_n` (eqs. (28)–(39)), the four circles on :math:`OV_n`
(eq. (31)) and finally their outer envelope :math:`k_\\mathrm{grasp}` (eq. (25)).  The
caption names the instrument and the paper's reference of every step; the new element is
highlighted and the earlier ones are dimmed, except the ones the step uses.

The captions number the steps as ``graspcompass steps`` prints them, and a label shared by
coincident points names only the points already made.  The command line writes the same
animation at full size, or for a projector (1280 × 720 pixels, captions at 20 pt beside the
diagram, each on screen long enough to read)::

    graspcompass animate fig6 --kind construction -o fig6-construction.gif
    graspcompass animate fig6 --quality lecture -o fig6-lecture.mp4
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.render import animate_construction, draw_construction

construction = gc.internal_force_diagram(gc.Grasp.preset("fig6"))
# small and light for the web page: 2 frames per step, 60 dpi (480 × 540 pixels, text at
# least 14 px, each caption 2 s); its player stores each still once, so every frame embeds
# under matplotlib's ``animation.embed_limit`` (tests/test_gallery_animation.py)
animation = animate_construction(
    construction, fps=8, frames_per_step=2, pause_frames=2, hold_frames=8, dpi=60
)
print(f"{animation.frame_count} frames for {len(construction)} steps")

# %%
# Four moments of the drawing
# ---------------------------
# The state after the steps that make :math:`V_1`, :math:`V_4`, the last circle and the
# envelope, drawn by :func:`~graspcompass.render.draw_construction` with the newest
# element highlighted, and the animation's caption at the end of each of these steps.
moments = ["V1", "V4", "circle4", "envelope"]
fig, axes = plt.subplots(2, 2, figsize=(10, 10), layout="constrained")
for name, ax in zip(moments, axes.flat):
    step = construction.step(name)
    draw_construction(construction, step=step.index, ax=ax, highlight_last=True)
    # the protocol's own numbers, as ``graspcompass steps`` prints them: 0 to len - 1
    ax.set_title(f"after step {step.index} (of 0–{len(construction) - 1}): {name}", fontsize=11)
plt.show()

for name in moments:
    frame = animation.timeline.last_frame_of_step(construction.step(name).index)
    head, body = animation.caption_at(frame).split("\n", 1)
    print(f"frame {frame:3d}: {head} — {body.replace(chr(10), ' ')}")

# %%
# The animation
# -------------
# ``plt.figure(animation.figure)`` hands the animation's figure to pyplot and
# :attr:`~graspcompass.render.ConstructionAnimation.animation` is the matplotlib
# ``FuncAnimation`` that plays it (``plt.show()`` in a script; embedded here).
plt.figure(animation.figure)
construction_animation = animation.animation
plt.show()
