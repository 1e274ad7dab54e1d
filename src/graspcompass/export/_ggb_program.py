"""GeoGebra for a construction file: sliders for its parameters, ``Prove`` for its claims.

A file's parameters become number sliders (labelled by their names, in their declared
domains, at the values given); its given points (``point``), directions
(``line_with_direction``), radii (``circle_radius``), angles (``rotate``) and ratios
(``homothety``) are written in those sliders, so that moving a slider moves the whole
construction.  Each claim GeoGebra's prover can state becomes a boolean
``claimN = Prove[...]`` and a list ``claimNdetails = ProveDetails[...]`` (its
non-degeneracy conditions), so that a teacher can compare GeoGebra's verdict with
``graspcompass check``.  Private to :mod:`graspcompass.export.geogebra`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any
from xml.sax.saxutils import quoteattr

import sympy as sp

if TYPE_CHECKING:
    from ..construction.program import Claim, Program
    from ..construction.protocol import Step

__all__ = ["claim_statements", "live", "param_label", "sliders", "symbolic_values"]

_RESERVED = {"x", "y", "z", "e", "i", "pi", "E"}


def param_label(name: str) -> str:
    """The slider's label for a parameter (GeoGebra's own names get a trailing ``_p``)."""
    return f"{name}_p" if name in _RESERVED else name


def _a(**attrs: Any) -> str:
    return " ".join(f"{k}={quoteattr(str(v))}" for k, v in attrs.items())


def _text(value: sp.Expr, program: Program) -> str:
    names = {p.symbol: sp.Symbol(param_label(p.name)) for p in program.params}
    return "(" + sp.sstr(sp.sympify(value).xreplace(names)).replace("**", "^") + ")"


def sliders(program: Program, values: Mapping[str, Any]) -> list[str]:
    """``<element type="numeric">`` sliders, one per parameter, at its value."""
    out = []
    for i, p in enumerate(program.params):
        v = float(sp.sympify(values[p.name]))
        top = float(max(4.0, math.ceil(2 * abs(v))))
        lo, hi = {
            "angle": (0.01, round(math.pi, 6)),
            "half_angle": (0.01, 1.5707),
            "real": (-top, top),
            "nonnegative": (0.0, top),
        }.get(p.domain, (0.01, top))
        out += [
            f"<element {_a(type='numeric', label=param_label(p.name))}>",
            f"\t<caption {_a(val=f'{p.name} ({p.domain})')}/>",
            f"\t<value {_a(val=repr(v))}/>",
            f"\t<slider {_a(min=repr(lo), max=repr(hi), width=180, x=20, y=30 + 36 * i)} "
            f"{_a(fixed='true', horizontal='true', showAlgebra='true')} "
            f"{_a(absoluteScreenLocation='true')}/>",
            f"\t<show {_a(object='true', label='true')}/>",
            f"\t<labelMode {_a(val=1)}/>",
            "</element>",
        ]
    return out


def symbolic_values(program: Program) -> dict[str, tuple[str, ...]]:
    """Step name -> its values written in the sliders (the steps whose values use them)."""
    out = {}
    for s in program.steps:
        if s.values and any(getattr(v, "free_symbols", ()) for v in s.values):
            out[s.name] = tuple(_text(v, program) for v in s.values)
    return out


def live(d: Any, step: Step, vals: tuple[str, ...]) -> Any:
    """The step's GeoGebra definition ``d`` with its values written in the sliders."""
    from dataclasses import replace

    from ._ggb_defs import ggb_label

    ins = tuple(ggb_label(n) for n in step.inputs)
    if step.op == "point":
        return replace(d, command=None, inputs=(), exp=f"({vals[0]}, {vals[1]})")
    if step.op == "line_with_direction" and d.command == "Line":
        return replace(d, inputs=(ins[0], f"{ins[0]} + ({vals[0]}, {vals[1]})"))
    if step.op == "circle_radius":
        return replace(d, inputs=(ins[0], vals[0]))
    if step.op in ("rotate", "homothety"):
        return replace(d, inputs=(ins[0], vals[0], ins[1]))
    return d


def _claim(c: Claim) -> str | None:
    found = [getattr(t, "name", None) for t in c.terms]
    names = [n for n in found if n is not None]
    if len(names) < len(found) and c.kind not in ("equal",):
        return None
    k = c.kind
    if k == "collinear" and len(names) == 3:
        return f"AreCollinear[{', '.join(names)}]"
    if k == "concyclic" and len(names) == 4:
        return f"AreConcyclic[{', '.join(names)}]"
    if k == "concurrent" and len(names) == 3:
        return f"AreConcurrent[{', '.join(names)}]"
    if k in ("parallel", "perpendicular"):
        return f"Are{k.capitalize()}[{names[0]}, {names[1]}]"
    if k == "congruent":
        a, b, cc, d = names
        return f"AreCongruent[Segment[{a}, {b}], Segment[{cc}, {d}]]"
    if k == "equal" and len(names) == len(found):
        return f"AreEqual[{names[0]}, {names[1]}]"
    return None


def claim_statements(program: Program) -> list[str]:
    """``Prove`` and ``ProveDetails`` of each claim GeoGebra's prover states, in order."""
    out = []
    for i, c in enumerate(program.claims, 1):
        stmt = _claim(c)
        if stmt is None:
            continue
        for cmd, label, kind in (
            ("Prove", f"claim{i}", "boolean"),
            ("ProveDetails", f"claim{i}details", "list"),
        ):
            out += [
                f"<command {_a(name=cmd)}>",
                f"\t<input {_a(a0=stmt)}/>",
                f"\t<output {_a(a0=label)}/>",
                "</command>",
                f"<element {_a(type=kind, label=label)}>",
                f"\t<caption {_a(val=f'claim (line {c.line}): {cmd}')}/>",
                f"\t<show {_a(object='false', label='true')}/>",
                "</element>",
            ]
    return out
