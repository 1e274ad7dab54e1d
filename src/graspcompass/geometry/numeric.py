"""Numeric evaluation of kernel values (floats, for drawing and checks)."""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from .primitives import Circle, Line, Point

__all__ = ["evaluate"]


def _f(expr: sp.Expr, subs: Mapping | None) -> float:
    e = expr.subs(subs) if subs else expr
    try:
        return float(e.evalf(17))
    except TypeError as exc:
        free = ", ".join(sorted(map(str, e.free_symbols)))
        raise ValueError(f"cannot evaluate {expr} numerically: free symbols {free}") from exc


def evaluate(obj: Point | Line | Circle | sp.Expr, subs: Mapping | None = None):
    """Float values of an exact object, with optional symbol substitutions.

    Returns ``(x, y)`` for a point, ``((px, py), (dx, dy))`` for a line,
    ``((cx, cy), r)`` for a circle and a float for an expression.

    Examples
    --------
    >>> from sympy import sqrt
    >>> evaluate(Point(sqrt(2), 1))
    (1.4142135623730951, 1.0)
    >>> evaluate(Circle(Point(0, 0), 2))
    ((0.0, 0.0), 1.4142135623730951)
    """
    if isinstance(obj, Point):
        return _f(obj.x, subs), _f(obj.y, subs)
    if isinstance(obj, Line):
        return evaluate(obj.point, subs), evaluate(obj.direction, subs)
    if isinstance(obj, Circle):
        return evaluate(obj.center, subs), _f(obj.radius2, subs) ** 0.5
    return _f(sp.sympify(obj), subs)
