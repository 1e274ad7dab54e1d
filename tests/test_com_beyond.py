"""The centre of mass beyond a contact (issue 13 §1): x1 <= 0 or x2 <= 0 with x1 + x2 > 0.

Why the model holds there: eqs. (12)-(16) are identities in x1, x2 (L F_T = M, L F_N = 0,
F_T · F_N = 0; det L L^T = 2 (x1 + x2)^2, checked symbolically below with real, unsigned
symbols); the coefficient of k in each of (8)-(11) is (μ_i s_i ∓ c_i)/(x1 + x2) times
F_e, positive by condition (1) whenever x1 + x2 > 0, so each is a lower limit k_n and
(18)-(25) follow; (27)-(39) rewrite them.  Here every expected k_grasp comes from the
linear program of tests/test_diagnosis.py (first principles: the null space of L as
the internal force, no closed form), and the construction is compared with the
closed form written out again from the paper (conftest.closed_form_SC).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import MARGIN, closed_form_SC, float_contact
from graspcompass import Grasp, InvalidGraspError, internal_force_diagram, place_grasp
from graspcompass import symbols as S
from graspcompass.proof.certify import certify
from test_diagnosis import check_against_lp, lp

R = sp.Rational


def test_equations_hold_without_signs_of_x1_x2():
    # sines and cosines as symbols, reduced modulo s² + c² − 1; x1, x2 real, no sign
    x1, x2, y, s1, c1, s2, c2, s, c = sp.symbols("x1 x2 y s1 c1 s2 c2 s c", real=True)
    L = sp.Matrix(
        [
            [-s1, -c1, s2, c2],
            [-c1, s1, -c2, s2],
            [-c1 * x1 + s1 * y, s1 * x1 + c1 * y, c2 * x2 - s2 * y, -s2 * x2 - c2 * y],
        ]
    )
    D = x1 + x2
    FT2D = sp.Matrix(
        [
            D * s1 * s + 2 * (y * s - x2 * c) * c1,
            D * c1 * s - 2 * (y * s - x2 * c) * s1,
            -D * s2 * s - 2 * (y * s + x1 * c) * c2,
            -D * c2 * s + 2 * (y * s + x1 * c) * s2,
        ]
    )  # 2 (x1 + x2) F_T, (13)
    FN = sp.Matrix([s1, c1, s2, c2])  # (x1 + x2) F_N, (15)
    circle = [s1**2 + c1**2 - 1, s2**2 + c2**2 - 1, s**2 + c**2 - 1]
    gens = (c1, c2, c, s1, s2, s, x1, x2, y)

    def zero(e):
        return sp.reduced(sp.expand(e), circle, *gens)[1] == 0

    assert all(zero(e) for e in L * FT2D - 2 * D * sp.Matrix([-s, c, 0]))  # L F_T = M
    assert all(zero(e) for e in L * FN)  # L F_N = 0
    assert zero((FT2D.T * FN)[0])  # F_T ⟂ F_N
    assert zero((L * L.T).det() - 2 * D**2)  # rank 3 exactly when x1 + x2 ≠ 0


@st.composite
def beyond_floats(draw) -> tuple[float, ...]:
    """``(x1, x2, y, φ1, φ2, μ1, μ2)`` floats with x1 <= 0 or x2 <= 0, x1 + x2 > 0."""
    D = draw(st.floats(0.2, 4.0))
    kind = draw(st.sampled_from(("x1=0", "x2=0", "x1<0", "x2<0")))
    u = draw(st.floats(0.0, 3.0))
    x1 = {"x1=0": 0.0, "x2=0": D, "x1<0": -u, "x2<0": D + u}[kind]
    x2 = {"x1=0": D, "x2=0": 0.0, "x1<0": D + u, "x2<0": -u}[kind]
    y = draw(st.one_of(st.just(0.0), st.floats(0.0, 3.0)))
    phi1, xi1 = draw(float_contact())
    phi2, xi2 = draw(float_contact())
    return x1, x2, y, phi1, phi2, math.tan(xi1), math.tan(xi2)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(p=beyond_floats(), theta=st.floats(0, 2 * math.pi))
def test_float_grasps_beyond_a_contact_match_lp(p, theta):
    g = Grasp(*p[:5], mu1=p[5], mu2=p[6])
    k_lp = lp(*p, theta)[0]
    scale = 1 + abs(k_lp)
    assert abs(g.k_grasp(theta) - k_lp) <= 1e-7 * scale
    assert abs(float(g.internal_force(theta)) - k_lp / (p[0] + p[1])) <= 1e-7 * scale / (
        p[0] + p[1]
    )
    check_against_lp(g, p, theta)  # and the slip diagnosis (which contact, which way)


def _exact_beyond(draw) -> Grasp:
    D = draw(st.fractions(R(1, 4), 4, max_denominator=8))
    u = draw(st.fractions(0, 3, max_denominator=8))
    swap = draw(st.booleans())
    x1, x2 = (-u, D + u) if not swap else (D + u, -u)
    y = draw(st.fractions(0, 3, max_denominator=8))
    phis = (sp.pi / 3, sp.pi / 2, 2 * sp.pi / 3)
    phi1, phi2 = draw(st.sampled_from(phis)), draw(st.sampled_from(phis))
    mus = []
    for phi in (phi1, phi2):
        lo = math.tan(abs(float(phi) - math.pi / 2) + MARGIN)
        mus.append(draw(st.fractions(math.ceil(lo * 8) / 8, 3, max_denominator=8)))
    return Grasp(str(x1), str(x2), str(y), phi1, phi2, mu1=str(mus[0]), mu2=str(mus[1]))


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_exact_grasps_beyond_construction_closed_form_lp(data):
    g = _exact_beyond(data.draw)
    assert g.x1 <= 0 or g.x2 <= 0
    c = internal_force_diagram(g)
    Sp, Cp = closed_form_SC(g.x1, g.x2, g.y, g.phi1, g.phi2, g.mu1, g.mu2)  # the paper's
    for n in (1, 2, 3, 4):
        assert c[f"V{n}"] == g.V[n - 1]  # the construction's V_n is the closed form
        for got, want in ((g.V[n - 1].x, Sp[n - 1]), (g.V[n - 1].y, Cp[n - 1])):
            assert abs(sp.N(got - want, 60)) < 1e-45
    floats = tuple(float(v) for v in (g.x1, g.x2, g.y, g.phi1, g.phi2, g.mu1, g.mu2))
    gf = Grasp(*floats[:5], mu1=floats[5], mu2=floats[6])
    thetas = np.linspace(0, 2 * np.pi, 13)[:-1] + 0.1
    exact_thetas = (R(1, 2), R(2), R(4))
    kx = np.array([float(g.k_grasp(t)) for t in exact_thetas])  # exact vs float
    assert np.allclose(
        kx, gf.k_grasp(np.array([float(t) for t in exact_thetas])), rtol=1e-12, atol=1e-12
    )
    assert np.allclose(g.k_grasp(thetas), gf.k_grasp(thetas), rtol=1e-12, atol=1e-12)
    env = c["envelope"]
    assert np.allclose(env.k(thetas), g.k_grasp(thetas), rtol=1e-12, atol=1e-12)
    for t in thetas:
        k_lp = lp(*floats, float(t))[0]
        assert abs(gf.k_grasp(float(t)) - k_lp) <= 1e-7 * (1 + abs(k_lp))


def test_x1_zero_exactly():
    # P1 straight above O: P1x = O, and the perpendiculars from P1x (steps for V2, V4)
    # pass through O, so Y2 = Y4 = O and C2 = C4 = x1 tan(φ2 ± ξ2) = 0
    g = Grasp(0, 2, 1, "pi/2", "pi/2", mu1=1, mu2="6/5")
    c = internal_force_diagram(g)
    assert c["P1x"] == c["O"] and c["Y2"] == c["O"] and c["Y4"] == c["O"]
    assert g.C[1] == 0 and g.C[3] == 0
    assert [c[f"V{n}"] for n in (1, 2, 3, 4)] == list(g.V)
    assert c["O_M"].x == -1  # midpoint of P1x = O and P2x = (-2, 0)
    # circles 2 and 4 (centres on the x-axis) touch at O: no second intersection
    assert "B24" in dict(c.skipped)
    for t in np.linspace(0.05, 6.2, 9):
        k_lp = lp(0.0, 2.0, 1.0, math.pi / 2, math.pi / 2, 1.0, 1.2, float(t))[0]
        assert abs(float(g.k_grasp(float(t))) - k_lp) <= 1e-8 * (1 + k_lp)


def test_x2_zero_on_the_line_identical_circles():
    # y = 0, x2 = 0: P2 = O; V1 = V3 = (-1, 0), one circle: both sides at P1 bind together
    from graspcompass.diagnosis import slip_intervals

    g = Grasp(2, 0, 0, "pi/2", "pi/2", mu1=1, mu2="6/5")
    assert g.V[0] == g.V[2]
    (iv,) = [iv for iv in slip_intervals(g) if iv.n == 1]
    assert iv.binding == (1, 3)


def test_certify_numeric_grasps_beyond_relies_on_no_hypothesis():
    # exact numbers: every fact is decided exactly for these values, with no hypothesis
    # (in particular not x1 > 0): PROVED is backed
    for g in (
        Grasp(-1, 3, 1, "pi/3", "pi/2", mu1=1, mu2="6/5"),
        Grasp(0, 2, 1, "pi/2", "pi/2", mu1=1, mu2="6/5"),
    ):
        certs = certify(internal_force_diagram(g))
        assert {x.result.status.value for x in certs} == {"GIVEN", "PROVED"}
        assert all(x.result.hypotheses == () for x in certs)
    # floats: NUMERIC, never PROVED
    certs = certify(internal_force_diagram(Grasp(-0.5, 2.5, 1.0, 1.4, 1.6, mu1=1.0, mu2=1.0)))
    assert "PROVED" not in {x.result.status.value for x in certs}


@pytest.mark.parametrize("x1", [-1, 0, R(-1, 2)])
def test_symbolic_grasps_keep_the_papers_domain(x1):
    # symbolic proofs state "domains of x1, x2 (§2.2)" (x1, x2 > 0) as hypotheses: a grasp
    # with symbols and x1 <= 0 would not meet them, so it is refused, not proved
    with pytest.raises(InvalidGraspError, match="grasp with symbols"):
        Grasp(x1, S.x2, S.y, S.phi1, S.phi2, mu1=S.mu1, mu2=S.mu2)
    with pytest.raises(InvalidGraspError, match="grasp with symbols"):
        Grasp(S.x1, x1, S.y, S.phi1, S.phi2, mu1=S.mu1, mu2=S.mu2)
    with pytest.raises(InvalidGraspError, match="grasp with symbols"):
        Grasp.symbolic("mu").subs({"x1": x1})


@pytest.mark.parametrize(("x1", "x2"), [(-2, 2), (0, 0), (1, "-1.5"), (-0.5, 0.25)])
def test_contacts_out_of_order_still_refused(x1, x2):
    with pytest.raises(InvalidGraspError, match=r"x1 \+ x2 = .* must be positive"):
        Grasp(x1, x2, 1, "pi/2", "pi/2", mu1=1, mu2=1)


def _world_check(wg, force):
    """The world contact forces balance the force and its moment about the centre of mass."""
    f = wg.contact_forces(force)
    com = [float(v) for v in wg.origin]
    tot = np.array(force, float) + sum(np.array([float(v) for v in fv]) for fv in f.values())
    mom = sum(
        (float(p[0]) - com[0]) * float(fv[1]) - (float(p[1]) - com[1]) * float(fv[0])
        for p, fv in zip(wg.contacts, (f[n] for n in wg.names))
    )
    assert np.abs(tot).max() < 1e-9 and abs(mom) < 1e-9


def test_place_grasp_with_the_centre_of_mass_beyond_a_contact():
    box = dict(contacts=[(2, 1), (-2, 1)], normals=[(-1, 0), (1, 0)], mu=(1, 1))
    wg = place_grasp(**box, com=(3, 0))  # beyond contact A: x1 = -1
    assert (wg.grasp.x1, wg.grasp.x2, wg.grasp.y) == (-1, 5, 1)
    _world_check(wg, (0, -1))
    wg = place_grasp(**box, com=(-2, 5))  # above contact B: x1 = 0 (frame turned)
    assert (wg.grasp.x1, wg.grasp.x2, wg.grasp.y) == (0, 4, 4)
    _world_check(wg, (0.3, -1))
    wf = place_grasp(
        contacts=[(2.0, 1.0), (-2.0, 1.0)],
        normals=[(-1.0, 0.0), (1.0, 0.0)],
        mu=(1.0, 1.0),
        com=(3.0, 0.0),
    )
    assert wf.grasp.numeric and math.isclose(float(wf.grasp.x1), -1.0)
    k_lp = lp(-1.0, 5.0, 1.0, math.pi / 2, math.pi / 2, 1.0, 1.0, 0.0)[0]
    assert math.isclose(float(wf.grasp.k_grasp(0.0)), k_lp, rel_tol=1e-9)


def test_drawing_beyond_a_contact():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from graspcompass.render import draw_construction

    for g in (
        Grasp(-1, 3, 1, "pi/3", "pi/2", mu1=1, mu2="6/5"),
        Grasp(0, 2, 0, "pi/2", "pi/2", mu1=1, mu2="6/5"),
    ):
        fig, ax = plt.subplots()
        artists = draw_construction(internal_force_diagram(g), ax=ax)
        assert artists
        plt.close(fig)
