"""The n-contact model, exact: the paper's V_1…V_4, Table I(c)'s redundancy, cdd, inputs."""

from __future__ import annotations

import itertools
import math
import random
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass.geometry.exact import approx, decide_zero
from graspcompass.grasp import Grasp, InvalidGraspError
from graspcompass.ncontact import (
    EffortError,
    InvalidContactError,
    NContactGrasp,
)

PRESETS = ["fig6", "table1a", "table1b", "table1c"]


def _same_point(a, b):
    return decide_zero(sp.sympify(a[0]) - b[0]) and decide_zero(sp.sympify(a[1]) - b[1])


def _candidate_set_is_V_and_O(grasp):
    h = NContactGrasp.from_grasp(grasp)
    Q = h.polygon()
    pts = [c.q for c in Q.all_candidates()]
    V = [tuple(v) for v in grasp.V]
    for v in V:  # every V_n of eqs. (28)-(39) is a dual vertex ...
        assert any(_same_point(p, v) for p in pts), (v, pts)
    for p in pts:  # ... and the only other one is O, from k >= 0
        assert any(_same_point(p, v) for v in V) or _same_point(p, (0, 0)), p
    return h, Q


@pytest.mark.parametrize("name", PRESETS)
def test_presets_reproduce_V1_to_V4_exactly(name):
    g = Grasp.preset(name)
    h, Q = _candidate_set_is_V_and_O(g)
    assert h.force_closure
    # the basis of V_n: the side of k_n plus both sides of the other contact (labels P1±, P2±)
    labels = h.constraint_labels()
    for n, v in enumerate(g.V, start=1):
        cand = next(c for c in Q.all_candidates() if _same_point(c.q, tuple(v)))
        names = {labels[r] for r in cand.bases[0]}
        other = {"P2+", "P2-"} if n in (1, 3) else {"P1+", "P1-"}
        assert other <= names, (n, names)
    for t in ["0", "pi/6", "2*pi/3", "5*pi/4", "-pi/12"]:
        assert decide_zero(h.k(t) - g.k_grasp(t)), (name, t)
    # 108° has opaque generators here and nested radicals in Grasp: compare to 25 digits
    assert abs(approx(h.k("108deg"), 40) - approx(g.k_grasp("108deg"), 40)) < 1e-25


def test_table1c_circle_4_is_redundant():
    """V_4 = (4/7, 10/7) lies strictly inside the triangle V_1 V_2 V_3 (Fig. 7(c))."""
    g = Grasp.preset("table1c")
    h = NContactGrasp.from_grasp(g)
    Q = h.polygon()
    red = [c.q for c in Q.redundant]
    assert any(_same_point(p, (sp.Rational(4, 7), sp.Rational(10, 7))) for p in red)
    assert len(Q.vertices) == 3
    # independent: barycentric coordinates of V4 in V1 V2 V3 are all positive
    (a, b, c, d) = [sp.Matrix(list(v)) for v in g.V]
    lam = sp.Matrix([[a[0], b[0], c[0]], [a[1], b[1], c[1]], [1, 1, 1]]).solve(
        sp.Matrix([d[0], d[1], 1])
    )
    assert all(x > 0 for x in lam)


def _random_rational_grasp(rng):
    while True:
        try:
            return Grasp(
                sp.Rational(rng.randint(2, 30), 10),
                sp.Rational(rng.randint(2, 30), 10),
                sp.Rational(rng.randint(0, 25), 10),
                sp.pi * sp.Rational(rng.randint(30, 70), 100),
                sp.pi * sp.Rational(rng.randint(30, 70), 100),
                mu1=sp.Rational(rng.randint(2, 15), 10),
                mu2=sp.Rational(rng.randint(2, 15), 10),
            )
        except InvalidGraspError:
            continue


def test_random_two_contact_grasps_reproduce_V_exactly():
    rng = random.Random(4)
    for _ in range(6):
        g = _random_rational_grasp(rng)
        h, _Q = _candidate_set_is_V_and_O(g)
        for t in ["pi/4", "11*pi/6"]:
            assert decide_zero(h.k(t) - g.k_grasp(t))


def test_float_grasp_matches_k_grasp():
    g = Grasp(1.3, 0.7, 0.4, 1.4, 1.6, mu1=0.6, mu2=0.9)
    t = np.linspace(0, 2 * math.pi, 361)
    assert np.allclose(NContactGrasp.from_grasp(g).k(t), g.k_grasp(t), rtol=1e-12, atol=1e-12)


def _unit(a, b):  # a rational unit vector from a Pythagorean parametrisation
    r = a * a + b * b
    return (Fraction(a * a - b * b, r), Fraction(2 * a * b, r))


def _rational_contacts(rng, n):
    out = []
    for _ in range(n):
        x, y = Fraction(rng.randint(-10, 10), 7), Fraction(rng.randint(-10, 10), 7)
        nx, ny = _unit(rng.choice([-1, 1]) * rng.randint(1, 5), rng.randint(1, 5))
        out.append((x, y, nx, ny, Fraction(rng.randint(1, 9), 10)))
    return out


def _cdd_points(contacts):
    """Projections -y_f of the vertices of {y : G^T y <= c} (sum of normal forces), by cdd.gmp."""
    cdd = pytest.importorskip("cdd.gmp", reason="pycddlib (GMP mode) is a GPL test extra")
    import cdd as cdd_root

    rows = []
    for x, y, nx, ny, mu in contacts:
        for s in (1, -1):
            dx, dy = nx - s * mu * ny, ny + s * mu * nx
            g = (dx, dy, x * dy - y * dx)
            rows.append([Fraction(1)] + [-v for v in g])  # 1 - g·y >= 0
    mat = cdd.matrix_from_array(rows, rep_type=cdd_root.RepType.INEQUALITY)
    gen = cdd.copy_generators(cdd.polyhedron_from_matrix(mat)).array
    verts = [(-r[1], -r[2]) for r in gen if r[0] == 1]
    rays = [(-r[1], -r[2]) for r in gen if r[0] == 0]
    return verts, rays


def _fraction_hull(points):
    pts = sorted(set(points))
    if len(pts) <= 2:
        return set(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lo, up = [], []
    for p in pts:
        while len(lo) >= 2 and cross(lo[-2], lo[-1], p) <= 0:
            lo.pop()
        lo.append(p)
    for p in reversed(pts):
        while len(up) >= 2 and cross(up[-2], up[-1], p) <= 0:
            up.pop()
        up.append(p)
    return set(lo[:-1] + up[:-1])


def test_exact_vertices_match_cdd_gmp_on_rational_grasps():
    pytest.importorskip("cdd.gmp", reason="pycddlib (GMP mode) is a GPL test extra")
    rng = random.Random(11)
    checked = 0
    for _ in range(40):
        n = rng.choice([3, 4])
        contacts = _rational_contacts(rng, n)
        g = NContactGrasp([tuple(str(v) for v in c) for c in contacts], exhaustive=True)
        try:
            Q = g.polygon()
        except Exception as exc:  # degenerate random draws (rank < 3)
            assert type(exc).__name__ == "DegenerateGraspError"
            continue
        verts, rays = _cdd_points(contacts)
        mine = {
            (Fraction(int(p[0].p), int(p[0].q)), Fraction(int(p[1].p), int(p[1].q)))
            for p in (c.q for c in Q.all_candidates())
        }
        assert mine == set(verts)  # the same dual vertices, projected
        screened = NContactGrasp(g.contacts).polygon()  # float screen + exact tiling
        assert [c.q for c in screened.candidates[: len(screened.vertex_index)]] == [
            c.q for c in Q.candidates[: len(Q.vertex_index)]
        ]
        assert g.force_closure == (not rays)
        if not rays:
            want = _fraction_hull(verts)
            got = {
                (Fraction(int(v.x.p), int(v.x.q)), Fraction(int(v.y.p), int(v.y.q)))
                for v in Q.vertices
            }
            assert got == want
            checked += 1
    assert checked >= 5


def test_exact_path_with_angles_in_degrees_agrees_with_floats():
    cs = [(1, 0, "180deg", "1/2"), (-1, "1/5", "10deg", "3/5"), ("1/5", -1, "95deg", "2/5")]
    g = NContactGrasp(cs)
    f = NContactGrasp(
        [
            (
                float(sp.sympify(x)),
                float(sp.sympify(y)),
                math.radians(float(a[:-3])),
                float(sp.sympify(m)),
            )
            for x, y, a, m in cs
        ]
    )
    assert g.force_closure and f.force_closure
    t = np.linspace(0, 2 * math.pi, 100)
    assert np.allclose(g.k(t), f.k(t), rtol=1e-9)
    v = g.k("pi/3")
    assert abs(float(v) - f.k(math.pi / 3)) < 1e-9


def test_forces_at_the_optimum_balance_the_load():
    g = NContactGrasp([(1, 0, -1, 0, "1/2"), (-1, 0, 1, 0, "1/2"), (0, -1, 0, 1, "1/2")])
    r = g.forces("pi/3")
    fx = sum(f[0] for f in r["forces"])
    fy = sum(f[1] for f in r["forces"])
    assert decide_zero(fx + sp.sin(sp.pi / 3)) and decide_zero(fy - sp.cos(sp.pi / 3))
    assert decide_zero(sum(r["weights"].values()) - r["effort"])  # effort = Σ normal forces
    torque = sum(c.p[0] * f[1] - c.p[1] * f[0] for c, f in zip(g.contacts, r["forces"]))
    assert decide_zero(torque)


def test_pair_effort_free_contacts_in_closure_give_zero():
    # contacts 3, 4 squeeze along a line with μ large: they alone are in force closure? no:
    # two contacts cannot resist every torque-free load, so add two more free ones
    cs = [(1, 0, -1, 0, 1), (-1, 0, 1, 0, 1), (0, 1, 0, -1, 1), (0, -1, 0, 1, 1)]
    g = NContactGrasp(cs, effort="pair:1,2")
    assert g.force_closure
    assert g.k(0) == 0  # contacts 3 and 4 (free) hold a downward load alone


def test_non_closure_arc_and_infinity():
    g = NContactGrasp([(1, 0, -1, 0, "1/2"), (0, -1, 0, 1, "1/2")])
    assert not g.force_closure
    assert g.k("pi") == sp.oo or g.k(0) == sp.oo


@settings(max_examples=60, deadline=None)
@given(
    st.one_of(
        st.none(),
        st.booleans(),
        st.text(max_size=8),
        st.floats(allow_nan=True),
        st.lists(st.integers(), max_size=7).filter(lambda v: len(v) not in (4, 5)),
        st.dictionaries(st.text(max_size=3), st.integers(), max_size=3),
    )
)
def test_hostile_contacts_are_refused_by_name(junk):
    with pytest.raises(InvalidContactError):
        NContactGrasp([junk, (1, 0, -1, 0, 1)])


@pytest.mark.parametrize("effort", ["paper", "pair:1,1", "pair:0,2", "nope", [1, 2], "pair:9,1"])
def test_bad_efforts_are_refused(effort):
    with pytest.raises(EffortError):
        NContactGrasp([(1, 0, -1, 0, 1), (-1, 0, 1, 0, 1), (0, 1, 0, -1, 1)], effort=effort)


def test_zero_normal_and_negative_mu_are_refused():
    with pytest.raises(InvalidContactError, match="zero"):
        NContactGrasp([(1, 0, 0, 0, 1), (-1, 0, 1, 0, 1)])
    with pytest.raises(InvalidContactError, match="μ"):
        NContactGrasp([(1, 0, -1, 0, "-1/2"), (-1, 0, 1, 0, 1)])


def test_bound_on_vertices():
    """At most 4n - 4 vertices for a linear effort without sign constraints."""
    rng = np.random.default_rng(3)
    from _ncontact_lp import random_contacts

    for n in (3, 4, 5):
        for _ in range(10):
            g = NContactGrasp(random_contacts(rng, n), effort="sum-normal")
            assert len(g.vertices()) <= 4 * n - 4
    assert list(itertools.islice(itertools.count(), 1))  # keep itertools used


def _cli(capsys, *argv):
    from graspcompass.cli import main

    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_cli_k_with_contacts_json(capsys):
    import json

    status, out, err = _cli(
        capsys,
        "k",
        "--contact",
        "1,0,-1,0,1/2",
        "--contact=-1,0,1,0,1/2",
        "--contact=0,-1,0,1,1/2",
        "--theta",
        "0,90deg",
        "--json",
    )
    assert status == 0, err
    rows = json.loads(out)
    assert [r["theta"] for r in rows] == ["0", "pi/2"]
    # by hand: a downward load needs N3 + μ(N1 + N2) >= 1, so N1 + N2 + N3 >= 1 (μ < 1), = 1
    # with the bottom contact alone
    assert rows[0]["k"] == pytest.approx(1.0, rel=1e-12)
    assert set(rows[0]["tight"]) >= {"P3+", "P3-"}


def test_cli_k_with_contacts_null_where_not_held(capsys):
    import json

    status, out, err = _cli(
        capsys,
        "k",
        "--contact",
        "1,0,-1,0,1/2",
        "--contact=0,-1,0,1,1/2",
        "--effort",
        "sum-normal",
        "--theta",
        "0,pi",
        "--json",
    )
    assert status == 0, err
    rows = json.loads(out)
    assert rows[0]["k"] is not None and rows[1]["k"] is None  # nothing pulls the object down


@pytest.mark.parametrize(
    "argv",
    [
        ["--contact", "1,0,-1,0,1/2"],
        ["--contact", "1,0,-1,0,1/2", "--contact", "1,2"],
        ["--contact", "1,0,-1,0,1/2", "--contact", "0,1,0,-1,x"],
        ["--contact", "1,0,0,0,1", "--contact", "0,1,0,-1,1"],
        ["--contact", "1,0,-1,0,1", "--contact", "0,1,0,-1,1", "--effort", "pair:1,7"],
    ],
)
def test_cli_k_with_contacts_refuses_bad_input(capsys, argv):
    status, _out, err = _cli(capsys, "k", *argv)
    assert status == 2 and err.count("\n") == 1 and "error" in err


def test_draw_ncontact_figure(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from graspcompass.render.ncontact import draw_ncontact

    g = NContactGrasp(
        [(1, 0, -1, 0, "1/2"), (0, -1, 0, 1, "1/2"), ("-1/2", "-1/2", "40deg", "3/10")]
    )
    fig = draw_ncontact(g)
    ax = fig.axes[0]
    assert len(ax.patches) >= len(g.vertices())  # a Thales circle per vertex (and arrows)
    assert "no force closure" in ax.get_title()
    fig.savefig(tmp_path / "n.png")
    assert (tmp_path / "n.png").stat().st_size > 10_000


def test_cli_draw_with_contacts(capsys, tmp_path):
    out = tmp_path / "n.svg"
    status, stdout, err = _cli(
        capsys,
        "draw",
        "--contact",
        "1,0,180deg,1/2",
        "--contact=-1/2,sqrt(3)/2,-60deg,1/2",
        "--contact=-1/2,-sqrt(3)/2,60deg,1/2",
        "-o",
        str(out),
    )
    assert status == 0, err
    assert out.read_text().lstrip().startswith("<?xml") and "wrote" in stdout


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.tuples(
            st.floats(-1.5, 1.5), st.floats(-1.5, 1.5), st.floats(0, 6.283), st.floats(0.1, 1.0)
        ),
        min_size=3,
        max_size=5,
    ),
    st.floats(0, 6.283),
)
def test_optimal_forces_balance_the_load_and_cost_v(raw, theta):
    """Primal check from first principles: nonnegative edge weights, the contact forces
    balance the load F_e e(θ) (force and moment about O), and their effort is v(θ)."""
    from graspcompass.ncontact import NContactError

    try:
        g = NContactGrasp([(x, y, a, m) for x, y, a, m in raw])
        v = g.k(theta)
    except NContactError:
        return  # degenerate draws (rank < 3)
    if not math.isfinite(v):
        return
    try:
        r = g.forces(theta)
    except NContactError as err:  # allowed only where double precision cannot resolve
        assert "not resolved in double precision" in str(err)
        return
    _balance(g, theta, v, r)


def test_cli_k_with_contacts_exact(capsys):
    import json

    status, out, err = _cli(
        capsys,
        "k",
        "--contact",
        "1,0,180deg,1/2",
        "--contact=-1/2,sqrt(3)/2,-60deg,1/2",
        "--contact=-1/2,-sqrt(3)/2,60deg,1/2",
        "--theta",
        "0",
        "--exact",
        "--external-force",
        "2",
        "--json",
    )
    assert status == 0, err
    row = json.loads(out)[0]
    from _ncontact_lp import lp_value  # the LP written in the tests

    s3 = math.sqrt(3) / 2
    contacts = [(1, 0, -1, 0, 0.5), (-0.5, s3, 0.5, -s3, 0.5), (-0.5, -s3, 0.5, s3, 0.5)]
    want = lp_value(contacts, 0.0, "sum-normal")
    assert float(sp.sympify(row["k_exact"])) == pytest.approx(want, rel=1e-9)
    assert decide_zero(sp.sympify(row["F_exact"]) - 2 * sp.sympify(row["k_exact"]))
    assert row["F"] == pytest.approx(2 * row["k"])


def _balance(g, theta, v, r):
    """Nonnegative edge weights whose contact forces balance the load F_e e(θ) (force
    and moment about O) at the effort v(θ) (first principles)."""
    assert all(w >= -1e-9 for w in r["weights"].values())
    fx = sum(f[0] for f in r["forces"])
    fy = sum(f[1] for f in r["forces"])
    tz = sum(c.p[0] * f[1] - c.p[1] * f[0] for c, f in zip(g.contacts, r["forces"]))
    scale = 1 + sum(abs(w) for w in r["weights"].values()) * (
        1 + max(math.hypot(*c.p) for c in g.contacts)
    )
    assert abs(fx + math.sin(theta)) <= 1e-8 * scale
    assert abs(fy - math.cos(theta)) <= 1e-8 * scale
    assert abs(tz) <= 1e-8 * scale
    normal = sum(f[0] * c.n[0] + f[1] * c.n[1] for c, f in zip(g.contacts, r["forces"]))
    assert abs(normal - v) <= 1e-8 * scale


def test_optimal_forces_of_a_degenerate_vertex():
    """Two coincident contacts and a third with a normal 1e-10 off theirs (found by
    hypothesis in CI): every float basis of the vertex fails; the forces still balance."""
    g = NContactGrasp([(0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0), (0.0, 1.0, 1e-10, 1.0)])
    v = g.k(4.0)
    assert v == pytest.approx(-math.sin(4.0))  # contact 1 alone: its normal force
    _balance(g, 4.0, v, g.forces(4.0))
