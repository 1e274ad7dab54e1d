"""The conditions under which a file's steps and claims exist, decided one by one.

A value is kept as written: the parser collects every divisor (≠ 0), every
radicand (≥ 0) and every domain of ``tan``, ``asin``, ``acos``, ``atan2``
(:func:`graspcompass.expr.parse_with_conditions`) before sympy evaluates the
text, so ``x1*Z/(x1*Z)`` keeps ``x1*Z ≠ 0`` although its value is 1.  A step
adds the existence conditions of its operation (:func:`operation_conditions`):
a circle through two points or on a diameter needs them distinct, a line its
direction, two circles distinct centres, an intersection with a circle a
discriminant ≥ 0 (not ≠ 0: two points are made, or one when tangent).

:func:`decide` splits each condition into *implied* (shown to follow from the
domains, μ = tan ξ and condition (1) where named: an exact zero test modulo
sin² + cos² = 1, or a sign from structure, :func:`~graspcompass.proof.signs.sign_of`),
*false* (false at every point of the model: the step or claim is then REFUTED as
vacuous, never PROVED) or *extra* (listed as a condition of the result).

Examples
--------
>>> from graspcompass.symbols import x1, phi1
>>> z = sp.sin(phi1)**2 + sp.cos(phi1)**2 - 1
>>> decide([("!=", x1 * z)], cond1=False).false
['x1*(sin(phi1)**2 + cos(phi1)**2 - 1) ≠ 0']
>>> decide([(">=", -x1)], cond1=False).false
['-x1 ≥ 0']
>>> decide([("!=", x1)], cond1=False).implied
['x1 ≠ 0 (sign from the domains)']
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, Literal

import sympy as sp

from .. import symbols as S
from ..boundary.expr import Condition
from ..geometry import Circle, Line, Point
from ..geometry.exact import decide_zero
from .signs import CONDITION_1, sign_of

__all__ = ["Decided", "decide", "operation_conditions", "tie_mu"]

_WORD = {"!=": "≠ 0", ">=": "≥ 0", ">": "> 0"}
#: Intervals that hold on the domains alone (ξ is a half angle, 0 < ξ < π/2).
_DOMAIN_INTERVALS = {S.xi1: (0, sp.pi / 2), S.xi2: (0, sp.pi / 2)}
_MAX_FACTOR_NODES = 400  # factor only small conditions (a sign from the factors)


@dataclass
class Decided:
    """Conditions split into implied (with reasons), false everywhere, and extra."""

    implied: list[str] = field(default_factory=list)
    false: list[str] = field(default_factory=list)
    extra: list[str] = field(default_factory=list)

    def add(self, other: Decided) -> None:
        """Merge ``other`` into this one (order kept, no repeats)."""
        for mine, theirs in ((self.implied, other.implied), (self.false, other.false),
                             (self.extra, other.extra)):
            mine += [t for t in theirs if t not in mine]


def tie_mu(names: Iterable[str]) -> dict[sp.Symbol, sp.Expr]:
    """μi -> sin ξi / cos ξi for each contact whose μ and ξ are both declared (eq. (22))."""
    names = set(names)
    return {getattr(S, f"mu{i}"): sp.sin(getattr(S, f"xi{i}")) / sp.cos(getattr(S, f"xi{i}"))
            for i in (1, 2)
            if f"mu{i}" in names and f"xi{i}" in names}


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
    atoms = sorted(num.atoms(sp.sin, sp.cos) | den.atoms(sp.sin, sp.cos),
                   key=sp.default_sort_key)
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
            term = sp.Add(*(sp.Rational(int(v.p), int(v.q)) * sp.Mul(*(g**i for g, i in
                          zip(gens, m))) for m, v in f.to_dict().items()))
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
        q = ctx.from_dict({m: flint.fmpq(int(c.numerator), int(c.denominator))
                           for m, c in p.terms()})
        c, factors = q.factor()
        out = sp.Rational(int(c.p), int(c.q))
        for f, k in factors:
            back = R.R.from_dict({m: R.R.domain(int(v.p), int(v.q))
                                  for m, v in f.to_dict().items()})
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
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, RecursionError,
            sp.PolynomialError):
        return None
    return got


def _even_power(t: sp.Expr) -> bool:
    """``t`` is a product of even powers of real expressions (so ``t ≥ 0``)."""
    factors = sp.Mul.make_args(t)
    return bool(factors) and all(
        isinstance(f, sp.Pow) and f.exp.is_Integer and f.exp % 2 == 0
        and f.base.is_real is True for f in factors)


def _bounded_trig(t: sp.Expr) -> bool:
    """``t`` is a product of powers of sines and cosines (so ``|t| ≤ 1``)."""
    return all(isinstance(f.base if isinstance(f, sp.Pow) else f, (sp.sin, sp.cos))
               and (not isinstance(f, sp.Pow) or (f.exp.is_Integer and f.exp > 0))
               and f.free_symbols for f in sp.Mul.make_args(t))


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


def _classified(e: sp.Expr, cond1: bool) -> tuple[list[str], list[str]] | Literal[False] | None:
    """``e ≠ 0`` by the checker's classification of ring factors (the kernel's own
    conditions are stated so, in the same words): (implied, extra), False when it is
    false for every parameter, None outside the ring."""
    from .certify_algebra import _primitive, ring
    from .program_decide import _classified as split

    try:
        p = ring().frac(e)[0]
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, RecursionError):
        return None
    if not p:
        return False
    try:
        return split([_primitive(p)], cond1)
    except ValueError:
        return False


def decide(conditions: Iterable[Condition], cond1: bool,
           tie: Mapping[sp.Symbol, sp.Expr] | None = None) -> Decided:
    """Split ``(relation, expr)`` conditions into implied, false everywhere and extra.

    Parameters
    ----------
    conditions : iterable of (str, sympy.Expr)
        ``("!=", e)``: e ≠ 0; ``(">=", e)``: e ≥ 0; ``(">", e)``: e > 0.
    cond1 : bool
        Whether condition (1) of §2.2.2 may be used (the file or claim names it).
    tie : Mapping, optional
        μi -> tan ξi where a file declares both (:func:`tie_mu`).

    Returns
    -------
    Decided
        Texts ``"e ≠ 0 (reason)"`` implied, ``"e ≠ 0"`` false at every point of the
        model, ``"e ≥ 0"`` kept as conditions.
    """
    out = Decided()
    ties = tuple(sorted(tie.items(), key=str)) if tie else ()
    for rel, e in dict.fromkeys(conditions):
        for bucket, text in _decide_one(rel, sp.sympify(e), cond1, ties):
            # internal: conditions the parser and the kernel made
            mine = getattr(out, bucket)
            if text not in mine:
                mine.append(text)
    return out


@lru_cache(maxsize=4096)
def _decide_one(rel: str, e: sp.Expr, cond1: bool, ties: tuple
                ) -> tuple[tuple[str, str], ...]:
    """One condition of :func:`decide`: ``((bucket, text), ...)`` with bucket one of
    implied, false, extra.  Remembered by content: the conditions of a step recur in
    every step and claim built on it."""
    intervals = CONDITION_1 if cond1 else _DOMAIN_INTERVALS
    why = "condition (1)" if cond1 else "the domains"
    if ties:
        e = e.xreplace(dict(ties))
    z = _zero(e)

    def text() -> str:  # printed only where the answer shows it (sympy prints slowly)
        return f"{e} {_WORD[rel]}"

    if z:
        return ((("implied", text() + " (identically zero)") if rel == ">=" else
                 ("false", text())),)
    s = _sign(e, intervals)
    if s is not None:
        lo, hi = s
        holds = {"!=": lo > 0 or hi < 0, ">=": lo >= 0, ">": lo > 0}[rel]
        fails = {"!=": lo == hi == 0, ">=": hi < 0, ">": hi <= 0}[rel]
        if holds:
            return (("implied", f"{text()} (sign from {why})"),)
        if fails:  # false on the domains (or on (1)): false on the whole model
            return (("false", text()),)
    if rel in (">=", ">") and _positive_sum(-e, intervals):  # negative everywhere
        return (("false", text()),)
    if rel in (">=", ">") and _positive_sum(e, intervals):
        return (("implied", f"{text()} (a positive sum of squares and signs from {why})"),)
    if rel == "!=" and _ring_nonzero(e):
        return (("implied", f"{text()} (a positive polynomial of x1, x2, μ modulo "
                            "sin² + cos² = 1)"),)
    if rel == "!=":
        split = _classified(e, cond1)
        if split is False:
            return (("false", text()),)
        if split is not None:
            return (*(("implied", t) for t in split[0]), *(("extra", t) for t in split[1]))
    if e.is_number and not e.free_symbols and z is False:
        return (("implied", f"{text()} (a number)"),)
    return (("extra", text()),)


def _norm2(p: Point) -> sp.Expr:
    return p.x ** 2 + p.y ** 2


def _disc(line: Line, circle: Circle) -> sp.Expr:
    """The discriminant of the kernel's line-circle intersection (two points iff > 0)."""
    d = line.direction
    w = Point(line.point.x - circle.center.x, line.point.y - circle.center.y)
    a, b = d.dot(d), d.dot(w)
    return b ** 2 - a * (w.dot(w) - circle.radius2)


def _radical_axis(c1: Circle, c2: Circle) -> Line:
    n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
    h = (c1.radius2 - c2.radius2 + c2.center.dot(c2.center) - c1.center.dot(c1.center)) / 2
    k = h / n.dot(n)
    return Line(Point(n.x * k, n.y * k), Point(-n.y, n.x))


def operation_conditions(op: str, inputs: list[Any], obj: Any
                         ) -> tuple[list[Condition], list[sp.Expr]]:
    """``(conditions the operation needs, kernel conditions they replace)``.

    The kernel records what it must divide by as ``≠ 0``; an intersection with a
    circle records its discriminant, which must be ≥ 0 for the point to exist, and a
    circle, a line or a radical axis may need two points distinct that the kernel
    does not record.  Computed from the step's inputs (exact expressions).
    """
    if op in ("circle_through", "circle_on_diameter"):
        return [("!=", obj.radius2)], []
    if op == "line_through":
        return [("!=", _norm2(obj.direction))], []
    if op == "line_with_direction":
        return [("!=", _norm2(obj.direction))], []
    if op == "intersect_line_circle":
        d = _disc(inputs[0], inputs[1])
        return [(">=", d)], [d]
    if op == "intersect_circles":
        c1, c2 = inputs
        n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
        conds: list[Condition] = [("!=", _norm2(n))]
        if decide_zero(sp.sympify(_norm2(n))) is True:
            return conds, []
        d = _disc(_radical_axis(c1, c2), c1)
        return [*conds, (">=", d)], [d]
    if op == "second_intersection":
        c1, c2, _ = inputs
        n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
        return [("!=", _norm2(n))], []
    if op in ("circle_radius", "circle_compass"):
        return [("!=", obj.radius2)], []
    if op == "radical_axis":
        c1, c2 = inputs
        return [("!=", _norm2(Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)))], []
    if op == "tangent_point":
        from ..construction._ops_class import polar

        p, circle = inputs
        d = _disc(polar(p, circle), circle)
        return [(">=", d)], [d]
    return [], []


def condition_words(op: str, names: tuple[str, ...]) -> list[str]:
    """What each condition of :func:`operation_conditions` says, in geometric words
    (as GCLC prints them), in the same order."""
    a, b = (*names, "?", "?")[:2]
    return {
        "line_through": [f"{a} and {b} are distinct"],
        "line_with_direction": ["the direction is not zero"],
        "circle_through": [f"{b} is not the centre {a}"],
        "circle_on_diameter": [f"{a} and {b} are distinct"],
        "intersect_line_circle": [f"the line {a} meets the circle {b}"],
        "intersect_circles": [f"the centres of {a} and {b} differ",
                              f"the circles {a} and {b} meet"],
        "second_intersection": [f"the centres of {a} and {b} differ"],
        "circle_radius": ["the radius is not 0"],
        "circle_compass": [f"{b} and {names[2] if len(names) > 2 else '?'} are distinct"],
        "radical_axis": [f"the centres of {a} and {b} differ"],
        "tangent_point": [f"{a} is not inside the circle {b}"],
    }.get(op, [])


def distinct(a: Point, b: Point, assumed: Iterable[sp.Expr]) -> bool:
    """Proof that ``a ≠ b`` wherever the ``assumed`` expressions are non-zero and the
    lengths and friction coefficients are positive: the numerators of ``a − b``, the
    relations sin² + cos² = 1 and ``1 − t·k`` (k the product of what is non-zero) have
    the Gröbner basis [1] (Rabinowitsch), so no point makes ``a = b``.  False: no proof."""
    assumed = list(assumed)
    fast = _distinct_in_ring(a, b, assumed)
    return _distinct_general(a, b, assumed) if fast is None else fast


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
        return ctx.from_dict({(t, *m): int(c.numerator) * (den // int(c.denominator))
                              for m, c in terms})

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
        polys, ctx).buchberger_naive(limits=(400, 4000, 4096))
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
        zs, ctx).buchberger_naive(limits=(400, 4000, 4096))
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
