"""Tests of graspcompass.grasp: the model of §2-§3.2 (eqs. (1)-(39)).

Expected values are derived by hand in the test (the paper's tangent values,
Table I rationals), from the paper's formulas re-typed in ``conftest.py``, or
from first principles (force balance, the pseudo-inverse, the friction
inequalities (8)-(11)); never copied from the implementation's output.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import graspcompass
from conftest import (
    PRESET_NAMES,
    PRESET_PARAMS,
    closed_form_SC,
    exact_params,
    float_params,
    grasp_matrix_sympy,
    is_zero,
    k_paper,
)
from graspcompass import ExpressionError, Grasp, InvalidGraspError, Point
from graspcompass import symbols as gs

pi, sqrt, R = sp.pi, sp.sqrt, sp.Rational
r3 = sqrt(3)

#: exact θ values used for exact checks
THETAS = (sp.Integer(0), pi / 6, pi / 3, pi / 2, 2 * pi / 3, 5 * pi / 4, 7 * pi / 4, -pi / 5)

FAST = settings(
    max_examples=60, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)
EXACT = settings(
    max_examples=15, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)


def friction_expressions(F: sp.Matrix, mu1, mu2) -> tuple[sp.Expr, ...]:
    """Left-hand sides of (8)-(11): μ1N1 − F1, μ2N2 − F2, μ1N1 + F1, μ2N2 + F2."""
    N1, F1, N2, F2 = F
    return (mu1 * N1 - F1, mu2 * N2 - F2, mu1 * N1 + F1, mu2 * N2 + F2)


# ---------------------------------------------------------------------------
# §4.1, Fig. 6: V1..V4 by hand
# ---------------------------------------------------------------------------
class TestFig6:
    # tangents of φ ± ξ for φ1 = φ2 = π/3, ξ1 = π/4, ξ2 = π/3, by hand
    T1P = -(2 + r3)  # tan(π/3 + π/4) = tan(7π/12)
    T2P = -r3  # tan(π/3 + π/3) = tan(2π/3)
    T1M = 2 - r3  # tan(π/3 - π/4) = tan(π/12)
    T2M = sp.Integer(0)  # tan(π/3 - π/3) = tan(0)

    def test_hand_tangents(self):
        # the hand values themselves, checked against sympy's tan
        for angle, value in (
            (7 * pi / 12, self.T1P),
            (2 * pi / 3, self.T2P),
            (pi / 12, self.T1M),
            (sp.Integer(0), self.T2M),
        ):
            assert sp.simplify(sp.tan(angle) - value) == 0

    def expected(self):
        x1 = x2 = r3 / 2
        y = R(1, 2)
        h = (x1 + x2) / 2
        return [
            (-h + y * self.T1P, x2 * self.T1P),  # (28), (29)
            (h - y * self.T2P, x1 * self.T2P),  # (34), (35)
            (-h + y * self.T1M, x2 * self.T1M),  # (36), (37)
            (h - y * self.T2M, x1 * self.T2M),  # (38), (39)
        ]

    def test_V_by_hand(self):
        g = Grasp.preset("fig6")
        for n, (V, (S, C)) in enumerate(zip(g.V, self.expected()), start=1):
            assert sp.simplify(V.x - S) == 0, f"S{n}"
            assert sp.simplify(V.y - C) == 0, f"C{n}"
            assert sp.simplify(g.S[n - 1] - S) == 0
            assert sp.simplify(g.C[n - 1] - C) == 0

    def test_V_canonical_forms(self):
        g = Grasp.preset("fig6")
        assert g.V[0] == Point(-1 - r3, -R(3, 2) - r3)
        assert g.V[1] == Point(r3, -R(3, 2))
        # V3 = (1 - √3, √3 - 3/2) and V4 = (√3/2, 0), worked out by hand
        assert sp.expand(g.V[2].x - (1 - r3)) == 0
        assert sp.expand(g.V[2].y - (r3 - R(3, 2))) == 0
        assert sp.expand(g.V[3].x - r3 / 2) == 0 and g.V[3].y == 0

    def test_section5_statements(self):
        # §5: Fig. 6 is case (a) (O_M inside both cones): V3.x < 0 < V4.x;
        # 0 < φ_i < π/2 with π/2 < φ_i + ξ_i < π: V1, V2 in y < 0, V1 left of V2
        g = Grasp.preset("fig6")
        V1, V2, V3, V4 = g.V
        assert V3.x < 0 < V4.x
        assert V1.y < 0 and V2.y < 0 and V1.x < V2.x

    def test_k_grasp_and_force_at_theta0(self):
        # θ = 0 (force straight down): k_n(0) = −C_n = 3/2 + √3, 3/2, 3/2 − √3, 0
        g = Grasp.preset("fig6")
        assert sp.simplify(g.k_grasp(0) - (R(3, 2) + r3)) == 0
        # (17): F_int = k/(x1 + x2) · F_e with x1 + x2 = √3
        assert sp.simplify(g.internal_force(0) - (1 + r3 / 2)) == 0
        assert sp.simplify(g.internal_force(0, 4) - (4 + 2 * r3)) == 0

    def test_params(self):
        g = Grasp.preset("fig6")
        assert g.P1 == Point(r3 / 2, R(1, 2)) and g.P2 == Point(-r3 / 2, R(1, 2))
        assert g.mu1 == 1 and sp.simplify(g.mu2 - r3) == 0
        assert g.xi1 == pi / 4 and g.xi2 == pi / 3


# ---------------------------------------------------------------------------
# §4.2, Table I
# ---------------------------------------------------------------------------
# φ = π/2: tan(φ + ξ) = −1/μ and tan(φ − ξ) = 1/μ; with x1 = x2 = 2, (x1 + x2)/2 = 2:
#   S1 = −2 − y/μ1, C1 = −2/μ1, S2 = 2 + y/μ2, C2 = −2/μ2,
#   S3 = −2 + y/μ1, C3 = 2/μ1,  S4 = 2 − y/μ2, C4 = 2/μ2.
TABLE1 = {
    # y = 1, μ1 = 1, μ2 = 6/5 (1/μ2 = 5/6)
    "table1a": [(-3, -2), (R(17, 6), -R(5, 3)), (-1, 2), (R(7, 6), R(5, 3))],
    # y = 3, μ1 = 1, μ2 = 6/5
    "table1b": [(-5, -2), (R(9, 2), -R(5, 3)), (1, 2), (-R(1, 2), R(5, 3))],
    # y = 2, μ1 = 1/2 (1/μ1 = 2), μ2 = 7/5 (1/μ2 = 5/7)
    "table1c": [(-6, -4), (R(24, 7), -R(10, 7)), (2, 4), (R(4, 7), R(10, 7))],
}


@pytest.mark.parametrize("name", sorted(TABLE1))
def test_table1_V_by_hand(name):
    g = Grasp.preset(name)
    for n, (V, (S, C)) in enumerate(zip(g.V, TABLE1[name]), start=1):
        assert V.x == S and V.y == C, f"V{n} of {name}: {V} != ({S}, {C})"
        assert V.x.is_Rational and V.y.is_Rational


def test_table1_qualitative_statements():
    V = {name: Grasp.preset(name).V for name in TABLE1}
    # §4.2/§5: V3 and V4 are switched between (a) and (b); in (c) both face right
    assert V["table1a"][2].x < 0 < V["table1a"][3].x
    assert V["table1b"][2].x > 0 > V["table1b"][3].x
    assert V["table1c"][2].x > 0 and V["table1c"][3].x > 0
    for name in TABLE1:
        V1, V2 = V[name][0], V[name][1]
        assert V1.y < 0 and V2.y < 0 and V1.x < V2.x  # §5


def test_table1_exact_decimal():
    g = Grasp.preset("table1a")
    assert g.mu2 == R(6, 5) and g.mu2.is_Rational and not g.mu2.atoms(sp.Float)
    assert g.mu1 == 1 and g.mu1.is_Integer
    assert Grasp.preset("table1c").mu2 == R(7, 5)
    same = [
        Grasp(2, 2, 1, "pi/2", "pi/2", mu1=1, mu2=v)
        for v in ("1.2", Fraction(6, 5), R(6, 5), "6/5")
    ]
    assert all(h == g for h in same)


# ---------------------------------------------------------------------------
# force balance LF = M, eqs. (2)-(5), (13)-(16)
# ---------------------------------------------------------------------------
TH, K, FE = gs.theta, sp.Symbol("k", real=True), gs.F_e


def M_wrench(theta, fe):
    """M of eq. (4)."""
    return sp.Matrix([-fe * sp.sin(theta), fe * sp.cos(theta), 0])


def _pythagoras(e: sp.Expr, angles) -> sp.Expr:
    """Expand and use cos²a = 1 − sin²a for each angle a: a cheap exact trig zero test."""
    e = sp.expand(e)
    e = e.subs({sp.cos(a) ** 2: 1 - sp.sin(a) ** 2 for a in angles})
    return sp.expand(e)


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_force_balance_preset(name):
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    L = grasp_matrix_sympy(p.x1, p.x2, p.y, p.phi1, p.phi2)
    assert all(is_zero(e) for e in g.grasp_matrix() - L)
    M = M_wrench(TH, FE)
    assert all(is_zero(e) for e in g.external_wrench(TH, FE) - M)
    F = g.contact_forces(TH, K, FE)
    assert all(is_zero(e) for e in L * F - M)
    FN = g.F_N(FE)
    assert all(is_zero(e) for e in L * FN)
    assert any(not is_zero(e) for e in FN)  # a non-trivial null vector


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_F_T_is_pseudo_inverse_solution(name):
    """Eq. (13) as printed equals L^T (L L^T)^-1 M (eq. (12)), L built here."""
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    L = grasp_matrix_sympy(p.x1, p.x2, p.y, p.phi1, p.phi2)
    M = M_wrench(TH, FE)
    pinv = L.T * (L * L.T).inv() * M
    assert all(is_zero(e) for e in g.F_T(TH, FE) - pinv)
    # F_N of (15) is (s1, c1, s2, c2) F_e / (x1 + x2)
    D = p.x1 + p.x2
    FN = sp.Matrix([sp.sin(p.phi1), sp.cos(p.phi1), sp.sin(p.phi2), sp.cos(p.phi2)]) * FE / D
    assert all(is_zero(e) for e in g.F_N(FE) - FN)


@pytest.mark.parametrize("friction", ["xi", "mu"])
def test_force_balance_symbolic(friction):
    g = Grasp.symbolic(friction)
    L = grasp_matrix_sympy(gs.x1, gs.x2, gs.y, gs.phi1, gs.phi2)
    assert all(sp.expand(e) == 0 for e in g.grasp_matrix() - L)
    angles = (gs.phi1, gs.phi2, TH)
    F = g.contact_forces(TH, K, FE)
    for e in L * F - M_wrench(TH, FE):
        assert _pythagoras(sp.together(e).as_numer_denom()[0], angles) == 0
    for e in L * g.F_N(FE):
        assert _pythagoras(e, angles) == 0
    # F_T ⊥ F_N: with L F_T = M this makes F_T the minimum-norm (pseudo-inverse) solution
    dot = (g.F_T(TH, FE).T * g.F_N(FE))[0]
    assert _pythagoras(sp.together(dot).as_numer_denom()[0], angles) == 0


def test_pythagoras_helper_can_fail():
    # the cheap zero test must not call everything zero
    assert _pythagoras(sp.sin(TH) ** 2 + sp.cos(TH) ** 2 - 1, [TH]) == 0
    assert _pythagoras(sp.sin(TH) ** 2 - sp.cos(TH) ** 2, [TH]) != 0


# ---------------------------------------------------------------------------
# k_n from first principles: the n-th friction inequality is tight at k = k_n
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", PRESET_NAMES)
def test_k_n_makes_inequality_tight(name):
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    L = grasp_matrix_sympy(p.x1, p.x2, p.y, p.phi1, p.phi2)
    D = p.x1 + p.x2
    FN = sp.Matrix([sp.sin(p.phi1), sp.cos(p.phi1), sp.sin(p.phi2), sp.cos(p.phi2)]) / D
    pinv = L.T * (L * L.T).inv()
    for theta in THETAS[:5]:
        FT = (pinv * M_wrench(theta, 1)).applyfunc(sp.radsimp)
        ks = g.k(theta)
        assert len(ks) == 4
        for n in range(4):
            F = FT + ks[n] * FN
            lhs = friction_expressions(F, p.mu1, p.mu2)[n]
            assert is_zero(lhs), f"inequality {n + 8} not tight at k{n + 1}({theta})"
            # and k_n is a LOWER limit: a larger k satisfies the inequality strictly
            lhs_more = friction_expressions(FT + (ks[n] + 1) * FN, p.mu1, p.mu2)[n]
            assert sp.N(lhs_more, 30) > 0


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_k_matches_paper_mu_form(name):
    """g.k equals the first lines of (18)-(21) (μ form), for exact θ and symbolic θ."""
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    for theta in (*THETAS, TH):
        for n, (got, want) in enumerate(zip(g.k(theta), k_paper(theta, *p.seven)), start=1):
            assert is_zero(got - want), f"k{n}({theta})"


def test_k_wrong_sign_would_be_caught():
    # the tightness check distinguishes k1 from −k1 (guards against vacuous checks)
    p = PRESET_PARAMS["table1a"]
    L = grasp_matrix_sympy(p.x1, p.x2, p.y, p.phi1, p.phi2)
    FN = sp.Matrix([1, 0, 1, 0]) / 4
    theta = pi / 6
    FT = L.T * (L * L.T).inv() * M_wrench(theta, 1)
    k1 = Grasp.preset("table1a").k(theta)[0]
    assert not is_zero(friction_expressions(FT - k1 * FN, p.mu1, p.mu2)[0])


# ---------------------------------------------------------------------------
# k_grasp (25), internal force (17), numeric vs exact paths
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", PRESET_NAMES)
def test_k_grasp_exact_is_max(name):
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    for theta in THETAS:
        cands = (*k_paper(theta, *p.seven), sp.Integer(0))
        vals = [sp.N(c, 30) for c in cands]
        best = max(range(5), key=lambda i: vals[i])
        kg = g.k_grasp(theta)
        assert is_zero(kg - cands[best]), (theta, kg, cands[best])
        assert sp.N(kg, 30) >= 0


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_k_grasp_symbolic_theta(name):
    g = Grasp.preset(name)
    t = sp.Symbol("t", real=True)
    kg = g.k_grasp(t)
    assert isinstance(kg, sp.Max)
    for theta in THETAS[:4]:
        assert abs(float(kg.subs(t, theta)) - float(g.k_grasp(theta))) < 1e-12


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_internal_force_eq17(name):
    p = PRESET_PARAMS[name]
    g = Grasp.preset(name)
    D = p.x1 + p.x2
    for theta in THETAS[:4]:
        kg = g.k_grasp(theta)
        assert is_zero(g.internal_force(theta) - kg / D)
        assert is_zero(g.internal_force(theta, FE) - kg * FE / D)
        assert is_zero(g.internal_force(theta, R(5, 2)) - kg * R(5, 2) / D)
    ts = np.linspace(0, 2 * np.pi, 37)
    np.testing.assert_allclose(
        g.internal_force(ts, 2.5), g.k_grasp(ts) * 2.5 / float(D), rtol=1e-14, atol=1e-14
    )
    assert isinstance(g.internal_force(0.3, 2.0), float)


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_vectorised_equals_exact_loop(name):
    g = Grasp.preset(name)
    exact = [pi * R(j, 12) for j in range(-2, 26)]
    ts = np.array([float(t) for t in exact])
    kv = g.k(ts)
    kgv = g.k_grasp(ts)
    assert kv.shape == (4, ts.size) and kgv.shape == ts.shape
    for j, t in enumerate(exact):
        ke = g.k(t)
        for n in range(4):
            assert abs(kv[n, j] - float(ke[n])) < 1e-12
        assert abs(kgv[j] - float(g.k_grasp(t))) < 1e-12
        assert abs(g.k_grasp(float(t)) - float(g.k_grasp(t))) < 1e-12


def test_array_shapes():
    g = Grasp.preset("fig6")
    assert g.k(0.3).shape == (4,)
    assert isinstance(g.k_grasp(0.3), float)
    assert g.k(np.zeros((2, 3))).shape == (4, 2, 3)
    assert g.k_grasp(np.zeros((2, 3))).shape == (2, 3)
    assert g.k(np.linspace(0, 1, 7)).shape == (4, 7)
    assert np.asarray(g.k([0.1, 0.2])).shape == (4, 2)
    assert isinstance(g.k(pi / 3), tuple) and len(g.k(pi / 3)) == 4
    # θ = 0 straight down: k_n(0) = −C_n
    np.testing.assert_allclose(
        g.k(0.0), [1.5 + math.sqrt(3), 1.5, 1.5 - math.sqrt(3), 0.0], atol=1e-14
    )


def test_symbolic_grasp_refuses_numeric_theta():
    with pytest.raises(TypeError):
        Grasp.symbolic().k(0.3)


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_float_grasp_matches_exact(name):
    p = PRESET_PARAMS[name]
    gf = Grasp(
        *[float(v) for v in (p.x1, p.x2, p.y, p.phi1, p.phi2)], mu1=float(p.mu1), mu2=float(p.mu2)
    )
    ge = Grasp.preset(name)
    assert gf.numeric and not ge.numeric
    for Vf, Ve in zip(gf.V, ge.V):
        assert abs(float(Vf.x) - float(Ve.x)) < 1e-12
        assert abs(float(Vf.y) - float(Ve.y)) < 1e-12
    ts = np.linspace(-np.pi, 3 * np.pi, 101)
    np.testing.assert_allclose(gf.k(ts), ge.k(ts), atol=1e-12)
    np.testing.assert_allclose(gf.k_grasp(ts), ge.k_grasp(ts), atol=1e-12)


# ---------------------------------------------------------------------------
# exactness
# ---------------------------------------------------------------------------
def _floats_in(g: Grasp) -> set:
    out = set()
    for e in (*g.S, *g.C, *(c for V in g.V for c in V)):
        out |= e.atoms(sp.Float)
    return out


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_exact_inputs_stay_exact(name):
    g = Grasp.preset(name)
    assert not g.numeric
    assert _floats_in(g) == set()
    for e in (*g.k(pi / 7), g.k_grasp(pi / 7), g.internal_force(pi / 7, 3)):
        assert not e.atoms(sp.Float)


def test_fraction_and_text_inputs_exact():
    g = Grasp(Fraction(3, 2), 1, "1/3", "pi/2", "60deg", mu1="0.75", mu2=Fraction(5, 4))
    assert not g.numeric and _floats_in(g) == set()
    assert g.x1 == R(3, 2) and g.y == R(1, 3) and g.phi2 == pi / 3 and g.mu1 == R(3, 4)


def test_floats_select_numeric_path():
    g = Grasp(1.5, 1.0, 0.5, math.pi / 2, math.pi / 3, mu1=0.8, mu2=1.3)
    assert g.numeric
    assert all(isinstance(v, np.ndarray) for v in (g.k(np.array([0.1, 0.2])),))
    # one float anywhere is enough
    assert Grasp(2, 2, 1, "pi/2", "pi/2", mu1=1, mu2=1.2).numeric


# ---------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------
P = dict(x1=2, x2=2, y=1, phi1="pi/2", phi2="pi/2")
MU = dict(mu1=1, mu2=1)


def _args(**over):
    a = {**P, **MU}
    a.update(over)
    return {k: v for k, v in a.items() if v is not None}


BAD = [
    # (kwargs, exception, substrings of the message)
    # x1 <= 0 or x2 <= 0 alone is a grasp (issue 13 §1); P1 must lie right of P2
    (_args(x1=-2), InvalidGraspError, ["x1 + x2 = 0", "positive"]),
    (_args(x1=-3.5), InvalidGraspError, ["x1 + x2", "-1.5", "positive"]),
    (_args(x2="-11/4"), InvalidGraspError, ["x1 + x2 = -3/4", "positive"]),
    (_args(x2=-2.0), InvalidGraspError, ["x1 + x2", "positive"]),
    (_args(y="-1/2"), InvalidGraspError, ["y = -1/2", "non-negative"]),
    (_args(phi1=0), InvalidGraspError, ["contact 1", "φ1", "positive"]),
    (_args(phi1="-pi/4"), InvalidGraspError, ["contact 1", "φ1", "-0.25π"]),
    # 4/π = 1.273...
    (_args(phi2=4), InvalidGraspError, ["contact 2", "φ2", "exceed π"]),
    (_args(mu1=0), InvalidGraspError, ["contact 1", "μ1 = 0", "positive"]),
    (_args(mu2=-1), InvalidGraspError, ["contact 2", "μ2 = -1", "positive"]),
    (_args(mu1=None, xi1=0), InvalidGraspError, ["contact 1", "ξ1", "0 < ξ < π/2"]),
    (_args(mu2=None, xi2="pi/2"), InvalidGraspError, ["contact 2", "ξ2", "0.5π"]),
    (_args(mu2=None, xi2="2*pi/3"), InvalidGraspError, ["contact 2", "ξ2", "0.667π"]),
    (_args(xi1="pi/4"), InvalidGraspError, ["contact 1", "mu1", "xi1", "exactly one"]),
    (_args(mu2=None), InvalidGraspError, ["contact 2", "mu2", "xi2"]),
    # condition (1): φ − ξ < π/2 fails — φ1 = 5π/6, ξ1 = π/4: φ1 − ξ1 = 7π/12 ≈ 0.583π
    (
        _args(phi1="5*pi/6"),
        InvalidGraspError,
        ["contact 1", "φ1 − ξ1", "0.583π", "P2", "condition (1)"],
    ),
    # φ + ξ > π/2 fails — φ1 = π/6, ξ1 = π/4: φ1 + ξ1 = 5π/12 ≈ 0.417π
    (
        _args(phi1="pi/6"),
        InvalidGraspError,
        ["contact 1", "φ1 + ξ1", "0.417π", "P2", "condition (1)"],
    ),
    (_args(phi2="5*pi/6"), InvalidGraspError, ["contact 2", "φ2 − ξ2", "0.583π", "P1"]),
    (_args(phi2="pi/6"), InvalidGraspError, ["contact 2", "φ2 + ξ2", "0.417π", "P1"]),
    # boundaries of (1) are excluded (strict inequalities): φ + ξ = π/2, φ − ξ = π/2
    (_args(phi1="pi/4", mu1=1), InvalidGraspError, ["contact 1", "φ1 + ξ1", "0.5π"]),
    (_args(phi2="3*pi/4", mu2=1), InvalidGraspError, ["contact 2", "φ2 − ξ2", "0.5π"]),
    # non-numbers
    (_args(x1=True), InvalidGraspError, ["x1", "True"]),
    (_args(y=float("inf")), InvalidGraspError, ["y", "inf"]),
    (_args(x2=float("nan")), InvalidGraspError, ["x2", "nan"]),
    (_args(x1=sp.I), InvalidGraspError, ["x1", "I"]),
    (_args(mu1=[1]), InvalidGraspError, ["mu1", "[1]"]),
    # text
    (_args(x1="sqrt(3"), ExpressionError, ["sqrt(3"]),
    (_args(x1="__import__('os')"), ExpressionError, ["__import__"]),
    (_args(phi1="pi/2; import os"), ExpressionError, ["import os"]),
]


@pytest.mark.parametrize("kwargs,exc,words", BAD, ids=[str(i) for i in range(len(BAD))])
def test_bad_input(kwargs, exc, words):
    with pytest.raises(exc) as info:
        Grasp(**kwargs)
    assert isinstance(info.value, ValueError)
    msg = str(info.value)
    for w in words:
        assert w in msg, f"{w!r} not in {msg!r}"


def test_bad_input_is_value_error_subclass():
    assert issubclass(InvalidGraspError, ValueError)
    assert issubclass(graspcompass.ExpressionError, ValueError)


def test_good_input_does_not_raise():
    # the BAD cases above are single changes away from this valid grasp
    Grasp(**_args())
    Grasp(**_args(phi1="pi/4", mu1="1.01"))  # just inside (1)
    Grasp(**_args(y=0))  # y = 0 is allowed (y ≥ 0)
    Grasp(
        **_args(
            phi1="pi - 1/10",
            phi2="pi - 1/10",
            mu1=None,
            mu2=None,
            xi1="pi/2 - 1/100",
            xi2="pi/2 - 1/100",
        )
    )
    # φ = π is in the range of §2.2.1 but (1) then needs ξ > π/2: never valid
    with pytest.raises(InvalidGraspError, match="φ1 − ξ1"):
        Grasp(**_args(phi1="pi", mu1=None, xi1="pi/2 - 1/1000"))


def test_parse_error_names_parameter():
    with pytest.raises(ExpressionError) as info:
        Grasp(**_args(x2="sqrt(3"))
    assert "x2" in str(info.value)


def test_phi_too_large_message_shows_phi():
    with pytest.raises(InvalidGraspError) as info:
        Grasp(**_args(phi2=4))
    assert "φ2 = 1.27π" in str(info.value)  # 4/π = 1.273...


def test_tiny_positive_float_accepted():
    Grasp(1e-13, 1.0, 0.0, math.pi / 2, math.pi / 2, mu1=1.0, mu2=1.0)


def test_unknown_preset():
    with pytest.raises(InvalidGraspError, match="unknown preset 'fig7'"):
        Grasp.preset("fig7")
    with pytest.raises(InvalidGraspError, match="friction"):
        Grasp.symbolic("nu")


@given(
    phi=st.floats(min_value=1e-3, max_value=math.pi),
    xi=st.floats(min_value=1e-3, max_value=math.pi / 2 - 1e-3),
    contact=st.sampled_from([1, 2]),
)
@settings(max_examples=60, deadline=None, database=None)
def test_condition1_decides_validity(phi, xi, contact):
    """Valid iff |φ − π/2| < ξ: exactly condition (1) given 0 < φ ≤ π, 0 < ξ < π/2.

    The two outer inequalities of (1), φ − ξ > −π/2 and φ + ξ < 3π/2, are implied
    by the ranges of φ and ξ, so only the two inner ones can ever fail.
    """
    assume(abs(abs(phi - math.pi / 2) - xi) > 1e-9)
    ok = dict(phi="pi/2", xi="pi/4")
    a = {
        f"phi{contact}": phi,
        f"xi{contact}": xi,
        f"phi{3 - contact}": ok["phi"],
        f"xi{3 - contact}": ok["xi"],
    }
    valid = abs(phi - math.pi / 2) < xi
    assert phi - xi > -math.pi / 2 and phi + xi < 3 * math.pi / 2
    if valid:
        Grasp(1.0, 1.0, 0.5, **a)
    else:
        with pytest.raises(InvalidGraspError) as info:
            Grasp(1.0, 1.0, 0.5, **a)
        msg = str(info.value)
        assert f"contact {contact}" in msg and "condition (1)" in msg
        assert f"P{3 - contact}" in msg
        sign = "−" if phi > math.pi / 2 else "+"
        assert f"φ{contact} {sign} ξ{contact}" in msg


# ---------------------------------------------------------------------------
# symbolic grasps record condition (1) as assumptions
# ---------------------------------------------------------------------------
def _normal(rel) -> tuple:
    return type(rel), sp.expand(rel.lhs - rel.rhs)


@pytest.mark.parametrize("friction", ["xi", "mu"])
def test_symbolic_assumptions(friction):
    g = Grasp.symbolic(friction)  # must not raise
    phi = (gs.phi1, gs.phi2)
    xi = (gs.xi1, gs.xi2) if friction == "xi" else (sp.atan(gs.mu1), sp.atan(gs.mu2))
    have = {_normal(a) for a in g.assumptions if isinstance(a, sp.core.relational.Relational)}
    for i in (0, 1):
        p, x = phi[i], xi[i]
        for rel in (p - x > -pi / 2, p - x < pi / 2, p + x > pi / 2, p + x < 3 * pi / 2):
            rel_gt = (
                rel
                if isinstance(rel, sp.StrictGreaterThan)
                else sp.StrictGreaterThan(rel.rhs - rel.lhs, 0)
            )
            assert _normal(rel_gt) in have, f"{rel} not among the assumptions"
        assert _normal(pi - p >= 0) in have  # φ ≤ π
    assert not g.numeric
    # substituting Table I(a) gives the preset back
    h = Grasp.symbolic("mu").subs(
        {gs.x1: 2, gs.x2: 2, gs.y: 1, gs.phi1: pi / 2, gs.phi2: pi / 2, gs.mu1: 1, gs.mu2: R(6, 5)}
    )
    assert h.V == Grasp.preset("table1a").V


def test_symbolic_assumptions_are_not_tautologies():
    g = Grasp.symbolic("xi")
    assert all(a is not sp.true for a in g.assumptions)


def test_symbolic_V_closed_form():
    g = Grasp.symbolic("mu")
    S, C = closed_form_SC(gs.x1, gs.x2, gs.y, gs.phi1, gs.phi2, gs.mu1, gs.mu2)
    for n in range(4):
        assert sp.cancel(g.V[n].x - S[n]) == 0
        assert sp.cancel(g.V[n].y - C[n]) == 0


# ---------------------------------------------------------------------------
# hypothesis: random valid grasps
# ---------------------------------------------------------------------------
GRID = np.linspace(0, 2 * np.pi, 181)


@FAST
@given(float_params())
def test_random_k_grasp_properties(p):
    g = p.grasp()
    assert g.numeric
    ks = g.k(GRID)
    kg = g.k_grasp(GRID)
    assert ks.shape == (4, GRID.size) and kg.shape == GRID.shape
    tol = 1e-12 * (1 + np.abs(ks).max())
    assert (kg >= 0).all()
    assert (kg >= ks - tol).all()
    gap = np.min(np.abs(np.vstack([ks, np.zeros_like(GRID)]) - kg), axis=0)
    assert (gap <= tol).all()
    # independent: eqs. (18)-(21), μ form, with numpy
    kp = np.array(k_paper(GRID, *p.floats, lib=np))
    np.testing.assert_allclose(ks, kp, rtol=1e-9, atol=1e-9 * (1 + np.abs(kp).max()))
    np.testing.assert_allclose(
        kg, np.maximum(kp.max(axis=0), 0), rtol=1e-9, atol=1e-9 * (1 + np.abs(kp).max())
    )


@FAST
@given(float_params())
def test_random_k_antisymmetric_and_thales(p):
    g = p.grasp()
    ks, kpi = g.k(GRID), g.k(GRID + np.pi)
    scale = 1 + np.abs(ks).max()
    np.testing.assert_allclose(kpi, -ks, atol=1e-12 * scale)
    e = np.array([np.sin(GRID), -np.cos(GRID)])  # e(θ), eq. (26)
    for n, V in enumerate(g.V):
        v = np.array([float(V.x), float(V.y)])
        P = ks[n] * e  # polar point of k_n
        # Thales (31): P on the circle with diameter O V_n: (P − O)·(P − V_n) = 0
        dot = np.einsum("ij,ij->j", P, P - v[:, None])
        assert np.abs(dot).max() <= 1e-9 * scale**2
        # and equivalently |P − V_n/2| = |V_n|/2
        np.testing.assert_allclose(
            np.linalg.norm(P - v[:, None] / 2, axis=0), np.linalg.norm(v) / 2, atol=1e-9 * scale
        )


@FAST
@given(float_params())
def test_random_V_closed_form_and_section5(p):
    g = p.grasp()
    x1, x2, y, phi1, phi2, mu1, mu2 = p.floats
    S, C = closed_form_SC(x1, x2, y, phi1, phi2, mu1, mu2, lib=np)
    for n in range(4):
        scale = 1 + abs(S[n]) + abs(C[n])
        assert abs(float(g.V[n].x) - S[n]) <= 1e-9 * scale
        assert abs(float(g.V[n].y) - C[n]) <= 1e-9 * scale
    # §5: V1, V2 lie in y < 0 with V1 left of V2 whenever φ_i + ξ_i < π
    if p.phi1 + p.xi1 < math.pi - 1e-6 and p.phi2 + p.xi2 < math.pi - 1e-6:
        assert float(g.V[0].y) < 0 and float(g.V[1].y) < 0
        assert float(g.V[0].x) < float(g.V[1].x)
    # §5, Fig. 8: O_M inside the cone at P1  <=>  V3.x < 0;  inside the cone at P2  <=>  V4.x > 0
    if y > 1e-3:
        OM = np.array([(x1 - x2) / 2, 0.0])

        def inside(P, normal, xi):
            w = OM - P
            return float(w @ normal) / np.linalg.norm(w) - math.cos(xi)

        a1 = inside(np.array([x1, y]), np.array([-math.sin(phi1), -math.cos(phi1)]), p.xi1)
        a2 = inside(np.array([-x2, y]), np.array([math.sin(phi2), -math.cos(phi2)]), p.xi2)
        assume(abs(a1) > 1e-7 and abs(a2) > 1e-7)
        assert (a1 > 0) == (float(g.V[2].x) < 0)
        assert (a2 > 0) == (float(g.V[3].x) > 0)


@EXACT
@given(exact_params())
def test_random_exact_V_and_k(p):
    g = p.grasp()
    assert not g.numeric and _floats_in(g) == set()
    S, C = closed_form_SC(*p.seven)
    for n in range(4):
        assert is_zero(g.V[n].x - S[n]) and is_zero(g.V[n].y - C[n])
    theta = pi / 3
    for got, want in zip(g.k(theta), k_paper(theta, *p.seven)):
        assert is_zero(got - want)
    # k_n(θ + π) = −k_n(θ), exactly
    for a, b in zip(g.k(theta), g.k(theta + pi)):
        assert is_zero(a + b)


def test_vectorised_contact_forces_balance_and_bind():
    """F(θ, k_grasp) on an array of θ: L F = M (L from the moments, built here) and the
    tightest friction inequality of (8)-(11) is exactly met, the others hold."""
    g = Grasp.preset("table1c")
    t = np.linspace(0.0, 2 * np.pi, 181)
    k = g.k_grasp(t)
    F = g.contact_forces(t, k)
    assert F.shape == (4, t.size)
    x1, x2, y, mu1, mu2 = 2.0, 2.0, 2.0, 0.5, 1.4  # Table I(c), φ = π/2: n1 = (-1, 0), n2 = (1, 0)
    forces = [
        ((x1, y), (-1.0, 0.0)),
        ((x1, y), (0.0, 1.0)),
        ((-x2, y), (1.0, 0.0)),
        ((-x2, y), (0.0, 1.0)),
    ]
    L = np.array(
        [
            [f[0] for _, f in forces],
            [f[1] for _, f in forces],
            [p[0] * f[1] - p[1] * f[0] for p, f in forces],
        ]
    )
    assert np.abs(L @ F - np.vstack([-np.sin(t), np.cos(t), 0 * t])).max() < 1e-12
    ineq = np.vstack([mu1 * F[0] - F[1], mu2 * F[2] - F[3], mu1 * F[0] + F[1], mu2 * F[2] + F[3]])
    assert ineq.min() > -1e-12
    binding = k > 1e-9
    assert np.abs(ineq.min(axis=0)[binding]).max() < 1e-12


# -- an immutable value (issue 13 §1) ---------------------------------------------------


@pytest.mark.parametrize("field", ["x1", "y", "phi2", "mu1", "xi2", "s1", "title", "_SC", "new"])
def test_assignment_raises(field):
    """Before issue 13, ``g.x1 = 3`` was accepted and k_grasp kept its stale float cache."""
    g = Grasp.preset("table1a")
    before = g.k_grasp(0.3)
    with pytest.raises(graspcompass.grasp.FrozenGraspError, match="immutable"):
        setattr(g, field, 3)
    with pytest.raises(AttributeError):  # also a dataclasses.FrozenInstanceError
        delattr(g, field)
    assert g.k_grasp(0.3) == before and g == Grasp.preset("table1a")


def test_replace_gives_the_new_k_grasp():
    """replace() validates again and computes anew: k_1(0) = (x2 c - 0) tan(φ1 + ξ1) with
    φ1 = π/2 is x2·μ1-dependent only, so changing x2 changes k_grasp(0) (eq. (18))."""
    g = Grasp.preset("table1a")
    g.k_grasp(0.0)  # fill the float cache of the original
    h = g.replace(x2=3)
    # θ = 0, φ = π/2: k1 = -x2 tan(π/2 + ξ1) = x2/μ1, k2 = x1/μ2 (eqs. (18), (19))
    assert h.k_grasp(0) == 3 and g.k_grasp(0) == 2
    assert h.k_grasp(0.0) == pytest.approx(3.0) and g.k_grasp(0.0) == pytest.approx(2.0)
    assert (h.x2, g.x2) == (3, 2) and h != g
    assert g.replace(x2=2) == g and hash(g.replace()) == hash(g)


def test_replace_friction_forms_and_errors():
    g = Grasp.preset("fig6")  # friction given as ξ
    assert g.replace() == g  # ξ kept as given (not atan(tan ξ))
    h = g.replace(mu1=2)  # the pair of contact 1 switches to μ; contact 2 keeps ξ
    assert (h.mu1, h.xi1, h.xi2) == (2, sp.atan(2), pi / 3)
    with pytest.raises(InvalidGraspError, match="contact 1"):
        g.replace(mu1=-1)
    with pytest.raises(TypeError, match="unexpected field"):
        g.replace(z=1)
    f = Grasp(0.8, 1.1, 0.4, 1.2, 1.4, xi1=0.5, mu2=0.7)
    assert f.replace() == f and f.replace(y=0.5).y == 0.5


def test_frozen_grasp_copies_and_pickles():
    import copy
    import pickle

    g = Grasp.preset("table1c")
    g.k_grasp(0.1)
    for c in (pickle.loads(pickle.dumps(g)), copy.deepcopy(g), copy.copy(g)):
        assert c == g and c.k_grasp(0.1) == g.k_grasp(0.1)
        with pytest.raises(AttributeError):
            c.x1 = 1
