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
from math import comb
from typing import Any

import sympy as sp

from .. import symbols as S
from ._flint import factor_list
from .prove import CONDITION_1, sign_of
from .reduce import reduce_expr

__all__ = ["Ring", "classify", "ring"]

_ANGLES = (S.phi1, S.phi2, S.xi1, S.xi2)
_POSITIVE = {S.x1, S.x2, S.mu1, S.mu2}
_NONNEG = _POSITIVE | {S.y}


def _expand_trig(expr: sp.Expr) -> sp.Expr:
    """sin, cos, tan of sums and multiples of angles as polynomials in sin a, cos a."""
    repl = {}
    for f in expr.atoms(sp.sin, sp.cos, sp.tan):
        if isinstance(f, sp.tan):
            a = f.args[0]
            repl[f] = sp.expand_trig(sp.sin(a)) / sp.expand_trig(sp.cos(a))
        elif not f.args[0].is_Symbol:
            repl[f] = sp.expand_trig(f)
    return expr.xreplace(repl) if repl else expr


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
        self._cache: dict[Any, tuple[Any, dict[Any, int]]] = {}

    def nd(self, expr: Any) -> tuple[Any, Any]:
        """``expr`` as (numerator, denominator) in the ring; ValueError if it is not one."""
        n, dens = self.frac(expr)
        d = self.R.one
        for f, k in dens.items():
            d = d * f**k
        return n, d

    def frac(self, expr: Any) -> tuple[Any, dict[Any, int]]:
        """``expr`` as (numerator, {denominator factor: multiplicity}).

        Denominators stay factored (each factor primitive with a positive leading
        coefficient), so adding fractions multiplies only by the missing factors.
        """
        expr = sp.sympify(expr)  # internal: expressions of the certifier
        hit = self._cache.get(expr)
        if hit is None:
            hit = self._frac(expr)
            self._cache[expr] = hit
        return hit

    def _factor(self, p: Any) -> tuple[Any, Any]:
        """``p = c·q`` with q primitive, leading coefficient > 0: (c, q)."""
        c, q = p.primitive()
        if q.LC < 0:
            c, q = -c, -q
        return c, q

    def _frac(self, e: sp.Expr) -> tuple[Any, dict[Any, int]]:
        hit = self._cache.get(e)
        if hit is not None:
            return hit
        R = self.R
        out: tuple[Any, dict[Any, int]]
        if e.is_Rational:
            out = R(e), {}
        elif e in self.index:
            out = R.gens[self.index[e]], {}
        elif e.is_Add and (flat := self._flat_sum(e)) is not None:
            out = flat, {}
        elif e.is_Mul:
            n = R.one
            dens: dict[Any, Any] = {}
            for a in e.args:
                n2, d2 = self._frac(a)
                n = n * n2
                for f, k in d2.items():
                    dens[f] = dens.get(f, 0) + k
            out = n, dens
        elif e.is_Add:
            parts = [self._frac(a) for a in e.args]
            dens = {}
            for _, d2 in parts:
                for f, k in d2.items():
                    dens[f] = max(dens.get(f, 0), k)
            n = R.zero
            for n2, d2 in parts:
                for f, k in dens.items():
                    if k > d2.get(f, 0):
                        n2 = n2 * f ** (k - d2.get(f, 0))
                n = n + n2
            out = n, dens
        elif e.is_Pow and e.exp.is_Integer:
            n, dens = self._frac(e.base)
            k = int(e.exp)
            if k >= 0:
                out = n**k, {f: m * k for f, m in dens.items()}
            else:
                if not n:
                    raise ValueError(f"division by zero in {e}")
                c, q = self._factor(n)
                num = R.one
                for f, m in dens.items():
                    num = num * f ** (m * -k)
                num = num * R.domain.quo(R.domain.one, c) ** (-k)
                out = num, ({q: -k} if not q.is_ground else {})
                if q.is_ground:
                    out = num * R.domain.quo(R.domain.one, q.LC) ** (-k), {}
        elif isinstance(e, (sp.sin, sp.cos, sp.tan)) and (t := _expand_trig(e)) != e:
            out = self._frac(t)
        else:
            raise ValueError(f"not a rational function of the model's generators: {e}")
        self._cache[e] = out
        return out

    def _flat_sum(self, e: sp.Expr) -> Any:
        """An expanded polynomial in one pass (None if a term is not a monomial)."""
        index = self.index
        acc: dict[Any, Any] = {}
        dom = self.R.domain
        zero = [0] * len(self.gens)
        for term in e.args:
            c, factors = term.as_coeff_mul()
            if not c.is_Rational:
                return None
            mon = zero.copy()
            for f in factors:
                base, k = (f.base, f.exp) if f.is_Pow else (f, sp.S.One)
                i = index.get(base)
                if i is None or not (k == 1 or (k.is_Integer and k > 0)):
                    return None
                mon[i] += int(k)
            key = tuple(mon)
            acc[key] = acc.get(key, dom.zero) + dom.convert(c)
        return self.R.from_dict({m: c for m, c in acc.items() if c})

    def reduce(self, p: Any) -> Any:
        """The normal form of ``p`` modulo sin² + cos² − 1 (sin^2k → (1 − cos²)^k).

        The relations are a Gröbner basis with leading terms sin², so this
        normal form (every sin of degree ≤ 1) is the remainder of the division.
        """
        if not p:
            return p
        acc: dict[tuple[int, ...], Any] = {}
        for mon, co in p.items():
            terms = [(list(mon), co)]
            for si in range(4):
                e = mon[si]
                if e < 2:
                    continue
                j, r = divmod(e, 2)
                new = []
                for m, cc in terms:
                    for k in range(j + 1):
                        m2 = m.copy()
                        m2[si], m2[si + 4] = r, m[si + 4] + 2 * k
                        new.append((m2, cc * (-1) ** k * comb(j, k)))
                terms = new
            for m, cc in terms:
                key = tuple(m)
                acc[key] = acc.get(key, 0) + cc
        return self.R.from_dict({m: c for m, c in acc.items() if c})

    def equal(self, lhs: Any, rhs: Any) -> tuple[bool, list[Any]]:
        """(lhs − rhs reduces to 0, the denominator factors assumed non-zero)."""
        n1, d1 = self.frac(lhs)
        n2, d2 = self.frac(rhs)
        dens = {f: max(d1.get(f, 0), d2.get(f, 0)) for f in {*d1, *d2}}
        for f, k in dens.items():
            if k > d1.get(f, 0):
                n1 = n1 * f ** (k - d1.get(f, 0))
            if k > d2.get(f, 0):
                n2 = n2 * f ** (k - d2.get(f, 0))
        return not self.reduce(n1 - n2), list(dens)

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
            (cx, cx, f"cos ξ{i}"),
            (sx, sx, f"sin ξ{i}"),
            (s, s, f"sin φ{i}"),
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


def _text(p: Any, most: int = 60) -> str:
    """``p`` as text; a polynomial of more than ``most`` terms by its first terms and its
    size."""
    R = ring()
    if len(p.terms()) <= most:
        return _full_text(p)
    head = R.R.from_dict(dict(p.terms()[:3]))
    return f"{R.expr(head)} + … ({len(p.terms())} terms, degree {sum(p.LM)})"


def _full_text(p: Any) -> str:
    """``p`` as text, whole (remembered: the same factors recur in many steps, and sympy's
    printer is slow on long sums)."""
    try:
        return _TEXTS[p]
    except KeyError:
        if len(_TEXTS) > 4096:
            _TEXTS.clear()
        text = _TEXTS[p] = str(ring().expr(p))
        return text
    except TypeError:  # pragma: no cover - an unhashable element
        return str(ring().expr(p))


_TEXTS: dict[Any, str] = {}


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
        raise ValueError(f"the condition {_text(poly)} ≠ 0 is false for every parameter")
    if whole is not None:
        return [(f"{_text(_primitive(poly))} ≠ 0", whole)], []
    factors = [f for f, _ in factor_list(poly)[1]] if len(poly.terms()) <= 40 else [poly]
    for f in factors:
        why = _classify_factor(f)
        if why == "identically zero":  # pragma: no cover - the product would reduce to 0
            raise ValueError(f"the condition {R.expr(f)} ≠ 0 is false for every parameter")
        if why is None:
            extra.append(f"{_text(_primitive(R.reduce(f)))} ≠ 0")
        else:
            implied.append((f"{_text(_primitive(f))} ≠ 0", why))
    return implied, extra
