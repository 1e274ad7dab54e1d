"""
Where to grip a part: contact pairs ranked by the worst-case squeeze
====================================================================

The paper sizes the squeeze for *given* contacts; turned round, its closed form ranks
contacts.  For a pair of contacts on an outline, in the pair's own frame (the origin at
the centre of mass, the :math:`x`-axis along the contacts, Fig. 2), the squeeze that holds
the part in every orientation is

.. math::

    F = m g \\, \\frac{\\max_n |V_n|}{x_1 + x_2} \\quad \\text{per jaw}

(eq. (17) with :math:`k_\\mathrm{grasp}(\\theta) \\le \\max_n |V_n|`, equality in the worst
direction; :math:`V_n` of eqs. (28)–(39)), and pairs that violate condition (1), a
friction cone missing the other contact, cannot be held by squeezing at all.

:func:`graspcompass.planning.plan_contacts` samples contacts along the edges of the
bracket of the docs (no vertex: the normal is undefined there), forms every pair and
evaluates them all at once; ``graspcompass plan --shape bracket.svg`` does the same from
the command line.  Then, for the edge pairs of the best sampled pairs, it finds the best
contacts anywhere along the two edges, with a proof, and it can rank the pairs for the
orientations the part will actually see instead of every orientation.
"""

import math
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from graspcompass.outlines import read_outline
from graspcompass.planning import plan_contacts
from graspcompass.render.planning import draw_plan_heatmap, draw_plan_outline

BRACKET_SVG = """<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="80mm"
  viewBox="0 0 120 80"><path d="M 10 10 L 90 10 A 20 20 0 0 1 110 30 L 110 70 L 70 70
  L 70 55 L 50 55 L 50 70 L 10 70 Z"/></svg>"""  # docs/_static/outlines/bracket.svg
path = Path(tempfile.mkdtemp()) / "bracket.svg"
path.write_text(BRACKET_SVG)
outline = read_outline(path)  # metres, y up

plan = plan_contacts(outline, mu=0.5, mass=0.2, samples=120)
print(
    f"{len(plan.i)} pairs of {len(plan.points)} contacts, "
    f"{int(plan.force_closure.sum())} force-closure with μ = 0.5"
)
for p in plan.top(5):
    a, b = (f"({x * 1e3:.1f}, {y * 1e3:.1f})" for x, y in p.contacts)
    print(f"#{p.rank}: {a} – {b} mm: {p.squeeze:.3f} N per jaw ({p.squeeze_per_kg:.2f} N/kg)")

# %%
# The best pairs and their friction cones
# ---------------------------------------
# The best pairs grip the two long vertical sides at about the centre of mass's
# height: :math:`y \approx 0` and :math:`x_1 \approx x_2`, where all four :math:`|V_n|`
# are about :math:`x_1\sqrt{1 + 1/\mu^2}`, the least possible (a rectangle's centred pair
# gives exactly :math:`m g \sqrt{1 + 1/\mu^2}/2`).
fig, ax = plt.subplots(figsize=(7, 4.6), layout="constrained")
draw_plan_outline(ax, plan, top=5)
plt.show()

# %%
# Every pair at once
# ------------------
# The squeeze over the pairs, contacts numbered counter-clockwise along the outline; the
# blank cells are pairs that are not force-closure (for μ = 0.5 a cone's half angle is
# 26.6°, so most pairs of non-parallel edges are out).  The circled cell is the best pair.
fig, ax = plt.subplots(figsize=(6, 5), layout="constrained")
im = draw_plan_heatmap(ax, plan)
fig.colorbar(im, ax=ax, label="squeeze, N per jaw (0.2 kg)")
plt.show()

# %%
# Better than the samples, with a proof
# -------------------------------------
# Along two straight edges, with contacts :math:`a(s)` and :math:`b(t)`, the squeeze is a
# closed form in :math:`(s, t)`: in the world frame
# :math:`V_n = -(\pm d/2 + \kappa_n J r)`, with :math:`d = a - b`,
# :math:`\kappa_n = (c_n \cdot d)/(d \times c_n)` for the cone side :math:`c_n`, and
# :math:`r` the other contact seen from the centre of mass.  Condition (1) is the sign of
# the four denominators :math:`d \times c_n`.  ``plan.exact`` holds the least squeeze over
# *every* force-closure pair of points of each of the best edge pairs.  A branch and bound
# over :math:`(s, t)` finds it: interval arithmetic, rounded outwards, bounds the squeeze
# from below on each box, and the search drops every box that cannot beat the best pair
# found.  ``lower_bound`` is proved, and ``squeeze`` is within the tolerance of it.
for p in plan.exact:
    a, b = (f"({x * 1e3:.2f}, {y * 1e3:.2f})" for x, y in p.contacts)
    print(
        f"edges {p.edges}: {a} – {b} mm, {p.squeeze:.5f} N per jaw (proved >= "
        f"{p.lower_bound:.5f}); best sample on these edges {p.sampled_squeeze:.5f} N: "
        f"{100 * p.improvement:.2f}% less"
    )

# %%
# The orientations the part will see
# ----------------------------------
# Held with gravity along :math:`-y` of the drawing, the part tilting by at most ±20°,
# the worst case is over that arc of load directions only (as ``graspcompass size
# --gravity 0,-1 --tilt 20deg``), and other pairs win: gripping the top edge and the floor
# of the notch needs about 40 % less than the best pair for every orientation.
tilted = plan_contacts(
    outline, mu=0.5, mass=0.2, samples=120, gravity=(0, -1), tilt=math.radians(20)
)
print(tilted.orientations())
for p in tilted.top(3):
    a, b = (f"({x * 1e3:.1f}, {y * 1e3:.1f})" for x, y in p.contacts)
    print(f"#{p.rank}: {a} – {b} mm: {p.squeeze:.3f} N per jaw")

# %%
# The proof under the tilt range: ``plan.exact`` again, over the same orientations.  Here
# the least squeeze is approached on the boundary of condition (1): as one contact reaches
# the edge of its friction cone the squeeze stays finite (under every orientation it would
# grow without bound), so the optimum is an infimum that no force-closure pair attains.
# ``on_boundary`` says so, ``cone_margin`` is how far inside the pair printed is (radians),
# and ``claim()`` states what is proved.  Such a pair has no margin for error in μ: back
# off from it.
for p in tilted.exact:
    a, b = (f"({x * 1e3:.2f}, {y * 1e3:.2f})" for x, y in p.contacts)
    print(
        f"edges {p.edges}: {a} – {b} mm, {p.squeeze:.5f} N (proved >= {p.lower_bound:.5f}"
        f"{', on the boundary of (1)' if p.on_boundary else ''}); "
        f"{100 * p.improvement:.2f}% less than the best sample"
    )
print(tilted.exact[0].claim())
fig, ax = plt.subplots(figsize=(7, 4.6), layout="constrained")
draw_plan_outline(ax, tilted, top=3)
plt.show()
