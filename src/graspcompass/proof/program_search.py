"""Counterexamples to a file's claims: points where every object exists and the claim fails.

A candidate point comes from three sources: the old exact grid (φ in steps of
π/12, friction coefficients whose 1 + μ² is a square), random points (angles
``atan r`` and ``π − atan r`` with rational sine and cosine, p·π/q, lengths
p/q), and *adversarial* points: the claim's value evaluated in floating point
at many random points, the ones where it comes closest to failing rounded to
nearby exact points.  A point is a counterexample only after

* the model's exact check (:func:`~graspcompass.proof.model.violations`: the
  domains, μ = tan ξ, and condition (1) when the claim or one of its steps uses it);
* the exact replay of the steps the claim depends on (the kernel refuses
  parallel lines that must meet, a branch that does not exist);
* every condition those steps and the claim need, as written (divisors ≠ 0,
  radicands ≥ 0, discriminants ≥ 0, distinct points of a circle: the
  :mod:`~graspcompass.proof.program_conditions`) decided true **exactly** there;
* the claim decided false exactly there.

Examples
--------
>>> from graspcompass.construction.language import parse
>>> prog = parse("param phi1 angle\\nparam xi1 half_angle\\n"
...              "claim sign cos(phi1+xi1)+1/100 < 0\\n")
>>> from graspcompass.proof.program_decide import sign_fails
>>> point = find(prog, sign_fails(prog.claims[0]), prog.claims[0], cond1=False)
>>> sorted(point)
['phi1', 'xi1']
"""

from __future__ import annotations

import dataclasses
import random
from collections.abc import Callable, Iterable, Mapping
from fractions import Fraction
from typing import Any

import mpmath
import sympy as sp

from .. import symbols as S
from ..boundary.errors import InputError
from ..boundary.expr import Condition
from ..construction.program import Claim, Program
from ..geometry import GeometryError
from ..geometry.exact import decide_sign
from ..geometry.trig import sincos
from .model import violations
from .program_conditions import operation_conditions
from .program_decide import grid_value
from .program_hypotheses import holds

__all__ = ["conditions_hold", "find", "sign_score", "value_at", "witness_point"]

_MODEL = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")
_GRID_MUS = tuple(
    sp.Rational(n, d)
    for n, d in ((3, 4), (4, 3), (5, 12), (12, 5), (8, 15), (1, 1), (7, 24), (15, 8))
)
_FAILURES = (
    GeometryError,
    InputError,
    ArithmeticError,
    ValueError,
    TypeError,
    KeyError,
    AttributeError,
    NotImplementedError,
    RecursionError,
)


# -- exact values at a point -----------------------------------------------------------------
def value_at(expr: sp.Expr, point: Mapping[sp.Symbol, sp.Expr]) -> sp.Expr:
    """``expr`` at an exact point: symbols replaced, sin/cos/tan of the parameters' forms
    given their exact values (:func:`graspcompass.geometry.trig.sincos`)."""
    table: dict[sp.Basic, sp.Expr] = dict(point)
    for atom in expr.atoms(sp.sin, sp.cos, sp.tan):
        if not atom.free_symbols:
            continue
        arg = atom.args[0].xreplace(point)
        s, c = sincos(arg)
        table[atom] = s if isinstance(atom, sp.sin) else c if isinstance(atom, sp.cos) else s / c
    return expr.xreplace(table)


def _holds(rel: str, value: sp.Expr) -> bool:
    if value.has(sp.I, sp.zoo, sp.nan, sp.oo, -sp.oo):
        return False
    s = decide_sign(value)
    if s is None:
        return False
    return {"!=": s != 0, ">=": s >= 0, ">": s > 0}[rel]


def conditions_hold(conditions: Iterable[Condition], point: Mapping[sp.Symbol, sp.Expr]) -> bool:
    """Every condition decided true exactly at ``point`` (undecided counts as false)."""
    try:
        return all(_holds(rel, value_at(sp.sympify(e), point)) for rel, e in conditions)
    except _FAILURES:
        return False


# -- candidate points ----------------------------------------------------------------------
def _rational_angle(theta: float, den: int = 40) -> sp.Expr:
    """An exact angle near ``theta`` in (0, π) with rational sine and cosine."""
    t = Fraction(float(mpmath.tan(theta / 2))).limit_denominator(den)
    if t <= 0:
        t = Fraction(1, den)
    s, c = (
        sp.Rational(2 * t.numerator * t.denominator, t.numerator**2 + t.denominator**2),
        sp.Rational(t.denominator**2 - t.numerator**2, t.numerator**2 + t.denominator**2),
    )
    if c == 0:
        return sp.pi / 2
    return sp.atan(s / c) if c > 0 else sp.pi - sp.atan(s / -c)


def _pyth_mu(rng: random.Random) -> sp.Rational:
    q = rng.randint(2, 12)
    p = rng.randint(1, q - 1)
    return sp.Rational(2 * p * q, q * q - p * p)


def _grid(program: Program, rng: random.Random) -> dict[str, sp.Expr]:
    pt: dict[str, sp.Expr] = {}
    for p in program.params:
        if p.name not in ("mu1", "mu2", "xi1", "xi2"):
            pt[p.name] = grid_value(p.domain, rng)
    _friction(program, pt, rng.choice(_GRID_MUS), rng.choice(_GRID_MUS))
    return pt


def _friction(program: Program, pt: dict[str, sp.Expr], *mus: sp.Expr) -> None:
    names = {p.name for p in program.params}
    for i, mu in zip("12", mus):
        if f"mu{i}" in names:
            pt[f"mu{i}"] = mu
        if f"xi{i}" in names:
            pt[f"xi{i}"] = sp.atan(mu)


def _random(program: Program, rng: random.Random) -> dict[str, sp.Expr]:
    pt: dict[str, sp.Expr] = {}
    for p in program.params:
        if p.name in ("mu1", "mu2", "xi1", "xi2"):
            continue
        if p.domain in ("angle", "half_angle"):
            top = mpmath.pi if p.domain == "angle" else mpmath.pi / 2
            if rng.random() < 0.3:
                q = rng.choice((12, 18, 24, 36))
                k = rng.randint(1, q if p.domain == "angle" else q // 2 - 1)
                pt[p.name] = sp.pi * sp.Rational(k, q)
            else:
                pt[p.name] = _rational_angle(rng.uniform(0.01, float(top) - 0.01))
        elif p.domain == "nonnegative" and rng.random() < 0.15:
            pt[p.name] = sp.Integer(0)
        else:
            v = sp.Rational(rng.randint(1, 60), rng.randint(1, 12))
            pt[p.name] = v * rng.choice((-1, 1)) if p.domain == "real" else v
    _friction(program, pt, _pyth_mu(rng), _pyth_mu(rng))
    return pt


def _float_point(program: Program, rng: random.Random) -> dict[str, float]:
    out: dict[str, float] = {}
    for p in program.params:
        if p.domain == "angle":
            out[p.name] = rng.uniform(0.001, 3.14)
        elif p.domain == "half_angle":
            out[p.name] = rng.uniform(0.001, 1.57)
        elif p.domain == "real":
            out[p.name] = rng.uniform(-10, 10)
        else:
            out[p.name] = rng.choice((rng.uniform(0, 10), rng.uniform(0, 0.5)))
    for i in "12":
        if f"xi{i}" in out and f"mu{i}" in out:
            out[f"mu{i}"] = float(mpmath.tan(out[f"xi{i}"]))
    return out


def _exact_near(program: Program, fl: Mapping[str, float]) -> dict[str, sp.Expr]:
    pt: dict[str, sp.Expr] = {}
    for p in program.params:
        v = fl[p.name]
        if p.name in ("mu1", "mu2"):
            continue
        if p.name in ("xi1", "xi2"):
            pt[p.name] = _rational_angle(v, 30)
        elif p.domain in ("angle", "half_angle"):
            pt[p.name] = _rational_angle(v, 30)
        else:
            f = Fraction(float(v)).limit_denominator(20)
            pt[p.name] = sp.Rational(f.numerator, f.denominator)
            if p.domain in ("positive", "friction") and pt[p.name] <= 0:
                pt[p.name] = sp.Rational(1, 20)
    for i in "12":
        if f"mu{i}" in fl:
            xi = pt.get(f"xi{i}")
            if xi is not None:  # both declared: μ = tan ξ exactly (rational here)
                s, c = sincos(xi)
                pt[f"mu{i}"] = s / c
            else:
                f = Fraction(max(fl[f"mu{i}"], 0.01)).limit_denominator(30)
                pt[f"mu{i}"] = sp.Rational(f.numerator, f.denominator)
    return pt


def _adversarial(
    program: Program,
    score: Callable[[dict[str, float]], float],
    rng: random.Random,
    n: int = 300,
    keep: int = 10,
    cond1: bool = False,
) -> list[dict[str, sp.Expr]]:
    scored = []
    for _ in range(n):
        fl = _float_point(program, rng)
        if cond1 and not _cond1_float(fl):
            continue
        try:
            v = score(fl)
        except _FAILURES:
            continue
        if v is not None and mpmath.isfinite(v):
            scored.append((v, fl))
    scored.sort(key=lambda t: -t[0])
    return [_exact_near(program, fl) for _, fl in scored[:keep]]


def _cond1_float(fl: Mapping[str, float]) -> bool:
    for i in "12":
        phi = fl.get(f"phi{i}")
        xi = fl.get(f"xi{i}", float(mpmath.atan(fl[f"mu{i}"])) if f"mu{i}" in fl else None)
        if phi is None or xi is None:
            continue
        if not (mpmath.pi / 2 < phi + xi < 3 * mpmath.pi / 2 and abs(phi - xi) < mpmath.pi / 2):
            return False
    return True


def sign_score(
    expr: sp.Expr, relation: str, program: Program
) -> Callable[[dict[str, float]], float]:
    """How far ``expr relation 0`` is from failing at a float point (large: fails)."""
    syms = {p.name: p.symbol for p in program.params}
    f = sp.lambdify(list(syms.values()), expr, "mpmath")
    direction = {">": -1, ">=": -1, "<": 1, "<=": 1, "!=": 0, "==": 0}[relation]

    def score(fl: dict[str, float]) -> float:
        with mpmath.workdps(30):
            v = f(*(fl[n] for n in syms))
        if isinstance(v, mpmath.mpc):
            return float("-inf")
        return (
            float(direction * v)
            if direction
            else -abs(float(v))
            if relation == "!="
            else abs(float(v))
        )

    return score


# -- the search ----------------------------------------------------------------------------
def _admissible(pt: Mapping[str, sp.Expr], cond1: bool) -> bool:
    bad = violations({getattr(S, k): v for k, v in pt.items() if k in _MODEL})
    return not [b for b in bad if cond1 or not b.startswith("condition (1)")]


def find(
    program: Program,
    fails: Callable[[dict[str, Any], Mapping[str, sp.Expr]], Any],
    claim: Claim | None = None,
    *,
    cond1: bool = True,
    names: Iterable[str] | None = None,
    score: Callable[[dict[str, float]], float] | None = None,
    tries: int = 60,
    seed: int = 2012,
) -> dict[str, str] | None:
    """A point where the objects ``names`` (and their inputs) exist and ``fails`` is True.

    Parameters
    ----------
    program : Program
    fails : callable
        ``fails(env, point)`` on the exact replay ``env`` (name -> object, with the
        parameters' values under ``"$params"``).
    claim : Claim, optional
        Its own conditions (as written) must hold at the point.
    cond1 : bool
        Whether the point must satisfy condition (1) (the claim or a step uses it).
    names : iterable of str, optional
        The steps the claim depends on (default: every step).
    score : callable, optional
        A float score of a float point (larger: closer to failing), for adversarial points.
    """
    keep = (
        set(program.steps[i].name for i in range(len(program.steps)))
        if names is None
        else set(names)
    )
    sub = dataclasses.replace(
        program, steps=tuple(s for s in program.steps if s.name in keep), claims=()
    )
    rng = random.Random(seed)
    candidates: list[dict[str, sp.Expr]] = []
    if score is not None:
        candidates += _adversarial(program, score, rng, cond1=cond1)
    for k in range(tries * 3):
        candidates.append(_grid(program, rng) if k % 2 else _random(program, rng))
    used = 0
    for pt in candidates:
        if used >= tries + (10 if score else 0):
            break
        if not _admissible(pt, cond1) or not holds(program, pt):
            continue
        used += 1
        hit = _try(sub, pt, fails, claim)
        if hit:
            return {k: str(v) for k, v in pt.items()}
    return None


def _try(
    sub: Program, pt: Mapping[str, sp.Expr], fails: Callable[..., Any], claim: Claim | None
) -> bool:
    from ..construction.language import replay

    try:
        c = replay(sub, dict(pt))
    except _FAILURES:
        return False
    at = {p.symbol: pt[p.name] for p in sub.params}
    env: dict[str, Any] = {s.name: s.obj for s in c.steps}
    statements = {s.name: s for s in sub.steps}
    for st in c.steps:  # every object exists, as written
        if not conditions_hold(statements[st.name].conditions, at):
            return False
        try:
            ops, _ = operation_conditions(st.op, [env[n] for n in st.inputs], st.obj)
        except _FAILURES:
            return False
        if not conditions_hold(ops, {}):
            return False
    if claim is not None:
        lengths = {sp.Symbol(k, real=True): v for k, v in env.items() if isinstance(v, sp.Expr)}
        if not conditions_hold([(r, e.xreplace(lengths)) for r, e in claim.conditions], at):
            return False
    env["$params"] = at
    try:
        return bool(fails(env, pt))
    except _FAILURES:
        return False


def witness_point(program: Any, tries: int = 400) -> dict[str, Any] | None:
    """A point of the domains where every hypothesis holds (the search's own points), or
    None: the hypotheses may contradict each other, and nothing is PROVED under them."""
    key = id(program)
    if key in _WITNESS and _WITNESS[key][0] is program:
        return _WITNESS[key][1]
    rng, found = random.Random(2012), None
    for k in range(tries):
        pt = _grid(program, rng) if k % 2 else _random(program, rng)
        if holds(program, pt):
            found = pt
            break
    _WITNESS.clear() if len(_WITNESS) > 64 else None
    _WITNESS[key] = (program, found)
    return found


_WITNESS: dict[int, tuple[Any, Any]] = {}
