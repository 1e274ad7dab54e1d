"""Exact on every whole grasp a user types (issue 20): all four angles typed at once.

The grasps are drawn as a user types them — φ1, φ2, ξ1, ξ2 in integer degrees,
one-decimal degrees or p·π/q with q <= 24, inside condition (1); x1, x2, y as one- or
two-decimal numbers, y = 0 included — and replayed with the exact construction.
Expected values come from outside the package:

* V_n of eqs. (28)-(39) typed in here: tan(φ ± ξ) evaluated by mpmath at 50 digits
  from the typed text (its own reading of degrees and π); and the drawing's V_n equal
  the package's closed form ``Grasp.V`` exactly (another code path: a zero test that
  must answer True, never None);
* k_grasp(θ) read off the exact envelope against the linear program of §2.2.5 written
  in ``test_linprog`` (scipy's HiGHS), which never uses eqs. (12)-(39);
* the break points B_nm: on both circles of the diameters O V_n, O V_m (Thales), checked
  at 50 digits.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram
from graspcompass.geometry.exact import decide_zero
from test_linprog import lp_k_grasp

mpmath.mp.dps = 50


def _degrees(text: str) -> Fraction:
    """The typed angle in degrees, read here (not by the package)."""
    if text.endswith("deg"):
        return Fraction(text[:-3])
    p, q = text.replace("*pi", "").split("/")
    return Fraction(180 * int(p), int(q))


def _mp(deg: Fraction) -> mpmath.mpf:
    return mpmath.pi * deg.numerator / (180 * deg.denominator)


def _sp(deg: Fraction) -> sp.Expr:
    return sp.pi * sp.Rational(deg.numerator, 180 * deg.denominator)


@st.composite
def typed_angle(draw, lo: Fraction, hi: Fraction) -> str:
    """An angle strictly inside (lo, hi) degrees, typed in one of the three ways."""
    kind = draw(st.sampled_from(("deg", "decimal", "pi")))
    if kind == "deg":
        d = draw(st.integers(int(lo) + 1, max(int(lo) + 1, int(hi) - 1)))
        text = f"{d}deg"
    elif kind == "decimal":
        t = draw(st.integers(int(lo * 10) + 1, max(int(lo * 10) + 1, int(hi * 10) - 1)))
        text = f"{t / 10:.1f}deg"
    else:
        q = draw(st.integers(2, 24))
        p = draw(st.integers(1, 2 * q))
        text = f"{p}*pi/{q}"
    deg = _degrees(text)
    if not lo < deg < hi:
        from hypothesis import reject

        reject()
    return text


@st.composite
def whole_grasp(draw) -> dict[str, str]:
    def length(low: int) -> str:
        digits = draw(st.sampled_from((1, 2)))
        v = draw(st.integers(low, 250)) / 100
        return f"{v:.{digits}f}" if f"{v:.{digits}f}" != f"{0:.{digits}f}" or low == 0 else "0.1"

    params = {"x1": length(10), "x2": length(10), "y": draw(st.sampled_from(("0", length(0))))}
    for i in (1, 2):
        phi = draw(typed_angle(Fraction(1), Fraction(180)))
        lo = abs(_degrees(phi) - 90) + 1  # condition (1): |φ - π/2| < ξ < π/2, margin 1°
        params[f"phi{i}"] = phi
        params[f"xi{i}"] = draw(typed_angle(lo, Fraction(89)))
    return params


def _paper_V(p: dict[str, str]) -> list[tuple[mpmath.mpf, mpmath.mpf]]:
    """V_n = (S_n, C_n) of eqs. (28)-(39) at 50 digits, from the typed text."""
    x1, x2, y = (
        mpmath.mpf(Fraction(p[k]).numerator) / Fraction(p[k]).denominator for k in ("x1", "x2", "y")
    )
    f1, f2, k1, k2 = (_mp(_degrees(p[k])) for k in ("phi1", "phi2", "xi1", "xi2"))
    t = [mpmath.tan(f1 + k1), mpmath.tan(f2 + k2), mpmath.tan(f1 - k1), mpmath.tan(f2 - k2)]
    h = (x1 + x2) / 2
    return [
        (-h + y * t[0], x2 * t[0]),
        (h - y * t[1], x1 * t[1]),
        (-h + y * t[2], x2 * t[2]),
        (h - y * t[3], x1 * t[3]),
    ]


def _mpv(e: sp.Expr) -> mpmath.mpf:
    """``e`` at 60 digits; its sines, cosines and roots first replaced by 90-digit floats.

    sympy's ``N`` re-evaluates every sin(pi/10) of an expanded 6000-operation break
    point term by term (about 1 s); with the atoms replaced once it adds floats (20x
    faster, the same digits).
    """
    atoms = {
        a: sp.Float(sp.N(a, 90), 90)
        for a in e.atoms(sp.Function, sp.Pow)
        if a.is_number and (a.is_Function or not a.exp.is_Integer)
    }
    return mpmath.mpf(sp.N(e.xreplace(atoms), 60))


def _check(p: dict[str, str], exact_V: bool = True) -> None:
    g = Grasp(**p)
    c = internal_force_diagram(g)
    want = _paper_V(p)
    for n, (vx, vy) in enumerate(want, 1):
        got = c[f"V{n}"]
        scale = 1 + abs(vx) + abs(vy)
        assert abs(_mpv(got.x) - vx) < 1e-40 * scale and abs(_mpv(got.y) - vy) < 1e-40 * scale
    if exact_V:  # the drawing's V_n are the closed form's, exactly (a zero test, not None)
        for n, v in enumerate(g.V, 1):
            got = c[f"V{n}"]
            assert decide_zero(got.x - v.x) is True and decide_zero(got.y - v.y) is True, (n, p)
    # the break points lie on both Thales circles (O B ⟂ B V at both diameters)
    for name in ("B12", "B13", "B14", "B23", "B24", "B34"):
        b = c[name]
        bx, by = _mpv(b.x), _mpv(b.y)
        for n in (int(name[1]), int(name[2])):
            vx, vy = want[n - 1]
            assert abs(bx * (bx - vx) + by * (by - vy)) < 1e-35 * (1 + vx * vx + vy * vy)
    # k_grasp read off the exact envelope against the LP written in test_linprog
    floats = [float(Fraction(p[k])) for k in ("x1", "x2", "y")]
    f1, f2, k1, k2 = (float(_mp(_degrees(p[k]))) for k in ("phi1", "phi2", "xi1", "xi2"))
    env = c["envelope"]
    thetas = np.linspace(0, 2 * np.pi, 25)[:-1]
    ks = env.k(thetas)
    for t, k in zip(thetas, ks):
        k_lp, _ = lp_k_grasp(*floats, f1, f2, float(np.tan(k1)), float(np.tan(k2)), t)
        assert abs(k - k_lp) <= 1e-7 * (1 + abs(k_lp)), (p, t, k, k_lp)


#: the grasps of the issue and the slowest ones found by bench/bench_whole_grasps.py
ISSUE_GRASPS = [
    dict(x1="1.2", x2="0.3", y="0.4", phi1="61deg", phi2="118deg", xi1="67deg", xi2="49deg"),
    dict(x1="1.5", x2="0.7", y="1.18", phi1="162.0deg", phi2="6.3deg", xi1="75deg", xi2="86.9deg"),
    dict(x1="0.4", x2="1.4", y="0.2", phi1="117.7deg", phi2="1*pi/12", xi1="72.9deg", xi2="89deg"),
    dict(x1="2.05", x2="0.3", y="0", phi1="3*pi/7", phi2="108.5deg", xi1="7*pi/18", xi2="60.5deg"),
]


@pytest.mark.parametrize("params", ISSUE_GRASPS, ids=lambda p: p["phi1"] + "," + p["phi2"])
def test_issue_grasps_are_exact(params):
    _check(params)


@settings(
    max_examples=12,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(whole_grasp())
def test_whole_typed_grasps_match_the_closed_form_and_the_lp(params):
    _check(params)


def test_steps_of_a_whole_typed_grasp_from_the_command_line(tmp_path):
    """The command of the issue answers (it ran past 60 s) with the exact V_n."""
    import subprocess
    import sys

    args = [f"--{k}={v}" for k, v in ISSUE_GRASPS[0].items()]
    out = subprocess.run(
        [sys.executable, "-m", "graspcompass", "steps", *args],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    ).stdout
    rows = {line.split()[1]: line for line in out.splitlines() if line[:2].strip().isdigit()}
    assert {"V1", "V2", "V3", "V4", "B12", "B34", "envelope"} <= set(rows)
    assert "cos(29*pi/180)" in rows["V1"] or "sin(29*pi/180)" in rows["V1"]  # exact, not float
