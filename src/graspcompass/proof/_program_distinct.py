"""Proofs that two points of a construction differ (the unit-ideal test, Rabinowitsch).

The general route (sympy's ``together`` and factoring) and the fast one in the
model's ring (python-flint), both ending in Buchberger's algorithm in C.  Private to
:func:`graspcompass.proof.program_conditions.distinct`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from functools import lru_cache
from typing import Any

import sympy as sp

from .. import symbols as S
from ..geometry import Point
from ._program_signs import _factor


def _distinct_general(a: Point, b: Point, assumed: Iterable[sp.Expr]) -> bool:
    """:func:`distinct` for any rational function of symbols, sines and cosines
    (sympy's ``together`` and factoring, then the same unit-ideal test)."""
    from .certify_algebra import _expand_trig

    exprs = [sp.together(_expand_trig(sp.sympify(e))) for e in (a.x - b.x, a.y - b.y)]
    nums = [sp.fraction(e)[0] for e in exprs]
    if any(n.is_number and n != 0 for n in nums):
        return True
    # k ≠ 0 exactly when each of its distinct irreducible factors is (python-flint's
    # factors, each once): the same denominators recur in many assumed expressions, and
    # their plain product made 1 − t·k run to hundreds of terms (seconds of Buchberger)
    bases: dict[sp.Expr, None] = {}
    for e in assumed:
        num = sp.fraction(sp.together(_expand_trig(sp.sympify(e))))[0]
        for f in sp.Mul.make_args(_factor(num)):
            base = f.base if f.is_Pow and f.exp.is_Integer and f.exp > 0 else f
            if not base.is_number:
                bases[base] = None
    k = sp.Mul(*bases)
    free = set().union(*(n.free_symbols for n in nums)) | k.free_symbols
    for s in (S.x1, S.x2, S.mu1, S.mu2):
        if s in free:
            k *= s
    if S.x1 in free and S.x2 in free:
        k *= S.x1 + S.x2
    atoms = set().union(*(n.atoms(sp.sin, sp.cos) for n in nums)) | k.atoms(sp.sin, sp.cos)
    if any(not at.args[0].is_Symbol for at in atoms):
        return False
    angles = {at.args[0] for at in atoms}
    sub: dict[sp.Basic, sp.Symbol] = {}
    rels = []
    for ang in angles:
        s_, c_ = sp.Symbol(f"_s_{ang}"), sp.Symbol(f"_c_{ang}")  # not Dummy: remembered
        sub[sp.sin(ang)], sub[sp.cos(ang)] = s_, c_
        rels.append(s_**2 + c_**2 - 1)
    t = sp.Symbol("_t")
    polys = [n.xreplace(sub) for n in nums] + rels + [1 - t * k.xreplace(sub)]
    gens = [t, *sorted({g for p in polys for g in p.free_symbols} - {t}, key=str)]
    if len(gens) > 12 or sp.count_ops(k) > 2000:
        return False
    return _unit_ideal(tuple(polys), tuple(gens))


def _distinct_in_ring(a: Point, b: Point, assumed: Iterable[sp.Expr]) -> bool | None:
    """:func:`distinct` in the model's ring (sines, cosines, μ, x1, x2, y): the same
    Rabinowitsch argument, with the polynomials converted structurally (no sympy
    ``together``) and factored by python-flint; None when an expression is not in the
    ring (the caller then takes the general route)."""
    import flint

    from ._flint import factor_list
    from .certify_algebra import ring

    R = ring()
    try:
        nums = [R.frac(sp.sympify(e))[0] for e in (a.x - b.x, a.y - b.y)]
        dens = [R.frac(sp.sympify(e))[0] for e in assumed]
    except (ValueError, TypeError, KeyError, ArithmeticError, NotImplementedError):
        return None
    if any(n.is_ground and n for n in nums):
        return True
    bases: dict[Any, None] = {}
    for d in dens:
        if d and not d.is_ground:
            for f, _ in factor_list(d)[1]:
                bases[f.monic()] = None
    k = R.R.one
    for f in bases:
        k *= f
    used = {i for p in (*nums, k) for m in p.monoms() for i, e in enumerate(m) if e}
    ix = R.index
    for s_ in (S.x1, S.x2, S.mu1, S.mu2):
        if ix[s_] in used:
            k *= R.R.gens[ix[s_]]
    if ix[S.x1] in used and ix[S.x2] in used:
        k *= R.R.gens[ix[S.x1]] + R.R.gens[ix[S.x2]]
    used = {i for p in (*nums, k) for m in p.monoms() for i, e in enumerate(m) if e}
    if len(used) > 13 or len(k.terms()) > 4000:
        return False
    n = len(R.gens)
    names = ("_t", *(f"g{i}" for i in range(n)))
    ctx = flint.fmpz_mpoly_ctx.get(names, "degrevlex")

    def z(p: Any, t: int = 0) -> Any:  # integer multiple of p, t^t times
        terms = p.terms()
        den = 1
        for _, c in terms:
            den = den * int(c.denominator) // math.gcd(den, int(c.denominator))
        return ctx.from_dict(
            {(t, *m): int(c.numerator) * (den // int(c.denominator)) for m, c in terms}
        )

    polys = [z(p) for p in nums if p]
    for i in range(4):  # sin² + cos² − 1 for each angle in use
        if i in used or i + 4 in used:
            polys.append(z(R.relations[i]))
    kz = z(k, 1)
    # 1 − t·k scaled: t·k has integer coefficients after scaling by k's denominator
    den = 1
    for _, c in k.terms():
        den = den * int(c.denominator) // math.gcd(den, int(c.denominator))
    polys.append(ctx.from_dict({(0,) * (n + 1): den}) - kz)
    # python-flint's stub says a vec; with ``limits`` it returns (vec, finished)
    done: tuple[flint.fmpz_mpoly_vec, bool] = flint.fmpz_mpoly_vec(  # type: ignore[assignment]
        polys, ctx
    ).buchberger_naive(limits=(400, 4000, 4096))
    basis, ok = done
    return bool(ok) and any(g.is_constant() and g != 0 for g in basis)


@lru_cache(maxsize=256)
def _unit_ideal(polys: tuple[sp.Expr, ...], gens: tuple[sp.Symbol, ...]) -> bool:
    """Whether the polynomials generate the unit ideal of Q[gens] (a Gröbner basis holds
    a non-zero constant), so that they have no common complex zero.

    Buchberger's algorithm in C (python-flint's ``fmpz_mpoly_vec.buchberger_naive``,
    grevlex, the polynomials scaled to integer coefficients, which spans the same ideal
    over Q), with limits on the basis and on the size of its polynomials: a run stopped
    at a limit proves nothing (False).  Remembered: the circles of a construction ask
    the same question again for each pair of centres.

    >>> from graspcompass.symbols import x1
    >>> t = sp.Symbol("_t")
    >>> _unit_ideal((x1**2 - 1, x1 - 1, 1 - t * (x1 - 1)), (t, x1))
    True
    >>> _unit_ideal((x1**2 - 1, 1 - t * (x1 - 1)), (t, x1))
    False
    """
    import flint

    ctx = flint.fmpz_mpoly_ctx.get(tuple(str(g) for g in gens), "degrevlex")
    qctx = flint.fmpq_mpoly_ctx.get(tuple(str(g) for g in gens), "degrevlex")
    try:
        qs = [_to_mpoly(p, dict(zip(gens, qctx.gens())), qctx) for p in polys]
    except (TypeError, ValueError, ArithmeticError, NotImplementedError):
        return False
    zs = []
    for q in qs:
        terms = q.to_dict()
        if not terms:
            continue
        den = 1
        for c in terms.values():
            den = den * int(c.q) // math.gcd(den, int(c.q))
        zs.append(ctx.from_dict({m: int(c.p) * (den // int(c.q)) for m, c in terms.items()}))
    if not zs:
        return False
    # python-flint's stub says a vec; with ``limits`` it returns (vec, finished)
    done: tuple[flint.fmpz_mpoly_vec, bool] = flint.fmpz_mpoly_vec(  # type: ignore[assignment]
        zs, ctx
    ).buchberger_naive(limits=(400, 4000, 4096))
    basis, ok = done
    return bool(ok) and any(g.is_constant() and g != 0 for g in basis)


def _to_mpoly(e: sp.Expr, gen: dict[sp.Basic, Any], ctx: Any) -> Any:
    """The polynomial ``e`` (sympy, in the symbols of ``gen``, rational coefficients) as a
    python-flint ``fmpq_mpoly``, by one walk over its tree (no expansion in sympy)."""
    import flint

    if e in gen:
        return gen[e]
    if e.is_Rational:
        return ctx.from_dict({}) + flint.fmpq(int(e.p), int(e.q))
    if e.is_Add:
        out = ctx.from_dict({})
        for a in e.args:
            out += _to_mpoly(a, gen, ctx)
        return out
    if e.is_Mul:
        out = ctx.from_dict({}) + 1
        for a in e.args:
            out *= _to_mpoly(a, gen, ctx)
        return out
    if e.is_Pow and e.exp.is_Integer and e.exp >= 0:
        return _to_mpoly(e.base, gen, ctx) ** int(e.exp)
    raise TypeError(f"not a polynomial in the generators: {e}")
