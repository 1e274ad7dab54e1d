"""What must vanish for a claim of a construction file to hold (and what must not).

The polynomials of each claim kind, from the paper's (equal, on, collinear, parallel,
perpendicular, concurrent) to a geometry class's (concyclic, congruent, equal angles,
angles, tangent, ratio).  Private to :mod:`graspcompass.proof.program_decide`, which
re-exports every public name (their ``__module__`` is that module's).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from typing import Any

import sympy as sp

from ..boundary.errors import InputError
from ..construction.program import Claim, PointValue, Ref
from ..geometry import Circle, Line, Point
from ..geometry.exact import decide_zero
from ..geometry.trig import sincos

__all__ = ["CheckError", "claim_zeros", "concyclic_zeros", "coords", "sign_expr"]


class CheckError(InputError):
    """A file that cannot be checked as asked (``against="paper"`` without the paper's
    parameters, or with no object named like a point of the paper)."""


# -- what must vanish ---------------------------------------------------------------------
def coords(obj: Any) -> tuple[sp.Expr, ...]:
    if isinstance(obj, Point):
        return obj.x, obj.y
    if isinstance(obj, Circle):
        return obj.center.x, obj.center.y, obj.radius2
    if isinstance(obj, sp.Expr):
        return (obj,)
    raise CheckError(f"cannot compare a {type(obj).__name__}")


def _term(t: Any, env: Mapping[str, Any], lengths: Mapping[sp.Symbol, Any]) -> Any:
    if isinstance(t, Ref):
        return env[t.name]
    if isinstance(t, PointValue):
        return Point(t.x.xreplace(lengths), t.y.xreplace(lengths))
    return t.expr.xreplace(lengths)


def _lengths(env: Mapping[str, Any]) -> dict[sp.Basic, Any]:
    """The claim's symbols -> values: lengths of the construction, and (at a sample point,
    under the key ``"$params"``) the parameters' exact values."""
    out: dict[sp.Basic, Any] = {
        sp.Symbol(k, real=True): v for k, v in env.items() if isinstance(v, sp.Expr)
    }
    out.update(env.get("$params", {}))
    return out


def _line_zero(a: Line, b: Line) -> list[sp.Expr]:
    return [
        a.direction.cross(b.direction),
        Point(b.point.x - a.point.x, b.point.y - a.point.y).cross(a.direction),
    ]


def claim_zeros(claim: Claim, env: Mapping[str, Any]) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """``(expressions that must vanish, expressions that must not)`` for a non-sign claim."""
    objs = [_term(t, env, _lengths(env)) for t in claim.terms]
    if claim.kind == "equal":
        a, b = objs
        if isinstance(a, Line):
            return _line_zero(a, b), []
        return [x - y for x, y in zip(coords(a), coords(b))], []
    if claim.kind == "on":
        p, c = objs
        if isinstance(c, Circle):
            return [(p.x - c.center.x) ** 2 + (p.y - c.center.y) ** 2 - c.radius2], []
        return [Point(p.x - c.point.x, p.y - c.point.y).cross(c.direction)], []
    if claim.kind == "collinear":  # rank of the differences <= 1: every pair, any repetition
        a = objs[0]
        return [
            Point(b.x - a.x, b.y - a.y).cross(Point(c.x - a.x, c.y - a.y))
            for b, c in itertools.combinations(objs[1:], 2)
        ], []
    if claim.kind == "concyclic":
        return concyclic_zeros(objs), []
    if claim.kind == "parallel":
        return [objs[0].direction.cross(objs[1].direction)], []
    if claim.kind == "perpendicular":
        return [objs[0].direction.dot(objs[1].direction)], []
    if claim.kind == "concurrent":
        return _concurrent_zeros(objs)
    return class_zeros(claim.kind, objs)


def _vec(a: Point, b: Point) -> Point:
    return Point(b.x - a.x, b.y - a.y)


def _d2(a: Point, b: Point) -> sp.Expr:
    v = _vec(a, b)
    return v.x**2 + v.y**2


def _angle(a: Point, b: Point, c: Point) -> tuple[sp.Expr, sp.Expr]:
    """The directed angle ABC (from ray BA to ray BC) as the complex number
    conj(A − B)(C − B) = u·v + i u×v: its argument is the angle, its modulus |u||v|."""
    u, v = _vec(b, a), _vec(b, c)
    return u.dot(v), u.cross(v)


def class_zeros(kind: str, objs: list[Any]) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """The claims of a geometry class (issue 24), as polynomials that must vanish:

    * ``congruent A B C D``: |AB|² − |CD|² (lengths are ≥ 0, so equal squares suffice);
    * ``equal_angles A B C D E F``: the directed angles ABC ≡ DEF (mod π): with
      z = conj(A − B)(C − B), w likewise, Im(z·conj(w)) = 0, the arms of non-zero length;
    * ``angles A B C ... == a``: Σ ABC ≡ a (mod π): Im(Π z · e^(−ia)) = 0;
    * ``tangent l c``: the line-circle discriminant vanishes (one common point);
      ``tangent c1 c2``: (d² − r1² − r2²)² − 4 r1² r2² = 0, d = |O1O2| ≠ 0
      (d = r1 + r2 or d = |r1 − r2|);
    * ``ratio A B C D == k``: |AB|² − k²|CD|², |CD| ≠ 0 (and k ≥ 0, proved by the checker).
    """
    if kind == "congruent":
        a, b, c, d = objs
        return [_d2(a, b) - _d2(c, d)], []
    if kind == "equal_angles":
        (x1, y1), (x2, y2) = _angle(*objs[:3]), _angle(*objs[3:])
        return [y1 * x2 - x1 * y2], [
            _d2(objs[0], objs[1]),
            _d2(objs[1], objs[2]),
            _d2(objs[3], objs[4]),
            _d2(objs[4], objs[5]),
        ]
    if kind == "angles":
        *pts, value = objs
        re_, im_ = sp.Integer(1), sp.Integer(0)
        nonzeros = []
        for i in range(0, len(pts), 3):
            x, y = _angle(*pts[i : i + 3])
            re_, im_ = re_ * x - im_ * y, re_ * y + im_ * x
            nonzeros += [_d2(pts[i], pts[i + 1]), _d2(pts[i + 1], pts[i + 2])]
        s, c = sincos(sp.sympify(value))
        return [im_ * c - re_ * s], nonzeros
    if kind == "tangent":
        a, b = objs
        if isinstance(a, Circle) and isinstance(b, Circle):
            d2 = _d2(a.center, b.center)
            return [(d2 - a.radius2 - b.radius2) ** 2 - 4 * a.radius2 * b.radius2], [d2]
        line, circle = (a, b) if isinstance(a, Line) else (b, a)
        dd = line.direction
        w = _vec(circle.center, line.point)
        return [dd.dot(w) ** 2 - dd.dot(dd) * (w.dot(w) - circle.radius2)], []
    if kind == "ratio":
        a, b, c, d, k = objs
        return [_d2(a, b) - k**2 * _d2(c, d)], [_d2(c, d)]
    raise CheckError(f"unknown claim kind {kind!r}")  # pragma: no cover - parser checks


def concyclic_zeros(points: list[Point]) -> list[sp.Expr]:
    """Points on one circle or one line: the rows ``(x² + y², x, y, 1)`` have rank ≤ 3,
    every 4 × 4 minor vanishes (any repetition: a repeated point adds a repeated row).

    A null vector ``(a, b, c, d)`` is the curve ``a(x² + y²) + bx + cy + d = 0``: a line
    when ``a = 0``, else a circle through the points; with at most three distinct points
    some such curve always exists (a line through two, the circle or line through three).
    """
    rows = [[p.x**2 + p.y**2, p.x, p.y, 1] for p in points]
    return [
        sp.Matrix([rows[i] for i in quad]).det(method="berkowitz")
        for quad in itertools.combinations(range(len(rows)), 4)
    ]


def _concurrent_zeros(lines: list[Line]) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """Lines with a common point: two lines ``i, j`` that are not parallel (kept as the
    condition) and every other row in the span of theirs (det of rows i, j, r); when
    every pair is parallel for all parameters, every line is line 0 (same point set)."""
    for i, j in itertools.combinations(range(len(lines)), 2):
        cross = lines[i].direction.cross(lines[j].direction)
        if decide_zero(sp.sympify(cross)) is True:
            continue
        rows = [sp.Matrix([list(ln.coefficients())]) for ln in lines]
        zeros = [
            sp.Matrix.vstack(rows[i], rows[j], rows[r]).det()
            for r in range(len(lines))
            if r not in (i, j)
        ]
        return zeros, [cross]
    a = lines[0]
    return [
        Point(b.point.x - a.point.x, b.point.y - a.point.y).cross(a.direction) for b in lines[1:]
    ], []


def sign_expr(claim: Claim, env: Mapping[str, Any]) -> sp.Expr:
    a, b = (_term(t, env, _lengths(env)) for t in claim.terms)
    return sp.sympify(a - b)  # internal: values of the construction


# documented and pickled as graspcompass.proof.program_decide's (which re-exports them)
for _public in (CheckError, coords, claim_zeros, class_zeros, concyclic_zeros, sign_expr):
    _public.__module__ = "graspcompass.proof.program_decide"
