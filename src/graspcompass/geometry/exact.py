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

import math
from functools import cmp_to_key, lru_cache

import sympy as sp

from ..expr import parse_exact

__all__ = ["Expr", "approx", "canon", "clear_caches", "decide_sign", "decide_zero",
           "fold_fractions", "has_float", "sym", "text"]

Expr = sp.Expr

_ADD_ORDER = cmp_to_key(sp.Basic.compare)  # the order of sympy's Add arguments

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


def text(expr: object) -> str:
    """``str(expr)`` in sympy's own term order, without its numeric sorting of terms.

    The default printer sorts the terms of a sum of numbers by evaluating each one,
    which is slow for long exact sums; this text is the same for equal canonical
    forms.

    Examples
    --------
    >>> text(sp.sqrt(3) / 2 + 1)
    'sqrt(3)/2 + 1'
    """
    if not isinstance(expr, sp.Basic):
        return str(expr)
    if expr.free_symbols or not expr.has(sp.sin, sp.cos, sp.atan):
        return str(expr)  # small radicals and symbols: sympy's usual order
    return sp.sstr(expr, order="none")


def has_float(expr: sp.Expr) -> bool:
    """True when ``expr`` holds a floating-point number (the numeric path)."""
    return bool(expr.atoms(sp.Float))


def canon(expr: sp.Expr) -> sp.Expr:
    """Canonical, small form of an exact expression (no ``simplify``).

    Numbers and symbolic expressions alike become one reduced fraction of
    sparse polynomials in their generators (symbols, ``sqrt(p)`` for primes p,
    ``sin(a)`` and ``cos(a)`` of each angle, other atoms), with the numerator
    and denominator reduced modulo ``sqrt(p)**2 = p`` and
    ``sin(a)**2 + cos(a)**2 = 1`` and square roots cleared from the denominator
    by conjugates.

    Examples
    --------
    >>> from sympy import sqrt, pi, tan, sin, cos, symbols
    >>> canon((sqrt(3) + 1) / (1 - sqrt(3)))
    -2 - sqrt(3)
    >>> canon(tan(7*pi/12) * sqrt(3)/2)
    -sqrt(3) - 3/2
    >>> a, b = symbols("a b")
    >>> canon((a**2 - b**2) / (a - b))
    a + b
    >>> canon(sin(a)**2 + cos(a)**2 - 1), canon(sqrt(6) - sqrt(2)*sqrt(3))
    (0, 0)
    """
    expr = sym(expr)
    if expr.is_Rational or expr.is_Symbol or expr in _MEMO:  # memo keys are canonical
        return expr
    if has_float(expr):
        return sp.Float(expr.evalf(17)) if not expr.free_symbols else sp.expand(expr)
    fast = _canon_ring(expr)
    if fast is not None:
        return fast
    if expr.free_symbols:
        return sp.cancel(sp.together(expr))
    num, den = sp.fraction(sp.together(expr))
    if den.is_Rational:
        return sp.expand(num) / den
    num, den = _rationalize(sp.expand(num), sp.expand(den))
    return sp.expand(num) / sp.expand(den)


@lru_cache(maxsize=4096)
def _ring(gens: tuple[sp.Expr, ...]):
    return sp.ring(gens, sp.QQ, sp.lex)[0]


#: Generators met so far: one growing ring keeps the memo below reusable.
_GENS: set[sp.Expr] = set()
#: Canonical expression -> (ring, numerator, denominator) of sparse polynomials.
_MEMO: dict[sp.Expr, tuple] = {}
_MAX_GENS = 80


def clear_caches() -> None:
    """Forget the generators and memoised canonical forms (for benchmarks and tests)."""
    _GENS.clear()
    _MEMO.clear()
    from . import trig

    _ring.cache_clear()
    _atom_plan.cache_clear()
    _positions.cache_clear()
    _gen_interval.cache_clear()
    _gen_ball.cache_clear()
    _gen_float.cache_clear()
    _relations.cache_clear()
    _has_opaque.cache_clear()
    _root_primes.cache_clear()
    _SQRT.clear()
    trig.sincos.cache_clear()
    trig._reference.cache_clear()


#: Trial division bound of :func:`_square_free`, sympy's own for ``sqrt`` of an integer.
_TRIAL = 2**15


@lru_cache(maxsize=1)
def _small_primes() -> tuple[int, ...]:
    return tuple(sp.primerange(2, _TRIAL))


def _square_free(r: sp.Rational) -> tuple[sp.Rational, tuple[int, ...]]:
    """``sqrt(r) = coefficient * prod(sqrt(p))`` over distinct factors p.

    The factors are the primes below 2**15 and, if a part of the radicand is left
    that is no square, that part as one factor: it is never factored further, so a
    radicand of any size is split at once (a large cofactor is not always prime,
    which only costs uniqueness of the form, never correctness: ``sqrt(c)`` keeps
    its relation ``sqrt(c)**2 = c``).
    """
    n = int(r.p) * int(r.q)
    k, factors = 1, []
    for p in _small_primes():
        if p * p > n:
            break
        if n % p:
            continue
        e = 0
        while n % p == 0:
            n //= p
            e += 1
        k *= p ** (e // 2)
        if e % 2:
            factors.append(p)
    if n > 1:
        root = math.isqrt(n)
        if root * root == n:
            k *= root
        else:
            factors.append(n)
    return sp.Rational(k, int(r.q)), tuple(sorted(factors))


_TRIG = (sp.sin, sp.cos, sp.tan)


@lru_cache(maxsize=8192)
def _atom_plan(atom: sp.Expr) -> tuple | None:
    """How an atom enters the ring: ("root", coefficient, primes), ("trig", kind, s, c, value)
    or ("gen",); None when it cannot (a negative radicand, ``I``)."""
    if atom.is_Pow:
        if atom.exp == sp.S.Half and atom.base.is_Rational:
            if atom.base < 0:
                return None
            coefficient, primes = _square_free(atom.base)
            return ("root", coefficient, primes)
        return ("gen",)  # cube roots, nested radicals: opaque generators
    if isinstance(atom, _TRIG):
        arg = atom.args[0]
        if arg.is_number and not arg.free_symbols:
            from .trig import OpaqueCos, OpaqueSin, sincos

            s, c = sincos(arg)
            if isinstance(s, OpaqueSin) and isinstance(c, OpaqueCos) and s.args == c.args:
                pair = (s, c)
            else:  # a reference angle, or radicals: the value stands for the atom
                value = s if isinstance(atom, sp.sin) else c if isinstance(atom, sp.cos) else s / c
                if value == atom:
                    return ("gen",)
                return ("value", value)
        elif isinstance(atom, sp.tan):
            return ("gen",)  # tan of a symbol (mu = tan xi): one generator, fewer variables
        else:
            pair = (sp.sin(arg), sp.cos(arg))
        kind = "sin" if isinstance(atom, sp.sin) else "cos" if isinstance(atom, sp.cos) else "tan"
        return ("trig", kind, *pair)
    if atom is sp.I or atom.is_Float:
        return None
    return ("gen",)


def _collect(expr: sp.Expr, atoms: dict, roots: set, pairs: set) -> bool:
    """Walk ``expr``; record its atoms' plans, the primes under roots, the trig pairs."""
    stack = [expr]
    while stack:
        a = stack.pop()
        if a.is_Rational or a in atoms:
            continue
        if a.is_Add or a.is_Mul or (a.is_Pow and a.exp.is_Integer):
            stack.extend(a.args)
            continue
        plan = _atom_plan(a)
        if plan is None:
            return False
        atoms[a] = plan
        if plan[0] == "root":
            roots.update(plan[2])
        elif plan[0] == "trig":
            pairs.add(plan[2:4])
        elif plan[0] == "value":
            stack.append(plan[1])
    return True


def fold_fractions(parts: list[tuple], multiply: bool) -> tuple:
    """The sum or product of fractions ``(n, d)`` of ring elements, with no gcd taken.

    Equal denominators are added without multiplying them; the kernel's canonical
    form and the proof checker's reduction both build their fractions with it.

    Examples
    --------
    >>> R, a = sp.ring("a", sp.QQ)
    >>> fold_fractions([(a, R(2)), (R(1), R(2))], multiply=False)
    (a + 1, 2)
    >>> fold_fractions([(a, R(2)), (R(1), a)], multiply=True)
    (a, 2*a)
    """
    n, d = parts[0]
    for n2, d2 in parts[1:]:
        if multiply:
            n, d = n * n2, d * d2
        elif d == d2:
            n = n + n2
        else:
            n, d = n * d2 + n2 * d, d * d2
    return n, d


def _convert(e: sp.Expr, R, amap: dict) -> tuple:
    """``e`` as (numerator, denominator) in R, atoms mapped by ``amap``, no gcd."""
    hit = _MEMO.get(e)
    if hit is not None:
        r, n, d = hit
        return (n, d) if r is R else (_lift(n, r, R), _lift(d, r, R))
    if e.is_Rational:
        return R(e.p), R(e.q)
    m = amap.get(e)
    if m is not None:
        return m
    if e.is_Add or e.is_Mul:
        return fold_fractions([_convert(a, R, amap) for a in e.args], multiply=e.is_Mul)
    if e.is_Pow and e.exp.is_Integer:
        n, d = _convert(e.base, R, amap)
        k = int(e.exp)
        if k < 0:
            n, d, k = d, n, -k
        return n**k, d**k
    raise ValueError(f"not a rational function of its atoms: {e}")


@lru_cache(maxsize=1024)
def _positions(r, R) -> tuple[int, ...] | None:
    """Where each generator of ring r sits in ring R (None if one is missing)."""
    index = {g: i for i, g in enumerate(R.symbols)}
    try:
        return tuple(index[g] for g in r.symbols)
    except KeyError:
        return None


def _lift(p, r, R):
    """The polynomial p of ring r as an element of R, whose generators include r's."""
    pos = _positions(r, R)
    if pos is None:
        return p.set_ring(R)
    k = R.ngens
    out = {}
    for monom, coeff in p.items():
        m = [0] * k
        for i, e in zip(pos, monom):
            m[i] = e
        out[tuple(m)] = coeff
    return R.dtype(out)


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


def _canon_ring(expr: sp.Expr) -> sp.Expr | None:
    """One reduced fraction in the growing ring of generators (see :func:`canon`)."""
    atoms: dict = {}
    primes: set[int] = set()
    pairs: set = set()
    if not _collect(expr, atoms, primes, pairs):
        return None
    roots = {sp.sqrt(p) for p in primes}
    sines = {s for s, _ in pairs}
    gens = roots | sines | {c for _, c in pairs}
    gens |= {a for a, plan in atoms.items() if plan[0] == "gen"}
    if not gens:
        return None
    _GENS.update(gens)
    order = tuple(sorted(gens, key=_gen_key))  # this expression's own generators
    R = _ring(order)
    index = {g: R.gens[i] for i, g in enumerate(order)}
    amap: dict = {g: (index[g], R.one) for g in gens}
    for a, plan in atoms.items():
        if plan[0] == "root":
            coefficient, ps = plan[1], plan[2]
            n = R(coefficient.p)
            for p in ps:
                n *= index[sp.sqrt(p)]
            amap[a] = (n, R(coefficient.q))
    for a, plan in atoms.items():  # after the roots: values may hold roots
        if plan[0] == "trig":
            s, c = index[plan[2]], index[plan[3]]
            amap[a] = {"sin": (s, R.one), "cos": (c, R.one), "tan": (s, c)}[plan[1]]
        elif plan[0] == "value":
            amap[a] = _convert(plan[1], R, amap)
    try:
        n, d = _convert(expr, R, amap)
    except ValueError:
        return None
    return _finish(R, n, d)


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


_U = 2.0**-53  # unit roundoff of IEEE double


@lru_cache(maxsize=4096)
def _gen_float(g: sp.Expr) -> float | None:
    """A double within one unit roundoff of the numeric generator ``g``, or None."""
    from mpmath import iv

    prec = iv.prec
    iv.prec = _IV_PREC
    try:
        v = _gen_interval(g)
    except TypeError:
        return None
    finally:
        iv.prec = prec
    lo, hi = float(v.a), float(v.b)
    m = (lo + hi) / 2
    if not math.isfinite(m) or m == 0 or hi - lo > abs(m) * _U:
        return None
    return m


def _float_sign(poly) -> int | None:
    """The sign of the number ``poly`` by a floating-point filter, or None.

    Each term is evaluated in doubles by repeated multiplication (generators
    within one unit roundoff u, coefficients correctly rounded); a term of degree
    D is then within (1.5 D + 1) u of its value and the sum of N terms adds at
    most N u of the sum of magnitudes M.  A computed sum beyond twice that bound,
    ``2 (2 D_max + N + 2) u M``, has the sign of the exact value (the usual
    static filter of exact geometric predicates); anything closer returns None and
    the caller falls back to interval arithmetic.
    """
    symbols = poly.ring.symbols
    values: dict[int, float] = {}
    total = magnitude = 0.0
    dmax = count = 0
    try:
        for monom, coeff in poly.terms():
            t = int(coeff.numerator) / int(coeff.denominator)
            degree = 0
            for i, e in enumerate(monom):
                if not e:
                    continue
                v = values.get(i)
                if v is None:
                    v = _gen_float(symbols[i])
                    if v is None:
                        return None
                    values[i] = v
                for _ in range(e):
                    t *= v
                degree += e
            total += t
            magnitude += abs(t)
            dmax = max(dmax, degree)
            count += 1
    except OverflowError:
        return None
    if not math.isfinite(magnitude) or magnitude < 1e-280:
        return None
    bound = 2.0 * (2 * dmax + count + 2) * _U * magnitude
    if total > bound:
        return 1
    if total < -bound:
        return -1
    return None


def _clearly_nonzero(poly) -> bool:
    """True when a float filter or interval arithmetic (200 bits) shows ``poly`` is not 0."""
    from mpmath import iv

    if _float_sign(poly) is not None:
        return True

    prec = iv.prec
    iv.prec = _IV_PREC
    try:
        (value,) = _intervals(poly)
    except TypeError:
        return False
    finally:
        iv.prec = prec
    return bool(value.a > 0 or value.b < 0)


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

    Exact numbers are decided for certain: a 40-digit evaluation proves a
    non-zero value; a zero canonical form (:func:`canon`) proves zero; the rare
    tiny number whose canonical form is not 0 is settled exactly in a
    cyclotomic field (:func:`~graspcompass.geometry.cyclotomic.is_zero_cyclotomic`)
    or by a 200-digit evaluation, else None.  Floats count as zero when
    ``|expr| <= 1e-12 * scale``: pass the magnitude of the quantities that
    ``expr`` was computed from; the default ``scale=0`` asks for an exact zero.
    Expressions with free symbols that do not reduce to 0, and whose sign
    assumptions do not settle it, are undecidable (None).

    Examples
    --------
    >>> from sympy import sqrt, Symbol, sin, cos, pi
    >>> decide_zero(sqrt(6) - sqrt(2)*sqrt(3)), decide_zero(sqrt(2) - 1)
    (True, False)
    >>> decide_zero(Symbol("a")) is None
    True
    >>> from graspcompass.geometry.trig import sincos
    >>> s, c = sincos(3*pi/5)
    >>> decide_zero(4*c + sqrt(5) - 1)    # cos 108° = (1 − √5)/4
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
    reduced = canon(expr)
    if reduced == 0:
        return True
    if _strict_sign(reduced) is not None:
        return False
    from .cyclotomic import is_zero_cyclotomic

    exact = is_zero_cyclotomic(reduced)
    if exact is not None:
        return exact
    value = reduced.evalf(200)
    if value.is_Number and abs(value) > sp.Float(10) ** -150:
        return False
    return None


def decide_sign(expr: sp.Expr) -> int | None:
    """Sign of ``expr`` as -1, 0 or +1, or None when it cannot be decided.

    Exact numbers: the canonical form's numerator and denominator are evaluated
    in interval arithmetic (200 bits); an interval that excludes 0 proves the
    sign, and a value that cannot be separated from 0 goes to the exact zero
    test of :func:`decide_zero`.

    Examples
    --------
    >>> from sympy import sqrt, pi
    >>> decide_sign(sqrt(3) - 2), decide_sign(pi/2 - pi/2), decide_sign(sqrt(2))
    (-1, 0, 1)
    """
    expr = sym(expr)
    if expr.is_Number and not has_float(expr):
        return 0 if expr == 0 else (1 if expr > 0 else -1)
    if not expr.free_symbols and not has_float(expr):
        q = expr / sp.pi  # angles: a rational multiple of pi is decided at once
        if q.is_Rational:
            return 0 if q == 0 else (1 if q > 0 else -1)
        sign = _strict_sign(canon(expr))
        if sign is not None:
            return sign
    zero = decide_zero(expr)
    if zero:
        return 0
    if zero is None:
        return None
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


_IV_PREC = 200  # bits of the interval evaluation


@lru_cache(maxsize=4096)
def _gen_interval(g: sp.Expr):
    """An interval (mpmath.iv) holding the value of a numeric generator."""
    from mpmath import iv

    if g.is_Pow and g.exp == sp.S.Half and g.base.is_Integer:
        return iv.sqrt(int(g.base))
    if isinstance(g, (sp.sin, sp.cos)):
        q = g.args[0] / sp.pi
        if q.is_Rational:
            a = iv.pi * int(q.p) / int(q.q)
        elif g.args[0].is_Rational:
            a = iv.mpf(int(g.args[0].p)) / int(g.args[0].q)
        else:
            a = None
        if a is not None:
            return iv.sin(a) if isinstance(g, sp.sin) else iv.cos(a)
    if g is sp.pi:
        return iv.pi
    if isinstance(g, sp.atan) and not g.args[0].free_symbols:
        inner = _interval(g.args[0])
        if inner is not None:
            return iv.atan2(inner, 1)
    value = g.evalf(70)  # other atoms: sympy's own error control, widened
    if not value.is_Number or value.has(sp.I):
        raise TypeError(f"not a real number: {g}")
    v = iv.mpf(str(value))
    return v + iv.mpf([-1, 1]) * (abs(v.a) + 1) * iv.mpf(10) ** -55


@lru_cache(maxsize=4096)
def _gen_ball(g: sp.Expr, k: int) -> tuple[int, int]:
    """``(m, r)`` with the numeric generator ``g`` in ``[(m - r) / 2**k, (m + r) / 2**k]``."""
    if g.is_Pow and g.exp == sp.S.Half and g.base.is_Integer:
        return math.isqrt(int(g.base) << (2 * k)), 1  # floor(sqrt(p) 2**k), exactly
    from mpmath import iv

    prec = iv.prec
    iv.prec = k + 32
    try:
        v = _gen_interval.__wrapped__(g)  # at this precision, not the cached one
    finally:
        iv.prec = prec
    a, b = (_scaled(e, k) for e in v._mpi_)
    return (a + b) // 2, (b - a) // 2 + 2


def _scaled(raw: tuple, k: int) -> int:
    """``floor(x * 2**k)`` of an mpmath raw number x (sign, mantissa, exponent, bits)."""
    sign, man, exp, _ = raw
    n = -int(man) if sign else int(man)
    shift = exp + k
    return n << shift if shift >= 0 else n >> -shift


def _ball_poly(poly, balls: list, k: int) -> tuple[int, int]:
    """Ball ``(m, r)`` at scale ``2**-k`` of the number ``poly`` (Python integers only).

    Products round down by ``>> k``; each adds its propagated error
    ``(|a| s + |b| r + r s) >> k`` plus 2 for the two floors, so the exact value
    always lies in ``[(m - r) / 2**k, (m + r) / 2**k]``.
    """
    m_total = r_total = 0
    for monom, coeff in poly.terms():
        m, r = (int(coeff.numerator) << k) // int(coeff.denominator), 1
        for i, e in enumerate(monom):
            if e:
                gm, gr = balls[i]
                for _ in range(e):
                    m, r = (m * gm) >> k, ((abs(m) * gr + abs(gm) * r + r * gr) >> k) + 2
        m_total += m
        r_total += r
    return m_total, r_total


def _intervals(*polys) -> list:
    """Intervals (mpmath.iv, at the current precision) of the numbers ``polys`` of one ring.

    Evaluated in exact integer ball arithmetic (:func:`_ball_poly`), each generator
    once, then widened outwards to an interval: much faster than mpmath's
    interval arithmetic and as rigorous.
    """
    from mpmath import iv

    k = iv.prec + 8
    scale = iv.mpf(2) ** -k
    return [iv.mpf([m - r, m + r]) * scale for m, r in _balls(polys, k)]


def _balls(polys: tuple, k: int) -> list[tuple[int, int]]:
    """Balls ``(m, r)`` at scale ``2**-k`` of the numbers ``polys`` of one ring."""
    symbols = polys[0].ring.symbols
    used = {i for p in polys for monom in p.monoms() for i, e in enumerate(monom) if e}
    balls = [_gen_ball(g, k) if i in used else None for i, g in enumerate(symbols)]
    return [_ball_poly(p, balls, k) for p in polys]


def _interval(expr: sp.Expr):
    """An interval holding the exact number ``expr``, or None (at the current iv.prec)."""
    from mpmath import iv

    reduced = canon(expr)
    if reduced.is_Rational:
        return iv.mpf(int(reduced.p)) / int(reduced.q)
    hit = _MEMO.get(reduced)
    if hit is None:
        return None
    _, n, d = hit
    nv, dv = _intervals(n, d)
    return nv / dv


def approx(expr: sp.Expr, dps: int = 30):
    """``expr`` as an :class:`mpmath.mpf` with about ``dps`` correct digits (fast).

    Exact numbers are evaluated from their canonical form by interval
    arithmetic (each generator once), much faster than ``sympy.N`` on long
    expressions; anything else goes through ``sympy.N``.

    Examples
    --------
    >>> float(approx(sp.sqrt(2) + sp.sin(3 * sp.pi / 5)))
    2.36527007866...
    """
    import mpmath

    expr = sym(expr)
    if not expr.free_symbols and not has_float(expr):
        try:
            reduced = canon(expr)
        except (TypeError, ZeroDivisionError):
            reduced = None
        if reduced is not None and reduced.is_Rational:
            with mpmath.workdps(dps):
                return mpmath.mpf(int(reduced.p)) / int(reduced.q)
        hit = _MEMO.get(reduced) if reduced is not None else None
        if hit is not None:
            value = _ball_quotient(hit[1], hit[2], dps)
            if value is not None:
                return value
    with mpmath.workdps(dps):
        return mpmath.mpf(sp.N(expr, dps))


def _ball_quotient(n, d, dps: int):
    """n/d to ``dps`` digits from integer balls, or None when they are too wide.

    With n in mn ± rn and d in md ± rd (rd <= |md|/2), n/d is within
    ``2 (rn/|mn| + rd/|md|)`` of mn/md relatively; that must be below 10**-(dps+2).
    """
    import mpmath

    k = max(_IV_PREC, int(dps * 3.33) + 64) + 8
    try:
        (mn, rn), (md, rd) = _balls((n, d), k)
    except TypeError:
        return None
    an, ad = abs(mn), abs(md)
    if an == 0 or 2 * rd > ad or 2 * (rn * ad + rd * an) * 10 ** (dps + 2) >= an * ad:
        return None
    with mpmath.workdps(dps):
        return mpmath.mpf(mn) / mpmath.mpf(md)


def _strict_sign(reduced: sp.Expr) -> int | None:
    """The sign of a canonical number proved by interval arithmetic, or None."""
    from mpmath import iv

    if reduced.is_Rational:
        return None if reduced == 0 else (1 if reduced > 0 else -1)
    hit = _MEMO.get(reduced)
    prec = iv.prec
    iv.prec = _IV_PREC
    try:
        if hit is None:
            value = reduced.evalf(_PREC)
            if value.is_Number and abs(value) > sp.Float(10) ** (-_PREC // 2):
                return 1 if value > 0 else -1
            return None
        _, n, d = hit
        fs = _float_sign(n), _float_sign(d)
        if None not in fs:
            return fs[0] * fs[1]
        nv, dv = _intervals(n, d)
    except TypeError:
        return None
    finally:
        iv.prec = prec
    signs = []
    for v in (nv, dv):
        if v.a > 0:
            signs.append(1)
        elif v.b < 0:
            signs.append(-1)
        else:
            return None
    return signs[0] * signs[1]


def _nd(e: sp.Expr, R, index: dict) -> tuple:
    """``e`` as (numerator, denominator) in the ring R whose generators are ``index``."""
    return _convert(e, R, {g: (R.gens[i], R.one) for g, i in index.items()})


def _ground(R, q: sp.Rational):
    """The rational ``q`` as a constant of ring R (``R(q)`` goes through ``from_expr``)."""
    return R.ground_new(R.domain.from_sympy(q))


class NotAFraction(Exception):
    """An expression the fast path cannot hold (floats, ``I``): use sympy arithmetic."""


class Frac:
    """An exact value as a fraction ``n/d`` of sparse polynomials in its generators.

    The kernel's constructions compute with these instead of building sympy
    expression trees; :meth:`expr` gives the canonical sympy expression (the same
    as :func:`canon`), reduced modulo the relations of the generators.

    Examples
    --------
    >>> a = Frac.of(sp.sqrt(3) / 2)
    >>> (a * a + Frac.of(sp.Rational(1, 4))).expr()
    1
    """

    __slots__ = ("R", "d", "n")

    def __init__(self, R, n, d) -> None:
        self.R, self.n, self.d = R, n, d

    @classmethod
    def of(cls, e: sp.Expr) -> Frac:
        """The fraction of an exact expression (a memo hit for the kernel's own values)."""
        if e.is_Rational:
            return cls(None, e, sp.Integer(1))
        hit = _MEMO.get(e)
        if hit is None:
            if e.has(sp.Float) or _canon_ring(e) is None:
                raise NotAFraction(e)
            hit = _MEMO.get(canon(e))
            if hit is None:
                raise NotAFraction(e)
        return cls(*hit)

    def _pair(self, other: Frac) -> tuple:
        if self.R is other.R:
            return self.R, self.n, self.d, other.n, other.d
        if self.R is None:
            R = other.R
            return R, _ground(R, self.n), R.one, other.n, other.d
        if other.R is None:
            R = self.R
            return R, self.n, self.d, _ground(R, other.n), R.one
        gens = set(self.R.symbols) | set(other.R.symbols)
        R = _ring(tuple(sorted(gens, key=_gen_key)))
        return (R, _lift(self.n, self.R, R), _lift(self.d, self.R, R),
                _lift(other.n, other.R, R), _lift(other.d, other.R, R))

    def __add__(self, other: Frac) -> Frac:
        if self.R is None and other.R is None:
            return Frac(None, self.n + other.n, sp.Integer(1))
        R, a, b, c, d = self._pair(other)
        if b == d:
            return Frac(R, a + c, b)
        return Frac(R, a * d + c * b, b * d)

    def __neg__(self) -> Frac:
        return Frac(self.R, -self.n, self.d)

    def __sub__(self, other: Frac) -> Frac:
        return self + (-other)

    def __mul__(self, other: Frac) -> Frac:
        if self.R is None and other.R is None:
            return Frac(None, self.n * other.n, sp.Integer(1))
        R, a, b, c, d = self._pair(other)
        return Frac(R, a * c, b * d)

    def __truediv__(self, other: Frac) -> Frac:
        if not other.n:
            raise ZeroDivisionError("division by zero")
        if other.R is None:
            return self * Frac(None, 1 / other.n, sp.Integer(1))
        return self * other.inverse()

    def inverse(self) -> Frac:
        """``1 / self`` with the square roots cleared from its denominator at once.

        Done here, once, a quotient used twice (the parameter t of a meet, for both
        coordinates) does not have its roots cleared again in every :meth:`expr`.
        """
        R = self.R
        root_rels, _, roots = _relations(R)
        n, d = self.d, self.n
        if roots:
            n, d = n.rem(root_rels), d.rem(root_rels)
            if not d:
                raise ZeroDivisionError("division by zero")
            n, d = _clear_roots(n, d, roots, root_rels, _has_opaque(R))
        return Frac(R, n, d)

    def is_zero(self) -> bool | None:
        """Whether the value is 0: True, False, or None when undecidable (symbols).

        Decided without building the sympy expression when it can be: a numerator
        that reduces to 0 modulo the generators' relations is 0, and one whose
        interval (200 bits) excludes 0 is not; anything else goes to
        :func:`decide_zero` on :meth:`expr`.

        Examples
        --------
        >>> a = Frac.of(sp.sqrt(6))
        >>> (a - Frac.of(sp.sqrt(2)) * Frac.of(sp.sqrt(3))).is_zero(), a.is_zero()
        (True, False)
        """
        if self.R is None:
            return self.n == 0
        root_rels, trig_rels, _ = _relations(self.R)
        n = self.n.rem(root_rels) if root_rels else self.n
        if n and trig_rels:
            n = n.rem(trig_rels)
        if not n:
            return True
        if _clearly_nonzero(n):
            return False
        return decide_zero(self.expr())

    def sign(self) -> int | None:
        """The sign -1, 0, +1 of the value, or None when undecidable (symbols).

        A float filter with a proven error bound decides most signs without the
        sympy expression; the rest goes to :func:`decide_sign` on :meth:`expr`.

        Examples
        --------
        >>> Frac.of(sp.sqrt(2) - sp.Rational(3, 2)).sign(), Frac.of(sp.Integer(0)).sign()
        (-1, 0)
        """
        if self.R is None:
            return 0 if self.n == 0 else (1 if self.n > 0 else -1)
        fs = _float_sign(self.n), _float_sign(self.d)
        if None not in fs:
            return fs[0] * fs[1]
        return decide_sign(self.expr())

    def reduced(self) -> Frac:
        """The same value in the canonical form of :meth:`expr`, without building it."""
        if self.R is None:
            return self
        return Frac(self.R, *_reduce(self.R, self.n, self.d))

    def expr(self) -> sp.Expr:
        """The canonical sympy expression of this value (as :func:`canon` gives it)."""
        if self.R is None:
            return self.n
        return _finish(self.R, self.n, self.d)
