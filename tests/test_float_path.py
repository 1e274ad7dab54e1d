"""The float path (issue 9): envelope, k_grasp and refusals near condition (1).

Python floats select the numeric path.  Every expected value here comes from an
independent derivation inside the test:

* the closed form (28)-(39) re-typed in ``conftest.py`` (:func:`closed_form_SC`),
  evaluated with mpmath at 50 digits on the exact binary values of the floats;
* a linear program over the contact forces (``lp_k``): minimise k subject to the
  friction inequalities (8)-(11) with F = F_T + k F_N (eq. (16)), F_T and F_N
  written out from eqs. (13), (15);
* geometry: a break point of the envelope lies on both of its circles (Thales).

The accuracy promised (see the module docstrings of ``graspcompass.grasp`` and
``graspcompass.construction.envelope``): ``k_grasp`` of a float grasp is the
correctly evaluated closed form (error ~1e-15 max|V_n|); the diagram's V_n carry
a relative error ~ε/|cos(φ ± ξ)| from the float construction; the envelope equals
max(k_1..k_4, 0) of its own V_n to ~1e-13 max|V_n|.  A float grasp whose margin
in condition (1) is below 1e-12 of the bound is refused with InvalidGraspError.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from conftest import closed_form_SC, is_zero
from graspcompass import Grasp, Point, internal_force_diagram
from graspcompass.grasp import InvalidGraspError

EPS = 2.0**-52
#: The refusal threshold of condition (1), relative to the bound (π/2 or 3π/2).
REL_MARGIN = 1e-12
HALF_PI = math.pi / 2


# ---------------------------------------------------------------------------
# references written from the paper
# ---------------------------------------------------------------------------
def mp(v) -> mpmath.mpf:
    """The exact binary value of a float (or an exact sympy number) as an mpf."""
    return mpmath.mpf(sp.Float(v, 60) if isinstance(v, float) else sp.N(v, 60))


def ref_SC(x1, x2, y, phi1, phi2, mu1, mu2) -> tuple[np.ndarray, np.ndarray]:
    """S_n, C_n of eqs. (28)-(39) at 50 digits, rounded once to double."""
    with mpmath.workdps(50):
        S, C = closed_form_SC(*(mp(v) for v in (x1, x2, y, phi1, phi2, mu1, mu2)), lib=mpmath)
        return np.array([float(s) for s in S]), np.array([float(c) for c in C])


def ref_k(S, C, theta) -> np.ndarray:
    t = np.asarray(theta, dtype=float)
    ks = np.array([S[n] * np.sin(t) - C[n] * np.cos(t) for n in range(4)])
    return np.maximum(ks.max(axis=0), 0.0)


def side_angles(phi1, phi2, mu1, mu2) -> dict[int, mpmath.mpf]:
    """φ_i ± ξ_i (n = 1, 2 upper; 3, 4 lower) at 50 digits, ξ = atan μ (22)."""
    with mpmath.workdps(50):
        xi1, xi2 = mpmath.atan(mp(mu1)), mpmath.atan(mp(mu2))
        return {1: mp(phi1) + xi1, 2: mp(phi2) + xi2, 3: mp(phi1) - xi1, 4: mp(phi2) - xi2}


def rel_margin(phi1, phi2, mu1, mu2) -> float:
    """Smallest margin of condition (1), relative to its bound (−π/2, π/2 or 3π/2)."""
    out = math.inf
    with mpmath.workdps(50):
        pi = mpmath.pi
        for n, a in side_angles(phi1, phi2, mu1, mu2).items():
            bounds = (
                ((pi / 2, 1), (3 * pi / 2, -1)) if n in (1, 2) else ((-pi / 2, 1), (pi / 2, -1))
            )
            for b, sg in bounds:
                out = min(out, float(sg * (a - b) / abs(b)))
    return out


def min_cos(phi1, phi2, mu1, mu2) -> float:
    """min |cos(φ ± ξ)| over the four cone sides: X_n, Y_n scale like its inverse."""
    with mpmath.workdps(50):
        return min(float(abs(mpmath.cos(a))) for a in side_angles(phi1, phi2, mu1, mu2).values())


def lp_k(x1, x2, y, phi1, phi2, mu1, mu2, theta) -> float:
    """Least k with F = F_T + k F_N (16) inside the friction cones (8)-(11), k ≥ 0.

    F_T (13) and F_N (15) are written out here (F_e = 1); scaled by 2D so that
    the constraint rows are O(1).  The variable is k alone.
    """
    s, c = math.sin(theta), math.cos(theta)
    s1, c1, s2, c2 = math.sin(phi1), math.cos(phi1), math.sin(phi2), math.cos(phi2)
    D = x1 + x2
    a, b = y * s - x2 * c, y * s + x1 * c
    FT = np.array(
        [
            D * s1 * s + 2 * a * c1,
            D * c1 * s - 2 * a * s1,
            -D * s2 * s - 2 * b * c2,
            -D * c2 * s + 2 * b * s2,
        ]
    ) / (2 * D)
    FN = np.array([s1, c1, s2, c2]) / D
    rows = [(mu1, -1, 0, 0), (mu1, 1, 0, 0), (0, 0, mu2, -1), (0, 0, mu2, 1)]  # (8)-(11)
    G = np.array(rows, dtype=float)
    # G (F_T + k F_N) >= 0  <=>  -(G F_N) k <= G F_T; each row scaled to a unit
    # coefficient of k, since HiGHS drops matrix entries below 1e-9 (near-horizontal
    # cone sides make G F_N ~ cos(φ ± ξ) tiny)
    a, b = -(G @ FN), G @ FT
    w = np.where(a != 0, 1 / np.maximum(np.abs(a), 1e-300), 1.0)
    res = linprog(
        [1.0],
        A_ub=(a * w)[:, None],
        b_ub=b * w,
        bounds=[(0, None)],
        method="highs",
        options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10},
    )
    # (HiGHS's default feasibility tolerance, 1e-7 absolute, was the larger error: it made
    # the LP, not k_grasp, miss the 50-digit value by 1.9e-8 on a near-degenerate grasp)
    assert res.status == 0, res.message
    return float(res.x[0])


# ---------------------------------------------------------------------------
# building grasps with a chosen cone side
# ---------------------------------------------------------------------------
def contact_with_side(a: float, upper: bool, u: float) -> tuple[float, float] | None:
    """(φ, ξ) whose upper (φ + ξ) or lower (φ − ξ) side has the angle ``a``.

    ``u`` in (0, 1) picks ξ inside the interval that keeps 0 < φ ≤ π, 0 < ξ < π/2
    and the other side inside condition (1).
    """
    if upper:
        lo = max(0.0, a - math.pi, (a - HALF_PI) / 2)
        hi = min(HALF_PI, a, (a + HALF_PI) / 2)
    else:
        lo = max(0.0, -a, (HALF_PI - a) / 2)
        hi = min(HALF_PI, math.pi - a, (3 * HALF_PI - a) / 2)
    if hi - lo < 1e-3:
        return None
    xi = lo + (hi - lo) * u
    return (a - xi if upper else a + xi), xi


def through_origin(x: float, y: float, upper: bool) -> float:
    """Angle of the cone side at a contact |x| from the y-axis that passes through O.

    Then V_n ≈ V_m for sides of both contacts through O: near-coincident circles.
    """
    return math.atan(x / y) + (math.pi if upper else 0.0)


def near_coincident(x1, x2, y, n, m, d1, d2, u1=0.5, u2=0.5) -> dict:
    """Float grasp with V_n ≈ V_m (n at P1, m at P2): both sides nearly through O."""
    c1 = contact_with_side(through_origin(x1, y, n == 1) + d1, n == 1, u1)
    c2 = contact_with_side(through_origin(x2, y, m == 2) + d2, m == 2, u2)
    assert c1 and c2
    return dict(x1=x1, x2=x2, y=y, phi1=c1[0], phi2=c2[0], mu1=math.tan(c1[1]), mu2=math.tan(c2[1]))


def seven(kw: dict) -> tuple:
    """``(x1, x2, y, phi1, phi2, mu1, mu2)``; a float ξ gives μ = tan ξ correctly rounded
    (22), computed here at 40 digits (``math.tan`` may be an ulp off)."""
    with mpmath.workdps(40):
        mu = [
            kw[f"mu{i}"] if f"mu{i}" in kw else float(mpmath.tan(mpmath.mpf(kw[f"xi{i}"])))
            for i in (1, 2)
        ]
    return (*(kw[k] for k in ("x1", "x2", "y", "phi1", "phi2")), *mu)


# ---------------------------------------------------------------------------
# the checks
# ---------------------------------------------------------------------------
def check_envelope(env, S, C, tol: float, exact: bool = False) -> None:
    """Arcs: a partition of the circle in increasing θ; k = max(k_n, 0); points on circles."""
    arcs = env.arcs
    Vf = [(float(v.x), float(v.y)) for v in env.V]
    scale = max(math.hypot(*v) for v in Vf)
    assert arcs and 0.0 <= float(arcs[0].theta_start) < 2 * math.pi
    for i, a in enumerate(arcs):
        b = arcs[(i + 1) % len(arcs)]
        t0, t1 = float(a.theta_start), float(a.theta_end)
        assert t1 > t0, f"arc {i} (circle {a.n}) runs backwards: {t0} -> {t1}"
        assert a.n != b.n or len(arcs) == 1
        assert a.end == b.start
        shift = 2 * math.pi if i == len(arcs) - 1 else 0.0
        assert abs(float(b.theta_start) + shift - t1) <= 1e-15 * (1 + t1)
        if exact:
            assert not (
                a.theta_start.atoms(sp.Float)
                or a.start.x.atoms(sp.Float)
                or a.start.y.atoms(sp.Float)
            )
        for q, t in ((a.start, t0), (a.end, t1)):
            qx, qy = float(q.x), float(q.y)
            if a.n == 0:
                assert q == Point(0, 0)
                continue
            # on its circle (Thales: (q - V/2)² = |V|²/4, i.e. q·(q - V) = 0) ...
            vx, vy = Vf[a.n - 1]
            assert abs(qx * (qx - vx) + qy * (qy - vy)) <= tol * scale
            # ... and the polar point of the envelope at its own angle
            k = float(env.k(t))
            assert math.hypot(qx - k * math.sin(t), qy + k * math.cos(t)) <= tol * scale
    assert abs(sum(float(a.theta_end) - float(a.theta_start) for a in arcs) - 2 * math.pi) < 1e-13
    # k from the envelope against max(k_n, 0) of the reference S, C, densely and
    # right at and beside every break angle
    brk = np.array([float(a.theta_start) for a in arcs])
    ts = np.concatenate(
        [np.linspace(0, 2 * np.pi, 4001), brk, brk + 1e-9, brk - 1e-9, brk + 1e-5, brk - 1e-5]
    )
    err = np.abs(env.k(ts) - ref_k(S, C, ts)).max()
    assert err <= tol * max(scale, np.hypot(S, C).max()), err


def construction_tol(kw: dict) -> float:
    """Relative accuracy of the float construction's V_n (stated: 8 ε / min|cos(φ ± ξ)|)."""
    return 1e-12 + 8 * EPS / min_cos(*seven(kw)[3:])


def check_float_grasp(kw: dict, lp_thetas: int = 6) -> None:
    g = Grasp(**kw)
    S, C = ref_SC(*seven(kw))
    Vmax = np.hypot(S, C).max()
    ts = np.linspace(0, 2 * np.pi, 361) + 0.001
    # k_grasp: the correctly evaluated closed form (25)
    kg = g.k_grasp(ts)
    assert np.abs(kg - ref_k(S, C, ts)).max() <= 1e-14 * Vmax
    # one float equals the array path
    for t in ts[::37]:
        assert abs(g.k_grasp(float(t)) - float(g.k_grasp(np.array([t]))[0])) <= 4 * EPS * Vmax
    assert np.allclose(
        g.internal_force(ts, 2.0), kg * 2.0 / (kw["x1"] + kw["x2"]), rtol=1e-15, atol=0
    )
    # the diagram: V_n of the construction within the stated accuracy, envelope = max
    c = internal_force_diagram(g)
    rel = construction_tol(kw)
    for n in range(4):
        v = c[f"V{n + 1}"]
        assert math.hypot(float(v.x) - S[n], float(v.y) - C[n]) <= rel * Vmax
    check_envelope(c["envelope"], S, C, tol=max(rel, 1e-12))
    # the linear program agrees with k_grasp
    for t in np.linspace(0.05, 2 * np.pi, lp_thetas, endpoint=False):
        k_lp = lp_k(*seven(kw), t)
        assert abs(k_lp - g.k_grasp(float(t))) <= 1e-8 * Vmax + rel * Vmax, (t, k_lp)


# ---------------------------------------------------------------------------
# 1. near-coincident circles
# ---------------------------------------------------------------------------
# found by random search: V1 ≈ V4, the envelope had an arc running backwards and
# Envelope.k off by 0.41 max|V_n|
REGRESSION_V1_V4 = dict(
    x1=0.8358528337625843,
    x2=2.162177197102839,
    y=2.0822357550356916,
    phi1=2.0237687676253833,
    phi2=2.351784987079755,
    xi1=1.4995545279798408,
    xi2=1.5475545394058174,
)


def test_regression_near_coincident_v1_v4():
    kw = dict(REGRESSION_V1_V4)
    S, C = ref_SC(*seven(kw))
    assert math.hypot(S[0] - S[3], C[0] - C[3]) < 1e-12 * np.hypot(S, C).max()
    check_float_grasp(kw)


@pytest.mark.parametrize("n,m", [(1, 2), (1, 4), (3, 2), (3, 4)])
@pytest.mark.parametrize("d", [0.0, 1e-16, 1e-13, -1e-10, 1e-7])
def test_near_coincident_circles(n, m, d):
    kw = near_coincident(1.0, 2.0, 1.0, n, m, d, -d / 3, 0.3, 0.6)
    S, C = ref_SC(*seven(kw))
    gap = math.hypot(S[n - 1] - S[m - 1], C[n - 1] - C[m - 1])
    assert gap < 1e-6 * np.hypot(S, C).max()
    check_float_grasp(kw, lp_thetas=3)


def test_near_coincident_exact_path():
    """Exact grasp with |V3 − V4| = O(1e-10): exact break points, right envelope."""
    # φ = π/2: tan(π/2 − ξ) = 1/μ; lower sides through O when 1/μ1 = x1/y, 1/μ2 = x2/y
    mu1, mu2 = sp.Integer(1) + sp.Rational(1, 10**10), sp.Rational(1, 2)
    g = Grasp("1", "2", "1", "pi/2", "pi/2", mu1=mu1, mu2=mu2)
    S, C = ref_SC(1, 2, 1, sp.pi / 2, sp.pi / 2, mu1, mu2)
    assert 0 < math.hypot(S[2] - S[3], C[2] - C[3]) < 1e-9
    c = internal_force_diagram(g)
    check_envelope(c["envelope"], S, C, tol=1e-13, exact=True)
    for a in c["envelope"].arcs:
        if a.n:
            assert is_zero(
                a.start.x * (a.start.x - c[f"V{a.n}"].x) + a.start.y * (a.start.y - c[f"V{a.n}"].y)
            )


# ---------------------------------------------------------------------------
# 2. condition (1) within rounding: refused; just outside: numbers with an accuracy
# ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    "case",
    [
        dict(phi1=HALF_PI, xi1=1e-15),  # φ1 − ξ1 ≈ π/2, φ1 + ξ1 ≈ π/2
        dict(phi1=1.0, xi1=HALF_PI - 1.0 + 1e-15),  # φ1 + ξ1 = π/2 + 1e-15
        dict(phi1=1.0, mu1=math.tan(HALF_PI - 1.0 + 1e-13)),  # side 1 within 1e-13 rad
        dict(phi1=1.0, mu1=math.tan(HALF_PI - 1.0 + 4e-16)),
        dict(phi1=2.5, xi1=2.5 - HALF_PI + 1e-14),  # φ1 − ξ1 = π/2 − 1e-14
        dict(phi1=0.2, mu1=math.tan(HALF_PI - 0.2 + 1e-13)),
        dict(phi1=2.0, mu1=math.tan(2.0 - HALF_PI + 5e-13)),  # φ1 − ξ1 = π/2 − 5e-13
    ],
)
def test_within_rounding_of_condition_1_is_refused(case):
    kw = dict(x1=1.0, x2=1.0, y=1.0, phi2=HALF_PI, xi2=0.7, **case)
    with pytest.raises(InvalidGraspError) as info:
        internal_force_diagram(Grasp(**kw))
    msg = str(info.value)
    assert "contact 1" in msg and "condition (1)" in msg
    assert "pi/2" in msg  # suggests exact input
    assert any(s in msg for s in ("φ1 + ξ1", "φ1 − ξ1"))


@pytest.mark.parametrize(
    "case",
    [
        dict(phi1=1.0, xi1=HALF_PI - 1.0),  # π/2 typed as a float sum
        dict(phi1=HALF_PI, xi1=1e-17),
        dict(phi1=1.0, mu1=math.tan(HALF_PI - 1.0)),
    ],
)
def test_half_ulp_from_condition_1_suggests_exact_input(case):
    kw = dict(x1=1.0, x2=1.0, y=1.0, phi2=HALF_PI, xi2=0.7, **case)
    with pytest.raises(InvalidGraspError, match=r"within rounding.*pi/2"):
        Grasp(**kw)


@pytest.mark.parametrize("margin", [1e-11, 1e-9, 1e-6])
@pytest.mark.parametrize("which", ["up-low", "low-high"])
def test_just_outside_threshold_agrees_with_exact(margin, which):
    # the bounds −π/2 and 3π/2 never bind: with 0 < ξ < π/2 the margins to π/2 are smaller
    if which == "up-low":  # φ1 + ξ1 = π/2 + margin
        phi1, xi = 1.0, HALF_PI - 1.0 + margin
    else:  # φ1 − ξ1 = π/2 − margin
        phi1, xi = 2.0, 2.0 - HALF_PI + margin
    kw = dict(x1=1.0, x2=1.5, y=0.7, phi1=phi1, phi2=1.3, mu1=math.tan(xi), mu2=0.9)
    m = rel_margin(kw["phi1"], kw["phi2"], kw["mu1"], kw["mu2"])
    assert REL_MARGIN < m < 1e-5
    check_float_grasp(kw)
    # the same parameters, rationalised, through the exact path: same V_n
    g_exact = Grasp(
        *(sp.Rational(v) for v in seven(kw)[:5]),
        mu1=sp.Rational(kw["mu1"]),
        mu2=sp.Rational(kw["mu2"]),
    )
    cf = internal_force_diagram(Grasp(**kw))
    rel = construction_tol(kw)
    Vmax = max(math.hypot(float(v.x), float(v.y)) for v in g_exact.V)
    for n, ve in enumerate(g_exact.V, start=1):
        vf = cf[f"V{n}"]
        assert math.hypot(float(vf.x) - float(ve.x), float(vf.y) - float(ve.y)) <= rel * Vmax


@pytest.mark.parametrize("margin", [2e-12, 1e-9])
def test_float_construction_full_accuracy_near_condition_1(margin):
    kw = dict(
        x1=1.0, x2=1.5, y=0.7, phi1=1.0, phi2=1.3, mu1=math.tan(HALF_PI - 1.0 + margin), mu2=0.9
    )
    S, C = ref_SC(*seven(kw))
    c = internal_force_diagram(Grasp(**kw))
    for n in range(4):
        v = c[f"V{n + 1}"]
        assert math.hypot(float(v.x) - S[n], float(v.y) - C[n]) <= 1e-14 * np.hypot(S, C).max()


@pytest.mark.parametrize(
    "case",
    [
        dict(phi1=2 * math.pi / 3, xi1=math.pi / 3),  # φ1 + ξ1 = π: upper side vertical
        dict(phi1=math.pi / 3, xi1=math.pi / 3),  # φ1 − ξ1 = 0: lower side vertical
        dict(phi1=HALF_PI, xi1=HALF_PI * (1 - 1e-16)),  # both sides nearly vertical
    ],
)
def test_vertical_cone_sides(case):
    kw = dict(x1=1.0, x2=1.0, y=1.0, phi2=HALF_PI, xi2=0.7, **case)
    check_float_grasp(kw)


def test_vertical_cone_side_exact_path():
    g = Grasp("1", "1", "1", "2*pi/3", "pi/2", xi1="pi/3", xi2="pi/4")
    S, C = ref_SC(1, 1, 1, 2 * sp.pi / 3, sp.pi / 2, sp.sqrt(3), 1)
    assert abs(C[0]) < 1e-15  # tan(π) = 0
    c = internal_force_diagram(g)
    check_envelope(c["envelope"], S, C, tol=1e-13, exact=True)


# ---------------------------------------------------------------------------
# 3. random grasps: envelope, k_grasp, closed form and LP agree, or a clear refusal
# ---------------------------------------------------------------------------
@st.composite
def hard_float_grasps(draw) -> dict:
    kind = draw(st.sampled_from(["coincident", "vertical", "horizontal", "generic"]))
    x1, x2 = draw(st.floats(0.2, 3.0)), draw(st.floats(0.2, 3.0))
    y = draw(st.floats(0.1, 3.0))
    u1, u2 = draw(st.floats(0.05, 0.95)), draw(st.floats(0.05, 0.95))
    up1, up2 = draw(st.booleans()), draw(st.booleans())
    tiny = st.sampled_from([0.0, 1e-16, -1e-16, 1e-14, -1e-12, 1e-10, -1e-8])
    if kind == "coincident":
        return (
            near_coincident(
                x1, x2, y, 1 if up1 else 3, 2 if up2 else 4, draw(tiny), draw(tiny), u1, u2
            )
            if contact_with_side(through_origin(x1, y, up1), up1, u1)
            and contact_with_side(through_origin(x2, y, up2), up2, u2)
            else {}
        )
    if kind == "vertical":
        a1 = (math.pi if up1 else 0.0) + draw(tiny)
        a2 = draw(st.floats(-1.4, 1.4)) + (math.pi if up2 else 0.0)
    elif kind == "horizontal":
        margin = 10.0 ** draw(st.floats(-16.5, -4.0)) * draw(st.sampled_from([1, 1, 1, -1]))
        low, high = (HALF_PI, 3 * HALF_PI) if up1 else (-HALF_PI, HALF_PI)
        a1 = low + margin if draw(st.booleans()) else high - margin
        a2 = draw(st.floats(-1.4, 1.4)) + (math.pi if up2 else 0.0)
    else:
        a1 = draw(st.floats(-1.4, 1.4)) + (math.pi if up1 else 0.0)
        a2 = draw(st.floats(-1.4, 1.4)) + (math.pi if up2 else 0.0)
    c1, c2 = contact_with_side(a1, up1, u1), contact_with_side(a2, up2, u2)
    if not (c1 and c2):
        return {}
    if draw(st.booleans()):  # friction by the cone half angle ξ (22)
        return dict(x1=x1, x2=x2, y=y, phi1=c1[0], phi2=c2[0], xi1=c1[1], xi2=c2[1])
    return dict(x1=x1, x2=x2, y=y, phi1=c1[0], phi2=c2[0], mu1=math.tan(c1[1]), mu2=math.tan(c2[1]))


@settings(
    max_examples=60,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(hard_float_grasps())
def test_random_hard_float_grasps(kw):
    assume(kw)
    m = rel_margin(*seven(kw)[3:])
    assume(0 < kw["phi1"] <= math.pi and 0 < kw["phi2"] <= math.pi)
    if m <= REL_MARGIN * (1 - 1e-6):
        with pytest.raises(InvalidGraspError, match="condition \\(1\\)"):
            Grasp(**kw)
        return
    assume(m > REL_MARGIN * (1 + 1e-6))
    check_float_grasp(kw, lp_thetas=4)


@settings(max_examples=200, deadline=None)
@given(xi=st.floats(1e-6, math.pi / 2 - 1e-6))
def test_float_xi_gives_the_correctly_rounded_mu(xi: float) -> None:
    """μ = tan ξ (22) rounded once: sympy's 53-bit tan was an ulp off for some ξ, and near a
    bound of condition (1) one ulp of μ moved k_grasp by 3e-10 of its size."""
    g = Grasp(1.0, 1.0, 0.5, math.pi / 2, math.pi / 2, xi1=xi, xi2=xi)
    with mpmath.workdps(60):
        want = float(mpmath.tan(mpmath.mpf(xi)))
    assert float(g.params["mu1"]) == want


def test_near_bound_float_grasp_from_xi() -> None:
    """The hypothesis find: φ1 + ξ1 within 4e-7 of π/2, |V1| ≈ 6.3e6."""
    check_float_grasp(
        {
            "x1": 1.0,
            "x2": 1.0,
            "y": 1.0,
            "phi1": 0.34926470093316486,
            "phi2": 1.1780972450961724,
            "xi1": 1.2215318503411545,
            "xi2": 1.1780972450961724,
        },
        lp_thetas=2,
    )
