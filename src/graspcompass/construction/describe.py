"""Plain-data views of a construction: one-line texts and JSON-ready dicts.

Exact values are written as sympy strings (``str(expr)``, which
:func:`graspcompass.expr.parse_exact` reads back for numbers), next to their
float values for convenience.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..geometry import Circle, Line, Point
from ..geometry.exact import text
from ..geometry.numeric import to_float
from .envelope import Envelope
from .protocol import Construction, Step

__all__ = ["describe", "step_record", "to_records"]


def _num(expr: sp.Expr) -> float | None:
    """The float value of ``expr``, or None if it has none (free symbols, not real).

    An expression in symbols can never become a float: it is answered at once,
    without the 17-digit evaluation (seconds per step on a symbolic grasp).
    """
    if getattr(expr, "free_symbols", None):
        return None
    try:
        return to_float(expr, 17)
    except TypeError:
        return None


def describe(obj: Any, ascii: bool = False) -> str:
    """A short exact text for a construction object (``ascii`` for TeX comments).

    Examples
    --------
    >>> describe(Point(1, "sqrt(3)/2"))
    '(1, sqrt(3)/2)'
    """
    if isinstance(obj, Point):
        return f"({text(obj.x)}, {text(obj.y)})"
    if isinstance(obj, Line):
        return f"through {describe(obj.point)} along {describe(obj.direction)}"
    if isinstance(obj, Circle):
        r2 = "radius^2" if ascii else "r²"
        return f"centre {describe(obj.center)}, {r2} = {text(obj.radius2)}"
    if isinstance(obj, Envelope):
        theta = "theta" if ascii else "θ"
        parts = [
            ("O" if a.is_zero else f"circle {a.n}") + f" for {theta} in [{text(a.theta_start)}, "
            f"{text(a.theta_end)}]"
            for a in obj.arcs
        ]
        return "; ".join(parts)
    return text(obj)


def _value(obj: Any) -> dict[str, Any]:
    if isinstance(obj, Point):
        return {"x": text(obj.x), "y": text(obj.y), "float": [_num(obj.x), _num(obj.y)]}
    if isinstance(obj, Line):
        return {"point": _value(obj.point), "direction": _value(obj.direction)}
    if isinstance(obj, Circle):
        return {
            "center": _value(obj.center),
            "radius2": text(obj.radius2),
            "radius": None if obj.radius2.free_symbols else _num(sp.sqrt(obj.radius2)),
        }
    if isinstance(obj, Envelope):
        return {
            "arcs": [
                {
                    "circle": a.n,
                    "theta_start": text(a.theta_start),
                    "theta_end": text(a.theta_end),
                    "theta_start_deg": _deg(a.theta_start),
                    "theta_end_deg": _deg(a.theta_end),
                    "start": _value(a.start),
                    "end": _value(a.end),
                }
                for a in obj.arcs
            ]
        }
    return {"exact": text(obj), "float": _num(obj)}


def _deg(theta: sp.Expr) -> float | None:
    v = _num(theta)
    return None if v is None else v * 180.0 / 3.141592653589793


def step_record(step: Step) -> dict[str, Any]:
    """One step as a JSON-ready dict (index, name, op, instrument, inputs, value, ...)."""
    return {
        "index": step.index,
        "name": step.name,
        "kind": step.kind,
        "op": step.op,
        "instrument": step.instrument,
        "inputs": list(step.inputs),
        "value": _value(step.obj),
        "conditions": [f"{c} != 0" for c in step.conditions],
        "caption": step.caption,
        "ref": step.ref,
        "key": step.key,
    }


def to_records(construction: Construction) -> list[dict[str, Any]]:
    """All steps as JSON-ready dicts, in protocol order."""
    return [step_record(s) for s in construction.steps]
