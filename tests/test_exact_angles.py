"""Exact on every angle a user types (issue 9, item 1): degrees, decimal degrees,
rational multiples of π, radians; vertical cone sides; radicals of several primes.

Expected values come from the paper's formulas (28)-(39) typed in here with
mpmath at 50 digits (an independent evaluation), from hand computation, and from
known trigonometric values (cos 108° = (1 − √5)/4).
"""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram
from graspcompass.geometry import Point
from graspcompass.geometry.cyclotomic import is_zero_cyclotomic
from graspcompass.geometry.exact import canon, decide_sign, decide_zero
from graspcompass.geometry.trig import OpaqueCos, OpaqueSin, sincos

mpmath.mp.dps = 50


def paper_V(x1, x2, y, phi1, phi2, xi1, xi2):
    """V_n = (S_n, C_n) of eqs. (28)-(39), in mpmath floats of 50 digits."""
    t = [
        mpmath.tan(phi1 + xi1),
        mpmath.tan(phi2 + xi2),
        mpmath.tan(phi1 - xi1),
        mpmath.tan(phi2 - xi2),
    ]
    h = (x1 + x2) / 2
    return [
        (-h + y * t[0], x2 * t[0]),
        (h - y * t[1], x1 * t[1]),
        (-h + y * t[2], x2 * t[2]),
        (h - y * t[3], x1 * t[3]),
    ]


def mp_value(text: str) -> mpmath.mpf:
    """An angle typed like '108.5deg' or '3*pi/7' or '6/5', evaluated independently."""
    if text.endswith("deg"):
        return (
            mpmath.mpf(Fraction(text[:-3]).numerator)
            / Fraction(text[:-3]).denominator
            * mpmath.pi
            / 180
        )
    if "pi" in text:
        p, q = text.replace("*pi", "").split("/")
        return mpmath.pi * int(p) / int(q)
    f = Fraction(text)
    return mpmath.mpf(f.numerator) / f.denominator


def close(a, b, tol=1e-40):
    return abs(mpmath.mpf(sp.N(a, 50)) - b) <= tol * (1 + abs(b))


def admissible_phi(xi: mpmath.mpf, phi: mpmath.mpf) -> bool:
    up, lo = phi + xi, phi - xi
    return (
        mpmath.pi / 2 < up < 3 * mpmath.pi / 2
        and -mpmath.pi / 2 < lo < mpmath.pi / 2
        and 0 < phi <= mpmath.pi
    )


# angles as a user types them: integer and one-decimal degrees, p*pi/q with q <= 24,
# and decimal radians
degrees = st.integers(1, 1799).map(lambda d: f"{Fraction(d, 10)}deg")
pi_multiples = st.builds(lambda p, q: f"{p}*pi/{q}", st.integers(1, 48), st.integers(1, 24))
radians = st.integers(1, 314).map(lambda r: str(Fraction(r, 100)))
typed_angle = st.one_of(degrees, pi_multiples, radians)


@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1c"])
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(angle=typed_angle, which=st.sampled_from(["phi1", "phi2"]))
def test_typed_angle_gives_the_exact_construction(preset, angle, which):
    base = Grasp.preset(preset)
    params = dict(
        x1=base.x1, x2=base.x2, y=base.y, phi1=base.phi1, phi2=base.phi2, xi1=base.xi1, xi2=base.xi2
    )
    params[which] = angle
    mp = {k: mpmath.mpf(sp.N(v, 60)) for k, v in params.items() if k != which}
    mp[which] = mp_value(angle)
    xi = mp["xi1"] if which == "phi1" else mp["xi2"]
    if not admissible_phi(xi, mp[which]):
        return  # refused by condition (1): tested elsewhere
    try:
        g = Grasp(**params)
    except ValueError as exc:  # only condition (1) at its exact bounds
        assert "condition (1)" in str(exc), exc
        return
    c = internal_force_diagram(g)
    expected = paper_V(*(mp[k] for k in ("x1", "x2", "y", "phi1", "phi2", "xi1", "xi2")))
    for n in (1, 2, 3, 4):
        V = c[f"V{n}"]
        assert V.is_exact
        assert close(V.x, expected[n - 1][0]) and close(V.y, expected[n - 1][1]), (n, V)
        closed = g.V[n - 1]  # eqs. (30)/(33): the same point exactly
        assert decide_zero(V.x - closed.x) and decide_zero(V.y - closed.y)
    # the envelope is max(k_n, 0) of (25), at sample directions, from the paper's V_n
    env = c["envelope"]
    for t in [i * 2 * mpmath.pi / 17 + mpmath.mpf(1) / 7 for i in range(17)]:
        want = max([0] + [S * mpmath.sin(t) - C * mpmath.cos(t) for S, C in expected])
        assert abs(env.k(float(t)) - float(want)) <= 1e-9 * (1 + float(want))


def test_108_degrees_is_exact_and_small():
    """The issue's example: table1a with φ1 = 108° (sympy: nested radicals)."""
    g = Grasp.preset("table1a")
    g = Grasp(g.x1, g.x2, g.y, "108deg", g.phi2, mu1=g.mu1, mu2=g.mu2)
    c = internal_force_diagram(g)
    nested = [
        a
        for n in (1, 2, 3, 4)
        for a in sp.preorder_traversal(c[f"V{n}"].x)
        if isinstance(a, sp.Pow) and not a.exp.is_Integer and not a.base.is_Rational
    ]
    assert not nested  # no nested radicals: sin/cos of 18° stay generators
    want = paper_V(2, 2, 1, mpmath.pi * 3 / 5, mpmath.pi / 2, mpmath.pi / 4, mpmath.atan(1.2))
    assert close(c["V1"].x, want[0][0]) and close(c["V1"].y, want[0][1])
    assert len(c["envelope"].arcs) >= 2


def test_cli_steps_with_108_degrees_finishes():
    """`graspcompass steps --preset table1a --phi1 108deg` used to hang (guard: 120 s)."""
    out = subprocess.run(
        [sys.executable, "-m", "graspcompass", "steps", "--preset", "table1a", "--phi1", "108deg"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    assert "V1" in out.stdout and "envelope" in out.stdout


def test_vertical_cone_side_no_zero_division():
    """φ2 + ξ2 = π: the upper side at P2 is vertical, tan = 0 (issue 9, item 1).

    By hand, eqs. (28)-(39) with x1 = x2 = y = 1: tan(φ1 + ξ1) = tan(3π/4) = −1 so
    V1 = (−2, −1); tan(π) = 0 so V2 = (1, 0); tan(π/4) = 1 so V3 = (0, 1);
    tan(π/6) = 1/√3 so V4 = (1 − 1/√3, 1/√3).  At θ = 0, k_n = −C_n: 1, 0, −1, −1/√3.
    """
    g = Grasp(1, 1, 1, "pi/2", "7*pi/12", mu1=1, xi2="5*pi/12")
    r3 = sp.sqrt(3)
    expected = [Point(-2, -1), Point(1, 0), Point(0, 1), Point(1 - 1 / r3, 1 / r3)]
    for V, E in zip(g.V, expected):
        assert decide_zero(V.x - E.x) and decide_zero(V.y - E.y), (V, E)
    assert g.k_grasp(0) == 1
    c = internal_force_diagram(g)
    for n, E in enumerate(expected, 1):
        assert decide_zero(c[f"V{n}"].x - E.x) and decide_zero(c[f"V{n}"].y - E.y)


@given(a=st.integers(1, 23), b=st.integers(1, 11), p=st.sampled_from([2, 3, 6, 5, 10, 15]))
@settings(max_examples=25, deadline=None)
def test_radicals_of_several_primes_never_divide_by_zero(a, b, p):
    """√6 next to √2 and √3 (the ZeroDivisionError class): exact, defined, right value."""
    phi, xi = sp.pi * a / 24, sp.pi * b / 24
    if not (sp.pi / 2 < phi + xi < 3 * sp.pi / 2 and -sp.pi / 2 < phi - xi < sp.pi / 2):
        return
    x = sp.sqrt(p) / 2
    g = Grasp(x, 1, sp.sqrt(2) / 3, phi, "pi/2", xi1=xi, mu2=1)
    want = paper_V(
        mpmath.sqrt(p) / 2,
        1,
        mpmath.sqrt(2) / 3,
        mpmath.pi * a / 24,
        mpmath.pi / 2,
        mpmath.pi * b / 24,
        mpmath.pi / 4,
    )
    for V, (S, C) in zip(g.V, want):
        assert close(V.x, S) and close(V.y, C)


def test_sincos_keeps_preset_radicals_and_uses_generators_elsewhere():
    assert sincos(sp.pi / 3) == (sp.sqrt(3) / 2, sp.Rational(1, 2))
    s, c = sincos(3 * sp.pi / 5)  # 108° = 90° + 18°
    assert isinstance(s, OpaqueCos) and isinstance(-c, OpaqueSin)
    assert close(s, mpmath.sin(mpmath.pi * 3 / 5)) and close(c, mpmath.cos(mpmath.pi * 3 / 5))
    assert canon(s**2 + c**2 - 1) == 0


@pytest.mark.parametrize(
    "expr, zero",
    [
        (lambda s, c: 4 * c + sp.sqrt(5) - 1, True),  # cos 108° = (1 − √5)/4
        (lambda s, c: 4 * c + sp.sqrt(5) - 1 + sp.Rational(1, 10**30), False),
        (lambda s, c: 2 * s * c - OpaqueSin(sp.pi / 5), False),  # sin 216° ≠ sin 36°
        (lambda s, c: 2 * s * c + OpaqueSin(sp.pi / 5), True),  # sin 216° = −sin 36°
    ],
)
def test_exact_zero_decisions_beyond_the_circle_relation(expr, zero):
    s, c = sincos(3 * sp.pi / 5)
    e = expr(s, c)
    assert decide_zero(e) is zero
    assert bool(abs(mpmath.mpf(sp.N(e, 60))) < 1e-40) is zero  # independent check


def test_cyclotomic_zero_test_against_known_identities():
    # Gauss: cos(2π/17) is a root of 16 c^4 + ... — use simpler known values
    assert is_zero_cyclotomic(sp.cos(sp.pi / 5, evaluate=False) - (1 + sp.sqrt(5)) / 4)
    assert is_zero_cyclotomic(OpaqueSin(sp.pi / 7) * 0) is True
    assert is_zero_cyclotomic(sp.sqrt(7) * sp.sqrt(3) - sp.sqrt(21)) is True
    assert is_zero_cyclotomic(sp.sqrt(7) - sp.Rational(8, 3)) is False
    assert is_zero_cyclotomic(sp.pi - 3) is None  # π alone is not in a cyclotomic field


@given(num=st.integers(-50, 50), den=st.integers(1, 20), q=st.integers(2, 24))
@settings(max_examples=40, deadline=None)
def test_decide_sign_agrees_with_50_digits(num, den, q):
    s, c = sincos(sp.pi * num / q)
    e = s * sp.Rational(num, den) - c * sp.sqrt(3) + sp.Rational(1, 7)
    v = (
        mpmath.sin(mpmath.pi * num / q) * mpmath.mpf(num) / den
        - mpmath.cos(mpmath.pi * num / q) * mpmath.sqrt(3)
        + mpmath.mpf(1) / 7
    )
    want = 0 if abs(v) < 1e-40 else (1 if v > 0 else -1)
    assert decide_sign(e) == want


def test_twelfths_table_is_sympys_radical_form():
    """trig's written-out sin/cos of π/12, π/6, π/4 are sympy's own, structurally."""
    import sympy as sp

    from graspcompass.geometry.trig import _TWELFTH_VALUES

    for v, (s, c) in _TWELFTH_VALUES.items():
        assert sp.srepr(s) == sp.srepr(sp.sin(v * sp.pi))
        assert sp.srepr(c) == sp.srepr(sp.cos(v * sp.pi))


@pytest.mark.parametrize("big", ["1e30", "1e300", "1e309"])
def test_envelope_of_lengths_of_very_different_sizes(big):
    """x1 = 10**309 with y = 1/2: the V_n differ by O(1) at size 10**309, which 40
    digits cannot separate; the envelope raises the precision instead of refusing
    a valid grasp.  Checked against eq. (25) evaluated in 800-digit arithmetic."""
    import mpmath
    import sympy as sp

    import graspcompass as gc

    g = gc.Grasp(big, 1, "1/2", "pi/2", "pi/2", mu1=1, mu2="6/5")
    env = gc.internal_force_diagram(g)["envelope"]
    S = [sp.Integer(0)] + [v.x for v in env.V]
    C = [sp.Integer(0)] + [v.y for v in env.V]
    with mpmath.workdps(800):
        for arc in env.arcs:
            t = (mpmath.mpf(sp.N(arc.theta_start, 820)) + mpmath.mpf(sp.N(arc.theta_end, 820))) / 2
            ks = [
                mpmath.mpf(sp.N(s, 820)) * mpmath.sin(t) - mpmath.mpf(sp.N(c, 820)) * mpmath.cos(t)
                for s, c in zip(S, C)
            ]
            assert max(range(5), key=lambda n: ks[n]) == arc.n
