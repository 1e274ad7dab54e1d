"""The values the safe expression parser reads: signs, sizes and degrees of exact numbers.

Private to :mod:`graspcompass.boundary._reader` (the parser's reader), which re-exports
:func:`real_sign`, documented as ``graspcompass.expr.real_sign``.
"""

from __future__ import annotations

import functools

import mpmath
import sympy
from sympy.core.evalf import evalf as _evalf

from .limits import MAX_NODES

__all__ = ["real_sign"]

#: What sympy may raise on a value it cannot handle; ``AttributeError`` is sympy's cache
#: wrapper failing on a lazy "cannot determine truth value" message (sympy 1.12-1.14).
_SYMPY_FAILURES = (
    ValueError,
    TypeError,
    ArithmeticError,
    AttributeError,
    RecursionError,
    MemoryError,
    IndexError,
    KeyError,
    NotImplementedError,
)


def real_sign(value: sympy.Expr) -> int | None:
    """The sign (-1, 0 or 1) of a real number given exactly, or None if it cannot be decided.

    Rationals are decided exactly; other numbers by a numerical evaluation whose
    accuracy is known (up to about 600 bits), so a decided sign is always right.
    A number that is zero without being written as zero (``sqrt(2) + sqrt(3) -
    sqrt(5 + 2*sqrt(6))``) and numbers closer to zero than the evaluation sees
    give None.

    Examples
    --------
    >>> real_sign(sympy.Rational(-1, 3)), real_sign(sympy.pi - 3), real_sign(sympy.Integer(0))
    (-1, 1, 0)
    >>> print(real_sign(sympy.sqrt(2) + sympy.sqrt(3) - sympy.sqrt(5 + 2 * sympy.sqrt(6))))
    None
    """
    if value.is_Rational:
        return (value.p > 0) - (value.p < 0)  # type: ignore[attr-defined]
    if value == 0:
        return 0
    for bits in (64, 256, 640):
        try:
            re, im, re_acc, _ = _evalf(value, bits, {"maxprec": 2 * bits})
        except _SYMPY_FAILURES:
            return None
        if im or re is None:
            return None
        if re_acc is not None and re_acc >= 16 and re[1]:  # 16 correct bits of a nonzero value
            return -1 if re[0] else 1
    return None


def _mpf(value: sympy.Expr) -> mpmath.mpf:
    """A real number (decided sign, bounded size) as an mpmath float, for messages."""
    return mpmath.mpf(sympy.Float(value.evalf(50))._mpf_)


def _short(value: sympy.Expr) -> str:
    shown = str(value)
    return shown if len(shown) <= 40 else shown[:37] + "..."


def _digits(bits: int) -> int:
    return int(bits * 0.30103)


def _clearly_inside_unit(value: sympy.Expr) -> bool:
    """``|value| < 1 - 2**-32`` by one evaluation of known accuracy (else: decide exactly)."""
    if value.is_Rational:
        return abs(value.p) < value.q  # type: ignore[attr-defined]
    try:
        re, im, re_acc, _ = _evalf(value, 64, {"maxprec": 128})
    except _SYMPY_FAILURES:
        return False
    if im or re is None:
        return re is None and im is None  # exactly zero
    return bool(re_acc is not None and re_acc >= 40 and mpmath.mpf(re) ** 2 < 1 - 2.0**-31)


_TRIG = frozenset({"sin", "cos", "tan"})


def _plain_real(arg: sympy.Expr) -> bool:
    """A real symbol known to be nonzero: ``sin``, ``cos``, ``tan`` of it are left as
    they are by sympy's evaluation, which is skipped (on the first call in a process it
    costs milliseconds of lazy imports and caches)."""
    return bool(arg.is_Symbol and arg.is_extended_real and arg.is_zero is False)


def _has_function(value: sympy.Expr) -> bool:
    return bool(value.atoms(sympy.Function))


#: Most distinct square roots in a number whose zero test needs its minimal polynomial.
_MINPOLY_ROOTS = 6


def _algebraic_sign(value: sympy.Expr) -> int | None:
    """0 if a number of square roots that no evaluation can tell from 0 is 0, 2 if it is
    shown nonzero (sign unknown), None if neither can be shown within the budget.

    Every square root is denested (:func:`sympy.sqrtdenest`) and the value expanded, which
    shows most zeros in disguise; then, for a value with at most :data:`_MINPOLY_ROOTS`
    distinct roots and no ``pi``, its minimal polynomial decides: it is ``x`` exactly when
    the value is 0.
    """
    roots = {
        p
        for p in sympy.preorder_traversal(value)
        if p.is_Pow and p.exp.is_Rational and p.exp.q == 2
    }
    try:
        denested = sympy.expand(value.xreplace({r: sympy.sqrtdenest(r) for r in roots}))
        if denested == 0:
            return 0
        sign = real_sign(denested)
        if sign is not None:
            return sign
        if len(roots) > _MINPOLY_ROOTS or value.has(sympy.pi):
            return None
        x = sympy.Dummy("x")
        return 0 if sympy.minimal_polynomial(value, x) == x else 2
    except (*_SYMPY_FAILURES, NotImplementedError):
        return None


@functools.lru_cache(maxsize=4096)
def _degree(value: sympy.Expr) -> int:
    """An upper bound on the degree of ``value`` in its symbols, read from its tree.

    A sum has the largest degree of its terms, a product the sum of its factors', a power
    ``b**(p/q)`` ``|p|`` times its base's (a root counted as the power it clears to), and
    a function of a symbolic argument its argument's degree (at least 1).
    """
    if value.is_Symbol:
        return 1
    if value.is_Atom:
        return 0
    if value.is_Add:
        return max(_degree(t) for t in value.args)
    if value.is_Mul:
        return sum(_degree(f) for f in value.args)
    if value.is_Pow and value.exp.is_Rational:
        return _degree(value.base) * abs(int(value.exp.p))
    inner = max(_degree(a) for a in value.args)
    return max(1, inner) if inner or value.free_symbols else 0


_INFINITE = frozenset({sympy.zoo, sympy.nan, sympy.oo, -sympy.oo})


def _scan(value: sympy.Expr) -> tuple[bool, int, int]:
    """In one walk of the tree: whether it holds an infinity or nan, the most bits of a
    numerator or denominator in it (:func:`_max_bits`) and its number of nodes."""
    infinite, bits, nodes = False, 0, 0
    for node in sympy.preorder_traversal(value):
        nodes += 1
        if node.is_Atom:
            if node.is_Rational:
                bits = max(bits, int(node.p).bit_length(), int(node.q).bit_length())
            elif node in _INFINITE:
                infinite = True
    return infinite, bits, nodes


def _too_many_nodes(value: sympy.Expr, most: int = MAX_NODES) -> bool:
    for count, _ in enumerate(sympy.preorder_traversal(value), 1):
        if count > most:
            return True
    return False


def _max_bits(value: sympy.Expr) -> int:
    """Most bits of a numerator or a denominator in ``value``."""
    if isinstance(value, sympy.Rational):
        return max(int(value.p).bit_length(), int(value.q).bit_length())
    return max((_max_bits(r) for r in value.atoms(sympy.Rational)), default=0)


def _total_bits(value: sympy.Expr) -> int:
    """Bits of all the integers in ``value``: a bound on the work of a root of it."""
    return sum(int(r.p).bit_length() + int(r.q).bit_length() for r in value.atoms(sympy.Rational))


real_sign.__module__ = "graspcompass.boundary._reader"  # its home before the split
