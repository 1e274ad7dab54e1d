"""Independent check of k_grasp (25) by linear programming (scipy.optimize.linprog).

The problem of §2.2.5 is posed directly, without eqs. (12)-(25):

    variables   F = (N1, F1, N2, F2)
    subject to  L F = M                                   (2), L of (5) built here
                μ1 N1 − F1 ≥ 0,  μ2 N2 − F2 ≥ 0,
                μ1 N1 + F1 ≥ 0,  μ2 N2 + F2 ≥ 0           (8)-(11), closed
                k(F) ≥ 0
    minimise    k(F) = F·F_N / |F_N|²,  F_N = (s1, c1, s2, c2)/(x1 + x2)   (F_e = 1)

k(F) is the component of F along the internal-force direction (the null vector
F_N of L, eq. (15)), so its minimum is the smallest admissible internal-force
parameter, which the paper's closed form says is max(k1, .., k4, 0).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from scipy.optimize import linprog

from conftest import PRESET_NAMES, PRESET_PARAMS, float_params, grasp_matrix_numpy
from graspcompass import Grasp

HIGHS = dict(primal_feasibility_tolerance=1e-10, dual_feasibility_tolerance=1e-10, presolve=True)


def lp_k_grasp(x1, x2, y, phi1, phi2, mu1, mu2, theta):
    """Least k by linear programming; also returns the optimal contact forces."""
    L = grasp_matrix_numpy(x1, x2, y, phi1, phi2)
    M = np.array([-math.sin(theta), math.cos(theta), 0.0])  # eq. (4), F_e = 1
    D = x1 + x2
    FN = np.array([math.sin(phi1), math.cos(phi1), math.sin(phi2), math.cos(phi2)]) / D
    c = FN / (FN @ FN)  # k(F) = c·F
    A_ub = -np.array(
        [
            [mu1, -1.0, 0.0, 0.0],  # μ1 N1 − F1 ≥ 0
            [0.0, 0.0, mu2, -1.0],  # μ2 N2 − F2 ≥ 0
            [mu1, 1.0, 0.0, 0.0],  # μ1 N1 + F1 ≥ 0
            [0.0, 0.0, mu2, 1.0],  # μ2 N2 + F2 ≥ 0
            c,  # k ≥ 0
        ]
    )
    res = linprog(
        c,
        A_ub=A_ub,
        b_ub=np.zeros(5),
        A_eq=L,
        b_eq=M,
        bounds=[(None, None)] * 4,
        method="highs",
        options=HIGHS,
    )
    assert res.status == 0, res.message
    F = res.x
    # the LP solution is a genuine solution of the force balance and the contact conditions
    scale = 1 + np.abs(F).max()
    assert np.abs(L @ F - M).max() < 1e-9 * scale
    assert (-(A_ub @ F) >= -1e-9 * scale).all()
    return float(c @ F), F


def _check(g: Grasp, params, thetas, tol: float = 1e-9) -> float:
    worst = 0.0
    kg = g.k_grasp(np.asarray(thetas))
    for t, k_pkg in zip(thetas, kg):
        k_lp, _ = lp_k_grasp(*params, t)
        err = abs(k_lp - k_pkg)
        assert err <= tol, (t, k_lp, k_pkg)  # HiGHS reaches ~1e-13 here
        worst = max(worst, err)
    return worst


THETAS = np.linspace(0, 2 * np.pi, 73)[:-1]


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_presets_match_linprog(name):
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    _check(g, p.floats, THETAS)


def test_fig6_down_by_lp():
    # θ = 0 in Fig. 6: the LP alone gives 3/2 + √3 (the paper's closed form by hand)
    p = PRESET_PARAMS["fig6"]
    k_lp, F = lp_k_grasp(*p.floats, 0.0)
    assert abs(k_lp - (1.5 + math.sqrt(3))) < 1e-9
    # and the binding constraint is the upper side at P1: μ1 N1 − F1 = 0 (n = 1)
    assert abs(p.floats[5] * F[0] - F[1]) < 1e-9


def test_lp_detects_wrong_answer():
    # the comparison is sharp: k_grasp shifted by 1e-6 is rejected
    p = PRESET_PARAMS["table1a"]
    g = Grasp.preset("table1a")
    k_lp, _ = lp_k_grasp(*p.floats, 0.4)
    assert abs(k_lp - g.k_grasp(0.4)) < 1e-9
    assert abs(k_lp - (g.k_grasp(0.4) + 1e-6)) > 1e-9
    # and the LP finds the zero region too (k_grasp = 0 where every k_n < 0)
    ts = np.linspace(0, 2 * np.pi, 361)
    zero = ts[g.k_grasp(ts) == 0]
    if zero.size:
        assert abs(lp_k_grasp(*p.floats, float(zero[0]))[0]) < 1e-9


@settings(
    max_examples=40, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)
@given(float_params())
def test_random_grasps_match_linprog(p):
    g = p.grasp()
    _check(g, p.floats, np.linspace(0, 2 * np.pi, 25)[:-1] + 0.0123)
