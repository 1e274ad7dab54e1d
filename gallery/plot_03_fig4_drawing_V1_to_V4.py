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
as double arrows and the right angles at the feet marked.  Panel (a) marks, as the paper
does with double arcs, the two equal angles :math:`\\gamma = \\pi - (\\varphi_1 + \\xi_1)`
of the Appendix: at :math:`P_1` between :math:`P_1P_{1x}` and the cone side, and at
:math:`P_{2x}` between :math:`P_{2x}O` and the perpendicular :math:`P_{2x}Y_1`, so that
:math:`\\overline{P_{1x}X_1} = \\overline{P_1P_{1x}}\\tan\\gamma` (A4) and
:math:`\\overline{OY_1} = \\overline{OP_{2x}}\\tan\\gamma` (A5).
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import graspcompass as gc
from graspcompass.render import draw_construction

grasp = gc.Grasp("6/5", "4/5", "3/5", "5*pi/12", "pi/2", mu1="3/5", mu2="2/5")
construction = gc.internal_force_diagram(grasp)

# the objects that belong to the drawing of one V_n (§3.3 steps (1)-(3))
OWN = ("X{}", "perp{}", "Y{}", "OMX{}", "OY{}", "V{}")


def xy(name: str) -> np.ndarray:
    p = construction[name]
    return np.array([float(p.x), float(p.y)])


def mark_gamma(ax, at: str, a: str, b: str, radius: float) -> float:
    """Double arcs at ``at`` between the rays to ``a`` and ``b``, labelled γ; the angle."""
    c = xy(at)
    ta, tb = (math.atan2(*(xy(q) - c)[::-1]) for q in (a, b))
    if (tb - ta) % (2 * math.pi) > math.pi:
        ta, tb = tb, ta
    t = np.linspace(ta, ta + (tb - ta) % (2 * math.pi), 40)
    for r in (radius, radius * 1.18):
        ax.plot(c[0] + r * np.cos(t), c[1] + r * np.sin(t), color="black", lw=0.8, zorder=7)
    mid = t[len(t) // 2]
    ax.annotate(
        r"$\gamma$",
        (c[0] + 1.75 * radius * math.cos(mid), c[1] + 1.75 * radius * math.sin(mid)),
        ha="center",
        va="center",
        fontsize=11,
        zorder=7,
    )
    return (tb - ta) % (2 * math.pi)


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
    if n == 1:  # the Appendix's two equal angles γ (A4), (A5)
        g1 = mark_gamma(ax, "P1", "P1x", "X1", 0.5)
        g2 = mark_gamma(ax, "P2x", "O", "Y1", 0.5)
        gamma = math.pi - float(grasp.phi1 + grasp.xi1)
        assert abs(g1 - gamma) < 1e-9 and abs(g2 - gamma) < 1e-9, (g1, g2, gamma)
    side = "upper" if n in (1, 2) else "lower"
    ax.set_title(f"({tag}) $V_{n}$: the {side} side of the cone at $P_{2 - n % 2}$", fontsize=11)
fig.suptitle("Fig. 4: drawing steps of each vector $V_n$ (§3.3)")
plt.show()
