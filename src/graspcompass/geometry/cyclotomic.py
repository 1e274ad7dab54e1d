"""Exact zero test in a cyclotomic field: the last word on tiny numbers.

A number built with + − × ÷ from rationals, square roots of rationals and
sines, cosines and tangents of rational multiples of π lies in a cyclotomic
field Q(ζ_M): ``cos(aπ/b) = (ζ^k + ζ^-k)/2`` with ``ζ^k = e^{iπa/b}``,
``i = ζ^{M/4}``, ``√2 = ζ_8 + ζ_8^{-1}`` and, for an odd prime p, the quadratic
Gauss sum g_p = Σ (a|p) ζ_p^a equals √p (p ≡ 1 mod 4) or i√p (p ≡ 3 mod 4).
Elements are polynomials in ζ reduced modulo the cyclotomic polynomial Φ_M,
so an element is zero exactly when its remainder is.

The kernel calls :func:`is_zero_cyclotomic` only for the rare number whose
canonical form is not 0 but whose 40-digit value is below 1e-20, i.e. on
degenerate configurations (coincident circles, vertical cone sides with
angles whose sines are not radicals).
"""

from __future__ import annotations

from functools import lru_cache
from math import lcm

import sympy as sp

__all__ = ["is_zero_cyclotomic"]

_Z = sp.Symbol("z")
#: Largest conductor handled (degree φ(M) of the field); beyond, the answer is None.
MAX_CONDUCTOR = 10_080


class _Unsupported(Exception):
    pass


@lru_cache(maxsize=32)
def _phi(m: int) -> sp.Poly:
    return sp.Poly(sp.cyclotomic_poly(m, _Z), _Z, domain=sp.QQ)


def _pi_fraction(arg: sp.Expr) -> sp.Rational:
    q = arg / sp.pi
    if not q.is_Rational:
        raise _Unsupported
    return q


def _square_free(r: sp.Rational) -> tuple[sp.Rational, int]:
    """``sqrt(r) = coefficient * sqrt(m)`` with m square-free."""
    n = int(r.p) * int(r.q)
    k, m = 1, 1
    for p, e in sp.factorint(n).items():
        k *= p ** (e // 2)
        if e % 2:
            m *= p
    return sp.Rational(k, int(r.q)), m


def _conductor(expr: sp.Expr) -> int:
    m = 4
    stack = [expr]
    while stack:
        a = stack.pop()
        if a.is_Add or a.is_Mul or (a.is_Pow and a.exp.is_Integer):
            stack.extend(a.args)
        elif isinstance(a, (sp.sin, sp.cos, sp.tan)):
            m = lcm(m, 2 * int(_pi_fraction(a.args[0]).q))
        elif a.is_Pow and not a.exp.is_Integer:
            if a.exp != sp.S.Half or not a.base.is_Rational or a.base < 0:
                raise _Unsupported
            for p in sp.factorint(_square_free(a.base)[1]):
                m = lcm(m, 8 if p == 2 else 4 * p)
        elif not a.is_Rational:
            raise _Unsupported  # pi outside sin/cos, E, symbols, floats, other functions
    return m


class _Field:
    """Q(ζ_M) with elements as polynomials in z modulo Φ_M."""

    def __init__(self, m: int) -> None:
        self.m, self.mod = m, _phi(m)

    def power(self, k: int) -> sp.Poly:
        return sp.Poly(_Z ** (k % self.m), _Z, domain=sp.QQ).rem(self.mod)

    def const(self, r: sp.Rational) -> sp.Poly:
        return sp.Poly(r, _Z, domain=sp.QQ)

    @property
    def i(self) -> sp.Poly:
        return self.power(self.m // 4)

    def root(self, p: int) -> sp.Poly:
        if p == 2:
            return self.power(self.m // 8) + self.power(-(self.m // 8))
        step = self.m // p
        g = sp.Poly(0, _Z, domain=sp.QQ)
        for a in range(1, p):
            g += sp.legendre_symbol(a, p) * self.power(a * step)
        return g if p % 4 == 1 else (-self.i * g).rem(self.mod)

    def inverse(self, f: sp.Poly) -> sp.Poly:
        if f.is_zero:
            raise ZeroDivisionError
        return sp.invert(f, self.mod)

    def value(self, e: sp.Expr) -> sp.Poly:
        if e.is_Rational:
            return self.const(e)
        if e.is_Add:
            out = self.const(sp.Integer(0))
            for a in e.args:
                out += self.value(a)
            return out
        if e.is_Mul:
            out = self.const(sp.Integer(1))
            for a in e.args:
                out = (out * self.value(a)).rem(self.mod)
            return out
        if e.is_Pow and e.exp.is_Integer:
            base = self.value(e.base)
            k = int(e.exp)
            if k < 0:
                base, k = self.inverse(base), -k
            out = self.const(sp.Integer(1))
            for _ in range(k):
                out = (out * base).rem(self.mod)
            return out
        if e.is_Pow:  # sqrt of a rational
            coefficient, m = _square_free(e.base)
            out = self.const(coefficient)
            for p in sp.factorint(m):
                out = (out * self.root(p)).rem(self.mod)
            return out
        q = _pi_fraction(e.args[0])
        k = int(q.p) * (self.m // (2 * int(q.q)))  # e^{iqπ} = ζ^k
        plus, minus = self.power(k), self.power(-k)
        cos2 = plus + minus  # 2 cos
        sin2i = plus - minus  # 2i sin
        if isinstance(e, sp.cos):
            return cos2 * sp.Rational(1, 2)
        sin = (sin2i * self.inverse(2 * self.i)).rem(self.mod)
        if isinstance(e, sp.sin):
            return sin
        return (sin * self.inverse(cos2 * sp.Rational(1, 2))).rem(self.mod)


def is_zero_cyclotomic(expr: sp.Expr) -> bool | None:
    """Decide ``expr == 0`` exactly in a cyclotomic field, or None if it is not in one.

    Parameters
    ----------
    expr : sympy.Expr
        A number built from rationals, square roots of rationals and sin, cos,
        tan of rational multiples of π (opaque or not).

    Returns
    -------
    bool or None
        None when ``expr`` holds anything else (π outside a sine, radians that
        are not multiples of π, nested radicals), when a division by zero occurs,
        or when the field would be too large (conductor above ``MAX_CONDUCTOR``).

    Examples
    --------
    >>> from graspcompass.geometry.trig import OpaqueCos, OpaqueSin
    >>> s, c = OpaqueSin(sp.pi / 10), OpaqueCos(sp.pi / 10)
    >>> is_zero_cyclotomic(4 * s - sp.sqrt(5) + 1)    # sin 18° = (√5 − 1)/4
    True
    >>> is_zero_cyclotomic(4 * c - sp.sqrt(5) + 1)
    False
    """
    try:
        m = _conductor(expr)
        if m > MAX_CONDUCTOR:
            return None
        return _Field(m).value(expr).rem(_phi(m)).is_zero
    except (_Unsupported, ZeroDivisionError, sp.polys.polyerrors.NotInvertible):
        return None
