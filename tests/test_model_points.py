"""Points of the model: the admissibility check, exact sampling, valid counterexamples (issue 9).

The expected verdicts are worked out here from the definitions: condition (1)
reads π/2 < φ + ξ < 3π/2 and −π/2 < φ − ξ < π/2, eq. (22) reads μ = tan ξ, and
the domains are those of §2.2.
"""

from __future__ import annotations

import random

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass.proof import Status, find_counterexample, prove_identity, prove_sign
from graspcompass.symbols import F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y

pi = sp.pi


def _model():
    from graspcompass.proof import model

    return model


def test_violations_accepts_points_of_the_model():
    v = _model().violations
    assert v({phi1: pi / 2, xi1: pi / 4, mu1: 1, x1: 1, x2: 2, y: 0}) == []
    # φ1 = 5π/6 with ξ1 = π/3: φ − ξ = π/2 exactly
    assert v({phi1: 5 * pi / 6, xi1: pi / 3}) != []  # φ − ξ = π/2 exactly: (1) is strict
    assert v({phi1: 3 * pi / 4, xi1: pi / 3}) == []  # φ − ξ = 5π/12, φ + ξ = 13π/12
    assert v({"phi1": "3*pi/4", "mu1": "sqrt(3)"}) == []  # atan(√3) = π/3, from text
    assert v({phi2: pi / 3, mu2: 2}) == []  # atan 2 > π/6 = π/2 − φ2


def test_violations_finds_each_kind_of_defect():
    v = _model().violations
    assert any("x1" in m for m in v({x1: 0}))
    assert any("y" in m for m in v({y: -1}))
    assert any("xi1" in m for m in v({xi1: pi / 2}))
    assert any("phi2" in m for m in v({phi2: 4}))  # 4 > π
    assert any("eq. (22)" in m for m in v({xi1: pi / 4, mu1: sp.Rational(11, 10)}))
    assert any("condition (1)" in m for m in v({phi1: pi / 6, xi1: pi / 12}))  # φ + ξ = π/4
    assert any("condition (1)" in m for m in v({phi1: pi / 6, mu1: sp.Rational(1, 2)}))
    assert any("condition (1)" in m for m in v({phi1: pi}))  # no ξ in (0, π/2) admits φ = π
    assert any("hypothesis" in m for m in v({theta: 1}, [theta < 1]))
    assert v({F_e: -1}) != []


@settings(max_examples=40, deadline=None)
@given(
    st.integers(0, 10**6),
    st.sets(st.sampled_from([x1, x2, y, phi1, phi2, xi1, xi2, mu1, mu2, theta, F_e]), min_size=1),
)
def test_samples_are_points_of_the_model(seed, syms):
    m = _model()
    p = m.sample(sorted(syms, key=str), random.Random(seed))
    assert set(p) == syms
    assert m.violations(p) == []
    assert all(not val.has(sp.Float) for val in p.values())  # exact


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10**6))
def test_samples_respect_change_of_variable_domains(seed):
    m = _model()
    a = sp.Symbol("alpha", positive=True)
    p = m.sample([a, phi1], random.Random(seed), {a: (0, pi / 2)})
    assert m.violations(p, [a < pi / 2]) == []


_WRONG = [
    lambda k: (mu1 * sp.sin(phi1), sp.sin(k * phi1 + xi1)),
    lambda k: (sp.tan(xi1) * sp.cos(phi1 + theta), mu1 * sp.cos(phi1 - k * theta)),
    lambda k: (mu1 * mu2 + sp.cos(xi2), sp.sin(phi2 + k * xi1) + mu2),
    lambda k: (sp.sin(phi1 + theta) * x1, sp.sin(phi1) * x1 + k * y),
]


@settings(max_examples=20, deadline=None)
@given(st.sampled_from(range(len(_WRONG))), st.integers(2, 6))
def test_counterexamples_of_wrong_claims_are_points_of_the_model(i, k):
    lhs, rhs = _WRONG[i](k)
    r = prove_identity(lhs, rhs)
    assert r.status is Status.REFUTED
    assert _model().violations(r.counterexample) == []


def test_a_wrong_sign_claim_mixing_mu_and_xi_has_a_valid_counterexample():
    r = prove_sign(mu1 - sp.sin(xi1) - sp.Rational(1, 2), +1)  # tan ξ − sin ξ − 1/2 < 0 near 0
    assert r.status is Status.REFUTED
    assert _model().violations(r.counterexample) == []


def test_caller_assumptions_add_to_the_model_not_replace_it():
    # the old search took `assumptions` instead of the model: phi1 < 2 let through
    # points that break (1)
    hits = find_counterexample(lambda v: True, [phi1, xi1], assumptions=[phi1 < 2])
    assert hits is not None and hits[phi1] < 2
    assert _model().violations(hits) == []
