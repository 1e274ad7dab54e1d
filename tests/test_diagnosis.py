"""Slip diagnosis (issue 13 §4): which friction condition binds, checked from first principles.

The expected answers come from the contact-force problem posed directly as a
linear program, without eqs. (12)-(25):

    variables   f = (N1, F1, N2, F2)
    subject to  L f = M                        (2), L of (5) written out in conftest
                μ_i N_i ∓ F_i ≥ 0              (8)-(11), closed
                u · f ≥ 0                      no pulling
    minimise    u · f

where u is the unit null vector of L (scipy.linalg.null_space), oriented so that
it squeezes (its force at P1 = (x1, y) points towards P2, −x).  The internal
force is then the size of that self-equilibrated squeeze at one contact,
(u · f) |(u_1, u_2)|, and k = F_int (x1 + x2) / F_e (17).  At the optimum the
active friction constraint says which contact slips; the sign of its
tangential force F_i says which way: friction on the object acts along
F_i t_i (t_i the tangential column of L), the contact point slides the
opposite way relative to the finger.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.linalg import null_space
from scipy.optimize import linprog

from conftest import PRESET_NAMES, PRESET_PARAMS, exact_params, float_params, grasp_matrix_numpy
from graspcompass import Grasp
from graspcompass.diagnosis import (
    INEQUALITIES,
    SLIP_DTYPE,
    Slip,
    slip,
    slip_intervals,
    zero_force_intervals,
)
from graspcompass.errors import (
    ComplexValueError,
    InputError,
    NonFiniteValueError,
    SymbolicValueError,
    WrongTypeError,
)
from graspcompass.expr import ExpressionError

HIGHS = dict(primal_feasibility_tolerance=1e-10, dual_feasibility_tolerance=1e-10)


def lp(x1, x2, y, phi1, phi2, mu1, mu2, theta):
    """``(k, f, slacks)``: least internal force parameter, contact forces, friction slacks."""
    L = grasp_matrix_numpy(x1, x2, y, phi1, phi2)
    M = np.array([-math.sin(theta), math.cos(theta), 0.0])
    u = null_space(L)[:, 0]
    if (u[0] * L[0, 0] + u[1] * L[0, 1]) > 0:  # x-force at P1 must point to −x: a squeeze
        u = -u
    G = np.array([[mu1, -1, 0, 0], [0, 0, mu2, -1], [mu1, 1, 0, 0], [0, 0, mu2, 1]], float)
    res = linprog(
        u,
        A_ub=-np.vstack([G, u]),
        b_ub=np.zeros(5),
        A_eq=L,
        b_eq=M,
        bounds=[(None, None)] * 4,
        method="highs",
        options=HIGHS,
    )
    assert res.status == 0, res.message
    f = res.x
    k = float(u @ f) * math.hypot(u[0], u[1]) * (x1 + x2)
    return k, f, G @ f, L


def slides_from_lp(f, L, n):
    """Direction the contact point slides (relative to the finger) when condition n binds."""
    j = 1 if n in (1, 3) else 3  # the tangential force's column
    t = L[:2, j]
    return -np.sign(f[j]) * t


def check_against_lp(g: Grasp, p, theta: float, tol: float = 1e-7) -> Slip:
    s = slip(g, theta)
    k, f, slack, L = lp(*p, theta)
    scale = 1 + float(np.abs(f).max()) + abs(k)
    assert abs(s.k_grasp - k) <= tol * scale, (s, k)
    clear = s.margin > 1e-5 * scale  # the active set is then unambiguous
    if s.n == 0:
        assert abs(k) <= tol * scale
        for m in s.binding[1:]:  # friction conditions at their limit with no squeeze
            assert abs(slack[m - 1]) <= tol * scale, (s, slack)
        if clear:
            rest = [slack[m - 1] for m in (1, 2, 3, 4) if m not in s.binding]
            assert min(rest) > 1e-7 * scale, (s, slack)
    else:
        for m in s.binding:  # every binding condition is active at the LP's optimum
            assert abs(slack[m - 1]) <= tol * scale, (s, slack)
        for i in s.unloaded:  # both sides of one cone bind: that contact carries nothing
            assert abs(f[2 * i - 2]) + abs(f[2 * i - 1]) <= tol * scale, (s, f)
        if clear:
            others = [slack[m - 1] for m in (1, 2, 3, 4) if m not in s.binding]
            if others:
                assert min(others) > 1e-7 * scale, (s, slack)
            assert k > 1e-7 * scale
        if clear and not s.unloaded:
            expect = slides_from_lp(f, L, s.n)
            assert np.allclose(s.slide, expect, atol=1e-9), (s, expect)
            # and the paper's words: upper side ↔ F_i = +μ N_i ↔ slides down (−y)
            q = INEQUALITIES[s.n]
            assert (f[1 if q.contact == 1 else 3] > 0) == (q.side == "upper")
            if abs(s.slide[1]) > 1e-9:
                assert (s.slide[1] < 0) == (q.way == "down")
    return s


THETAS = np.linspace(0, 2 * np.pi, 25)[:-1] + 0.01


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_presets_against_lp(name):
    g = Grasp.preset(name)
    for t in THETAS:
        check_against_lp(g, PRESET_PARAMS[name].floats, float(t))


def test_table1a_down_first_principles():
    # θ = 0, table1a: the weight pulls straight down; P1 has the smaller μ (1 < 1.2), so
    # P1 slides down its wall first (condition (8), upper side): k1 = x2·1 = 2, k2 = 2/1.2
    s = slip(Grasp.preset("table1a"), 0)
    assert (s.n, s.contact, s.side, s.binding, s.slide) == (1, 1, "upper", (1,), (0, -1))
    assert (s.k_grasp, s.runner_up, s.margin) == (2, 2, sp.Rational(1, 3))
    assert not s.zero_force and not s.tie
    assert "slips at P1" in s.description and "(8)" in s.description


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(p=float_params(), theta=st.floats(0, 2 * math.pi))
def test_random_float_grasps_against_lp(p, theta):
    check_against_lp(p.grasp(), p.floats, theta)


ZERO = Grasp(1, 1, "1/2", "3*pi/4", "3*pi/4", mu1=2, mu2=2)  # cradled: no squeeze near θ = 0


def test_zero_force_region_named_and_exact():
    ((a, b),) = zero_force_intervals(ZERO)
    assert a == 2 * sp.pi - sp.atan(sp.Rational(2, 5)) and b == 2 * sp.pi + sp.atan(
        sp.Rational(2, 5)
    )
    s = slip(ZERO, 0)
    assert s.zero_force and s.n == 0 and s.contact is None and s.slide is None
    assert s.k_grasp == 0 and s.margin > 0
    assert s.margin == -max(ZERO.k(0))  # how far the largest k_n stays below zero
    assert "zero-force region" in s.description
    p = (1.0, 1.0, 0.5, 3 * math.pi / 4, 3 * math.pi / 4, 2.0, 2.0)
    for t in (0.0, 0.3, -0.3 % (2 * math.pi)):
        assert check_against_lp(ZERO, p, t).n == 0
    # the edge of the region: k = 0 and one friction condition bind together
    edge = slip(ZERO, b)
    assert edge.n == 0 and edge.tie and len(edge.binding) == 2 and edge.k_grasp == 0
    fedge = slip(ZERO, float(b))
    assert fedge.binding == edge.binding


def _check_intervals(g: Grasp) -> None:
    ivs = slip_intervals(g)
    total = sum(float(iv.theta_end - iv.theta_start) for iv in ivs)
    assert math.isclose(total, 2 * math.pi, rel_tol=1e-12)
    for prev, iv in zip(ivs[-1:] + ivs[:-1], ivs):
        assert (
            iv.theta_start == prev.theta_end
            or sp.simplify(iv.theta_start + 2 * sp.pi - prev.theta_end) == 0
            or math.isclose(float(iv.theta_start) + 2 * math.pi, float(prev.theta_end))
        )
        mid = (float(iv.theta_start) + float(iv.theta_end)) / 2
        assert slip(g, mid).n == iv.n
        # the exact break point: both neighbours bind there (a tie), exactly
        s = slip(g, iv.theta_start)
        assert {iv.n, prev.n} <= set(s.binding), (iv, prev, s)
        assert s.tie
        f = slip(g, float(iv.theta_start))  # and the float path sees the tie too
        assert set(f.binding) == set(s.binding)
        if iv.n:
            assert iv.contact == INEQUALITIES[iv.n].contact and iv.side in ("upper", "lower")


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_intervals_exact_presets(name):
    _check_intervals(Grasp.preset(name))


def test_intervals_with_zero_region():
    _check_intervals(ZERO)
    assert [iv.n for iv in slip_intervals(ZERO)][-1] == 0


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(p=exact_params())
def test_intervals_exact_random(p):
    _check_intervals(p.grasp())


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(p=exact_params(), q=st.fractions(0, 7, max_denominator=50))
def test_exact_and_float_agree(p, q):
    g = p.grasp()
    theta = sp.Rational(q.numerator, q.denominator)
    e = slip(g, theta)
    f = slip(g, float(theta))
    gf = Grasp(*p.floats)  # the same grasp on the float path, an exact θ
    ff = slip(gf, theta)
    assert isinstance(f.k_grasp, float) and isinstance(ff.theta, float)
    for r in (f, ff):
        assert math.isclose(float(e.k_grasp), r.k_grasp, rel_tol=1e-9, abs_tol=1e-9)
        assert math.isclose(float(e.margin), r.margin, rel_tol=1e-6, abs_tol=1e-9)
        if float(e.margin) > 1e-6:
            assert (r.n, r.binding, r.runner_up) == (e.n, e.binding, e.runner_up)
            if e.slide is not None:
                assert np.allclose([float(v) for v in e.slide], r.slide)


def test_exact_ties_where_circles_coincide():
    # φ1 = φ2, μ1 = μ2, x1 = x2, y = 0: V1 and V2 are mirror images; at θ = 0 (down) the
    # two upper sides bind together: both contacts slip down at once
    g = Grasp(1, 1, 0, "pi/2", "pi/2", mu1="1/2", mu2="1/2")
    s = slip(g, 0)
    assert s.binding == (1, 2) and s.tie and s.n == 1
    assert "Tie" in s.description and s.unloaded == ()


def test_unloaded_contact_where_the_force_points_at_the_other_contact():
    # e(θ) along O -> P1 = (1, 1): θ = 3π/4; a force through O and P1 can be carried by
    # contact 1 alone (zero moment), so k2 = k4 there and contact 2 is unloaded
    g = Grasp(1, 1, 1, "pi/2", "pi/2", mu1=2, mu2=2)
    s = slip(g, "3*pi/4")
    assert {2, 4} <= set(s.binding) or s.n in (0, 1, 3)
    k = g.k("3*pi/4")
    assert k[1] == k[3]
    if {2, 4} <= set(s.binding):
        assert s.unloaded == (2,) and "lose contact" in s.description
    f = slip(g, 0.0)
    assert f.binding == (1, 2)
    a = slip(g, np.array([0.0, 1e-3]))
    assert a["binding"][0].tolist() == [False, True, True, False, False]
    assert a["binding"][1].sum() == 1


def test_vectorised_matches_scalar():
    g = Grasp.preset("fig6")
    t = np.linspace(0, 2 * np.pi, 12).reshape(3, 4)
    a = slip(g, t)
    assert a.dtype == SLIP_DTYPE and a.shape == (3, 4)
    for idx in np.ndindex(t.shape):
        s = slip(g, float(t[idx]))
        row = a[idx]
        assert row["n"] == s.n and row["k_grasp"] == s.k_grasp and row["margin"] == s.margin
        assert tuple(np.flatnonzero(row["binding"])) == s.binding
        assert row["contact"] == (s.contact or 0)
    assert np.array_equal(a["k_grasp"], g.k_grasp(t))
    assert slip(g, []).shape == (0,)


def test_record_is_immutable():
    s = slip(Grasp.preset("fig6"), "pi/3")
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.n = 3  # type: ignore[misc]


@pytest.mark.parametrize(
    ("theta", "error"),
    [
        ("__import__('os').system('true')", ExpressionError),
        ("t", ExpressionError),
        ("asin(2)", ComplexValueError),
        (1j, ComplexValueError),
        (sp.I, ComplexValueError),
        (float("nan"), NonFiniteValueError),
        (float("inf"), NonFiniteValueError),
        ([0.0, float("nan")], NonFiniteValueError),
        (None, WrongTypeError),
        (True, WrongTypeError),
        ({"theta": 1}, WrongTypeError),
        (["pi/3"], WrongTypeError),
        ("1e400", ExpressionError),
    ],
)
def test_hostile_theta(theta, error):
    with pytest.raises(error) as info:
        slip(Grasp.preset("fig6"), theta)
    assert isinstance(info.value, InputError)
    assert str(info.value).startswith("theta")


def test_symbolic_refused():
    with pytest.raises(SymbolicValueError):
        slip(Grasp.symbolic(), 0)
    with pytest.raises(SymbolicValueError):
        slip(Grasp.symbolic(), 0.5)
    with pytest.raises(SymbolicValueError):
        slip_intervals(Grasp.symbolic())
    with pytest.raises(SymbolicValueError):
        slip(Grasp.preset("fig6"), sp.Symbol("t"))


def test_float_grasp_intervals():
    g = Grasp(2.0, 2.0, 1.0, math.pi / 2, math.pi / 2, mu1=1.0, mu2=1.2)
    ivs = slip_intervals(g)
    assert [iv.n for iv in ivs] == [iv.n for iv in slip_intervals(Grasp.preset("table1a"))]
    for iv in ivs:
        assert isinstance(iv.theta_start, sp.Float)
