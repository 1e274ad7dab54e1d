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
        (round(x, 12) + 0.0, round(y, 12) + 0.0) for x, y in pts}


def test_rectangle_best_pair_from_first_principles() -> None:
    """Centred pairs of opposite sides: y = 0, x1 = x2 = a, φ = π/2.

    Then t_1 = tan(π/2 + ξ) = −1/μ, V_1 = (−a, −a/μ) by (28), (29), and all four
    |V_n| = a sqrt(1 + 1/μ²), so F = m g sqrt(1 + 1/μ²)/2 per jaw, whatever a.  Any
    y > 0 adds y/μ to |S_n|, and x1 ≠ x2 makes max(x1, x2)/μ > a/μ: no pair does better.
    """
    plan = plan_contacts(PLATE, mu=MU, mass=2.0, samples=48, g=G)
    expected = 2.0 * G * math.sqrt(1 + 1 / MU**2) / 2
    centred = {frozenset({(0.0, -0.03), (0.0, 0.03)}), frozenset({(0.05, 0.0), (-0.05, 0.0)})}
    best = plan.top(3)
    for p in best[:2]:
        assert frozenset((round(x, 12) + 0.0, round(y, 12) + 0.0) for x, y in p.contacts) \
            in centred
        assert p.squeeze == pytest.approx(expected, rel=1e-12)
        assert p.squeeze_per_kg == pytest.approx(expected / 2.0, rel=1e-12)
    assert best[2].squeeze > expected * (1 + 1e-6)
    # an LP over the load directions (the paper's least internal force, per jaw)
    (p1, p2), (n1, n2) = best[0].contacts, best[0].normals
    lp = max(lp_squeeze(p1, p2, n1, n2, MU, MU, plan.com, 2.0 * G * e(t))[0]
             for t in np.linspace(0, 2 * np.pi, 721))
    assert lp == pytest.approx(expected, rel=1e-4)
    assert np.nanmin(plan.squeeze) == pytest.approx(expected, rel=1e-12)


def test_frames_and_squeezes_agree_with_place_grasp_and_size_gripper() -> None:
    from graspcompass.outlines import read_outline

    outline = read_outline(BRACKET)
    plan = plan_contacts(outline, mu=MU, mass=1.5, samples=60, g=G)
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
        math.pi / 2)


def test_result_is_read_only_and_json_ready() -> None:
    plan = plan_contacts(PLATE, mu=MU, samples=16)
    with pytest.raises(ValueError):
        plan.squeeze[0] = 0.0
    d = json.loads(json.dumps(plan.to_dict(3)))
    assert d["pairs"] == 120 and len(d["top"]) == 3 and d["top"][0]["rank"] == 1


@pytest.mark.parametrize("kwargs, error, text", [
    (dict(samples=1000), InputTooLargeError, str(MAX_PAIRS)),
    (dict(samples=2), InputError, "at least 3"),
    (dict(samples=True), InputError, "integer"),
    (dict(mu=0.0), InputError, "mu"),
    (dict(mu=float("nan")), InputError, "mu"),
    (dict(mass=-1.0), InputError, "mass"),
    (dict(per="both"), InputError, "per"),
    (dict(com=("x", 0)), InputError, "com"),
])
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
    assert plan_contacts(triangle, mu=0.7, samples=30).force_closure.any()


# -- the command line ----------------------------------------------------------------------
def test_cli_bracket_json_and_drawing(tmp_path, capsys) -> None:
    out = tmp_path / "plan.png"
    assert main(["plan", "--shape", str(BRACKET), "--mass", "500g", "--mu", "0.5", "--samples",
                 "60", "--top", "3", "--json", "--draw", str(out)]) == 0
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
    open_path.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm" '
                         'viewBox="0 0 10 10"><path d="M 0 0 L 10 0 L 10 10"/></svg>')
    tri = tmp_path / "tri.svg"
    tri.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
                   'viewBox="0 0 100 100"><path d="M 0 90 L 100 90 L 50 3.4 Z"/></svg>')
    _one_line_exit_2(["plan", "--shape", str(open_path)], capsys, "closed")
    _one_line_exit_2(["plan", "--shape", str(tri), "--mu", "0.3"], capsys, "force-closure")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--samples", "100000"], capsys,
                     "at most 200")
    _one_line_exit_2(["plan", "--shape", str(tmp_path / "none.svg")], capsys, "none.svg")
    _one_line_exit_2(["plan", "--shape", "part.png"], capsys, ".svg or .dxf")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--mu", "-1"], capsys, "--mu")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--mass", "5lb"], capsys, "unit")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--draw", "/no/such/folder/p.png"],
                     capsys, "/no/such/folder")
    _one_line_exit_2(["plan", "--shape", str(BRACKET), "--top", "0"], capsys, "--top")


@pytest.mark.parametrize("argv", [
    ["plan", "--shape", "part.svg", "--samples", "100000"],
    ["plan", "--shape", "part.txt"], ["plan", "--shape", "p.svg", "--mass", "5lb"],
])
def test_cli_refusals_load_no_heavy_module(argv) -> None:
    code = ("import contextlib, io\nfrom graspcompass.cli import main\nwith "
            f"contextlib.redirect_stderr(io.StringIO()):\n    assert main({argv!r}) == 2")
    assert not any(_loaded_after(code).values())


def test_as_a_process() -> None:
    out = subprocess.run([sys.executable, "-m", "graspcompass", "plan", "--shape", str(BRACKET),
                          "--samples", "20", "--top", "1", "--exact", "0"], capture_output=True,
                         text=True,
                         timeout=120)
    assert out.returncode == 0 and out.stdout.count("\n") == 4, out.stderr
