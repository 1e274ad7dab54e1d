"""The claims catalogue (issue 9): PROVED means proved, and the catalogue checks the paper.

Every counterexample of a REFUTED claim is re-checked here, independently of the
checker: the domains of every symbol, condition (1) by hand, μ_i = tan ξ_i when
both appear, and that the statement really fails there.
"""

from __future__ import annotations

import functools
import json
import math

import pytest
import sympy as sp

from graspcompass.cli import main
from graspcompass.expr import parse_exact
from graspcompass.proof import paper as P
from graspcompass.proof.catalogue import CLAIMS, Claim, build_claims, check, claim, session
from graspcompass.proof.catalogue_section5 import FIG8_GOALS, fig8_case, table1_signs
from graspcompass.proof.prove import ProofResult, Status, prove_identity
from graspcompass.proof.report import run_catalogue, to_json, to_markdown, to_table
from graspcompass.symbols import F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y

SYMS = {str(s): s for s in (F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y)}
HALF_PI = math.pi / 2


def admissible(values: dict[str, str]) -> bool:
    """Every domain, μ = tan ξ where both are given, and condition (1), by hand (floats with a
    margin far above rounding; the points are exact multiples of π/24 or small rationals)."""
    v = {k: float(sp.N(parse_exact(x), 30)) for k, x in values.items()}
    for k in ("x1", "x2", "F_e", "mu1", "mu2", "r"):
        if k in v and not v[k] > 0:
            return False
    if "y" in v and not v["y"] >= 0:
        return False
    for i in ("1", "2"):
        phi, xi, mu = v.get("phi" + i), v.get("xi" + i), v.get("mu" + i)
        if xi is not None and not 0 < xi < HALF_PI:
            return False
        if phi is not None and not 0 < phi <= math.pi:
            return False
        if xi is not None and mu is not None and abs(math.tan(xi) - mu) > 1e-12:
            return False
        fric = xi if xi is not None else (math.atan(mu) if mu is not None else None)
        if phi is not None and fric is not None:
            if not (-HALF_PI < phi - fric < HALF_PI < phi + fric < 3 * HALF_PI):
                return False
        elif phi is not None and not phi < math.pi:  # some ξ satisfies (1) iff φ < π
            return False
    return True


def test_admissible_catches_the_blind_spots():
    assert admissible({"phi1": "pi/3", "xi1": "pi/4", "mu1": "1"})
    assert not admissible({"phi1": "pi/3", "xi1": "pi/4", "mu1": "2"})  # μ ≠ tan ξ
    assert not admissible({"phi1": "pi/12", "xi1": "pi/6"})  # φ + ξ < π/2: (1) fails
    assert not admissible({"xi1": "pi/2"}) and not admissible({"x2": "0"})


@functools.cache
def catalogue_reports():
    """The catalogue, run once per test session (shared with test_proof.py)."""
    return run_catalogue(quiet=True)


@pytest.fixture(scope="session")
def reports():
    return catalogue_reports()


@pytest.fixture(scope="session")
def by_id(reports):
    return {r.claim.id: r for r in reports}


# the printed statements that fail, and what fails there (lhs - rhs, or a sign to hold)
_REFUTED_CHECK = {
    "eq23-printed-upper": lambda: (
        (P.c1 * mu1 + P.s1) / (P.s1 * mu1 - P.c1) - (P.s1 + P.c1 * mu1) / (P.c1 - P.s1 * mu1)
    ),
    "eq23-printed-lower": lambda: (
        (P.c1 * mu1 - P.s1) / (P.s1 * mu1 + P.c1) - (P.s1 - P.c1 * mu1) / (P.c1 + P.s1 * mu1)
    ),
    "A1-printed": lambda: F_e / (x1 + x2) * (sp.cos(phi2) - sp.sin(phi2)),
}


def test_errata_are_exactly_the_known_ones_and_corrected(by_id):
    refuted = {i for i, r in by_id.items() if r.result.status is Status.REFUTED}
    assert refuted == {"eq23-printed-upper", "eq23-printed-lower", "A1-printed", "s5-V1V2-printed"}
    for i in refuted:
        fix = by_id[i].claim.corrected_by
        assert fix and by_id[fix].result.proved
    assert all(r.result.status is not Status.UNDECIDED for r in by_id.values())


def test_every_counterexample_is_a_point_of_the_model(by_id):
    for i, r in by_id.items():
        if r.result.status is Status.REFUTED:
            cx = r.result.counterexample
            assert cx and admissible(cx), (i, cx)
            subs = {SYMS[k]: parse_exact(v) for k, v in cx.items()}
            if i in _REFUTED_CHECK:
                assert abs(sp.N(_REFUTED_CHECK[i]().subs(subs), 50)) > 1e-20, i
            else:  # s5-V1V2-printed: V1 or V2 not in y < 0, or V1 not left of V2
                S = [sp.N(sp.sympify(s).subs(subs), 50) for s in P.S_printed[:2]]
                C = [sp.N(sp.sympify(c).subs(subs), 50) for c in P.C_printed[:2]]
                assert any(val.free_symbols == set() and val >= 0 for val in C) or (
                    S[0].free_symbols == set() and S[0] >= S[1]
                ), (i, cx)


def test_s5_V1V2_by_hand():
    # φ1 = 19π/24, ξ1 = 5π/12 satisfies (1) but φ1 + ξ1 = 29π/24 > π: tan > 0, C1 > 0
    cx = {"phi1": "19*pi/24", "xi1": "5*pi/12", "x2": "1"}
    assert admissible(cx)
    assert sp.N(P.C_printed[0].subs({phi1: 19 * sp.pi / 24, xi1: 5 * sp.pi / 12, x2: 1})) > 0


def test_no_memo_by_id():
    # a new claim reusing an existing id with a false statement is not PROVED
    old = claim("eq16")
    assert check(old).proved
    fake = Claim("eq16", old.ref, "2 = 3", lambda: prove_identity(sp.sin(phi1) ** 2, 1))
    assert not check(fake).proved
    with session():
        assert check(old).proved and not check(fake).proved


def test_composites_check_their_own_statement():
    fig = [claim("fig8-V3"), claim("fig8-V4")]
    for case, (_text, premise, goal) in FIG8_GOALS.items():
        assert fig8_case(premise, goal, fig).proved, case
    # wrong own statements: (a) with V3 on the right; (c) "opposite sides"
    bad_a = fig8_case(FIG8_GOALS["a"][1], lambda v: v["R3"], fig)
    bad_c = fig8_case(FIG8_GOALS["c"][1], lambda v: v["L3"] and v["R4"], fig)
    assert not bad_a.proved and not bad_c.proved
    # a composite whose dependency is false is not PROVED either
    false_dep = Claim("x", "", "", lambda: ProofResult(Status.UNDECIDED, "", 0.0))
    assert not fig8_case(FIG8_GOALS["a"][1], FIG8_GOALS["a"][2], [false_dep]).proved


def test_eq24_25_depends_on_its_lemmas_by_object(by_id):
    c = by_id["eq24-25"].claim
    assert {d.id for d in c.depends} == {
        f"eq{n}-{w}" for n in (8, 9, 10, 11) for w in ("factor", "divisor-sign")
    }
    assert "infimum" in by_id["eq24-25"].result.method


def test_A1_corrected_is_not_a_tautology():
    # the corrected vector is typed entry by entry: swapping two entries must fail
    f = P.f_N_printed
    r = prove_identity(P.F_N_printed, sp.Matrix([f[0], f[1], f[3], f[2]]))
    assert r.status is Status.REFUTED and admissible(r.counterexample)


def test_mutated_new_claims_are_not_proved():
    from graspcompass.proof.catalogue_core import sign
    from graspcompass.proof.catalogue_section5 import _v1v2

    # V1 in y > 0 is false under φ + ξ < π
    C1 = P.C_printed[0].replace(sp.tan, lambda u: sp.sin(u) / sp.cos(u))
    r = sign(C1, +1, [C1], {phi1 + xi1: (sp.pi / 2, sp.pi)})
    assert r.status is Status.REFUTED and admissible(r.counterexample)
    assert sp.N(C1.subs({SYMS[k]: parse_exact(v) for k, v in r.counterexample.items()})) < 0
    # the printed §5 reading is never PROVED
    assert not all(p.proved for p in _v1v2(None, ""))
    # Fig. 8 with V3 tied to the wrong cone: refuted
    u = phi2 - xi2
    bad = prove_identity(P.S_printed[2] * sp.cos(u), y * sp.sin(u) - (x1 + x2) / 2 * sp.cos(u))
    assert bad.status is Status.REFUTED and admissible(bad.counterexample)


def test_table1_by_hand():
    # (36), (38) at φ = π/2: S3 = −2 + y/μ1, S4 = 2 − y/μ2 (tan(π/2 − ξ) = 1/μ)
    for case, y_, m1, m2 in (
        ("a", 1, 1, sp.Rational(6, 5)),
        ("b", 3, 1, sp.Rational(6, 5)),
        ("c", 2, sp.Rational(1, 2), sp.Rational(7, 5)),
    ):
        assert table1_signs(case) == (sp.sign(-2 + y_ / m1), sp.sign(2 - y_ / m2))


def test_all_statements_cover_the_paper(by_id):
    assert {
        "eq6-7",
        "s3.2-envelope",
        "s4-table1-V3V4",
        "s5-V1V2-corrected",
        "s5-robust",
        "s5-same-contact-24",
    } <= set(by_id)
    assert any("cos(phi1)" in x for x in by_id["eq23-rest-upper"].result.conditions)
    assert "foot" in by_id["eq31"].claim.statement
    assert "strictly" in by_id["fig8-V3"].claim.statement
    assert "√" in by_id["A3-17"].claim.statement


def test_fresh_catalogue_has_new_objects():
    again = build_claims()
    assert [c.id for c in again] == [c.id for c in CLAIMS]
    assert all(a is not b for a, b in zip(again, CLAIMS))


def test_reports_show_hypotheses_conditions_and_certificates(reports):
    recs = json.loads(to_json(reports))
    assert all({"hypotheses", "conditions", "implied"} <= set(r) for r in recs)
    assert any(r.get("certificate") for r in recs if r["status"] == "PROVED")
    by = {r["id"]: r for r in recs}
    assert "condition (1)" in by["eq8-divisor-sign"]["hypotheses"]
    assert "μ_i = tan ξ_i (22)" in by["eq8-divisor-sign"]["hypotheses"]
    md, table = to_markdown(reports), to_table(reports)
    # the Markdown writes the condition as MathJax math (issue 23), the table as text
    assert "extra: $\\cos{\\left(\\phi_{1} \\right)} \\ne 0$" in md and "hypotheses" in table
    assert all(f"`{c.id}`" in md for c in CLAIMS)


def test_cli_verify_json_and_help(capsys):
    assert main(["verify", "--help"]) == 0  # main() returns its status, never exits
    assert "exit status" in capsys.readouterr().out


def _leaves(cert):
    if cert is None:
        return []
    if "parts" in cert and "kind" not in cert:
        return [x for p in cert["parts"] for x in _leaves(p)]
    return [cert]


def test_every_certificate_of_verify_rechecks(reports):
    from graspcompass.proof.recheck import problems

    n = 0
    for r in reports:
        if r.result.proved:
            for cert in _leaves(r.result.certificate):
                n += 1
                assert not problems(cert), (r.claim.id, problems(cert)[:3])
    assert n >= 60
