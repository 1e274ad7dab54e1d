"""Check a construction file: certify its steps, prove its claims, grade it against the paper.

:func:`check_program` takes a :class:`~graspcompass.construction.program.Program`
(from a file in the construction language or the Python builder) and returns a
:class:`ProgramReport` with one :class:`CheckRow` per step, claim and target.

* **Steps.**  The program is replayed with symbolic parameters; each step's
  non-degeneracy conditions (two lines that must meet, a radius that must not
  vanish) are split into those implied by the domains and the file's hypotheses
  and those that stay conditions of every result that uses the step.  A
  condition that vanishes for every parameter makes the step REFUTED.
* **Claims** (``claim ...`` lines) are reduced to expressions that must vanish
  (or have a sign) and decided by polynomial reduction in the model's ring
  (:mod:`~graspcompass.proof.certify_algebra`, :func:`~graspcompass.proof.prove_identity`,
  :func:`~graspcompass.proof.prove_sign`), under the parameters' domains and the
  hypotheses the claim names (``under condition1``).
* **Targets** (``against="paper"``): every object named like a point of the
  paper (``X1``-``X4``, ``Y1``-``Y4``, ``V1``-``V4``, ``circle1``-``circle4``,
  ``O_M``, ``P1x``, ``P2x``) is compared with the paper's statement for it
  (:class:`~graspcompass.proof.certify_paper.PaperModel`: §3.3, eqs. (28)-(39),
  (A4)-(A8)) for every grasp that satisfies condition (1).

A verdict is PROVED (an exact argument for every admissible parameter: the
result lists its hypotheses, the conditions shown to follow from them and the
non-degeneracy conditions that remain), REFUTED (a counterexample: a point of
the model, every domain, condition (1) and μ = tan ξ checked exactly by
:func:`~graspcompass.proof.model.violations`, at which the file, **replayed
exactly**, contradicts the claim; the point is reported only after that exact
replay) or UNDECIDED.

Examples
--------
>>> from graspcompass.construction.language import parse
>>> prog = parse('''
... param a > 0
... A = point (0, 0)
... B = point (a, 0)
... M = midpoint A B
... claim M == point(a/2, 0)
... claim M == point(a/3, 0)
... ''')
>>> r = check_program(prog)
>>> [row.status.value for row in r.claims]
['PROVED', 'REFUTED']
>>> r.claims[1].counterexample  # doctest: +SKIP
{'a': '1/2'}
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import sympy as sp

from .. import symbols as S
from ..construction.language import replay
from ..construction.program import Claim, PointValue, Program, Ref, Value
from ..construction.protocol import Construction
from ._budget import TIMED_OUT, Budget
from ._program_rows import CheckRow, ProgramReport
from .certify_paper import PaperModel, model_at
from .program_conditions import (
    condition_words,
    decide,
    distinct,
    operation_conditions,
    tie_mu,
)
from .program_decide import (
    DOMAIN_WORDS,
    CheckError,
    claim_zeros,
    coords,
    nonzero,
    prove_sign_claim,
    prove_zero,
    sign_expr,
    sign_fails,
    step_conditions,
    zeros_fail,
)
from .program_hypotheses import branch_roots, discharge
from .program_hypotheses import texts as hypothesis_texts
from .program_search import find, sign_score
from .program_words import kernel_worded
from .prove import ProofResult, Status

__all__ = ["PAPER_TARGETS", "CheckError", "CheckRow", "ProgramReport", "check_program"]

#: Names of objects graded by ``against="paper"`` -> (what the paper says it is, reference).
PAPER_TARGETS: dict[str, str] = {
    **{f"X{n}": f"X{n} on the x-axis, O_M X{n} = −S{n} (§3.3 step (1), (A7))" for n in range(1, 5)},
    **{f"Y{n}": f"Y{n} on the y-axis, O Y{n} = −C{n} (§3.3 step (2), (A8))" for n in range(1, 5)},
    **{f"V{n}": f"V{n} = (S{n}, C{n}), eqs. (28)-(39)" for n in range(1, 5)},
    **{f"circle{n}": f"the circle on the diameter O V{n} (§3.2, Fig. 3)" for n in range(1, 5)},
    "O_M": "the midpoint of P1x P2x, ((x1 − x2)/2, 0) (§3.3)",
    "P1x": "the foot of P1 on the x-axis, (x1, 0) (§3.3)",
    "P2x": "the foot of P2 on the x-axis, (−x2, 0) (§3.3)",
}
#: The parameters a file must declare to be graded against the paper.
_PAPER_PARAMS = ("x1", "x2", "y", "phi1", "phi2")
_COND1 = "condition1"


# -- hypotheses ---------------------------------------------------------------------------
def _domain_text(program: Program) -> list[str]:
    return [f"{p.name}: {p.domain}" for p in program.params]


def _hypotheses(program: Program, cond1: bool) -> tuple[str, ...]:
    domains = ("domains " + ", ".join(_domain_text(program)),) if program.params else ()
    return (*domains, *(("condition (1)",) if cond1 else ()), *hypothesis_texts(program))


def _check_model_params(program: Program) -> None:
    """A parameter named like one of the model's must have the model's domain."""
    for p in program.params:
        want = DOMAIN_WORDS.get(p.name)
        if want is not None and p.domain != want:
            raise CheckError(f"{program.file}:{p.line}:1: {p.name} is the model's parameter "
                             f"and has the domain {want}; declare it so (got {p.domain})")


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


def _vacuous(name: str, kind: str, line: int, t0: float, hyps: tuple[str, ...],
             why: str) -> CheckRow:
    """REFUTED without a counterexample: what it is about exists at no point of the model."""
    return CheckRow(name, kind, line, ProofResult(
        Status.REFUTED, "vacuous: a condition it needs is false at every point of the model "
        "(no counterexample: nothing exists there to contradict)", time.perf_counter() - t0,
        detail=why, hypotheses=hyps))


def _uses_cond1(implied: Iterable[str]) -> bool:
    return any("(1)" in t for t in implied)


_CRASHES = (ArithmeticError, ValueError, TypeError, AttributeError, KeyError, IndexError,
            NotImplementedError, RecursionError, sp.PolynomialError)


def _guarded(name: str, kind: str, line: int, hyps: tuple[str, ...],
             run: Callable[[], CheckRow]) -> CheckRow:
    """A row whatever happens inside: a failure of the algebra is UNDECIDED, named."""
    t0 = time.perf_counter()
    try:
        return run()
    except _CRASHES as exc:
        return CheckRow(name, kind, line, ProofResult(
            Status.UNDECIDED, "the checker could not decide it", time.perf_counter() - t0,
            detail=f"{type(exc).__name__}: {exc}"[:300], hypotheses=hyps))


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


def _check_claim(program: Program, claim: Claim, env: dict[str, Any],
                 step_conds: Mapping[str, tuple[list[str], list[str]]],
                 vacuous: Mapping[str, str] | None = None) -> CheckRow:
    t0 = time.perf_counter()
    cond1 = _COND1 in claim.under
    hyps = _hypotheses(program, cond1)
    tie = tie_mu(p.name for p in program.params)
    missing = [t.name for t in claim.terms if isinstance(t, Ref) and t.name not in env]
    if missing:  # an optional step left out, or the envelope (numbers only)
        return CheckRow(_text(claim), "claim", claim.line, ProofResult(
            Status.UNDECIDED, "not made for general parameters", time.perf_counter() - t0,
            detail=f"{', '.join(missing)} is not made when the parameters are symbols",
            hypotheses=hyps))
    implied: list[str] = []
    extra: list[str] = []
    ancestors = _ancestors(program, _refs(claim))
    gone = [f"{n}: {vacuous[n]}" for n in ancestors if vacuous and n in vacuous]
    lengths = {sp.Symbol(k, real=True): v for k, v in env.items() if isinstance(v, sp.Expr)}
    own = decide([(r, e.xreplace(lengths)) for r, e in claim.conditions], cond1, tie)
    if gone or own.false:
        return _vacuous(_text(claim), "claim", claim.line, t0, hyps,
                        "; ".join([*gone, *(f"{t} is false everywhere" for t in own.false)]))
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
        ok, r = prove_sign_claim(e.xreplace(tie) if tie else e, claim.relation, cond1,
                                 program.inequalities)
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
    search_kw = {"claim": claim, "cond1": True, "score": score,
                 "names": ancestors}
    return _row(program, _text(claim), "claim", claim.line, ok, fails, t0, hyps,
                implied, extra, method if ok else "", search_kw)


def _row(program: Program, name: str, kind: str, line: int, ok: bool | None,
         fails: Callable[[dict[str, Any], Any], bool], t0: float, hyps: tuple[str, ...],
         implied: list[str], extra: list[str], method: str,
         search_kw: Mapping[str, Any] | None = None) -> CheckRow:
    implied, extra = list(dict.fromkeys(implied)), list(dict.fromkeys(extra))
    if ok:
        return CheckRow(name, kind, line, ProofResult(
            Status.PROVED, method, time.perf_counter() - t0, hypotheses=hyps,
            conditions=tuple(extra), implied=tuple(implied)))
    cx = find(program, fails, **(search_kw or {}))
    if cx is not None:
        return CheckRow(name, kind, line, ProofResult(
            Status.REFUTED, "counterexample: a point of the model (domains, condition (1), "
            "μ = tan ξ checked exactly) at which the file, replayed exactly, contradicts it",
            time.perf_counter() - t0, counterexample=cx, hypotheses=hyps))
    return CheckRow(name, kind, line, ProofResult(
        Status.UNDECIDED, "not proved, and no counterexample found by exact replay at "
        "points of the model", time.perf_counter() - t0, hypotheses=hyps,
        conditions=tuple(extra), implied=tuple(implied)))


# -- targets (against the paper) ----------------------------------------------------------
def _paper_model(program: Program) -> PaperModel:
    names = {p.name for p in program.params}
    missing = [n for n in _PAPER_PARAMS if n not in names]
    for d in "12":
        if f"mu{d}" not in names and f"xi{d}" not in names:
            missing.append(f"mu{d} (or xi{d})")
    if missing:
        raise CheckError(f"{program.file}: grading against the paper needs the parameters "
                         f"x1, x2, y, phi1, phi2 and mu1/xi1, mu2/xi2; missing: "
                         f"{', '.join(missing)}")
    values: dict[sp.Symbol, sp.Expr] = {getattr(S, n): getattr(S, n) for n in _PAPER_PARAMS}
    mu_form = []
    for i in (1, 2):
        mu, xi = getattr(S, f"mu{i}"), getattr(S, f"xi{i}")
        if f"mu{i}" in names:
            values[mu], values[xi] = mu, sp.atan(mu)
            mu_form.append(True)
        else:
            values[mu], values[xi] = sp.tan(xi), xi
            mu_form.append(False)
    return PaperModel(values, (mu_form[0], mu_form[1]), False)


def _paper_object(model: PaperModel, name: str) -> tuple[sp.Expr, ...]:
    if name == "O_M":
        return model.O_M
    if name in ("P1x", "P2x"):
        return model.Px(int(name[1]))
    kind, n = name.rstrip("1234"), int(name[-1])
    if kind == "circle":
        (cx, cy), r2 = model.circle(n)
        return cx, cy, r2
    return {"X": model.X, "Y": model.Y, "V": model.V}[kind](n)


def _model_point(pt: Mapping[str, Any]) -> dict[sp.Symbol, sp.Expr]:
    out = {getattr(S, k): sp.sympify(v) for k, v in pt.items() if k in DOMAIN_WORDS}
    for i in (1, 2):  # the model holds both μ and ξ
        mu, xi = getattr(S, f"mu{i}"), getattr(S, f"xi{i}")
        if mu in out and xi not in out:
            out[xi] = sp.atan(out[mu])
        elif xi in out and mu not in out:
            out[mu] = sp.tan(out[xi])
    return out


def _check_target(program: Program, name: str, env: dict[str, Any], model: PaperModel,
                  step_conds: Mapping[str, tuple[list[str], list[str]]],
                  vacuous: Mapping[str, str] | None = None) -> CheckRow:
    t0 = time.perf_counter()
    obj = env[name]
    want = _paper_object(model, name)
    hyps = _hypotheses(program, True)
    gone = [f"{n}: {vacuous[n]}" for n in _ancestors(program, [name])
            if vacuous and n in vacuous]
    if gone:
        return _vacuous(name, "target", _line(program, name), t0, hyps, "; ".join(gone))
    try:
        have = coords(obj)
    except CheckError:
        have = ()
    if len(have) != len(want):
        what = {2: "a point", 3: "a circle", 1: "a number"}[len(want)]
        return CheckRow(name, "target", _line(program, name), ProofResult(
            Status.REFUTED, f"the file's {name} is a {type(obj).__name__}; the paper's is "
            f"{PAPER_TARGETS[name]}", time.perf_counter() - t0, hypotheses=hyps,
            detail=f"no counterexample needed: the file's {name} is a {type(obj).__name__} "
            f"for every value of the parameters (the kind of an object does not depend on "
            f"them) and the paper's {name} is {what}, so they differ at every point of the "
            f"model"))
    implied: list[str] = []
    extra: list[str] = []
    for n in _ancestors(program, [name]):
        imp, ext = step_conds.get(n, ([], []))
        implied += imp
        extra += ext
    ok, imp, ext, method = prove_zero([h - w for h, w in zip(have, want)], True)

    def fails(env_at: dict[str, Any], pt: Any) -> bool:
        at = model_at(model, _model_point(pt))
        return any(nonzero(h - w) for h, w in
                   zip(coords(env_at[name]), _paper_object(at, name)))

    return _row(program, name, "target", _line(program, name), ok, fails, t0, hyps,
                implied + imp, extra + ext, method,
                {"cond1": True, "names": _ancestors(program, [name])})


def _worded(out: Any, ops: list, words: list[str], cond1: bool, tie: Any) -> Any:
    """``out`` (decided conditions of the values) with each of the operation's own
    conditions ``ops`` decided and followed by what it says (``words``)."""
    for i, cond in enumerate(ops):
        d = decide([cond], cond1, tie)
        say = f" ({words[i]})" if i < len(words) else ""
        for bucket in ("implied", "false", "extra"):
            mine = getattr(out, bucket)
            mine += [t + say for t in getattr(d, bucket) if t + say not in mine]
    return out


def _line(program: Program, name: str) -> int:
    return next((s.line for s in program.steps if s.name == name), 0)


_TWO_POINTS = ("line_through", "circle_through", "circle_on_diameter", "intersect_circles",
               "second_intersection")


def _distinct_ends(program: Program, c: Construction, s: Any, own: Any,
                   texts: list[str]) -> None:
    """Two points shown distinct under the kernel conditions of the steps before (which
    every result using the step assumes): a line's direction, a circle's radius, the
    line of two centres; the condition (``texts``) is then implied."""
    if not texts or not all(t in own.extra for t in texts):
        return
    by = {st.name: st for st in c.steps}
    ins = [by[n].obj for n in s.inputs]
    assumed = [e for n in _ancestors(program, [s.name]) if n in by for e in by[n].conditions]
    a, b = (ins[0], ins[1]) if s.op in ("line_through", "circle_through",
                                        "circle_on_diameter") else (ins[0].center, ins[1].center)
    if distinct(a, b, assumed):
        own.extra = [t for t in own.extra if t not in texts]
        own.implied += [t + " (the two points differ wherever the steps before are defined)"
                        for t in texts]


# -- the whole file -----------------------------------------------------------------------
def check_program(program: Program, against: str | None = None,
                  progress: Callable[[int, int, str], None] | None = None,
                  timeout: float | None = None) -> ProgramReport:
    """Certify the steps, prove the claims and (``against="paper"``) grade the objects.

    Parameters
    ----------
    program : Program
        A parsed file (:func:`graspcompass.construction.language.parse`) or a
        builder's program.
    against : {None, "paper"}, optional
        ``"paper"``: also prove that each object named like a point of the paper
        (:data:`PAPER_TARGETS`) equals the paper's statement (§3.3, eqs. (28)-(39))
        for every grasp satisfying condition (1) and μ = tan ξ (22).
    progress : callable, optional
        Called as ``progress(done, total, name)`` after each row.
    timeout : float, optional
        Seconds for the whole check (``None``: no limit).  Every verdict reached
        before the limit is kept; each row not decided by then (and every row when
        the replay itself does not end in time) is UNDECIDED, its method
        :data:`~graspcompass.proof._budget.TIMED_OUT`.

    Returns
    -------
    ProgramReport
        Rows for the steps, the claims and the targets; ``exit_status`` is 0
        (all proved), 1 (something refuted) or 3 (something undecided).

    Raises
    ------
    CheckError
        ``against="paper"`` for a file without the paper's parameters or without
        any object named like a point of the paper; a model parameter declared
        with another domain than the model's.
    DegenerateStepError
        A step that cannot be made for general parameters.
    """
    if against not in (None, "paper"):
        raise CheckError(f"cannot check against {against!r}: the one reference is 'paper'")
    t0 = time.perf_counter()
    _check_model_params(program)
    model = _paper_model(program) if against == "paper" else None
    targets = [s.name for s in program.steps if s.name in PAPER_TARGETS]
    if against == "paper" and not targets:
        raise CheckError(f"{program.file}: no object is named like a point of the paper "
                         f"({', '.join(PAPER_TARGETS)}): nothing to grade")
    budget = Budget(timeout)

    def late(name: str, kind: str, line: int) -> Callable[[], CheckRow]:
        return lambda: CheckRow(name, kind, line, ProofResult(
            Status.UNDECIDED, TIMED_OUT, 0.0, detail=f"--timeout {timeout:g} s",
            hypotheses=_hypotheses(program, _COND1 in program.hypotheses)))

    c = budget.run(lambda: replay(program), lambda: None)
    if c is None:  # the replay itself ran out of time: every row is timed out
        rows = [late(st.name, "step", st.line)() for st in program.steps]
        claims = [late(_text(cl), "claim", cl.line)() for cl in program.claims]
        tg = [late(t, "target", _line(program, t))() for t in targets]
        return ProgramReport(program.file, tuple(rows), tuple(claims), tuple(tg), against,
                             time.perf_counter() - t0, None)
    env = {s.name: s.obj for s in c.steps}
    made = set(env)
    targets = [t for t in targets if t in made]  # an optional step may be left out
    cond1_file = _COND1 in program.hypotheses
    total = len(c.steps) + len(program.claims) + len(targets)
    done = 0
    step_rows: list[CheckRow] = []
    step_conds: dict[str, tuple[list[str], list[str]]] = {}
    hyps = _hypotheses(program, cond1_file)
    tie = tie_mu(p.name for p in program.params)
    statements = {st.name: st for st in program.steps}
    vacuous: dict[str, str] = {}
    plain_conds = _Later()

    def step_row(s: Any) -> CheckRow:
        """One step's row; the shared tables are written only once it is complete."""
        t1 = time.perf_counter()
        line = _line(program, s.name)
        stmt = statements[s.name]
        gone = [n for n in s.inputs if n in vacuous]
        if gone:  # built on a step that exists nowhere: it exists nowhere either
            why = "; ".join(dict.fromkeys(  # the first step that exists nowhere, once
                vacuous[n] if vacuous[n].startswith("built on ") else
                f"built on {n}, which exists at no point of the model ({vacuous[n]})"
                for n in gone))
            vacuous[s.name] = why
            return CheckRow(s.name, "step", line, ProofResult(
                Status.REFUTED, "degenerate for every parameter: it exists at no point of "
                "the model", time.perf_counter() - t1, detail=why, hypotheses=hyps))
        ops, replaced = operation_conditions(s.op, [env[n] for n in s.inputs], s.obj)
        own = _worded(decide(stmt.conditions, cond1_file, tie), ops,
                      condition_words(s.op, s.inputs), cond1_file, tie)
        if s.op in _TWO_POINTS and own.extra:
            _distinct_ends(program, c, s, own, _worded(
                decide((), cond1_file, tie), ops[:1], condition_words(s.op, s.inputs),
                cond1_file, tie).extra)
        try:
            implied, extra = step_conditions(s, cond1_file, replaced, tie)
            extra = kernel_worded(extra, s.op, s.inputs, statements)
            if own.false:
                raise ValueError("; ".join(f"{t} is false for every parameter"
                                           for t in own.false))
            implied, extra = implied + own.implied, extra + own.extra
        except ValueError as exc:
            vacuous[s.name] = str(exc)
            return CheckRow(s.name, "step", line, ProofResult(
                Status.REFUTED, "degenerate for every parameter: it exists at no point of "
                "the model", time.perf_counter() - t1, detail=str(exc), hypotheses=hyps))
        step_conds[s.name] = (implied, extra)
        if cond1_file:  # for claims not under condition1: the same, without (1), decided
            def plain(s: Any = s, stmt: Any = stmt, ops: Any = ops, replaced: Any = replaced,
                      mine: tuple[list[str], list[str]] = (implied, extra)
                      ) -> tuple[list[str], list[str]]:
                try:  # only when such a claim is built on the step
                    imp0, ext0 = step_conditions(s, False, replaced, tie)
                    own0 = decide([*stmt.conditions, *ops], False, tie)
                    return imp0 + own0.implied, ext0 + own0.extra
                except ValueError:
                    return mine
            plain_conds.later(s.name, plain)
        else:
            plain_conds[s.name] = (implied, extra)
        given = s.op == "point" or (s.op == "line_with_direction" and not s.inputs[1:])
        return CheckRow(s.name, "step", line, ProofResult(
            Status.GIVEN if given and not s.inputs else Status.PROVED,
            "defined where its conditions hold (the kernel's non-degeneracy conditions)",
            time.perf_counter() - t1, hypotheses=hyps, conditions=tuple(extra),
            implied=tuple(implied)))

    for s in c.steps:
        line = _line(program, s.name)
        step_rows.append(budget.run(lambda s=s: step_row(s), late(s.name, "step", line)))
        done += 1
        if progress:
            progress(done, total, s.name)
    claim_rows = []
    for cl in program.claims:
        use = step_conds if _COND1 in cl.under or not cond1_file else plain_conds
        claim_rows.append(budget.run(
            lambda cl=cl, use=use: _guarded(_text(cl), "claim", cl.line, hyps, lambda: (
                _check_claim(program, cl, env, use, vacuous))),
            late(_text(cl), "claim", cl.line)))
        done += 1
        if progress:
            progress(done, total, claim_rows[-1].name)
    target_rows = []
    if model is not None:
        for name in targets:
            line = _line(program, name)
            target_rows.append(budget.run(
                lambda name=name, line=line: _guarded(name, "target", line, hyps, lambda: (
                    _check_target(program, name, env, model, step_conds, vacuous))),
                late(name, "target", line)))
            done += 1
            if progress:
                progress(done, total, name)
    symbols = {p.name: p.symbol for p in program.params}
    step_rows, claim_rows, target_rows = ([_tidy(r, symbols, program) for r in rows] for rows in (
        step_rows, claim_rows, target_rows))
    return ProgramReport(program.file, tuple(step_rows), tuple(claim_rows), tuple(target_rows),
                         against, time.perf_counter() - t0, c)


def _tidy(row: CheckRow, symbols: Mapping[str, sp.Symbol], program: Program) -> CheckRow:
    """The row with its conditions factored, merged, discharged and worded
    (:func:`~graspcompass.proof.program_words.tidy`)."""
    from dataclasses import replace

    from .program_words import tidy

    r = row.result
    if not r.conditions and not r.implied:
        return row
    extra, implied = tidy(r.conditions, r.implied, symbols)
    extra, by_hyp = discharge(extra, program.inequalities, symbols)
    implied += by_hyp
    return replace(row, result=replace(r, conditions=tuple(extra), implied=tuple(implied)))
