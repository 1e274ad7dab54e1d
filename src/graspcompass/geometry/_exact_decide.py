"""Zero and sign decisions and fast evaluation of the kernel's exact numbers.

:func:`decide_zero` and :func:`decide_sign` prove what they answer: by interval
arithmetic on the canonical form (:func:`_strict_sign`), an exact zero test of the
canonical form, a cyclotomic field, else None.  :func:`approx` evaluates a number
from its canonical form in integer balls.  Private to
:mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

from functools import lru_cache

import flint
import sympy as sp

from . import _exact_bounds
from ._exact_bounds import _IV_PREC, _balls, _clearly_nonzero, _float_sign, _intervals
from ._exact_canon import canon, free, has_float, sym
from ._exact_ring import _MEMO, Ring, reduce_poly

#: Above this many terms a symbolic numerator whose terms do not show it nonzero
#: (:func:`_nonzero_by_terms`) is not handed to sympy's assumptions: they settle
#: short sums such as ``2 - cos(a)**2`` (cosines are bounded), and on the longer
#: numerators of a symbolic construction only take milliseconds to answer None.
_ASSUME_TERMS = 3


@lru_cache(maxsize=1024)
def _signs_of(symbols: tuple[sp.Expr, ...]) -> tuple[tuple[int, bool] | None, ...]:
    """What the assumptions say of each generator: ``(sign, strict)`` with sign +1 or
    -1 and ``strict`` False for a generator that may be 0 (``y >= 0``); ``(0, False)``
    for a real generator of unknown sign; None for anything else."""
    signs: list[tuple[int, bool] | None] = []
    for g in symbols:
        if g.is_positive:
            signs.append((1, True))
        elif g.is_negative:
            signs.append((-1, True))
        elif g.is_nonnegative:
            signs.append((1, False))
        elif g.is_nonpositive:
            signs.append((-1, False))
        elif g.is_extended_real:
            signs.append((0, False))
        else:
            signs.append(None)
    return tuple(signs)


def _nonzero_by_terms(R: Ring, n: flint.fmpq_mpoly) -> bool:
    """``n != 0`` wherever the generators' assumptions hold, shown by the signs of its
    terms: every term is >= 0 (or every term <= 0) and one of them is strictly so.

    A term's sign is its coefficient's times its generators' (an even power of a real
    generator is >= 0); a term of unknown sign shows nothing.  This is what sympy's
    assumptions decide of such a sum, without building it (the polynomial is kept
    modulo the relations, so the value is the value of ``n`` as written).
    """
    signs = _signs_of(R.symbols)
    total, strict_any = 0, False
    for m, c in n.to_dict().items():
        s, strict = (1 if c > 0 else -1), True
        for i, e in enumerate(m[: R.ngens]):
            if not e:
                continue
            g = signs[i]
            if g is None or (g[0] == 0 and e % 2):
                return False  # a term of unknown sign
            if e % 2 and g[0] < 0:
                s = -s
            strict = strict and g[1]
        if total and s != total:
            return False
        total, strict_any = s, strict_any or strict
    return strict_any


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
        if R.free:  # not 0 modulo the relations: the assumptions may show it nonzero
            if _nonzero_by_terms(R, n):
                return False
            if len(n) > _ASSUME_TERMS:
                return None  # too long to ask sympy's assumptions (they would say None)
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
        fn, fd = _float_sign(R, n), _float_sign(R, d)
        if fn is not None and fd is not None:
            return fn * fd
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
