"""Choosing the contacts on an outline (issue 13 §3): graspcompass.planning and ``plan``.

The rectangle's best pair is derived here from first principles and its squeeze
checked with an independent LP (``lp_squeeze`` of test_sizing) over the
directions of the load; the vectorised paper frames are checked against
:func:`graspcompass.place_grasp` and the squeezes against :func:`size_gripper`.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from graspcompass import place_grasp
from graspcompass.cli import main
from graspcompass.errors import InputError, InputTooLargeError
from graspcompass.planning import MAX_PAIRS, pair_frames, plan_contacts, sample_contacts
from graspcompass.sizing import NotForceClosureError, size_gripper
from graspcompass.world import FrictionConeError, OutlineError
from test_cli_startup import _loaded_after
from test_sizing import e, lp_squeeze

ROOT = Path(__file__).resolve().parents[1]
BRACKET = ROOT / "docs" / "_static" / "outlines" / "bracket.svg"
#: A 100 × 60 mm plate centred on the origin; 48 samples put 15 and 9 points on its
#: sides (odd: each side's midpoint is sampled).
PLATE = [(-0.05, -0.03), (0.05, -0.03), (0.05, 0.03), (-0.05, 0.03)]
MU, G = 0.5, 9.81


def test_sampling_skips_vertices_and_gives_inward_normals() -> None:
    pts, nrm, edges = sample_contacts(PLATE, 48)
    assert len(pts) == 48 and np.bincount(edges).tolist() == [15, 9, 15, 9]
    corners = np.array(PLATE)
    assert np.min(np.linalg.norm(pts[:, None] - corners[None], axis=-1)) > 1e-3
    # inward: a small step along the normal stays inside the plate
    inside = pts + 1e-4 * nrm
    assert (np.abs(inside[:, 0]) < 0.05).all() and (np.abs(inside[:, 1]) < 0.03).all()
    assert {(0.0, -0.03), (0.0, 0.03), (0.05, 0.0), (-0.05, 0.0)} <= {
        (round(x, 12) + 0.0, round(y, 12) + 0.0) for x, y in pts
    }


def test_rectangle_best_pair_from_first_principles() -> None:
    """Centred pairs of opposite sides: y = 0, x1 = x2 = a, φ = π/2.

    Then t_1 = tan(π/2 + ξ) = −1/μ, V_1 = (−a, −a/μ) by (28), (29), and all four
    |V_n| = a sqrt(1 + 1/μ²), so F = m g sqrt(1 + 1/μ²)/2 per jaw, whatever a.  Any
    y > 0 adds y/μ to |S_n|, and x1 ≠ x2 makes max(x1, x2)/μ > a/μ: no pair does better.
    """
    plan = plan_contacts(PLATE, mu=MU, mass=2.0, samples=48, g=G, exact=0)
    expected = 2.0 * G * math.sqrt(1 + 1 / MU**2) / 2
    centred = {frozenset({(0.0, -0.03), (0.0, 0.03)}), frozenset({(0.05, 0.0), (-0.05, 0.0)})}
    best = plan.top(3)
    for p in best[:2]:
        assert frozenset((round(x, 12) + 0.0, round(y, 12) + 0.0) for x, y in p.contacts) in centred
        assert p.squeeze == pytest.approx(expected, rel=1e-12)
        assert p.squeeze_per_kg == pytest.approx(expected / 2.0, rel=1e-12)
    assert best[2].squeeze > expected * (1 + 1e-6)
    # an LP over the load directions (the paper's least internal force, per jaw)
    (p1, p2), (n1, n2) = best[0].contacts, best[0].normals
    lp = max(
        lp_squeeze(p1, p2, n1, n2, MU, MU, plan.com, 2.0 * G * e(t))[0]
        for t in np.linspace(0, 2 * np.pi, 721)
    )
    assert lp == pytest.approx(expected, rel=1e-4)
    assert np.nanmin(plan.squeeze) == pytest.approx(expected, rel=1e-12)


def test_frames_and_squeezes_agree_with_place_grasp_and_size_gripper() -> None:
    from graspcompass.outlines import read_outline

    outline = read_outline(BRACKET)
    plan = plan_contacts(outline, mu=MU, mass=1.5, samples=60, g=G, exact=0)
    picks = plan.order[np.linspace(0, len(plan.order) - 1, 6).astype(int)]
    values = []
    for k in picks:
        p = plan.pair(int(k))
        wg = place_grasp(list(p.contacts), list(p.normals), mu=(MU, MU), com=plan.com)
        g = wg.grasp
        got = [float(v) for v in (g.x1, g.x2, g.y, g.phi1, g.phi2)]
        want = [p.paper[n] for n in ("x1", "x2", "y", "phi1", "phi2")]
        assert got == pytest.approx(want, rel=1e-9, abs=1e-12)
        s = float(size_gripper(wg, 1.5, g=G).worst_squeeze)
        assert s == pytest.approx(p.squeeze, rel=1e-9)
        values.append(s)
    assert values == sorted(values)  # the ranking agrees with size_gripper
    # pairs that are not force-closure are refused by place_grasp too
    bad = np.flatnonzero(~plan.force_closure)[::97][:5]
    for k in bad:
        p = plan.pair(int(k))
        if p.paper["x1"] + p.paper["x2"] <= 0:
            continue
        with pytest.raises(FrictionConeError):
            place_grasp(list(p.contacts), list(p.normals), mu=(MU, MU), com=plan.com)


def test_pair_frames_swap_puts_the_centre_of_mass_below() -> None:
    fr = pair_frames([[0.0, 1.0]], [[0.0, -1.0]], [[0.0, -1.0]], [[0.0, 1.0]], (0.0, 0.0))
    assert fr["y"].tolist() == [0.0] and fr["x1"] + fr["x2"] == pytest.approx(2.0)
    fr = pair_frames([[-1.0, 1.0]], [[1.0, 0.0]], [[1.0, 1.0]], [[-1.0, 0.0]], (0.0, 0.0))
    assert bool(fr["swapped"][0]) and fr["y"][0] == pytest.approx(1.0)
    assert fr["phi1"][0] == pytest.approx(math.pi / 2) and fr["phi2"][0] == pytest.approx(
        math.pi / 2
    )


def test_result_is_read_only_and_json_ready() -> None:
    plan = plan_contacts(PLATE, mu=MU, samples=16)
    with pytest.raises(ValueError):
        plan.squeeze[0] = 0.0
    d = json.loads(json.dumps(plan.to_dict(3)))
    assert d["pairs"] == 120 and len(d["top"]) == 3 and d["top"][0]["rank"] == 1


@pytest.mark.parametrize(
    "kwargs, error, text",
    [
        (dict(samples=1000), InputTooLargeError, str(MAX_PAIRS)),
        (dict(samples=2), InputError, "at least 3"),
        (dict(samples=True), InputError, "integer"),
        (dict(mu=0.0), InputError, "mu"),
        (dict(mu=float("nan")), InputError, "mu"),
        (dict(mass=-1.0), InputError, "mass"),
        (dict(per="both"), InputError, "per"),
        (dict(com=("x", 0)), InputError, "com"),
    ],
)
def test_bad_arguments(kwargs, error, text) -> None:
    with pytest.raises(error, match=text):
        plan_contacts(PLATE, **{"mu": MU, **kwargs})


def test_bad_outlines_and_no_force_closure() -> None:
    with pytest.raises(OutlineError):
        plan_contacts([(0, 0), (1, 1), (1, 0), (0, 1)], mu=MU)  # a bow tie
    with pytest.raises(OutlineError):
        plan_contacts([(0, 0), (1, 0)], mu=MU)
    triangle = [(0, 0), (0.1, 0), (0.05, 0.05 * math.sqrt(3))]  # needs μ > tan 30°
    with pytest.raises(NotForceClosureError, match="none of the"):
        plan_contacts(triangle, mu=0.3, samples=30)
    assert plan_contacts(triangle, mu=0.7, samples=30, exact=0).force_closure.any()


# -- the command line ----------------------------------------------------------------------
def test_cli_bracket_json_and_drawing(tmp_path, capsys) -> None:
    out = tmp_path / "plan.png"
    assert (
        main(
            [
                "plan",
                "--shape",
                str(BRACKET),
                "--mass",
                "500g",
                "--mu",
                "0.5",
                "--samples",
                "60",
                "--top",
                "3",
                "--json",
                "--draw",
                str(out),
            ]
        )
        == 0
    )
    d = json.loads(capsys.readouterr().out)
    assert len(d["top"]) == 3 and d["mass_kg"] == 0.5 and out.stat().st_size > 10_000
    best = d["top"][0]
    assert best["squeeze_N"] == pytest.approx(0.5 * best["squeeze_N_per_kg"])
    # the text table
    assert main(["plan", "--shape", str(BRACKET.with_suffix(".dxf")), "--samples", "40"]) == 0
    text = capsys.readouterr().out
    assert "force-closure with μ = 0.5" in text and "\n   1 " in text


def _one_line_exit_2(argv, capsys, text):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("graspcompass: error:") and text in err, err


def test_cli_bad_inputs_one_line_exit_2(tmp_path, capsys) -> None:
    open_path = tmp_path / "open.svg"
    open_path.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm" '
        'viewBox="0 0 10 10"><path d="M 0 0 L 10 0 L 10 10"/></svg>'
    )
    tri = tmp_path / "tri.svg"
    tri.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
        'viewBox="0 0 100 100"><path d="M 0 90 L 100 90 L 50 3.4 Z"/></svg>'
    )
    _one_line_exit_2(["plan", "--shape", str(open_path)], capsys, "closed")
    _one_line_exit_2(["plan", "--shape", str(tri), "--mu", "0.3"], capsys, "force-closure")
    _one_line_exit_2(
        ["plan", "--shape", str(BRACKET), "--samples", "100000"], capsys, "at most 200"
    )
    _one_line_exit_2(["plan", "--shape", str(tmp_path / "none.svg")], capsys, "none.svg")
    _one_line_exit_2(["plan", "--shape", "part.png"], capsys, ".svg or .dxf")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--mu", "-1"], capsys, "--mu")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--mass", "5lb"], capsys, "unit")
    _one_line_exit_2(
        ["plan", "--shape", str(BRACKET), "--draw", "/no/such/folder/p.png"],
        capsys,
        "/no/such/folder",
    )
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--top", "0"], capsys, "--top")


@pytest.mark.parametrize(
    "argv",
    [
        ["plan", "--shape", "part.svg", "--samples", "100000"],
        ["plan", "--shape", "part.txt"],
        ["plan", "--shape", "p.svg", "--mass", "5lb"],
    ],
)
def test_cli_refusals_load_no_heavy_module(argv) -> None:
    code = (
        "import contextlib, io\nfrom graspcompass.cli import main\nwith "
        f"contextlib.redirect_stderr(io.StringIO()):\n    assert main({argv!r}) == 2"
    )
    assert not any(_loaded_after(code).values())


def test_as_a_process() -> None:
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "graspcompass",
            "plan",
            "--shape",
            str(BRACKET),
            "--samples",
            "20",
            "--top",
            "1",
            "--exact",
            "0",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0 and out.stdout.count("\n") == 4, out.stderr


# -- issue 13 §3: exact along edge pairs, the user's orientations ---------------------------
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from graspcompass.planning._exact import EdgePair, Load, edge_pair_values, refine_edge_pair  # noqa: E402
from graspcompass.sizing import SizingError  # noqa: E402


def paper_squeeze(a, na, b, nb, com, mu, g=G):
    """m g max_n |V_n| / (x1 + x2) per kg from the paper's formulas, nan off condition (1).

    The frame of §2.2.1 (origin O, x-axis along P2→P1, y >= 0), the angles of Fig. 2,
    t_n = tan(φ ± ξ) and eqs. (28)-(39): S = (y t1 − h, h − y t2, y t3 − h, h − y t4),
    C = (x2 t1, x1 t2, x2 t3, x1 t4), h = (x1 + x2)/2.
    """
    with np.errstate(invalid="ignore", divide="ignore"):  # a = b where two edges meet: nan
        return _paper_squeeze(a, na, b, nb, com, mu, g)


def _paper_squeeze(a, na, b, nb, com, mu, g, frame=False):
    a, na, b, nb, o = (np.asarray(v, float) for v in (a, na, b, nb, com))
    J = lambda v: np.stack([-v[..., 1], v[..., 0]], axis=-1)  # noqa: E731
    dot = lambda u, v: (u * v).sum(axis=-1)  # noqa: E731
    length = np.linalg.norm(a - b, axis=-1)
    ex = (a - b) / length[..., None]
    flip = dot(a - o, J(ex)) < 0
    ex = np.where(flip[..., None], -ex, ex)
    ey = J(ex)
    p1, p2 = np.where(flip[..., None], b, a), np.where(flip[..., None], a, b)
    n1, n2 = np.where(flip[..., None], nb, na), np.where(flip[..., None], na, nb)
    x1, x2, y = dot(p1 - o, ex), dot(o - p2, ex), dot(p1 - o, ey)
    phi1 = np.arctan2(-dot(n1, ex), -dot(n1, ey))
    phi2 = np.arctan2(dot(n2, ex), -dot(n2, ey))
    xi = math.atan(mu)
    ok = np.ones(np.shape(x1), bool)
    for phi in (phi1, phi2):
        ok &= (
            (phi > 0)
            & (phi <= np.pi)
            & (phi - xi > -np.pi / 2)
            & (phi - xi < np.pi / 2)
            & (phi + xi > np.pi / 2)
            & (phi + xi < 3 * np.pi / 2)
        )
    h = (x1 + x2) / 2
    t1, t2, t3, t4 = (np.tan(p + s * xi) for p, s in ((phi1, 1), (phi2, 1), (phi1, -1), (phi2, -1)))
    S = [y * t1 - h, h - y * t2, y * t3 - h, h - y * t4]
    C = [x2 * t1, x1 * t2, x2 * t3, x1 * t4]
    if frame:
        return S, C, ex, ey, x1 + x2, ok
    r = np.max([np.hypot(s, c) for s, c in zip(S, C)], axis=0)
    return np.where(ok, g * r / (x1 + x2), np.nan)


def _edge(ring, k):
    a0, a1 = ring[k], ring[k + 1]
    d = a1 - a0
    return a0, d, np.array([-d[1], d[0]]) / np.linalg.norm(d)


def brute_force(ring, ea, eb, com, mu, n=601, fn=None, rounds=3, starts=1):
    """The least paper_squeeze (or fn) over an n × n grid of (s, t), then finer grids around it.

    With ``starts`` > 1, finer grids around each of that many best local minima of the
    first grid (a valley nearly flat along a short edge can hide the optimum at its end).
    """
    (a0, da, na), (b0, db, nb) = _edge(ring, ea), _edge(ring, eb)
    fn = fn or (lambda a, na, b, nb: paper_squeeze(a, na, b, nb, com, mu))

    def grid(lo_s, hi_s, lo_t, hi_t, n):
        s, t = np.meshgrid(np.linspace(lo_s, hi_s, n), np.linspace(lo_t, hi_t, n), indexing="ij")
        return s, t, fn(a0 + s[..., None] * da, na, b0 + t[..., None] * db, nb)

    s, t, q = grid(0.0, 1.0, 0.0, 1.0, n)
    pad = np.pad(np.where(np.isnan(q), np.inf, q), 1, constant_values=np.inf)
    local = np.isfinite(q) & np.all(
        [q <= pad[1 + i : 1 + i + n, 1 + j : 1 + j + n] for i in (-1, 0, 1) for j in (-1, 0, 1)],
        axis=0,
    )
    cand = np.flatnonzero(local.ravel())
    cand = cand[np.argsort(q.ravel()[cand])][:starts] if starts > 1 else [np.nanargmin(q)]
    out = np.inf
    for k in cand:
        best, (sb, tb) = float(q.ravel()[k]), (float(s.ravel()[k]), float(t.ravel()[k]))
        w, m = (4 / (n - 1), 4 / (n - 1)), n
        for _ in range(rounds - 1):
            lo_s, hi_s = max(0.0, sb - w[0]), min(1.0, sb + w[0])
            lo_t, hi_t = max(0.0, tb - w[1]), min(1.0, tb + w[1])
            m = 201
            ss, tt, qq = grid(lo_s, hi_s, lo_t, hi_t, m)
            j = np.nanargmin(qq)
            best, (sb, tb) = float(qq.ravel()[j]), (float(ss.ravel()[j]), float(tt.ravel()[j]))
            w = 4 * (hi_s - lo_s) / (m - 1), 4 * (hi_t - lo_t) / (m - 1)
        out = min(out, best)
    return out


def paper_squeeze_tilted(a, na, b, nb, com, mu, gdir, tau, accel=0.0, g=G):
    """The squeeze per kg over the tilts |ρ| <= τ of gravity g ĝ and accelerations |a| <= A.

    In the paper frame (eqs. (17), (28)-(39)) the internal force for a load F_e is
    max(0, max_n V_n · F_e) / (x1 + x2), V_n = (S_n, C_n); F_e = g R_ρ ĝ + a, and over
    |a| <= A the worst V_n · a is A |V_n|.  Over ρ, V_n · R_ρ ĝ is a sinusoid in ρ:
    its maximum on [−τ, τ] is at an end or at its peak (the ρ turning ĝ onto V_n).
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        S, C, ex, ey, span, ok = _paper_squeeze(a, na, b, nb, com, mu, g, frame=True)
        gx, gy = gdir
        top = np.full(np.shape(span), -np.inf)
        for s_, c_ in zip(S, C):
            vx, vy = s_ * ex[..., 0] + c_ * ey[..., 0], s_ * ex[..., 1] + c_ * ey[..., 1]
            peak = np.clip(np.arctan2(gx * vy - gy * vx, gx * vx + gy * vy), -tau, tau)
            for rho in (-tau, tau, peak):
                wx = g * (np.cos(rho) * gx - np.sin(rho) * gy)
                wy = g * (np.sin(rho) * gx + np.cos(rho) * gy)
                top = np.maximum(top, vx * wx + vy * wy + accel * np.hypot(vx, vy))
        return np.where(ok, np.maximum(top, 0.0) / span, np.nan)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1, 1), min_size=12, max_size=12), st.floats(0.2, 1.5))
def test_edge_closed_form_is_the_papers(v, mu) -> None:
    """V_n from equilibrium in the world frame (the module) = eqs. (28)-(39) in the paper frame."""
    a0, a1, b0, b1 = (
        (0.5 * v[0], -1 + 0.3 * v[1]),
        (1.5 + 0.5 * v[2], -1 + 0.3 * v[3]),
        (0.5 * v[4], 1 + 0.3 * v[5]),
        (-1.5 + 0.5 * v[6], 1 + 0.3 * v[7]),
    )
    com = (0.4 * v[8], 0.4 * v[9])
    pair = EdgePair.of(a0, a1, b0, b1, com, mu)
    s, t = (
        np.linspace(0, 1, 7) * 0.98 + 0.01 * (1 + v[10]),
        np.linspace(1, 0, 7) * 0.98 + 0.01 * (1 + v[11]),
    )
    q = edge_pair_values(pair, Load(g=G), s, t)
    a, b = pair.points(s, t)
    na, nb = pair.normals()
    want = paper_squeeze(a, na, b, nb, com, mu)
    both = np.isfinite(q) & np.isfinite(want)
    assert np.allclose(q[both], want[both], rtol=1e-9)
    # condition (1) agrees away from its boundary (within 1e-9 of a bound, rounding decides)
    assert (np.isfinite(q) == np.isfinite(want)).mean() >= 6 / 7


def test_exact_rectangle_centred_pair_in_closed_form() -> None:
    """Long sides of the plate: s = t = 1/2 and F = m g sqrt(1 + 1/μ²)/2, proved within tol."""
    plan = plan_contacts(PLATE, mu=MU, mass=2.0, samples=48, g=G, exact=2, tol=1e-7)
    want = 2.0 * G * math.sqrt(1 + 1 / MU**2) / 2
    assert {p.edges for p in plan.exact} == {(0, 2), (1, 3)}
    for p in plan.exact:
        assert p.certified and p.lower_bound <= want * (1 + 1e-12)
        assert p.squeeze == pytest.approx(want, rel=1e-7)
        assert p.params == pytest.approx((0.5, 0.5), abs=1e-3)
        assert p.squeeze <= p.sampled_squeeze * (1 + 1e-12)


@pytest.mark.parametrize("mu, com", [(0.5, None), (0.35, (0.06, -0.045))])
def test_exact_bracket_against_brute_force_and_samples(mu, com) -> None:
    from graspcompass.outlines import read_outline

    plan = plan_contacts(
        read_outline(BRACKET), mu=mu, mass=1.0, samples=60, g=G, com=com, exact=1 if com else 2
    )
    assert plan.exact
    ring = np.asarray(plan.outline)
    for p in plan.exact:
        ea, eb = p.edges
        grid = brute_force(ring, ea, eb, plan.com, mu)
        assert p.certified and p.squeeze - p.lower_bound <= p.tol * p.squeeze
        # the proof holds against an independent fine grid, and the optimum is found
        assert p.lower_bound <= grid * (1 + 1e-12)
        assert p.squeeze <= grid * (1 + 2e-6)
        # no sampled pair on these two edges does better
        on = ((plan.edges[plan.i] == ea) & (plan.edges[plan.j] == eb)) | (
            (plan.edges[plan.i] == eb) & (plan.edges[plan.j] == ea)
        )
        sampled = plan.squeeze[on & plan.force_closure]
        assert p.lower_bound <= sampled.min() * (1 + 1e-12)
        assert p.squeeze <= sampled.min() and p.sampled_squeeze == sampled.min()
        # the optimum's squeeze against the LP over the load directions
        (p1, p2), (n1, n2) = p.contacts, p.normals
        lp = max(
            lp_squeeze(p1, p2, n1, n2, mu, mu, plan.com, G * e(t))[0]
            for t in np.linspace(0, 2 * np.pi, 121)
        )
        assert lp <= p.squeeze * (1 + 1e-9) and lp == pytest.approx(p.squeeze, rel=2e-3)
    assert plan.exact[0].squeeze <= plan.top(1)[0].squeeze


@pytest.mark.parametrize("mu", [0.7, 1.2])
def test_exact_adjacent_edges_of_a_triangle(mu) -> None:
    """Edges meeting at a vertex (where (s, t) is singular): still proved, against the grid.

    For μ >= 1 a cone side can be ⟂ d, so no single |V_n| stays away from 0 at the vertex;
    the bound is joint over the sides (:class:`graspcompass.planning._bounds._Vertex`).
    """
    tri = [(0, 0), (0.1, 0), (0.05, 0.05 * math.sqrt(3))]
    plan = plan_contacts(tri, mu=mu, samples=30, g=G, exact=1)
    p = plan.exact[0]
    grid = brute_force(np.asarray(plan.outline), *p.edges, plan.com, mu)
    assert p.certified and p.lower_bound <= grid * (1 + 1e-12) <= p.squeeze * (1 + 1e-3)
    assert p.squeeze <= p.sampled_squeeze


TRAPEZE = [(-0.05, -0.03), (0.05, -0.03), (0.04, 0.03), (-0.05, 0.03)]


@pytest.mark.parametrize(
    "shape, mu, com, gdir, tilt, accel, boundary",
    [
        # the least squeeze approached on the boundary of condition (1), finite there
        ("trapeze", 0.6, (0.01, 0.005), (0.0, -1.0), 25, 1.0, True),
        ("bracket", 0.5, None, (0.6, -0.8), 30, 0.0, False),
    ],
)
def test_exact_under_tilt_range_against_grid_and_samples(
    shape, mu, com, gdir, tilt, accel, boundary
) -> None:
    """Under a tilt range: proved, ≤ every sampled pair, and the brute-force grid's optimum."""
    from graspcompass.outlines import read_outline

    outline = TRAPEZE if shape == "trapeze" else read_outline(BRACKET)
    tau = math.radians(tilt)
    plan = plan_contacts(
        outline,
        mu=mu,
        mass=1.0,
        samples=40,
        g=G,
        com=com,
        gravity=gdir,
        tilt=f"{tilt}deg",
        accel=accel,
        exact=1,
    )
    p = plan.exact[0]
    ring = np.asarray(plan.outline)
    ea, eb = p.edges

    def fn(a, na, b, nb):
        return paper_squeeze_tilted(a, na, b, nb, plan.com, mu, gdir, tau, accel)

    grid = brute_force(ring, ea, eb, plan.com, mu, n=301, fn=fn, rounds=4, starts=3)
    assert p.certified and p.squeeze - p.lower_bound <= p.tol * p.squeeze
    # the proof holds against the grid (a bound too high fails here), and it is the optimum
    assert p.lower_bound <= grid * (1 + 1e-12)
    assert p.squeeze <= grid * (1 + p.tol) and grid <= p.squeeze * (1 + 1e-4)
    # no sampled pair on these two edges does better
    on = ((plan.edges[plan.i] == ea) & (plan.edges[plan.j] == eb)) | (
        (plan.edges[plan.i] == eb) & (plan.edges[plan.j] == ea)
    )
    sampled = plan.squeeze[on & plan.force_closure]
    assert p.lower_bound <= sampled.min() * (1 + 1e-12) and p.squeeze <= sampled.min()
    assert p.sampled_squeeze == sampled.min()
    # the reported pair: force-closure by the paper's condition (1), its squeeze the paper's
    (p1, p2), (n1, n2) = p.contacts, p.normals
    here = fn(np.array(p1), np.array(n1), np.array(p2), np.array(n2))
    assert here == pytest.approx(p.squeeze, rel=1e-9)
    # ... and by dense sampling of the orientations (A = 0: an LP per orientation)
    if not accel:
        lp = max(
            lp_squeeze(p1, p2, n1, n2, mu, mu, plan.com, G * rot)[0]
            for rot in (
                np.array(
                    [
                        math.cos(r) * gdir[0] - math.sin(r) * gdir[1],
                        math.sin(r) * gdir[0] + math.cos(r) * gdir[1],
                    ]
                )
                for r in np.linspace(-tau, tau, 41)
            )
        )
        assert lp <= p.squeeze * (1 + 1e-9) and lp == pytest.approx(p.squeeze, rel=1e-3)
    # what is proved, stated: the boundary of (1), the orientations, the tolerance
    assert p.on_boundary is boundary and (p.cone_margin <= 1e-6) is boundary
    assert p.cone_margin > 0 and f"±{tilt}°" in p.claim() and "condition (1)" in p.claim()
    assert ("boundary of condition (1)" in p.claim()) is boundary
    assert p.to_dict()["on_boundary"] is boundary


def _boxes_hold(pair, load, rng, n=200, corner=False):
    """Random boxes 1e-4 to 0.1 wide (half of them at (s, t) = (1, 0) with ``corner``): each
    box's lower bound is at most q at every force-closure point sampled in it; returns how
    many straddle the boundary of (1)."""
    from graspcompass.planning._bounds import _Bounds

    bounds = _Bounds(pair, load)
    c, h = rng.uniform(0, 1, (n, 2)), 10 ** rng.uniform(-4, -1, n)
    if corner:
        c[: n // 2] = np.stack(
            [1 - 10 ** rng.uniform(-4, -0.5, n // 2), 10 ** rng.uniform(-4, -0.5, n // 2)], axis=-1
        )
    s_box = np.clip(c[:, 0] - h, 0, 1), np.clip(c[:, 0] + h, 0, 1)
    t_box = np.clip(c[:, 1] - h, 0, 1), np.clip(c[:, 1] + h, 0, 1)
    lower, feasible = bounds.lower(s_box, t_box)
    u = np.linspace(0, 1, 15)
    S = s_box[0][:, None, None] + (s_box[1] - s_box[0])[:, None, None] * u[None, :, None]
    T = t_box[0][:, None, None] + (t_box[1] - t_box[0])[:, None, None] * u[None, None, :]
    q = edge_pair_values(pair, load, S, T).reshape(n, -1)
    has = np.isfinite(q).any(axis=1)
    least = np.where(has, np.nanmin(np.where(np.isfinite(q), q, np.inf), axis=1), np.inf)
    assert feasible[has].all()  # no box with a force-closure point is dropped
    assert np.all(lower[has] <= least[has] * (1 + 1e-12))
    return int((feasible & bounds.straddle).sum())


def test_box_lower_bounds_hold_across_the_boundary_of_condition_1() -> None:
    """Random edge pairs, tilt ranges and accelerations, many boxes straddling the boundary
    of (1) (where κ is unbounded); μ up to 1.5."""
    rng = np.random.default_rng(0)
    straddling = 0
    for _ in range(9):
        v = rng.uniform(-1, 1, 10)
        pair = EdgePair.of(
            (0.5 * v[0], -1 + 0.3 * v[1]),
            (1.5 + 0.5 * v[2], -1 + 0.3 * v[3]),
            (0.5 * v[4], 1 + 0.3 * v[5]),
            (-1.5 + 0.5 * v[6], 1 + 0.3 * v[7]),
            (0.4 * v[8], 0.4 * v[9]),
            rng.uniform(0.2, 1.5),
        )
        ang = rng.uniform(-math.pi, math.pi)
        load = Load(
            g=G,
            accel=float(rng.choice([0.0, 3.0, 20.0])),
            gravity=(math.cos(ang), math.sin(ang)),
            tau=float(rng.uniform(0, 1.2)),
        )
        straddling += _boxes_hold(pair, load, rng)
    assert straddling >= 10


def test_box_lower_bounds_hold_at_a_shared_vertex_for_mu_above_1() -> None:
    """Two edges of a triangle meeting at a vertex, μ from 0.8 to 2.5, every orientation."""
    rng = np.random.default_rng(3)
    for _ in range(6):
        v = rng.uniform(-1, 1, 6)
        P = np.array(
            [(0.0, 0.0), (0.1 + 0.05 * v[0], 0.02 * v[1]), (0.03 * v[2], 0.1 + 0.05 * v[3])]
        )
        com = P.mean(axis=0) + 0.01 * v[4:6]
        pair = EdgePair.of(P[0], P[1], P[1], P[2], com, rng.uniform(0.8, 2.5))
        _boxes_hold(pair, Load(g=G, accel=float(rng.choice([0.0, 3.0]))), rng, corner=True)


def test_refine_edge_pair_tilt_range_lower_bound_holds() -> None:
    """The search under a tilt range: its lower bound is below a fine grid's least value."""
    pair = EdgePair.of(
        (-0.05, -0.03), (0.05, -0.03), (0.04, 0.03), (-0.05, 0.03), (0.01, 0.005), 0.6
    )
    load = Load(g=G, accel=1.0, gravity=(0.0, -1.0), tau=math.radians(25))
    opt = refine_edge_pair(pair, load, tol=1e-5, max_boxes=4000)
    s, t = np.meshgrid(np.linspace(0, 1, 801), np.linspace(0, 1, 801), indexing="ij")
    grid = np.nanmin(edge_pair_values(pair, load, s, t))
    # the infimum lies on the boundary of condition (1) here: proved all the same
    assert opt.lower <= grid * (1 + 1e-12) and opt.value <= grid * (1 + 1e-5)
    assert opt.certified and opt.margin < 1e-4 and opt.boxes <= 2 * 4000
    # with too small a budget: "not closed", and the lower bound still holds
    cut = refine_edge_pair(pair, load, tol=1e-5, max_boxes=100)
    assert not cut.certified and cut.lower <= grid * (1 + 1e-12) and cut.boxes <= 200


def test_tilt_range_ranking_against_lp_over_sampled_orientations() -> None:
    """Every orientation within ±τ of gravity, by an LP per orientation (test_sizing)."""
    tau, gdir, m = math.radians(30), np.array([0.6, -0.8]), 1.5
    plan = plan_contacts(
        PLATE, mu=MU, mass=m, samples=24, g=G, gravity=tuple(gdir), tilt="30deg", accel=0.0, exact=0
    )
    assert plan.exact == () and plan.tilt == pytest.approx(tau)
    assert "±30°" in plan.orientations()
    rhos = np.linspace(-tau, tau, 61)
    rot = lambda r: np.array([[math.cos(r), -math.sin(r)], [math.sin(r), math.cos(r)]])  # noqa: E731
    picks = plan.order[np.linspace(0, len(plan.order) - 1, 3).astype(int)]
    for k in picks:
        p = plan.pair(int(k))
        (p1, p2), (n1, n2) = p.contacts, p.normals
        lp = max(
            lp_squeeze(p1, p2, n1, n2, MU, MU, plan.com, m * G * rot(r) @ gdir)[0] for r in rhos
        )
        assert p.squeeze >= lp * (1 - 1e-9) and p.squeeze == pytest.approx(lp, rel=2e-3, abs=1e-9)
        wg = place_grasp(list(p.contacts), list(p.normals), mu=(MU, MU), com=plan.com)
        s = size_gripper(wg, m, g=G, gravity=tuple(gdir), tilt=tau)
        assert float(s.squeeze) == pytest.approx(p.squeeze, rel=1e-9, abs=1e-12)
    # the given orientation (no tilt) and a tilt of 180°: every orientation again
    fixed = plan_contacts(PLATE, mu=MU, samples=24, gravity=(0, -1), exact=0)
    assert fixed.tilt == 0.0 and fixed.orientations() == "gravity along (0, -1)"
    every = plan_contacts(PLATE, mu=MU, samples=24, exact=0)
    half_turn = plan_contacts(PLATE, mu=MU, samples=24, gravity=(0, -1), tilt=math.pi, exact=0)
    assert np.allclose(every.squeeze, half_turn.squeeze, equal_nan=True)
    assert np.all((fixed.squeeze <= every.squeeze * (1 + 1e-12)) | np.isnan(every.squeeze))


@settings(max_examples=40, deadline=None)
@given(
    st.floats(-3, 3),
    st.floats(-3, 3),
    st.floats(0.1, 3),
    st.floats(0, 3.2),
    st.floats(-math.pi, math.pi),
)
def test_arc_max_many_is_arc_max(S, C, gmag, tau, ang) -> None:
    from graspcompass.sizing._arc import arc_max_many
    from graspcompass.sizing.core import _arc_max

    w = (gmag * math.cos(ang), gmag * math.sin(ang))
    want, _ = _arc_max(S, C, math.hypot(S, C), w, gmag, tau, False)
    brute = max(
        S * (math.cos(r) * w[0] - math.sin(r) * w[1])
        + C * (math.sin(r) * w[0] + math.cos(r) * w[1])
        for r in np.linspace(-tau, tau, 2001)
    )
    got = float(arc_max_many(S, C, w, tau))
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)
    assert got >= brute - 1e-12 and got == pytest.approx(brute, abs=1e-5 * (1 + gmag))


@pytest.mark.parametrize(
    "kwargs, error, text",
    [
        (dict(tilt="10deg"), SizingError, "gravity"),
        (dict(gravity=(0, 0)), SizingError, "zero vector"),
        (dict(gravity=(0, -1), tilt=-0.1), SizingError, "tilt"),
        (dict(gravity=(0, -1), tilt="10"), InputError, "unit"),
        (dict(gravity=("x", 1)), InputError, "gravity"),
        (dict(exact=-1), InputError, "exact"),
        (dict(exact=True), InputError, "exact"),
        (dict(tol=0.0), InputError, "tol"),
        (dict(tol=0.5), InputError, "tol"),
    ],
)
def test_bad_orientation_and_exact_arguments(kwargs, error, text) -> None:
    with pytest.raises(error, match=text):
        plan_contacts(PLATE, **{"mu": MU, "samples": 12, **kwargs})


def test_cli_exact_and_tilt_json(capsys) -> None:
    assert main(["plan", "--shape", str(BRACKET), "--samples", "40", "--exact", "1", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    ex = d["exact"][0]
    assert ex["certified"] and ex["lower_bound_N"] <= ex["squeeze_N"] <= ex["sampled_squeeze_N"]
    assert "branch and bound" in d["exact_method"] and d["orientations"] == "every orientation"
    assert (
        main(
            [
                "plan",
                "--shape",
                str(BRACKET),
                "--samples",
                "40",
                "--gravity",
                "0,-1",
                "--tilt",
                "15deg",
                "--exact",
                "1",
                "--json",
            ]
        )
        == 0
    )
    d = json.loads(capsys.readouterr().out)
    assert d["tilt_deg"] == pytest.approx(15) and d["gravity"] == [0, -1]
    ex = d["exact"][0]  # proved under the tilt range too, and says over which orientations
    assert ex["certified"] and ex["lower_bound_N"] <= ex["squeeze_N"] <= ex["sampled_squeeze_N"]
    assert "±15°" in ex["proves"] and "condition (1)" in ex["proves"]
    assert isinstance(ex["on_boundary"], bool) and ex["cone_margin_rad"] > 0
    assert main(["plan", "--shape", str(BRACKET), "--samples", "40", "--exact", "1"]) == 0
    assert "proved >=" in capsys.readouterr().out


@pytest.mark.parametrize(
    "extra, text",
    [
        (["--tilt", "10deg"], "--tilt needs --gravity"),
        (["--gravity", "0,0"], "zero vector"),
        (["--gravity", "0,-1", "--tilt", "10"], "unit"),
        (["--gravity", "0,-1", "--tilt=-10deg"], "tilt"),
        (["--gravity", "1"], "--gravity"),
        (["--exact", "99"], "--exact"),
        (["--tol", "0"], "--tol"),
    ],
)
def test_cli_bad_orientation_one_line_exit_2(extra, text, capsys) -> None:
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--samples", "12", *extra], capsys, text)


def test_arc_max_of_an_arc_past_a_half_turn_is_every_orientation() -> None:
    """±τ with τ >= π holds every turn: V = (−1, 0) against w = (1, 0) reaches
    V·R_π w = 1 (found by hypothesis in CI: τ = 3.1875 gave cos τ < −1 + 0.002)."""
    from graspcompass.sizing.core import _arc_max

    for tau in (math.pi, 3.1875, 4.0):
        got, rho = _arc_max(-1.0, 0.0, 1.0, (1.0, 0.0), 1.0, tau, False)
        assert got == pytest.approx(1.0) and abs(abs(rho) - math.pi) < 1e-12
