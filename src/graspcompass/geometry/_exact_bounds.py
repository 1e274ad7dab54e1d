"""Numeric bounds of the kernel's exact numbers: a float filter and integer balls.

A number of the kernel is a polynomial in numeric generators (``sqrt(p)``,
``sin(a)``, ``cos(a)``, other atoms).  Its sign is proved, without building the
sympy expression, first by a floating-point filter with a static error bound
(:func:`_float_sign`), then by exact integer ball arithmetic (:func:`_intervals`),
each generator evaluated once (:func:`_gen_interval`, :func:`_gen_ball`).
Private to :mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import lru_cache
from typing import Any

import sympy as sp

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


def _float_sign(R, poly) -> int | None:
    """The sign of the number ``poly`` by a floating-point filter, or None.

    Each term is evaluated in doubles by repeated multiplication (generators
    within one unit roundoff u, coefficients correctly rounded); a term of degree
    D is then within (1.5 D + 1) u of its value and the sum of N terms adds at
    most N u of the sum of magnitudes M.  A computed sum beyond twice that bound,
    ``2 (2 D_max + N + 2) u M``, has the sign of the exact value (the usual
    static filter of exact geometric predicates); anything closer returns None and
    the caller falls back to interval arithmetic.
    """
    symbols = R.symbols
    values: dict[int, float] = {}
    total = magnitude = 0.0
    dmax = count = 0
    try:
        for monom, coeff in poly.terms():
            t = int(coeff.p) / int(coeff.q)
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
    bound = 2.0 * (2 * int(dmax) + count + 2) * _U * magnitude
    if total > bound:
        return 1
    if total < -bound:
        return -1
    return None


def _clearly_nonzero(R, poly) -> bool:
    """True when a float filter or interval arithmetic (200 bits) shows ``poly`` is not 0."""
    from mpmath import iv

    if _float_sign(R, poly) is not None:
        return True

    prec = iv.prec
    iv.prec = _IV_PREC
    try:
        (value,) = _intervals(R, poly)
    except TypeError:
        return False
    finally:
        iv.prec = prec
    return bool(value.a > 0 or value.b < 0)


_IV_PREC = 200  # bits of the interval evaluation

#: The interval of an exact number, or None: ``_exact_decide._interval``, which sets it
#: at its import (it reduces by canon, a layer of the kernel above this module; issue 21:
#: no import cycle).  Unset, an atan's argument is evaluated by sympy like other atoms.
_ARGUMENT_INTERVAL: Callable[[sp.Expr], Any] | None = None


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
        inner = None if _ARGUMENT_INTERVAL is None else _ARGUMENT_INTERVAL(g.args[0])
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
        m, r = (int(coeff.p) << k) // int(coeff.q), 1
        for i, e in enumerate(monom):
            if e:
                gm, gr = balls[i]
                for _ in range(e):
                    m, r = (m * gm) >> k, ((abs(m) * gr + abs(gm) * r + r * gr) >> k) + 2
        m_total += m
        r_total += r
    return m_total, r_total


def _intervals(R, *polys) -> list:
    """Intervals (mpmath.iv, at the current precision) of the numbers ``polys`` of one ring.

    Evaluated in exact integer ball arithmetic (:func:`_ball_poly`), each generator
    once, then widened outwards to an interval: much faster than mpmath's
    interval arithmetic and as rigorous.
    """
    from mpmath import iv

    k = iv.prec + 8
    scale = iv.mpf(2) ** -k
    return [iv.mpf([m - r, m + r]) * scale for m, r in _balls(R, polys, k)]


def _balls(R, polys: tuple, k: int) -> list[tuple[int, int]]:
    """Balls ``(m, r)`` at scale ``2**-k`` of the numbers ``polys`` of ring R."""
    symbols = R.symbols
    used = {i for p in polys for i, e in enumerate(p.degrees()) if e}
    balls = [_gen_ball(g, k) if i in used else None for i, g in enumerate(symbols)]
    return [_ball_poly(p, balls, k) for p in polys]
