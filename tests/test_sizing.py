"""Sizing in newtons (issue 13 §2), checked against values derived here from first principles.

The reference is a linear program written in this file on the *world-frame* contact
forces f1, f2 of a part held at two contacts, without the paper's equations:

    f1 + f2 + f = 0,  (p1 − c) × f1 + (p2 − c) × f2 = 0     (balance of the load f at c)
    |f_i · t_i| <= μ_i f_i · n_i                             (the friction cones, exact in 2D)
    minimise K = (f2 − f1) · u / 2,  u = (p1 − p2)/|p1 − p2|

K is the mean push of the two contacts towards each other along the line: the
squeeze per jaw.  The required squeeze is max(0, K*).  Worst cases over orientations
and accelerations are checked by brute force over grids of gravity and acceleration
directions, the issue's worked example by hand.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from _hang import no_hang
from graspcompass import Grasp, place_grasp
from graspcompass.errors import InputError, NonFiniteValueError, WrongTypeError
from graspcompass.sizing import (
    MissingUnitError,
    NotForceClosureError,
    SizingError,
    UnknownUnitError,
    force_closure,
    least_mu,
    size_gripper,
    vendor_squeeze,
    worst_squeeze_many,
)
from graspcompass.sizing.units import length_value, mass_value, split_unit
from graspcompass.world import FrictionConeError

HIGHS = dict(primal_feasibility_tolerance=1e-10, dual_feasibility_tolerance=1e-10)
G_ISSUE = 9.81


# -- the first-principles reference -----------------------------------------------------------
def lp_squeeze(p1, p2, n1, n2, mu1, mu2, com, load):
    """Least squeeze per jaw for the load vector ``load`` at ``com``, and the contact forces."""
    p1, p2, n1, n2, c, f = (np.asarray(v, float) for v in (p1, p2, n1, n2, com, load))
    n1, n2 = n1 / np.linalg.norm(n1), n2 / np.linalg.norm(n2)
    t1, t2 = np.array([-n1[1], n1[0]]), np.array([-n2[1], n2[0]])
    u = (p1 - p2) / np.linalg.norm(p1 - p2)
    r1, r2 = p1 - c, p2 - c
    # variables x = (f1x, f1y, f2x, f2y)
    A_eq = np.array([[1, 0, 1, 0], [0, 1, 0, 1], [-r1[1], r1[0], -r2[1], r2[0]]], float)
    b_eq = np.array([-f[0], -f[1], 0.0])
    rows = []
    for i, (n, t, mu) in enumerate(((n1, t1, mu1), (n2, t2, mu2))):
        for sg in (1, -1):  # sg t·f_i − μ n·f_i <= 0
            row = np.zeros(4)
            row[2 * i : 2 * i + 2] = sg * t - mu * n
            rows.append(row)
    cost = np.concatenate([-u, u]) / 2
    res = linprog(
        cost,
        A_ub=np.array(rows),
        b_ub=np.zeros(4),
        A_eq=A_eq,
        b_eq=b_eq,
        bounds=[(None, None)] * 4,
        method="highs",
        options=HIGHS,
    )
    assert res.status == 0, res.message
    return max(0.0, float(res.fun)), res.x


def e(theta: float) -> np.ndarray:
    """The paper's direction (26) in the world frame: θ counter-clockwise from −y."""
    return np.array([math.sin(theta), -math.cos(theta)])


class Part:
    """A part in one world frame: contacts, inward normals, friction, centre of mass."""

    def __init__(self, name, p1, p2, n1, n2, mu1, mu2, com, mass, accel=0.0):
        self.name, self.mass, self.accel = name, mass, accel
        self.p1, self.p2, self.n1, self.n2 = p1, p2, n1, n2
        self.mu1, self.mu2, self.com = mu1, mu2, com

    def world(self, exact: bool = False):
        conv = str if exact else float
        return place_grasp(
            [tuple(map(conv, self.p1)), tuple(map(conv, self.p2))],
            [tuple(map(conv, self.n1)), tuple(map(conv, self.n2))],
            mu=(conv(self.mu1), conv(self.mu2)),
            com=tuple(map(conv, self.com)),
        )

    def lp(self, load):
        return lp_squeeze(
            self.p1, self.p2, self.n1, self.n2, float(self.mu1), float(self.mu2), self.com, load
        )


def _unit(deg: float, inward_x: float) -> tuple[str, str]:
    """A normal tilted by ``deg`` from ±x, as exact-looking text (cos, sin to 17 digits)."""
    a = math.radians(deg)
    return (repr(inward_x * math.cos(a)), repr(math.sin(a)))


PARTS = [
    # the issue's worked example: jaws 100 mm apart, CoM 25 mm towards jaw A
    Part(
        "worked",
        ("0.05", "0"),
        ("-0.05", "0"),
        ("-1", "0"),
        ("1", "0"),
        "0.3",
        "0.3",
        ("0.025", "0"),
        1.0,
    ),
    Part(
        "centred",
        ("0.05", "0"),
        ("-0.05", "0"),
        ("-1", "0"),
        ("1", "0"),
        "0.3",
        "0.3",
        ("0", "0"),
        1.0,
    ),
    Part(
        "offset-below",
        ("0.04", "0.01"),
        ("-0.06", "0.01"),
        ("-1", "0"),
        ("1", "0"),
        "0.4",
        "0.4",
        ("0.01", "-0.02"),
        0.5,
        3.0,
    ),
    Part(
        "unequal-friction",
        ("0.03", "0"),
        ("-0.03", "0"),
        ("-1", "0"),
        ("1", "0"),
        "0.2",
        "0.6",
        ("-0.01", "-0.005"),
        2.0,
        1.5,
    ),
    Part(
        "tilted-jaws",
        ("0.04", "0"),
        ("-0.04", "0"),
        ("-0.96", "0.28"),
        ("0.8", "0.6"),
        "0.8",
        "1",
        ("0.005", "-0.01"),
        0.75,
        2.0,
    ),
    Part(
        "rotated-frame",
        ("0.03", "0.04"),
        ("-0.03", "-0.04"),
        ("-0.6", "-0.8"),
        ("0.6", "0.8"),
        "0.5",
        "0.35",
        ("0.012", "0"),
        1.2,
        9.80665,
    ),
    Part(
        "heavy-rubber",
        ("0.1", "0.02"),
        ("-0.1", "0.02"),
        ("-1", "0"),
        ("1", "0"),
        "1.2",
        "1.2",
        ("-0.06", "-0.03"),
        5.0,
        0.5,
    ),
]
PART_IDS = [p.name for p in PARTS]


# -- the worked example by hand ---------------------------------------------------------------
def test_worked_example_by_hand() -> None:
    """1 kg, jaws 100 mm apart, μ = 0.3, CoM 25 mm towards jaw A (issue 13 §2).

    By hand: the jaws are parallel, x1 = 25 mm, x2 = 75 mm, y = 0, φ = π/2, so the
    cone sides have tan(π/2 ± ξ) = ∓1/μ and V_n = (∓D/2, ∓x/μ): the longest is
    V_1 = (−0.05, −0.25), |V_1| = sqrt(0.065).  Worst squeeze per jaw
    m g |V_1| / D = 9.81 · 0.254951 / 0.1 = 25.01 N.  The vendor formula per jaw:
    m g / (2μ) = 9.81 / 0.6 = 16.35 N.
    """
    wg = PARTS[0].world(exact=True)
    s = size_gripper(wg, "1kg", g="9.81")
    hand = sp.Rational(981, 100) * sp.sqrt(sp.Rational(65, 1000)) / sp.Rational(1, 10)
    assert sp.simplify(s.worst_squeeze - hand) == 0 and s.exact
    assert round(float(s.worst_squeeze), 1) == 25.0
    assert s.vendor_squeeze == sp.Rational(327, 20) and float(s.vendor_squeeze) == 16.35
    assert s.worst_ratio == pytest.approx(25.0107 / 16.35, rel=1e-5)
    # the part slips at jaw A (nearer the CoM: it carries 3/4 of the load), sliding down
    assert (s.worst_slipping_contact, s.worst_side) == ("A", 1)
    assert s.worst_slip_direction == pytest.approx((0.0, -1.0))
    # worst load along V_1: θ = atan2(S, −C) = atan2(−0.05, 0.25) = −11.31°
    assert s.worst_direction_deg == pytest.approx(360 - math.degrees(math.atan(0.2)))
    # the same from the LP at that load, and the total squeeze is twice it
    load = 9.81 * e(math.radians(s.worst_direction_deg))
    assert PARTS[0].lp(load)[0] == pytest.approx(25.0107, rel=1e-5)
    assert size_gripper(wg, 1, g="9.81", per="total").worst_squeeze == 2 * s.worst_squeeze
    # standard gravity is the default: 25.00 N and 16.34 N
    d = size_gripper(wg, "1000g").to_dict()
    assert round(d["worst_squeeze_N"], 2) == 25.0 and round(d["vendor_squeeze_N"], 2) == 16.34


def test_centred_part_loaded_along_the_pads_is_the_vendor_formula() -> None:
    """The vendor formula is right exactly where it claims to be, and only there."""
    wg = PARTS[1].world(exact=True)
    up = size_gripper(wg, 1, gravity=(0, -1), accel=(0, "0.5g"), safety=2)  # lifted at g/2
    assert up.squeeze == up.vendor_squeeze and up.ratio == 1.0
    assert up.worst_squeeze > up.vendor_squeeze  # but not in every orientation
    ball = size_gripper(wg, 1, gravity=(0, -1), accel="0.5g", safety=2)  # |a| <= g/2 anywhere
    assert ball.squeeze > ball.vendor_squeeze


# -- six parts and more against the LP and brute force ----------------------------------------
@pytest.fixture(scope="module", params=PARTS, ids=PART_IDS)
def part(request):
    p = request.param
    return p, p.world(), size_gripper(p.world(), p.mass, accel=p.accel)


def test_worst_over_orientations_and_accelerations_matches_lp_and_brute_force(part) -> None:
    p, wg, s = part
    g, A = 9.80665, p.accel
    # (1) the claimed worst is reached: the LP at the claimed worst load (|f| = m(g + A))
    load = p.mass * (g + A) * e(math.radians(s.worst_direction_deg))
    lp, _ = p.lp(load)
    assert lp == pytest.approx(float(s.worst_squeeze), rel=1e-7)
    # (2) nothing is worse: brute force over gravity directions × acceleration directions
    #     (the closed form k_n of the model at each load), and the LP at scattered loads
    th = np.radians(np.arange(0, 360, 2.5))
    gv = p.mass * g * np.stack([np.sin(th), -np.cos(th)], -1)
    av = p.mass * A * np.stack([np.sin(th), -np.cos(th)], -1)
    loads = (gv[:, None, :] + av[None, :, :]).reshape(-1, 2)
    brute = _model_squeeze(wg, loads)
    assert brute.max() <= float(s.worst_squeeze) * (1 + 1e-12)
    assert brute.max() >= float(s.worst_squeeze) * math.cos(math.radians(2.5))
    rng = np.random.default_rng(7)
    for f in loads[rng.choice(len(loads), 12, replace=False)]:
        assert p.lp(f)[0] == pytest.approx(_model_squeeze(wg, f[None])[0], rel=1e-7, abs=1e-9)
    # (3) the best orientation: no gravity direction needs less (brute force, the worst
    #     acceleration for each), and it is reached
    #     (sampling the acceleration ring every δ = 2.5° misses at most m A |V| (1 − cos δ/2)/D)
    per_g = brute.reshape(len(th), len(th)).max(axis=1)
    r = max(math.hypot(float(v.x), float(v.y)) for v in wg.grasp.V)
    slack = p.mass * A * r * (1 - math.cos(math.radians(1.25))) / float(wg.grasp.D)
    assert s.best_squeeze <= per_g.min() + slack + 1e-12
    gb = p.mass * g * e(math.radians(s.best_gravity_direction_deg))
    fine = np.radians(np.arange(0, 360, 0.01))
    ring = p.mass * A * np.stack([np.sin(fine), -np.cos(fine)], -1)
    at_best = _model_squeeze(wg, gb[None] + ring).max()
    assert at_best == pytest.approx(s.best_squeeze, rel=1e-8, abs=1e-12)


def _model_squeeze(wg, loads: np.ndarray) -> np.ndarray:
    """max(0, k_grasp(θ)) F_e / D for world load vectors, through Grasp.k_grasp (eq. (25))."""
    ex, ey = np.array(wg.ex, float), np.array(wg.ey, float)
    loads = np.asarray(loads, float)
    paper = np.stack([loads @ ex, loads @ ey], -1)
    fe = np.hypot(paper[:, 0], paper[:, 1])
    theta = np.arctan2(paper[:, 0], -paper[:, 1])
    return np.asarray(wg.grasp.k_grasp(theta)) * fe / float(wg.grasp.D)


@pytest.mark.parametrize("p", PARTS[2:5], ids=PART_IDS[2:5])
def test_given_gravity_tilts_and_acceleration_vector_against_brute_force(p) -> None:
    wg = p.world()
    g, A = 9.80665, p.accel
    grav, a = np.array([0.3, -1.0]), np.array([0.5, 1.0])
    ghat = grav / np.linalg.norm(grav)
    circle = np.stack(
        [np.sin(np.radians(np.arange(0, 360, 1.0))), -np.cos(np.radians(np.arange(0, 360, 1.0)))],
        -1,
    )
    # (a) the given orientation, ball |a'| <= A: the worst is on the ball's rim
    s = size_gripper(wg, p.mass, gravity=tuple(grav), accel=A)
    loads = p.mass * (g * ghat + A * circle)
    assert _model_squeeze(wg, loads).max() == pytest.approx(float(s.squeeze), rel=1e-4)
    assert _model_squeeze(wg, loads).max() <= float(s.squeeze) * (1 + 1e-12)
    worst_load = p.mass * (g * ghat + A * e(math.radians(s.accel_direction_deg) + math.pi))
    assert p.lp(worst_load)[0] == pytest.approx(float(s.squeeze), rel=1e-7)
    # (b) a given acceleration vector, tilts of ±25°
    tilt = math.radians(25)
    s = size_gripper(wg, p.mass, gravity=tuple(grav), accel=tuple(a), tilt="25deg")
    rho = np.radians(np.linspace(-25, 25, 2001))
    w = g * ghat - a
    rot = np.stack(
        [np.cos(rho) * w[0] - np.sin(rho) * w[1], np.sin(rho) * w[0] + np.cos(rho) * w[1]], -1
    )
    brute = _model_squeeze(wg, p.mass * rot)
    assert brute.max() == pytest.approx(float(s.squeeze), rel=1e-6)
    assert brute.max() <= float(s.squeeze) * (1 + 1e-12)
    assert brute.min() >= s.best_squeeze * (1 - 1e-9) - 1e-12
    gb = e(math.radians(s.best_gravity_direction_deg))  # reached, within the tilts
    best_rho = math.atan2(ghat[0] * gb[1] - ghat[1] * gb[0], ghat @ gb)
    assert abs(best_rho) <= tilt + 1e-12
    wb = np.array(
        [
            math.cos(best_rho) * w[0] - math.sin(best_rho) * w[1],
            math.sin(best_rho) * w[0] + math.cos(best_rho) * w[1],
        ]
    )
    assert _model_squeeze(wg, p.mass * wb[None])[0] == pytest.approx(s.best_squeeze, rel=1e-9)
    assert (
        abs(
            math.radians(
                ((s.gravity_direction_deg or 0) - math.degrees(math.atan2(ghat[0], -ghat[1])) + 180)
                % 360
                - 180
            )
        )
        <= tilt + 1e-12
    )
    # (c) any orientation with a given acceleration vector: the load m(gĝ − a) turns whole
    s2 = size_gripper(wg, p.mass, gravity=tuple(grav), accel=tuple(a), tilt="180deg")
    r = max(math.hypot(float(v.x), float(v.y)) for v in wg.grasp.V)
    assert float(s2.squeeze) == pytest.approx(
        p.mass * np.linalg.norm(w) * r / float(wg.grasp.D), rel=1e-12
    )


def test_exact_and_float_paths_agree(part) -> None:
    p, wg, s = part
    se = size_gripper(p.world(exact=True), str(p.mass), accel=str(p.accel))
    assert se.exact and not s.exact
    for name in ("worst_squeeze", "squeeze", "vendor_squeeze"):
        assert float(getattr(se, name)) == pytest.approx(float(getattr(s, name)), rel=1e-12)
    assert se.worst_direction_deg == pytest.approx(s.worst_direction_deg, abs=1e-9)
    assert se.best_squeeze == pytest.approx(s.best_squeeze, rel=1e-9)
    assert (se.worst_slipping_contact, se.worst_side) == (s.worst_slipping_contact, s.worst_side)
    # the vectorised float64 path of many grasps gives the same number
    g = wg.grasp
    many = worst_squeeze_many(
        *(float(v) for v in (g.x1, g.x2, g.y, g.phi1, g.phi2, g.mu1, g.mu2)), p.mass, accel=p.accel
    )
    assert float(many) == pytest.approx(float(s.worst_squeeze), rel=1e-9)


def test_slipping_contact_and_way_from_the_lp(part) -> None:
    """At the worst load the LP's contact force at the slipping contact is on its cone's edge,
    and its friction on the part opposes the reported slip direction."""
    p, _, s = part
    load = p.mass * (9.80665 + p.accel) * e(math.radians(s.worst_direction_deg))
    _, x = p.lp(load)
    i = "AB".index(s.worst_slipping_contact)  # place_grasp names the first contact A
    n = np.array([float(v) for v in (p.n1, p.n2)[i]])
    n /= np.linalg.norm(n)
    f = x[2 * i : 2 * i + 2]
    fn = f @ n
    ft = f - fn * n
    mu = float((p.mu1, p.mu2)[i])
    assert np.linalg.norm(ft) == pytest.approx(mu * fn, rel=1e-6)
    slip = np.array(s.worst_slip_direction)
    assert abs(slip @ n) < 1e-12 and ft @ slip < 0


# -- the key identity of the closed form, proved ----------------------------------------------
def test_key_identity_of_the_disc_maximum_is_proved() -> None:
    """(V·e(θ))² + (V × e(θ))² = |V|² for the paper's symbolic V_1 (eqs. (28), (29)), so
    k_n(θ) <= |V_n| with equality at e(θ) = V_n/|V_n|: the maximum over a disc of loads of
    centre c and radius r is V_n·c + r|V_n|, and over all orientations (g + A)|V_n|."""
    from graspcompass.proof import Status, prove_identity
    from graspcompass.symbols import theta

    g = Grasp.symbolic("mu")
    S, C = g.S[0], g.C[0]
    k = S * sp.sin(theta) - C * sp.cos(theta)  # k_1 (eq. (27))
    cross = S * sp.cos(theta) + C * sp.sin(theta)
    with no_hang("prove_identity", 60):
        r = prove_identity(k**2 + cross**2, S**2 + C**2)
    assert r.status is Status.PROVED, r


# -- hypothesis: random parts ------------------------------------------------------------------
@st.composite
def random_parts(draw):
    d = draw(st.floats(0.02, 0.3))
    t = draw(st.floats(0.05, 0.95))
    off = draw(st.floats(0.0, 0.1))
    mu1, mu2 = draw(st.floats(0.15, 1.5)), draw(st.floats(0.15, 1.5))
    a1 = draw(st.floats(-0.9, 0.9)) * math.atan(mu1)
    a2 = draw(st.floats(-0.9, 0.9)) * math.atan(mu2)
    beta = draw(st.floats(-math.pi, math.pi))
    rot = np.array([[math.cos(beta), -math.sin(beta)], [math.sin(beta), math.cos(beta)]])
    p1, p2 = rot @ [d / 2, 0.0], rot @ [-d / 2, 0.0]
    n1 = rot @ [-math.cos(a1), math.sin(a1)]
    n2 = rot @ [math.cos(a2), math.sin(a2)]
    com = rot @ [d / 2 - t * d, -off]
    return tuple(map(tuple, (p1, p2, n1, n2))), (mu1, mu2), tuple(com)


@settings(
    max_examples=25,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    phases=(Phase.explicit, Phase.reuse, Phase.generate),
)  # no shrinking: time budget
@given(random_parts(), st.floats(0.05, 20), st.floats(0, 20))
def test_random_parts_against_brute_force(part, mass, A) -> None:
    (p1, p2, n1, n2), (mu1, mu2), com = part
    wg = place_grasp([p1, p2], [n1, n2], mu=(mu1, mu2), com=com)
    s = size_gripper(wg, mass, accel=A)
    th = np.radians(np.arange(0, 360, 0.5))
    loads = mass * (9.80665 + A) * np.stack([np.sin(th), -np.cos(th)], -1)
    brute = _model_squeeze(wg, loads)
    assert brute.max() <= float(s.worst_squeeze) * (1 + 1e-9)
    assert brute.max() >= float(s.worst_squeeze) * math.cos(math.radians(0.25)) * (1 - 1e-9)
    assert float(size_gripper(wg, mass, accel=A, per="total").worst_squeeze) == pytest.approx(
        2 * float(s.worst_squeeze), rel=1e-15
    )
    # best orientation (ball of accelerations at each): brute force over gravity directions
    gl = mass * 9.80665 * np.stack([np.sin(th), -np.cos(th)], -1)
    ring = mass * A * np.stack([np.sin(th[::8]), -np.cos(th[::8])], -1)  # every 4°
    per_g = (
        _model_squeeze(wg, (gl[:, None] + ring[None]).reshape(-1, 2))
        .reshape(len(th), -1)
        .max(axis=1)
    )
    r = max(math.hypot(float(v.x), float(v.y)) for v in wg.grasp.V)
    slack = mass * A * r * (1 - math.cos(math.radians(2))) / float(wg.grasp.D)
    assert s.best_squeeze <= per_g.min() * (1 + 1e-9) + slack
    # a larger μ never needs more squeeze
    more = place_grasp([p1, p2], [n1, n2], mu=(mu1 * 1.5, mu2 * 1.5), com=com)
    assert float(size_gripper(more, mass, accel=A).worst_squeeze) <= float(s.worst_squeeze) * (
        1 + 1e-12
    )


# -- inverse questions -------------------------------------------------------------------------
def test_least_mu_for_parallel_jaws_by_hand() -> None:
    """Parallel jaws, y = 0: per jaw m(g + A) sqrt((D/2)² + (x/μ)²)/D <= F, so
    μ = x / sqrt((F D / m(g + A))² − (D/2)²) with x = max(x1, x2)."""
    wg = PARTS[0].world()
    F, m, A = 40.0, 1.0, 2.0
    r = least_mu(wg, f"{F}N", m, accel=A)
    D, x = 0.1, 0.075
    hand = x / math.sqrt((F * D / (m * (9.80665 + A))) ** 2 - (D / 2) ** 2)
    assert r.mu == pytest.approx(hand, rel=1e-10) and r.mu_force_closure == 0.0
    # at that μ the squeeze is the limit; the LP agrees at the worst load
    at = place_grasp(
        PARTS[0].world().contacts, PARTS[0].world().normals, mu=(r.mu, r.mu), com=(0.025, 0.0)
    )
    s = size_gripper(at, m, accel=A)
    assert float(s.worst_squeeze) == pytest.approx(F, rel=1e-10)
    load = m * (9.80665 + A) * e(math.radians(s.worst_direction_deg))
    lp, _ = lp_squeeze((0.05, 0), (-0.05, 0), (-1, 0), (1, 0), r.mu, r.mu, (0.025, 0), load)
    assert lp == pytest.approx(F, rel=1e-7)
    # with infinite friction the part still needs m(g + A)/2 per jaw: below that, no μ
    r = least_mu(wg, (9.80665 + A) / 2 * 0.999, m, accel=A)
    assert r.mu is None and r.squeeze_infinite_friction == pytest.approx((9.80665 + A) / 2)
    assert "no friction suffices" in r.message


def test_least_mu_tilted_jaws_has_a_force_closure_floor() -> None:
    p = PARTS[4]
    wg = p.world()
    r = least_mu(wg, 100, p.mass, per="total")
    # each normal makes atan(0.28/0.96) and atan(0.6/0.8) with the line: closure needs 0.75
    assert r.mu_force_closure == pytest.approx(0.75, rel=1e-12)
    assert r.mu > 0.75
    assert float(
        size_gripper(wg.grasp.replace(mu1=r.mu, mu2=r.mu), p.mass, per="total").worst_squeeze
    ) == pytest.approx(100, rel=1e-9)


def test_force_closure_verdict() -> None:
    ok = force_closure([(1, 0), (-1, 0)], [(-1, 0), (1, 0)], mu=("0.3", "0.3"))
    assert ok.holds and ok.message.startswith("force-closure")
    bad = force_closure(
        [("0.04", 0), ("-0.04", 0)], [("-0.8", "0.6"), (1, 0)], mu=("0.5", "0.5"), names=("L", "R")
    )
    assert not bad.holds and bad.least_mu[0] == pytest.approx(0.75)
    assert "squeezing harder cannot hold this part" in bad.message and "contact L" in bad.message
    away = force_closure([(1, 0), (-1, 0)], [(1, 0), (1, 0)], mu=(1, 1))
    assert not away.holds and away.least_mu[0] == math.inf and "no friction" in away.message
    # at the bound (μ equal to the tangent) it is not force-closure: exact decision
    edge = force_closure([(1, 0), (-1, 0)], [("-0.8", "0.6"), (1, 0)], mu=("0.75", 1))
    assert not edge.holds
    assert issubclass(NotForceClosureError, FrictionConeError)


# -- units and hostile input -------------------------------------------------------------------
def test_units() -> None:
    assert length_value("100mm", "x") == sp.Rational(1, 10)
    assert length_value("2.5 cm", "x") == sp.Rational(1, 40)
    assert length_value("1e3um", "x") == sp.Rational(1, 1000)
    assert mass_value("500g", "m") == sp.Rational(1, 2) and mass_value("2t", "m") == 2000
    assert mass_value(Fraction(3, 2), "m") == sp.Rational(3, 2)
    assert float(mass_value(1.5, "m")) == 1.5
    assert split_unit("sqrt(2)/2 mm", "length", "x") == ("sqrt(2)/2", "mm")
    with pytest.raises(UnknownUnitError, match="'lb' in '3 lb'"):
        mass_value("3 lb", "--mass")
    with pytest.raises(UnknownUnitError, match="'in'"):
        length_value("4in", "--p1")
    with pytest.raises(MissingUnitError, match="'30' needs a unit"):
        size_gripper(Grasp.preset("table1a"), 1, gravity=(0, -1), tilt="30")


@pytest.mark.parametrize(
    "kwargs, error, text",
    [
        (dict(mass=float("nan")), NonFiniteValueError, "nan"),
        (dict(mass="sqrt(-1)"), InputError, "not a real number"),
        (dict(mass=1j), InputError, "mass"),
        (dict(mass=-1), SizingError, "mass must be positive"),
        (dict(mass="0kg"), SizingError, "mass must be positive"),
        (dict(mass=True), WrongTypeError, "mass"),
        (dict(mass="5lb"), UnknownUnitError, "5lb"),
        (dict(mass=1, g=0), SizingError, "g"),
        (dict(mass=1, safety="1/2"), SizingError, "safety factor must be at least 1"),
        (dict(mass=1, per="both"), SizingError, "'jaw' or 'total'"),
        (dict(mass=1, accel=-2), SizingError, "acceleration bound"),
        (dict(mass=1, accel=(1, 2)), SizingError, "needs the gravity direction"),
        (dict(mass=1, tilt="5deg"), SizingError, "needs the gravity direction"),
        (dict(mass=1, gravity=(0, 0)), SizingError, "zero vector"),
        (dict(mass=1, gravity="down"), WrongTypeError, "pair"),
        (dict(mass="__import__('os')"), InputError, "cannot read"),
    ],
)
def test_hostile_input_is_refused_with_a_named_error(kwargs, error, text) -> None:
    with no_hang("size_gripper", 30), pytest.raises(error, match=text.replace("(", r"\(")):
        size_gripper(Grasp.preset("table1a"), **kwargs)


def test_hostile_grasps() -> None:
    with pytest.raises(WrongTypeError, match="WorldGrasp"):
        size_gripper("table1a", 1)
    with pytest.raises(SizingError, match="symbolic"):
        size_gripper(Grasp.symbolic("mu"), 1)
    with pytest.raises(FrictionConeError, match="does not contain"):
        place_grasp([(0.04, 0), (-0.04, 0)], [(-0.8, 0.6), (1, 0)], mu=(0.5, 0.5), com=(0, 0))
    with pytest.raises(InputError):
        vendor_squeeze(1, "-0.3")
    with pytest.raises(SizingError, match="force limit"):
        least_mu(Grasp.preset("table1a"), "-3N", 1)
    with pytest.raises(UnknownUnitError, match="lbf"):
        least_mu(Grasp.preset("table1a"), "3lbf", 1)


def test_result_is_immutable_and_says_per_jaw_or_total() -> None:
    s = size_gripper(Grasp.preset("fig6"), 1, accel=1, safety=2)
    with pytest.raises(AttributeError):
        s.squeeze = 0  # type: ignore[misc]
    d = s.to_dict()
    assert d["per"] == "jaw" and "per jaw" in d["per_note"]
    t = size_gripper(Grasp.preset("fig6"), 1, accel=1, safety=2, per="total").to_dict()
    assert t["per"] == "total" and t["worst_squeeze_N"] == pytest.approx(2 * d["worst_squeeze_N"])
    assert t["vendor_squeeze_N"] == pytest.approx(2 * d["vendor_squeeze_N"])
    assert t["ratio"] == pytest.approx(d["ratio"])
    s1 = size_gripper(Grasp.preset("fig6"), 1, accel=1)
    assert s.worst_squeeze == 2 * s1.worst_squeeze  # the safety factor multiplies
