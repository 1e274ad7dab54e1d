"""Exact arithmetic helpers of the kernel: canonical form, zero and sign decisions.

The kernel never calls :func:`sympy.simplify`.  Every coordinate a construction
makes is passed once through :func:`canon`, which is cheap and canonical enough
for the expressions of the paper:

* a number free of symbols is put over a rationalised denominator and expanded
  (``radsimp`` then ``expand``), so that ``tan(7*pi/12)`` style quotients come
  out as ``-2 - sqrt(3)`` instead of towers of nested radicals;
* an expression with symbols is brought to one reduced fraction
  (:func:`sympy.cancel`) in its generators (``x1``, ``sin(phi1)``, ``mu1`` ...);
* an expression holding floats is evaluated to a float.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from ..expr import parse_exact

__all__ = ["Expr", "canon", "decide_sign", "decide_zero", "has_float", "sym"]

Expr = sp.Expr

#: Digits used to separate a non-zero exact number from zero before an exact test.
_PREC = 40


def sym(value: object) -> sp.Expr:
    """Return ``value`` as a sympy expression without any parsing of text.

    Python ints become :class:`sympy.Integer`, floats :class:`sympy.Float`;
    sympy expressions pass through; text is read exactly and safely by
    :func:`graspcompass.expr.parse_exact` (``"1.2"`` is 6/5).

    Examples
    --------
    >>> sym(3), sym(0.5), sym("1.2")
    (3, 0.500000000000000, 6/5)
    """
    if isinstance(value, sp.Basic):
        return value  # type: ignore[return-value]
    if isinstance(value, str):
        return parse_exact(value)
    if isinstance(value, bool):
        raise TypeError(f"expected a number or a sympy expression, got {value!r}")
    if isinstance(value, int):
        return sp.Integer(value)
    if isinstance(value, float):
        return sp.Float(value)
    try:
        return sp.sympify(value, strict=True)  # numpy scalars, Fraction
    except (sp.SympifyError, TypeError) as exc:
        raise TypeError(f"expected a number or a sympy expression, got {value!r}") from exc


def has_float(expr: sp.Expr) -> bool:
    """True when ``expr`` holds a floating-point number (the numeric path)."""
    return bool(expr.atoms(sp.Float))


def canon(expr: sp.Expr) -> sp.Expr:
    """Canonical, small form of an exact expression (no ``simplify``).

    Examples
    --------
    >>> from sympy import sqrt, pi, tan
    >>> canon((sqrt(3) + 1) / (1 - sqrt(3)))
    -2 - sqrt(3)
    >>> canon(tan(7*pi/12) * sqrt(3)/2)
    -sqrt(3) - 3/2
    >>> from sympy import symbols
    >>> a, b = symbols("a b")
    >>> canon((a**2 - b**2) / (a - b))
    a + b
    """
    expr = sym(expr)
    if expr.is_Rational or expr.is_Symbol:
        return expr
    if has_float(expr):
        return sp.Float(expr.evalf(17)) if not expr.free_symbols else sp.expand(expr)
    if expr.free_symbols:
        fast = _canon_field(expr)
        if fast is not None:
            return fast
        out = sp.cancel(sp.together(expr))
        num, den = sp.fraction(out)
        if _square_roots(den):
            out = sp.radsimp(out)
        return out
    fast = _canon_radicals(expr)
    if fast is not None:
        return fast
    num, den = sp.fraction(sp.together(expr))
    if den.is_Rational:
        return sp.expand(num) / den
    num, den = _rationalize(sp.expand(num), sp.expand(den))
    if not den.is_Rational:  # not only square roots: fall back to sympy's radsimp
        num, den = sp.fraction(sp.radsimp(num / den))
    return sp.expand(num) / sp.expand(den)


@lru_cache(maxsize=64)
def _ring(gens: tuple[sp.Expr, ...]):
    return sp.ring(gens, sp.QQ)[0]


#: Generators met so far: one growing ring keeps the memo below reusable.
_GENS: set[sp.Expr] = set()
#: Canonical expression -> (ring, numerator, denominator) of sparse polynomials.
_MEMO: dict[sp.Expr, tuple] = {}


def _generators(expr: sp.Expr) -> set[sp.Expr] | None:
    """Generators of ``expr`` as a rational function, or None if it is not one."""
    funcs = expr.atoms(sp.Function)
    if any(a.atoms(sp.Function) for f in funcs for a in f.args):
        return None
    if any(not p.exp.is_Integer for p in expr.atoms(sp.Pow)):
        return None
    inner = set().union(*(f.free_symbols for f in funcs)) if funcs else set()
    if expr.free_symbols & inner - set().union(*(f.free_symbols for f in funcs)):
        return None
    outer = {s for s in expr.free_symbols if not any(s in f.free_symbols for f in funcs)}
    if (expr.free_symbols - outer) - inner:
        return None
    return funcs | outer


def _nd(e: sp.Expr, R, index: dict) -> tuple:
    """``e`` as (numerator, denominator) in the ring R, with no gcd on the way."""
    hit = _MEMO.get(e)
    if hit is not None:
        r, n, d = hit
        return (n, d) if r is R else (n.set_ring(R), d.set_ring(R))
    if e.is_Rational:
        return R(e.p), R(e.q)
    if e in index:
        return R.gens[index[e]], R.one
    if e.is_Add or e.is_Mul:
        parts = [_nd(a, R, index) for a in e.args]
        n, d = parts[0]
        for n2, d2 in parts[1:]:
            if e.is_Mul:
                n, d = n * n2, d * d2
            elif d == d2:
                n = n + n2
            else:
                n, d = n * d2 + n2 * d, d * d2
        return n, d
    if e.is_Pow and e.exp.is_Integer:
        n, d = _nd(e.base, R, index)
        k = int(e.exp)
        if k < 0:
            n, d, k = d, n, -k
        return n**k, d**k
    raise ValueError(f"not a rational function: {e}")


def _canon_field(expr: sp.Expr) -> sp.Expr | None:
    """Reduced fraction through sympy's sparse polynomials (one gcd at the end).

    Applies to rational functions of symbols and of function atoms such as
    ``sin(phi1)``; returns None for anything else (radicals, nested functions).
    Each result is remembered, so building on earlier results stays cheap.
    """
    gens = _generators(expr)
    if not gens:
        return None
    _GENS.update(gens)
    order = tuple(sorted(_GENS, key=sp.default_sort_key))
    R = _ring(order)
    try:
        n, d = _nd(expr, R, {g: i for i, g in enumerate(order)})
    except ValueError:
        return None
    if not d:
        return None
    n, d = n.cancel(d)
    if d.LC < 0:
        n, d = -n, -d
    out = n.as_expr() / d.as_expr()
    if len(_MEMO) > 100_000:
        _MEMO.clear()
    _MEMO[out] = (R, n, d)
    return out


def _canon_radicals(expr: sp.Expr) -> sp.Expr | None:
    """Exact number in Q(√a, √b, ..., π, ...): sparse polynomials, conjugates, no radsimp.

    Square roots of rationals become ring generators tied by ``r**2 = a``;
    the denominator is cleared by multiplying with conjugates (``r -> -r``).
    Returns None for other algebraic numbers (cube roots, nested radicals).
    """
    gens: set[sp.Expr] = set()
    roots: dict[sp.Expr, sp.Expr] = {}
    for a in sp.preorder_traversal(expr):
        if a.is_Pow and not a.exp.is_Integer:
            if a.exp == sp.S.Half and a.base.is_Rational:
                gens.add(a)
                roots[a] = a.base
            else:
                return None
        elif a.is_Function or a in (sp.pi, sp.E):
            if a.is_Function and a.args and not a.args[0].is_Rational and not (
                    a.args[0].is_Mul and a.args[0].has(sp.pi)):
                return None
            gens.add(a)
    if not gens:
        return None
    order = tuple(sorted(gens, key=sp.default_sort_key))
    R = _ring(order)
    index = {g: i for i, g in enumerate(order)}
    try:
        n, d = _nd(expr, R, index)
    except ValueError:
        return None
    rels = [R.gens[index[r]] ** 2 - R(roots[r]) for r in roots]
    n, d = (n.rem(rels), d.rem(rels)) if rels else (n, d)
    if not d:
        return None
    for r in roots:
        g = R.gens[index[r]]
        if d.degree(g) > 0:
            conj = d.compose(g, -g)
            n, d = (n * conj).rem(rels), (d * conj).rem(rels)
    if d.is_ground:
        return (n.quo_ground(d.LC)).as_expr()
    n, d = n.cancel(d)
    return n.as_expr() / d.as_expr()


def _square_roots(expr: sp.Expr) -> list[sp.Pow]:
    return sorted(
        (p for p in expr.atoms(sp.Pow) if p.exp == sp.S.Half and p.base.is_Rational),
        key=sp.default_sort_key,
    )


def _rationalize(num: sp.Expr, den: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Clear square roots of rationals from ``den`` by conjugates, one root at a time.

    ``den = A + B*r`` with r a square root; multiplying by ``A - B*r`` leaves
    ``A**2 - B**2*r**2``, free of r.  Much cheaper than ``radsimp`` (which runs
    ``nsimplify``) on the quadratic fields of the paper's examples.
    """
    for _ in range(6):
        roots = _square_roots(den)
        if not roots or den.is_Rational:
            break
        r = roots[0]
        b = den.coeff(r)
        a = sp.expand(den - b * r)
        if a.has(r) or b.has(r):
            break
        num = sp.expand(num * (a - b * r))
        den = sp.expand(a**2 - b**2 * r.base)
    return num, den


def decide_zero(expr: sp.Expr, scale: float = 0.0) -> bool | None:
    """Decide whether ``expr`` is zero: True, False, or None when undecidable.

    Exact numbers are decided for certain (a high-precision evaluation proves
    non-zero, the canonical form or :meth:`sympy.Expr.equals` proves zero).
    Floats count as zero when ``|expr| <= 1e-12 * scale``: pass the magnitude of
    the quantities that ``expr`` was computed from; the default ``scale=0``
    asks for an exact zero.  Expressions with free symbols that do not reduce
    to 0, and whose sign assumptions do not settle it, are undecidable (None).

    Examples
    --------
    >>> from sympy import sqrt, Symbol
    >>> decide_zero(sqrt(6) - sqrt(2)*sqrt(3)), decide_zero(sqrt(2) - 1)
    (True, False)
    >>> decide_zero(Symbol("a")) is None
    True
    """
    expr = sym(expr)
    if expr.is_Number:
        if has_float(expr):
            return abs(float(expr)) <= 1e-12 * scale
        return bool(expr == 0)
    if expr.free_symbols:
        reduced = canon(expr)
        if reduced == 0:
            return True
        # the symbols' own assumptions may settle it, e.g. (x + 1)**2 for x > 0
        if len(reduced.args) < 40 and reduced.is_zero is False:
            return False
        return None
    if has_float(expr):
        return abs(float(expr.evalf(17))) <= 1e-12 * scale
    value = expr.evalf(_PREC)
    if value.is_Number and abs(value) > sp.Float(10) ** (-_PREC // 2):
        return False
    if canon(expr) == 0:
        return True
    eq = expr.equals(0)
    return None if eq is None else bool(eq)


def decide_sign(expr: sp.Expr) -> int | None:
    """Sign of ``expr`` as -1, 0 or +1, or None when it cannot be decided.

    Examples
    --------
    >>> from sympy import sqrt, pi
    >>> decide_sign(sqrt(3) - 2), decide_sign(pi/2 - pi/2), decide_sign(sqrt(2))
    (-1, 0, 1)
    """
    expr = sym(expr)
    zero = decide_zero(expr)
    if zero:
        return 0
    if expr.free_symbols:
        if expr.is_positive:
            return 1
        if expr.is_negative:
            return -1
        return None
    value = expr.evalf(_PREC)
    if not value.is_Number:
        return None
    return 1 if value > 0 else -1
