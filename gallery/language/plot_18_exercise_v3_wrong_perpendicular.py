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

from graspcompass.construction.language import example_text, parse
from graspcompass.proof.program_check import check_program
from graspcompass.render.grading import figure_counterexample

ATTEMPT = example_text("exercise-v3.gc")  # shipped with the package
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
