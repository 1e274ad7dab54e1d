"""Trigonometric identities reduced to polynomial ones.

Every angle symbol ``a`` (φ1, φ2, ξ1, ξ2, θ, ...) gets two polynomial variables,
``sin a`` and ``cos a`` themselves, tied by ``sin(a)**2 + cos(a)**2 = 1``; sums of
angles are expanded by the addition formulas, ``tan = sin/cos`` and a friction
coefficient ``mu_i`` is ``tan xi_i``.  An expression then becomes a rational
function; it vanishes identically (on the real parameter domain, where the
circles ``s**2 + c**2 = 1`` are Zariski dense) exactly when its numerator
reduces to zero modulo the ideal of those relations.  Their leading terms
``s_a**2`` are pairwise coprime, so they already form a Groebner basis and the
reduction is a plain multivariate division: no ``simplify``, no guessing.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

from .. import symbols as S
from ..geometry.exact import _nd

__all__ = ["ANGLES", "Reduction", "is_identically_zero", "reduce_expr", "trig_to_poly"]

#: Angle symbols of the model; any other symbol inside sin/cos/tan is added on the fly.
ANGLES: tuple[sp.Symbol, ...] = (S.phi1, S.phi2, S.xi1, S.xi2, S.theta)
_MU = {S.mu1: S.xi1, S.mu2: S.xi2}


#: sin(a) -> (sin(a), cos(a)) for every angle met so far.
_PAIRS: dict[sp.Expr, tuple[sp.Expr, sp.Expr]] = {}


@cache
def _sc(angle: sp.Symbol) -> tuple[sp.Expr, sp.Expr]:
    """The polynomial variables of an angle: ``sin(a)`` and ``cos(a)`` themselves.

    Keeping the function atoms as variables lets the construction's own
    (memoised) expressions enter the reduction without being rewritten.
    """
    pair = sp.sin(angle), sp.cos(angle)
    _PAIRS[pair[0]] = pair
    return pair


def _linear_angle(arg: sp.Expr) -> tuple[sp.Expr, dict[sp.Symbol, int]] | None:
    """``arg`` as ``k*pi + sum(n_a * a)`` with rational k and integer n_a."""
    k: sp.Expr = sp.Integer(0)
    coeffs: dict[sp.Symbol, int] = {}
    for term in sp.Add.make_args(sp.expand(arg)):
        c, rest = term.as_coeff_Mul()
        if rest == sp.pi:
            k += c
        elif rest.is_Symbol and c.is_Integer:
            coeffs[rest] = coeffs.get(rest, 0) + int(c)
        else:
            return None
    return k, coeffs


def _sin_cos(arg: sp.Expr) -> tuple[sp.Expr, sp.Expr] | None:
    """(sin arg, cos arg) as polynomials in the s_a, c_a of its angles."""
    lin = _linear_angle(arg)
    if lin is None:
        return None
    k, coeffs = lin
    s, c = sp.sin(k * sp.pi), sp.cos(k * sp.pi)
    for a, n in coeffs.items():
        sa, ca = _sc(a)
        sb = sa if n > 0 else -sa
        for _ in range(abs(n)):
            s, c = s * ca + c * sb, c * ca - s * sb
    return sp.expand(s), sp.expand(c)


def trig_to_poly(expr: sp.Expr) -> sp.Expr:
    """Replace sin, cos, tan of angle combinations and ``mu_i`` by s_a, c_a variables.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1
    >>> trig_to_poly(sp.sin(phi1 + xi1)) == sp.sin(phi1)*sp.cos(xi1) + sp.sin(xi1)*sp.cos(phi1)
    True
    """
    expr = sp.sympify(expr)
    repl: dict[sp.Expr, sp.Expr] = {}
    for f in expr.atoms(sp.sin, sp.cos, sp.tan):
        if f.args[0].is_Symbol and not isinstance(f, sp.tan):
            _sc(f.args[0])
            continue
        sc = _sin_cos(f.args[0])
        if sc is None:
            raise ValueError(f"cannot reduce {f}: its argument is not a sum of angle symbols")
        s, c = sc
        repl[f] = s if isinstance(f, sp.sin) else c if isinstance(f, sp.cos) else s / c
    for mu, xi in _MU.items():  # mu = tan xi, needed only where xi appears too
        if expr.has(mu) and expr.has(xi):
            s, c = _sc(xi)
            repl[mu] = s / c
    return expr.xreplace(repl) if repl else expr


@dataclass(frozen=True)
class Reduction:
    """The normal form of an expression's numerator, and its denominator."""

    remainder: sp.Expr
    denominator: sp.Expr

    @property
    def is_zero(self) -> bool:
        """True when the expression vanishes identically."""
        return self.remainder == 0


def reduce_expr(expr: sp.Expr) -> Reduction:
    """Reduce ``expr`` modulo ``s_a**2 + c_a**2 - 1`` for every angle in it.

    Examples
    --------
    >>> from graspcompass.symbols import phi1
    >>> reduce_expr(sp.sin(phi1)**2 + sp.cos(phi1)**2 - 1).is_zero
    True
    >>> reduce_expr(sp.sin(phi1)**2 - sp.cos(phi1)**2).is_zero
    False
    """
    poly = trig_to_poly(expr)
    trig = poly.atoms(sp.sin, sp.cos)
    pairs = sorted({_PAIRS[sp.sin(f.args[0])] for f in trig}, key=str)
    inner = set().union(*(f.free_symbols for f in trig)) if trig else set()
    outer = poly.xreplace({f: sp.Dummy() for f in trig}).free_symbols - {
        d for d in poly.xreplace({f: sp.Dummy() for f in trig}).free_symbols if d.is_Dummy}
    if outer & inner:
        raise ValueError(f"an angle appears outside sin/cos: {sorted(map(str, outer & inner))}")
    sines = [p[0] for p in pairs]
    gens = [*sines, *sorted((outer | {p[1] for p in pairs}), key=str)]
    if not gens:
        return Reduction(sp.Integer(0) if poly == 0 else poly, sp.Integer(1))
    R = sp.ring(gens, sp.QQ, sp.lex)[0]
    # numerator and denominator as sparse polynomials, without any gcd on the way
    num, den = _nd(poly, R, {g: i for i, g in enumerate(gens)})
    if not num or not pairs:
        return Reduction(num.as_expr(), den.as_expr())
    rem = num.rem([R(s**2 + c**2 - 1) for s, c in pairs])
    return Reduction(rem.as_expr(), den.as_expr())


def is_identically_zero(expr: sp.Expr) -> bool:
    """True when ``expr`` vanishes for every value of its symbols (where defined)."""
    return reduce_expr(expr).is_zero
