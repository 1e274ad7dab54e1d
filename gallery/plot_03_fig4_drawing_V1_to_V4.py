"""
Fig. 4 (a)–(d) — drawing V1 … V4 with ruler and compass
========================================================

The points :math:`V_n = (S_n, C_n)` of eqs. (28)–(39) need no calculation: §3.3 draws them
from the friction cones alone.  First drop perpendiculars from :math:`P_1` and
:math:`P_2` to the :math:`x`-axis (feet :math:`P_{1x}`, :math:`P_{2x}`) and mark the midpoint
:math:`O_M` of :math:`P_{1x}P_{2x}`.  Then, for :math:`V_1`:

1. extend the upper side of the friction cone at :math:`P_1` to the :math:`x`-axis:
   :math:`X_1`; the signed length :math:`\\overline{O_M X_1} = -S_1`, eq. (28);
2. draw the perpendicular from :math:`P_{2x}` to that side; it meets the :math:`y`-axis at
   :math:`Y_1`, and :math:`\\overline{OY_1} = -C_1`, eq. (29);
3. plot :math:`V_1 = (-\\overline{O_M X_1}, -\\overline{OY_1})`, eq. (30).

:math:`V_2` uses the upper side at :math:`P_2` and the perpendicular from :math:`P_{1x}`;
:math:`V_3` and :math:`V_4` the lower sides (eqs. (34)–(39)).  The Appendix proves
:math:`\\overline{O_M X_n} = -S_n` and :math:`\\overline{OY_n} = -C_n`; ``graspcompass
verify`` checks these identities symbolically (claims ``s3.3-V1-OMX`` … ``s3.3-V4-OY`` of
the proof report).

The grasp here is a generic one, with unequal contacts, normals and friction
(its object outline does not matter: only the contacts, their normals and friction enter):
:math:`P_1 = (6/5, 3/5)`, :math:`P_2 = (-4/5, 3/5)`, :math:`\\varphi_1 = 75°`,
:math:`\\varphi_2 = 90°`, :math:`\\mu_1 = 0.6`, :math:`\\mu_2 = 0.4`.  Each panel shows the
construction of one :math:`V_n` (the other cone sides are faint), with the signed lengths
as double arrows.
"""

import matplotlib.pyplot as plt

import graspcompass as gc
from graspcompass.render import draw_construction

grasp = gc.Grasp("6/5", "4/5", "3/5", "5*pi/12", "pi/2", mu1="3/5", mu2="2/5")
construction = gc.internal_force_diagram(grasp)

# the objects that belong to the drawing of one V_n (§3.3 steps (1)-(3))
OWN = ("X{}", "perp{}", "Y{}", "OMX{}", "OY{}", "V{}")


def others(n: int) -> set[str]:
    """Names of the objects that draw the other points V_m, m ≠ n."""
    return {name.format(m) for m in (1, 2, 3, 4) if m != n for name in OWN}


# %%
# The exact values the drawing produces
# -------------------------------------
# The signed lengths are steps of the protocol; they are exact.
for n in (1, 2, 3, 4):
    print(
        f"n = {n}:  O_M X{n} = {construction[f'OMX{n}']},   O Y{n} = {construction[f'OY{n}']}"
        f"   ->   V{n} = {construction[f'V{n}']}"
    )
print("closed form (27)-(39):", grasp.V)
print("drawn == closed form:", tuple(construction[f"V{n}"] for n in (1, 2, 3, 4)) == grasp.V)

# %%
# The four drawings
# -----------------
fig, axes = plt.subplots(2, 2, figsize=(10, 10), layout="constrained")
last = construction.step("V4").index
for n, ax, tag in zip((1, 2, 3, 4), axes.flat, "abcd"):
    # the whole drawing up to V4 in the same view for every panel; the objects of the
    # other V_m are hidden and the cone sides they use are faint
    artists = draw_construction(construction, step=last, ax=ax)
    shown = {id(a) for name, lst in artists.items() if name not in others(n) for a in lst}
    for name in others(n):
        for a in artists[name]:
            a.set_visible(id(a) in shown)  # a label shared with a shown point stays
    for m in (1, 2, 3, 4):
        if m != n:
            for a in artists[f"side{m}"]:
                a.set_alpha(0.2)
    side = "upper" if n in (1, 2) else "lower"
    ax.set_title(f"({tag}) $V_{n}$: the {side} side of the cone at $P_{2 - n % 2}$", fontsize=11)
fig.suptitle("Fig. 4: drawing steps of each vector $V_n$ (§3.3)")
plt.show()
