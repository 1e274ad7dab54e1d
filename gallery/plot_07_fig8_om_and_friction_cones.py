"""
Fig. 8 (a)(b)(c) — where V3 and V4 lie: O_M and the friction cones
===================================================================

§5 of the paper: "Regarding :math:`V_3` and :math:`V_4`, the position of the point
:math:`O_M` is critical.  If :math:`O_M` is included in both friction cones, :math:`V_3` is
in the region :math:`x < 0`, while :math:`V_4` is in the region :math:`x > 0` (Fig. 8(a));
if :math:`O_M` is excluded from both friction cones, :math:`V_3` is in the region
:math:`x > 0`, while :math:`V_4` is in the region :math:`x < 0` (Fig. 8(b)); otherwise, both
:math:`V_3` and :math:`V_4` are in the same region :math:`x > 0` or :math:`x < 0`
(Fig. 8(c))."

Seen from :math:`P_i`, the midpoint :math:`O_M` of :math:`P_{1x}P_{2x}` lies at the angle
:math:`\\arctan\\frac{x_1 + x_2}{2y}` from the negative :math:`y`-axis, towards the other
contact; the upper side of cone :math:`i` always passes above it (condition (1)), so

.. math::

    O_M \\text{ inside cone } i \\iff \\varphi_i - \\xi_i < \\arctan\\frac{x_1 + x_2}{2y}.

The four grasps below show every case:

- case (a), **inside both** cones: Table I(a) (Fig. 7(a)); also Fig. 6;
- case (b), **outside both** cones: Table I(b) (Fig. 7(b));
- case (c), **inside the cone at** :math:`P_2` **only**: Table I(c) (Fig. 7(c)), both points
  right;
- case (c′), **inside the cone at** :math:`P_1` **only**: the generic grasp of Figs. 4 and 5,
  both points left.

``graspcompass verify`` proves the rule for all admissible parameters (claims ``fig8-V3``,
``fig8-V4``, ``fig8a``–``fig8c`` of the proof report): :math:`V_3` lies in :math:`x < 0`
exactly when :math:`O_M` is inside the cone at :math:`P_1`, and :math:`V_4` in
:math:`x > 0` exactly when :math:`O_M` is inside the cone at :math:`P_2`.
"""

import matplotlib.pyplot as plt
import sympy as sp

import graspcompass as gc
from graspcompass.geometry import decide_sign
from graspcompass.render import draw_construction

grasps = {
    "a": gc.Grasp.preset("table1a"),
    "b": gc.Grasp.preset("table1b"),
    "c": gc.Grasp.preset("table1c"),
    "c′": gc.Grasp("6/5", "4/5", "3/5", "5*pi/12", "pi/2", mu1="3/5", mu2="2/5"),
}


def om_inside(g: gc.Grasp, i: int) -> bool:
    """O_M strictly inside the friction cone at P_i: φ_i − ξ_i < atan((x1 + x2)/(2y))."""
    phi, xi = (g.phi1, g.xi1) if i == 1 else (g.phi2, g.xi2)
    bound = sp.atan((g.x1 + g.x2) / (2 * g.y)) if g.y != 0 else sp.pi / 2
    return decide_sign(bound - (phi - xi)) == 1


# %%
# The geometry decides the case, the construction places V3 and V4
# -----------------------------------------------------------------
constructions = {}
for tag, g in grasps.items():
    c = constructions[tag] = gc.internal_force_diagram(g)
    inside = [om_inside(g, 1), om_inside(g, 2)]
    x3, x4 = decide_sign(c["V3"].x), decide_sign(c["V4"].x)
    print(
        f"({tag}) O_M inside cone 1: {inside[0]!s:5}  inside cone 2: {inside[1]!s:5}  |  "
        f"V3.x {'<' if x3 < 0 else '>'} 0, V4.x {'<' if x4 < 0 else '>'} 0  |  "
        f"rule holds: {(x3 < 0) == inside[0] and (x4 > 0) == inside[1]}"
    )

# %%
# The drawings
# ------------
# The construction up to :math:`V_4`, without the objects of :math:`V_1` and :math:`V_2`;
# the dotted lines join each contact to :math:`O_M`, the half-plane :math:`x < 0` is shaded.
HIDE = {f"{name}{n}" for n in (1, 2) for name in ("X", "perp", "Y", "OMX", "OY", "V")}
titles = {
    "a": "(a) O_M inside both cones",
    "b": "(b) O_M outside both cones",
    "c": "(c) O_M inside the cone at P_2 only",
    "c′": "(c′) O_M inside the cone at P_1 only",
}
fig, axes = plt.subplots(2, 2, figsize=(10, 10), layout="constrained")
for (tag, c), ax in zip(constructions.items(), axes.flat):
    artists = draw_construction(c, step=c.step("V4").index, ax=ax)
    keep = {id(a) for name, lst in artists.items() if name not in HIDE for a in lst}
    for name in HIDE:
        for a in artists[name]:
            a.set_visible(id(a) in keep)
    for name in ("side1", "side2"):
        for a in artists[name]:
            a.set_alpha(0.25)
    om = c["O_M"].evalf()
    for p in ("P1", "P2"):
        ax.plot(*zip(c[p].evalf(), om), color="#e63946", lw=1.4, ls=":")
    x0, x1 = ax.get_xlim()
    ax.axvspan(x0, 0, color="#457b9d", alpha=0.07, zorder=0)
    ax.set_xlim(x0, x1)
    ax.set_title(
        titles[tag].replace("O_M", "$O_M$").replace("P_1", "$P_1$").replace("P_2", "$P_2$"),
        fontsize=11,
    )
fig.suptitle("Fig. 8: the direction of $V_3$ and $V_4$ depends on where $O_M$ lies")
plt.show()
