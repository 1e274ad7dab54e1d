"""Certify one construction: prove that it *is* the paper's drawing, step by step.

Each step is compared with what the paper says the object is
(:mod:`~graspcompass.proof.certify_facts`, from an independent transcription of
eqs. (28)-(39), (A4)-(A8) and §3.3 in :mod:`~graspcompass.proof.certify_paper`),
never with the grasp's own closed form.  Verdicts:

* exact numbers: each fact decided exactly — PROVED, or REFUTED;
* floats: each fact to ``1e-9`` times the magnitudes involved — NUMERIC, or REFUTED
  beyond the tolerance (never PROVED);
* symbols: each fact by polynomial reduction with cleared denominators
  (:mod:`~graspcompass.proof.certify_algebra`) — PROVED for every admissible
  parameter, with the proof's and the construction's non-degeneracy conditions
  split into those implied by the domains and condition (1) (``implied``) and
  extra hypotheses (``conditions``); or REFUTED with a counterexample: a point of
  the model (domains, (1), μ = tan ξ) at which the construction, replayed exactly,
  differs from the paper;
* given data (O, the axes, P1, P2, the cone sides): GIVEN when they match the
  grasp, REFUTED when not.
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..construction import Construction, Step
from ..construction.protocol import replay
from ..geometry import GeometryError
from ..geometry.exact import decide_sign, decide_zero
from ._budget import TIMED_OUT, Budget
from .certify_algebra import classify, ring
from .certify_facts import GIVEN_OPS, Fact, facts_for
from .certify_paper import PaperModel, model_at, paper_model
from .prove import ProofResult, Status, prove_identity

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["StepCertificate", "certify", "certify_records", "step_facts"]

#: Relative tolerance of facts on float constructions.
RTOL = 1e-9
_HYP = ("domains of x1, x2, y, φ, ξ, μ (§2.2)", "condition (1)", "μ_i = tan ξ_i (22)")


@dataclass(frozen=True)
class StepCertificate:
    """The facts of one step and the verdict on them."""

    step: str
    facts: tuple[str, ...]
    result: ProofResult


def step_facts(
    step: Step, env: dict[str, Any], model: PaperModel | None = None, grasp: Grasp | None = None
) -> list[tuple[str, Any]]:
    """``(text, expression that must vanish)`` for the facts of ``step``.

    ``model`` defaults to the paper's objects for ``grasp``; non-equality facts
    (``≠ 0``, ``≥ 0``) are returned with their expression as is.
    """
    m = model if model is not None else paper_model(grasp)
    return [(f.text, f.lhs - f.rhs) for f in facts_for(step, env, m)]


def _given(step: Step) -> bool:
    return step.op in GIVEN_OPS


# -- numbers --------------------------------------------------------------------
def _decide_exact(f: Fact) -> bool | None:
    d = sp.sympify(f.lhs - f.rhs)  # internal: a fact built from the construction
    if f.kind == "eq":
        return decide_zero(d)
    if f.kind == "nonzero":
        z = decide_zero(d)
        return None if z is None else not z
    s = decide_sign(d)
    return None if s is None else s >= 0


def _decide_float(f: Fact) -> bool | None:
    try:
        v = float(sp.N(f.lhs - f.rhs, 17))
        tol = RTOL * f.scale()
    except (TypeError, ValueError):
        return None
    if f.kind == "eq":
        return abs(v) <= tol
    if f.kind == "nonzero":
        return None if abs(v) <= tol else True
    return v >= -tol


# -- symbols ----------------------------------------------------------------------
@dataclass
class _Sym:
    ok: bool | None
    conditions: list[Any]
    method: str = "polynomial reduction, cleared denominators"


def _decide_symbolic(f: Fact) -> _Sym:
    R = ring()
    try:
        if f.kind == "eq":
            ok, dens = R.equal(f.lhs, f.rhs)
            return _Sym(ok, dens)
        n, den_powers = R.frac(sp.sympify(f.lhs - f.rhs))  # internal: a fact (sympy)
    except ValueError:  # not a rational function of the model's generators
        if f.kind != "eq":
            return _Sym(None, [])
        r = prove_identity(f.lhs, f.rhs)
        return _Sym(
            True if r.proved else (False if r.status is Status.REFUTED else None),
            [],
            "prove_identity",
        )
    if f.kind == "nonzero":  # an assumption: listed, unless identically false
        return _Sym(bool(R.reduce(n)), [n, *den_powers])
    return _Sym(None, [])


def _sample_point(rng: random.Random) -> dict[sp.Symbol, sp.Expr]:
    """A point of the model with small exact values (φ in π/12 steps, rational μ)."""
    from .. import symbols as S

    lengths = [sp.Rational(n, d) for n, d in ((1, 2), (1, 1), (3, 2), (2, 1), (3, 1), (7, 5))]
    mus = [sp.Rational(n, d) for n, d in ((1, 3), (1, 2), (1, 1), (6, 5), (2, 1), (3, 1))]
    pt: dict[sp.Symbol, sp.Expr] = {
        S.x1: rng.choice(lengths),
        S.x2: rng.choice(lengths),
        S.y: rng.choice([sp.Integer(0), *lengths]),
    }
    for phi, xi, mu in ((S.phi1, S.xi1, S.mu1), (S.phi2, S.xi2, S.mu2)):
        m = rng.choice(mus)
        pt[mu], pt[xi], pt[phi] = m, sp.atan(m), sp.pi * sp.Rational(rng.randint(1, 12), 12)
    return pt


def _violations(pt: dict[sp.Symbol, sp.Expr]) -> list[str]:
    try:
        from .model import violations
    except ImportError:  # pragma: no cover - the model module comes with the prover core
        pass
    else:
        return list(violations(pt))
    import math

    from .. import symbols as S

    bad = []
    for phi, mu in ((S.phi1, S.mu1), (S.phi2, S.mu2)):
        p, x = float(pt[phi]), math.atan(float(pt[mu]))
        if not (
            0 < p <= math.pi
            and math.pi / 2 < p + x < 1.5 * math.pi
            and -math.pi / 2 < p - x < math.pi / 2
        ):
            bad.append(f"condition (1) fails at {phi}")
    return bad


def _counterexample(
    c: Construction, index: int, text: str, model: PaperModel, tries: int = 40, seed: int = 2012
) -> dict[str, str] | None:
    """A re-checked point of the model where the replayed step ``index`` breaks ``text``."""
    rng = random.Random(seed)
    specs = [s.spec for s in c.steps[: index + 1]]
    for _ in range(tries):
        pt = _sample_point(rng)
        if _violations(pt):
            continue
        try:
            rc = replay(specs, c.grasp, subs=pt)
        except (GeometryError, ZeroDivisionError, ValueError, TypeError):
            continue
        env = {s.name: s.obj for s in rc.steps[:-1]}
        mp = model_at(model, pt)
        try:
            facts = {f.text: f for f in facts_for(rc.steps[-1], env, mp)}
        except (ValueError, TypeError, ZeroDivisionError):
            continue
        f = facts.get(text)
        if f is not None and _decide_exact(f) is False:
            return {str(k): str(v) for k, v in pt.items()}
    return None


def _result(status: Status, method: str, t0: float, bad: list[str], **kw: Any) -> ProofResult:
    return ProofResult(status, method, time.perf_counter() - t0, detail="; ".join(bad), **kw)


def _certify_step(
    c: Construction, step: Step, env: dict[str, Any], model: PaperModel, symbolic: bool
) -> tuple[list[Fact], ProofResult]:
    t0 = time.perf_counter()
    facts = facts_for(step, env, model)
    given = _given(step)
    if not symbolic:
        decide = _decide_float if model.numeric else _decide_exact
        verdicts = [decide(f) for f in facts]
        bad = [f.text for f, v in zip(facts, verdicts) if v is not True]
        if any(v is False for v in verdicts):
            return facts, _result(
                Status.REFUTED,
                "exact decision"
                if not model.numeric
                else f"float, tolerance {RTOL:g} × magnitudes",
                t0,
                [f.text for f, v in zip(facts, verdicts) if v is False],
            )
        if bad:
            return facts, _result(Status.UNDECIDED, "undecided facts", t0, bad)
        status = Status.GIVEN if given else Status.NUMERIC if model.numeric else Status.PROVED
        method = (
            "matches the grasp"
            if given
            else f"float, tolerance {RTOL:g} × magnitudes"
            if model.numeric
            else "exact decision of each fact"
        )
        return facts, _result(status, method, t0, [])
    conds: list[Any] = []
    for f in facts:
        r = _decide_symbolic(f)
        if r.ok is not True:
            if r.ok is None:
                return facts, _result(Status.UNDECIDED, r.method, t0, [f.text])
            cx = _counterexample(c, step.index, f.text, model)
            if cx is None:
                return facts, _result(
                    Status.UNDECIDED,
                    r.method + " (non-zero normal form, no re-checked counterexample)",
                    t0,
                    [f.text],
                )
            return facts, _result(
                Status.REFUTED,
                r.method + "; counterexample replayed exactly",
                t0,
                [f.text],
                counterexample=cx,
                hypotheses=_HYP,
            )
        conds += r.conditions
    R = ring()
    for e in step.conditions:
        try:
            conds.append(R.frac(e)[0])
        except ValueError:
            conds.append(None)
    implied: dict[str, str] = {}
    extra: dict[str, None] = {}
    for p in conds:
        if p is None:
            extra["a kernel condition outside the model's ring"] = None
            continue
        try:
            imp, ext = classify(p)
        except ValueError as exc:
            return facts, _result(
                Status.REFUTED,
                "degenerate: a divisor vanishes for every parameter",
                t0,
                [str(exc)],
                hypotheses=_HYP,
            )
        implied.update(imp)
        extra.update(dict.fromkeys(ext))
    status = Status.GIVEN if given else Status.PROVED
    return facts, _result(
        status,
        "polynomial reduction modulo sin² + cos² − 1, cleared denominators",
        t0,
        [],
        hypotheses=_HYP,
        conditions=tuple(extra),
        implied=tuple(f"{k} ({v})" for k, v in implied.items()),
    )


def certify(
    construction: Construction,
    progress: Callable[[int, int], None] | None = None,
    timeout: float | None = None,
    budget: Budget | None = None,
) -> list[StepCertificate]:
    """Prove that every step of ``construction`` is the paper's (§3.3, (28)-(39), (A4)-(A8)).

    ``timeout`` bounds the whole run (seconds, ``None``: no limit): the
    certificates made by then are kept, every later step is UNDECIDED with the
    method :data:`~graspcompass.proof._budget.TIMED_OUT`; ``budget`` shares one
    budget with the caller instead.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> certs = certify(internal_force_diagram(Grasp.preset("table1a")))
    >>> sorted({c.result.status.value for c in certs})
    ['GIVEN', 'PROVED']
    """
    model = paper_model(construction.grasp)
    # internal: the grasp's values, already read by graspcompass.inputs when it was made
    symbolic = any(sp.sympify(v).free_symbols for v in model.values.values())
    env: dict[str, Any] = {}
    out = []
    budget = budget if budget is not None else Budget(timeout)
    for i, step in enumerate(construction.steps):
        facts, result = budget.run(
            lambda step=step: _certify_step(construction, step, env, model, symbolic),
            lambda: (
                [],
                ProofResult(
                    Status.UNDECIDED,
                    TIMED_OUT,
                    0.0,
                    hypotheses=_HYP,
                    detail=f"--timeout {budget.seconds:g} s",
                ),
            ),
        )
        out.append(StepCertificate(step.name, tuple(f.text for f in facts), result))
        env[step.name] = step.obj
        if progress:
            progress(i + 1, len(construction.steps))
    return out


def certify_records(certs: list[StepCertificate]) -> list[dict[str, Any]]:
    """JSON-ready rows: step, status, facts, conditions, implied, counterexample, seconds."""
    return [
        dict(
            step=c.step,
            status=c.result.status.value,
            method=c.result.method,
            facts=list(c.facts),
            detail=c.result.detail,
            conditions=list(c.result.conditions),
            implied=list(c.result.implied),
            hypotheses=list(c.result.hypotheses),
            counterexample=c.result.counterexample,
            seconds=round(c.result.seconds, 4),
        )
        for c in certs
    ]
