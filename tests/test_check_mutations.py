"""A mutation suite of users' files: planted false, vacuous and degenerate claims (issue 19).

Every file is checked by :func:`graspcompass.proof.program_check.check_program`; every
verdict is judged by ``tests/_evaluator.py``, which shares no code with graspcompass
(its own parser and geometry, mpmath at 60 digits):

* a planted false, vacuous or degenerate claim is never PROVED;
* every PROVED claim holds (or its object does not exist) at random admissible points;
* every counterexample is a point where the claim's objects exist and the claim is false.
"""

from __future__ import annotations

import random

import pytest

from _evaluator import evaluate, params_of, random_point
from graspcompass.construction.language import parse
from graspcompass.proof.program_check import check_program
from graspcompass.proof.prove import Status

Z = "(sin(phi1)**2 + cos(phi1)**2 - 1)"
Z2 = "(sin(phi1 + pi/180)**2 + cos(phi1 + pi/180)**2 - 1)"
SQ = """param a > 0
param b > 0
A = point (0, 0)
B = point (a, 0)
C = point (a, b)
D = point (0, b)
M = midpoint A C
AB = line_through A B
BC = line_through B C
AC = line_through A C
BD = line_through B D
CD = line_through C D
"""
GR = """param x1 > 0
param x2 > 0
param y >= 0
param phi1 angle
param mu1 friction
hypothesis condition1
O = point (0, 0)
P1 = point (x1, y)
C = point (x1, 0)
Q = point (x2, 0)
xa = line_with_direction O (1, 0)
side1 = line_with_direction P1 (-(sin(phi1) + cos(phi1)*mu1), -(cos(phi1) - sin(phi1)*mu1))
X1 = meet side1 xa
"""
AN = """param phi1 angle
param phi2 angle
param xi1 half_angle
param x1 > 0
param x2 > 0
"""

#: (file, what the last claim is): "false" (false somewhere), "vacuous" (its object exists
#: nowhere, or a condition it needs is false everywhere), "true".
FILES = [
    (SQ + "claim collinear A B A D", "false"),
    (SQ + "claim collinear A A B D", "false"),
    (SQ + "claim collinear B A D A", "false"),
    (SQ + "claim collinear A B B C", "false"),
    (SQ + "claim collinear A M C A", "true"),
    (SQ + "claim collinear A M C D", "false"),
    (SQ + "MM = midpoint A A\nclaim collinear MM B D", "false"),
    (SQ + "MM = midpoint A A\nclaim collinear A MM B", "true"),
    (SQ + "claim concurrent AB AB CD", "false"),
    (SQ + "claim concurrent AC BD AB", "false"),
    (SQ + "claim concurrent AC BD AC", "true"),
    (SQ + "BA = line_through B A\nclaim concurrent AB BA CD", "false"),
    (SQ + "claim sign a + 1 == a", "false"),
    (SQ + "claim sign a*b == b*a", "true"),
    (SQ + "claim sign a - b == 0", "false"),
    (SQ + "claim perpendicular AB AC", "false"),
    (SQ + "claim parallel AB CD", "true"),
    (SQ + "claim on M BD", "true"),
    (SQ + "claim on D AC", "false"),
    (SQ + "claim M == point(a/2, b/2)", "true"),
    (SQ + "claim M == point(a/2, a/2)", "false"),
    (GR + f"P = point (x1*{Z}/(x1*{Z}), 0)\nclaim P == point(1, 0)", "vacuous"),
    (GR + f"claim sign {Z}/{Z} > 0", "vacuous"),
    (GR + "claim sign 1/(x1 - x1*sin(phi1)**2 - x1*cos(phi1)**2) > 0", "vacuous"),
    (GR + "R = point (sqrt(-x1), 0)\nclaim R == point(sqrt(-x1), 0)", "vacuous"),
    (GR + "claim sign sqrt(-x1 - 1) >= 0", "vacuous"),
    (GR + "let k = x1*(x1 - x2)/(x1 - x2)\nclaim sign k > x1", "false"),
    (GR + "claim sign x1*(x1 - x2)/(x1 - x2) == x1", "true"),
    (GR + "c = circle_through C Q\nclaim on Q c", "true"),
    (GR + "OM = midpoint C C\nc = circle_on_diameter OM C\nclaim on O c", "vacuous"),
    (GR + "c = circle_on_diameter O X1\nclaim on X1 c", "true"),
    (GR + "claim on X1 side1", "true"),
    (GR + "claim sign x1 - x2 > 0", "false"),
    (GR + "claim sign cos(phi1) > 0", "false"),
    (GR + "claim sign mu1*sin(phi1) - cos(phi1) > 0 under condition1", "true"),
    (GR + "claim sign mu1*sin(phi1) - cos(phi1) < 0 under condition1", "false"),
    (GR + f"P = point (x1*{Z2}/(x1*{Z2}), 0)\nclaim P == point(2, 0)", "vacuous"),
    (AN + "claim sign cos(phi1 + xi1) + 1/100 < 0", "false"),
    (AN + "claim sign cos(phi1 + phi2) < 0", "false"),
    (AN + "claim sign sin(phi1) >= 0", "true"),
    (AN + "claim sign sin(phi1 + 1) > -2", "true"),
    (AN + "claim sign tan(xi1) > 0", "true"),
    (AN + "claim sign x1/(x1 - x1) > 0", "vacuous"),
    (AN + "claim sign x1 + x2 != x1", "true"),
    (AN + "claim sign x1 - x2 != 0", "false"),
    (
        "param mu1 friction\nparam xi1 half_angle\nO = point (0, 0)\nA = point (1, 0)\n"
        "l = line_with_direction O (1, mu1)\nm = line_with_direction A (cos(xi1), sin(xi1))\n"
        "X = meet l m\nclaim on X l",
        "vacuous",
    ),
    (
        "param a > 0\nA = point (0, 0)\nB = point (a, 0)\nl = line_through A B\n"
        "m = line_with_direction B (1, 0)\nX = meet l m\nclaim on X l",
        "degenerate",
    ),
    # -- concyclic: one circle or one line, as a set of points
    (SQ + "claim concyclic A B C D", "true"),
    (SQ + "claim concyclic A B C M", "false"),
    (SQ + "claim concyclic A B C D M", "false"),
    (SQ + "claim concyclic A B A M", "true"),
    (SQ + "claim concyclic A M C A M", "true"),
    (SQ + "MM = midpoint A A\nclaim concyclic MM B C D", "true"),
    (SQ + "MM = midpoint A A\nclaim concyclic MM B C M", "false"),
    (GR + "F = foot O side1\nclaim concyclic O P1 F C", "true"),
    (GR + "F = foot O side1\nclaim concyclic O P1 F X1", "false"),
    # -- a hidden 0/0 in a let
    (GR + f"let k = x1*{Z}/{Z}\nclaim sign k > 0", "vacuous"),
    (GR + f"let k = {Z}/(x1*{Z})\nP = point (k, 0)\nclaim P == point(1/x1, 0)", "vacuous"),
    (GR + "let k = (x1 - x2)/(x1 - x2)\nclaim sign k == 1", "true"),
    # -- a radicand negative on the whole model
    (GR + "let r = sqrt(-x1 - y)\nclaim sign r >= 0", "vacuous"),
    (AN + "claim sign sqrt(cos(phi1)**2 - 2) > 0", "vacuous"),
    (GR + "R = point (sqrt(-(x1 - x2)**2 - 1), 0)\nclaim on R xa", "vacuous"),
    # -- an intersection that never exists
    (
        "param a > 0\nO = point (0, 0)\nA = point (a, 0)\nc = circle_through O A\n"
        "B = point (0, 2*a)\nl = line_with_direction B (1, 0)\n"
        "P = intersect_line_circle l c (0)\nclaim on P c",
        "vacuous",
    ),
    (
        "param a > 0\nO = point (0, 0)\nA = point (a, 0)\nc = circle_through O A\n"
        "E = point (4*a, 0)\nF = point (5*a, 0)\nc2 = circle_through E F\n"
        "P = intersect_circles c c2 (0)\nclaim on P c2",
        "vacuous",
    ),
    (
        "param a > 0\nO = point (0, 0)\nA = point (a, 0)\nB = point (2*a, 0)\n"
        "c = circle_through O A\nc2 = circle_through O B\n"
        "P = intersect_circles c c2 (0)\nclaim on P c",
        "vacuous",
    ),
    # -- a claim under a hypothesis that is false where the claim needs it
    (GR + "claim sign 1/sqrt(cos(phi1) - mu1*sin(phi1)) > 0 under condition1", "vacuous"),
    (GR + "claim sign sqrt(mu1*sin(phi1) - cos(phi1)) >= 0 under condition1", "true"),
    (GR + "claim sign mu1*sin(phi1) - cos(phi1) == 0 under condition1", "false"),
]


def _check(text: str):
    try:
        return check_program(parse(text, "mut.gc"))
    except Exception as exc:  # a refusal is fine for a degenerate file; a crash is not
        from graspcompass.errors import InputError
        from graspcompass.geometry import GeometryError

        assert isinstance(exc, (InputError, GeometryError)), repr(exc)
        return None


@pytest.mark.parametrize(
    "text, kind", FILES, ids=[f"{i:02d}-{k}" for i, (_, k) in enumerate(FILES)]
)
def test_mutation(text: str, kind: str) -> None:
    text += "\n"
    report = _check(text)
    if report is None:
        assert kind in ("degenerate", "vacuous")  # refused: never PROVED
        return
    row = report.claims[-1]
    if kind != "true":
        assert row.status is not Status.PROVED, (row.name, row.result)
    for r in report.rows:  # REFUTED: a counterexample or a stated exact reason, never bare
        if r.status is Status.REFUTED:
            assert r.counterexample is not None or r.reason, (r.name, r.result)
    params = params_of(text)
    rng = random.Random(19)
    for i, claim_row in enumerate(report.claims):
        if claim_row.status is Status.PROVED:
            cond1 = "condition (1)" in claim_row.result.hypotheses
            for _ in range(6):
                got = evaluate(text, random_point(params, rng, cond1))[i]
                assert got is not False, (claim_row.name, claim_row.result)
        if claim_row.counterexample:
            got = evaluate(text, dict(claim_row.counterexample))[i]
            assert got is False, (claim_row.name, claim_row.counterexample, got)


def test_the_suite_is_large_enough() -> None:
    assert len(FILES) >= 60
    assert sum(k != "true" for _, k in FILES) >= 38
    assert sum("concyclic" in t for t, _ in FILES) >= 9
