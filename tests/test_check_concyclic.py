"""``claim concyclic``: points on one circle or one line, over any repetition (issue 19).

The truth comes from ``tests/_evaluator.py`` (no code shared with graspcompass; mpmath
at 60 digits): coincident points are one point, three or fewer distinct points always
lie on a circle or a line, and more must lie on the line or the circle through the first
three distinct ones.  The configurations are drawn by hypothesis from points on the
circle x² + y² = 25, on the x-axis and on a small grid, repeated and coincident (one
point also made as the midpoint of a point with itself), scaled by a parameter a > 0
and moved by b: concyclicity does not depend on a and b, so PROVED must be the truth
at every point and REFUTED its negation.
"""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _evaluator import evaluate, params_of, random_point
from graspcompass.construction.language import ConstructionBuilder, parse
from graspcompass.construction.program import ConstructionSyntaxError
from graspcompass.proof.program_check import check_program
from graspcompass.proof.prove import Status

CIRCLE = [(3, 4), (4, 3), (-3, 4), (5, 0), (0, -5), (-4, -3), (0, 5)]
AXIS = [(-2, 0), (1, 0), (6, 0)]
GRID = [(1, 1), (2, -1), (0, 0), (1, 2)]
POOL = CIRCLE + AXIS + GRID


def _file(points: list[tuple[int, int]], order: list[int], twin: int | None) -> str:
    lines = ["param a > 0", "param b real"]
    for i, (x, y) in enumerate(points):
        lines.append(f"P{i} = point ({x}*a + b, {y}*a)")
    names = [f"P{i}" for i in order]
    if twin is not None:  # the same point under another name, made by the construction
        lines.append(f"T = midpoint P{twin} P{twin}")
        names.append("T")
    lines.append("claim concyclic " + " ".join(names))
    return "\n".join(lines) + "\n"


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(POOL), min_size=2, max_size=5, unique=True), st.data())
def test_concyclic_against_the_evaluator(points, data) -> None:
    n = len(points)
    size = data.draw(st.integers(min_value=max(4 - (n < 4), 3), max_value=6))
    order = data.draw(st.lists(st.integers(0, n - 1), min_size=size, max_size=size))
    twin = data.draw(st.one_of(st.none(), st.integers(0, n - 1)))
    if len(order) + (twin is not None) < 4:
        order += [order[0]] * (4 - len(order) - (twin is not None))
    text = _file(points, order, twin)
    row = check_program(parse(text)).claims[0]
    rng = random.Random(7)
    truth = {evaluate(text, random_point(params_of(text), rng))[0] for _ in range(3)}
    assert len(truth) == 1 and None not in truth, (text, truth)  # independent of a, b
    want = truth.pop()
    assert row.status is (Status.PROVED if want else Status.REFUTED), (text, row.result)
    if row.counterexample:
        assert evaluate(text, dict(row.counterexample))[0] is False


@pytest.mark.parametrize(
    "names, want",
    [
        ("A B C D", True),  # the rectangle's corners: one circle
        ("A B C M", False),  # A, M, C collinear, B off their line
        ("A M C A", True),  # repeated A: two... three distinct points, on one line
        ("A B A B", True),  # two distinct points
        ("A B M C D", False),
        ("A A A A", True),
    ],
)
def test_concyclic_examples(names: str, want: bool) -> None:
    text = (
        "param a > 0\nparam b > 0\nA = point (0, 0)\nB = point (a, 0)\n"
        "C = point (a, b)\nD = point (0, b)\nM = midpoint A C\n"
        f"claim concyclic {names}\n"
    )
    row = check_program(parse(text)).claims[0]
    assert row.status is (Status.PROVED if want else Status.REFUTED)
    assert evaluate(text, {"a": 2, "b": 3})[0] is want


def test_concyclic_on_a_constructed_circle() -> None:
    """Points made on a circle (centre O, through A: its intersections with two lines
    through O), with a parameter in the circle; the centre is on no circle through three
    of them."""
    text = (
        "param a > 0\nO = point (0, 0)\nA = point (a, 0)\nc = circle_through O A\n"
        "l = line_with_direction O (1, 1)\nm = line_with_direction O (1, -2)\n"
        "P = intersect_line_circle l c (0)\nQ = intersect_line_circle m c (0)\n"
        "R = intersect_line_circle m c (1)\n"
        "claim concyclic A P Q R\nclaim concyclic O A P Q\n"
    )
    rows = check_program(parse(text)).claims
    assert [r.status for r in rows] == [Status.PROVED, Status.REFUTED]
    assert evaluate(text, {"a": "3/2"}) == [True, False]
    assert evaluate(text, dict(rows[1].counterexample))[1] is False


def test_concyclic_takes_four_points_or_more() -> None:
    with pytest.raises(ConstructionSyntaxError, match="at least 4"):
        parse(
            "param a > 0\nA = point (0, 0)\nB = point (a, 0)\nC = point (a, a)\n"
            "claim concyclic A B C\n"
        )
    b = ConstructionBuilder()
    b.param("a", "positive")
    for n, v in (("A", (0, 0)), ("B", ("a", 0)), ("C", ("a", "a")), ("D", (0, "a"))):
        b.step(n, "point", values=v)
    b.claim("concyclic", "A", "B", "C", "D")
    assert check_program(b.build()).claims[0].status is Status.PROVED
