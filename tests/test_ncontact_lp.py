"""The n-contact model against an LP written in the test (scipy HiGHS): values and arcs.

1000 random grasps n = 3…6 (seeded numpy; 24 θ each, a subset of 32 at 720 θ), four
efforts (sum of normal forces, a
designated pair, custom weights, the largest normal force), with and without force
closure; n = 2 with the paper's k (and its k >= 0).  The model's float path must give
the LP's value (relative 1e-9) where the LP is feasible and +inf exactly where it
is infeasible (the feasible arc).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("scipy")

from _ncontact_lp import SweepLP, force_closure, lp_value, random_contacts
from graspcompass.grasp import Grasp
from graspcompass.ncontact import NContactError, NContactGrasp

THETA_720 = np.linspace(0.0, 2 * math.pi, 720, endpoint=False) + 1e-3  # off the grid's ties
REL = 1e-9


def _efforts(rng, n):
    return [
        "sum-normal",
        f"pair:{1 + n // 2},1",
        [float(v) for v in rng.uniform(0.5, 2.0, n)],
        "max-normal",
    ]


def _compare(contacts, effort, thetas, com=(0.0, 0.0), fast=False):
    """The model's k(θ) against the LP written here: the same feasible arcs and values to
    ``REL``; ``fast``: one warm-started HiGHS model for all θ (sorted) instead of ``linprog``
    per θ."""
    g = NContactGrasp(contacts, com=com, effort=effort)
    got = g.k(thetas)
    want = (
        SweepLP(contacts, effort, com)(thetas)
        if fast
        else np.array([lp_value(contacts, t, effort, com) for t in thetas])
    )
    fin = np.isfinite(want)
    assert np.array_equal(np.isfinite(got), fin), (
        f"feasible arcs differ at θ = {thetas[np.isfinite(got) != fin][:5]}"
    )
    rel = np.abs(got[fin] - want[fin]) / np.maximum(1.0, np.abs(want[fin]))
    assert rel.size == 0 or rel.max() <= REL, rel.max()
    return g, fin


def _compare_fast(contacts, effort, thetas, com=(0.0, 0.0)):
    return _compare(contacts, effort, thetas, com, fast=True)


def _arc_ends_against_the_lp(contacts, g, com, eps=1e-5):
    """The model's feasible arc [lo, hi]: the LP is feasible just inside each end and
    infeasible just outside (the arc of the LP is the model's, not only on a grid)."""
    lo, hi = g.arc()
    assert 0 < hi - lo <= math.pi + 1e-12
    t = np.array([lo - eps, lo + eps, hi - eps, hi + eps])
    got = SweepLP(contacts, "sum-normal", com)(t)
    assert list(np.isfinite(got)) == [False, True, True, False], (lo, hi, got)


#: Grasps in the big comparison: 8 blocks of 125 (n = 3…6 in turn, one in three on an arc).
BLOCKS, PER_BLOCK, FEW_THETA = 8, 125, 24


@pytest.mark.parametrize("block", range(BLOCKS))
def test_thousand_grasps_four_efforts_against_the_lp(block):
    """1000 random grasps in all (n = 3…6, with and without force closure, a centre of mass
    off the origin), four efforts each, 24 θ each (a shifted grid: the full 720 θ run on
    the subset below); values to 1e-9 relative, infinite exactly where the LP is
    infeasible, and each open arc's two ends where the LP says they are."""
    rng = np.random.default_rng(4_000 + block)
    kinds = {True: 0, False: 0}
    arcs = 0
    for k in range(PER_BLOCK):
        n = 3 + k % 4
        contacts = random_contacts(rng, n, closure=k % 3 != 2)
        com = tuple(float(v) for v in rng.uniform(-0.2, 0.2, 2))
        thetas = np.sort(
            (rng.uniform(0, 2 * math.pi) + np.linspace(0, 2 * math.pi, FEW_THETA, endpoint=False))
            % (2 * math.pi)
        )
        for effort in _efforts(rng, n):
            g, fin = _compare_fast(contacts, effort, thetas, com=com)
        kinds[g.force_closure] += 1
        if g.force_closure:
            assert fin.all()
        elif g.arc() is not None:
            _arc_ends_against_the_lp(contacts, g, com)
            arcs += 1
    assert kinds[True] > 0 and kinds[False] > 0 and arcs > 0, (kinds, arcs)


@pytest.mark.parametrize("block", range(4))
def test_720_directions_against_the_lp(block):
    """The subset at 720 θ: 8 grasps per block (32 in all; n = 3…6; half of them on an arc,
    mostly not in force closure), the four efforts, force closure against the LP's."""
    rng = np.random.default_rng(20261202 + block)
    for k in range(8):
        n = 3 + k % 4
        contacts = random_contacts(rng, n, closure=k % 2 == 0)
        for effort in _efforts(rng, n):
            g, fin = _compare_fast(contacts, effort, THETA_720)
        assert g.force_closure == force_closure(contacts)
        if g.force_closure:
            assert fin.all()


def test_feasible_arc_matches_the_sampled_lp():
    """Without force closure the arc where v < inf is the arc where the LP is feasible."""
    rng = np.random.default_rng(5)
    seen = 0
    for _ in range(30):
        contacts = random_contacts(rng, 3, closure=False)
        g = NContactGrasp(contacts)
        if g.force_closure:
            continue
        arc = g.arc()
        if arc is None:
            continue
        seen += 1
        lo, hi = arc
        assert 0 < hi - lo <= math.pi + 1e-12
        inside = (THETA_720 - lo) % (2 * math.pi) <= hi - lo
        feasible = np.isfinite(SweepLP(contacts, "sum-normal")(THETA_720))
        near = (
            np.minimum(
                np.abs((THETA_720 - lo + math.pi) % (2 * math.pi) - math.pi),
                np.abs((THETA_720 - hi + math.pi) % (2 * math.pi) - math.pi),
            )
            < 1e-9
        )
        assert np.array_equal(inside[~near], feasible[~near])
        if seen == 6:
            break
    assert seen >= 3


@pytest.mark.parametrize("seed", range(4))
def test_two_contacts_paper_effort_against_the_lp(seed):
    """n = 2, the paper's k with k >= 0 (eq. (25)), 720 θ, random grasps of the paper's frame."""
    rng = np.random.default_rng(99 + seed)
    x1, x2 = rng.uniform(0.5, 2.0, 2)
    y = rng.uniform(0.0, 2.0)
    phi1, phi2 = rng.uniform(1.2, 1.9, 2)
    mu1, mu2 = rng.uniform(0.3, 1.2, 2)
    g = Grasp(
        float(x1), float(x2), float(y), float(phi1), float(phi2), mu1=float(mu1), mu2=float(mu2)
    )
    h = NContactGrasp.from_grasp(g)
    contacts = [(c.p[0], c.p[1], c.n[0], c.n[1], float(c.mu)) for c in h.contacts]
    want = SweepLP(contacts, "paper")(THETA_720)
    got = h.k(THETA_720)
    assert np.allclose(got, want, rtol=REL, atol=REL)
    assert np.allclose(got, g.k_grasp(THETA_720), rtol=1e-12, atol=1e-12)


def test_paper_effort_where_k_geq_0_is_active():
    """Two-contact grasps whose Q has the vertex O (the "0" of eq. (25) active on an arc)."""
    rng = np.random.default_rng(2026)
    found = 0
    for _ in range(300):
        x1, x2 = rng.uniform(0.3, 2.0, 2)
        y = rng.uniform(0.0, 2.5)
        phi1, phi2 = rng.uniform(0.9, 2.3, 2)
        mu1, mu2 = rng.uniform(0.2, 1.5, 2)
        try:
            g = Grasp(
                float(x1),
                float(x2),
                float(y),
                float(phi1),
                float(phi2),
                mu1=float(mu1),
                mu2=float(mu2),
            )
        except ValueError:
            continue
        h = NContactGrasp.from_grasp(g)
        V = h.polygon().float_vertices()
        if not np.any(np.all(np.abs(V) < 1e-12, axis=1)):
            continue
        found += 1
        contacts = [(c.p[0], c.p[1], c.n[0], c.n[1], float(c.mu)) for c in h.contacts]
        t = THETA_720[::4]
        want = SweepLP(contacts, "paper")(t)
        got = h.k(t)
        assert np.allclose(got, want, rtol=REL, atol=REL)
        assert np.any(np.abs(got) < 1e-12)  # the arc where no squeeze is needed
        if found == 3:
            break
    assert found >= 1


def test_regression_normal_cone_sharing_the_feasible_cone_start():
    """Two contacts at one point: a vertex of Q whose normal cone starts where the feasible
    cone starts (hypothesis found the float path dropping it; the LP says 0.84 at θ = 0)."""
    raw = [(0.0, 0.0, 1.0, 1.0), (0.0, 0.0, 2.0, 0.5), (0.0, 1.0, 0.0, 1.0)]
    contacts = [(x, y, math.cos(a), math.sin(a), m) for x, y, a, m in raw]
    _compare(contacts, "sum-normal", THETA_720[::3])
    exact = NContactGrasp([(0, 0, 1, 1), (0, 0, 2, "1/2"), (0, 1, 0, 1)])
    assert np.allclose(
        exact.k(THETA_720[::3]), NContactGrasp(raw).k(THETA_720[::3]), rtol=1e-12, equal_nan=True
    )


def test_degenerate_grid_grasps_against_the_lp():
    """Contacts on a half-unit grid with normals at multiples of 45°: coincident points,
    parallel edges, collinear dual vertices (the float path's tolerances are stressed)."""
    rng = np.random.default_rng(31)
    done = 0
    for _ in range(80):
        n = int(rng.integers(2, 6))
        contacts = []
        for _ in range(n):
            a = float(rng.integers(0, 8)) * math.pi / 4
            contacts.append(
                (
                    float(rng.integers(-2, 3)) / 2,
                    float(rng.integers(-2, 3)) / 2,
                    math.cos(a),
                    math.sin(a),
                    float(rng.choice([0.25, 0.5, 1.0])),
                )
            )
        thetas = np.sort(rng.uniform(0, 2 * math.pi, 6))
        for effort in ["sum-normal", "max-normal", f"pair:1,{n}"]:
            try:
                _compare_fast(contacts, effort, thetas)
            except NContactError:  # rank < 3: no vertex
                continue
            done += 1
    assert done >= 100


def test_worst_direction_against_the_lp():
    """max_θ v(θ) = max |q| (three-jaw gripper sizing): the LP at the returned θ gives it, and
    no θ of a 360-point grid needs more."""
    rng = np.random.default_rng(12)
    checked = 0
    for n in (3, 4, 3, 4, 5):
        contacts = random_contacts(rng, n)
        g = NContactGrasp(contacts)
        if not g.force_closure:
            continue
        checked += 1
        value, theta = g.worst(2.0)
        assert lp_value(contacts, theta, "sum-normal") * 2.0 == pytest.approx(value, rel=1e-9)
        grid = SweepLP(contacts, "sum-normal")(THETA_720[::2])
        assert grid.max() * 2.0 <= value * (1 + 1e-9)
    assert checked >= 2


def test_worst_exact_matches_float():
    exact = NContactGrasp(
        [
            ("1", "0", "180deg", "1/2"),
            ("-1/2", "sqrt(3)/2", "-60deg", "1/2"),
            ("-1/2", "-sqrt(3)/2", "60deg", "1/2"),
        ]
    )
    s3 = math.sqrt(3) / 2
    flt = NContactGrasp(
        [(1.0, 0, -1, 0, 0.5), (-0.5, s3, 0.5, -s3, 0.5), (-0.5, -s3, 0.5, s3, 0.5)]
    )
    (ve, te), (vf, _) = exact.worst(), flt.worst()
    assert float(ve) == pytest.approx(vf, rel=1e-12)
    assert float(exact.k(te)) == pytest.approx(float(ve), rel=1e-12)


def test_the_warm_sweep_is_the_plain_lp():
    """The test's warm-started HiGHS model gives linprog's answer, θ by θ (both efforts'
    forms, closure and not): the fast oracle is the slow one."""
    rng = np.random.default_rng(8)
    for k in range(4):
        contacts = random_contacts(rng, 3 + k, closure=k % 2 == 0)
        t = np.sort(rng.uniform(0, 2 * math.pi, 20))
        for effort in _efforts(rng, 3 + k):
            fast = SweepLP(contacts, effort)(t)
            slow = np.array([lp_value(contacts, x, effort) for x in t])
            assert np.array_equal(np.isfinite(fast), np.isfinite(slow))
            assert np.allclose(fast, slow, rtol=1e-11, atol=1e-11, equal_nan=False)
