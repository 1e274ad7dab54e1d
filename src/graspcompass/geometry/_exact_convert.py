"""From a sympy expression to a fraction in the ring of its generators.

Each atom of an expression gets a plan (:func:`_atom_plan`): a square root of a
rational becomes a coefficient times prime square roots (:func:`_square_free`),
``sin``, ``cos`` and ``tan`` of an angle a sine-cosine pair (or the value
:func:`~graspcompass.geometry.trig.sincos` knows), anything else one generator;
:func:`_canon_ring` converts the expression in the ring of these generators and
reduces it (:func:`~graspcompass.geometry._exact_ring._finish`).  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

import itertools
import math
from functools import lru_cache

import sympy as sp

from ._exact_ring import _MEMO, _finish, _gen_key, _ring

#: Generators met so far: one growing ring keeps the memo below reusable.
_GENS: set[sp.Expr] = set()
_MAX_GENS = 80
#: Trial division bound of :func:`_square_free`, sympy's own for ``sqrt`` of an integer.
_TRIAL = 2**15
#: Below this, :func:`_square_free` tries 2 and the odd numbers instead of the primes.
_ODD_TRIAL = 2**20


@lru_cache(maxsize=1)
def _small_primes() -> tuple[int, ...]:
    """The primes below :data:`_TRIAL`, by a sieve (``sympy.primerange`` takes 20 ms)."""
    sieve = bytearray([1]) * _TRIAL
    sieve[:2] = b"\x00\x00"
    for i in range(2, math.isqrt(_TRIAL - 1) + 1):
        if sieve[i]:
            sieve[i * i :: i] = bytes(len(range(i * i, _TRIAL, i)))
    return tuple(itertools.compress(range(_TRIAL), sieve))


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
    # a small radicand by 2 and the odd numbers (a composite divides no more: its primes
    # are divided out first), without the table of primes
    candidates = (
        _small_primes()
        if n >= _ODD_TRIAL
        else itertools.chain((2,), range(3, math.isqrt(n) + 1, 2))
    )
    for p in candidates:
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
        return R(int(e.p)), R(int(e.q))
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
def _positions(r, R) -> tuple[int | None, ...]:
    """Where each generator of ring r sits in ring R (None where R lacks it)."""
    return tuple(R.index.get(g) for g in r.symbols)


def _lift(p, r, R):
    """The polynomial p of ring r as an element of R (which holds every generator p uses)."""
    if r is R:
        return p
    if p.is_constant():
        return R.ctx.constant(p.leading_coefficient()) if not p.is_zero() else R.zero
    pos = _positions(r, R)
    if None in pos:
        if any(e and i is None for i, e in zip(pos, p.degrees())):
            raise ValueError(f"{R} does not hold the generators of {p} in {r}")
    return p.compose(*(R.zero if i is None else R.gens[i] for i in pos), ctx=R.ctx)


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
            n = R(int(coefficient.p))
            for p in ps:
                n *= index[sp.sqrt(p)]
            amap[a] = (n, R(int(coefficient.q)))
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
