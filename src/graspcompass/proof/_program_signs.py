"""Whether one condition's expression vanishes or has a sign: the tests of ``decide``.

The exact zero test (modulo sin² + cos² = 1 and μ = tan ξ), the factoring by
python-flint, signs on intervals and the sums whose every term has a sign.  Private
to :mod:`graspcompass.proof.program_conditions`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy as sp

from ..geometry.exact import decide_zero
from .signs import sign_of

_MAX_FACTOR_NODES = 400  # factor only small conditions (a sign from the factors)


def _zero(e: sp.Expr) -> bool | None:
    """``e`` vanishes at every point where it is defined (modulo sin² + cos² = 1 and
    μ = tan ξ where ξ occurs); True also when ``e`` is defined nowhere (0/0 everywhere)."""
    from .reduce import DegenerateClaimError, reduce_expr

    if e.is_number and not e.free_symbols:
        z = decide_zero(e)
        return z
    try:
        return reduce_expr(e).is_zero or None
    except DegenerateClaimError:
        return True
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, RecursionError):
        return None


def _factor(e: sp.Expr) -> sp.Expr:
    """``e`` as a product of irreducible factors over Q, numerator and denominator, by
    python-flint (sympy's ``factor`` took minutes on the conditions of a recipe drawing a
    perpendicular as ``line_through``): sines, cosines and other atoms are generators;
    anything else (a float, a radical of a symbol) falls back to ``sp.factor``."""
    import flint

    fast = _factor_in_ring(e)
    if fast is not None:
        return fast
    num, den = sp.fraction(sp.together(e))
    roots = [a for a in num.atoms(sp.Pow) | den.atoms(sp.Pow) if not a.exp.is_Integer]
    if roots or num.atoms(sp.Float) | den.atoms(sp.Float):
        return sp.factor(e)
    atoms = sorted(num.atoms(sp.sin, sp.cos) | den.atoms(sp.sin, sp.cos), key=sp.default_sort_key)
    dummies = [sp.Dummy(f"g{i}") for i in range(len(atoms))]
    sub = dict(zip(atoms, dummies))
    num, den = num.xreplace(sub), den.xreplace(sub)
    gens = sorted(num.free_symbols | den.free_symbols, key=str)
    if not gens:
        return e
    ctx = flint.fmpq_mpoly_ctx.get(tuple(str(g) for g in gens), "lex")
    back = {d: a for a, d in sub.items()}

    def one(x: sp.Expr) -> sp.Expr:
        poly = sp.Poly(x, *gens, domain="QQ")
        q = ctx.from_dict({m: flint.fmpq(int(c.p), int(c.q)) for m, c in poly.terms()})
        c, factors = q.factor()
        out = sp.Rational(int(c.p), int(c.q))
        for f, k in factors:
            term = sp.Add(
                *(
                    sp.Rational(int(v.p), int(v.q)) * sp.Mul(*(g**i for g, i in zip(gens, m)))
                    for m, v in f.to_dict().items()
                )
            )
            out *= term.xreplace(back) ** int(k)
        return out

    return one(num) / one(den)


def _factor_in_ring(e: sp.Expr) -> sp.Expr | None:
    """:func:`_factor` through the model's ring (its structural conversion is much faster
    than expanding a sympy expression); None outside the ring."""
    import flint

    from .certify_algebra import ring

    R = ring()
    try:
        num, dens = R.frac(e)
    except (ValueError, TypeError, KeyError, ArithmeticError, NotImplementedError):
        return None
    names = tuple(f"g{i}" for i in range(len(R.gens)))
    ctx = flint.fmpq_mpoly_ctx.get(names, "lex")

    def factored(p: Any) -> sp.Expr:
        if not p:
            return sp.Integer(0)
        q = ctx.from_dict(
            {m: flint.fmpq(int(c.numerator), int(c.denominator)) for m, c in p.terms()}
        )
        c, factors = q.factor()
        out = sp.Rational(int(c.p), int(c.q))
        for f, k in factors:
            back = R.R.from_dict(
                {m: R.R.domain(int(v.p), int(v.q)) for m, v in f.to_dict().items()}
            )
            out *= R.expr(back) ** int(k)
        return out

    den = sp.Integer(1)
    for f, k in dens.items():
        den *= factored(f) ** k
    return factored(num) / den


def _sign(e: sp.Expr, intervals: Mapping) -> tuple[int, int] | None:
    got = None
    try:
        got = sign_of(e, intervals)
        if got is None and sp.count_ops(e) <= _MAX_FACTOR_NODES:
            got = sign_of(_factor(e), intervals)
    except (
        ValueError,
        TypeError,
        ArithmeticError,
        NotImplementedError,
        RecursionError,
        sp.PolynomialError,
    ):
        return None
    return got


def _even_power(t: sp.Expr) -> bool:
    """``t`` is a product of even powers of real expressions (so ``t ≥ 0``)."""
    factors = sp.Mul.make_args(t)
    return bool(factors) and all(
        isinstance(f, sp.Pow) and f.exp.is_Integer and f.exp % 2 == 0 and f.base.is_real is True
        for f in factors
    )


def _bounded_trig(t: sp.Expr) -> bool:
    """``t`` is a product of powers of sines and cosines (so ``|t| ≤ 1``)."""
    return all(
        isinstance(f.base if isinstance(f, sp.Pow) else f, (sp.sin, sp.cos))
        and (not isinstance(f, sp.Pow) or (f.exp.is_Integer and f.exp > 0))
        and f.free_symbols
        for f in sp.Mul.make_args(t)
    )


def _positive_sum(f: sp.Expr, intervals: Mapping) -> bool:
    """``f > 0`` at every point, term by term: a number adds itself to a floor, a
    positive multiple of even powers of real expressions is ≥ 0, c·(product of sines and
    cosines) is ≥ −|c|, any other term needs a sign ≥ 0 on the intervals; then the floor
    is > 0, or ≥ 0 with a term > 0 ((x1 − x2)² + 1 and 2 − cos²φ, which interval signs
    alone do not see)."""
    floor = sp.Integer(0)
    strict = False
    for t in sp.Add.make_args(sp.sympify(f)):
        c, rest = t.as_coeff_Mul()
        if rest == 1:
            floor += c
        elif c > 0 and _even_power(rest):
            continue
        elif _bounded_trig(rest):
            floor -= abs(c)
        else:
            sg = _sign(t, intervals)
            if sg is None or sg[0] < 0:
                return False
            strict = strict or sg[0] > 0
    return bool(floor > 0) or (bool(floor >= 0) and strict)


def _ring_nonzero(e: sp.Expr) -> bool:
    """The numerator of ``e`` reduces to a non-zero constant or a polynomial of positive
    terms in x1, x2, μ (y ≥ 0) in the model's ring (its denominators are the kernel's,
    assumed non-zero where they are recorded)."""
    from .certify_algebra import _positive, ring

    R = ring()
    try:
        q = R.reduce(R.frac(e)[0])
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, RecursionError):
        return False
    return bool(q) and (q.is_ground or _positive(q, R))
