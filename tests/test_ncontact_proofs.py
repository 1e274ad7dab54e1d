"""The n-contact claims (issue 25): proved, and their wrong variants refuted."""

from __future__ import annotations

import sympy as sp

from graspcompass.proof.catalogue import CLAIMS, ncontact_extra
from graspcompass.proof.catalogue_core import check
from graspcompass.proof.catalogue_ncontact import (
    _dual,
    redundant_inside,
    table1c_vertices,
    wrong_claims,
)
from graspcompass.proof.prove import Status


def test_table1c_vertices_are_the_papers_printed_numbers() -> None:
    """Table I(c): φ = π/2, μ1 = 1/2, μ2 = 7/5; by hand from (28)-(39), tan(π/2 ± ξ) = ∓1/μ."""
    R = sp.Rational
    assert table1c_vertices() == ((-6, -4), (R(24, 7), R(-10, 7)), (2, 4), (R(4, 7), R(10, 7)))


def test_table1c_redundancy_is_in_the_default_catalogue_and_proved() -> None:
    c = next(c for c in CLAIMS if c.id == "table1c-V4-redundant")
    assert check(c).status is Status.PROVED


def test_wrong_claims_are_refuted() -> None:
    for name, run in wrong_claims().items():
        assert run().status is Status.REFUTED, name
    # a point on an edge of the triangle is not strictly inside
    V = ((0, 0), (2, 0), (0, 2), (1, 0))
    assert redundant_inside(V).status is Status.REFUTED
    assert (
        redundant_inside(((0, 0), (2, 0), (0, 2), (sp.Rational(1, 2),) * 2)).status is Status.PROVED
    )


def test_v1_formula_dual_feasibility_and_slackness_proved() -> None:
    by = {c.id: c for c in ncontact_extra()}
    assert {"nc2-V1", "nc2-V4-cs", "nc2-short"} <= set(by)
    for cid in ("nc2-V1", "nc2-V1-dual", "nc2-V1-cs"):
        r = check(by[cid])
        assert r.status is Status.PROVED and "condition (1)" in r.hypotheses, cid
    assert _dual(3, -1).status is Status.REFUTED


def test_three_fingers_symbolic_vertex_constructed_and_dual_feasible() -> None:
    by = {c.id: c for c in ncontact_extra()}
    r = check(by["nc3-constructed"])
    assert r.status is Status.PROVED and any("mu1**2" in c for c in r.conditions)
    d = check(by["nc3-dual"])
    assert d.status is Status.PROVED and any("π/3" in h for h in d.hypotheses)
    assert check(by["nc3-vertex"]).status is Status.PROVED
