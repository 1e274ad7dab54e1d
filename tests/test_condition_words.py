"""Conditions in geometric words (issue 24), and the exact arguments behind the last
corpus claims proved: a quadratic in one symbol ≥ 0, p + q√R by squaring, a constant's
minimal polynomial.  Expected values from hand computation."""

from __future__ import annotations

import json

import sympy as sp

from graspcompass.construction.language import parse
from graspcompass.geometry.roots import constructed_sqrt, nonnegative
from graspcompass.proof.program_check import check_program
from graspcompass.proof.program_report import to_json, to_markdown, to_table
from graspcompass.proof.program_roots import algebraic_zero, positive_by_squaring

MEET = """param a real
param b real
A = point (0, 0)
B = point (1, a)
C = point (0, 1)
D = point (1, b)
l = line_through A B
m = line_through C D
X = meet l m
claim on X l
"""


def test_the_lines_are_not_parallel_in_table_json_and_markdown():
    # AB = (1, a), CD = (1, b - 1): they meet iff the cross product b - 1 - a ≠ 0
    report = check_program(parse(MEET))
    (cond,) = report.claims[0].result.conditions
    lhs = sp.sympify(
        cond.split(" ≠ 0")[0],
        locals={"a": sp.Symbol("a", real=True), "b": sp.Symbol("b", real=True)},
    )
    a, b = sp.symbols("a b", real=True)
    assert sp.expand(lhs * (b - 1 - a)) != 0 and sp.cancel(lhs / (b - 1 - a)).is_number
    words = "the lines AB and CD are not parallel"
    assert cond.endswith(f"({words})")
    assert words in to_table(report)
    assert words in json.loads(to_json(report))["claims"][0]["conditions"][0]
    assert words in to_markdown(report)


def test_a_condition_true_everywhere_is_not_asked():
    # the line through D and B meets the circle about B through C: (|BC|)² ≥ 0 always
    text = """param c1 real
param c2 real
B = point (0, 0)
D = point (0, 1)
C = point (c1, c2)
lDB = line_through D B
kC = circle_through B C
G = intersect_line_circle lDB kC (0)
claim on G kC
"""
    r = check_program(parse(text)).claims[0].result
    assert not any("≥" in c for c in r.conditions), r.conditions
    assert any("meets the circle kC" in c for c in r.implied)


def test_nonnegative_quadratic_in_one_symbol():
    k, t = sp.symbols("k t", real=True)
    # 2t²k² − 2tk + t² + 1: discriminant in k is −4t²(2t² + 1) ≤ 0, leading 2t² ≥ 0
    assert nonnegative(sp.expand(2 * k**2 * t**2 - 2 * k * t + t**2 + 1))
    # k² − 3kt + t² is negative at k = t = 1: never shown ≥ 0
    assert not nonnegative(k**2 - 3 * k * t + t**2)
    assert not nonnegative(sp.expand(k**2 * t**2 - 2 * k * t + 1 - t**2))  # −1 at k = 0, t = 1
    f = 2 * k**2 * t**2 - 2 * k * t + t**2 + 1
    assert constructed_sqrt(sp.expand(f**2)) == f


def test_squaring_is_sound():
    a, b = sp.symbols("a b", positive=True)
    pos = lambda e: bool(e.is_positive)  # noqa: E731
    assert positive_by_squaring(a + b - sp.sqrt(a**2 + b**2), pos)
    assert positive_by_squaring(sp.sqrt(a**2 + b**2) - a, pos)  # b² > 0
    # (a + b)² − 2(a² + b²) = −(a − b)²: not positive, so not shown
    assert not positive_by_squaring(a + b - sp.sqrt(2) * sp.sqrt(a**2 + b**2), pos)
    assert not positive_by_squaring(sp.sqrt(a**2 + b**2) - a - b, pos)


def test_algebraic_zero_is_exact():
    # 2 sin 36° = √(10 − 2√5)/2 (the side of the regular pentagon in the unit circle)
    side = sp.sqrt(10 - 2 * sp.sqrt(5)) / 2
    assert algebraic_zero(side - 2 * sp.sin(sp.pi / 5))
    assert not algebraic_zero(side - 2 * sp.sin(sp.pi / 5) - sp.Rational(1, 10**30))
    assert not algebraic_zero(sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6)) + 1)
    assert algebraic_zero(sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6)))


def test_conditions_factored_through_fractions_and_powers():
    from graspcompass.proof.program_words import tidy

    t, u = sp.symbols("t u", real=True)
    names = {"t": t, "u": u}
    # 4t²/(t² + 1) ≠ 0 iff t ≠ 0 (t² + 1 > 0); (t² + 1)/(u − 1) ≠ 0 iff u ≠ 1 (defined)
    assert tidy(["4*t**2/(t**2 + 1) ≠ 0"], [], names)[0] == ["t ≠ 0"]
    assert tidy(["(t**2 + 1)/(u - 1) ≠ 0"], [], names)[0] == ["u - 1 ≠ 0"]
    # a sign through a divisor of unknown sign is kept as written
    assert tidy(["(t - 1)/(u - 2) ≥ 0"], [], names)[0] == ["(t - 1)/(u - 2) ≥ 0"]
    assert tidy(["(t - 1)/(u**2 + 2) ≥ 0"], [], names)[0] == ["t - 1 ≥ 0"]
    # the same condition written twice (expanded, times −2) is asked once, with its words
    got = tidy(
        ["(t - u)**2 + 1 - 1 + t ≠ 0 (A and B are distinct)", "-2*t**2 + 4*t*u - 2*u**2 - 2*t ≠ 0"],
        [],
        names,
    )[0]
    assert len(got) == 1 and got[0].endswith("(A and B are distinct)")
