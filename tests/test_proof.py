"""The proof checker: every claim of the paper, and deliberately wrong variants.

A checker that proves everything is a defect: each family of claims is fed
mutated statements (a sign flipped, an index swapped, φ+ξ for φ−ξ) that must
come back REFUTED with a counterexample that the test itself checks by exact
substitution at 50 digits, inside the admissible domain of condition (1).
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from graspcompass import Grasp, internal_force_diagram
from graspcompass.cli import main
from graspcompass.construction import Construction
from graspcompass.expr import parse_exact
from graspcompass.geometry import Point
from graspcompass.proof import (
    CLAIMS,
    Status,
    certify,
    check,
    claim,
    exit_status,
    prove_identity,
    prove_sign,
    to_markdown,
)
from graspcompass.proof import paper as P
from graspcompass.proof.catalogue import symbolic_construction
from graspcompass.proof.crosscheck import k_linprog, run_crosscheck
from graspcompass.symbols import F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y

SYMS = {str(s): s for s in (F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y)}


def admissible(values: dict) -> bool:
    """Every domain, condition (1) and μ = tan ξ when both appear, checked independently."""
    from test_catalogue import admissible as strict

    return strict(values)


def assert_refuted(result, lhs, rhs=0):
    assert result.status is Status.REFUTED, result
    cx = result.counterexample
    assert cx, "a refutation must carry a counterexample"
    assert admissible(cx), cx
    subs = {SYMS.get(k, sp.Symbol(k)): parse_exact(v) for k, v in cx.items()}
    diff = sp.sympify(lhs) - sp.sympify(rhs)
    entries = list(diff) if isinstance(diff, sp.MatrixBase) else [diff]
    values = [sp.N(e.subs(subs), 50) for e in entries]
    assert any(abs(val) > 1e-20 for val in values), values


# -- the catalogue --------------------------------------------------------------
@pytest.fixture(scope="module")
def reports():
    from test_catalogue import catalogue_reports

    return catalogue_reports()


def test_every_claim_is_decided_and_errata_are_corrected(reports):
    by_id = {r.claim.id: r for r in reports}
    assert len(reports) == len(CLAIMS) >= 50
    for r in reports:
        assert r.result.status is not Status.UNDECIDED, r.claim.id
        if r.result.status is Status.REFUTED:
            assert r.claim.printed and r.claim.corrected_by, r.claim.id
            assert by_id[r.claim.corrected_by].result.proved
    assert exit_status(reports) == 0


def test_the_errata_found_are_exactly_the_known_ones(reports):
    refuted = {r.claim.id for r in reports if r.result.status is Status.REFUTED}
    assert refuted == {"eq23-printed-upper", "eq23-printed-lower", "A1-printed", "s5-V1V2-printed"}


def test_eq23_counterexample_by_hand():
    # (23) as printed: (cμ + s)/(sμ − c) = (s + cμ)/(c − sμ); the two sides differ by the
    # sign of the denominator, so at φ = π/3, μ = 1 (denominators ≠ 0) they are opposite.
    s, c, m = sp.sqrt(3) / 2, sp.Rational(1, 2), 1
    lhs, rhs = (c * m + s) / (s * m - c), (s + c * m) / (c - s * m)
    assert sp.simplify(lhs + rhs) == 0 and lhs != rhs
    r = check(claim("eq23-printed-upper"))
    assert_refuted(
        r,
        (sp.cos(phi1) * mu1 + sp.sin(phi1)) / (sp.sin(phi1) * mu1 - sp.cos(phi1)),
        (sp.sin(phi1) + sp.cos(phi1) * mu1) / (sp.cos(phi1) - sp.sin(phi1) * mu1),
    )


def test_A1_counterexample_is_checked():
    fN = list(P.F_N_printed)
    assert_refuted(check(claim("A1-printed")), fN[3], fN[2])


def test_json_and_markdown_report(tmp_path, capsys):
    md = tmp_path / "proof.md"
    code = main(["verify", "--json", "--markdown", str(md), "--quiet"])
    recs = json.loads(capsys.readouterr().out)
    assert code == 0
    assert {"id", "ref", "status", "seconds", "statement"} <= set(recs[0])
    refuted = [r for r in recs if r["status"] == "REFUTED"]
    assert refuted and all("counterexample" in r and "corrected_by" in r for r in refuted)
    text = md.read_text()
    assert "Errata" in text and "eq. (23)" in text and "(A1)" in text


def test_markdown_lists_every_claim(reports):
    text = to_markdown(reports)
    assert all(f"`{c.id}`" in text for c in CLAIMS)


# -- mutation tests: a checker that proves everything is a defect ---------------
s, c = P.s, P.c
s1, c1, s2, c2 = P.s1, P.c1, P.s2, P.c2
D = x1 + x2


def _mutants():
    L = P.L_printed
    L_bad = L.copy()
    L_bad[2, 0] = +c1 * x1 + s1 * y  # sign of the moment flipped
    FT_bad = P.F_T_printed.copy()
    FT_bad[0] = F_e / (2 * D) * (D * s1 * s + 2 * (y * s - x1 * c) * c1)  # x2 -> x1
    FN_bad = F_e / D * sp.Matrix([c1, s1, s2, c2])  # s1 <-> c1
    return [
        ("grasp matrix, moment sign", L_bad * P.F_N_printed, sp.zeros(3, 1)),
        ("F_T, x1 for x2", L * FT_bad, P.M_printed),
        ("F_N, s1 <-> c1", L * FN_bad, sp.zeros(3, 1)),
        ("k1 tan form, φ−ξ for φ+ξ", P.k_tan_printed[0].subs(xi1, -xi1), P.k_mu_printed[0]),
        ("k2 μ form, sign of s/2 term", P.k_mu_printed[1] - D * s, P.k_tan_printed[1]),
        ("k3 μ form, x1 for x2", P.k_mu_printed[2].subs(x2, x1), P.k_tan_printed[2]),
        (
            "k4 index swap (contact 1 data)",
            P.k_tan_printed[3],
            P.k_tan_printed[3].subs({phi2: phi1, xi2: xi1}),
        ),
        (
            "V1, sign of y tan",
            (-D / 2 - y * sp.tan(phi1 + xi1)) * s - P.C_printed[0] * c,
            P.k_tan_printed[0],
        ),
        ("C2 with x2 for x1", P.S_printed[1] * s - x2 * sp.tan(phi2 + xi2) * c, P.k_tan_printed[1]),
        (
            "Thales with radius |V|",
            (((sp.Symbol("a") * s) * s - sp.Symbol("a") / 2) ** 2 + (sp.Symbol("a") * s * c) ** 2),
            sp.Symbol("a") ** 2,
        ),
        ("A6 without π", sp.tan(phi1 + xi1), -sp.tan(phi1 + xi1)),
        (
            "A2 mixing contacts",
            P.F_N_printed[0] ** 2 + P.F_N_printed[3] ** 2,
            (F_e / D) ** 2 + P.F_N_printed[1] ** 2 - P.F_N_printed[0] ** 2,
        ),
    ]


@pytest.mark.parametrize("name, lhs, rhs", _mutants(), ids=[m[0] for m in _mutants()])
def test_mutated_identities_are_refuted(name, lhs, rhs):
    assert_refuted(prove_identity(lhs, rhs), lhs, rhs)


def test_construction_claims_mutated():
    c = symbolic_construction()
    # O_M X1 = +S1 (sign lost) and O Y2 = −C1 (index swapped) are wrong
    assert_refuted(prove_identity(c["OMX1"], P.S_printed[0]), c["OMX1"], P.S_printed[0])
    assert_refuted(prove_identity(c["OY2"], -P.C_printed[0]), c["OY2"], -P.C_printed[0])
    # the §5 line through O: B12 is not on the line through O and P1 (sides 1 and 3 meet there)
    B = c["B12"]
    assert_refuted(prove_identity(B.x * y - B.y * x1), B.x * y - B.y * x1)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_divisor_signs_and_their_negations(n):
    from graspcompass.proof.catalogue_core import with_xi
    from graspcompass.proof.catalogue_model import DIV_WITNESS as _DIV_WITNESS
    from graspcompass.proof.catalogue_model import DIVISOR

    _DIVISOR = {n: with_xi(d) for n, d in DIVISOR.items()}

    assert prove_sign(_DIVISOR[n], +1, witness=_DIV_WITNESS[n]).proved
    wrong = prove_sign(_DIVISOR[n], -1, witness=_DIV_WITNESS[n])
    assert wrong.status is Status.REFUTED and admissible(wrong.counterexample)
    subs = {SYMS[k]: parse_exact(v) for k, v in wrong.counterexample.items()}
    assert sp.N(_DIVISOR[n].subs(subs), 50) > 0  # so "< 0" is indeed false there


def test_sign_without_witness_is_not_proved():
    r = prove_sign(mu1 * s1 - c1, +1)
    assert r.status is Status.UNDECIDED


def test_fig8_mutation_is_refuted():
    r, a = sp.Symbol("r", positive=True), sp.Symbol("alpha", positive=True)
    subs = {x1: 2 * r * sp.sin(a) - x2, y: r * sp.cos(a)}
    wrong = r * sp.sin(phi1 + xi1 - a) / sp.cos(phi1 - xi1)
    res = prove_identity(P.S_printed[2].subs(subs), wrong)
    assert res.status is Status.REFUTED


def test_fig8_classification_on_table1():
    # §4.2: case (a) V3 left, V4 right; (b) the reverse; (c) both right.  Independently:
    # O_M inside cone 1 iff φ1 − ξ1 < α = atan((x1 + x2)/(2y)).
    for name, inside1, inside2 in (
        ("table1a", True, True),
        ("table1b", False, False),
        ("table1c", False, True),
    ):
        g = Grasp.preset(name)
        alpha = sp.atan((g.x1 + g.x2) / (2 * g.y))
        assert bool(g.phi1 - g.xi1 < alpha) is inside1
        assert bool(g.phi2 - g.xi2 < alpha) is inside2
        assert bool(g.V[2].x < 0) is inside1 and bool(g.V[3].x > 0) is inside2


# -- certify -------------------------------------------------------------------
@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1c"])
def test_certify_presets(preset):
    certs = certify(internal_force_diagram(Grasp.preset(preset)))
    given = {"O", "x-axis", "y-axis", "P1", "P2", "side1", "side2", "side3", "side4"}
    for cert in certs:  # given data is GIVEN (never PROVED); every constructed step PROVED
        want = Status.GIVEN if cert.step in given else Status.PROVED
        assert cert.result.status is want, (cert.step, cert.result)
    assert any("X1" in f for cert in certs for f in cert.facts)


def test_certify_catches_a_tampered_step():
    c = internal_force_diagram(Grasp.preset("fig6"))
    steps = list(c.steps)
    i = c.names.index("Y1")
    bad = Point(0, sp.Rational(3, 2) + sp.sqrt(3) + sp.Rational(1, 10**6))
    steps[i] = type(steps[i])(**{**steps[i].__dict__, "obj": bad})
    certs = certify(Construction(tuple(steps), c.grasp))
    by_name = {x.step: x for x in certs}
    assert by_name["Y1"].result.status is Status.REFUTED


def test_certify_symbolic_construction():
    certs = certify(symbolic_construction())
    given = {"O", "x-axis", "y-axis", "P1", "P2", "side1", "side2", "side3", "side4"}
    for cert in certs:
        want = Status.GIVEN if cert.step in given else Status.PROVED
        assert cert.result.status is want, (cert.step, cert.result)


# -- numerical cross-check -----------------------------------------------------
def test_linprog_matches_by_hand_table1a():
    # Table I(a) at θ = 0: k1 = −C1 = 2 (V1 = (−3, −2) by hand) is the largest
    assert k_linprog(2, 2, 1, float(sp.pi / 2), float(sp.pi / 2), 1.0, 1.2, 0.0) == pytest.approx(
        2.0, abs=1e-9
    )


def test_crosscheck_small(capsys):
    r = run_crosscheck(4, 12, seed=3, quiet=True)
    assert r.grasps == 4 and r.max_abs_diff < 1e-8
    assert main(["crosscheck", "--grasps", "2", "--thetas", "6", "--quiet"]) == 0
    assert "largest" in capsys.readouterr().out
