"""Sympy expressions as sparse polynomial fractions over Q (the converter of :mod:`.reduce`).

Two passes: the first collects the atoms (angles inside sin/cos/tan, square
roots, symbols, other function atoms), which fixes the generators and their
lexicographic order (roots first, outer before inner; sines; the rest; cosines);
the second converts bottom-up to ``(numerator, denominator)`` pairs, recording
every denominator it meets.  No gcd, no ``expand`` of sympy trees, no
``simplify``: ``sin(24*phi)`` costs 24 ring multiplications.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import sympy as sp

from .. import symbols as S
from ..boundary.errors import GraspCompassError
from ..geometry.exact import fold_fractions

__all__ = ["DegenerateClaimError", "RingForm", "poly_json", "to_ring"]


class DegenerateClaimError(GraspCompassError):
    """An expression with a denominator that vanishes identically: 0/0 or undefined everywhere."""


def poly_json(p: Any) -> list[list[Any]]:
    """A sparse polynomial as JSON: ``[["p/q", [exponents...]], ...]`` (sorted)."""
    return sorted(
        ([f"{int(c.numerator)}/{int(c.denominator)}", list(m)] for m, c in p.terms()),
        key=lambda t: t[1],
    )


# documented and pickled with the reductions that raise it (no import cycle: issue 21)
DegenerateClaimError.__module__ = "graspcompass.proof.reduce"

_MU = {S.mu1: S.xi1, S.mu2: S.xi2}
_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def _linear(arg: sp.Expr) -> tuple[sp.Expr, dict[sp.Symbol, int]]:
    """``arg`` as ``k*pi + sum(n_a * a)`` with rational k and integer n_a."""
    k: sp.Expr = sp.Integer(0)
    coeffs: dict[sp.Symbol, int] = {}
    for term in sp.Add.make_args(sp.expand(arg)):
        c, rest = term.as_coeff_Mul()
        if rest == sp.pi and c.is_Rational:
            k += c
        elif rest.is_Symbol and c.is_Integer:
            coeffs[rest] = coeffs.get(rest, 0) + int(c)
        elif term.is_Rational and term == 0:
            continue
        else:
            raise ValueError(
                f"cannot reduce a sine or cosine of {arg}: its argument is not "
                "an integer combination of angle symbols plus a rational "
                "multiple of pi"
            )
    return k, {a: n for a, n in coeffs.items() if n}


def _const_sc(k: sp.Expr) -> tuple[sp.Expr, sp.Expr] | None:
    """Exact sin, cos of k*pi when they are rational or sums of square roots of rationals."""
    s, c = sp.sin(k * sp.pi), sp.cos(k * sp.pi)
    for v in (s, c):
        if not sp.fraction(sp.together(v))[1].is_Rational:
            return None
        for a in sp.preorder_traversal(v):
            if (
                a.is_Pow
                and not a.exp.is_Integer
                and not (a.exp == sp.S.Half and a.base.is_Rational)
            ):
                return None
            if a.is_Function:
                return None
    return s, c


@dataclass
class RingForm:
    """Expressions converted into one lex polynomial ring, with the relations that tie it."""

    ring: Any
    gens: list[sp.Expr]
    names: list[str]
    pairs: list[tuple[str, int, int]]  # (angle, index of sin, index of cos)
    roots: list[tuple[int, Any, sp.Expr]]  # (index of w, radicand polynomial, sqrt expr)
    relations: list[Any]
    values: list[tuple[Any, Any]] = field(default_factory=list)
    denominators: list[list[Any]] = field(default_factory=list)

    def as_expr(self, p: Any) -> sp.Expr:
        """The polynomial ``p`` as a sympy expression (roots written as ``sqrt``)."""
        if not hasattr(p, "as_expr"):
            return sp.sympify(p)  # internal: a ground number
        return p.as_expr(*self._back)

    @cached_property
    def _back(self) -> tuple[sp.Expr, ...]:
        """The expression of each generator (a root's ``w`` as its ``sqrt``), in order:
        :meth:`as_expr` writes them in directly instead of substituting afterwards."""
        back = [*self.ring.symbols] if self.gens else [sp.Integer(1)]
        for i, g in enumerate(self.gens):
            back[i] = g
        for i, _, r in self.roots:
            back[i] = r
        return tuple(back)

    def describe_relations(self) -> str:
        """The relations in words."""
        parts = [f"sin({a})**2 + cos({a})**2 - 1" for a, _, _ in self.pairs]
        parts += [f"{self.names[i]}**2 - ({self.as_expr(p)})" for i, p, _ in self.roots]
        return ", ".join(parts) or "nothing"

    def certificate(self, num: Any, quotients: list[Any]) -> dict[str, Any]:
        """``num = sum q_i rel_i`` as JSON-ready data (see :mod:`.recheck`)."""
        rels = [{"kind": "pythagoras", "angle": a, "sin": i, "cos": j} for a, i, j in self.pairs]
        rels += [{"kind": "root", "var": i, "radicand": poly_json(p)} for i, p, _ in self.roots]
        for r, p in zip(rels, self.relations):
            r["poly"] = poly_json(p)
        return {
            "vars": list(self.names),
            "relations": rels,
            "numerator": poly_json(num),
            "cofactors": [poly_json(q) for q in quotients],
        }


class _Scan:
    def __init__(self) -> None:
        self.angles: set[sp.Symbol] = set()
        self.roots: dict[sp.Expr, sp.Expr] = {}  # sqrt atom -> base
        self.atoms: set[sp.Expr] = set()
        self.const_pairs: set[sp.Expr] = set()  # k with sin(k pi) kept as a variable
        self.seen: set[sp.Expr] = set()

    def walk(self, e: sp.Expr) -> None:
        if e in self.seen:
            return
        self.seen.add(e)
        if e.is_Rational:
            return
        if e.is_Float:
            raise ValueError(f"a floating-point number ({e}) cannot be reduced exactly")
        if e.is_Symbol or e.is_NumberSymbol or e is sp.I:
            self.atoms.add(e)
        elif isinstance(e, _TRIG):
            k, coeffs = _linear(e.args[0])
            self.angles.update(coeffs)
            if k:
                sc = _const_sc(k)
                if sc is None:
                    self.const_pairs.add(k)
                else:
                    self.walk(sc[0])
                    self.walk(sc[1])
        elif e.is_Add or e.is_Mul:
            for a in e.args:
                self.walk(a)
        elif e.is_Pow and e.exp.is_Integer:
            self.walk(e.base)
        elif e.is_Pow and e.exp.is_Rational and e.exp.q == 2:
            self.roots[sp.sqrt(e.base)] = e.base
            self.walk(e.base)
        elif e.is_Pow:
            raise ValueError(f"cannot reduce {e}: only integer powers and square roots")
        elif e.is_Atom or e.is_Function:
            self.atoms.add(e)
        else:
            raise ValueError(f"cannot reduce {e} ({type(e).__name__})")


def to_ring(exprs: list[sp.Expr]) -> RingForm:
    """Convert ``exprs`` into one ring; ``values[i]`` is (numerator, denominator) of expr i."""
    sc = _Scan()
    for e in exprs:
        sc.walk(e)
    atoms = set(sc.atoms)
    mus = {mu: xi for mu, xi in _MU.items() if mu in atoms and (xi in sc.angles or xi in atoms)}
    angles = set(sc.angles) | set(mus.values())
    atoms -= set(mus)
    depth = {
        r: sum(1 for a in sp.preorder_traversal(b) if a in sc.roots) for r, b in sc.roots.items()
    }
    roots = sorted(sc.roots, key=lambda r: (-depth[r], sp.default_sort_key(r)))
    pair_keys: list[tuple[str, sp.Expr, sp.Expr]] = [
        (str(a), sp.sin(a), sp.cos(a)) for a in sorted(angles, key=sp.default_sort_key)
    ]
    pair_keys += [
        (f"{k}*pi", sp.Symbol(f"sin({k}*pi)"), sp.Symbol(f"cos({k}*pi)"))
        for k in sorted(sc.const_pairs, key=sp.default_sort_key)
    ]
    others = sorted(atoms, key=sp.default_sort_key)
    taken = {str(a) for a in others} | {str(p[1]) for p in pair_keys}
    wnames = []
    for i in range(len(roots)):
        n = f"w{i}"
        while n in taken:
            n = "_" + n
        wnames.append(n)
    gens: list[sp.Expr] = [*roots, *(p[1] for p in pair_keys), *others, *(p[2] for p in pair_keys)]
    names = [*wnames, *(str(g) for g in gens[len(roots) :])]
    R = (
        sp.ring([sp.Dummy(n) for n in wnames] + gens[len(roots) :], sp.QQ, sp.lex)[0]
        if gens
        else sp.ring([sp.Dummy("one")], sp.QQ, sp.lex)[0]
    )
    index = {g: i for i, g in enumerate(gens) if i >= len(roots)}
    pairs = [(a, index[s], index[c]) for a, s, c in pair_keys]
    conv = _Converter(
        R,
        index,
        mus,
        {
            k: (R.gens[index[s]], R.gens[index[c]])
            for (_, s, c), k in zip(
                pair_keys[len(angles) :], sorted(sc.const_pairs, key=sp.default_sort_key)
            )
        },
    )
    conv.angle_sc = {a: (R.gens[index[sp.sin(a)]], R.gens[index[sp.cos(a)]]) for a in angles}
    root_rels: list[Any] = []
    for i in reversed(range(len(roots))):  # inner roots first: outer radicands use them
        n, d = conv.nd(sc.roots[roots[i]])
        conv.root_info[roots[i]] = (R.gens[i], d)
        root_rels.insert(0, (i, n * d, roots[i]))
    relations = [R.gens[i] ** 2 + R.gens[j] ** 2 - 1 for _, i, j in pairs]
    relations = [R.gens[i] ** 2 - p for i, p, _ in root_rels] + relations
    form = RingForm(R, gens, names, pairs, root_rels, relations)
    # the order of the relations in the certificate: pairs first, then roots
    form.relations = relations[len(root_rels) :] + relations[: len(root_rels)]
    for e in exprs:
        conv.dens = []
        form.values.append(conv.nd(e))
        form.denominators.append(list(conv.dens))
    return form


class _Converter:
    def __init__(self, R: Any, index: dict, mus: dict, const: dict) -> None:
        self.R, self.index, self.mus, self.const = R, index, mus, const
        self.angle_sc: dict[sp.Symbol, tuple[Any, Any]] = {}
        self.root_info: dict[sp.Expr, tuple[Any, Any]] = {}
        self.memo: dict[sp.Expr, tuple[Any, Any, tuple]] = {}
        self.multiples: dict[tuple[sp.Symbol, int], tuple[Any, Any]] = {}
        self.dens: list[Any] = []

    def _den(self, d: Any, e: sp.Expr) -> None:
        if not d:
            raise DegenerateClaimError(f"{e} divides by zero")
        if not d.is_ground:
            self.dens.append(d)

    def nd(self, e: sp.Expr) -> tuple[Any, Any]:
        hit = self.memo.get(e)
        if hit is not None:
            self.dens.extend(hit[2])
            return hit[0], hit[1]
        start = len(self.dens)
        n, d = self._nd(e)
        self.memo[e] = (n, d, tuple(self.dens[start:]))
        return n, d

    def _nd(self, e: sp.Expr) -> tuple[Any, Any]:
        R = self.R
        if e.is_Rational:
            return R(e.p), R(e.q)
        if e in self.mus:
            s, c = self.angle_sc[self.mus[e]]
            self._den(c, e)
            return s, c
        if e in self.index:
            return R.gens[self.index[e]], R.one
        if isinstance(e, _TRIG):
            s, c = self._sin_cos(e.args[0])
            n, d = {
                sp.sin: (s, R.one),
                sp.cos: (c, R.one),
                sp.tan: (s, c),
                sp.cot: (c, s),
                sp.sec: (R.one, c),
                sp.csc: (R.one, s),
            }[type(e)]
            self._den(d, e)
            return n, d
        if e.is_Add or e.is_Mul:
            return fold_fractions([self.nd(a) for a in e.args], multiply=e.is_Mul)
        if e.is_Pow and e.exp.is_Integer:
            n, d = self.nd(e.base)
            k = int(e.exp)
            if k < 0:
                self._den(n, e)
                n, d, k = d, n, -k
            return n**k, d**k
        if e.is_Pow and e.exp.is_Rational and e.exp.q == 2:
            w, d = self.root_info[sp.sqrt(e.base)]
            self.nd(e.base)  # records the radicand's own denominators
            k = int(e.exp.p)
            if k < 0:
                self._den(w, e)
                return d ** (-k), w ** (-k)
            return w**k, d**k
        raise ValueError(f"cannot reduce {e}")

    def _multiple(self, a: sp.Symbol, n: int) -> tuple[Any, Any]:
        key = (a, n)
        if key not in self.multiples:
            s1, c1 = self.angle_sc[a]
            if n == 1:
                self.multiples[key] = (s1, c1)
            else:
                s, c = self._multiple(a, n - 1)
                self.multiples[key] = (s * c1 + c * s1, c * c1 - s * s1)
        return self.multiples[key]

    def _sin_cos(self, arg: sp.Expr) -> tuple[Any, Any]:
        k, coeffs = _linear(arg)
        R = self.R
        if not k:
            s, c = R.zero, R.one
        elif k in self.const:
            s, c = self.const[k]
        else:
            cs = _const_sc(k)
            assert cs is not None
            (sn, sd), (cn, cd) = self.nd(cs[0]), self.nd(cs[1])
            s, c = sn.quo_ground(sd.LC), cn.quo_ground(cd.LC)  # sums of roots over rationals
        for a, n in coeffs.items():
            sa, ca = self._multiple(a, abs(n))
            if n < 0:
                sa = -sa
            s, c = s * ca + c * sa, c * ca - s * sa
        return s, c
