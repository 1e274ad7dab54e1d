"""Exact sine and cosine of the angles a user types, without nested radicals.

sympy writes ``sin(3*pi/5)`` as ``sqrt(sqrt(5)/8 + 5/8)``: nested radicals whose
products and quotients explode in size (issue: ``--phi1 108deg`` never finished).
Here the sine and cosine of an angle are either

* the small radicals of Q(√2, √3) when the angle is a multiple of π/12
  (``sin(pi/3) = sqrt(3)/2``: the paper's presets keep their printed form), or
  any angle whose sine and cosine sympy writes with square roots of rationals
  only (``sin(atan(2)) = 2*sqrt(5)/5``);
* otherwise a pair of opaque atoms ``sin(a)``, ``cos(a)`` that sympy never
  evaluates: generators tied by ``sin(a)**2 + cos(a)**2 = 1``, the relation
  the canonical form (:func:`graspcompass.geometry.exact.canon`) and the proof
  checker reduce by.  They are numbers (``is_number``), evaluated to floats only
  for display and for sign decisions.

Rational multiples of π are first reduced to a reference angle in [0, π/4]
(``sin(108°) = cos(18°)``, ``cos(108°) = -sin(18°)``), so that angles differing
by quarter turns or adding up to them share generators and their relations
(a cone side at φ + ξ = π is vertical *exactly*).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

__all__ = ["OpaqueCos", "OpaqueSin", "is_radical", "sincos", "tan_exact"]


class OpaqueSin(sp.sin):
    """``sin(a)`` for a fixed number ``a``, never rewritten into radicals.

    Examples
    --------
    >>> s = OpaqueSin(sp.pi / 10)
    >>> s, s.is_number, round(float(s), 12)
    (sin(pi/10), True, 0.309016994375)
    """

    @classmethod
    def eval(cls, arg: sp.Expr) -> None:  # never evaluate: keep the atom
        return None


class OpaqueCos(sp.cos):
    """``cos(a)`` for a fixed number ``a``, never rewritten into radicals."""

    @classmethod
    def eval(cls, arg: sp.Expr) -> None:  # never evaluate: keep the atom
        return None


# the printers name a function by its class: show the opaque atoms as sin and cos
OpaqueSin.__name__ = "sin"
OpaqueCos.__name__ = "cos"


def is_radical(expr: sp.Expr) -> bool:
    """True when ``expr`` is built from rationals and square roots of rationals only.

    Examples
    --------
    >>> is_radical(sp.sqrt(3) / 2 + 1), is_radical(sp.sqrt(sp.sqrt(5) + 5)), is_radical(sp.pi)
    (True, False, False)
    """
    for a in sp.preorder_traversal(expr):
        if a.is_Atom:
            if not a.is_Rational:
                return False
        elif a.is_Pow:
            if not (a.exp.is_Integer or (a.exp == sp.S.Half and a.base.is_Rational)):
                return False
        elif not (a.is_Add or a.is_Mul):
            return False
    return True


_TWELFTHS = 12  # multiples of pi/12 have sines and cosines in Q(sqrt(2), sqrt(3))


def _twelfths() -> dict[sp.Rational, tuple[sp.Expr, sp.Expr]]:
    """(sin vπ, cos vπ) for v = 1/12, 1/6, 1/4 in sympy's own radical form.

    Written out rather than evaluated: sympy's ``sin(pi/12)`` costs milliseconds
    of table lookups on every cold call (tests check the two agree).
    """
    r2, r3, r6 = sp.sqrt(2), sp.sqrt(3), sp.sqrt(6)
    q = sp.Rational(1, 4)
    return {
        sp.Rational(1, 12): (q * r6 - q * r2, q * r6 + q * r2),
        sp.Rational(1, 6): (sp.S.Half, r3 / 2),
        sp.Rational(1, 4): (r2 / 2, r2 / 2),
    }


_TWELFTH_VALUES = _twelfths()


@lru_cache(maxsize=4096)
def _reference(q: sp.Rational) -> tuple[sp.Expr, sp.Expr]:
    """(sin qπ, cos qπ) through a reference angle in [0, π/4]."""
    t = q % 2
    k = int(t * 2)  # the quadrant, 0..3
    u = t - sp.Rational(k, 2)  # in [0, 1/2)
    if u == 0:
        s, c = sp.Integer(0), sp.Integer(1)
    else:
        swap = u > sp.Rational(1, 4)
        v = sp.S.Half - u if swap else u
        if _TWELFTHS % v.q == 0:
            s, c = _TWELFTH_VALUES[v]
        else:
            s, c = OpaqueSin(v * sp.pi), OpaqueCos(v * sp.pi)
        if swap:
            s, c = c, s
    return ((s, c), (c, -s), (-s, -c), (-c, s))[k]


def _pi_multiple(angle: sp.Expr) -> sp.Rational | None:
    q = angle / sp.pi
    return q if q.is_Rational else None


@lru_cache(maxsize=4096)
def sincos(angle: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Exact ``(sin a, cos a)`` of an exact angle, free of nested radicals.

    Parameters
    ----------
    angle : sympy.Expr
        A number (``3*pi/5``, ``6/5`` radians, ``atan(2)``) or an expression in
        symbols (then ``sin``/``cos`` of it are returned as they are).

    Returns
    -------
    tuple of sympy.Expr
        Radicals of Q(√2, √3) for multiples of π/12, square roots of rationals
        where sympy finds them, else the opaque atoms ``sin(a)``, ``cos(a)``.

    Examples
    --------
    >>> sincos(sp.pi / 3)
    (sqrt(3)/2, 1/2)
    >>> sincos(3 * sp.pi / 5)
    (cos(pi/10), -sin(pi/10))
    >>> sincos(sp.atan(2))
    (2*sqrt(5)/5, sqrt(5)/5)
    >>> sincos(sp.Rational(6, 5))
    (sin(6/5), cos(6/5))
    """
    try:
        angle = sp.sympify(angle, strict=True)  # text, lists, arrays refused: never eval
    except sp.SympifyError:
        from ..boundary.errors import WrongTypeError

        raise WrongTypeError(
            f"an angle must be a number or a sympy expression, got "
            f"{type(angle).__name__} {str(angle)[:60]!r} (read text with "
            "graspcompass.expr.parse_exact)"
        ) from None
    if angle.free_symbols or not angle.is_number:
        return sp.sin(angle), sp.cos(angle)
    q = _pi_multiple(angle)
    if q is not None:
        return _reference(q)
    s, c = sp.sin(angle), sp.cos(angle)
    if is_radical(s) and is_radical(c):
        return s, c
    return OpaqueSin(angle), OpaqueCos(angle)


def tan_exact(angle: sp.Expr) -> sp.Expr:
    """``sin a / cos a`` from :func:`sincos` (unreduced; pass it through ``canon``).

    Examples
    --------
    >>> tan_exact(sp.pi / 4), tan_exact(sp.pi / 3)
    (1, sqrt(3))
    """
    s, c = sincos(angle)
    return s / c
