"""
Exercise 2 — construct V1 (right on every example of the paper, and still wrong)
================================================================================

:math:`S_1 = -\\overline{O_M X_1}` is measured from :math:`O_M`, the midpoint of the feet
:math:`P_{1x}, P_{2x}` (§3.3, eq. (28)).  A student measures from the origin :math:`O`
instead.  The paper's four grasps (Fig. 6, Table I) all have :math:`x_1 = x_2`, where
:math:`O_M = O`: the attempt gives the paper's :math:`V_1` on every one of them.  The
check proves or refutes for *every* grasp satisfying condition (1), and refutes it.
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.construction.language import parse, replay
from graspcompass.proof.program_check import check_program
from graspcompass.render.grading import figure_counterexample

ATTEMPT = """\
param x1 > 0
param x2 > 0
param y >= 0
param phi1 angle
param phi2 angle
param mu1 friction
param mu2 friction
hypothesis condition1
O = point (0, 0)
x-axis = line_with_direction O (1, 0)
y-axis = line_with_direction O (0, 1)
P1 = point (x1, y)
P2 = point (-x2, y)
side1 = line_with_direction P1 (-(sin(phi1) + cos(phi1)*mu1), -(cos(phi1) - sin(phi1)*mu1))
P2x = foot P2 x-axis
X1 = meet side1 x-axis
perp1 = perpendicular side1 P2x
Y1 = meet perp1 y-axis
OX1 = signed_length O X1 x-axis
OY1 = signed_length O Y1 y-axis
V1 = point_from_lengths OX1 OY1 (-1, -1)
"""
program = parse(ATTEMPT, "v1.gc")

# %%
# Right on the paper's examples
# -----------------------------
# Replayed on each preset (``graspcompass steps v1.gc --preset NAME``), the attempt's
# :math:`V_1` is the paper's.
for name in gc.PRESETS:
    grasp = gc.Grasp.preset(name)
    mine, paper = replay(program, grasp)["V1"], gc.internal_force_diagram(grasp)["V1"]
    print(f"{name:8} V1 = {mine}  the paper's: {mine == paper}")

# %%
# Refuted in general
# ------------------
report = check_program(program, against="paper")
for row in report.targets:
    print(f"{row.name:4} {row.status.value}")
row = next(r for r in report.targets if r.status.value == "REFUTED")
cx = row.counterexample
print(f"{row.name} is refuted at x1 = {cx['x1']}, x2 = {cx['x2']} (x1 ≠ x2):", cx)

# %%
# The counterexample picture
# --------------------------
# The file's construction (left) and the paper's (right) at that grasp: with
# :math:`x_1 \\ne x_2` the midpoint :math:`O_M` is not :math:`O`, and :math:`V_1` moves by
# :math:`O_M`'s abscissa :math:`(x_1 - x_2)/2`.
fig = figure_counterexample(program, row.name, cx)
plt.show()
