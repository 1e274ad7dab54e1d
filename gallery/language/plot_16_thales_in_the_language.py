"""
Fig. 3 in the language — the Thales circle
==========================================

The paper's key step (§3.2, Fig. 3): :math:`k_n(\\theta) = V_n \\cdot e(\\theta)` is the
signed length :math:`\\overline{OH_n}` of the foot :math:`H_n` of the perpendicular from
:math:`V_n` on the line along :math:`e(\\theta)`, and by Thales' theorem :math:`H_n` lies on
the circle on the diameter :math:`OV_n`.  Written in the construction language, with its
own parameters: :math:`V = (a, b)` and the direction :math:`e(\\theta)` as :math:`(t, -1)`,
:math:`t = \\tan\\theta`.  The file's claim is proved for *every* :math:`a, b > 0` and every
:math:`t`, and the same file is drawn for a few values of :math:`t`, exactly as
``graspcompass draw thales.gc --set a=2 --set b=1 --set t=1/3`` draws it.
"""

import matplotlib.pyplot as plt
import sympy as sp

from graspcompass.construction.language import example_text, parse, replay
from graspcompass.proof.program_check import check_program
from graspcompass.render import draw_construction

THALES = example_text("thales.gc")  # shipped with the package
program = parse(THALES, "thales.gc")

# %%
# The claim, proved
# -----------------
# ``graspcompass check thales.gc`` proves the claim for all admissible parameters (an
# exact argument, not a sample of values):
report = check_program(program)
for row in report.claims:
    print(f"{row.name}: {row.status.value}")

# %%
# Replayed with values
# --------------------
# :func:`~graspcompass.construction.language.replay` takes the values of the parameters
# (the command line's ``--set a=2``); every object is exact.  Checked here from first
# principles: :math:`H = \frac{V \cdot d}{d \cdot d}\, d` with :math:`d = (t, -1)`.
a, b = sp.Integer(2), sp.Integer(1)
for t in (sp.Rational(1, 3), sp.Integer(-2), sp.Integer(0)):
    c = replay(program, {"a": a, "b": b, "t": t})
    lam = (a * t - b) / (t**2 + 1)
    print(
        f"t = {t}: H = {c['H']}, first principles ({lam * t}, {-lam}):",
        (c["H"].x, c["H"].y) == (lam * t, -lam),
    )

# %%
# The drawing
# -----------
# The same file for five directions :math:`t`: the feet :math:`H` all fall on one circle.
fig, ax = plt.subplots(figsize=(6.4, 6.4), layout="constrained")
for t in ("1/3", "-2", "0", "3/2", "-1/2"):
    draw_construction(replay(program, {"a": a, "b": b, "t": t}), ax=ax, labels=t == "1/3")
ax.set_title("thales.gc for five directions t: every H on the circle on OV")
plt.show()
