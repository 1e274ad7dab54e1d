"""Zero and sign decisions and fast evaluation of the kernel's exact numbers.

:func:`decide_zero` and :func:`decide_sign` prove what they answer: by interval
arithmetic on the canonical form (:func:`_strict_sign`), an exact zero test of the
canonical form, a cyclotomic field, else None.  :func:`approx` evaluates a number
from its canonical form in integer balls.  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

import flint
import sympy as sp

from . import _exact_bounds
from ._exact_bounds import _IV_PREC, _balls, _clearly_nonzero, _float_sign, _intervals
from ._exact_canon import canon, free, has_float, sym
from ._exact_ring import _MEMO, Ring, reduce_poly

#: Above this many terms a symbolic numerator is not handed to sympy's assumptions
#: (they settle small sums such as ``(x + 1)**2`` with ``x > 0``; on the long
#: numerators of a symbolic construction they only take time to answer None).
_ASSUME_TERMS = 8


def _positive_terms(R: Ring, n: flint.fmpq_mpoly) -> bool:
    """Every term of ``n`` is a positive rational times powers of positive symbols, so
    ``n > 0`` wherever the symbols' assumptions hold (and ``n ≠ 0``)."""
    pos = [g.is_Symbol and g.is_positive is True for g in R.symbols]
    for m, c in n.to_dict().items():
        if c <= 0 or any(e and not pos[i] for i, e in enumerate(m[:R.ngens])):
            return False
    return True


#: Digits used to separate a non-zero exact number from zero before an exact test.
_PREC = 40


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
    hit = _MEMO.get(expr)
    if hit is not None:  # a canonical number: 0 when its numerator reduces to 0
        R, n, _ = hit
        n = reduce_poly(R, n)
        if n.is_zero():
            return True
        if not R.free and _clearly_nonzero(R, n):
            return False
        if R.free and _positive_terms(R, n):
            return False
        if R.free and len(n) > _ASSUME_TERMS:
            return None  # not 0 modulo the relations; too long to ask the assumptions
    if free(expr):
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
    hit = _MEMO.get(expr)
    if hit is not None and not hit[0].free:
        sign = _strict_sign(expr)
        if sign is not None:
            return sign
    if not free(expr) and not has_float(expr):
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
    if free(expr):
        if expr.is_positive:
            return 1
        if expr.is_negative:
            return -1
        return None
    value = expr.evalf(_PREC)
    if not value.is_Number:
        return None
    return 1 if value > 0 else -1


def _interval(expr: sp.Expr):
    """An interval holding the exact number ``expr``, or None (at the current iv.prec)."""
    from mpmath import iv

    reduced = canon(expr)
    if reduced.is_Rational:
        return iv.mpf(int(reduced.p)) / int(reduced.q)
    hit = _MEMO.get(reduced)
    if hit is None:
        return None
    R, n, d = hit
    nv, dv = _intervals(R, n, d)
    return nv / dv


_exact_bounds._ARGUMENT_INTERVAL = _interval  # an atan's argument (no import cycle)


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
    if not free(expr) and not has_float(expr):
        try:
            reduced = canon(expr)
        except (TypeError, ZeroDivisionError):
            reduced = None
        if reduced is not None and reduced.is_Rational:
            with mpmath.workdps(dps):
                return mpmath.mpf(int(reduced.p)) / int(reduced.q)
        hit = _MEMO.get(reduced) if reduced is not None else None
        if hit is not None:
            value = _ball_quotient(*hit, dps)
            if value is not None:
                return value
    with mpmath.workdps(dps):
        return mpmath.mpf(sp.N(expr, dps))


def _ball_quotient(R, n, d, dps: int):
    """n/d to ``dps`` digits from integer balls, or None when they are too wide.

    With n in mn ± rn and d in md ± rd (rd <= |md|/2), n/d is within
    ``2 (rn/|mn| + rd/|md|)`` of mn/md relatively; that must be below 10**-(dps+2).
    """
    import mpmath

    k = max(_IV_PREC, int(dps * 3.33) + 64) + 8
    try:
        (mn, rn), (md, rd) = _balls(R, (n, d), k)
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
        R, n, d = hit
        fs = _float_sign(R, n), _float_sign(R, d)
        if None not in fs:
            return fs[0] * fs[1]
        nv, dv = _intervals(R, n, d)
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
