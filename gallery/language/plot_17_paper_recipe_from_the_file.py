"""
The paper's recipe, replayed from its file
==========================================

The construction of §3.3 and §3.2 ships as a file of the construction language,
``recipes/paper.gc`` (``graspcompass recipe`` prints it): the frame and the contacts, the
sides of the friction cones, the feet :math:`P_{1x}, P_{2x}` and their midpoint
:math:`O_M`, then for each :math:`n` the points :math:`X_n`, :math:`Y_n`, the signed
lengths and :math:`V_n = (-\\overline{O_M X_n}, -\\overline{OY_n})`, the circles on the
diameters :math:`OV_n`, their second intersections and the outer envelope (eq. (25)).
:func:`~graspcompass.internal_force_diagram` replays this very file, and so does every
command given it: ``graspcompass draw paper.gc --preset table1c`` draws what
``graspcompass draw --preset table1c`` draws.
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.construction.language import paper_program, paper_text, replay
from graspcompass.render import figure_diagram

text = paper_text()
print("\n".join(line for line in text.splitlines() if line.startswith(("param", "X1 ", "V1 "))))

# %%
# Replayed on the grasp of Fig. 7(c)
# ----------------------------------
# :func:`~graspcompass.construction.language.replay` runs the file's steps with the exact
# kernel on a grasp's values: the protocol, names, captions and exact objects are those of
# :func:`~graspcompass.internal_force_diagram`.
grasp = gc.Grasp.preset("table1c")
program = paper_program()
c = replay(program, grasp)
print(
    len(program.steps),
    "steps in the file,",
    len(c),
    "in the protocol; left out:",
    [name for name, _ in c.skipped],
)
print(
    "internal_force_diagram gives this protocol (it replays the file):",
    c.steps == gc.internal_force_diagram(grasp).steps,
)
for n in (1, 2, 3, 4):
    print(f"V{n} = {c[f'V{n}']}")

# %%
# The file's claims
# -----------------
# The file also states the closed form (27)–(39) as claims about its own points;
# ``graspcompass check paper.gc`` proves them for every grasp satisfying condition (1).
print("\n".join(line for line in text.splitlines() if line.startswith("claim V")))

# %%
# The drawing
# -----------
fig = figure_diagram(c)
plt.show()
