"""The optimal contact forces for the sublinear effort "max-normal" (issue 25).

Checked against an LP written in the tests (scipy HiGHS on ``min t``, ``G a = -(e, 0)``,
``a_{i+} + a_{i-} <= t``, ``a >= 0``; :mod:`_ncontact_lp`, not the model's code): the
least largest normal force is the LP's value, and the forces returned are a primal
optimum by first principles (nonnegative edge weights, force and moment balance
rebuilt from the contacts, every normal force at most the largest, the largest equal
to the LP's value), carried only by the edges complementary slackness allows.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from _ncontact_lp import edge_matrix, lp_value, random_contacts
from graspcompass.geometry.exact import decide_zero
from graspcompass.geometry.trig import sincos
from graspcompass.ncontact import NContactGrasp

THETAS = np.linspace(0.0, 2 * math.pi, 24, endpoint=False)


def check_primal(contacts, r, theta, want) -> None:
    """``r`` is an optimal solution of the LP for the load e(θ), value ``want``."""
    G, owner = edge_matrix(contacts)
    n = len(contacts)
    a = np.zeros(2 * n)
    for label, w in r["weights"].items():
        i, side = int(label[1:-1]) - 1, label[-1]
        a[2 * i + (0 if side == "+" else 1)] = float(w)
        assert label in r["tight"], (label, r["tight"])
    assert np.all(a >= 0)
    b = -np.array([math.sin(theta), -math.cos(theta), 0.0])
    assert np.abs(G @ a - b).max() <= 1e-9 * (1 + np.abs(a).max())
    N = np.bincount(owner, weights=a, minlength=n)
    scale = 1 + want
    assert N.max() <= want + 1e-9 * scale
    assert abs(N.max() - want) <= 1e-9 * scale
    assert abs(float(r["effort"]) - want) <= 1e-9 * scale
    for i in r["largest"]:
        assert abs(N[i - 1] - want) <= 1e-9 * scale
    # the contact forces are the edge forces summed per contact
    for i, f in enumerate(r["forces"]):
        fx = sum(a[j] * G[0, j] for j in range(2 * n) if owner[j] == i)
        fy = sum(a[j] * G[1, j] for j in range(2 * n) if owner[j] == i)
        assert math.hypot(float(f[0]) - fx, float(f[1]) - fy) <= 1e-9 * scale


@pytest.mark.parametrize("n", [3, 4, 5, 6])
def test_forces_against_the_lp(n: int) -> None:
    rng = np.random.default_rng(20261203 + n)
    held = unheld = 0
    for k in range(30):
        contacts = random_contacts(rng, n, closure=k % 3 != 0)
        g = NContactGrasp(contacts, effort="max-normal")
        for t in THETAS:
            want = lp_value(contacts, float(t), "max-normal")
            r = g.forces(float(t))
            if not math.isfinite(want):
                assert r["effort"] == math.inf and r["forces"] is None
                unheld += 1
                continue
            check_primal(contacts, r, float(t), want)
            held += 1
    assert held >= 250 and unheld >= 10, (held, unheld)


def test_exact_three_fingers() -> None:
    """Three fingers 120° apart, μ = 1/2, a unit load straight down: exact balance, the
    largest normal force equal to k(0) and to the LP's value."""
    spec = [
        (1, 0, "180deg", "1/2"),
        ("-1/2", "sqrt(3)/2", "-60deg", "1/2"),
        ("-1/2", "-sqrt(3)/2", "60deg", "1/2"),
    ]
    g = NContactGrasp(spec, effort="max-normal")
    for theta in ("0", "pi/5", "2*pi/3", "7*pi/4"):
        r = g.forces(theta)
        t = sp.sympify(theta)
        st, ct = sincos(t)
        assert decide_zero(r["effort"] - g.k(theta))
        fx = sum(f[0] for f in r["forces"])
        fy = sum(f[1] for f in r["forces"])
        tz = sum(c.p[0] * f[1] - c.p[1] * f[0] for c, f in zip(g.contacts, r["forces"]))
        assert decide_zero(fx + st) and decide_zero(fy - ct) and decide_zero(tz)
        N = [sp.nsimplify(0)] * 3
        for label, w in r["weights"].items():
            N[int(label[1]) - 1] += w
        assert all(float(w) >= 0 for w in r["weights"].values())
        assert all(float(v - r["effort"]) <= 1e-30 for v in N)
        assert any(decide_zero(v - r["effort"]) for v in N)
        floats = [
            (float(c.p[0]), float(c.p[1]), float(c.n[0]), float(c.n[1]), float(c.mu))
            for c in g.contacts
        ]
        assert abs(float(r["effort"]) - lp_value(floats, float(t), "max-normal")) <= 1e-9


def test_no_force_closure_outside_the_arc() -> None:
    g = NContactGrasp(
        [("1", "0", "180deg", "1/2"), ("0", "-1", "90deg", "1/2")], effort="max-normal"
    )
    assert g.forces("pi")["forces"] is None and g.forces("pi")["effort"] == sp.oo
    r = g.forces("pi/4")
    assert r["forces"] is not None and float(r["effort"]) > 0


def test_k_command_lists_the_edges_that_carry_load(capsys: pytest.CaptureFixture) -> None:
    """``k --effort max-normal --json``: on each held row, the HiGHS LP restricted to the
    listed edges (every other edge weight fixed at 0) reaches the full LP's value."""
    import json

    from scipy.optimize import linprog

    from _ncontact_lp import lp_data
    from graspcompass.cli import main

    spec = [
        "1,0,180deg,1/2",
        "-1/2,sqrt(3)/2,-60deg,1/2",
        "-1/2,-sqrt(3)/2,60deg,1/2",
        "0,1,0,-1,1/3",
    ]
    assert (
        main(
            [
                "k",
                *(f"--contact={c}" for c in spec),
                "--effort",
                "max-normal",
                "--theta",
                "0:360:15deg",
                "--json",
            ]
        )
        == 0
    )
    rows = json.loads(capsys.readouterr().out)
    r3 = math.sqrt(3)
    floats = [
        (1, 0, -1, 0, 0.5),
        (-0.5, r3 / 2, 0.5, -r3 / 2, 0.5),
        (-0.5, -r3 / 2, 0.5, r3 / 2, 0.5),
        (0, 1, 0, -1, 1 / 3),
    ]
    c, A_eq, A_ub, b_ub = lp_data(floats, "max-normal")
    names = [f"P{i + 1}{s}" for i in range(4) for s in "+-"]
    assert len(rows) == 24
    for row in rows:
        t = math.radians(row["theta_deg"])
        b = -np.array([math.sin(t), -math.cos(t), 0.0])
        full = linprog(c, A_eq=A_eq, b_eq=b, A_ub=A_ub, b_ub=b_ub, bounds=(0, None), method="highs")
        assert row["tight"], row
        bounds = [(0, None) if n in row["tight"] else (0, 0) for n in names] + [(0, None)]
        part = linprog(c, A_eq=A_eq, b_eq=b, A_ub=A_ub, b_ub=b_ub, bounds=bounds, method="highs")
        assert part.status == 0 and abs(part.fun - full.fun) <= 1e-9 * (1 + full.fun)
        assert abs(row["k"] - full.fun) <= 1e-9 * (1 + full.fun)
