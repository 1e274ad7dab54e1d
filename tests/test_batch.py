"""graspcompass.batch and the table path of Grasp.k_grasp (issue 13 §5 "Fast numeric path").

References: :class:`graspcompass.Grasp` (the float path rounds a 40-digit evaluation once)
and an independent mpmath evaluation of eqs. (28)-(39) at 50 digits written here.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, batch
from graspcompass.errors import InputError, NonFiniteValueError
from graspcompass.grasp import _envelope
from graspcompass.sizing import worst_squeeze_many

U = 2.0**-53
EPS = 2.0**-52
HALF_PI = math.pi / 2
DOCS = Path(__file__).resolve().parents[1] / "docs"


# -- references --------------------------------------------------------------------------------
def mp_closed_form(x1, x2, y, phi1, phi2, mu1, mu2, dps=50):
    """S_n, C_n, tan(φ ± ξ) and the μ form's pieces at ``dps`` digits (floats taken exactly)."""
    with mpmath.workdps(dps):
        x1, x2, y = mpmath.mpf(x1), mpmath.mpf(x2), mpmath.mpf(y)
        h = (x1 + x2) / 2
        S, C, T, parts = [], [], [], []
        for n in (1, 2, 3, 4):
            phi, mu = (phi1, mu1) if n in (1, 3) else (phi2, mu2)
            s, c, mu = mpmath.sin(mpmath.mpf(phi)), mpmath.cos(mpmath.mpf(phi)), mpmath.mpf(mu)
            sg = 1 if n in (1, 2) else -1
            num, den = s + sg * mu * c, c - sg * mu * s
            t = num / den
            S.append(-h + y * t if n in (1, 3) else h - y * t)
            C.append((x2 if n in (1, 3) else x1) * t)
            T.append(t)
            parts.append((abs(s) + mu * abs(c), abs(c) + mu * abs(s), abs(num), abs(den)))
        return S, C, T, parts


def stated_bound(p, S, C, T, parts):
    """The error bound of the batch module's docstring, per n, for S and for C."""
    x1, x2, y = p[0], p[1], p[2]
    h = abs(x1 + x2) / 2
    out = []
    for n in range(4):
        a, b, num, den = (float(v) for v in parts[n])
        t = float(abs(T[n]))
        dt = 4 * U * t * (1 + a / num + b / den)
        x = x2 if n in (0, 2) else x1
        out.append(
            (abs(y) * dt + 2 * U * (abs(float(S[n])) + h), abs(x) * dt + U * abs(float(C[n])))
        )
    return out


def np_relative_bound(x1, x2, y, phi1, phi2, mu1, mu2):
    """The stated bound on the error of max_n |V_n|, relative to it, vectorised (numpy)."""
    err = np.zeros(np.shape(x1))
    vmax = np.zeros(np.shape(x1))
    h = np.abs(x1 + x2) / 2
    for n in (1, 2, 3, 4):
        phi, mu, x = (phi1, mu1, x2) if n in (1, 3) else (phi2, mu2, x1)
        s, c = np.sin(phi), np.cos(phi)
        sg = 1 if n in (1, 2) else -1
        num, den = s + sg * mu * c, c - sg * mu * s
        t = num / den
        dt = (
            4
            * U
            * np.abs(t)
            * (
                1
                + (np.abs(s) + mu * np.abs(c)) / np.abs(num)
                + (np.abs(c) + mu * np.abs(s)) / np.abs(den)
            )
        )
        S, C = (y * t - h if n in (1, 3) else h - y * t), x * t
        err = np.maximum(
            err, np.abs(y) * dt + 2 * U * (np.abs(S) + h) + np.abs(x) * dt + U * np.abs(C)
        )
        vmax = np.maximum(vmax, np.hypot(S, C))
    return err / vmax


# -- random valid grasps, some within 1e-11 of a bound of condition (1) ---------------------
@st.composite
def contact(draw):
    """(φ, μ) inside condition (1): generic, or φ ± ξ within δ of π/2."""
    kind = draw(st.sampled_from(["generic", "upper", "lower", "parallel"]))
    if kind == "parallel":
        return HALF_PI, draw(st.floats(0.01, 3.0))
    if kind == "generic":
        phi = draw(st.floats(0.2, math.pi - 0.2))
        lo = abs(phi - HALF_PI) + 1e-3
        xi = draw(st.floats(lo, HALF_PI - 1e-3)) if lo < HALF_PI - 1e-3 else HALF_PI - 5e-4
        return phi, math.tan(xi)
    delta = 10.0 ** draw(st.floats(-11, -2))
    if kind == "upper":  # φ + ξ = π/2 + δ: the upper side nearly horizontal
        phi = draw(st.floats(0.05, HALF_PI - 0.05))
        return phi, math.tan(HALF_PI + delta - phi)
    phi = draw(st.floats(HALF_PI + 0.05, math.pi - 0.05))  # φ − ξ = π/2 − δ
    return phi, math.tan(phi - HALF_PI + delta)


@st.composite
def grasps(draw):
    x1 = draw(st.floats(0.01, 5.0))
    x2 = draw(st.floats(-0.5 * x1, 5.0))  # the centre of mass may lie beyond a contact
    y = draw(st.sampled_from([0.0, draw(st.floats(0.0, 5.0))]))
    (phi1, mu1), (phi2, mu2) = draw(contact()), draw(contact())
    return (x1, x2, y, phi1, phi2, mu1, mu2)


# -- the closed form against mpmath and Grasp ------------------------------------------------
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(grasps())
def test_closed_form_within_the_stated_bound_of_mpmath_and_grasp(p):
    if not bool(batch.valid(*p, margin=2e-12)):  # μ = tan ξ rounded: a hair outside
        return
    S, C = batch.closed_form(*p)
    Sm, Cm, T, parts = mp_closed_form(*p)
    bound = stated_bound(p, Sm, Cm, T, parts)
    Sg, Cg = Grasp(*p[:5], mu1=p[5], mu2=p[6])._floats()  # correct to one ulp
    for n in range(4):
        bS, bC = bound[n]
        assert abs(float(S[n]) - float(Sm[n])) <= bS, (n, p)
        assert abs(float(C[n]) - float(Cm[n])) <= bC, (n, p)
        assert abs(S[n] - Sg[n]) <= bS + U * abs(Sg[n]), (n, p)
        assert abs(C[n] - Cg[n]) <= bC + U * abs(Cg[n]), (n, p)


@settings(max_examples=40, deadline=None)
@given(grasps(), st.lists(st.floats(-10.0, 10.0), min_size=1, max_size=8))
def test_k_and_k_grasp_equal_grasp(p, thetas):
    if not bool(batch.valid(*p, margin=2e-12)):
        return
    g = Grasp(*p[:5], mu1=p[5], mu2=p[6])
    t = np.array(thetas)
    Sm, Cm, T, parts = mp_closed_form(*p)
    vmax = max(math.hypot(float(a), float(b)) for a, b in zip(Sm, Cm))
    err = max(b for pair in stated_bound(p, Sm, Cm, T, parts) for b in pair) + 4 * EPS * vmax
    kb = batch.k(t, *p)  # (len(t), 4)
    np.testing.assert_allclose(kb, g.k(t).T, rtol=0, atol=2 * err)
    np.testing.assert_allclose(batch.k_grasp(t, *p), g.k_grasp(t), rtol=0, atol=2 * err)
    fe = 2.5
    np.testing.assert_allclose(
        batch.internal_force(t, *p, fe),
        g.internal_force(t, fe),
        rtol=0,
        atol=2 * err * fe / (p[0] + p[1]),
    )


def test_worst_squeeze_equals_the_sizing_module_and_grasp():
    rng = np.random.default_rng(5)
    n = 50_000  # above the block length: the numpy blocks are exercised
    x1, x2, y = rng.uniform(0.01, 0.1, n), rng.uniform(0.01, 0.1, n), rng.uniform(0, 0.05, n)
    phi1, phi2 = rng.uniform(1.4, 1.75, (2, n))
    mu1, mu2 = rng.uniform(0.4, 1.0, (2, n))
    mass = rng.uniform(0.1, 3.0, n)
    p = (x1, x2, y, phi1, phi2, mu1, mu2)
    assert batch.valid(*p).all()
    F = batch.worst_squeeze(*p, mass, g=9.81, accel=2.0, safety=1.5, per="total")
    ref = worst_squeeze_many(*p, mass, g=9.81, accel=2.0, safety=1.5, per="total")
    np.testing.assert_allclose(F, ref, rtol=1e-13)
    for i in (0, 1234, n - 1):
        S, C = Grasp(*(float(v[i]) for v in p[:5]), mu1=float(mu1[i]), mu2=float(mu2[i]))._floats()
        want = 1.5 * mass[i] * (9.81 + 2.0) * 2 * np.hypot(S, C).max() / (x1[i] + x2[i])
        assert F[i] == pytest.approx(want, rel=1e-13)


def test_worst_squeeze_issue_example_and_sweep_shapes():
    F = batch.worst_squeeze(0.025, 0.075, 0.0, HALF_PI, HALF_PI, 0.3, 0.3, 1.0, g=9.81)
    assert float(F) == pytest.approx(9.81 * math.sqrt(26) / 2, rel=1e-14)  # 981 √26 / 200
    mu = np.linspace(0.2, 1.0, 5)
    y = np.linspace(0, 0.05, 3)[:, None]
    out = batch.worst_squeeze(0.05, 0.05, y, HALF_PI, HALF_PI, mu, mu, 1.0)
    assert out.shape == (3, 5)
    assert batch.closed_form(0.05, 0.05, y, HALF_PI, HALF_PI, mu, mu)[0].shape == (3, 5, 4)
    assert batch.k(np.zeros(7)[:, None, None], 0.05, 0.05, y, HALF_PI, HALF_PI, mu, mu).shape == (
        7,
        3,
        5,
        4,
    )


# -- namespaces --------------------------------------------------------------------------------
def test_numpy_and_array_api_strict_give_identical_results():
    xs = pytest.importorskip(
        "array_api_strict",
        reason="array-api-strict is not installed (pip install 'graspcompass[test]')",
    )
    pytest.importorskip(
        "array_api_compat",
        reason="array-api-compat is not installed (pip install 'graspcompass[batch]')",
    )
    rng = np.random.default_rng(9)
    n = 3000
    p = [
        rng.uniform(0.01, 1, n),
        rng.uniform(0.01, 1, n),
        rng.uniform(0, 1, n),
        rng.uniform(1.2, 1.9, n),
        rng.uniform(1.2, 1.9, n),
        rng.uniform(0.1, 1.5, n),
        rng.uniform(0.1, 1.5, n),
    ]
    t = rng.uniform(-4, 4, n)
    ps = [xs.asarray(v) for v in p]
    ts = xs.asarray(t)
    ok = batch.valid(*p)
    assert 0 < ok.sum() < n
    assert np.array_equal(np.asarray(batch.valid(*ps)), ok)
    for fn, args, sargs in (
        (batch.closed_form, p, ps),
        (batch.k, [t, *p], [ts, *ps]),
        (batch.k_grasp, [t, *p], [ts, *ps]),
        (batch.internal_force, [t, *p], [ts, *ps]),
        (batch.worst_squeeze, [*p, 2.0], [*ps, 2.0]),
    ):
        a, b = fn(*args, on_invalid="nan"), fn(*sargs, on_invalid="nan")
        for u, v in zip(a if isinstance(a, tuple) else (a,), b if isinstance(b, tuple) else (b,)):
            assert type(v).__module__.startswith("array_api_strict"), fn
            assert np.array_equal(np.asarray(v), u, equal_nan=True), fn  # bit for bit
        with pytest.raises(batch.InvalidGraspsError) as e1:
            fn(*args)
        with pytest.raises(batch.InvalidGraspsError) as e2:
            fn(*sargs)
        assert (e1.value.index, e1.value.count) == (e2.value.index, e2.value.count)


def test_sincos_table_is_within_two_units_of_mpmath():
    rng = np.random.default_rng(2)
    x = np.concatenate(
        [
            rng.uniform(0, math.pi, 4000),
            rng.uniform(-20, 20, 1000),
            [
                0.0,
                5e-324,
                1e-300,
                1e-8,
                HALF_PI,
                math.pi,
                -math.pi,
                2 * math.pi,
                np.nextafter(HALF_PI, 0),
                np.nextafter(math.pi, 0),
                3 * HALF_PI,
            ],
        ]
    )
    s, c = batch._sincos(np, x)
    with mpmath.workdps(40):
        es = max(abs(float(mpmath.sin(mpmath.mpf(v)) - mpmath.mpf(a))) for v, a in zip(x, s))
        ec = max(abs(float(mpmath.cos(mpmath.mpf(v)) - mpmath.mpf(a))) for v, a in zip(x, c))
    assert es < 2 * U and ec < 2 * U, (es / U, ec / U)
    assert s[-11] == 0.0 and s[-10] == 5e-324 and c[-11] == 1.0


# -- invalid grasps --------------------------------------------------------------------------
def test_invalid_grasps_raise_with_the_first_index_or_give_nan():
    mu = np.array([[0.5, 0.5, 0.5], [0.5, -0.1, 0.05]])
    p = (1.0, 1.0, 0.5, HALF_PI - 0.1, HALF_PI, mu, 0.5)
    with pytest.raises(batch.InvalidGraspsError) as err:
        batch.worst_squeeze(*p, 1.0)
    e = err.value
    assert isinstance(e, ValueError) and isinstance(e, InputError)
    assert e.index == (1, 1) and e.count == 2 and e.reason == "μ1 > 0"
    assert "2 of 6 grasps are invalid" in str(e) and "mu1=-0.1" in str(e)
    F = batch.worst_squeeze(*p, 1.0, on_invalid="nan")
    assert np.isnan(F).tolist() == [[False] * 3, [False, True, True]]
    S, _ = batch.closed_form(*p, on_invalid="nan")
    assert np.isnan(S[1, 2]).all() and not np.isnan(S[0]).any()
    with pytest.raises(batch.InvalidGraspsError, match=r"φ1 \+ ξ1 > π/2 of condition \(1\)"):
        batch.closed_form(1.0, 1.0, 0.5, HALF_PI - 0.1, HALF_PI, 0.05, 0.5)
    with pytest.raises(batch.InvalidGraspsError, match=r"φ2 − ξ2 < π/2"):
        batch.k_grasp(0.0, 1.0, 1.0, 0.5, HALF_PI, HALF_PI + 0.1, 0.5, 0.05)
    for bad in (dict(x2=-1.0), dict(y=-0.1), dict(phi1=0.0), dict(phi1=4.0)):
        q = dict(x1=1.0, x2=1.0, y=0.5, phi1=HALF_PI, phi2=HALF_PI, mu1=0.5, mu2=0.5) | bad
        assert not bool(batch.valid(**q))
        with pytest.raises(batch.InvalidGraspsError):
            batch.closed_form(**q)
    with pytest.raises(InputError, match="on_invalid"):
        batch.closed_form(1.0, 1.0, 0.0, 1.5, 1.5, 0.5, 0.5, on_invalid="ignore")


def test_nan_propagation():
    nan = math.nan
    p = (1.0, 1.0, 0.5, HALF_PI, HALF_PI, 0.5, 0.5)
    assert not bool(batch.valid(1.0, nan, 0.5, HALF_PI, HALF_PI, 0.5, 0.5))
    with pytest.raises(batch.InvalidGraspsError, match="x2 = nan is not finite"):
        batch.worst_squeeze(1.0, nan, 0.5, HALF_PI, HALF_PI, 0.5, 0.5, 1.0)
    out = batch.worst_squeeze(
        1.0, np.array([1.0, nan]), 0.5, HALF_PI, HALF_PI, 0.5, 0.5, 1.0, on_invalid="nan"
    )
    assert math.isfinite(out[0]) and math.isnan(out[1])
    kg = batch.k_grasp(np.array([0.0, nan]), *p)  # θ is not checked: nan in, nan out
    assert math.isfinite(kg[0]) and math.isnan(kg[1])
    with np.errstate(invalid="ignore"):
        assert math.isnan(float(batch.k_grasp(math.inf, *p)))


def test_margin_matches_the_float_path_refusal():
    phi, mu = 1.0, math.tan(HALF_PI - 1.0 + 1e-13)  # φ1 + ξ1 = π/2 + 1e-13
    p = (1.0, 1.0, 0.5, phi, HALF_PI, mu, 0.5)
    assert bool(batch.valid(*p)) and not bool(batch.valid(*p, margin=1e-12))
    with pytest.raises(ValueError, match="within rounding"):
        Grasp(*p[:5], mu1=p[5], mu2=p[6])


def test_refuses_bools_complex_and_text():
    from graspcompass.errors import ComplexValueError, WrongTypeError

    with pytest.raises(WrongTypeError):
        batch.valid(True, 1.0, 0.0, 1.5, 1.5, 0.5, 0.5)
    with pytest.raises(ComplexValueError):
        batch.valid(np.array([1 + 1j]), 1.0, 0.0, 1.5, 1.5, 0.5, 0.5)
    with pytest.raises((WrongTypeError, TypeError)):
        batch.valid("1", 1.0, 0.0, 1.5, 1.5, 0.5, 0.5)
    assert batch.valid([1, 2], 1, 0, 1.5, 1.5, 0.5, 0.5).tolist() == [True, True]  # ints


# -- Grasp.k_grasp on many angles: the table of the envelope ---------------------------------
def _mp_k_grasp(S, C, theta):
    with mpmath.workdps(40):
        t = mpmath.mpf(float(theta))
        s, c = mpmath.sin(t), mpmath.cos(t)
        return float(
            max(
                [mpmath.mpf(0)]
                + [mpmath.mpf(float(a)) * s - mpmath.mpf(float(b)) * c for a, b in zip(S, C)]
            )
        )


def _break_angles(S, C):
    """Where two k_n cross or one crosses zero: the envelope's possible break points."""
    out = []
    for m in range(4):
        out += [math.atan2(C[m], S[m]), math.atan2(C[m], S[m]) + math.pi]
        for n in range(m):
            a = math.atan2(C[m] - C[n], S[m] - S[n])
            out += [a, a + math.pi]
    return out


@pytest.mark.parametrize("name", ["fig6", "table1a", "table1b", "table1c", "random"])
def test_k_grasp_table_within_three_eps_of_mpmath(name):
    if name == "random":
        g = Grasp(0.7, 0.2, 0.4, 1.1, 2.0, mu1=0.9, mu2=0.8)
    else:
        g = Grasp.preset(name)
    S, C = g._floats()
    vmax = float(np.hypot(S, C).max())
    rng = np.random.default_rng(1)
    breaks = _break_angles(S, C)
    h = 2 * math.pi / _envelope.M
    near = [b + k for b in breaks for k in (-h, -h / 2, -1e-12, -1e-16, 0.0, 1e-16, h / 2, h)]
    t = np.concatenate([near, rng.uniform(-7, 7, 40_000), rng.uniform(-6e4, 6e4, 1000)])
    t = t[np.abs(t) <= _envelope.THETA_MAX]
    assert t.size >= _envelope.TABLE_MIN_SIZE
    kg = g.k_grasp(t)
    assert g.__dict__["_ktable"].broken_bins >= 2
    direct = _envelope.direct_k_grasp(S, C, t)  # the formula of the array path before §5
    assert np.abs(kg - direct).max() <= 4 * EPS * vmax
    sample = np.concatenate(
        [np.arange(len(near)), rng.integers(0, t.size, 300), np.argsort(np.abs(kg - direct))[-100:]]
    )
    err = max(abs(kg[i] - _mp_k_grasp(S, C, t[i])) for i in sample)
    assert err <= 3 * EPS * vmax, err / (EPS * vmax)
    # the scalar path agrees as before (tests/test_float_path.py's tolerance)
    for i in sample[:50]:
        assert abs(g.k_grasp(float(t[i])) - kg[i]) <= 4 * EPS * vmax


def test_k_grasp_table_shapes_large_angles_and_cache():
    g = Grasp.preset("fig6")
    t = np.linspace(-10, 10, 2 * _envelope.TABLE_MIN_SIZE).reshape(256, -1)
    kg = g.k_grasp(t)
    assert kg.shape == t.shape
    table = g.__dict__["_ktable"]
    assert g.k_grasp(t[::-1]) is not None and g.__dict__["_ktable"] is table  # cached
    S, C = g._floats()
    np.testing.assert_allclose(kg, _envelope.direct_k_grasp(S, C, t), rtol=0, atol=1e-14)
    vmax = float(np.hypot(S, C).max())
    big = t * 1e5  # beyond the table: reduced by 2π (exactly), then the table
    np.testing.assert_allclose(
        g.k_grasp(big), _envelope.direct_k_grasp(S, C, big), rtol=0, atol=4 * EPS * vmax
    )
    huge = t * 1e12  # beyond THETA_MAX: the direct formula
    np.testing.assert_array_equal(g.k_grasp(huge), _envelope.direct_k_grasp(S, C, huge))
    small = t.reshape(-1)[:100]
    np.testing.assert_array_equal(g.k_grasp(small), _envelope.direct_k_grasp(S, C, small))
    assert g == Grasp.preset("fig6") and hash(g) == hash(Grasp.preset("fig6"))


def _dot_max(S, C, t):
    """The reference written here: max(0, max_n V_n · e(θ)), e(θ) = (sin θ, −cos θ) (26)."""
    t = np.asarray(t, dtype=float)
    e = np.stack([np.sin(t), -np.cos(t)])  # libm: correctly reduced for any finite θ
    V = np.stack([np.asarray(S, float), np.asarray(C, float)], axis=1)  # (4, 2)
    return np.maximum(np.max(V @ e, axis=0), 0.0)


def _ulps(values, k=2):
    """Each value and its neighbours up to ``k`` ulps away."""
    out = [np.asarray(values, float)]
    for direction in (np.inf, -np.inf):
        v = out[0]
        for _ in range(k):
            v = np.nextafter(v, direction)
            out.append(v)
    return np.concatenate(out)


def _hard_angles(S, C):
    """Break points ± 2 ulps on several turns, the table's edges and bins, 0, ±π, ±2π, huge."""
    h = _envelope._STEP
    breaks = np.array(_break_angles(S, C))
    turns = np.array([-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 160.0, -1e5])
    on_turns = (breaks[:, None] + 2 * np.pi * turns).ravel()
    edges = np.array(
        [
            0.0,
            -0.0,
            np.pi,
            -np.pi,
            2 * np.pi,
            -2 * np.pi,
            3 * np.pi,
            _envelope.J_LO * h,
            (_envelope.J_LO + 0.5) * h,
            (_envelope.J_LO + 1.5) * h,
            _envelope.J_HI * h,
            (_envelope.J_HI - 0.5) * h,
            (_envelope.J_HI - 1.5) * h,
            0.5 * h,
            1.5 * h,
            -0.5 * h,
            1e6,
            -1e6,
            _envelope.THETA_MAX,
            -_envelope.THETA_MAX,
            1e7,
            -1e9,
            1e300,
            5e-324,
            -5e-324,
        ]
    )
    return np.concatenate([_ulps(on_turns), _ulps(edges), on_turns + h / 2, on_turns - h / 2])


angle_lists = st.lists(
    st.one_of(
        st.floats(-7.0, 7.0),
        st.floats(-1e7, 1e7),
        st.floats(-1e-6, 1e-6),
        st.floats(allow_nan=False, allow_infinity=False),
    ),
    min_size=1,
    max_size=50,
)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(grasps(), angle_lists)
def test_envelope_table_equals_the_max_of_dot_products(p, thetas):
    """Random valid grasps: the table path within 4 ε max|V_n| of the dot products, everywhere.

    Where all four dot products are clearly negative (the zero region, if the grasp has
    one) the table's value is exactly 0, and it is never negative.
    """
    if not bool(batch.valid(*p, margin=2e-12)):
        return
    S, C = batch.closed_form(*p)
    vmax = float(np.hypot(S, C).max())
    table = _envelope.EnvelopeTable(S, C)
    t = np.concatenate([np.array(thetas), _hard_angles(S, C)])
    kg, ref = table(t), _dot_max(S, C, t)
    assert kg.shape == t.shape and np.isfinite(kg).all()
    err = np.abs(kg - ref) / (EPS * vmax)
    assert err.max() <= 4, (p, t[np.argmax(err)], err.max())
    assert (kg >= 0).all()
    V = np.stack([S, C], axis=1)
    below = np.max(V @ np.stack([np.sin(t), -np.cos(t)]), axis=0) < -8 * EPS * vmax
    assert (kg[below] == 0).all()
    # the same angles one by one, reversed, and as a 2-d array: the same numbers
    np.testing.assert_array_equal(table(t[::-1])[::-1], kg)
    np.testing.assert_array_equal(table(t[:, None])[:, 0], kg)


def test_envelope_table_against_mpmath_on_the_hard_angles():
    """fig6 and a grasp with a zero region: within 3 ε max|V_n| of 40 digits."""
    for g in (Grasp.preset("fig6"), Grasp(1.0, 1.0, 1.0, 2.3, 2.3, mu1=2.0, mu2=2.0)):
        S, C = g._floats()
        vmax = float(np.hypot(S, C).max())
        t = _hard_angles(S, C)
        kg = _envelope.EnvelopeTable(S, C)(t)
        for theta, value in zip(t, kg):
            assert abs(value - _mp_k_grasp(S, C, theta)) <= 3 * EPS * vmax, theta


def test_zero_region_is_exactly_zero():
    """Normals tilted upwards (φ > π/2, jaws carrying from below): k_grasp = 0 on a range."""
    p = (1.0, 1.0, 0.0, 2.5, 2.5, 3.0, 3.0)
    S, C = batch.closed_form(*p)
    table = _envelope.EnvelopeTable(S, C)
    t = np.linspace(-20, 20, 400_001)
    V = np.stack([S, C], axis=1)
    dots = np.max(V @ np.stack([np.sin(t), -np.cos(t)]), axis=0)
    kg = table(t)
    assert (dots < 0).sum() > 1000  # the grasp has a zero region
    assert (kg[dots < -1e-14] == 0.0).all()
    assert (kg >= 0).all()


def test_envelope_table_blocks_and_non_finite_angles():
    """Several blocks with nan, ±inf, break points and far angles in different ones."""
    g = Grasp.preset("fig6")
    S, C = g._floats()
    vmax = float(np.hypot(S, C).max())
    rng = np.random.default_rng(13)
    n = 2 * _envelope.CHUNK + 5
    t = rng.uniform(0, 2 * np.pi, n)
    hard = _hard_angles(S, C)
    where = rng.choice(n, hard.size, replace=False)
    t[where] = hard
    specials = [3, _envelope.CHUNK - 1, _envelope.CHUNK, n - 1]
    t[specials] = [np.nan, np.inf, -np.inf, np.nan]
    kg = _envelope.EnvelopeTable(S, C)(t)
    ok = np.isfinite(t)
    assert np.isnan(kg[specials]).all() and not np.isnan(kg[ok]).any()
    assert np.abs(kg[ok] - _dot_max(S, C, t[ok])).max() <= 4 * EPS * vmax
    assert _envelope.EnvelopeTable(S, C)(np.empty((0, 3))).shape == (0, 3)
    # Grasp.k_grasp refuses nan and infinities, on the table's sizes too (as before)
    with pytest.raises(NonFiniteValueError):
        g.k_grasp(t)
    t[specials] = 0.0
    np.testing.assert_allclose(g.k_grasp(t), _dot_max(S, C, t), rtol=0, atol=4 * EPS * vmax)


# -- Dask: the documented example on a local cluster -----------------------------------------
def _doc_example() -> str:
    text = (DOCS / "howto" / "batch.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)
    dask_blocks = [b for b in blocks if "LocalCluster" in b]
    assert len(dask_blocks) == 1, "docs/howto/batch.md shows one Dask example"
    return dask_blocks[0]


def test_dask_example_on_a_local_cluster():
    pytest.importorskip(
        "dask.distributed",
        reason="dask is not installed: pip install "
        "'graspcompass[dask]' to run the Dask example of docs/howto/batch.md",
    )
    pytest.importorskip("array_api_compat", reason="array-api-compat is not installed")
    ns: dict = {}
    exec(compile(_doc_example(), "docs/howto/batch.md", "exec"), ns)
    F, lazy_F, grasps = ns["F"], ns["lazy_F"], ns["grasps"]  # computed on the cluster
    ref = batch.worst_squeeze(*grasps, 1.0, g=9.81, accel=2.0, on_invalid="nan")
    assert F.shape == ref.shape and np.isnan(ref).any()
    np.testing.assert_array_equal(F, ref)  # map_blocks: numpy blocks, the same numbers
    # dask.array namespace: libm's sin and cos, both within the stated bound of the exact value
    ok = ~np.isnan(ref)
    assert np.array_equal(np.isnan(lazy_F), ~ok)
    tol = ref[ok] * (2 * np_relative_bound(*(v[ok] for v in grasps)) + 8 * U)
    assert (np.abs(lazy_F[ok] - ref[ok]) <= tol).all()
    assert np.abs(lazy_F[ok] - ref[ok]).max() > 0  # not trivially the same path
    assert ns["n_valid"] == int(batch.valid(*grasps).sum())
