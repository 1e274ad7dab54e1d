"""
Exercise 1 — construct V3 (a wrong perpendicular)
=================================================

§3.3 builds :math:`V_3` from the lower side of the friction cone at :math:`P_1`
(Fig. 4(c)): extend the side to the x-axis (:math:`X_3`), draw the perpendicular to the
side through :math:`P_{2x}`, meet the y-axis (:math:`Y_3`), then plot
:math:`V_3 = (-\\overline{O_M X_3}, -\\overline{OY_3})`.  A student's attempt with one slip:
the perpendicular goes through :math:`P_{1x}`.  ``graspcompass check v3.gc --against
paper --draw v3.png`` grades it; here the same from Python.
"""

import matplotlib.pyplot as plt

from graspcompass.construction.language import parse
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
side3 = line_with_direction P1 (-(sin(phi1) - cos(phi1)*mu1), -(cos(phi1) + sin(phi1)*mu1))
P1x = foot P1 x-axis
P2x = foot P2 x-axis
O_M = midpoint P1x P2x
X3 = meet side3 x-axis
perp3 = perpendicular side3 P1x
Y3 = meet perp3 y-axis
OMX3 = signed_length O_M X3 x-axis
OY3 = signed_length O Y3 y-axis
V3 = point_from_lengths OMX3 OY3 (-1, -1)
"""
program = parse(ATTEMPT, "v3.gc")

# %%
# The grade
# ---------
# Every object named like a point of the paper is compared with the paper's, for every
# grasp satisfying condition (1): PROVED is an exact argument, REFUTED comes with a grasp
# at which the file, replayed exactly, differs from the paper.
report = check_program(program, against="paper")
for row in report.targets:
    print(f"{row.name:4} {row.status.value}")
print("exit status of graspcompass check:", report.exit_status)

# %%
# The counterexample
# ------------------
# :math:`X_3` is right; :math:`Y_3` is the first wrong object, and :math:`V_3` follows
# from it.  At the counterexample grasp (its values exact) the file's construction is on
# the left, the paper's on the right, :math:`Y_3` highlighted.
row = next(r for r in report.targets if r.status.value == "REFUTED")
print(row.name, "is refuted at", row.counterexample)
fig = figure_counterexample(program, row.name, row.counterexample)
plt.show()

# %%
# The fix
# -------
# With :math:`P_{2x}` in place of :math:`P_{1x}` every target is PROVED.
fixed = parse(ATTEMPT.replace("perpendicular side3 P1x", "perpendicular side3 P2x"))
print("fixed:", check_program(fixed, against="paper").exit_status == 0)
