"""Trigonometric identities, square roots and quotients reduced to polynomial ones.

Every angle symbol ``a`` (φ1, φ2, ξ1, ξ2, θ, ...) gets two polynomial variables,
``sin a`` and ``cos a`` themselves, tied by ``sin(a)**2 + cos(a)**2 = 1``; sums of
angles are expanded by the addition formulas in the polynomial ring (linear in
``n`` for ``sin(n a)``), ``tan = sin/cos`` and a friction coefficient ``mu_i``
is ``tan xi_i`` where ``xi_i`` occurs too (eq. (22)).  A square root ``sqrt(P)``
becomes a variable ``w`` tied by ``w**2 = P``.  An expression then becomes a
rational function; its numerator is divided by the relations.

Why the division decides: in the lexicographic order with the roots first (outer
roots before inner ones) and each sine before its cosine, the leading monomials
``w**2`` and ``s_a**2`` of the relations are pairwise coprime, so the relations
are a Groebner basis (Buchberger's first criterion) and the remainder is a normal
form.  A zero remainder proves the identity wherever the expression is defined,
for every sign of every root, so for the principal roots too.  Without roots a
non-zero remainder means the identity fails somewhere (the circles
``s**2 + c**2 = 1`` are Zariski dense); **with roots a non-zero remainder is not
a refutation** (``sqrt(2)*sqrt(3) - sqrt(6)``): the counterexample search decides.

Every denominator met in the expression tree is recorded; one that vanishes
modulo the relations makes the expression undefined everywhere
(:class:`DegenerateClaimError`); the others are returned as irreducible
factors (:attr:`Reduction.factors`) for the prover to discharge or to list as
non-degeneracy conditions.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any

import sympy as sp

from .. import symbols as S
from ._flint import divide, factor_list
from ._ring import DegenerateClaimError, RingForm, to_ring
from .model import outside_expr

__all__ = [
    "ANGLES",
    "DegenerateClaimError",
    "Reduction",
    "is_identically_zero",
    "reduce_expr",
    "trig_to_poly",
]

#: Angle symbols of the model; any other symbol inside sin/cos/tan is added on the fly.
ANGLES: tuple[sp.Symbol, ...] = (S.phi1, S.phi2, S.xi1, S.xi2, S.theta)


def trig_to_poly(expr: sp.Expr) -> sp.Expr:
    """Replace sin, cos, tan of angle combinations and ``mu_i`` by s_a, c_a variables.

    The result is a rational function of ``sin(a)``, ``cos(a)``, the other symbols
    and the square roots; ``mu_i`` becomes ``sin(xi_i)/cos(xi_i)`` where ``xi_i``
    occurs too (eq. (22)).

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1
    >>> trig_to_poly(sp.sin(phi1 + xi1)) == sp.sin(phi1)*sp.cos(xi1) + sp.sin(xi1)*sp.cos(phi1)
    True
    """
    form = to_ring([outside_expr(expr, "expr")])  # the caller's: never sympify
    n, d = form.values[0]
    return form.as_expr(n) / form.as_expr(d)


@dataclass(frozen=True)
class Reduction:
    """The normal form of an expression's numerator, its denominator, and the data of a proof.

    Attributes
    ----------
    remainder_poly : PolyElement or int
        Normal form of the numerator modulo the relations, in the ring of ``form``
        (0 proves the identity); :attr:`remainder` is the same as an expression.
    denominator_poly : PolyElement
        The product of every denominator met (no cancellation), in the ring of ``form``;
        :attr:`denominator` is the same as an expression.
    factors : tuple of sympy.Expr
        The distinct irreducible (non-constant) factors of the denominators met,
        none of them zero modulo the relations.
    certificate : dict, optional
        When the remainder is 0: the numerator, the relations and the cofactors
        (``N = sum q_i rel_i``) as JSON-ready sparse polynomials.
    form : RingForm, optional
        The ring of the reduction.
    """

    remainder_poly: Any = field(repr=False)
    denominator_poly: Any = field(repr=False)
    factors: tuple[sp.Expr, ...] = ()
    certificate: dict[str, Any] | None = field(default=None, compare=False)
    form: RingForm | None = field(default=None, repr=False, compare=False)

    @cached_property
    def remainder(self) -> sp.Expr:
        """The normal form of the numerator as an expression (built on demand: a
        non-zero normal form can be long, and a zero test does not need it)."""
        p = self.remainder_poly
        if not p:
            return sp.Integer(0)
        return self.form.as_expr(p) if self.form is not None else sp.sympify(p)

    @cached_property
    def denominator(self) -> sp.Expr:
        """The product of every denominator met, as an expression (built on demand)."""
        p = self.denominator_poly
        # internal: a ring element
        return self.form.as_expr(p) if self.form is not None else sp.sympify(p)

    @property
    def is_zero(self) -> bool:
        """True when the expression vanishes identically (where defined)."""
        if not self.remainder_poly:
            return True
        # a root's generator written back as its sqrt may let sympy cancel what the
        # ring keeps apart (sqrt(5*a**2) is sqrt(5)*a for a > 0): only then is the
        # expression built
        return bool(self.form is not None and self.form.roots and self.remainder == 0)


#: Normal form of a denominator -> its irreducible factors: by content (the ring's
#: generators as expressions and the polynomial's terms), never by a name.
_FACTORS: dict[tuple, tuple[sp.Expr, ...]] = {}


def _irreducible(p: Any) -> list[Any]:
    """The irreducible factors of the polynomial ``p`` (multiplicities dropped).

    Fast path, exact: if ``p = A x + B`` with ``A != 0`` and ``A, B`` free of ``x``,
    every factorisation puts the whole of ``x`` in one factor, so the other divides
    ``h = gcd(A, B)``: ``p / h`` is irreducible, and ``h`` is factored the same way.
    Only a polynomial of degree >= 2 in every variable goes to ``factor_list``.
    """
    if p.is_ground:
        return []
    for i in range(p.ring.ngens):
        if p.degree(i) == 1:
            a = p.ring({(*m[:i], 0, *m[i + 1 :]): c for m, c in p.terms() if m[i] == 1})
            h = a.gcd(p - a * p.ring.gens[i])
            if h.is_ground:
                return [p]
            return [p.exquo(h), *_irreducible(h)]
    return [f for f, _ in factor_list(p)[1]]


def _factors(form: RingForm, dens: list, expr: sp.Expr) -> tuple[sp.Expr, ...]:
    out: dict[sp.Expr, None] = {}
    for d in dict.fromkeys(dens):
        if d.is_ground:
            continue
        _, rem = d.div(form.relations) if form.relations else ([], d)
        if not rem:
            raise DegenerateClaimError(
                f"{expr} is undefined for every value of its symbols: its denominator "
                f"{form.as_expr(d)} is 0 modulo {form.describe_relations()} (0/0)"
            )
        if rem.is_ground:  # a non-zero constant on the variety: no condition
            continue
        key = (tuple(form.gens), frozenset(rem.terms()))  # = d wherever the relations hold
        if key not in _FACTORS:
            parts = (
                [rem]
                if len(rem) > 80
                else [f for f, _ in rem.sqf_list()[1]]
                if len(rem) > 30
                else _irreducible(rem)
            )
            _FACTORS[key] = tuple(
                form.as_expr(f.quo_ground(f.LC)) for f in parts if not f.is_ground
            )
        out.update(dict.fromkeys(_FACTORS[key]))
    return tuple(sorted(out, key=sp.default_sort_key))


def reduce_expr(expr: sp.Expr) -> Reduction:
    """Reduce ``expr`` modulo ``s_a**2 + c_a**2 - 1`` (each angle) and ``w**2 - P`` (each root).

    Cached by content (the expression itself), never by a name.

    Raises
    ------
    DegenerateClaimError
        If a denominator met is 0 modulo the relations (the expression is 0/0 or
        undefined everywhere).
    ValueError
        For what is not a rational function of sines, cosines and square roots
        (floats, ``sin(phi1/2)``, cube roots).

    Examples
    --------
    >>> from graspcompass.symbols import phi1, x1
    >>> reduce_expr(sp.sin(phi1)**2 + sp.cos(phi1)**2 - 1).is_zero
    True
    >>> reduce_expr(sp.sin(phi1)**2 - sp.cos(phi1)**2).is_zero
    False
    >>> reduce_expr((x1**2 - 1) / (x1 - 1) - x1 - 1).factors
    (x1 - 1,)
    """
    return _reduce(outside_expr(expr, "expr"))  # the caller's: never sympify


@lru_cache(maxsize=4096)
def _reduce(expr: sp.Expr) -> Reduction:
    """:func:`reduce_expr` of an expression already read (cached by content)."""
    form = to_ring([expr])
    (num, den), dens = form.values[0], form.denominators[0]
    factors = _factors(form, dens, expr)
    if not num:
        return Reduction(
            0, den, factors, form.certificate(num, [R0 * 0 for R0 in form.relations]), form
        )
    if not form.relations:
        return Reduction(num, den, factors, None, form)
    # roots (outer, then inner) before sin² + cos² − 1: see _flint.divide
    npairs = len(form.pairs)
    order = [*range(npairs, len(form.relations)), *range(npairs)]
    qs, rem = divide(num, [form.relations[i] for i in order])
    quotients = [R0 * 0 for R0 in form.relations]
    for i, q in zip(order, qs):
        quotients[i] = q
    cert = form.certificate(num, quotients) if not rem else None
    return Reduction(rem, den, factors, cert, form)


def is_identically_zero(expr: sp.Expr) -> bool:
    """True when ``expr`` vanishes for every value of its symbols (where defined).

    Examples
    --------
    >>> from graspcompass.symbols import phi1
    >>> is_identically_zero(sp.sin(2 * phi1) - 2 * sp.sin(phi1) * sp.cos(phi1))
    True
    """
    return reduce_expr(expr).is_zero
