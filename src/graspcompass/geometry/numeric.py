"""Numeric evaluation of kernel values (floats, for drawing and checks).

Values from outside (an expression given as text or a number, the symbol
values of ``subs``) go through :mod:`graspcompass.inputs`: text is parsed
safely, never by ``sympify``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import sympy as sp

from ..errors import InputError, NonFiniteValueError
from ..inputs import real_value, substitutions
from .primitives import Circle, Line, Point

__all__ = ["evaluate"]


def _f(expr: sp.Expr, subs: Mapping | None) -> float:
    e = expr.subs(subs) if subs else expr
    try:
        out = float(e.evalf(17))
    except TypeError as exc:
        free = ", ".join(sorted(map(str, e.free_symbols)))
        raise InputError(f"cannot evaluate {expr} numerically: free symbols {free}") from exc
    if not math.isfinite(out):
        raise NonFiniteValueError(f"cannot evaluate {expr} numerically: it is beyond double "
                                  "precision (about 1.8e308)")
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
