"""Issue 19, one test per item (each failed before the fix)."""

from __future__ import annotations

import pytest
import sympy as sp

from graspcompass import symbols as S
from graspcompass.construction.language import ConstructionBuilder, parse
from graspcompass.expr import parse_with_conditions
from graspcompass.proof.program_check import check_program
from graspcompass.proof.prove import DegenerateClaimError, Status, prove_sign

Z = "(sin(phi1)**2 + cos(phi1)**2 - 1)"
HEAD = "param x1 > 0\nparam x2 > 0\nparam phi1 angle\n"


def _last(text: str):
    return check_program(parse(text)).claims[-1]


def test_collinear_with_a_repeated_first_point_is_refuted() -> None:  # item 1
    text = "param a > 0\nA = point (0, 0)\nB = point (a, 0)\nD = point (0, a)\n"
    assert _last(text + "claim collinear A B A D\n").status is Status.REFUTED
    b = ConstructionBuilder()
    b.param("a", "positive")
    b.step("A", "point", values=(0, 0))
    b.step("B", "point", values=("a", 0))
    b.step("D", "point", values=(0, "a"))
    b.claim("collinear", "A", "B", "A", "D")
    assert check_program(b.build()).claims[0].status is Status.REFUTED


def test_equality_in_a_sign_claim_is_decided() -> None:  # item 6
    assert _last(HEAD + "claim sign x1 + 1 == x1\n").status is Status.REFUTED
    assert _last(HEAD + "claim sign 2*x1 == x1 + x1\n").status is Status.PROVED


def test_the_parser_keeps_divisors_and_radicands() -> None:  # items 2-4
    x1, x2 = sp.symbols("x1 x2", positive=True)
    _, conds = parse_with_conditions("x1*(x1 - x2)/(x1 - x2)", symbols={"x1": x1, "x2": x2})
    assert ("!=", x1 - x2) in conds
    _, conds = parse_with_conditions("x1/x1", symbols={"x1": x1})
    assert ("!=", x1) in conds


@pytest.mark.parametrize(
    "text",
    [
        f"P = point (x1*{Z}/(x1*{Z}), 0)\nclaim P == point(1, 0)\n",
        f"claim sign {Z}/{Z} > 0\n",
        "Q = point (sqrt(-x1), 0)\nclaim Q == point(sqrt(-x1), 0)\n",
        "claim sign 1/(x1 - x1*sin(phi1)**2 - x1*cos(phi1)**2) > 0\n",
    ],
)
def test_a_vacuous_claim_is_refuted_not_proved(text: str) -> None:  # items 2, 3, 7
    row = _last(HEAD + text)
    assert row.status is Status.REFUTED and row.counterexample is None


def test_mu_and_xi_declared_together_are_tied() -> None:  # item 3
    text = (
        "param mu1 friction\nparam xi1 half_angle\nO = point (0, 0)\nA = point (1, 0)\n"
        "l = line_with_direction O (1, mu1)\nm = line_with_direction A (cos(xi1), "
        "sin(xi1))\nX = meet l m\n"
    )
    assert check_program(parse(text)).steps[-1].status is Status.REFUTED


def test_existence_conditions_are_listed() -> None:  # item 4
    r = check_program(
        parse(HEAD + "C = point (x1, 0)\nQ = point (x2, 0)\nc = circle_through C Q\n")
    )
    assert r.steps[-1].result.conditions  # degenerate at x1 = x2
    r = check_program(parse(HEAD + "claim sign x1*(x1 - x2)/(x1 - x2) > 0\n"))
    assert any("x1 - x2" in c for c in r.claims[0].result.conditions)


@pytest.mark.parametrize("claim", ["sign cos(phi1 + phi2) < 0", "sign x1 - x2 > 0"])
def test_false_sign_claims_are_refuted(claim: str) -> None:  # item 6
    row = _last(f"param x1 > 0\nparam x2 > 0\nparam phi1 angle\nparam phi2 angle\nclaim {claim}\n")
    assert row.status is Status.REFUTED and row.counterexample


def test_a_narrow_false_sign_claim_is_refuted() -> None:  # item 6
    row = _last("param phi1 angle\nparam xi1 half_angle\nclaim sign cos(phi1 + xi1) + 1/100 < 0\n")
    assert row.status is Status.REFUTED


def test_prove_sign_refuses_an_empty_interval_and_a_0_over_0() -> None:  # items 5, 7
    with pytest.raises(ValueError):
        prove_sign(S.x1, 1, intervals={S.phi1: (sp.pi, 0)})
    z = sp.sin(S.phi1) ** 2 + sp.cos(S.phi1) ** 2 - 1
    with pytest.raises(DegenerateClaimError):
        prove_sign(z * S.x1 / sp.expand(S.x1 * z), -1, witness=[1])


def test_an_unreducible_claim_is_a_verdict_not_a_crash() -> None:  # item 7
    row = _last(HEAD + "claim sign sin(phi1 + 1) > -2\n")
    assert row.status in (Status.PROVED, Status.UNDECIDED)


# -- item 2, last sentence: the replay at typed angles, and check --against paper ---------------
def _zero_over_zero_recipe() -> str:
    from graspcompass.construction.language import paper_text

    text = paper_text()
    old = "V1 = point_from_lengths OMX1 OY1 (-1, -1)"
    assert old in text
    return text.replace(old, f"V1 = point_from_lengths OMX1 OY1 (-1*{Z}/{Z}, -1*{Z}/{Z})")


@pytest.mark.parametrize("phi1", ["108deg", "3*pi/7", "1.2", "60deg", "2*pi/3", "5/4", "pi/2"])
def test_the_replay_refuses_a_hidden_0_over_0_at_every_typed_angle(phi1: str) -> None:
    """Before the new kernel the replay returned a value at 108°, 3π/7, 1.2 rad and refused
    the same 0/0 at 60° only: Z = sin² + cos² − 1 is 0 at every angle, so Z/Z is nowhere."""
    from graspcompass import PRESETS, Grasp, cli
    from graspcompass.construction.language import replay
    from graspcompass.errors import InputError

    text = _zero_over_zero_recipe()
    params = dict(PRESETS["fig6"]["params"], phi1=phi1)
    with pytest.raises((InputError, ArithmeticError, ValueError), match="V1"):
        replay(parse(text), Grasp(**params))
    with pytest.raises(SystemExit) as info:  # the command line: one line, exit 2
        import tempfile
        from pathlib import Path

        with tempfile.TemporaryDirectory() as d:
            f = Path(d) / "zz.gc"
            f.write_text(text)
            raise SystemExit(cli.main(["steps", str(f), "--phi1", phi1]))
    assert info.value.code == 2


def test_check_against_paper_proves_nothing_about_a_0_over_0_v1(tmp_path, capsys) -> None:
    from graspcompass import cli

    f = tmp_path / "zz.gc"
    f.write_text(_zero_over_zero_recipe())
    status = cli.main(["check", str(f), "--against", "paper", "-q", "--json"])
    out = capsys.readouterr()
    assert status != 0
    if out.out.strip():  # a report: none of the objects made from V1 is PROVED
        import json

        doc = json.loads(out.out)
        rows = {r["name"]: r["status"] for k in ("steps", "targets") for r in doc[k]}
        for name in ("V1", "circle1", "B12", "B13", "B14"):
            assert rows.get(name) != "PROVED", name
    else:  # refused: one line naming the step, exit 2
        assert status == 2 and "V1" in out.err and len(out.err.strip().splitlines()) == 1


# -- item 5: a REFUTED row carries a counterexample or a stated exact reason --------------------
def test_a_target_of_the_wrong_kind_is_refuted_with_a_stated_reason() -> None:
    from graspcompass.construction.language import paper_text

    text = paper_text()
    head = text[: text.index("# -- the circles")]
    old = "V1 = point_from_lengths OMX1 OY1 (-1, -1)"
    r = check_program(parse(head.replace(old, "V1 = line_through O P1")), "paper")
    row = next(t for t in r.targets if t.name == "V1")
    assert row.status is Status.REFUTED and row.counterexample is None
    assert row.reason and "Line" in row.reason and "every" in row.reason
    assert row.record()["reason"] == row.reason
    from graspcompass.proof.program_report import to_markdown, to_table

    assert row.reason[:40] in to_table(r) and "none: " in to_markdown(r)


def test_a_bare_refuted_row_is_not_reported_as_refuted() -> None:
    from graspcompass.proof.program_check import CheckRow
    from graspcompass.proof.prove import ProofResult

    row = CheckRow("x", "claim", 1, ProofResult(Status.REFUTED, "no reason", 0.0))
    assert row.status is Status.UNDECIDED


def test_steps_built_on_a_step_that_exists_nowhere_are_refuted() -> None:  # item 2
    """The 0/0 hidden in a let: V1 is vacuous, and so is every step made from it (circle1,
    the break points B12, B13, B14): none is PROVED, each says where it comes from."""
    from graspcompass.construction.language import paper_text

    text = paper_text().replace(
        "V1 = point_from_lengths OMX1 OY1 (-1, -1)",
        f"let z = {Z}/{Z}\nV1 = point_from_lengths OMX1 OY1 (-z, -1)",
    )
    r = check_program(parse(text), "paper")
    rows = {(row.kind, row.name): row for row in r.rows}
    for name in ("V1", "circle1", "B12", "B13", "B14"):
        row = rows[("step", name)]
        assert row.status is Status.REFUTED and row.reason, name
    assert "built on V1" in rows[("step", "B12")].reason
    assert rows[("target", "V1")].status is Status.REFUTED
    assert rows[("target", "circle1")].status is Status.REFUTED
    assert rows[("step", "circle2")].status is Status.PROVED  # the rest stands
    assert r.exit_status == 1
