"""The rings of the kernel's canonical form, their relations and the reduction.

A canonical number is one fraction ``n/d`` of sparse polynomials over QQ in its
generators; :data:`_MEMO` remembers the fraction of each canonical expression.
:func:`_reduce` brings ``n/d`` to the canonical form: modulo ``sqrt(p)**2 = p``
and ``sin(a)**2 + cos(a)**2 = 1`` (:func:`_relations`), square roots cleared from
the denominator by conjugates (:func:`_clear_roots`), cancelled.  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

from functools import cmp_to_key, lru_cache

import sympy as sp

from ._exact_bounds import _clearly_nonzero

_ADD_ORDER = cmp_to_key(sp.Basic.compare)  # the order of sympy's Add arguments


@lru_cache(maxsize=4096)
def _ring(gens: tuple[sp.Expr, ...]):
    return sp.ring(gens, sp.QQ, sp.lex)[0]


#: Canonical expression -> (ring, numerator, denominator) of sparse polynomials.
_MEMO: dict[sp.Expr, tuple] = {}


@lru_cache(maxsize=4096)
def _gen_key(g: sp.Expr) -> tuple:
    """Order of generators: prime square roots, then sines (their relations lead), then rest."""
    if g.is_Pow and g.exp == sp.S.Half and g.base.is_Integer:
        rank = 0
    elif isinstance(g, sp.sin):
        rank = 1
    else:
        rank = 2
    return (rank, sp.default_sort_key(g))


@lru_cache(maxsize=4096)
def _relations(R) -> tuple[list, list, list]:
    """Ring R's relations: ``r**2 - p`` for prime roots, ``s**2 + c**2 - 1`` for
    sine-cosine pairs, and the root generators."""
    from .trig import OpaqueCos, OpaqueSin

    index = {g: R.gens[i] for i, g in enumerate(R.symbols)}
    prime_roots = [g for g in R.symbols if _gen_key(g)[0] == 0]
    roots = [index[g] for g in prime_roots]
    root_rels = [index[g] ** 2 - int(g.base) for g in prime_roots]
    trig_rels = []
    for g in R.symbols:
        if isinstance(g, sp.sin):
            c = OpaqueCos(g.args[0]) if isinstance(g, OpaqueSin) else sp.cos(g.args[0])
            if c in index:
                trig_rels.append(index[g] ** 2 + index[c] ** 2 - 1)
    return root_rels, trig_rels, roots


#: sqrt(m) of the square-free m met so far (sympy's evaluation of sqrt is slow).
_SQRT: dict[int, sp.Expr] = {}


@lru_cache(maxsize=4096)
def _root_primes(R) -> tuple[int, ...] | None:
    """The primes p of ring R when all its generators are square roots sqrt(p), else None."""
    if not all(_gen_key(g)[0] == 0 for g in R.symbols):
        return None
    return tuple(int(g.base) for g in R.symbols)


def _as_expr(p) -> sp.Expr:
    """``p.as_expr()``, built directly for a reduced polynomial in prime square roots.

    Gives the very expression sympy builds (``Add`` of ``coefficient * sqrt(m)``
    terms, ``sqrt(2)*sqrt(3)`` as ``sqrt(6)``, in sympy's argument order) without
    its flattening; ``test_exact_filter`` checks the two agree structurally.
    """
    primes = _root_primes(p.ring)
    if primes is None or len(p) < 2:
        return p.as_expr()
    const = None
    terms = []
    for monom, c in p.items():
        m = 1
        for prime, e in zip(primes, monom):
            if e > 1:
                return p.as_expr()  # not reduced
            if e:
                m *= prime
        q = sp.Rational(int(c.numerator), int(c.denominator))
        if m == 1:
            const = q
            continue
        root = _SQRT.get(m)
        if root is None:
            root = _SQRT[m] = sp.sqrt(m)
        terms.append(root if q is sp.S.One else sp.Mul._from_args((q, root), True))
    terms.sort(key=_ADD_ORDER)
    if const is not None:
        terms.insert(0, const)
    return sp.Add._from_args(terms, True)


@lru_cache(maxsize=4096)
def _has_opaque(R) -> bool:
    """Whether ring R has numeric generators other than prime square roots."""
    return any(g.is_number and _gen_key(g)[0] != 0 for g in R.symbols)


def _finish(R, n, d) -> sp.Expr:
    """The canonical sympy expression of n/d (:func:`_reduce`); remember it."""
    n, d = _reduce(R, n, d)
    out = n.as_expr() / d.as_expr() if d != R.one else _as_expr(n)
    if len(_MEMO) > 100_000:
        _MEMO.clear()
    _MEMO[out] = (R, n, d)
    return out


def _reduce(R, n, d) -> tuple:
    """Reduce n/d modulo the relations, clear roots from d, cancel.

    Square roots are always reduced (``sqrt(p)**2 = p``) and cleared from the
    denominator.  The trigonometric relations ``s**2 + c**2 = 1`` form a Groebner
    basis, so the numerator reduces to 0 exactly when the value is 0; the reduced
    numerator and denominator are kept only when they are smaller than the
    cancelled ones (reducing first would hide common factors from the gcd and blow
    up long symbolic fractions).
    """
    root_rels, trig_rels, roots = _relations(R)
    if root_rels:
        n, d = n.rem(root_rels), d.rem(root_rels)
    if not d:
        raise ZeroDivisionError("division by zero")
    opaque = _has_opaque(R)
    n, d = _clear_roots(n, d, roots, root_rels, opaque)
    if d.is_ground:
        n, d = n.quo_ground(d.LC), R.one
    else:
        n, d = n.cancel(d)
    if trig_rels and n:
        nr = n.rem(trig_rels)
        if not nr:
            n, d = nr, R.one
        else:
            if len(nr) < len(n):
                n = nr
            if not d.is_ground:
                dr = d.rem(trig_rels)
                if not dr:
                    raise ZeroDivisionError("division by zero")
                if len(dr) < len(d):
                    d = dr
    if d.is_ground and d != R.one:
        n, d = n.quo_ground(d.LC), R.one
    if d.LC < 0:
        n, d = -n, -d
    return n, d


def _clear_roots(n, d, roots: list, rels: list, opaque: bool) -> tuple:
    """Multiply by conjugates (sqrt(p) -> -sqrt(p)) until ``d`` is free of roots.

    The conjugation is a field automorphism of Q(sqrt(p1), ..., sqrt(pk)); when the
    number also holds opaque algebraic atoms it need not respect them, so the new
    denominator is then checked to be non-zero numerically (and the step skipped
    if it is not clearly so).
    """
    for g in roots:
        if d.degree(g) <= 0:
            continue
        conj = d.compose(g, -g)
        n2, d2 = (n * conj).rem(rels), (d * conj).rem(rels)
        if not d2:
            continue
        if opaque and not _clearly_nonzero(conj):
            continue
        n, d = n2, d2
    return n, d
