"""Deciding the facts of a symbolic construction: one polynomial ring, cleared denominators.

Every fact ``lhs == rhs`` of a symbolic construction is a rational function of
sin φ_i, cos φ_i, sin ξ_i, cos ξ_i, μ_i, x1, x2, y.  Both sides are brought to
numerator/denominator form in one sparse polynomial ring (each side once,
cached; the construction's coordinates are already canonical fractions), the
denominators are cleared by cross-multiplication, and the numerator
``n1·d2 − n2·d1`` is reduced modulo ``sin² + cos² − 1`` of every angle (a
Gröbner basis: the leading terms sin² are coprime).  A zero remainder proves
the fact wherever ``d1·d2 ≠ 0``; those denominators are the proof's
non-degeneracy conditions.  Each condition's factors are then either shown to
hold under the domains and condition (1) (positive polynomials in the
lengths and μ; ±cos(φ_i ± ξ_i), cos ξ_i, sin ξ_i, sin φ_i by their angle
intervals) or listed as extra hypotheses.
"""

from __future__ import annotations

from functools import cache
from itertools import combinations_with_replacement
from typing import Any

import sympy as sp

from .. import symbols as S
from .prove import CONDITION_1, sign_of
from .reduce import reduce_expr, trig_to_poly

__all__ = ["Ring", "classify", "ring"]

_ANGLES = (S.phi1, S.phi2, S.xi1, S.xi2)
_POSITIVE = {S.x1, S.x2, S.mu1, S.mu2}
_NONNEG = _POSITIVE | {S.y}


class Ring:
    """The polynomial ring of the model with the relations sin² + cos² = 1."""

    def __init__(self) -> None:
        sines = [sp.sin(a) for a in _ANGLES]
        cosines = [sp.cos(a) for a in _ANGLES]
        self.gens = [*sines, *cosines, S.mu1, S.mu2, S.x1, S.x2, S.y]
        self.R = sp.ring(self.gens, sp.QQ, sp.lex)[0]
        self.index = {g: i for i, g in enumerate(self.gens)}
        g = self.R.gens
        self.relations = [g[i] ** 2 + g[i + 4] ** 2 - 1 for i in range(4)]
        self._cache: dict[Any, tuple[Any, Any]] = {}

    def nd(self, expr: Any) -> tuple[Any, Any]:
        """``expr`` as (numerator, denominator) in the ring; ValueError if it is not one."""
        expr = sp.sympify(expr)
        hit = self._cache.get(expr)
        if hit is None:
            hit = self._nd(trig_to_poly(expr))
            if not hit[1]:
                raise ValueError(f"zero denominator in {expr}")
            self._cache[expr] = hit
        return hit

    def _nd(self, e: sp.Expr) -> tuple[Any, Any]:
        """Numerator and denominator of ``e``, no gcd on the way; every node cached."""
        hit = self._cache.get(e)
        if hit is not None:
            return hit
        R = self.R
        if e.is_Rational:
            out = R(e.p), R(e.q)
        elif e in self.index:
            out = R.gens[self.index[e]], R.one
        elif e.is_Add or e.is_Mul:
            n, d = self._nd(e.args[0])
            for a in e.args[1:]:
                n2, d2 = self._nd(a)
                if e.is_Mul:
                    n, d = n * n2, d * d2
                elif d == d2:
                    n = n + n2
                else:
                    n, d = n * d2 + n2 * d, d * d2
            out = n, d
        elif e.is_Pow and e.exp.is_Integer:
            n, d = self._nd(e.base)
            k = int(e.exp)
            if k < 0:
                n, d, k = d, n, -k
            out = n**k, d**k
        else:
            raise ValueError(f"not a rational function of the model's generators: {e}")
        self._cache[e] = out
        return out

    def reduce(self, p: Any) -> Any:
        """The normal form of ``p`` modulo sin² + cos² − 1."""
        return p.rem(self.relations) if p else p

    def equal(self, lhs: Any, rhs: Any) -> tuple[bool, list[Any]]:
        """(lhs − rhs reduces to 0, the denominators assumed non-zero)."""
        n1, d1 = self.nd(lhs)
        n2, d2 = self.nd(rhs)
        num = n1 - n2 if d1 == d2 else n1 * d2 - n2 * d1
        return not self.reduce(num), [d for d in (d1, d2) if not d.is_ground]

    def expr(self, p: Any) -> sp.Expr:
        """``p`` back as a sympy expression."""
        return p.as_expr()


@cache
def ring() -> Ring:
    """The shared ring (built once per process)."""
    return Ring()


@cache
def _sign_table() -> tuple[tuple[Any, str], ...]:
    """Polynomials of fixed sign under the domains and (1), each with its reason.

    Every entry is checked here: an identity with a product of sines and cosines
    (by polynomial reduction, μ = tan ξ) whose sign follows from the intervals of
    :data:`~graspcompass.proof.prove.CONDITION_1`.
    """
    out = []
    for phi, xi, mu, i in ((S.phi1, S.xi1, S.mu1, 1), (S.phi2, S.xi2, S.mu2, 2)):
        s, c, sx, cx = sp.sin(phi), sp.cos(phi), sp.sin(xi), sp.cos(xi)
        entries = [
            (c - s * mu, sp.cos(phi + xi) / cx, f"c{i} − s{i}μ{i} = cos(φ{i}+ξ{i})/cos ξ{i}"),
            (c + s * mu, sp.cos(phi - xi) / cx, f"c{i} + s{i}μ{i} = cos(φ{i}−ξ{i})/cos ξ{i}"),
            (c * cx - s * sx, sp.cos(phi + xi), f"cos(φ{i}+ξ{i})"),
            (c * cx + s * sx, sp.cos(phi - xi), f"cos(φ{i}−ξ{i})"),
            (cx, cx, f"cos ξ{i}"), (sx, sx, f"sin ξ{i}"), (s, s, f"sin φ{i}"),
        ]
        for poly, witness, text in entries:
            if not reduce_expr(poly.subs(mu, sp.tan(xi)) - witness).is_zero:
                raise AssertionError(f"sign table: {text} is not an identity")  # pragma: no cover
            sg = sign_of(witness, CONDITION_1)
            if sg is None or sg[0] != sg[1] or sg[0] == 0:
                raise AssertionError(f"sign table: no strict sign for {text}")  # pragma: no cover
            out.append((ring().nd(poly)[0], f"{text} {'> 0' if sg[0] > 0 else '< 0'} by (1)"))
    return tuple(out)


def _positive(p: Any, R: Ring) -> bool:
    """All coefficients positive, in lengths and μ only, with a term free of y."""
    used = {R.gens[i] for mon in p.monoms() for i, e in enumerate(mon) if e}
    if not used <= _NONNEG:
        return False
    coeffs = p.coeffs()
    if not (all(c > 0 for c in coeffs) or all(c < 0 for c in coeffs)):
        return False
    iy = R.index[S.y]
    return any(mon[iy] == 0 for mon in p.monoms())


def _gens_of(p: Any) -> frozenset[int]:
    return frozenset(i for mon in p.monoms() for i, e in enumerate(mon) if e)


@cache
def _powers(gq: frozenset[int], limit: int = 4) -> tuple[tuple[Any, str], ...]:
    """Reduced products of at most ``limit`` sign-table entries whose generators are ``gq``."""
    R = ring()
    table = [(t, why) for t, why in _sign_table() if _gens_of(t) <= gq]
    out = []
    for size in range(1, limit + 1):
        for combo in combinations_with_replacement(range(len(table)), size):
            polys = [table[i][0] for i in combo]
            if frozenset().union(*(_gens_of(q) for q in polys)) != gq:
                continue
            prod = R.R.one
            for q in polys:
                prod = prod * q
            why = " · ".join(dict.fromkeys(table[i][1] for i in combo))
            out.append((R.reduce(prod), why))
    return tuple(out)


@cache
def _classify_factor(p: Any) -> str | None:
    R = ring()
    q = R.reduce(p)
    if not q:
        return "identically zero"
    if q.is_ground:
        return "a non-zero constant"
    if _positive(q, R):
        return "a positive polynomial of x1, x2, μ (y ≥ 0)"
    gq = _gens_of(q)
    if len(q.terms()) <= 80:
        for t, why in _powers(gq):
            if len(t.terms()) == len(q.terms()) and q * t.LC == t * q.LC:
                return why
    return None


def _primitive(p: Any) -> Any:
    p = p.primitive()[1]
    return -p if p.LC < 0 else p


def classify(poly: Any) -> tuple[list[tuple[str, str]], list[str]]:
    """Split ``poly ≠ 0`` into (implied factors with reasons, extra conditions).

    Small polynomials are factored first; each factor (reduced modulo the
    relations) is compared with products of at most four sign-table entries.
    Raises ValueError if ``poly`` vanishes identically (a degenerate construction).
    """
    R = ring()
    implied: list[tuple[str, str]] = []
    extra: list[str] = []
    whole = _classify_factor(poly)
    if whole == "identically zero":
        raise ValueError(f"the condition {R.expr(poly)} ≠ 0 is false for every parameter")
    if whole is not None:
        return [(f"{R.expr(_primitive(poly))} ≠ 0", whole)], []
    factors = [f for f, _ in poly.factor_list()[1]] if len(poly.terms()) <= 40 else [poly]
    for f in factors:
        why = _classify_factor(f)
        if why == "identically zero":  # pragma: no cover - the product would reduce to 0
            raise ValueError(f"the condition {R.expr(f)} ≠ 0 is false for every parameter")
        if why is None:
            extra.append(f"{R.expr(_primitive(R.reduce(f)))} ≠ 0")
        else:
            implied.append((f"{R.expr(_primitive(f))} ≠ 0", why))
    return implied, extra
