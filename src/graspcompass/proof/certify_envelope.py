"""Facts of the outer envelope (eq. (25), §3.3 "outside extraction", Fig. 5).

Each arc of the envelope is won by one circle n (or by O where every k ≤ 0).
The facts: the arcs join up and cover one full turn; the end points of an arc
of circle n lie on the paper's circle on O V_n; and circle n is the outermost
on the whole arc.  For the last one, k_n − k_m (and k_n − 0) is a sinusoid
``A sin(θ − α)`` of eq. (27), non-negative on a closed half turn: if it is ≥ 0
at both ends of a piece shorter than π, it is ≥ 0 on the whole piece (leaving
the half turn and coming back would take more than π).  So the arc is cut into
pieces shorter than π and the sign is decided at every cut; at an end point
B ≠ O the sign of k_n − k_m is that of (V_n − V_m)·B, exact and cheap.
"""

from __future__ import annotations

import math
from typing import Any

import sympy as sp

from ..geometry import Point
from ._fact import Fact, _f
from .certify_paper import PaperModel

__all__ = ["envelope_facts"]


def _is_origin(p: Point) -> bool:
    return p.x == 0 and p.y == 0


def _k_at_point(m: PaperModel, n: int, p: Point) -> Any:
    """|p|·k_n(θ) for e(θ) along p: V_n·p (eq. (27))."""
    if n == 0:
        return sp.Integer(0)
    s, c = m.V(n)
    return s * p.x + c * p.y


def envelope_facts(env: Any, m: PaperModel) -> list[Fact]:
    """The facts of an :class:`~graspcompass.construction.envelope.Envelope`."""
    arcs, L = env.arcs, m.length
    facts: list[Fact] = []
    if not arcs:
        return [Fact("the envelope has at least one arc", 1, 0)]
    total = sum((a.theta_end - a.theta_start for a in arcs), sp.Integer(0))
    facts.append(Fact("the arcs cover one full turn", total, 2 * sp.pi, scale=lambda: 2 * math.pi))
    for j, a in enumerate(arcs):
        nxt = arcs[(j + 1) % len(arcs)]
        lab = f"arc {j + 1} ({'O' if a.n == 0 else f'circle{a.n}'})"
        gap = a.theta_end - nxt.theta_start
        turns = round(float(gap) / (2 * float(sp.pi))) if j == len(arcs) - 1 else 0
        facts.append(
            Fact(
                f"{lab} ends at the angle where arc {(j + 1) % len(arcs) + 1} starts",
                gap,
                2 * sp.pi * turns,
                scale=lambda: 2 * math.pi,
            )
        )
        for c in "xy":
            pa, pb = getattr(a.end, c), getattr(nxt.start, c)
            facts.append(
                Fact(
                    f"{lab} ends where the next arc starts ({c})",
                    pa,
                    pb,
                    scale=lambda pa=pa, pb=pb: _f(pa, pb, L),
                )
            )
        for where, p in (("starts", a.start), ("ends", a.end)):
            if a.n == 0:
                facts += [
                    Fact(
                        f"{lab} {where} at O ({c})",
                        getattr(p, c),
                        0,
                        scale=lambda p=p: _f(p.x, p.y, L),
                    )
                    for c in "xy"
                ]
            elif not _is_origin(p):
                s, cc = m.V(a.n)
                facts.append(
                    Fact(
                        f"{lab} {where} on the circle on O V{a.n}",
                        p.x**2 + p.y**2,
                        s * p.x + cc * p.y,
                        scale=lambda p=p, s=s, cc=cc: _f(p.x, p.y, L) * _f(p.x, p.y, s, cc, L),
                    )
                )
        facts += _winner_facts(a, lab, m)
    return facts


def _winner_facts(a: Any, lab: str, m: PaperModel) -> list[Fact]:
    """k_{a.n} ≥ k_m at the cuts of pieces shorter than π (eq. (25), (27))."""
    t0, t1 = a.theta_start, a.theta_end
    pieces = int(float(t1 - t0) // math.pi) + 1
    cuts: list[tuple[str, Any, Any]] = []  # (where, point or None, angle)
    for j in range(pieces + 1):
        end = a.start if j == 0 else a.end if j == pieces else None
        t = t0 + (t1 - t0) * sp.Rational(j, pieces)
        cuts.append(
            (f"θ = {float(t):.6g}", end if end is not None and not _is_origin(end) else None, t)
        )
    out = []
    for where, p, t in cuts:
        for k in range(5):
            if k == a.n:
                continue
            if p is not None:
                lhs, rhs = _k_at_point(m, a.n, p), _k_at_point(m, k, p)
            else:
                lhs = m.k(a.n, t) if a.n else sp.Integer(0)
                rhs = m.k(k, t) if k else sp.Integer(0)
            who = f"k{a.n}" if a.n else "0"
            out.append(
                Fact(
                    f"{lab}: {who} ≥ {f'k{k}' if k else '0'} at {where} (eq. (27))",
                    lhs - rhs,
                    0,
                    kind="nonneg",
                    scale=lambda lhs=lhs, rhs=rhs: _f(lhs, rhs, m.length),
                )
            )
    return out
