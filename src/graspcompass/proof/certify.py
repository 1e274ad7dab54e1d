"""Certify one construction: prove every step from the facts it must establish.

Each step of a :class:`~graspcompass.construction.Construction` establishes
facts that do not depend on how the kernel computed it: X_n lies on the cone
side and on the x-axis, the perpendicular is perpendicular, O_M is the
midpoint, V_n is (−O_M X_n, −O Y_n), the circles pass through O and V_n, the
break points lie on both circles... Each fact is an expression that must
vanish; exact numbers are decided exactly (their radicals included), symbolic
ones by polynomial reduction.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..construction import Construction, Step
from ..geometry import Circle, Line, Point
from ..geometry.exact import decide_zero
from .prove import ProofResult, Status, prove_identity

__all__ = ["StepCertificate", "certify", "step_facts"]


@dataclass(frozen=True)
class StepCertificate:
    """The facts of one step and the verdict on them."""

    step: str
    facts: tuple[str, ...]
    result: ProofResult


def _on_line(p: Point, line: Line) -> sp.Expr:
    return (p.x - line.point.x) * line.direction.y - (p.y - line.point.y) * line.direction.x


def _on_circle(p: Point, c: Circle) -> sp.Expr:
    return (p.x - c.center.x) ** 2 + (p.y - c.center.y) ** 2 - c.radius2


def step_facts(step: Step, env: dict[str, Any]) -> list[tuple[str, sp.Expr]]:
    """``(text, expression that must be 0)`` for the facts ``step`` establishes."""
    o, ins = step.obj, [env[n] for n in step.inputs]
    names = step.inputs
    if step.op == "meet":
        return [(f"{step.name} on {n}", _on_line(o, ln)) for n, ln in zip(names, ins)]
    if step.op == "foot":
        p, ln = ins
        return [(f"{step.name} on {names[1]}", _on_line(o, ln)),
                (f"{names[0]}{step.name} ⟂ {names[1]}",
                 (p.x - o.x) * ln.direction.x + (p.y - o.y) * ln.direction.y)]
    if step.op == "perpendicular":
        ln, p = ins
        return [(f"{step.name} through {names[1]}", _on_line(p, o)),
                (f"{step.name} ⟂ {names[0]}", o.direction.x * ln.direction.x
                 + o.direction.y * ln.direction.y)]
    if step.op == "midpoint":
        p, q = ins
        return [(f"2·{step.name} = {names[0]} + {names[1]} (x)", 2 * o.x - p.x - q.x),
                (f"2·{step.name} = {names[0]} + {names[1]} (y)", 2 * o.y - p.y - q.y)]
    if step.op == "signed_length":
        a, b, ln = ins
        d = ln.direction
        return [(f"{step.name} = ({names[1]} − {names[0]})·u", o * sp.sqrt(d.x**2 + d.y**2)
                 - ((b.x - a.x) * d.x + (b.y - a.y) * d.y))]
    if step.op == "point_from_lengths":
        a, b = ins
        sx, sy = step.params
        return [(f"{step.name}.x = {sx}·{names[0]}", o.x - sx * a),
                (f"{step.name}.y = {sy}·{names[1]}", o.y - sy * b)]
    if step.op == "circle_on_diameter":
        return [(f"{n} on {step.name}", _on_circle(p, o)) for n, p in zip(names, ins)]
    if step.op == "second_intersection":
        c1, c2, k = ins
        if o.x.free_symbols or o.y.free_symbols:
            # symbolic: the mirror image of the common point K in the line of centres is
            # the other common point; two linear facts instead of two quadratic ones
            w = c2.center - c1.center
            return [(f"{step.name}K ⟂ line of centres",
                     (o.x - k.x) * w.x + (o.y - k.y) * w.y),
                    (f"midpoint of {step.name}K on the line of centres",
                     ((o.x + k.x) / 2 - c1.center.x) * w.y - ((o.y + k.y) / 2 - c1.center.y) * w.x)]
        return [(f"{step.name} on {names[0]}", _on_circle(o, c1)),
                (f"{step.name} on {names[1]}", _on_circle(o, c2))]
    if step.op == "envelope":
        facts = []
        for a in o.arcs:
            if a.n:
                c = env[f"circle{a.n}"]
                facts += [(f"arc {a.n} starts on circle{a.n}", _on_circle(a.start, c)),
                          (f"arc {a.n} ends on circle{a.n}", _on_circle(a.end, c))]
        return facts
    return []  # given data: points, the axes, the cone sides


def _decide(expr: sp.Expr) -> Status:
    if expr.free_symbols:
        return prove_identity(expr).status
    z = decide_zero(expr)
    return Status.PROVED if z else Status.REFUTED if z is False else Status.UNDECIDED


def certify(construction: Construction,
            progress: Callable[[int, int], None] | None = None) -> list[StepCertificate]:
    """Prove every step of ``construction`` exactly (its radicals, or its symbols).

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> certs = certify(internal_force_diagram(Grasp.preset("table1a")))
    >>> all(c.result.proved for c in certs)
    True
    """
    env: dict[str, Any] = {}
    out = []
    for i, step in enumerate(construction.steps):
        t0 = time.perf_counter()
        facts = step_facts(step, env)
        statuses = [_decide(e) for _, e in facts]
        if all(s is Status.PROVED for s in statuses):
            status = Status.PROVED
        elif Status.REFUTED in statuses:
            status = Status.REFUTED
        else:
            status = Status.UNDECIDED
        method = "given" if not facts else "exact zero test of each fact"
        bad = [t for (t, _), s in zip(facts, statuses) if s is not Status.PROVED]
        out.append(StepCertificate(step.name, tuple(t for t, _ in facts), ProofResult(
            status, method, time.perf_counter() - t0, detail="; ".join(bad))))
        env[step.name] = step.obj
        if progress:
            progress(i + 1, len(construction.steps))
    return out
