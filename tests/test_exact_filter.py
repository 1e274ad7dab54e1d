"""The kernel's floating-point sign filter never claims a wrong sign.

``exact._float_sign`` decides the sign of a polynomial in numeric generators
from doubles with an error bound; when it answers, the answer must be the sign
of the exact value, which the tests get independently from mpmath at 300
digits (and from exact zeros built to cancel).
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass.geometry import exact
from graspcompass.geometry.trig import OpaqueCos, OpaqueSin

_GENS = (
    sp.sqrt(2),
    sp.sqrt(3),
    sp.sqrt(5),
    OpaqueSin(sp.pi / 10),
    OpaqueCos(sp.pi / 10),
    OpaqueSin(sp.Rational(6, 5)),
    OpaqueCos(sp.Rational(6, 5)),
)
_R = exact._ring(tuple(sorted(_GENS, key=exact._gen_key)))


def _true_value(poly) -> mpmath.mpf:
    with mpmath.workdps(300):
        values = [mpmath.mpf(sp.N(g, 320)) for g in _R.symbols]
        total = mpmath.mpf(0)
        for monom, coeff in poly.terms():
            t = mpmath.mpf(int(coeff.numerator)) / int(coeff.denominator)
            for v, e in zip(values, monom):
                t *= v ** int(e)
            total += t
        return total


_coeff = st.fractions(min_value=-(10**6), max_value=10**6, max_denominator=10**6)
_monom = st.tuples(*[st.integers(0, 3) for _ in _GENS])
_poly = st.lists(st.tuples(_monom, _coeff), min_size=1, max_size=8).map(
    lambda ts: _R.from_dict({m: sp.QQ(c.numerator, c.denominator) for m, c in ts})
)


def _check(poly) -> None:
    got = exact._float_sign(_R, poly)
    if got is None:
        return
    v = _true_value(poly)
    assert v != 0 and got == (1 if v > 0 else -1), (poly, got, v)


@settings(max_examples=120, deadline=None)
@given(_poly)
def test_filter_sign_is_the_true_sign(poly):
    _check(poly)


@settings(max_examples=60, deadline=None)
@given(_poly, _poly, st.integers(-60, -20))
def test_filter_near_cancellation(p, q, k):
    """p*q - p*q' with q' = q + 2^k: tiny but non-zero, and exact zeros p*q - q*p."""
    a = p * q
    two_k = Fraction(2) ** k
    shift = _R.from_dict({(0,) * len(_GENS): sp.QQ(two_k.numerator, two_k.denominator)})
    _check(a - p * (q + shift))
    zero = a - q * p
    assert not zero or exact._float_sign(_R, zero) is None or _true_value(zero) != 0


def test_filter_refuses_exact_zero_in_disguise():
    """(sqrt2 + sqrt3)^2 - 5 - 2 sqrt6 is 0 once sqrt6 = sqrt2 sqrt3; unreduced it is
    a polynomial whose double evaluation is rounding noise: no sign may come out."""
    r2, r3 = _R(sp.sqrt(2)), _R(sp.sqrt(3))
    poly = (r2 + r3) ** 2 - 5 - 2 * r2 * r3
    assert exact._float_sign(_R, poly) is None
    s, c = _R(OpaqueSin(sp.pi / 10)), _R(OpaqueCos(sp.pi / 10))
    assert exact._float_sign(_R, s**2 + c**2 - 1) is None
    # 4 cos(pi/10)^2 - (10 + 2 sqrt5)/4 * ... : cos(pi/10)^2 = (5 + sqrt5)/8
    assert exact._float_sign(_R, 8 * c**2 - 5 - _R(sp.sqrt(5))) is None


@settings(max_examples=80, deadline=None)
@given(_poly, st.sampled_from([64, 200, 333]))
def test_integer_balls_hold_the_true_value(poly, prec):
    """exact._intervals (integer ball arithmetic) encloses the value, tightly."""
    from mpmath import iv

    saved = iv.prec
    iv.prec = prec
    try:
        (box,) = exact._intervals(_R, poly)
    finally:
        iv.prec = saved
    v = _true_value(poly)
    with mpmath.workdps(300):
        lo, hi = (mpmath.mpf(e) for e in box._mpi_)
        assert lo <= v <= hi, (poly, lo, v, hi)
        magnitude = sum(abs(int(c.numerator)) / int(c.denominator) for c in poly.coeffs())
        assert hi - lo <= mpmath.mpf(2) ** (-prec + 40) * (1 + magnitude) * 10**6


@settings(max_examples=100, deadline=None)
@given(
    st.lists(
        st.tuples(st.integers(-9, 9), st.sampled_from((*_GENS[:3], sp.Integer(1)))),
        min_size=1,
        max_size=4,
    ),
    st.lists(
        st.tuples(st.integers(1, 9), st.sampled_from((*_GENS[:3], sp.Integer(1)))),
        min_size=1,
        max_size=3,
    ),
    st.sampled_from([15, 30, 50]),
)
def test_approx_has_the_digits_it_promises(num, den, dps):
    """approx(expr, dps) (integer balls, then a quotient) against sympy.N at 80 digits."""
    e = sum((k * g for k, g in num), sp.Integer(0)) / sum((k * g for k, g in den), sp.Integer(0))
    want = sp.N(e, 80)
    if want == 0:
        return
    got = exact.approx(e, dps)
    with mpmath.workdps(90):
        assert abs(mpmath.mpf(got) - mpmath.mpf(want)) <= abs(mpmath.mpf(want)) * 10 ** (1 - dps)


_ROOTS_R = exact._ring((sp.sqrt(2), sp.sqrt(3), sp.sqrt(5), sp.sqrt(7)))


@settings(max_examples=80, deadline=None)
@given(st.dictionaries(st.tuples(*[st.integers(0, 1)] * 4), _coeff, min_size=1, max_size=16))
def test_direct_expression_is_sympys(terms):
    """exact._as_expr builds Add/Mul without flattening: it must be sympy's own tree."""
    from sympy.core.cache import clear_cache

    p = _ROOTS_R.from_dict({m: sp.QQ(c.numerator, c.denominator) for m, c in terms.items()})
    ours = exact._as_expr(_ROOTS_R, p)
    clear_cache()
    theirs = _sympy_sum(_ROOTS_R.symbols, terms)
    assert sp.srepr(ours) == sp.srepr(theirs)
    assert ours == theirs and hash(ours) == hash(theirs)
    assert exact.canon(ours) == ours


def _sympy_sum(gens, terms) -> sp.Expr:
    """The polynomial built by sympy's own (evaluating) Add and Mul."""
    return sp.Add(
        *[
            sp.Rational(c.numerator, c.denominator) * sp.Mul(*[g**e for g, e in zip(gens, m)])
            for m, c in terms.items()
            if c
        ]
    )


_MIXED_GENS = tuple(
    sorted(
        (
            sp.sqrt(2),
            sp.sqrt(3),
            OpaqueSin(sp.pi / 10),
            OpaqueCos(sp.pi / 10),
            sp.Symbol("x1", positive=True),
            sp.Symbol("mu1", positive=True),
        ),
        key=exact._gen_key,
    )
)
_MIXED_R = exact._ring(_MIXED_GENS)


@settings(max_examples=80, deadline=None)
@given(
    st.dictionaries(
        st.tuples(*[st.integers(0, 2)] * len(_MIXED_GENS)), _coeff, min_size=1, max_size=12
    )
)
def test_direct_expression_with_trig_and_symbols_is_sympys(terms):
    """The builder makes sympy's own tree for every kind of generator (the factors in
    sympy's order, reduced roots multiplied into one), up to 48 terms."""
    from sympy.core.cache import clear_cache

    terms = {
        m: c for m, c in terms.items() if all(e <= 1 for g, e in zip(_MIXED_GENS, m) if g.is_Pow)
    }  # roots reduced
    if not any(terms.values()):
        return
    p = _MIXED_R.from_dict({m: sp.QQ(c.numerator, c.denominator) for m, c in terms.items()})
    ours = exact._as_expr(_MIXED_R, p)
    clear_cache()
    theirs = _sympy_sum(_MIXED_GENS, terms)
    assert sp.srepr(ours) == sp.srepr(theirs)
    assert ours == theirs and hash(ours) == hash(theirs)


def test_a_denominator_zero_on_the_model_is_division_by_zero():
    """Values as written: Z = sin² + cos² − 1 is 0 at every point, so x·Z/(x·Z) is 0/0 —
    never 1 by a cancelled common factor (the reduction comes before the gcd)."""
    import pytest

    s, c = OpaqueSin(sp.pi / 10), OpaqueCos(sp.pi / 10)
    x = sp.Symbol("x1", positive=True)
    for z in (s**2 + c**2 - 1, sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1):
        zf = exact.Frac.of(sp.expand(x * z + x)) - exact.Frac.of(x)  # x·Z, built unreduced
        with pytest.raises(ZeroDivisionError):
            zf / zf
        with pytest.raises(ZeroDivisionError):
            (exact.Frac.of(x) / zf).expr()
    # a factor that is non-zero on the model still cancels
    f = exact.Frac.of(x + s)
    assert ((f * exact.Frac.of(x)) / f).expr() == x


def test_nonzero_by_the_signs_of_terms_is_never_claimed_for_a_value_that_can_vanish():
    """Frac.is_zero answers False ("never 0") from the signs of the terms only when
    every term has one sign and one is strictly so; sums that vanish somewhere on the
    assumptions (false statements of non-vanishing) stay undecided."""
    import sympy as sp

    from graspcompass.geometry._exact_frac import Frac

    x = sp.Symbol("x", positive=True)
    y = sp.Symbol("y", nonnegative=True)
    r = sp.Symbol("r", real=True)
    a = sp.Symbol("a", positive=True)
    u = sp.Symbol("u")  # no assumptions: not even real
    vanish = [  # each is 0 at some point allowed by the assumptions
        x - 1,
        x * y,
        y,
        r,
        r**2,
        r + 1,
        x * r**2,
        y**2 - y,
        x * y - x * y**2,
        sp.sin(a) * x + x,
        sp.sin(a) + sp.cos(a),
        x * sp.cos(a),
        u**2 + 1,
        x**2 * y + y - x * y,
        (x - 1) * (y + 1) + 0,
    ]
    for e in vanish:
        assert Frac.of(e).is_zero() is not False, e
    never = [  # positive (or negative) everywhere on the assumptions
        x,
        x + y,
        x * y + 1,
        -x - y - 1,
        r**2 + x,
        r**2 * y + x * y + x,
        (x + 1) ** 2,
        -(x**3) * (r**2 + 1) - y,
        sp.sin(a) ** 2 + 1,
    ]
    for e in never:
        assert Frac.of(e).is_zero() is False, e
