"""The claims of a checked construction file: each proved, refuted or left undecided.

The rows of :func:`graspcompass.proof.program_check.check_program` for the file's
``claim`` lines and the helpers its steps and targets share (the hypotheses of a
row, the steps a name is built on, the verdict from a proof or a counterexample).
Private to :mod:`graspcompass.proof.program_check`.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import sympy as sp

from ..construction.program import Claim, PointValue, Program, Ref, Value
from ._program_rows import CheckRow
from .program_conditions import decide, tie_mu
from .program_decide import (
    claim_zeros,
    prove_sign_claim,
    prove_zero,
    sign_expr,
    sign_fails,
    zeros_fail,
)
from .program_hypotheses import branch_roots
from .program_hypotheses import texts as hypothesis_texts
from .program_search import find, sign_score, witness_point
from .prove import ProofResult, Status

_COND1 = "condition1"


# -- hypotheses ---------------------------------------------------------------------------
def _domain_text(program: Program) -> list[str]:
    return [f"{p.name}: {p.domain}" for p in program.params]


def _hypotheses(program: Program, cond1: bool) -> tuple[str, ...]:
    domains = ("domains " + ", ".join(_domain_text(program)),) if program.params else ()
    return (*domains, *(("condition (1)",) if cond1 else ()), *hypothesis_texts(program))


# -- one claim ----------------------------------------------------------------------------
def _ancestors(program: Program, names: Iterable[str]) -> list[str]:
    by = {s.name: s for s in program.steps}
    seen: dict[str, None] = {}
    todo = [n for n in names if n in by]
    while todo:
        n = todo.pop()
        if n in seen:
            continue
        seen[n] = None
        todo += [i for i in by[n].inputs if i in by]
    return list(seen)


def _refs(claim: Claim) -> list[str]:
    names = []
    for t in claim.terms:
        if isinstance(t, Ref):
            names.append(t.name)
        else:
            exprs = (t.x, t.y) if isinstance(t, PointValue) else (t.expr,)
            names += [str(s) for e in exprs for s in e.free_symbols]
    return names


def _text(claim: Claim) -> str:
    return Program(claims=(claim,)).to_text().strip().removeprefix("claim ")


def _vacuous(
    name: str, kind: str, line: int, t0: float, hyps: tuple[str, ...], why: str
) -> CheckRow:
    """REFUTED without a counterexample: what it is about exists at no point of the model."""
    return CheckRow(
        name,
        kind,
        line,
        ProofResult(
            Status.REFUTED,
            "vacuous: a condition it needs is false at every point of the model "
            "(no counterexample: nothing exists there to contradict)",
            time.perf_counter() - t0,
            detail=why,
            hypotheses=hyps,
        ),
    )


def _uses_cond1(implied: Iterable[str]) -> bool:
    return any("(1)" in t for t in implied)


_CRASHES = (
    ArithmeticError,
    ValueError,
    TypeError,
    AttributeError,
    KeyError,
    IndexError,
    NotImplementedError,
    RecursionError,
    sp.PolynomialError,
)


def _guarded(
    name: str, kind: str, line: int, hyps: tuple[str, ...], run: Callable[[], CheckRow]
) -> CheckRow:
    """A row whatever happens inside: a failure of the algebra is UNDECIDED, named."""
    t0 = time.perf_counter()
    try:
        return run()
    except _CRASHES as exc:
        return CheckRow(
            name,
            kind,
            line,
            ProofResult(
                Status.UNDECIDED,
                "the checker could not decide it",
                time.perf_counter() - t0,
                detail=f"{type(exc).__name__}: {exc}"[:300],
                hypotheses=hyps,
            ),
        )


class _Later(dict):  # type: ignore[type-arg]
    """A step's conditions without condition (1), worked out when a claim first asks."""

    def __init__(self) -> None:
        super().__init__()
        self._thunks: dict[str, Callable[[], tuple[list[str], list[str]]]] = {}

    def later(self, name: str, thunk: Callable[[], tuple[list[str], list[str]]]) -> None:
        self._thunks[name] = thunk

    def get(self, name: str, default: Any = None) -> Any:
        if name not in self and name in self._thunks:
            self[name] = self._thunks.pop(name)()
        return super().get(name, default)


def _check_claim(
    program: Program,
    claim: Claim,
    env: dict[str, Any],
    step_conds: Mapping[str, tuple[list[str], list[str]]],
    vacuous: Mapping[str, str] | None = None,
) -> CheckRow:
    t0 = time.perf_counter()
    cond1 = _COND1 in claim.under
    hyps = _hypotheses(program, cond1)
    tie = tie_mu(p.name for p in program.params)
    missing = [t.name for t in claim.terms if isinstance(t, Ref) and t.name not in env]
    if missing:  # an optional step left out, or the envelope (numbers only)
        return CheckRow(
            _text(claim),
            "claim",
            claim.line,
            ProofResult(
                Status.UNDECIDED,
                "not made for general parameters",
                time.perf_counter() - t0,
                detail=f"{', '.join(missing)} is not made when the parameters are symbols",
                hypotheses=hyps,
            ),
        )
    implied: list[str] = []
    extra: list[str] = []
    ancestors = _ancestors(program, _refs(claim))
    gone = [f"{n}: {vacuous[n]}" for n in ancestors if vacuous and n in vacuous]
    lengths = {sp.Symbol(k, real=True): v for k, v in env.items() if isinstance(v, sp.Expr)}
    own = decide([(r, e.xreplace(lengths)) for r, e in claim.conditions], cond1, tie)
    if gone or own.false:
        return _vacuous(
            _text(claim),
            "claim",
            claim.line,
            t0,
            hyps,
            "; ".join([*gone, *(f"{t} is false everywhere" for t in own.false)]),
        )
    for n in ancestors:
        imp, ext = step_conds.get(n, ([], []))
        implied += imp
        extra += ext
    implied += own.implied
    extra += own.extra
    if not cond1 and _uses_cond1(implied):  # a step's condition follows from (1): say so
        hyps = _hypotheses(program, True)
    if claim.kind == "sign":
        e = branch_roots(sign_expr(claim, env), program.inequalities)
        ok, r = prove_sign_claim(
            e.xreplace(tie) if tie else e, claim.relation, cond1, program.inequalities
        )
        if ok and r is not None:
            implied += list(r.implied)
            extra += list(r.conditions)
            method = r.method
        fails = sign_fails(claim)
        try:
            score = sign_score(e, claim.relation, program)
        except (TypeError, ValueError, NameError, SyntaxError, KeyError):
            score = None
    else:
        score = None
        zeros, nonzeros = claim_zeros(claim, env)
        zeros = [branch_roots(z, program.inequalities) for z in zeros]
        if tie:
            zeros = [sp.sympify(z).xreplace(tie) for z in zeros]
        ok, imp, ext, method = prove_zero(zeros, cond1)
        if ok and claim.kind == "ratio":  # a ratio of lengths is >= 0
            k = sign_expr(Claim("sign", (claim.terms[-1], Value(sp.Integer(0)))), env)
            k_ok, k_r = prove_sign_claim(k.xreplace(tie) if tie else k, ">=", cond1)
            ok = True if k_ok else None
            imp = [*imp, *(k_r.implied if k_ok and k_r is not None else ())]
        if ok and any(prove_zero([n], cond1)[0] for n in nonzeros):
            ok = None  # a condition that never holds (two parallel lines): not a proof
        implied += imp
        extra += ext + [f"{sp.factor(n)} ≠ 0" for n in nonzeros]
        fails = zeros_fail(claim)
    # a counterexample is a point of the model: condition (1) holds there too (docs)
    search_kw = {"claim": claim, "cond1": True, "score": score, "names": ancestors}
    return _row(
        program,
        _text(claim),
        "claim",
        claim.line,
        ok,
        fails,
        t0,
        hyps,
        implied,
        extra,
        method if ok else "",
        search_kw,
    )


def _row(
    program: Program,
    name: str,
    kind: str,
    line: int,
    ok: bool | None,
    fails: Callable[[dict[str, Any], Any], bool],
    t0: float,
    hyps: tuple[str, ...],
    implied: list[str],
    extra: list[str],
    method: str,
    search_kw: Mapping[str, Any] | None = None,
) -> CheckRow:
    implied, extra = list(dict.fromkeys(implied)), list(dict.fromkeys(extra))
    if ok and program.inequalities and witness_point(program) is None:
        return CheckRow(
            name,
            kind,
            line,
            ProofResult(
                Status.UNDECIDED,
                "a proof under the file's hypotheses, but no point found where "
                "they all hold (they may contradict each other)",
                time.perf_counter() - t0,
                hypotheses=hyps,
                conditions=tuple(extra),
                implied=tuple(implied),
            ),
        )
    if ok:
        return CheckRow(
            name,
            kind,
            line,
            ProofResult(
                Status.PROVED,
                method,
                time.perf_counter() - t0,
                hypotheses=hyps,
                conditions=tuple(extra),
                implied=tuple(implied),
            ),
        )
    cx = find(program, fails, **(search_kw or {}))
    if cx is not None:
        return CheckRow(
            name,
            kind,
            line,
            ProofResult(
                Status.REFUTED,
                "counterexample: a point of the model (domains, condition (1), "
                "μ = tan ξ checked exactly) at which the file, replayed exactly, contradicts it",
                time.perf_counter() - t0,
                counterexample=cx,
                hypotheses=hyps,
            ),
        )
    return CheckRow(
        name,
        kind,
        line,
        ProofResult(
            Status.UNDECIDED,
            "not proved, and no counterexample found by exact replay at points of the model",
            time.perf_counter() - t0,
            hypotheses=hyps,
            conditions=tuple(extra),
            implied=tuple(implied),
        ),
    )


def _line(program: Program, name: str) -> int:
    return next((s.line for s in program.steps if s.name == name), 0)
