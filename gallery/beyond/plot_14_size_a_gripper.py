"""
Sizing a gripper: the paper's worst case against the vendor formula
===================================================================

Gripper vendors size the squeeze of a two-jaw gripper with :math:`F = m (g + a) S /
(\\mu n)` per jaw, which is right for a part centred between the jaws and loaded along
the pads.  The paper's model (eq. (17)) gives the squeeze for every direction of the load,
and its worst case over all orientations is

.. math::

    F = m g \\, \\frac{\\max_n |V_n|}{x_1 + x_2} \\quad \\text{per jaw}

(:math:`V_n` of eqs. (28)–(39)).  For a 1 kg part in jaws 100 mm apart with
:math:`\\mu = 0.3`, the vendor formula says 16.35 N per jaw whatever the part; the
paper's worst case grows as the centre of mass moves towards one jaw: 25.0 N when it sits
25 mm off centre.  :func:`graspcompass.sizing.size_gripper` computes it (``graspcompass
size`` from the command line), with the orientation that is worst and the contact that
slips.
"""

import matplotlib.pyplot as plt
import numpy as np

from graspcompass import place_grasp
from graspcompass.sizing import size_gripper

G, MASS, MU = 9.81, 1.0, 0.3
offsets = np.linspace(0.0, 0.045, 19)  # the centre of mass, metres towards jaw 1
worst, vendor, slips = [], [], []
for d in offsets:
    part = place_grasp(
        [(0.05, 0.0), (-0.05, 0.0)],
        [(-1.0, 0.0), (1.0, 0.0)],
        mu=(MU, MU),
        com=(float(d), 0.0),
        names=("jaw 1", "jaw 2"),
    )
    s = size_gripper(part, MASS, g=G)
    worst.append(s.worst_squeeze)
    vendor.append(s.vendor_squeeze)
    slips.append(s.worst_slipping_contact)

fig, ax = plt.subplots(figsize=(7, 4.2), layout="constrained")
ax.plot(offsets * 1000, worst, "o-", label="the paper's worst case over all orientations")
ax.plot(offsets * 1000, vendor, "--", label="vendor formula m g S / (μ n), n = 2")
ax.axvline(25, color="0.6", lw=0.8)
ax.annotate(
    f"{worst[10]:.1f} N at 25 mm", (25, worst[10]), xytext=(8, -14), textcoords="offset points"
)
ax.set_xlabel("centre of mass off centre, towards jaw 1 (mm)")
ax.set_ylabel("squeeze per jaw (N)")
ax.set_title("1 kg part, jaws 100 mm apart, μ = 0.3")
ax.legend(loc="upper left")

# %%
# The worked example of the issue: 25 mm off centre.
part = place_grasp(
    [(0.05, 0.0), (-0.05, 0.0)],
    [(-1.0, 0.0), (1.0, 0.0)],
    mu=(MU, MU),
    com=(0.025, 0.0),
    names=("jaw 1", "jaw 2"),
)
s = size_gripper(part, MASS, g=G)
print(
    f"worst {s.worst_squeeze:.2f} N per jaw (load towards {s.worst_direction_deg:.1f}°, "
    f"{s.worst_slipping_contact} slips); vendor {s.vendor_squeeze:.2f} N; "
    f"ratio {s.worst_squeeze / s.vendor_squeeze:.2f}"
)
