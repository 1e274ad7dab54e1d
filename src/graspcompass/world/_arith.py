"""Exact-or-float arithmetic and reading world-frame pairs, for :mod:`graspcompass.world`.

Every helper takes ``exact``: True keeps sympy numbers canonical
(:func:`~graspcompass.geometry.exact.canon`, signs decided exactly), False works
in floats.  The pairs (points, normals, outline vertices) are read through the
input boundary (:func:`~graspcompass.inputs.real_value`), a shapely Point too.

Examples
--------
>>> _vec(("3/5", "4/5"), "normal"), _sqrt(8, True), _pt((0.5, "1/3"))
((3/5, 4/5), 2*sqrt(2), '(0.5, 1/3)')
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import sympy as sp

from ..boundary.errors import SymbolicValueError, WrongTypeError
from ..boundary.inputs import real_value
from ..geometry.exact import canon, decide_sign

__all__ = ["ON_OUTLINE_TOL"]

#: Floats: a contact is on the outline (at a vertex) when within ``ON_OUTLINE_TOL`` times
#: the outline's size.
ON_OUTLINE_TOL = 1e-9

Vec = tuple[Any, Any]


# -- arithmetic on exact values or floats --------------------------------------------
def _sqrt(v: Any, exact: bool) -> Any:
    return canon(sp.sqrtdenest(sp.sqrt(v))) if exact else math.sqrt(v)


def _sign(v: Any, exact: bool) -> int | None:
    return decide_sign(canon(v)) if exact else (v > 0) - (v < 0)


def _dot(a: Vec, b: Vec) -> Any:
    return a[0] * b[0] + a[1] * b[1]


def _cross(a: Vec, b: Vec) -> Any:
    return a[0] * b[1] - a[1] * b[0]


def _sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _scaled(a: Vec, k: Any, exact: bool) -> Vec:
    return _c((a[0] * k, a[1] * k), exact)


def _c(a: Vec, exact: bool) -> Vec:
    return (canon(a[0]), canon(a[1])) if exact else (float(a[0]), float(a[1]))


def _fmt(v: Any) -> str:
    return f"{v:.6g}" if isinstance(v, float) else str(v)


def _pt(p: Vec) -> str:
    return f"({_fmt(p[0])}, {_fmt(p[1])})"


def _deg(a: Any) -> str:
    return f"{math.degrees(float(a)):.4g}°"


# -- reading the inputs ----------------------------------------------------------------
def _pair(value: Any, what: str) -> tuple[Any, Any]:
    if hasattr(value, "geom_type") and getattr(value, "geom_type", None) == "Point":
        return (value.x, value.y)  # a shapely Point
    if isinstance(value, (str, bytes, dict)) or (
        not isinstance(value, Sequence) and not hasattr(value, "__array__")
    ):
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {type(value).__name__}")
    items = list(value)
    if len(items) != 2:
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {len(items)} values")
    return items[0], items[1]


def _vec(value: Any, what: str) -> Vec:
    x, y = _pair(value, what)
    return (real_value(x, f"{what} x"), real_value(y, f"{what} y"))


def _no_symbols(values: list[Any]) -> None:
    for v in values:
        if isinstance(v, sp.Basic) and v.free_symbols:
            raise SymbolicValueError(
                f"world-frame data must be numbers, got {v} (for symbols use Grasp)"
            )


def _as_kind(v: Any, exact: bool) -> Any:
    return canon(v) if exact else float(v)
