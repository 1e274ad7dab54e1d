"""The prover's polynomial algebra through python-flint agrees with sympy's.

``divide`` (FLINT's division, one relation at a time) must give sympy's normal form
modulo the model's relations, with quotients that rebuild the polynomial;
``factor_list`` must give irreducible factors whose product is the polynomial.
"""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass.proof._flint import divide, factor_list

R, w, s1, s2, c1, c2, a = sp.ring("w, s1, s2, c1, c2, a", sp.QQ, sp.lex)
# a root w = sqrt(2 + c1 + a**2), then sin² + cos² − 1 for two angles: the order of _ring
RELATIONS = [w**2 - (2 + c1 + a**2), s1**2 + c1**2 - 1, s2**2 + c2**2 - 1]

monomials = st.tuples(*[st.integers(0, 3)] * 6)
coeffs = st.fractions(min_value=-5, max_value=5, max_denominator=4)
polys = st.dictionaries(monomials, coeffs, max_size=8).map(
    lambda d: R.from_dict({m: R.domain(c.numerator, c.denominator) for m, c in d.items() if c})
)


@settings(max_examples=60, deadline=None)
@given(polys)
def test_divide_is_sympys_normal_form(p) -> None:
    quotients, rem = divide(p, RELATIONS)
    assert rem == p.div(RELATIONS)[1]  # the normal form is unique (a Gröbner basis)
    assert sum((q * r for q, r in zip(quotients, RELATIONS)), R.zero) + rem == p
    for m in rem.monoms():  # no term divisible by a leading monomial w², s1², s2²
        assert m[0] < 2 and m[1] < 2 and m[2] < 2
    for q in (*quotients, rem):  # plain ints: certificates are JSON (recheck reads them)
        assert all(type(e) is int for m in q.monoms() for e in m)


@settings(max_examples=40, deadline=None)
@given(polys, polys)
def test_factor_list_rebuilds_the_product(p, q) -> None:
    f = p * q
    if not f:
        return
    c, fs = factor_list(f)
    prod = R.one * c
    for g, k in fs:
        assert not g.is_ground
        prod *= g**k
    assert prod == f
    # as many factors as sympy finds (both factor over Q)
    assert sorted(k for _, k in fs) == sorted(k for _, k in f.factor_list()[1])
