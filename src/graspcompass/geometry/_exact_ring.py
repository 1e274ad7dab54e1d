"""The rings of the kernel's exact numbers, their relations and the canonical form.

A number is one fraction ``n/d`` of sparse polynomials over Q (python-flint's
``fmpq_mpoly``, in C) in its generators: prime square roots ``sqrt(p)``, the
sine and cosine of each angle, symbols and other atoms.  The generators are
tied by *quadratic relations* ``g**2 = q``: ``sqrt(p)**2 = p`` and
``sin(a)**2 = 1 - cos(a)**2``.  Each relation's generator comes before every
generator of its right-hand side in the ring's lex order, so the relations form
a Groebner basis and :func:`reduce_poly` gives the unique normal form of a
polynomial (degree at most 1 in every related generator): a polynomial is 0 on
the model exactly when its normal form is the zero polynomial.

:func:`_reduce` puts ``n/d`` in canonical form **in this order**, which is what
keeps values as written:

1. both ``n`` and ``d`` are reduced modulo the relations;
2. a denominator whose normal form is 0 raises :class:`ZeroDivisionError`
   (``Z/Z`` with ``Z = sin**2 + cos**2 - 1`` is 0/0, never 1);
3. square roots are cleared from ``d`` by conjugates;
4. only then the polynomial gcd of ``n`` and ``d`` is cancelled (flint), and
   the pair is normalised as sympy's ``cancel`` does (integer coefficients,
   jointly primitive, positive leading coefficient of ``d``).

The gcd divides ``d``, so cancelling it is valid wherever ``d`` is non-zero:
the callers prove ``d != 0`` at the point (numbers) or record it as a
non-degeneracy condition (symbols).  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

from functools import cmp_to_key, lru_cache
from math import gcd, lcm

import flint
import sympy as sp

from ._exact_bounds import _clearly_nonzero

_ADD_ORDER = cmp_to_key(sp.Basic.compare)  # the order of sympy's Add arguments

__all__ = ["Ring", "reduce_poly"]


class Ring:
    """A polynomial ring over Q in sympy generators, with their quadratic relations.

    ``symbols`` are the sympy atoms, ``gens`` the flint generators in the same
    order, ``quad`` the relations ``(i, q)`` meaning ``gens[i]**2 = q``,
    ``roots`` the indices of prime square roots.

    Examples
    --------
    >>> R = _ring((sp.sqrt(3),))
    >>> r, = R.gens
    >>> reduce_poly(R, r**3 + 1) == 3 * r + 1
    True
    """

    __slots__ = (
        "__weakref__",
        "ctx",
        "free",
        "gens",
        "index",
        "ngens",
        "one",
        "opaque",
        "quad",
        "root_primes",
        "roots",
        "symbols",
        "zero",
    )

    def __init__(self, symbols: tuple[sp.Expr, ...]) -> None:
        self.symbols = symbols
        self.ngens = len(symbols)
        names = tuple(f"g{i}" for i in range(max(1, self.ngens)))
        self.ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
        self.gens = self.ctx.gens()[: self.ngens]
        self.one = self.ctx.constant(1)
        self.zero = self.ctx.constant(0)
        self.index = {g: i for i, g in enumerate(symbols)}
        self.quad, self.roots = _quadratic(self)
        #: the numeric generators that are no prime square roots (sin, cos, other atoms)
        self.opaque = tuple(i for i, g in enumerate(symbols) if g.is_number and _gen_key(g)[0] != 0)
        self.free = any(g.free_symbols for g in symbols)  # symbols: not a number
        self.root_primes = (
            tuple(int(g.base) for g in symbols)
            if all(_gen_key(g)[0] == 0 for g in symbols)
            else None
        )

    def __call__(self, value: int | sp.Expr) -> flint.fmpq_mpoly:
        """The constant ``value`` (an int or a sympy Rational), or a generator, of this ring."""
        if isinstance(value, int):
            return self.ctx.constant(value)
        if not value.is_Rational:
            return self.gens[self.index[value]]
        return self.ctx.constant(flint.fmpq(int(value.p), int(value.q)))

    def from_dict(self, terms: dict) -> flint.fmpq_mpoly:
        """The polynomial with the given ``{monomial: coefficient}`` terms."""
        return self.ctx.from_dict(terms)

    def __repr__(self) -> str:
        return f"Ring({', '.join(map(str, self.symbols))})"


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


def _quadratic(R: Ring) -> tuple[tuple, tuple[int, ...]]:
    """Ring R's relations ``(i, q)``: ``sqrt(p)**2 = p``, ``sin**2 = 1 - cos**2``."""
    from .trig import OpaqueCos, OpaqueSin

    quad, roots = [], []
    for i, g in enumerate(R.symbols):
        if _gen_key(g)[0] == 0:
            quad.append((i, R.ctx.constant(int(g.base))))
            roots.append(i)
        elif isinstance(g, sp.sin):
            c = OpaqueCos(g.args[0]) if isinstance(g, OpaqueSin) else sp.cos(g.args[0])
            j = R.index.get(c)
            if j is not None:
                quad.append((i, 1 - R.gens[j] ** 2))
    return tuple(quad), tuple(roots)


@lru_cache(maxsize=4096)
def _ring(gens: tuple[sp.Expr, ...]) -> Ring:
    return Ring(gens)


def reduce_poly(R: Ring, p: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """The normal form of ``p`` modulo R's relations (degree <= 1 in each related generator)."""
    if not R.quad:
        return p
    degrees = p.degrees()
    for i, q in R.quad:
        if degrees[i] >= 2:
            p = divmod(p, R.gens[i] ** 2 - q)[1]
    return p


#: Canonical expression -> (ring, numerator, denominator) of flint polynomials.
_MEMO: dict[sp.Expr, tuple[Ring, flint.fmpq_mpoly, flint.fmpq_mpoly]] = {}

#: sqrt(m) of the square-free m met so far (sympy's evaluation of sqrt is slow).
_SQRT: dict[int, sp.Expr] = {}


def _coefficient(c: flint.fmpq) -> sp.Rational:
    return sp.Rational(int(c.p), int(c.q))


def _as_expr(R: Ring, p: flint.fmpq_mpoly) -> sp.Expr:
    """The sympy expression of the polynomial ``p``, built without sympy's flattening.

    Each term is ``Mul(coefficient, *factors)`` with the factors in sympy's own
    order and the reduced square roots multiplied into one (``sqrt(2)*sqrt(3)`` is
    ``sqrt(6)``), as ``Mul`` makes it; a sum of at most :data:`_SORTED_TERMS` terms
    has its terms in sympy's order too (``test_exact_filter`` checks that it is
    sympy's own tree), a longer one keeps the ring's monomial order (sorting it
    would cost more than the arithmetic that made it).
    """
    if p.is_zero():
        return sp.Integer(0)
    symbols = R.symbols
    roots = set(R.roots)
    primes = {i: int(symbols[i].base) for i in roots}
    powers: dict[tuple[int, int], sp.Expr] = {}
    const = None
    terms: list[sp.Expr] = []
    raw: list[tuple[sp.Rational, list]] = []
    distinct: set[sp.Expr] = set()
    for monom, c in p.terms():
        q = _coefficient(c)
        m = 1
        factors = []
        for i, e in enumerate(monom):
            if not e:
                continue
            if i in roots and e == 1:
                m *= primes[i]
                continue
            f = powers.get((i, e))
            if f is None:
                f = powers[(i, e)] = symbols[i] if e == 1 else sp.Pow(symbols[i], int(e))
            factors.append(f)
        if m > 1:
            root = _SQRT.get(m)
            if root is None:
                root = _SQRT[m] = sp.sqrt(m)
            factors.append(root)
        if not factors:
            const = q
            continue
        raw.append((q, factors))
        distinct.update(factors)
    # sympy's order of the factors, found once for the distinct factors of p
    rank = {f: k for k, f in enumerate(sorted(distinct, key=_ADD_ORDER))}
    for q, factors in raw:
        if len(factors) > 1:
            factors.sort(key=rank.__getitem__)
        if q is sp.S.One:
            terms.append(factors[0] if len(factors) == 1 else sp.Mul._from_args(factors, True))
        else:
            terms.append(sp.Mul._from_args((q, *factors), True))
    if len(terms) <= _SORTED_TERMS:
        terms.sort(key=_ADD_ORDER)
    if const is not None:
        terms.insert(0, const)
    return terms[0] if len(terms) == 1 else sp.Add._from_args(terms, True)


#: Longest sum whose terms are put in sympy's order (see :func:`_as_expr`).
_SORTED_TERMS = 48


def _finish(R: Ring, n, d) -> sp.Expr:
    """The canonical sympy expression of n/d (:func:`_reduce`); remember it."""
    n, d = _reduce(R, n, d)
    out = _as_expr(R, n) / _as_expr(R, d) if not d.is_one() else _as_expr(R, n)
    if len(_MEMO) > 100_000:
        _MEMO.clear()
    _MEMO[out] = (R, n, d)
    return out


def _reduce(R: Ring, n, d) -> tuple:
    """Check d, reduce n/d modulo the relations, clear roots from d, cancel, normalise.

    Raises
    ------
    ZeroDivisionError
        When ``d`` is 0 modulo the relations (0 at every point of the model).

    The gcd is taken of the polynomials before the trigonometric relations are
    applied (reducing first hides common factors: ``sin(a)**2`` becomes
    ``1 - cos(a)**2``); it divides ``d``, which is non-zero modulo the relations,
    and the ring modulo them is an integral domain, so the gcd is non-zero there
    too and cancelling it keeps the value.  The reduced numerator and denominator
    are then kept when they are smaller.
    """
    if reduce_poly(R, d).is_zero():
        raise ZeroDivisionError("division by zero")
    if R.roots:
        n, d = reduce_roots(R, n), reduce_roots(R, d)
        if not uses_opaque(R, n, d):
            n, d = _clear_roots(R, n, d)
    if n.is_zero():
        return R.zero, R.one
    if not d.is_constant():
        g = n.gcd(d)
        if not g.is_one():
            n, d = n / g, d / g
    if len(R.quad) > len(R.roots):
        nr = reduce_poly(R, n)
        if nr.is_zero():
            return R.zero, R.one
        if len(nr) < len(n):
            n = nr
        if not d.is_constant():
            dr = reduce_poly(R, d)
            if len(dr) < len(d):
                d = dr
    if d.is_constant():
        return n / d.leading_coefficient(), R.one
    return _normalise(n, d)


def uses_opaque(R: Ring, *polys: flint.fmpq_mpoly) -> bool:
    """Whether a polynomial uses one of R's opaque generators (a sine, a cosine, an atom):
    then the square roots stay in the denominator (clearing them by conjugates multiplies
    the size by two per root, and is canonical only in a field of radicals)."""
    if not R.opaque:
        return False
    return any(p.degrees()[i] for p in polys for i in R.opaque)


def reduce_roots(R: Ring, p: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``p`` modulo the relations ``sqrt(q)**2 = q`` of R's square roots only."""
    degrees = p.degrees()
    for i in R.roots:
        if degrees[i] >= 2:
            p = divmod(p, R.gens[i] ** 2 - R.quad[R.roots.index(i)][1])[1]
    return p


def _normalise(n, d) -> tuple:
    """Integer coefficients, jointly primitive, positive leading coefficient of d."""
    coeffs = n.coeffs() + d.coeffs()
    den = lcm(*(int(c.q) for c in coeffs))
    num = gcd(*(int(c.p) for c in coeffs))
    scale = flint.fmpq(den, num)
    if d.leading_coefficient() < 0:
        scale = -scale
    if scale != 1:
        n, d = n * scale, d * scale
    return n, d


def _clear_roots(R: Ring, n, d) -> tuple:
    """Multiply by conjugates (sqrt(p) -> -sqrt(p)) until ``d`` is free of roots.

    The conjugation is a field automorphism of Q(sqrt(p1), ..., sqrt(pk)); when the
    number also holds opaque algebraic atoms it need not respect them, so the new
    denominator is then checked to be non-zero numerically (and the step skipped
    if it is not clearly so).
    """
    gens = R.gens
    for i in R.roots:
        if d.degrees()[i] <= 0:
            continue
        conj = d.compose(*(-g if j == i else g for j, g in enumerate(gens)))
        d2 = reduce_roots(R, d * conj)
        if d2.is_zero():
            continue
        if R.opaque and uses_opaque(R, conj) and not _clearly_nonzero(R, conj):
            continue
        n, d = reduce_roots(R, n * conj), d2
    return n, d
