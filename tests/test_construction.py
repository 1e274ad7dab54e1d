"""Tests of graspcompass.construction: the ruler-and-compass recipe of §3.3.

Every constructed object is compared with a value derived independently in the
test: the closed form (28)-(39) re-typed in ``conftest.py``, the geometric
meaning of the step (a point on a line, a perpendicular, Thales' circle), or a
physical argument (three concurrent forces).  None of the expected values is
copied from the implementation's output.
"""

from __future__ import annotations

import math
from itertools import combinations

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings

from conftest import (
    PRESET_NAMES,
    PRESET_PARAMS,
    Params,
    closed_form_SC,
    exact_params,
    is_zero,
)
from graspcompass import Circle, Grasp, Line, Point, internal_force_diagram
from graspcompass import symbols as gs
from graspcompass.construction import INSTRUMENTS

pi = sp.pi
VN = (1, 2, 3, 4)
PAIRS = list(combinations(VN, 2))


def cross(a, b) -> sp.Expr:
    (ax, ay), (bx, by) = a, b
    return ax * by - ay * bx


def dot(a, b) -> sp.Expr:
    (ax, ay), (bx, by) = a, b
    return ax * bx + ay * by


def on_line(p: Point, line: Line) -> bool:
    return is_zero(
        cross((p.x - line.point.x, p.y - line.point.y), (line.direction.x, line.direction.y))
    )


def on_circle(p: Point, c: Circle) -> bool:
    return is_zero((p.x - c.center.x) ** 2 + (p.y - c.center.y) ** 2 - c.radius2)


def side_direction(p, n):
    """Direction of friction-cone side n from the conventions, divided by cos ξ > 0.

    At P1 (n = 1, 3) the angle α = φ1 ± ξ1 is measured clockwise from the negative
    y-axis: (−sin α, −cos α); at P2 (n = 2, 4) counter-clockwise: (sin α, −cos α).
    sin(φ ± ξ)/cos ξ = sin φ ± μ cos φ,  cos(φ ± ξ)/cos ξ = cos φ ∓ μ sin φ.
    """
    phi, mu = (p.phi1, p.mu1) if n in (1, 3) else (p.phi2, p.mu2)
    sg = 1 if n in (1, 2) else -1
    s_a = sp.sin(phi) + sg * mu * sp.cos(phi)
    c_a = sp.cos(phi) - sg * mu * sp.sin(phi)
    return (-s_a, -c_a) if n in (1, 3) else (s_a, -c_a)


def check_construction(c, p) -> None:
    """Every constructed object against its independent closed form / meaning."""
    x1, x2, y = p.x1, p.x2, p.y
    S, C = closed_form_SC(*p.seven)
    origin = c["O"]
    assert origin == Point(0, 0)
    assert is_zero(c["P1"].x - x1) and is_zero(c["P1"].y - y)
    assert is_zero(c["P2"].x + x2) and is_zero(c["P2"].y - y)
    assert is_zero(c["P1x"].x - x1) and c["P1x"].y == 0
    assert is_zero(c["P2x"].x + x2) and c["P2x"].y == 0
    assert is_zero(c["O_M"].x - (x1 - x2) / 2) and c["O_M"].y == 0
    # axes
    assert on_line(origin, c["x-axis"]) and c["x-axis"].direction.y == 0
    assert on_line(origin, c["y-axis"]) and c["y-axis"].direction.x == 0
    for n in VN:
        Pi = c["P1"] if n in (1, 3) else c["P2"]
        foot = c["P2x"] if n in (1, 3) else c["P1x"]
        side, perp = c[f"side{n}"], c[f"perp{n}"]
        X, Y, V = c[f"X{n}"], c[f"Y{n}"], c[f"V{n}"]
        # the side: through P_i along the cone side (meaning, not closed form)
        assert on_line(Pi, side)
        assert is_zero(cross((side.direction.x, side.direction.y), side_direction(p, n)))
        # step (1): X_n is on the extended side and on the x-axis; O_M X_n = −S_n
        assert X.y == 0 and on_line(X, side)
        assert is_zero(X.x - c["O_M"].x + S[n - 1]), f"O_M X{n} != -S{n}"
        assert is_zero(c[f"OMX{n}"] + S[n - 1])
        # step (2): perpendicular from P2x (n = 1, 3) / P1x (n = 2, 4); Y_n on the y-axis
        assert on_line(foot, perp)
        assert is_zero(
            dot((perp.direction.x, perp.direction.y), (side.direction.x, side.direction.y))
        )
        assert Y.x == 0 and on_line(Y, perp)
        assert is_zero(Y.y + C[n - 1]), f"O Y{n} != -C{n}"
        assert is_zero(c[f"OY{n}"] + C[n - 1])
        # step (3): V_n = (S_n, C_n)
        assert is_zero(V.x - S[n - 1]) and is_zero(V.y - C[n - 1]), f"V{n}"
        # circle on the diameter O V_n (Thales, eq. (31))
        circ = c[f"circle{n}"]
        assert on_circle(origin, circ) and on_circle(V, circ)
        assert is_zero(circ.center.x - V.x / 2) and is_zero(circ.center.y - V.y / 2)
    for n, m in PAIRS:
        name = f"B{n}{m}"
        if name in c:
            B = c[name]
            Vn, Vm = c[f"V{n}"], c[f"V{m}"]
            assert not (is_zero(B.x) and is_zero(B.y)), f"{name} is O"
            assert on_circle(B, c[f"circle{n}"]) and on_circle(B, c[f"circle{m}"])
            # in the direction of B: k_n = V_n·e = V_m·e
            assert is_zero(dot(Vn, B) - dot(Vm, B))
        else:
            # skipped only when the circles touch at O: V_n, V_m, O collinear
            assert name in dict(c.skipped)
            assert is_zero(cross(c[f"V{n}"], c[f"V{m}"]))


# ---------------------------------------------------------------------------
# presets and random exact grasps
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", PRESET_NAMES)
def test_preset_construction_closed_form(name, preset_constructions):
    check_construction(preset_constructions[name], PRESET_PARAMS[name])


@settings(
    max_examples=10, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)
@given(exact_params())
def test_random_exact_construction(p):
    c = internal_force_diagram(p.grasp())
    check_construction(c, p)
    check_envelope_k(c, p, np.linspace(0, 2 * np.pi, 2001))
    check_envelope_arcs(c, p)


def test_fig6_by_hand(preset_constructions):
    """§4.1 values worked out by hand from the drawing (tan 7π/12 = −(2 + √3))."""
    c = preset_constructions["fig6"]
    r3 = sp.sqrt(3)
    # X1: from P1 = (√3/2, 1/2) along (−sin 7π/12, −cos 7π/12) down to y = 0:
    # X1.x = √3/2 − (1/2) tan(7π/12) = √3/2 + 1 + √3/2 = 1 + √3; O_M = (0, 0)
    assert is_zero(c["X1"].x - (1 + r3)) and c["O_M"] == Point(0, 0)
    assert c["V1"] == Point(-1 - r3, -sp.Rational(3, 2) - r3)
    assert c["V2"] == Point(r3, -sp.Rational(3, 2))


def test_concurrency_of_forces(preset_constructions):
    """§5 (ref. 15): B_nm, O and the meeting point of the cone sides are collinear.

    Where k_n = k_m both contact forces lie on the corresponding cone sides; three
    forces in equilibrium are concurrent, so the line of F_e through O passes through
    the meeting point Q of the two sides.  For n, m at the same contact (1-3, 2-4) that
    contact carries no force and the other contact's force line passes through O.
    """
    for name, c in preset_constructions.items():
        for n, m in PAIRS:
            B = c[f"B{n}{m}"] if f"B{n}{m}" in c else None
            if B is None:
                continue
            if (n, m) == (1, 3):
                Q = c["P2"]
            elif (n, m) == (2, 4):
                Q = c["P1"]
            else:
                s, t = c[f"side{n}"], c[f"side{m}"]
                # meet the two sides by Cramer's rule
                a = sp.Matrix([[s.direction.x, -t.direction.x], [s.direction.y, -t.direction.y]])
                rhs = sp.Matrix([t.point.x - s.point.x, t.point.y - s.point.y])
                u = a.LUsolve(rhs)[0]
                Q = Point(s.point.x + u * s.direction.x, s.point.y + u * s.direction.y)
            assert is_zero(cross(B, Q)), f"{name}: B{n}{m} not on the line O Q"


def test_numeric_grasp_same_V(preset_constructions):
    for name in PRESET_NAMES:
        p = PRESET_PARAMS[name]
        gf = Grasp(
            *[float(v) for v in (p.x1, p.x2, p.y, p.phi1, p.phi2)],
            mu1=float(p.mu1),
            mu2=float(p.mu2),
        )
        cf = internal_force_diagram(gf)
        ce = preset_constructions[name]
        for n in VN:
            for a, b in zip(cf[f"V{n}"], ce[f"V{n}"]):
                assert abs(float(a) - float(b)) < 1e-12
        ts = np.linspace(0, 2 * np.pi, 721)
        np.testing.assert_allclose(cf["envelope"].k(ts), ce["envelope"].k(ts), atol=1e-9)


# ---------------------------------------------------------------------------
# the envelope: k_grasp(θ) = max(0, k_1..k_4), eq. (25)
# ---------------------------------------------------------------------------
def k_grasp_first_principles(p, theta):
    S, C = closed_form_SC(*p.floats, lib=np)
    ks = np.array([S[n] * np.sin(theta) - C[n] * np.cos(theta) for n in range(4)])
    return np.maximum(ks.max(axis=0), 0.0), ks


def check_envelope_k(c, p, ts) -> None:
    """envelope.k, .winner, .polyline against max(0, k_1..k_4) of the closed form."""
    env = c["envelope"]
    # include the break angles and their neighbourhoods
    brk = np.array([float(a.theta_start) for a in env.arcs])
    ts = np.concatenate([ts, brk, brk + 1e-7, brk - 1e-7])
    want, ks = k_grasp_first_principles(p, ts)
    np.testing.assert_allclose(env.k(ts), want, atol=1e-9, rtol=0)
    # winner: the index of a k_n equal to the max (0 for the zero region)
    w = env.winner(ts)
    assert set(np.unique(w)) <= {0, 1, 2, 3, 4}
    pad = np.vstack([np.zeros_like(ts), ks])
    np.testing.assert_allclose(pad[w, np.arange(ts.size)], want, atol=1e-9)
    # polyline: points k(θ) e(θ)
    pl = env.polyline(361)
    t = np.linspace(0, 2 * np.pi, 361)
    kk, _ = k_grasp_first_principles(p, t)
    np.testing.assert_allclose(pl, np.column_stack([kk * np.sin(t), -kk * np.cos(t)]), atol=1e-9)


def check_envelope_arcs(c, p) -> None:
    """Arcs contiguous, covering 2π, end points on their circles (or O), right winner."""
    arcs = c["envelope"].arcs
    S, C = closed_form_SC(*p.floats, lib=np)
    assert len(arcs) >= 1
    total = sp.Integer(0)
    for i, a in enumerate(arcs):
        b = arcs[(i + 1) % len(arcs)]
        assert a.n in (0, 1, 2, 3, 4)
        assert a.n != b.n or len(arcs) == 1
        # contiguous: end of one arc is the start of the next (angle mod 2π and point)
        assert a.end == b.start
        assert is_zero(sp.sin(a.theta_end - b.theta_start)) and is_zero(
            sp.cos(a.theta_end - b.theta_start) - 1
        )
        assert 0 <= float(a.theta_start) < 2 * math.pi + 1e-15
        assert float(a.theta_end) > float(a.theta_start)
        total += a.theta_end - a.theta_start
        for q, th in ((a.start, a.theta_start), (a.end, a.theta_end)):
            if a.n == 0:
                assert q == Point(0, 0)
            else:
                assert on_circle(q, c[f"circle{a.n}"])
                # and q is the polar point k_n(θ) e(θ) at its own angle
                t = float(th)
                kn = S[a.n - 1] * math.sin(t) - C[a.n - 1] * math.cos(t)
                scale = 1 + abs(S[a.n - 1]) + abs(C[a.n - 1])
                assert abs(float(q.x) - kn * math.sin(t)) < 1e-9 * scale
                assert abs(float(q.y) + kn * math.cos(t)) < 1e-9 * scale
        # inside the arc, circle n is the outermost (or all k_n ≤ 0 for n = 0)
        mid = (float(a.theta_start) + float(a.theta_end)) / 2
        want, ks = k_grasp_first_principles(p, np.array([mid]))
        if a.n == 0:
            assert want[0] == 0.0
        else:
            assert abs(ks[a.n - 1, 0] - want[0]) < 1e-12 * (1 + want[0]) and want[0] > 0
    assert is_zero(total - 2 * pi)


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_envelope_k_equals_max(name, preset_constructions):
    check_envelope_k(
        preset_constructions[name], PRESET_PARAMS[name], np.linspace(-np.pi, 3 * np.pi, 20001)
    )


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_envelope_arcs(name, preset_constructions):
    check_envelope_arcs(preset_constructions[name], PRESET_PARAMS[name])


# A grasp from below (φ = π/3 < π/2, y = 0, μ = 2): all V_n lie in y < 0, so for a force
# pointing up (θ = π, e = (0, 1)) every k_n = V_n·e = C_n is negative: a zero region.
ZERO_REGION = Params(
    sp.Integer(1),
    sp.Integer(1),
    sp.Integer(0),
    pi / 3,
    pi / 3,
    sp.Integer(2),
    sp.Integer(2),
    sp.atan(2),
    sp.atan(2),
)


def test_envelope_zero_region():
    p = ZERO_REGION
    c = internal_force_diagram(p.grasp())
    check_construction(c, p)
    _, C = closed_form_SC(*p.seven)
    assert all(sp.N(Cn) < 0 for Cn in C)  # by hand: tan(π/3 ± atan 2) < 0 and y = 0
    check_envelope_k(c, p, np.linspace(0, 2 * np.pi, 20001))
    check_envelope_arcs(c, p)
    env = c["envelope"]
    assert any(a.is_zero for a in env.arcs)
    assert env.winner(np.pi) == 0 and env.k(np.pi) == 0
    ((t0, t1),) = env.zero_region
    assert float(t0) < np.pi < float(t1)


def test_envelope_can_detect_wrong_winner(preset_constructions):
    # sanity of the check above: circle 3 is not outermost everywhere
    p = PRESET_PARAMS["table1a"]
    ts = np.linspace(0, 2 * np.pi, 100)
    want, ks = k_grasp_first_principles(p, ts)
    assert np.abs(np.maximum(ks[2], 0) - want).max() > 0.1


# ---------------------------------------------------------------------------
# the protocol
# ---------------------------------------------------------------------------
EXPECTED_NAMES = (
    ["O", "x-axis", "y-axis", "P1", "P2", "side1", "side3", "side2", "side4", "P1x", "P2x", "O_M"]
    + [f"{s}{n}" for n in VN for s in ("X", "perp", "Y", "OMX", "OY", "V")]
    + [f"circle{n}" for n in VN]
    + [f"B{n}{m}" for n, m in PAIRS]
)


@pytest.mark.parametrize("name", PRESET_NAMES)
def test_protocol(name, preset_constructions):
    c = preset_constructions[name]
    names = [s.name for s in c.steps]
    assert len(names) == len(set(names))
    assert set(EXPECTED_NAMES) <= set(names) | {n for n, _ in c.skipped}
    assert names[-1] == "envelope"
    made: set[str] = set()
    for i, s in enumerate(c.steps):
        assert s.index == i
        assert set(s.inputs) <= made, f"{s.name} uses {set(s.inputs) - made} before it is made"
        assert s.caption.strip() and s.ref.strip()
        assert s.instrument in {"ruler", "compass", "perpendicular", "mark"}
        made.add(s.name)
    assert set(INSTRUMENTS) == {"ruler", "compass", "perpendicular", "mark"}
    for n in VN:
        assert c.step(f"V{n}").key
        assert c.step(f"circle{n}").key
        assert not c.step(f"X{n}").key
        assert f"V{n} step (1)" in c.step(f"X{n}").ref
        assert f"V{n} step (2)" in c.step(f"perp{n}").ref
        assert f"V{n} step (2)" in c.step(f"Y{n}").ref
        assert f"V{n} step (3)" in c.step(f"V{n}").ref
        assert c.step(f"X{n}").ref.startswith("§3.3")
        assert c.step(f"X{n}").instrument == "ruler"
        assert c.step(f"perp{n}").instrument == "perpendicular"
        foot = "P2x" if n in (1, 3) else "P1x"
        assert c.step(f"perp{n}").inputs == (f"side{n}", foot)
    assert c.step("envelope").key


@pytest.mark.parametrize("name", ["fig6", "table1c"])
def test_upto(name, preset_constructions):
    c = preset_constructions[name]
    n = len(c.steps)
    for i in range(n):
        part = c.upto(i)
        assert len(part.steps) == i + 1
        assert part.steps == c.steps[: i + 1]
        for s in part.steps:
            assert part[s.name] == c[s.name]
        later = c.steps[i + 1].name if i + 1 < n else None
        if later is not None:
            with pytest.raises(KeyError):
                part[later]
    assert len(c.upto(-1).steps) == n
    with pytest.raises(IndexError):
        c.upto(n)


def test_exact_construction_has_no_floats(preset_constructions):
    for c in preset_constructions.values():
        for s in c.steps:
            obj = s.obj
            if isinstance(obj, Point):
                assert obj.is_exact, s.name
            elif isinstance(obj, sp.Expr):
                assert not obj.atoms(sp.Float), s.name
            elif isinstance(obj, Circle):
                assert obj.center.is_exact and not obj.radius2.atoms(sp.Float)
        assert c.conditions == ()  # numbers: conditions are checked, not assumed


# ---------------------------------------------------------------------------
# the general (symbolic) construction
# ---------------------------------------------------------------------------
@pytest.fixture(scope="module")
def symbolic_construction():
    return internal_force_diagram(Grasp.symbolic("mu"))


def test_symbolic_construction(symbolic_construction):
    c = symbolic_construction
    assert "envelope" not in c
    S, C = closed_form_SC(gs.x1, gs.x2, gs.y, gs.phi1, gs.phi2, gs.mu1, gs.mu2)
    for n in VN:
        V = c[f"V{n}"]
        assert sp.cancel(V.x - S[n - 1]) == 0, f"S{n}"
        assert sp.cancel(V.y - C[n - 1]) == 0, f"C{n}"
        X, Y = c[f"X{n}"], c[f"Y{n}"]
        assert sp.cancel(X.x - c["O_M"].x + S[n - 1]) == 0
        assert sp.cancel(Y.y + C[n - 1]) == 0
    assert sp.cancel(c["O_M"].x - (gs.x1 - gs.x2) / 2) == 0


def test_symbolic_conditions(symbolic_construction):
    conds = symbolic_construction.conditions
    assert conds
    s1, c1, s2, c2 = (sp.sin(gs.phi1), sp.cos(gs.phi1), sp.sin(gs.phi2), sp.cos(gs.phi2))

    def listed(expr):
        # some condition is a constant multiple of expr
        return any(sp.cancel(k / expr).is_number for k in conds)

    # denominators of tan(φ ± ξ) in the μ form: the cone sides are not parallel to the x-axis
    assert listed(c1 - gs.mu1 * s1)
    assert listed(c2 - gs.mu2 * s2)
    assert listed(c1 + gs.mu1 * s1)
    assert listed(c2 + gs.mu2 * s2)
    assert not listed(gs.x1 + 7)  # the check above can fail
    for k in conds:
        assert k.free_symbols and k != 0
