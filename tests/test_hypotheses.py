"""Hypotheses as named inequalities on the parameters (issue 24): read, written back,
used by the checker, stated in its results; never a proof of a false statement."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from graspcompass.construction._hypotheses import Inequality
from graspcompass.construction.language import ConstructionBuilder, parse
from graspcompass.construction.program import ConstructionSyntaxError
from graspcompass.proof.program_check import check_program
from graspcompass.proof.program_hypotheses import discharge, sign_from
from graspcompass.proof.program_report import to_json, to_markdown, to_table

OUTSIDE = """param p real
param q real
hypothesis outside: p**2 + q**2 > 1
O = point (0, 0)
E = point (1, 0)
P = point (p, q)
circ = circle_through O E
T = tangent_point P circ (0)
"""


def test_read_and_written_back():
    prog = parse(OUTSIDE)
    (h,) = prog.inequalities
    p, q = (x.symbol for x in prog.params)
    assert (h.name, h.relation, h.lhs, h.rhs) == ("outside", ">", p**2 + q**2, 1)
    assert parse(prog.to_text()) == prog
    assert "hypothesis outside: p**2 + q**2 > 1" in prog.to_text()


@pytest.mark.parametrize(
    "line, what",
    [
        ("hypothesis h: 1 > 0", "has none"),
        ("hypothesis h: p == 1", "REL one of"),
        ("hypothesis h: z > 1", "unknown name 'z'"),
        ("hypothesis condition1: p > 1", "twice or a reserved"),
    ],
)
def test_bad_hypotheses_are_refused_with_their_line(line, what):
    with pytest.raises(ConstructionSyntaxError, match=what) as err:
        parse("param p real\n" + line, "f.gc")
    assert err.value.line == 2


def test_the_builder_makes_the_same_program():
    b = ConstructionBuilder()
    b.param("p", "real")
    b.param("q", "real")
    b.hypothesis("outside", "p**2 + q**2 > 1")
    assert (
        b.build().inequalities
        == parse("param p real\nparam q real\nhypothesis outside: p**2 + q**2 > 1").inequalities
    )


def test_sign_from_hypotheses_by_hand():
    p, q = sp.symbols("p q", real=True)
    H = (Inequality("h", ">", p, sp.Integer(1)),)  # p > 1
    assert sign_from(p - 1, H)[0] == 1
    assert sign_from(p, H)[0] == 1  # p = (p - 1) + 1
    assert sign_from((1 - p) * (q**2 + 1), H)[0] == -1
    assert sign_from(p - 2, H) is None  # p > 1 does not give p > 2
    assert sign_from(p * q, H) is None  # q's sign is unknown
    assert sign_from(sp.sqrt(p - 1) * (p + 1), H)[0] == 1
    kept, implied = discharge(["p - 1 ≠ 0 (A and B are distinct)", "q ≠ 0"], H, {"p": p, "q": q})
    assert kept == ["q ≠ 0"] and implied[0].endswith("(from the hypothesis h)")


def test_the_checker_uses_and_states_the_hypothesis():
    text = OUTSIDE + (
        "claim sign p**2 + q**2 - 1 > 0\nclaim sign p > 1\nclaim sign p**2 + q**2 > 2\n"
    )
    report = check_program(parse(text))
    statuses = [r.status.value for r in report.claims]
    assert statuses == ["PROVED", "REFUTED", "REFUTED"]
    hyp = "hypothesis outside: p**2 + q**2 > 1"
    assert all(hyp in r.result.hypotheses for r in report.rows)
    for r in report.claims[1:]:  # the counterexamples lie where the hypothesis holds
        pt = {k: sp.Rational(v) for k, v in r.counterexample.items()}
        assert pt["p"] ** 2 + pt["q"] ** 2 > 1
    # the tangent point's condition (P not inside the circle) follows from the hypothesis
    step_t = next(r for r in report.steps if r.name == "T")
    assert not step_t.result.conditions
    assert any("from the hypothesis outside" in t for t in step_t.result.implied)
    assert to_table(report).splitlines()[0].endswith(hyp)
    data = json.loads(to_json(report))
    assert all(hyp in row["hypotheses"] for row in data["claims"])
    assert r"hypothesis outside: p\*\*2 + q\*\*2 \> 1" in to_markdown(report)  # escaped


def test_without_the_hypothesis_the_claim_is_refuted():
    text = (
        OUTSIDE.replace("hypothesis outside: p**2 + q**2 > 1\n", "")
        + "claim sign p**2 + q**2 - 1 > 0\n"
    )
    assert check_program(parse(text)).claims[0].status.value == "REFUTED"


def test_a_hypothesis_decides_the_branch():
    # the line OA meets the circle on the diameter A(1, 0) B(p, 0) in A and B; the
    # kernel's branch 0 lies further along, x = max(1, p): B where p > 1, A where p < 1
    path = "tests/corpus_geometry/48_branch_by_hypothesis.gc"
    from pathlib import Path

    text = (Path(__file__).parent.parent / path).read_text("utf-8")
    first = check_program(parse(text)).claims[0]
    assert first.status.value == "PROVED" and "hypothesis beyond: p > 1" in first.result.hypotheses
    other = text.replace("hypothesis beyond: p > 1", "hypothesis before: p < 1")
    got = [r.status.value for r in check_program(parse(other)).claims[:4]]
    assert got == ["REFUTED", "REFUTED", "PROVED", "PROVED"]  # Y == B, X == A now
    none = text.replace("hypothesis beyond: p > 1", "")
    assert check_program(parse(none)).claims[0].status.value == "REFUTED"


def test_branch_roots_by_hand():
    from graspcompass.proof.program_hypotheses import branch_roots

    p, q = sp.symbols("p q", real=True)
    H = (Inequality("h", ">", p, sp.Integer(1)),)
    assert branch_roots(sp.sqrt((p - 1) ** 2 * (q**2 + 1)), H) == (p - 1) * sp.sqrt(q**2 + 1)
    assert branch_roots(sp.sqrt(sp.expand((p - 1) ** 2 * (q**2 + 1))), H) == (p - 1) * sp.sqrt(
        q**2 + 1
    )
    assert branch_roots(sp.sqrt(sp.expand((1 - p) ** 2)), H) == p - 1
    assert branch_roots(sp.sqrt((q - 1) ** 2), H) == sp.sqrt((q - 1) ** 2)  # q's sign unknown


def test_contradictory_hypotheses_prove_nothing():
    text = (
        "param p real\nhypothesis big: p > 1\nhypothesis small: p < 0\n"
        "A = point (p, 0)\nclaim sign p > 5\nclaim sign p**2 + 1 > 0\n"
    )
    got = [r.status.value for r in check_program(parse(text)).claims]
    # vacuous under p > 1 and p < 0: neither is reported as a proof (the second is true
    # for every p, but the file states it under its hypotheses)
    assert got == ["UNDECIDED", "UNDECIDED"]


def test_a_weak_hypothesis_gives_no_non_zero():
    p = sp.Symbol("p", real=True)
    ge = (Inequality("h", ">=", p, sp.Integer(1)),)
    ne = (Inequality("h", "!=", p, sp.Integer(1)),)
    assert sign_from(p - 1, ge, nonzero_only=True) is None  # p ≥ 1 allows p - 1 = 0
    assert sign_from(p - 1, ne, nonzero_only=True) == (0, ("h",))  # ≠ 0, sign unknown
    assert sign_from(p - 1, ne) is None
