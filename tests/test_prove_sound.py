"""Soundness of the core checker: denominators, hypotheses, roots, certificates (issue 9).

Each test states what must hold from first principles (a 0/0 is no proof, tan φ1
is undefined at φ1 = π/2 which condition (1) admits, ...); the re-checker is
fed forged certificates.  New names are imported inside the tests so that each
test failed on its own against the code before issue 9.
"""

from __future__ import annotations

import copy
import random

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass.proof import CONDITION_1, Status, prove_identity, prove_sign
from graspcompass.symbols import mu1, phi1, phi2, theta, x1, x2, xi1, xi2, y

s1, c1 = sp.sin(phi1), sp.cos(phi1)
Z = s1**2 + c1**2 - 1  # zero for every phi1, but sympy does not know it


def _violations(cx, extra=()):
    from graspcompass.proof.model import violations

    return violations(cx, extra)


# -- 1. denominators ---------------------------------------------------------------
def test_zero_over_zero_is_an_error_not_a_proof():
    from graspcompass.proof.prove import DegenerateClaimError

    for claim in (Z / sp.expand((x1 + 1) * Z), x1 / sp.expand((x1 + 2) * Z)):
        try:
            r = prove_identity(claim, 5)
        except DegenerateClaimError as exc:
            assert "0/0" in str(exc) or "undefined" in str(exc)
            assert isinstance(exc, ValueError)
        else:
            raise AssertionError(f"no error for {claim}: {r.status}")


def test_removable_denominator_is_listed_as_a_condition():
    r = prove_identity((x1**2 - 1) / (x1 - 1), x1 + 1)  # equal except at x1 = 1
    assert r.proved and r.conditions == ("x1 - 1 != 0",), r
    assert r.implied == ()


def test_denominators_implied_by_condition_1_and_the_others_listed():
    # tan(phi1) is undefined at phi1 = pi/2, a point that (1) admits (any xi1);
    # cos(xi1) > 0 and cos(phi1 + xi1) < 0 follow from (1)
    r = prove_identity(sp.tan(phi1 + xi1), (sp.tan(phi1) + mu1) / (1 - sp.tan(phi1) * mu1))
    assert r.proved
    assert r.conditions == ("cos(phi1) != 0",)
    assert "cos(xi1) != 0 (from (1))" in r.implied
    assert len(r.implied) == 2 and all(t.endswith("(from (1))") for t in r.implied)
    assert "condition (1)" in r.hypotheses
    assert not _violations({phi1: sp.pi / 2, xi1: sp.pi / 5})


def test_mu_divisor_is_implied_by_condition_1():
    d = mu1 * s1 - c1  # = -cos(phi1 + xi1)/cos(xi1) > 0 under (1) and (22)
    r = prove_identity(sp.expand(d**2) / d, d)
    assert r.proved and r.conditions == ()
    assert r.implied == (f"{d} != 0 (from (1))",) or r.implied == (f"{-d} != 0 (from (1))",)


def test_wrong_identities_are_refuted_with_points_of_the_model():
    lhs = (sp.tan(phi1) + mu1) / (1 - sp.tan(phi1) * mu1)
    for wrong, right in (
        (sp.tan(phi1 - xi1), lhs),  # sign slip
        (sp.sin(phi1 + xi2), sp.sin(phi1 + xi1)),  # index slip
        (sp.cos(phi2 - xi2), sp.cos(phi2) * sp.cos(xi2) - s1 * sp.sin(xi2)),
    ):
        r = prove_identity(wrong, right)
        assert r.status is Status.REFUTED, (wrong, r)
        assert _violations(r.counterexample) == []


# -- 2. hypotheses of sign claims ---------------------------------------------------
def test_sign_hypotheses_are_recorded():
    r = prove_sign(mu1 * s1 - c1, +1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)])
    assert r.proved and r.hypotheses == ("condition (1)",)


def test_caller_intervals_are_hypotheses_and_restrict_counterexamples():
    iv = {**CONDITION_1, phi1: (0, sp.pi / 2)}
    r = prove_sign(c1, +1, witness=[c1], intervals=iv)  # cos > 0 on (0, pi/2)
    assert r.proved, r
    assert "phi1 in (0, pi/2)" in r.hypotheses and "condition (1)" in r.hypotheses
    wrong = prove_sign(c1, -1, witness=[c1], intervals=iv)
    assert wrong.status is Status.REFUTED
    assert _violations(wrong.counterexample, [phi1 < sp.pi / 2]) == []


def test_change_of_variables_is_recorded_and_counterexamples_are_points_of_the_model():
    r_, a = sp.Symbol("r", positive=True), sp.Symbol("alpha", positive=True)
    subs = {x1: 2 * r_ * sp.sin(a) - x2, y: r_ * sp.cos(a)}
    dom = {a: (0, sp.pi / 2)}
    iv = {**CONDITION_1, a: (0, sp.pi / 2)}
    ok = prove_sign(x1 + x2, +1, witness=[2, r_, sp.sin(a)], intervals=iv, subs=subs, domains=dom)
    assert ok.proved, ok
    assert any(h.startswith("change of variables x1 = ") for h in ok.hypotheses)
    assert "alpha in (0, pi/2)" in ok.hypotheses
    bad = prove_sign(y - x2, +1, intervals=iv, subs=subs, domains=dom)
    assert bad.status is Status.REFUTED
    cx = bad.counterexample
    assert {"x1", "y", "r", "alpha"} <= set(cx)
    assert _violations(cx, [a < sp.pi / 2]) == []


# -- 3. square roots ----------------------------------------------------------------
def test_square_roots_can_be_stated_and_proved():
    S = x1 / 2 + y * sp.tan(phi1 + xi1)  # a length of the kind of S_n, C_n
    C = x2 * sp.tan(phi1 + xi1)
    w = sp.sqrt(S**2 + C**2)  # |V|
    r = prove_identity((w - S) * (w + S), C**2)
    assert r.proved, r
    wrong = prove_identity((w - S) * (w + S), C**2 + 1)
    assert wrong.status is Status.REFUTED and _violations(wrong.counterexample) == []
    v = sp.sqrt(1 + sp.sqrt(x1))  # nested
    assert prove_identity((v - 1) * (v + 1), sp.sqrt(x1)).proved
    u = sp.sqrt(x1**2 + x2**2)
    q = prove_identity(1 / (u - x1), (u + x1) / x2**2)  # u - x1 > 0, not seen by the checker
    assert q.proved and q.conditions == (f"{u - x1} != 0",), q
    assert any(t.startswith("x2 != 0") for t in q.implied)


# -- 4. multiple angles -------------------------------------------------------------
def test_sin_24_phi_is_linear_work():
    assert prove_identity(sp.sin(24 * phi1), 2 * sp.sin(12 * phi1) * sp.cos(12 * phi1)).proved
    assert prove_identity(sp.cos(30 * theta) ** 2 + sp.sin(30 * theta) ** 2, 1).proved
    r = prove_identity(sp.sin(24 * phi1), 24 * s1 * c1**23)
    assert r.status is Status.REFUTED


# -- 6. certificates ----------------------------------------------------------------
def _forge_false_identity():
    """A 'proof' of sin² − cos² = 1 from the wrong relation s² − c² − 1."""
    rel = [["1/1", [2, 0]], ["-1/1", [0, 2]], ["-1/1", [0, 0]]]
    return {
        "kind": "identity",
        "denominators": [],
        "entries": [
            {
                "vars": ["sin(phi1)", "cos(phi1)"],
                "numerator": rel,
                "cofactors": [[["1/1", [0, 0]]]],
                "relations": [
                    {"kind": "pythagoras", "angle": "phi1", "sin": 0, "cos": 1, "poly": rel}
                ],
            }
        ],
    }


def test_certificates_recheck_and_tampering_is_rejected():
    from graspcompass.proof.recheck import RecheckError, problems, recheck

    r = prove_identity(sp.tan(phi1 + xi1) ** 2 + 1, 1 / sp.cos(phi1 + xi1) ** 2)
    cert = r.certificate
    assert r.proved and recheck(cert, strict=True)
    entry = cert["entries"][0]
    assert entry["numerator"] and entry["cofactors"] and entry["relations"]
    t1 = copy.deepcopy(cert)  # change one coefficient
    t1["entries"][0]["numerator"][0][0] = "7/3"
    t2 = copy.deepcopy(cert)  # drop a cofactor
    t2["entries"][0]["cofactors"].pop()
    for bad in (t1, t2, _forge_false_identity()):
        assert not recheck(bad)
        try:
            recheck(bad, strict=True)
        except RecheckError:
            pass
        else:
            raise AssertionError("strict recheck must raise")
    assert any("declared form" in p for p in problems(_forge_false_identity()))


def test_sign_certificates_recheck_and_a_crossing_interval_is_rejected():
    from graspcompass.proof.recheck import recheck

    r = prove_sign(mu1 * s1 - c1, +1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)])
    cert = r.certificate
    assert cert["kind"] == "sign" and recheck(cert, strict=True)
    node = cert["factors"][1]["reason"]
    assert node["type"] == "trig" and node["interval"] == ["1/2", "3/2"]
    crossing = copy.deepcopy(cert)  # cos on (0, 3π/2) changes sign at π/2
    n2 = crossing["factors"][1]["reason"]
    n2["pieces"][0]["interval"] = ["0/1", "3/2"]
    n2["interval"] = ["0/1", "3/2"]
    for iv in crossing["intervals"]:
        if iv["form"] == {"phi1": 1, "xi1": 1}:
            iv["interval"] = ["0/1", "3/2"]
    assert not recheck(crossing)
    flipped = copy.deepcopy(cert)
    flipped["sign"] = -1
    assert not recheck(flipped)
    undeclared = copy.deepcopy(cert)  # an interval that no hypothesis states
    undeclared["intervals"] = [
        iv for iv in undeclared["intervals"] if iv["form"] != {"phi1": 1, "xi1": 1}
    ]
    assert not recheck(undeclared)


_ANGLES = [phi1, phi2, xi1, xi2, theta]


@st.composite
def trig_products(draw):
    factors = []
    for _ in range(draw(st.integers(1, 3))):
        terms = []
        for _ in range(draw(st.integers(1, 2))):
            angs = draw(st.lists(st.sampled_from(_ANGLES), min_size=1, max_size=3))
            signs = draw(st.lists(st.sampled_from([1, -1]), min_size=len(angs), max_size=len(angs)))
            u = sum(s * a for s, a in zip(signs, angs))
            fn = draw(st.sampled_from([sp.sin, sp.cos]))
            terms.append(draw(st.integers(-3, 3)) * fn(u))
        factors.append(sp.Add(*terms))
    return sp.Mul(*factors)


@settings(max_examples=25, deadline=None)
@given(trig_products())
def test_random_true_identities_carry_certificates_that_recheck(expr):
    from graspcompass.proof.recheck import recheck

    other = sp.expand(sp.expand_trig(expr))  # sympy's own addition formulas
    r = prove_identity(expr, other)
    assert r.proved
    assert recheck(r.certificate)
    entry = r.certificate["entries"][0]
    if entry["numerator"]:
        bad = copy.deepcopy(r.certificate)
        bad["entries"][0]["numerator"][0][0] = "1/7" if entry["numerator"][0][0] != "1/7" else "2/7"
        assert not recheck(bad)


@settings(max_examples=15, deadline=None)
@given(trig_products(), st.sampled_from(_ANGLES))
def test_random_wrong_identities_are_never_proved(expr, a):
    wrong = sp.expand(sp.expand_trig(expr)) + sp.sin(a) ** 2 - sp.cos(a) ** 2 / 2
    r = prove_identity(expr, wrong)
    assert not r.proved
    if r.status is Status.REFUTED:
        assert _violations(r.counterexample) == []


# -- 7. caching by content ----------------------------------------------------------
def test_results_depend_on_content_only():
    t_pos, t_any = sp.Symbol("t", positive=True), sp.Symbol("t")
    assert prove_sign(t_pos, +1, witness=[t_pos]).proved
    assert not prove_sign(t_any, +1, witness=[t_any]).proved
    assert prove_identity(x1 * (x1 + 1), x1**2 + x1).proved
    assert not prove_identity(x1 * (x1 + 1), x1**2 - x1).proved


def test_counterexamples_are_random_free_of_the_model_blind_spot():
    rng = random.Random(5)
    for _ in range(5):
        k = rng.randint(2, 5)
        r = prove_identity(mu1 * s1, sp.sin(k * phi1 + xi1))  # mixes the mu and xi forms
        assert r.status is Status.REFUTED
        assert _violations(r.counterexample) == []
