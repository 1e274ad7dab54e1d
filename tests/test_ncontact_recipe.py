"""The n-contact vertex recipe in the construction language (issue 25).

The recipe's vertices (geometric kernel: meets and parallels, one quarter turn) must
be the dual vertices found by Cramer's rule in :mod:`graspcompass.ncontact`: two
independent computations.  The shorter recipe for V_1..V_4 (recipes/short.gc) is
proved equal to the paper's (28)-(39) by the checker; a wrong cost point is refuted.
"""

from __future__ import annotations

from fractions import Fraction
from importlib import resources

import numpy as np
import pytest
import sympy as sp

from graspcompass import cli
from graspcompass.construction.language import parse, replay
from graspcompass.construction.ncontact_recipe import ncontact_recipe
from graspcompass.construction.operations import OPERATIONS
from graspcompass.geometry import Point
from graspcompass.grasp import Grasp
from graspcompass.ncontact import NContactGrasp
from graspcompass.proof.program_check import check_program
from graspcompass.proof.prove import Status

THREE = [
    ("1", "0", "180deg", "1/2"),
    ("-1/2", "sqrt(3)/2", "-60deg", "1/2"),
    ("-1/2", "-sqrt(3)/2", "60deg", "1/2"),
]


def _short() -> str:
    return (resources.files("graspcompass.construction") / "recipes" / "short.gc").read_text()


def _constructed(g: NContactGrasp) -> list[tuple]:
    c = replay(parse(ncontact_recipe(g)))
    return [(c[f"q{k}"], c.step(f"q{k}").op) for k in range(1, len(g.polygon().vertex_index) + 1)]


def _same(p: Point, q: tuple) -> bool:
    return all(sp.simplify(sp.sympify(a) - b) == 0 for a, b in zip((p.x, p.y), q))


def test_quarter_turn_and_parallel_to_points_from_first_principles() -> None:
    qt, par = OPERATIONS["quarter_turn"], OPERATIONS["parallel_to_points"]
    # (3, 1) about (1, 1): the offset (2, 0) turned clockwise is (0, -2)
    assert qt.function(Point(3, 1), Point(1, 1)) == Point(1, -1)
    assert qt.ggb_for(("R", "O"), ()) == "Rotate[R, -90°, O]"
    line = par.function(Point(0, 0), Point(2, 1), Point(0, 3))
    d = line.direction
    assert line.point == Point(0, 3) and d.x * 1 - d.y * 2 == 0 and d.x > 0
    assert qt.function(Point(0, 0), Point(0, 0)) == Point(0, 0)


def test_three_fingers_every_vertex_constructed_exactly() -> None:
    """Three fingers 120° apart, μ = 1/2, sum of normal forces: six vertices, all by the
    three-force recipe, each the enumeration's vertex exactly (sqrt(3) in the field)."""
    g = NContactGrasp(THREE)
    Q = g.polygon()
    got = _constructed(g)
    assert len(got) == 6 and all(op == "quarter_turn" for _, op in got)
    for (p, _), i in zip(got, Q.vertex_index):
        assert _same(p, Q.candidates[i].q)


@pytest.mark.parametrize("seed", range(3))
def test_rational_grasps_constructed_vertices_are_the_enumerated_ones(seed) -> None:
    from _ncontact_lp import random_contacts

    rng = np.random.default_rng(300 + seed)
    for n in (3, 4):
        raw = random_contacts(rng, n)
        cs = [tuple(str(Fraction(v).limit_denominator(20)) for v in c) for c in raw]
        for effort in ("sum-normal", "pair:1,2"):
            g = NContactGrasp(cs, effort=effort)
            Q = g.polygon()
            for (p, _), i in zip(_constructed(g), Q.vertex_index):
                assert (p.x, p.y) == tuple(sp.nsimplify(v) for v in Q.candidates[i].q) or _same(
                    p, Q.candidates[i].q
                )


def test_two_contacts_paper_effort_gives_the_paper_vertices() -> None:
    """n = 2 with the paper's k, Table I(c) (P1 = (2, 2), P2 = (-2, 2), φ = π/2, μ1 = 1/2,
    μ2 = 7/5): by (28)-(39) with tan(π/2 ± ξ) = ∓1/μ, V1 = (-6, -4), V2 = (24/7, -10/7),
    V3 = (2, 4), V4 = (4/7, 10/7); the recipe constructs V1, V2, V3 and not V4 (inside
    the triangle: redundant)."""
    g = NContactGrasp.from_grasp(Grasp.preset("table1c"))
    pts = {(p.x, p.y) for p, _ in _constructed(g)}
    R = sp.Rational
    assert pts == {(-6, -4), (R(24, 7), R(-10, 7)), (2, 4)}


def test_short_recipe_is_proved_equal_to_the_paper() -> None:
    r = check_program(parse(_short(), "short.gc"), "paper")
    assert r.exit_status == 0
    assert {t.name for t in r.targets} == {"V1", "V2", "V3", "V4"}
    rows = (*r.targets, *r.claims)
    assert len(r.claims) == 4 and all(t.status is Status.PROVED for t in rows)
    # the non-degeneracy the recipe needs is stated: O off P1P2
    assert all(any("y" in str(c) for c in t.result.conditions) for t in rows)


def test_short_recipe_with_a_wrong_cost_point_is_refuted() -> None:
    wrong = _short().replace("T2 = point (0, -(x1 + x2)/2)", "T2 = point (0, (x1 + x2)/2)")
    assert wrong != _short()
    r = check_program(parse(wrong, "wrong.gc"), "paper")
    assert r.exit_status == 1
    assert all(t.status is Status.REFUTED for t in r.claims)


def test_steps_and_draw_from_a_contacts_file(tmp_path, capsys) -> None:
    f = tmp_path / "three.txt"
    f.write_text(
        "# three fingers\n" + "\n".join(",".join(c) for c in THREE) + "\neffort sum-normal\n"
    )
    assert cli.main(["steps", "--contacts", str(f)]) == 0
    out = capsys.readouterr().out
    assert "q6" in out and "circle6" in out and "quarter_turn" not in out
    assert cli.main(["steps", "--contacts", str(f), "--json"]) == 0
    capsys.readouterr()
    png = tmp_path / "s.png"
    assert cli.main(["draw", "--contacts", str(f), "--step", "20", "-o", str(png), "-q"]) == 0
    assert png.stat().st_size > 1000
    args = ["steps"] + [f"--contact={','.join(c)}" for c in THREE] + ["--effort", "pair:1,2"]
    assert cli.main(args) == 0
    assert "circle" in capsys.readouterr().out


@pytest.mark.parametrize(
    "text, what",
    [
        ("1,0,180deg,1/2\nhello\n", "expected a contact"),
        ("# nothing\n", "no contact"),
        ("1,0,180deg\n0,1,0deg\n", "expected 4 or 5"),
    ],
)
def test_contacts_file_errors_exit_2(tmp_path, capsys, text, what) -> None:
    f = tmp_path / "bad.txt"
    f.write_text(text)
    assert cli.main(["steps", "--contacts", str(f)]) == 2
    err = capsys.readouterr().err
    assert what in err and err.count("\n") == 1


def test_size_three_jaws_worst_squeeze_against_the_lp(capsys) -> None:
    """size --contact: F_e max|q| with F_e = m g; the LP on 720 θ never needs more and
    comes within 1e-4 (the grid's spacing) of it."""
    import json
    import math

    pytest.importorskip("scipy")
    from _ncontact_lp import SweepLP

    args = ["size", "--mass", "500g", "--json"] + [f"--contact={','.join(c)}" for c in THREE]
    assert cli.main(args) == 0
    rec = json.loads(capsys.readouterr().out)
    load = 0.5 * 9.80665
    s3 = math.sqrt(3) / 2
    flt = [(1.0, 0.0, -1.0, 0.0, 0.5), (-0.5, s3, 0.5, -s3, 0.5), (-0.5, -s3, 0.5, s3, 0.5)]
    grid = SweepLP(flt, "sum-normal")(np.linspace(0, 2 * math.pi, 720, endpoint=False))
    assert rec["load_N"] == pytest.approx(load, rel=1e-12)
    assert grid.max() * load <= rec["worst_N"] * (1 + 1e-9)
    assert grid.max() * load == pytest.approx(rec["worst_N"], rel=1e-4)
    # the farthest vertex by hand: q = (7 - 4√3, 3√3 - 4) (three-force basis)
    assert rec["max_q"] == pytest.approx(
        math.hypot(7 - 4 * math.sqrt(3), 3 * math.sqrt(3) - 4), rel=1e-12
    )


def test_size_contact_refuses_two_jaw_options(capsys) -> None:
    args = ["size", "--mass", "1", "--p1", "0,0"] + [f"--contact={','.join(c)}" for c in THREE]
    assert cli.main(args) == 2
    assert "--p1 is for two jaws" in capsys.readouterr().err
