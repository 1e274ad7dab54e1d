"""Exact values as fractions of sparse polynomials: the kernel's fast arithmetic.

Constructions compute with :class:`Frac` instead of sympy expression trees; its
zero and sign tests use the float filter and integer balls of
:mod:`~graspcompass.geometry._exact_bounds` before the decisions of
:mod:`~graspcompass.geometry._exact_decide`.  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

import sympy as sp

from ._exact_bounds import _clearly_nonzero, _float_sign
from ._exact_canon import canon
from ._exact_convert import _canon_ring, _convert, _lift
from ._exact_decide import _ASSUME_TERMS, _nonzero_by_terms, decide_sign, decide_zero
from ._exact_ring import (
    _MEMO,
    _clear_roots,
    _finish,
    _gen_key,
    _reduce,
    _ring,
    reduce_poly,
    reduce_roots,
    uses_opaque,
)


def _nd(e: sp.Expr, R, index: dict) -> tuple:
    """``e`` as (numerator, denominator) in the ring R whose generators are ``index``."""
    return _convert(e, R, {g: (R.gens[i], R.one) for g, i in index.items()})


def _ground(R, q: sp.Rational):
    """The rational ``q`` as a constant of ring R."""
    return R(q)


#: Products of term counts from which a sum or product first cancels across its operands
#: ((a/b)(c/d) = (a/g)(c/h) / ((b/h)(d/g)), g = gcd(a, d), h = gcd(c, b)): the gcds of
#: the small operands cost far less than the one of the large result.
_CROSS = 400


def _cancel_pair(a, d) -> tuple:
    """``(a/g, d/g)`` with ``g = gcd(a, d)`` (the same pair when they share no factor).

    Cancelling a common factor of a numerator and a denominator is valid wherever
    the denominator ``d`` is non-zero, which its caller checks or records.
    """
    if a == d:
        one = a.context().constant(1)
        return one, one
    g = a.gcd(d)
    return (a, d) if g.is_one() else (a / g, d / g)


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
        return (
            R,
            _lift(self.n, self.R, R),
            _lift(self.d, self.R, R),
            _lift(other.n, other.R, R),
            _lift(other.d, other.R, R),
        )

    def __add__(self, other: Frac) -> Frac:
        if self.R is None and other.R is None:
            return Frac(None, self.n + other.n, sp.Integer(1))
        R, a, b, c, d = self._pair(other)
        if b == d:
            return Frac(R, a + c, b)
        if b.is_constant() or d.is_constant() or len(b) * len(d) < _CROSS:
            return Frac(R, a * d + c * b, b * d)
        g = b.gcd(d)  # over the least common denominator: far smaller when they share factors
        if g.is_one():
            return Frac(R, a * d + c * b, b * d)
        bg, dg = b / g, d / g
        return Frac(R, a * dg + c * bg, bg * d)

    def __neg__(self) -> Frac:
        return Frac(self.R, -self.n, self.d)

    def __sub__(self, other: Frac) -> Frac:
        return self + (-other)

    def __mul__(self, other: Frac) -> Frac:
        if self.R is None and other.R is None:
            return Frac(None, self.n * other.n, sp.Integer(1))
        R, a, b, c, d = self._pair(other)
        if len(a) * len(d) >= _CROSS and not d.is_constant():
            a, d = _cancel_pair(a, d)
        if len(c) * len(b) >= _CROSS and not b.is_constant():
            c, b = _cancel_pair(c, b)
        return Frac(R, a * c, b * d)

    def __truediv__(self, other: Frac) -> Frac:
        if other.R is None:
            if not other.n:
                raise ZeroDivisionError("division by zero")
        elif reduce_poly(other.R, other.n).is_zero():
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
        if reduce_poly(R, self.n).is_zero():
            raise ZeroDivisionError("division by zero")
        n, d = self.d, self.n
        if R.roots:
            n, d = reduce_roots(R, n), reduce_roots(R, d)
            if not uses_opaque(R, n, d):
                n, d = _clear_roots(R, n, d)
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
        n = reduce_poly(self.R, self.n)
        if n.is_zero():
            return True
        if _clearly_nonzero(self.R, n):
            return False
        if self.R.free:  # what the assumptions show, without building the expression
            if _nonzero_by_terms(self.R, n):
                return False
            if len(n) > _ASSUME_TERMS:  # sympy's assumptions would take long to say None
                return None
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
        fn, fd = _float_sign(self.R, self.n), _float_sign(self.R, self.d)
        if fn is not None and fd is not None:
            return fn * fd
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
