"""The decisions behind ``graspcompass check``: what must vanish, proofs, exact replay.

:func:`claim_zeros` turns a claim of a construction file into expressions that
must vanish (and expressions that must not, its non-degeneracy conditions);
:func:`prove_zero` decides them by polynomial reduction in the model's ring
(:mod:`~graspcompass.proof.certify_algebra`) or by
:func:`~graspcompass.proof.prove_identity`; :func:`search` looks for a
counterexample by replaying the file **exactly** at sample points of the model
(every domain, condition (1) and μ = tan ξ checked by
:func:`~graspcompass.proof.model.violations`).  Used by
:mod:`graspcompass.proof.program_check`.

Examples
--------
>>> from graspcompass.construction.language import parse, replay
>>> prog = parse("param a > 0\\nA = point (0, 0)\\nB = point (a, 0)\\nM = midpoint A B\\n"
...              "claim M == point(a/2, 0)\\n")
>>> env = {s.name: s.obj for s in replay(prog).steps}
>>> zeros, nonzeros = claim_zeros(prog.claims[0], env)
>>> prove_zero(zeros, cond1=False)[0]
True
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import sympy as sp

from .. import symbols as S
from ..boundary.errors import InputError
from ..construction.language import replay
from ..construction.program import Claim, Program
from ..construction.protocol import Construction
from ..geometry import GeometryError, Line, Point
from ..geometry.exact import decide_sign, decide_zero
from ._program_zeros import (
    CheckError,
    _lengths,
    _term,
    claim_zeros,
    class_zeros,  # noqa: F401  (public before the split)
    concyclic_zeros,
    coords,
    sign_expr,
)
from .certify_algebra import _full_text, _positive, _primitive, _text, classify, ring
from .model import violations
from .program_roots import algebraic_zero, by_roots_or_hypotheses
from .prove import CONDITION_1, ProofResult, Status, prove_identity, prove_sign

if TYPE_CHECKING:
    from ..construction.protocol import Step

__all__ = [
    "DOMAIN_WORDS",
    "CheckError",
    "claim_zeros",
    "concyclic_zeros",
    "coords",
    "nonzero",
    "not_concurrent_at",
    "prove_sign_claim",
    "prove_zero",
    "replay_at",
    "search",
    "sign_expr",
    "sign_fails",
    "step_conditions",
    "zeros_fail",
]

#: The model's parameters and their domains (a file must declare them so).
DOMAIN_WORDS = {
    "x1": "positive",
    "x2": "positive",
    "y": "nonnegative",
    "phi1": "angle",
    "phi2": "angle",
    "mu1": "friction",
    "mu2": "friction",
    "xi1": "half_angle",
    "xi2": "half_angle",
}
#: Exact sample values: lengths, friction coefficients whose 1 + μ² is a square (so that
#: sin and cos of ξ = atan μ are rational) and φ in steps of π/12.
_LENGTHS = tuple(
    sp.Rational(n, d) for n, d in ((1, 2), (1, 1), (3, 2), (2, 1), (3, 1), (7, 5), (5, 3), (1, 3))
)
_MUS = tuple(
    sp.Rational(n, d)
    for n, d in ((3, 4), (4, 3), (5, 12), (12, 5), (8, 15), (1, 1), (7, 24), (15, 8))
)


# -- deciding -----------------------------------------------------------------------------
def _classified(dens: Iterable[Any], cond1: bool) -> tuple[list[str], list[str]]:
    """Denominator factors (ring elements) -> (implied with reasons, extra conditions)."""
    R = ring()
    implied: dict[str, None] = {}
    extra: dict[str, None] = {}
    for p in dens:
        if cond1:
            imp, ext = classify(p)  # ValueError: identically zero
            implied.update(dict.fromkeys(f"{t} ({why})" for t, why in imp))
            extra.update(dict.fromkeys(ext))
        else:
            q = R.reduce(p)
            if not q:
                raise ValueError(f"the condition {R.expr(p)} ≠ 0 is false for every parameter")
            if q.is_ground:
                implied[f"{_full_text(p)} ≠ 0 (a non-zero constant)"] = None
                continue
            p = _primitive(p)
            if _positive(R.reduce(p), R):
                implied[f"{_text(p, 12)} ≠ 0 (a positive polynomial of x1, x2, μ)"] = None
                continue
            extra[f"{_full_text(p)} ≠ 0"] = None
    return list(implied), list(extra)


def step_conditions(
    step: Step,
    cond1: bool,
    exclude: Iterable[sp.Expr] = (),
    tie: Mapping[sp.Symbol, sp.Expr] | None = None,
) -> tuple[list[str], list[str]]:
    """The kernel's ``≠ 0`` conditions of a step: (implied with reasons, extra).

    ``exclude``: conditions the checker states otherwise (a discriminant is ≥ 0, not
    ≠ 0); ``tie``: μ -> tan ξ where a file declares both.  ValueError: a condition
    false for every parameter."""
    R = ring()
    polys, outside = [], []
    exclude = list(exclude)
    for e in step.conditions:
        if any(decide_zero(sp.sympify(e - x)) is True for x in exclude):
            continue
        if tie:
            e = e.xreplace(tie)
        try:
            polys.append(R.frac(e)[0])
        except ValueError:
            outside.append(f"{e} ≠ 0")
    implied, extra = _classified(polys, cond1)
    return implied, extra + outside


def prove_zero(zeros: list[sp.Expr], cond1: bool) -> tuple[bool | None, list[str], list[str], str]:
    """(all vanish?, implied, extra conditions, method) by reduction in the model's ring."""
    R = ring()
    try:
        dens: list[Any] = []
        ok = True
        for z in zeros:
            good, d = R.equal(z, 0)
            ok = ok and good
            dens += d
        if not ok:
            return False, [], [], "polynomial reduction in the model's ring"
        implied, extra = _classified(dens, cond1)
        return (
            True,
            implied,
            extra,
            ("polynomial reduction modulo sin² + cos² − 1, cleared denominators"),
        )
    except ValueError:  # not a rational function of the model's generators
        pass
    fast = _fraction_zero(zeros)
    if fast:
        return (
            True,
            [],
            [],
            (
                "exact fractions of polynomials (the kernel's arithmetic): "
                "every numerator reduces to 0 modulo the relations of its "
                "roots and sin² + cos² = 1, wherever the steps are defined"
            ),
        )
    r = prove_identity(sp.Matrix(zeros), 0, intervals=CONDITION_1 if cond1 else {})
    verdict = True if r.proved else False if r.status is Status.REFUTED else None
    return verdict, list(r.implied), list(r.conditions), "prove_identity"


def _fraction_zero(zeros: list[sp.Expr]) -> bool:
    """Every expression is 0 as a fraction of polynomials in its generators (parameters,
    square roots with their squares, sine and cosine with sin² + cos² = 1): an identity
    wherever its denominators (the steps' own non-degeneracy conditions) do not vanish.
    False means only "not shown so" (the caller goes on)."""
    from ..construction._lang_values import _frac
    from ..geometry.exact import NotAFraction

    try:
        return all(_frac(sp.sympify(z), {}).is_zero() is True for z in zeros)
    except (NotAFraction, ZeroDivisionError, ValueError, TypeError):
        return False


def _witness(e: sp.Expr) -> list[sp.Expr]:
    num, den = sp.fraction(sp.together(e))
    out: list[sp.Expr] = []
    for part, k in ((num, 1), (den, -1)):
        c, fs = sp.factor_list(part)
        out.append(sp.Integer(c) ** k if c.is_Integer else c**k)
        out += [f ** (m * k) for f, m in fs]
    return out


def prove_sign_claim(
    e: sp.Expr, relation: str, cond1: bool, hyps: Sequence[Any] = ()
) -> tuple[bool | None, ProofResult | None]:
    intervals = CONDITION_1 if cond1 else {}
    if relation == "==":  # an identity: reduced to zero, or refuted by the search
        ok, implied, extra, method = prove_zero([e], cond1)
        if ok:
            return True, ProofResult(
                Status.PROVED, method, 0.0, conditions=tuple(extra), implied=tuple(implied)
            )
        if algebraic_zero(e):
            return True, ProofResult(
                Status.PROVED,
                "exactly 0: its minimal polynomial over ℚ is x (a constant algebraic number)",
                0.0,
            )
        return None, None
    r = _prove_sign_core(e, relation, cond1, intervals)
    if r[0] or relation not in (">", ">=", "<", "<=", "!="):
        return r
    return by_roots_or_hypotheses(
        e, relation, lambda x: prove_sign_claim(x, ">", cond1, hyps), hyps
    )


def _prove_sign_core(
    e: sp.Expr, relation: str, cond1: bool, intervals: Any
) -> tuple[bool | None, ProofResult | None]:
    signs = {">": [1], "<": [-1], ">=": [1], "<=": [-1], "!=": [1, -1]}[relation]
    try:
        witness = _witness(e)
    except (sp.PolynomialError, ValueError, TypeError):
        witness = None
    for s in signs:
        try:
            r = prove_sign(e, s, witness, intervals=intervals)
        except (ValueError, ArithmeticError):
            continue
        if r.proved:
            return True, r
    if relation in (">", ">=", "<", "<="):
        conds = _positive_factors(e if relation[0] == ">" else -e)
        if conds is not None:
            return True, ProofResult(
                Status.PROVED,
                "a product of positive factors: positive parameters, "
                "square roots of non-zero radicands, squared lengths (positive "
                "semi-definite quadratics) that do not vanish",
                0.0,
                conditions=tuple(f"{c} ≠ 0" for c in conds),
            )
    if relation in (">=", "<="):
        ok, implied, extra, _ = prove_zero([e], cond1)
        if ok:
            return True, ProofResult(
                Status.PROVED,
                "identically zero",
                0.0,
                conditions=tuple(extra),
                implied=tuple(implied),
            )
    return None, None


def _positive_factors(e: sp.Expr) -> list[sp.Expr] | None:
    """``e > 0`` wherever the returned expressions are non-zero, or None (not shown).

    ``e`` is split into factors (square roots kept as generators); each must be a
    positive rational, positive by the parameters' assumptions, a square root √R
    (> 0 where R ≠ 0: R is returned), or a polynomial shown ≥ 0 for all real values
    (:func:`graspcompass.geometry.roots.nonnegative`, > 0 where it is non-zero: it is
    returned), any of them to any integer power.
    """
    from ..geometry.roots import nonnegative

    try:
        num, den = sp.fraction(sp.together(sp.sympify(e)))
    except (sp.PolynomialError, TypeError, ValueError):
        return None
    conds: list[sp.Expr] = []

    def positive(part: sp.Expr) -> bool:
        try:
            c, factors = sp.factor_list(part)
        except (sp.PolynomialError, NotImplementedError, ValueError, TypeError):
            return False
        if not (sp.sympify(c) > 0):
            return False
        for f, _m in factors:
            if f.is_positive:
                continue
            if f.is_Pow and f.exp == sp.Rational(1, 2):
                if not (f.base.is_positive or nonnegative(f.base)):
                    return False
                if not f.base.is_positive:
                    conds.append(f.base)
                continue
            if (
                f.free_symbols
                and not f.atoms(sp.Pow) - {a for a in f.atoms(sp.Pow) if a.exp.is_Integer}
                and nonnegative(f)
            ):
                conds.append(f)
                continue
            return False
        return True

    if positive(num) and positive(den):
        return list(dict.fromkeys(conds))
    return None


# -- exact replay at sample points (counterexamples) --------------------------------------
def _sample(program: Program, rng: random.Random) -> dict[str, sp.Expr]:
    pt: dict[str, sp.Expr] = {}
    names = {p.name: p for p in program.params}
    for i in ("1", "2"):
        mu = rng.choice(_MUS)
        if f"mu{i}" in names:
            pt[f"mu{i}"] = mu
        if f"xi{i}" in names:
            pt[f"xi{i}"] = sp.atan(mu)
        if f"phi{i}" in names:
            pt[f"phi{i}"] = sp.pi * sp.Rational(rng.randint(1, 12), 12)
    for p in program.params:
        if p.name not in pt:
            pt[p.name] = grid_value(p.domain, rng)
    return pt


def grid_value(domain: str, rng: random.Random) -> sp.Expr:
    """An exact sample of a parameter of the given domain: an angle in steps of π/12, a
    half angle below π/2, a length of :data:`_LENGTHS` (0 one time in five where it may be,
    either sign for a real)."""
    if domain == "angle":
        return sp.pi * sp.Rational(rng.randint(1, 12), 12)
    if domain == "half_angle":
        return sp.pi * sp.Rational(rng.randint(1, 5), 12)
    if domain == "nonnegative" and rng.random() < 0.2:
        return sp.Integer(0)
    if domain == "real":
        return rng.choice(_LENGTHS) * rng.choice((-1, 1))
    return rng.choice(_LENGTHS)


def _admissible(program: Program, pt: Mapping[str, sp.Expr]) -> bool:
    return not violations({getattr(S, k): v for k, v in pt.items() if k in DOMAIN_WORDS})


def replay_at(program: Program, point: Mapping[str, Any]) -> Construction:
    """The program replayed exactly at ``point`` (parameter name -> exact value)."""
    return replay(program, dict(point))


def search(
    program: Program,
    fails: Callable[[dict[str, Any], Mapping[str, sp.Expr]], bool | None],
    tries: int = 40,
    seed: int = 2012,
) -> dict[str, str] | None:
    """A point of the model where the file, replayed exactly, makes ``fails`` True."""
    rng = random.Random(seed)
    for _ in range(tries * 3):
        pt = _sample(program, rng)
        if not _admissible(program, pt):
            continue
        tries -= 1
        if tries < 0:
            break
        try:
            c = replay_at(program, pt)
        except (GeometryError, InputError, ArithmeticError, ValueError):
            continue
        env: dict[str, Any] = {s.name: s.obj for s in c.steps}
        env["$params"] = {p.symbol: pt[p.name] for p in program.params}
        try:
            hit = fails(env, pt)
        except (KeyError, GeometryError, ArithmeticError, ValueError, TypeError):
            continue
        if hit:
            return {k: str(v) for k, v in pt.items()}
    return None


def nonzero(v: sp.Expr) -> bool:
    """``v`` (an exact number of a replay) is decided non-zero."""
    return decide_zero(sp.sympify(v)) is False  # internal: exact values of a replay


def _on(p: Point, line: Line) -> bool:
    return decide_zero(Point(p.x - line.point.x, p.y - line.point.y).cross(line.direction)) is True


def not_concurrent_at(lines: list[Line]) -> bool:
    """Decided exactly: the lines (exact values) have no common point."""
    for a, b in itertools.combinations(lines, 2):
        if decide_zero(a.direction.cross(b.direction)) is False:
            a0, b0 = a.coefficients(), b.coefficients()
            det = a0[0] * b0[1] - a0[1] * b0[0]
            p = Point((a0[1] * b0[2] - a0[2] * b0[1]) / det, (a0[2] * b0[0] - a0[0] * b0[2]) / det)
            return not all(_on(p, ln) for ln in lines)
    # all parallel: concurrent only if they are one line
    return not all(_on(ln.point, lines[0]) for ln in lines)


def zeros_fail(claim: Claim) -> Callable[[dict[str, Any], Any], bool]:
    """``fails(env, point)``: the claim is false in the exact replay ``env``."""

    def fails(env: dict[str, Any], pt: Any) -> bool:
        if claim.kind == "concurrent":  # decided as it is stated: a common point
            return not_concurrent_at([_term(t, env, {}) for t in claim.terms])  # all Refs
        zeros, nonzeros = claim_zeros(claim, env)
        if any(decide_zero(sp.sympify(n)) is not False for n in nonzeros):
            return False  # outside the claim's non-degeneracy conditions
        if (
            claim.kind == "ratio"
            and decide_sign(sp.sympify(_term(claim.terms[-1], env, _lengths(env)))) == -1
        ):
            return True  # a negative ratio of lengths
        return any(nonzero(z) for z in zeros)

    return fails


def sign_fails(claim: Claim) -> Callable[[dict[str, Any], Any], bool]:
    """``fails(env, point)``: the sign claim is false in the exact replay ``env``."""

    def fails(env: dict[str, Any], pt: Any) -> bool:
        s = decide_sign(sign_expr(claim, env))
        if s is None:
            return False
        return {">": s <= 0, "<": s >= 0, ">=": s < 0, "<=": s > 0, "!=": s == 0, "==": s != 0}[
            claim.relation
        ]

    return fails
