"""Numeric evaluation of kernel values (floats, for drawing and checks).

Values from outside (an expression given as text or a number, the symbol
values of ``subs``) go through :mod:`graspcompass.inputs`: text is parsed
safely, never by ``sympify``.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from typing import Any

import sympy as sp

from ..boundary.errors import InputError, NonFiniteValueError
from ..boundary.inputs import real_value, substitutions
from .exact import approx, has_float
from .exact import free as _has_symbols
from .primitives import Circle, Line, Point

__all__ = ["evaluate", "to_float"]


def to_float(expr: sp.Expr, digits: int = 20) -> float:
    """``float(expr)`` of a number, fast for the kernel's long exact values.

    An exact number is evaluated from its canonical form (integer ball arithmetic,
    each generator once, :func:`~graspcompass.geometry.exact.approx` to ``digits``
    digits, then rounded once), not by ``sympy.N``, whose evaluation of a long
    expression in the sines and cosines of typed angles takes seconds.

    Raises
    ------
    TypeError
        If ``expr`` has free symbols.

    Examples
    --------
    >>> to_float(sp.sqrt(2) / 2)
    0.7071067811865476
    """
    if isinstance(expr, (int, float)):
        return float(expr)
    if expr.is_Float or expr.is_Rational:
        return float(expr)
    if _has_symbols(expr):
        raise TypeError(f"{expr} has free symbols and no numeric value")
    if not has_float(expr):
        return _exact_float(expr, digits)
    return float(sp.N(expr, digits))


@functools.lru_cache(maxsize=4096)
def _exact_float(expr: sp.Expr, digits: int) -> float:
    """:func:`to_float` of an exact number, remembered: a picture reads the same angles
    and coordinates several times (the scene, the envelope's polyline), and an angle of the
    envelope (an arctangent) is evaluated by ``sympy.N``."""
    return float(approx(expr, digits))


def _f(expr: sp.Expr, subs: Mapping | None) -> float:
    e = expr.subs(subs) if subs else expr
    try:
        if e.is_Float:
            out = float(e)
        elif not _has_symbols(e) and not has_float(e):  # exact: from the canonical form, fast
            out = float(approx(e, 20))
        else:
            out = float(e.evalf(17))
    except TypeError as exc:
        free = ", ".join(sorted(map(str, e.free_symbols)))
        raise InputError(f"cannot evaluate {expr} numerically: free symbols {free}") from exc
    if not math.isfinite(out):
        raise NonFiniteValueError(
            f"cannot evaluate {expr} numerically: it is beyond double precision (about 1.8e308)"
        )
    return out


def _free(obj: Any) -> set[sp.Symbol]:
    if isinstance(obj, Point):
        return obj.x.free_symbols | obj.y.free_symbols
    if isinstance(obj, Line):
        return _free(obj.point) | _free(obj.direction)
    if isinstance(obj, Circle):
        return _free(obj.center) | obj.radius2.free_symbols
    return obj.free_symbols


def evaluate(obj: Point | Line | Circle | sp.Expr | str | float, subs: Mapping | None = None):
    """Float values of an exact object, with optional symbol substitutions.

    Returns ``(x, y)`` for a point, ``((px, py), (dx, dy))`` for a line,
    ``((cx, cy), r)`` for a circle and a float for an expression (or a number
    or text, read by :func:`graspcompass.inputs.real_value`).  ``subs`` maps
    symbols (or their names) to values, read the same way; keys that are not
    symbols of ``obj`` are ignored.  A value beyond double precision raises
    :class:`~graspcompass.errors.NonFiniteValueError`.

    Examples
    --------
    >>> from sympy import sqrt
    >>> evaluate(Point(sqrt(2), 1))
    (1.4142135623730951, 1.0)
    >>> evaluate(Circle(Point(0, 0), 2))
    ((0.0, 0.0), 1.4142135623730951)
    """
    if not isinstance(obj, (Point, Line, Circle, sp.Basic)):
        obj = real_value(obj, "evaluate")
    if subs:
        subs = substitutions(subs, _free(obj), "subs", strict=False)
    if isinstance(obj, Point):
        return _f(obj.x, subs), _f(obj.y, subs)
    if isinstance(obj, Line):
        return evaluate(obj.point, subs), evaluate(obj.direction, subs)
    if isinstance(obj, Circle):
        return evaluate(obj.center, subs), _f(obj.radius2, subs) ** 0.5
    return _f(obj, subs)
