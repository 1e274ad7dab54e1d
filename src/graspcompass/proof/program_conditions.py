"""The conditions under which a file's steps and claims exist, decided one by one.

A value is kept as written: the parser collects every divisor (≠ 0), every
radicand (≥ 0) and every domain of ``tan``, ``asin``, ``acos``, ``atan2``
(:func:`graspcompass.expr.parse_with_conditions`) before sympy evaluates the
text, so ``x1*Z/(x1*Z)`` keeps ``x1*Z ≠ 0`` although its value is 1.  A step
adds the existence conditions of its operation (:func:`operation_conditions`):
a circle through two points or on a diameter needs them distinct, a line its
direction, two circles distinct centres, an intersection with a circle a
discriminant ≥ 0 (not ≠ 0: two points are made, or one when tangent).

:func:`decide` splits each condition into *implied* (shown to follow from the
domains, μ = tan ξ and condition (1) where named: an exact zero test modulo
sin² + cos² = 1, or a sign from structure, :func:`~graspcompass.proof.signs.sign_of`),
*false* (false at every point of the model: the step or claim is then REFUTED as
vacuous, never PROVED) or *extra* (listed as a condition of the result).

Examples
--------
>>> from graspcompass.symbols import x1, phi1
>>> z = sp.sin(phi1)**2 + sp.cos(phi1)**2 - 1
>>> decide([("!=", x1 * z)], cond1=False).false
['x1*(sin(phi1)**2 + cos(phi1)**2 - 1) ≠ 0']
>>> decide([(">=", -x1)], cond1=False).false
['-x1 ≥ 0']
>>> decide([("!=", x1)], cond1=False).implied
['x1 ≠ 0 (sign from the domains)']
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, Literal

import sympy as sp

from .. import symbols as S
from ..boundary.expr import Condition
from ..geometry import Circle, Line, Point
from ..geometry.exact import decide_zero
from ._program_distinct import _distinct_general, _distinct_in_ring
from ._program_signs import _positive_sum, _ring_nonzero, _sign, _zero
from .signs import CONDITION_1

__all__ = ["Decided", "decide", "operation_conditions", "tie_mu"]

_WORD = {"!=": "≠ 0", ">=": "≥ 0", ">": "> 0"}
#: Intervals that hold on the domains alone (ξ is a half angle, 0 < ξ < π/2).
_DOMAIN_INTERVALS = {S.xi1: (0, sp.pi / 2), S.xi2: (0, sp.pi / 2)}


@dataclass
class Decided:
    """Conditions split into implied (with reasons), false everywhere, and extra."""

    implied: list[str] = field(default_factory=list)
    false: list[str] = field(default_factory=list)
    extra: list[str] = field(default_factory=list)

    def add(self, other: Decided) -> None:
        """Merge ``other`` into this one (order kept, no repeats)."""
        for mine, theirs in (
            (self.implied, other.implied),
            (self.false, other.false),
            (self.extra, other.extra),
        ):
            mine += [t for t in theirs if t not in mine]


def tie_mu(names: Iterable[str]) -> dict[sp.Symbol, sp.Expr]:
    """μi -> sin ξi / cos ξi for each contact whose μ and ξ are both declared (eq. (22))."""
    names = set(names)
    return {
        getattr(S, f"mu{i}"): sp.sin(getattr(S, f"xi{i}")) / sp.cos(getattr(S, f"xi{i}"))
        for i in (1, 2)
        if f"mu{i}" in names and f"xi{i}" in names
    }


def _classified(e: sp.Expr, cond1: bool) -> tuple[list[str], list[str]] | Literal[False] | None:
    """``e ≠ 0`` by the checker's classification of ring factors (the kernel's own
    conditions are stated so, in the same words): (implied, extra), False when it is
    false for every parameter, None outside the ring."""
    from .certify_algebra import _primitive, ring
    from .program_decide import _classified as split

    try:
        p = ring().frac(e)[0]
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, RecursionError):
        return None
    if not p:
        return False
    try:
        return split([_primitive(p)], cond1)
    except ValueError:
        return False


def decide(
    conditions: Iterable[Condition], cond1: bool, tie: Mapping[sp.Symbol, sp.Expr] | None = None
) -> Decided:
    """Split ``(relation, expr)`` conditions into implied, false everywhere and extra.

    Parameters
    ----------
    conditions : iterable of (str, sympy.Expr)
        ``("!=", e)``: e ≠ 0; ``(">=", e)``: e ≥ 0; ``(">", e)``: e > 0.
    cond1 : bool
        Whether condition (1) of §2.2.2 may be used (the file or claim names it).
    tie : Mapping, optional
        μi -> tan ξi where a file declares both (:func:`tie_mu`).

    Returns
    -------
    Decided
        Texts ``"e ≠ 0 (reason)"`` implied, ``"e ≠ 0"`` false at every point of the
        model, ``"e ≥ 0"`` kept as conditions.
    """
    out = Decided()
    ties = tuple(sorted(tie.items(), key=str)) if tie else ()
    for rel, e in dict.fromkeys(conditions):
        for bucket, text in _decide_one(rel, sp.sympify(e), cond1, ties):
            # internal: conditions the parser and the kernel made
            mine = getattr(out, bucket)
            if text not in mine:
                mine.append(text)
    return out


@lru_cache(maxsize=4096)
def _decide_one(rel: str, e: sp.Expr, cond1: bool, ties: tuple) -> tuple[tuple[str, str], ...]:
    """One condition of :func:`decide`: ``((bucket, text), ...)`` with bucket one of
    implied, false, extra.  Remembered by content: the conditions of a step recur in
    every step and claim built on it."""
    intervals = CONDITION_1 if cond1 else _DOMAIN_INTERVALS
    why = "condition (1)" if cond1 else "the domains"
    if ties:
        e = e.xreplace(dict(ties))
    z = _zero(e)

    def text() -> str:  # printed only where the answer shows it (sympy prints slowly)
        return f"{e} {_WORD[rel]}"

    if z:
        return (
            (("implied", text() + " (identically zero)") if rel == ">=" else ("false", text())),
        )
    s = _sign(e, intervals)
    if s is not None:
        lo, hi = s
        holds = {"!=": lo > 0 or hi < 0, ">=": lo >= 0, ">": lo > 0}[rel]
        fails = {"!=": lo == hi == 0, ">=": hi < 0, ">": hi <= 0}[rel]
        if holds:
            return (("implied", f"{text()} (sign from {why})"),)
        if fails:  # false on the domains (or on (1)): false on the whole model
            return (("false", text()),)
    if rel in (">=", ">") and _positive_sum(-e, intervals):  # negative everywhere
        return (("false", text()),)
    if rel in (">=", ">") and _positive_sum(e, intervals):
        return (("implied", f"{text()} (a positive sum of squares and signs from {why})"),)
    if rel == "!=" and _ring_nonzero(e):
        return (
            ("implied", f"{text()} (a positive polynomial of x1, x2, μ modulo sin² + cos² = 1)"),
        )
    if rel == "!=":
        split = _classified(e, cond1)
        if split is False:
            return (("false", text()),)
        if split is not None:
            return (*(("implied", t) for t in split[0]), *(("extra", t) for t in split[1]))
    if e.is_number and not e.free_symbols and z is False:
        return (("implied", f"{text()} (a number)"),)
    return (("extra", text()),)


def _norm2(p: Point) -> sp.Expr:
    return p.x**2 + p.y**2


def _disc(line: Line, circle: Circle) -> sp.Expr:
    """The discriminant of the kernel's line-circle intersection (two points iff > 0)."""
    d = line.direction
    w = Point(line.point.x - circle.center.x, line.point.y - circle.center.y)
    a, b = d.dot(d), d.dot(w)
    return b**2 - a * (w.dot(w) - circle.radius2)


def _radical_axis(c1: Circle, c2: Circle) -> Line:
    n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
    h = (c1.radius2 - c2.radius2 + c2.center.dot(c2.center) - c1.center.dot(c1.center)) / 2
    k = h / n.dot(n)
    return Line(Point(n.x * k, n.y * k), Point(-n.y, n.x))


def operation_conditions(
    op: str, inputs: list[Any], obj: Any
) -> tuple[list[Condition], list[sp.Expr]]:
    """``(conditions the operation needs, kernel conditions they replace)``.

    The kernel records what it must divide by as ``≠ 0``; an intersection with a
    circle records its discriminant, which must be ≥ 0 for the point to exist, and a
    circle, a line or a radical axis may need two points distinct that the kernel
    does not record.  Computed from the step's inputs (exact expressions).
    """
    if op in ("circle_through", "circle_on_diameter"):
        return [("!=", obj.radius2)], []
    if op == "line_through":
        return [("!=", _norm2(obj.direction))], []
    if op == "line_with_direction":
        return [("!=", _norm2(obj.direction))], []
    if op == "intersect_line_circle":
        d = _disc(inputs[0], inputs[1])
        return [(">=", d)], [d]
    if op == "intersect_circles":
        c1, c2 = inputs
        n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
        conds: list[Condition] = [("!=", _norm2(n))]
        if decide_zero(sp.sympify(_norm2(n))) is True:
            return conds, []
        d = _disc(_radical_axis(c1, c2), c1)
        return [*conds, (">=", d)], [d]
    if op == "second_intersection":
        c1, c2, _ = inputs
        n = Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)
        return [("!=", _norm2(n))], []
    if op in ("circle_radius", "circle_compass"):
        return [("!=", obj.radius2)], []
    if op == "radical_axis":
        c1, c2 = inputs
        return [("!=", _norm2(Point(c2.center.x - c1.center.x, c2.center.y - c1.center.y)))], []
    if op == "tangent_point":
        from ..construction._ops_class import polar

        p, circle = inputs
        d = _disc(polar(p, circle), circle)
        return [(">=", d)], [d]
    return [], []


def condition_words(op: str, names: tuple[str, ...]) -> list[str]:
    """What each condition of :func:`operation_conditions` says, in geometric words
    (as GCLC prints them), in the same order."""
    a, b = (*names, "?", "?")[:2]
    return {
        "line_through": [f"{a} and {b} are distinct"],
        "line_with_direction": ["the direction is not zero"],
        "circle_through": [f"{b} is not the centre {a}"],
        "circle_on_diameter": [f"{a} and {b} are distinct"],
        "intersect_line_circle": [f"the line {a} meets the circle {b}"],
        "intersect_circles": [
            f"the centres of {a} and {b} differ",
            f"the circles {a} and {b} meet",
        ],
        "second_intersection": [f"the centres of {a} and {b} differ"],
        "circle_radius": ["the radius is not 0"],
        "circle_compass": [f"{b} and {names[2] if len(names) > 2 else '?'} are distinct"],
        "radical_axis": [f"the centres of {a} and {b} differ"],
        "tangent_point": [f"{a} is not inside the circle {b}"],
    }.get(op, [])


def distinct(a: Point, b: Point, assumed: Iterable[sp.Expr]) -> bool:
    """Proof that ``a ≠ b`` wherever the ``assumed`` expressions are non-zero and the
    lengths and friction coefficients are positive: the numerators of ``a − b``, the
    relations sin² + cos² = 1 and ``1 − t·k`` (k the product of what is non-zero) have
    the Gröbner basis [1] (Rabinowitsch), so no point makes ``a = b``.  False: no proof."""
    assumed = list(assumed)
    fast = _distinct_in_ring(a, b, assumed)
    return _distinct_general(a, b, assumed) if fast is None else fast
