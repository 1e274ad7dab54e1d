"""Tests of graspcompass.world: grasps in the user's frame (issue 13 §1).

Expected values are built in the test: paper-frame grasps are placed in the world by
rigid motions written here (rotations with rational sines and cosines, so exact data
stay exact), and the least internal force is checked against a small linear program
written from first principles in the world frame (friction cones, force and moment
balance about the centre of mass, the squeeze along P1P2), never against graspcompass.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog
from shapely.geometry import Polygon

from graspcompass import Grasp
from graspcompass.geometry.exact import canon
from graspcompass.world import (
    CoincidentContactsError,
    ContactOffOutlineError,
    FrictionConeError,
    NormalNotUnitError,
    NormalOutwardError,
    OutlineError,
    VertexContactError,
    WorldGraspError,
    place_grasp,
)

R = sp.Rational
SETTINGS = settings(
    max_examples=25, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)

#: rational points on the unit circle (Pythagorean triples), for exact rotations and normals
TRIPLES = [(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29), (0, 1, 1)]
UNIT = sorted(
    {(R(a * sa, c), R(b * sb, c)) for a, b, c in TRIPLES for sa in (1, -1) for sb in (1, -1)}
    | {(R(b * sb, c), R(a * sa, c)) for a, b, c in TRIPLES for sa in (1, -1) for sb in (1, -1)}
)


def rot(v, c, s):
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def move(p, c, s, t):
    q = rot(p, c, s)
    return (q[0] + t[0], q[1] + t[1])


@st.composite
def paper_grasps(draw, y_positive=True):
    """A valid exact paper-frame grasp: x1, x2, y, rational unit normals, μ inside (1)."""
    x1, x2 = (R(draw(st.integers(1, 40)), draw(st.integers(1, 9))) for _ in range(2))
    y = R(draw(st.integers(1 if y_positive else 0, 30)), draw(st.integers(1, 9)))
    # n1 points left (towards P2), n2 right; the cone must hold the line P1P2
    n1 = draw(st.sampled_from([u for u in UNIT if u[0] < 0]))
    n2 = draw(st.sampled_from([u for u in UNIT if u[0] > 0]))
    mu1 = abs(n1[1] / n1[0]) + R(draw(st.integers(1, 20)), 10)  # tan of the angle, plus some
    mu2 = abs(n2[1] / n2[0]) + R(draw(st.integers(1, 20)), 10)
    return x1, x2, y, n1, n2, mu1, mu2


@st.composite
def motions(draw):
    c, s = draw(st.sampled_from(UNIT))
    t = (
        R(draw(st.integers(-50, 50)), draw(st.integers(1, 7))),
        R(draw(st.integers(-50, 50)), draw(st.integers(1, 7))),
    )
    return c, s, t


def world_data(paper, motion, swap):
    """The paper-frame grasp placed by a rigid motion, contacts in the given order."""
    x1, x2, y, n1, n2, mu1, mu2 = paper
    c, s, t = motion
    a = (move((x1, y), c, s, t), rot(n1, c, s), mu1)
    b = (move((-x2, y), c, s, t), rot(n2, c, s), mu2)
    first, second = (b, a) if swap else (a, b)
    return dict(
        contacts=[first[0], second[0]],
        normals=[first[1], second[1]],
        mu=(first[2], second[2]),
        com=t,
    )


@SETTINGS
@given(paper_grasps(), motions(), motions(), st.booleans())
def test_rigid_motions_give_the_same_exact_grasp(paper, m1, m2, swap):
    """Placed anywhere, in either contact order, the grasp in the paper's frame is the same,
    parameter for parameter, and it is the one the motion started from."""
    x1, x2, y, n1, n2, mu1, mu2 = paper
    g1 = place_grasp(**world_data(paper, m1, False)).grasp
    wg2 = place_grasp(**world_data(paper, m2, swap))
    assert g1 == wg2.grasp and g1.params == wg2.grasp.params
    assert wg2.swapped == swap and wg2.names == (("B", "A") if swap else ("A", "B"))
    g = wg2.grasp
    assert (g.x1, g.x2, g.y, g.mu1, g.mu2) == (x1, x2, y, mu1, mu2)  # μ follows its contact
    # φ as the paper defines it: n1 = (-sin φ1, -cos φ1), n2 = (sin φ2, -cos φ2)
    assert canon(g.s1 + n1[0]) == 0 and canon(g.c1 + n1[1]) == 0
    assert canon(g.s2 - n2[0]) == 0 and canon(g.c2 + n2[1]) == 0
    # the frame maps back: the contacts and the paper's axes
    c, s, t = m2
    assert wg2.to_world((x1, y)) == tuple(canon(v) for v in move((x1, y), c, s, t))
    assert wg2.vector_to_world((0, -1)) == tuple(canon(v) for v in rot((0, -1), c, s))


def float_world(paper, angle, t, swap):
    x1, x2, y, n1, n2, mu1, mu2 = (
        tuple(float(v) for v in p) if isinstance(p, tuple) else float(p) for p in paper
    )
    c, s = math.cos(angle), math.sin(angle)
    return world_data((x1, x2, y, n1, n2, mu1, mu2), (c, s, t), swap)


@SETTINGS
@given(
    paper_grasps(),
    st.floats(-math.pi, math.pi),
    st.floats(-3, 3),
    st.floats(-3, 3),
    st.booleans(),
    st.floats(0, 2 * math.pi),
)
def test_rigid_motions_float(paper, angle, tx, ty, swap, theta_w):
    """Floats: the same paper-frame parameters to 1e-12, and the same least squeeze
    k_grasp for the same force relative to the object (the world direction turned
    with the object)."""
    x1 = paper[0]
    wg0 = place_grasp(**float_world(paper, 0.0, (0.0, 0.0), False))
    wg = place_grasp(**float_world(paper, angle, (tx, ty), swap))
    p0, p = wg0.grasp.params, wg.grasp.params
    for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"):
        assert float(p[k]) == pytest.approx(float(p0[k]), abs=1e-12, rel=1e-12), k
    assert float(p["x1"]) == pytest.approx(float(x1), rel=1e-12)
    # one force, fixed to the object, seen in both placements
    f0 = (math.sin(theta_w), -math.cos(theta_w))
    f = rot(f0, math.cos(angle), math.sin(angle))
    assert wg.internal_force(f) == pytest.approx(wg0.internal_force(f0), rel=1e-9, abs=1e-12)
    t0 = wg0.theta_to_paper(theta_w)
    t1 = wg.theta_to_paper(theta_w + angle)
    assert wg.grasp.k_grasp(t1) == pytest.approx(wg0.grasp.k_grasp(t0), rel=1e-9, abs=1e-12)


# -- the least internal force from first principles (an LP in the world frame) ------------
def lp_least_squeeze(contacts, normals, mus, com, force):
    """min over contact forces f_A, f_B in the friction cones with f_A + f_B + F = 0 and
    zero moment about the centre of mass of the squeeze (f_A - f_B)·u/2 >= 0 along the
    unit u from A to B.  Returns (squeeze, f_A, f_B)."""
    a, b = (np.array(p, float) for p in contacts)
    c = np.array(com, float)
    u = (b - a) / np.linalg.norm(b - a)
    A_ub, b_ub = [], []
    for i, (n, mu) in enumerate(zip(normals, mus)):
        n = np.array(n, float)
        t = np.array([-n[1], n[0]])
        for sgn in (1, -1):  # mu (f·n) ± f·t >= 0, written as <= 0
            row = np.zeros(4)
            row[2 * i : 2 * i + 2] = -(mu * n + sgn * t)
            A_ub.append(row)
            b_ub.append(0.0)
    squeeze = np.concatenate([u / 2, -u / 2])
    A_ub.append(-squeeze)  # the squeeze is not negative (k >= 0)
    b_ub.append(0.0)
    ra, rb = a - c, b - c
    A_eq = [[1, 0, 1, 0], [0, 1, 0, 1], [-ra[1], ra[0], -rb[1], rb[0]]]
    b_eq = [-force[0], -force[1], 0.0]
    res = linprog(
        squeeze,
        A_ub=np.array(A_ub),
        b_ub=b_ub,
        A_eq=A_eq,
        b_eq=b_eq,
        bounds=[(None, None)] * 4,
        method="highs",
    )
    assert res.status == 0, res.message
    return res.fun, res.x[:2], res.x[2:]


@st.composite
def float_world_grasps(draw):
    """A world grasp from scratch: contacts anywhere, normals within their cones (with a
    margin), a centre of mass projecting between the contacts, on either side."""
    fl = st.floats(-5, 5)
    a = np.array([draw(fl), draw(fl)])
    b = np.array([draw(fl), draw(fl)])
    d = np.linalg.norm(b - a)
    assume(d > 0.5)
    u = (b - a) / d
    mus = [draw(st.floats(0.2, 1.5)), draw(st.floats(0.2, 1.5))]
    normals = []
    for direction, mu in ((u, mus[0]), (-u, mus[1])):
        xi = math.atan(mu)
        al = draw(st.floats(-0.95, 0.95)) * xi
        normals.append(tuple(rot(direction, math.cos(al), math.sin(al))))
    t = draw(st.floats(0.1, 0.9))
    h = draw(st.floats(-3, 3))
    com = a + t * (b - a) + h * np.array([-u[1], u[0]])
    return [tuple(a), tuple(b)], normals, mus, tuple(com)


@settings(max_examples=60, deadline=None, database=None)
@given(float_world_grasps(), st.floats(0, 2 * math.pi), st.floats(0.1, 20))
def test_least_internal_force_matches_an_lp(grasp, phi, magnitude):
    contacts, normals, mus, com = grasp
    wg = place_grasp(contacts, normals, mu=mus, com=com)
    force = (magnitude * math.cos(phi), magnitude * math.sin(phi))
    squeeze, fa, fb = lp_least_squeeze(contacts, normals, mus, com, force)
    scale = magnitude * (
        1 + max(abs(float(v)) for v in wg.grasp.S + wg.grasp.C) / float(wg.grasp.D)
    )
    assert wg.internal_force(force) == pytest.approx(squeeze, abs=1e-7 * scale)
    forces = wg.contact_forces(force)
    assert np.allclose(forces["A"], fa, atol=1e-6 * scale)
    assert np.allclose(forces["B"], fb, atol=1e-6 * scale)


def test_lp_on_exact_grasps_and_the_paper_example():
    """Table I(a) placed tilted: the exact F_int equals the LP, and k_grasp(0) = x2/μ1 = 2."""
    paper = (R(2), R(2), R(1), (R(-1), R(0)), (R(1), R(0)), R(1), R(6, 5))
    c, s, t = R(3, 5), R(4, 5), (R(1, 2), R(-7, 3))
    wg = place_grasp(**world_data(paper, (c, s, t), True))
    assert wg.grasp == Grasp.preset("table1a")
    down = rot((0, -10), c, s)  # 10 N along the object's -y: θ = 0
    assert wg.internal_force(down) == 5  # k/(x1 + x2) F_e = 2/4 · 10
    d = world_data(paper, (c, s, t), True)
    squeeze, _, _ = lp_least_squeeze(
        d["contacts"], d["normals"], d["mu"], d["com"], [float(v) for v in down]
    )
    assert squeeze == pytest.approx(5, abs=1e-9)
    fs = wg.contact_forces(down)
    total = [canon(fs["A"][i] + fs["B"][i] + down[i]) for i in (0, 1)]
    assert total == [0, 0]


# -- outlines ------------------------------------------------------------------------------
BOX = [(-2, -4), (2, -4), (2, 4), (-2, 4)]  # Fig. 7: the 4 × 8 rectangle


def test_rectangle_outline_exact_and_shapely():
    wg = place_grasp([(-2, 1), (2, 1)], outline=BOX[::-1], mu=("1.2", "1"))  # clockwise
    assert wg.grasp == Grasp.preset("table1a") and wg.names == ("B", "A")
    assert wg.normals == ((-1, 0), (1, 0)) and wg.origin == (0, 0)
    wf = place_grasp([(-2.0, 1.0), (2.0, 1.0)], outline=Polygon(BOX), mu=(1.2, 1.0))
    ref = Grasp.preset("table1a")
    for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"):
        assert float(wf.grasp.params[k]) == pytest.approx(float(ref.params[k]), abs=1e-14)


def test_tilted_part():
    """The rectangle turned by atan(4/3) and moved: the same grasp, exactly; as a shapely
    polygon to 1e-12; the world gravity lands at the paper's θ = -β."""
    c, s, t = R(3, 5), R(4, 5), (R(10), R(-3))
    box = [move(p, c, s, t) for p in BOX]
    contacts = [move((2, 1), c, s, t), move((-2, 1), c, s, t)]
    wg = place_grasp(contacts, outline=box, mu=(1, "1.2"))
    assert wg.grasp == Grasp.preset("table1a") and wg.origin == t
    assert wg.beta == sp.atan2(s, c)
    assert wg.theta_to_paper(0) == -sp.atan(R(4, 3))
    wf = place_grasp(
        [tuple(float(v) for v in p) for p in contacts],
        outline=Polygon([tuple(float(v) for v in p) for p in box]),
        mu=(1, 1.2),
    )
    for k in ("x1", "x2", "y", "phi1", "phi2"):
        assert float(wf.grasp.params[k]) == pytest.approx(float(wg.grasp.params[k]), abs=1e-12)


U_SHAPE = [(0, 0), (6, 0), (6, 4), (4, 4), (4, 1), (2, 1), (2, 4), (0, 4)]  # non-convex


def test_non_convex_outline_centroid_and_normals():
    """A U: area 24 - 6 = 18, centroid y = (24·2 - 6·5/2)/18 = 11/6 (by hand)."""
    wg = place_grasp([(0, 3), (6, 3)], outline=U_SHAPE, mu=(1, 1))
    assert wg.origin == (3, R(11, 6))
    c = Polygon(U_SHAPE).centroid
    assert (c.x, c.y) == pytest.approx((3, 11 / 6), abs=1e-12)
    assert wg.normals == ((-1, 0), (1, 0)) and wg.names == ("B", "A")
    assert wg.grasp == Grasp(3, 3, R(7, 6), "pi/2", "pi/2", mu1=1, mu2=1)
    # inside the notch the inward normals point apart: an expanding grip is refused
    with pytest.raises(
        NormalOutwardError, match=r"contact A at \(4, 2\).*points away from contact B"
    ):
        place_grasp([(4, 2), (2, 2)], outline=U_SHAPE, mu=(1, 1))


def test_vertex_contacts():
    diamond = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    with pytest.raises(VertexContactError, match=r"contact A at \(1, 0\) is at a vertex"):
        place_grasp([(1, 0), (-1, 0)], outline=diamond, mu=(2, 2))
    wg = place_grasp([(1, 0), (-1, 0)], outline=diamond, mu=(2, 2), at_vertex="bisector")
    assert wg.normals == ((-1, 0), (1, 0))  # the bisector of the two inward edge normals
    assert wg.grasp == Grasp(1, 1, 0, "pi/2", "pi/2", mu1=2, mu2=2)
    # a normal given for the vertex contact is used instead
    n = (R(-3, 5), R(4, 5))
    wg = place_grasp([(1, 0), (-1, 0)], [n, None], outline=diamond, mu=(2, 2), at_vertex="bisector")
    assert wg.names == ("A", "B") and wg.normals == (n, (1, 0))


# -- refusals, each naming the contact -------------------------------------------------------
@pytest.mark.parametrize(
    "kwargs, error, words",
    [
        (
            dict(contacts=[(2, 1), (-2, 9)], outline=BOX, mu=(1, 1)),
            ContactOffOutlineError,
            "contact B at .-2, 9. does not lie on the outline",
        ),
        (
            dict(contacts=[(2.0, 1.0), (-2.1, 1.0)], outline=Polygon(BOX), mu=(1, 1)),
            ContactOffOutlineError,
            "contact B",
        ),
        (
            dict(contacts=[(2, 4), (-2, 1)], outline=BOX, mu=(1, 1)),
            VertexContactError,
            "contact A at .2, 4. is at a vertex",
        ),
        (
            dict(contacts=[(2, 1), (-2, 1)], normals=[(0, 0), (1, 0)], mu=(1, 1), com=(0, 0)),
            NormalNotUnitError,
            "contact A at .2, 1.: its normal .0, 0. is the zero vector",
        ),
        (
            dict(contacts=[(2, 1), (-2, 1)], normals=[(1, 0), (1, 0)], mu=(1, 1), com=(0, 0)),
            NormalOutwardError,
            "contact A at .2, 1.: its inward normal .1, 0. points away from contact B",
        ),
        (
            dict(contacts=[(2, 1), (-2, 1)], normals=[(-1, 0), (-1, 0)], outline=BOX, mu=(1, 1)),
            NormalOutwardError,
            "contact B at .-2, 1.: its normal .-1, 0. points out of the outline",
        ),
        (
            dict(
                contacts=[(R(1, 20), 0), (R(-1, 20), 0)],
                normals=[(R(-3, 5), R(4, 5)), (1, 0)],
                mu=("0.3", "0.3"),
                com=(0, "-0.01"),
            ),
            FrictionConeError,
            r"contact A at \(1/20, 0\): its friction cone \(μ = 3/10, half angle 16.7°\) does not "
            r"contain contact B at \(-1/20, 0\): the inward normal \(-3/5, 4/5\) makes 53.13°",
        ),
        (
            dict(
                contacts=[(2.0, 1.0), (-2.0, 1.0)],
                normals=[(-1.0, 0.0), (0.6, -0.8)],
                xi=("30deg", "30deg"),
                com=(0, 0),
            ),
            FrictionConeError,
            "contact B at .-2, 1.: its friction cone .half angle 30°",
        ),
        (
            dict(contacts=[(2, 1), (2, 1)], normals=[(-1, 0), (1, 0)], mu=(1, 1), com=(0, 0)),
            CoincidentContactsError,
            "contacts A and B are the same point",
        ),
        (
            dict(contacts=[(0, 0), (2, 2)], outline=[(0, 0), (2, 2), (2, 0), (0, 2)], mu=(1, 1)),
            OutlineError,
            "simple polygon",
        ),
    ],
)
def test_refusals_name_the_contact(kwargs, error, words):
    with pytest.raises(error, match=words) as info:
        place_grasp(**kwargs)
    assert isinstance(info.value, WorldGraspError) and isinstance(info.value, ValueError)


def test_names_and_input_errors():
    with pytest.raises(FrictionConeError, match="contact left jaw at"):
        place_grasp(
            [(2, 1), (-2, 1)],
            [(R(-3, 5), R(4, 5)), (1, 0)],
            mu=(1, 1),
            com=(0, 0),
            names=("left jaw", "right jaw"),
        )
    from graspcompass.errors import InputError

    with pytest.raises(InputError, match="contact B: give its friction"):
        place_grasp([(2, 1), (-2, 1)], [(-1, 0), (1, 0)], mu=(1, None), com=(0, 0))
    with pytest.raises(InputError, match="com: give the centre of mass"):
        place_grasp([(2, 1), (-2, 1)], [(-1, 0), (1, 0)], mu=(1, 1))
    with pytest.raises(InputError, match="contact A x"):
        place_grasp([("__import__('os')", 1), (-2, 1)], [(-1, 0), (1, 0)], mu=(1, 1), com=(0, 0))


def test_exact_text_stays_exact_and_floats_go_numeric():
    wg = place_grasp(
        [("0.05", 0), ("-0.05", 0)], [(-1, 0), (1, 0)], mu=("0.3", "0.3"), com=("0.025", "-0.01")
    )
    assert not wg.grasp.numeric and wg.grasp.x1 == R(1, 40) and wg.grasp.x2 == R(3, 40)
    wf = place_grasp(
        [(0.05, 0), (-0.05, 0)], [(-1, 0), (1, 0)], mu=("0.3", "0.3"), com=(0.025, -0.01)
    )
    assert wf.grasp.numeric and float(wf.grasp.x1) == pytest.approx(0.025, abs=1e-15)
    # the worked example: 1 kg, jaws 100 mm apart, μ = 0.3, CoM 25 mm off centre
    g = 9.80665
    assert float(wg.internal_force((0, -g))) == pytest.approx(
        lp_least_squeeze(
            [(0.05, 0), (-0.05, 0)], [(-1, 0), (1, 0)], (0.3, 0.3), (0.025, -0.01), (0, -g)
        )[0],
        rel=1e-9,
    )


def test_fig6_placed_in_the_world_and_mixed_inputs():
    """Fig. 6's circle: contacts on the unit circle, normals to its centre (§4.1)."""
    r3 = "sqrt(3)/2"
    wg = place_grasp(
        [(r3, "1/2"), ("-" + r3, "1/2")],
        [("-" + r3, "-1/2"), (r3, "-1/2")],
        xi=("pi/4", "pi/3"),
        com=(0, 0),
    )
    assert wg.grasp == Grasp.preset("fig6") and wg.beta == 0
    # a float force on an exact grasp gives floats; an exact force exact values
    f = wg.internal_force((0.0, -1.0))
    assert isinstance(f, float) and f == pytest.approx(float(wg.internal_force((0, -1))))
    assert all(isinstance(v, float) for v in wg.contact_forces((0.3, -1.0))["A"])
    assert wg.theta_to_world(0.5) == 0.5 and wg.theta_to_paper("pi/2") == sp.pi / 2


def test_more_refusals():
    from graspcompass.errors import InputError, SymbolicValueError

    ok = dict(contacts=[(2, 1), (-2, 1)], normals=[(-1, 0), (1, 0)], mu=(1, 1), com=(0, 0))
    with pytest.raises(InputError, match="different names"):
        place_grasp(**ok, names=("jaw", "jaw"))
    with pytest.raises(SymbolicValueError):
        place_grasp(**{**ok, "com": (sp.Symbol("c"), 0)})
    with pytest.raises(WorldGraspError, match="distance between contacts A and B"):
        place_grasp(
            [(0, 0), (1, "1 + sqrt(2)")],
            [(R(-3, 5), R(-4, 5)), (R(3, 5), R(4, 5))],
            mu=(5, 5),
            com=(1, 0),
        )
    with pytest.raises(InputError, match="force: the external force must not be zero"):
        place_grasp(**ok).internal_force((0, 0))


def test_centre_of_mass_on_the_contact_line_keeps_the_order():
    """y = 0: both directions of the line qualify; P1 is the first contact given, and the
    two orders give the grasp turned by a half turn (x1 ↔ x2, μ1 ↔ μ2, φ ↔ π - φ)."""
    n = [(R(-3, 5), R(4, 5)), (R(3, 5), R(4, 5))]
    ab = place_grasp([(3, 0), (-1, 0)], n, mu=(2, 3), com=(0, 0))
    ba = place_grasp([(-1, 0), (3, 0)], n[::-1], mu=(3, 2), com=(0, 0), names=("B", "A"))
    assert ab.names == ("A", "B") and ba.names == ("B", "A") and not ba.swapped
    g, h = ab.grasp, ba.grasp
    assert (g.x1, g.x2, g.y, g.mu1, g.mu2) == (3, 1, 0, 2, 3)
    assert (h.x1, h.x2, h.y, h.mu1, h.mu2) == (1, 3, 0, 3, 2)
    assert canon(g.s1 - R(3, 5)) == 0 and canon(g.c1 + R(4, 5)) == 0  # n1 = (-sin φ1, -cos φ1)
    assert canon(h.s1 - R(3, 5)) == 0 and canon(h.c1 - R(4, 5)) == 0  # turned: "up" is down
    assert ab.beta == 0 and ba.beta == sp.pi
    for t in (0.0, 0.7, 2.0, 4.0):  # one world force, two frames: the same squeeze
        assert g.internal_force(ab.theta_to_paper(t)) == pytest.approx(
            h.internal_force(ba.theta_to_paper(t)), abs=1e-12
        )
    assert ab.world_degrees(0) == 0.0 and ba.world_degrees(0) == 180.0


def test_shapely_outlines_non_convex_and_with_a_hole():
    wf = place_grasp([(0.0, 3.0), (6.0, 3.0)], outline=Polygon(U_SHAPE), mu=(1.0, 1.0))
    assert wf.origin == pytest.approx((3, 11 / 6), abs=1e-12)
    assert wf.normals[0] == pytest.approx((-1, 0)) and wf.names == ("B", "A")
    # a 6 × 6 plate with a 2 × 2 hole off centre: the centroid moves away from the hole
    plate = Polygon([(0, 0), (6, 0), (6, 6), (0, 6)], [[(3, 3), (5, 3), (5, 5), (3, 5)]])
    wg = place_grasp([(6.0, 2.0), (0.0, 2.0)], outline=plate, mu=(1.0, 1.0))
    cx = (36 * 3 - 4 * 4) / 32  # by hand: (36·3 - 4·4)/32
    assert wg.origin == pytest.approx((cx, cx), abs=1e-12)
    # the centre of mass above the contacts: the frame turns over, B becomes P1
    assert float(wg.grasp.y) == pytest.approx(cx - 2) and wg.names == ("B", "A")
    assert wg.normals == ((1.0, 0.0), (-1.0, 0.0))
    # on the hole's edges the inward normals point apart (into the plate): refused
    with pytest.raises(NormalOutwardError, match=r"contact A at \(3, 4\)"):
        place_grasp([(3.0, 4.0), (5.0, 4.0)], outline=plate, mu=(1.0, 1.0))
