"""The facts each step of the drawing must establish, against the paper's statements.

A step that plays a role of the paper's recipe (``X1``, ``perp2``, ``circle3``,
``B14``...) is compared with :class:`~graspcompass.proof.certify_paper.PaperModel`:
X_n on the x-axis with P_ix X_n from (A4), Y_n on the y-axis with O Y_n from
(A5), (A8), O_M X_n = −S_n (A7), V_n = (S_n, C_n) (28)-(39), the circles on the
diameters O V_n (§3.2), each break point B_nm the reflection of O in the line of
centres (so on both circles, with k_n = k_m there, §3.3) and not O, and the
envelope's arcs won by the largest k_n of eq. (27).  Given data (O, the axes,
P1, P2, the cone sides) are compared with the grasp.  Any other step gets the
facts of its kernel operation (``line_through``: both points on the line).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..construction import Step
from ..geometry import Circle, Line, Point
from ._fact import Fact, _f
from .certify_envelope import envelope_facts
from .certify_paper import SIDES, PaperModel

__all__ = ["GIVEN_OPS", "Fact", "facts_for"]

#: Kernel operations that only record data of the problem.
GIVEN_OPS = ("point", "line_with_direction")
Pt = tuple[Any, Any]


def _xy(p: Any) -> Pt:
    return (p.x, p.y) if isinstance(p, Point) else p


def _cross(a: Pt, b: Pt) -> Any:
    return a[0] * b[1] - a[1] * b[0]


def _sub(a: Pt, b: Pt) -> Pt:
    return a[0] - b[0], a[1] - b[1]


def _point_eq(name: str, obj: Point, exp: Pt, what: str, L: Any) -> list[Fact]:
    return [
        Fact(f"{name}.{c} = {what}", a, b, scale=lambda a=a, b=b: _f(a, b, L))
        for c, a, b in (("x", obj.x, exp[0]), ("y", obj.y, exp[1]))
    ]


def _through(name: str, line: Line, p: Pt, who: str, L: Any) -> Fact:
    q, d = _xy(line.point), _xy(line.direction)
    return Fact(
        f"{name} passes through {who}",
        _cross(_sub(p, q), d),
        scale=lambda: (_f(*p, *q) + _f(L)) * _f(*d),
    )


def _parallel(name: str, line: Line, e: Pt, what: str) -> Fact:
    d = _xy(line.direction)
    return Fact(f"{name} ∥ {what}", _cross(d, e), scale=lambda: _f(*d) * _f(*e))


def _perp(name: str, line: Line, e: Pt, what: str) -> Fact:
    d = _xy(line.direction)
    return Fact(f"{name} ⟂ {what}", d[0] * e[0] + d[1] * e[1], scale=lambda: _f(*d) * _f(*e))


def _role_facts(step: Step, m: PaperModel) -> list[Fact] | None:
    """Facts of a step of the paper's recipe, or None if the name plays no role."""
    name, o, L = step.name, step.obj, m.length
    if name == "O" and isinstance(o, Point):
        return _point_eq(name, o, (0, 0), "0 (origin at the centre of mass, §2.2.1)", L)
    if name in ("x-axis", "y-axis") and isinstance(o, Line):
        e = (1, 0) if name == "x-axis" else (0, 1)
        return [_through(name, o, (0, 0), "O", L), _parallel(name, o, e, str(e))]
    if name in ("P1", "P2") and isinstance(o, Point):
        i = int(name[1])
        return _point_eq(name, o, m.P(i), "(x1, y)" if i == 1 else "(−x2, y)", L)
    if name in ("P1x", "P2x") and isinstance(o, Point):
        i = int(name[1])
        return _point_eq(name, o, m.Px(i), "(x1, 0)" if i == 1 else "(−x2, 0)", L)
    if name == "O_M" and isinstance(o, Point):
        return _point_eq(name, o, m.O_M, "(x1 − x2)/2 (midpoint of P1x P2x)", L)
    digit = name[-1]
    if not (
        len(name) >= 2
        and digit in "1234"
        and name[:-1] in ("side", "X", "perp", "Y", "OMX", "OY", "V", "circle")
    ):
        return _break_facts(step, m) if name[:1] == "B" else None
    n = int(digit)
    i, sg = SIDES[n]
    ang = f"φ{i} {'+' if sg > 0 else '−'} ξ{i}"
    kind = name[:-1]
    if kind == "side" and isinstance(o, Line):
        return [
            _through(name, o, m.P(i), f"P{i}", L),
            _parallel(
                name, o, m.side_direction(n), f"the cone side at {ang} from the negative y-axis"
            ),
        ]
    if kind == "X" and isinstance(o, Point):
        a4 = m.Px(i)[0] + m.PxX(n)
        return [
            Fact(f"{name} on the x-axis", o.y, 0, scale=lambda: _f(o.y, L)),
            Fact(
                f"(A4) P{i}x {name} = {'−' if i == 1 else ''}y·tan({ang})",
                o.x,
                a4,
                scale=lambda: _f(o.x, a4, L),
            ),
        ]
    if kind == "perp" and isinstance(o, Line):
        j = 2 if i == 1 else 1
        return [
            _through(name, o, m.foot_of(n), f"P{j}x", L),
            _perp(name, o, m.side_direction(n), f"side{n}"),
        ]
    if kind == "Y" and isinstance(o, Point):
        a5 = -(m.P(1)[0] if i == 2 else -m.P(2)[0]) * m.tan_side(n)  # −x_other·tan
        return [
            Fact(f"{name} on the y-axis", o.x, 0, scale=lambda: _f(o.x, L)),
            Fact(f"(A5) O {name} = −x{3 - i}·tan({ang})", o.y, a5, scale=lambda: _f(o.y, a5, L)),
        ]
    if kind in ("OMX", "OY") and isinstance(o, sp.Expr):
        exp = -m.S(n) if kind == "OMX" else -m.C(n)
        text = f"(A7) O_M X{n} = −S{n}" if kind == "OMX" else f"(A8) O Y{n} = −C{n}"
        return [Fact(text, o, exp, scale=lambda: _f(o, exp, L))]
    if kind == "V" and isinstance(o, Point):
        return _point_eq(name, o, m.V(n), f"(S{n}, C{n}) of eqs. (28)-(39)", L)
    if kind == "circle" and isinstance(o, Circle):
        (cx, cy), r2 = m.circle(n)
        return [
            *_point_eq(f"{name} centre", o.center, (cx, cy), f"V{n}/2", L),
            Fact(
                f"{name} radius² = |V{n}|²/4",
                o.radius2,
                r2,
                scale=lambda: _f(o.radius2, r2) + _f(L) ** 2,
            ),
        ]
    return None


def _break_facts(step: Step, m: PaperModel) -> list[Fact] | None:
    name, o = step.name, step.obj
    if not (len(name) == 3 and name[1] in "1234" and name[2] in "1234" and isinstance(o, Point)):
        return None
    a, b = int(name[1]), int(name[2])
    va, vb = m.V(a), m.V(b)
    w, p = _sub(vb, va), (o.x, o.y)
    sc = lambda: (_f(*p) + _f(*va) + _f(*vb)) * (_f(*w) + _f(*va))  # noqa: E731
    return [
        Fact(f"{name} ⟂ V{a}V{b}: k{a} = k{b} there", p[0] * w[0] + p[1] * w[1], scale=sc),
        Fact(
            f"midpoint of O{name} on the line of centres V{a}/2 V{b}/2 (so {name} is on "
            f"circle{a} and circle{b})",
            _cross(_sub(p, va), w),
            scale=sc,
        ),
        Fact(
            f"{name} ≠ O (O, V{a}, V{b} not collinear)",
            _cross(va, vb),
            kind="nonzero",
            scale=lambda: _f(*va) * _f(*vb),
        ),
    ]


def _op_facts(step: Step, env: dict[str, Any], L: Any) -> list[Fact]:
    """Facts of a kernel operation for a step outside the paper's recipe."""
    o, names = step.obj, step.inputs
    ins = [env[n] for n in names]
    if step.op == "point":
        return _point_eq(step.name, o, tuple(step.params), str(tuple(step.params)), L)
    if step.op == "line_with_direction":
        p = ins[0]
        return [
            _through(step.name, o, (p.x, p.y), names[0], L),
            _parallel(step.name, o, tuple(step.params), str(tuple(step.params))),
        ]
    if step.op == "line_through":
        return [_through(step.name, o, (p.x, p.y), n, L) for n, p in zip(names, ins)]
    if step.op == "meet":
        return [_through(n, ln, (o.x, o.y), step.name, L) for n, ln in zip(names, ins)]
    if step.op == "foot":
        p, ln = ins
        d = _xy(ln.direction)
        return [
            _through(names[1], ln, (o.x, o.y), step.name, L),
            Fact(
                f"{names[0]}{step.name} ⟂ {names[1]}",
                (p.x - o.x) * d[0] + (p.y - o.y) * d[1],
                scale=lambda: (_f(p.x, p.y, o.x, o.y) + _f(L)) * _f(*d),
            ),
        ]
    if step.op == "perpendicular":
        ln, p = ins
        return [
            _through(step.name, o, (p.x, p.y), names[1], L),
            _perp(step.name, o, _xy(ln.direction), names[0]),
        ]
    if step.op == "midpoint":
        p, q = ins
        return _point_eq(
            step.name, o, ((p.x + q.x) / 2, (p.y + q.y) / 2), f"({names[0]} + {names[1]})/2", L
        )
    if step.op == "circle_on_diameter":
        p, q = ins
        return [
            *_point_eq(
                f"{step.name} centre",
                o.center,
                ((p.x + q.x) / 2, (p.y + q.y) / 2),
                f"({names[0]} + {names[1]})/2",
                L,
            ),
            Fact(
                f"{names[0]} on {step.name}",
                (p.x - o.center.x) ** 2 + (p.y - o.center.y) ** 2,
                o.radius2,
                scale=lambda: _f(o.radius2) + _f(L) ** 2,
            ),
        ]
    if step.op == "point_from_lengths":
        sx, sy = step.params
        return _point_eq(
            step.name, o, (sx * ins[0], sy * ins[1]), f"({sx}·{names[0]}, {sy}·{names[1]})", L
        )
    if step.op == "signed_length":
        a, b, ln = ins
        d = _xy(ln.direction)
        return [
            Fact(
                f"{step.name} = ({names[1]} − {names[0]})·u",
                o * sp.sqrt(d[0] ** 2 + d[1] ** 2),
                (b.x - a.x) * d[0] + (b.y - a.y) * d[1],
                scale=lambda: (_f(o) + _f(a.x, a.y, b.x, b.y, L)) * _f(*d),
            )
        ]
    if step.op == "second_intersection":
        return [
            Fact(
                f"{step.name} on {n}",
                (o.x - c.center.x) ** 2 + (o.y - c.center.y) ** 2,
                c.radius2,
                scale=lambda c=c: _f(c.radius2) + _f(L) ** 2,
            )
            for n, c in zip(names[:2], ins[:2])
        ]
    raise ValueError(f"step {step.name!r}: no facts known for operation {step.op!r}")


def facts_for(step: Step, env: dict[str, Any], m: PaperModel) -> list[Fact]:
    """The facts ``step`` must establish: against the paper, or of its operation."""
    if step.op == "envelope":
        return envelope_facts(step.obj, m)
    facts = _role_facts(step, m)
    return facts if facts is not None else _op_facts(step, env, m.length)
