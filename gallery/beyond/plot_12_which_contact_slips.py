"""
Which contact slips, and which way, around the circle
=====================================================

Each arc of the envelope belongs to one circle :math:`n`: there :math:`k_n` is the largest
limit, so with the least internal force :math:`k = k_\\mathrm{grasp}` the friction
inequality :math:`n` of (8)–(11) becomes an equality: the contact force at one fingertip
lies on one side of its friction cone, and that contact is about to slip (§2.2.4):

.. list-table::
   :header-rows: 1

   * - n
     - contact
     - side of the cone
     - about to happen
   * - 1
     - 1
     - upper, :math:`F_1 = \\mu_1 N_1`
     - the object slides *down* past fingertip 1
   * - 2
     - 2
     - upper, :math:`F_2 = \\mu_2 N_2`
     - the object slides *down* past fingertip 2
   * - 3
     - 1
     - lower, :math:`F_1 = -\\mu_1 N_1`
     - the object slides *up* past fingertip 1
   * - 4
     - 2
     - lower, :math:`F_2 = -\\mu_2 N_2`
     - the object slides *up* past fingertip 2

"Up" and "down" are along the tangent of the object's surface at the contact,
:math:`t_1 = (-\\cos\\varphi_1, \\sin\\varphi_1)` and :math:`t_2 = (\\cos\\varphi_2,
\\sin\\varphi_2)` (the second and fourth columns of the grasp matrix (5)), which both
point upwards: a positive tangential force :math:`F_i` pushes the object up along
:math:`t_i`, so when friction is at its limit upwards the object is about to slide
down, and the other way round.  Where no :math:`k_n` is positive (an arc of "circle 0",
absent here) the external force needs no squeezing at all.

Below for the grasp of Fig. 6: the arcs of the envelope coloured by the contact that
slips, arrows for the direction the object slides, and a check with the contact forces of
eq. (16).
"""

import matplotlib.pyplot as plt
import numpy as np

import graspcompass as gc
from graspcompass.render import DEFAULT_THEME, draw_construction

grasp = gc.Grasp.preset("fig6")
construction = gc.internal_force_diagram(grasp)
envelope = construction["envelope"]
phi1, phi2 = float(grasp.phi1), float(grasp.phi2)
tangent = {1: np.array([-np.cos(phi1), np.sin(phi1)]), 2: np.array([np.cos(phi2), np.sin(phi2)])}
mu = {1: float(grasp.mu1), 2: float(grasp.mu2)}


def meaning(n: int) -> tuple[int, str, int]:
    """Contact, cone side and slip direction (±1 along t_i) for the binding limit k_n."""
    return (1 if n in (1, 3) else 2), ("upper" if n in (1, 2) else "lower"), (-1 if n <= 2 else 1)


# %%
# The arcs, and a check with the contact forces
# ---------------------------------------------
# In the middle of each arc, with k = k_grasp, the contact forces F = F_T + k F_N of
# eq. (16) give the four friction inequalities (8)-(11); the one of the arc is 0 (it
# binds), the others are positive.
for arc in envelope.arcs:
    t0, t1 = float(arc.theta_start), float(arc.theta_end)
    mid = (t0 + t1) / 2
    k = grasp.k_grasp(mid)
    N1, F1, N2, F2 = (float(v) for v in grasp.contact_forces(mid, k))
    ineq = [mu[1] * N1 - F1, mu[2] * N2 - F2, mu[1] * N1 + F1, mu[2] * N2 + F2]
    i, side, way = meaning(arc.n)
    print(
        f"θ in [{np.degrees(t0):5.1f}°, {np.degrees(t1):5.1f}°]: circle {arc.n}, contact {i} "
        f"on the {side} side, slides {'down' if way < 0 else 'up'};  (8)-(11) at "
        f"θ = {np.degrees(mid) % 360:5.1f}°: " + ", ".join(f"{v:+.2e}" for v in ineq)
    )

# %%
# The picture
# -----------
th = DEFAULT_THEME
fig, (ax, bx) = plt.subplots(
    1, 2, figsize=(12, 6), layout="constrained", gridspec_kw=dict(width_ratios=[1, 1.15])
)
draw_construction(construction, step=construction.step("P2").index, ax=ax)
for arc in envelope.arcs:
    t = np.linspace(float(arc.theta_start), float(arc.theta_end), 200)
    r = grasp.k_grasp(t)
    i, side, way = meaning(arc.n)
    ax.plot(
        r * np.sin(t),
        -r * np.cos(t),
        color=th.circle_color(arc.n),
        lw=4,
        solid_capstyle="butt",
        label=f"circle {arc.n}: contact {i}, {side} side, slides {'down' if way < 0 else 'up'}",
    )
    p = np.array((grasp.P1 if i == 1 else grasp.P2).evalf())
    d = 0.55 * way * tangent[i]
    shift = 0.12 * (1 if arc.n > 2 else -1) * np.array([tangent[i][1], -tangent[i][0]])
    ax.annotate(
        "",
        xy=tuple(p + shift + d),
        xytext=tuple(p + shift),
        arrowprops=dict(arrowstyle="-|>", color=th.circle_color(arc.n), lw=2.2),
    )
ax.set(xlim=(-4, 2.4), ylim=(-4, 1.8))
ax.legend(loc="lower right", fontsize=8)
ax.set_title("arcs of the envelope by binding limit; arrows: the object slides")

# the same along θ
for arc in envelope.arcs:
    t0, t1 = np.degrees(float(arc.theta_start)), np.degrees(float(arc.theta_end))
    i, side, way = meaning(arc.n)
    for a, b in ((t0, min(t1, 360)), (0, t1 - 360)) if t1 > 360 else ((t0, t1),):
        if b > a:
            bx.axvspan(a, b, color=th.circle_color(arc.n), alpha=0.18)
    centre = (t0 + t1) / 2 % 360 if t1 - t0 < 300 else 0
    bx.text(
        centre,
        4.05,
        f"contact {i}\nslides {'down' if way < 0 else 'up'}",
        ha="center",
        va="top",
        fontsize=9,
        color=th.circle_color(arc.n),
    )
theta = np.linspace(0, 2 * np.pi, 1441)
for n, k in enumerate(grasp.k(theta), 1):
    bx.plot(np.degrees(theta), k, color=th.circle_color(n), lw=1, ls="--", label=f"$k_{n}$")
bx.plot(
    np.degrees(theta), grasp.k_grasp(theta), color=th.envelope_color, lw=2.5, label="$k_{grasp}$"
)
bx.set(
    xlim=(0, 360),
    ylim=(-0.5, 4.4),
    xticks=np.arange(0, 361, 45),
    xlabel=r"direction of the external force $\theta$ [deg]",
    ylabel="$k$",
)
bx.legend(loc="lower left", fontsize=8, ncol=5)
bx.set_title("which limit binds, for every direction of the external force")
plt.show()
