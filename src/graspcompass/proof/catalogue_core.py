"""The claim record, how a claim is run, and the proof combinators of the catalogue.

No verdict is memoised by id: :func:`check` runs the claim every time, except
inside a :func:`session`, where a result is reused for the *same claim object*
(its identity, never its id), so that a composite claim and the catalogue share
the proof of a lemma within one run.  Composite claims check their own logic
(:func:`conjunction`, :func:`propositional`); a dependency only ever lowers
their status.
"""

from __future__ import annotations

import contextlib
import dataclasses
import itertools
import time
from collections.abc import Callable, Iterator, Sequence
from contextvars import ContextVar
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import sympy as sp

from ..symbols import mu1, mu2, xi1, xi2
from .prove import CONDITION_1, ProofResult, Status, prove_identity, prove_sign, sign_of

__all__ = [
    "CLAIM_ERRORS",
    "Claim",
    "check",
    "conjunction",
    "early_construction",
    "identity",
    "propositional",
    "session",
    "sign",
    "symbolic_construction",
    "with_xi",
]

#: Hypotheses named in reports.
H1 = "condition (1)"
H22 = "μ_i = tan ξ_i (22)"


@dataclass(frozen=True, eq=False)
class Claim:
    """One statement of the paper.

    Attributes
    ----------
    id, ref, statement : str
        Identifier, place in the paper, and the statement checked (all of it).
    run : callable
        Returns a :class:`ProofResult`; it checks the whole statement.
    printed : bool
        The paper's own wording (as opposed to a derived or corrected claim).
    corrected_by : str, optional
        Id of the claim that corrects a wrong printed one.
    depends : tuple of Claim
        Lemmas whose results this claim combines (by object, not by id).
    hypotheses : tuple of str
        What the statement assumes besides the symbols' domains.
    note : str
    """

    id: str
    ref: str
    statement: str
    run: Callable[[], ProofResult] = field(repr=False)
    printed: bool = True
    corrected_by: str | None = None
    depends: tuple[Claim, ...] = field(default=(), repr=False)
    hypotheses: tuple[str, ...] = (H1,)
    note: str = ""


_SESSION: ContextVar[dict[int, tuple[Claim, ProofResult]] | None] = ContextVar(
    "graspcompass_catalogue_session", default=None
)

#: Errors of a claim's own run that make it UNDECIDED (e.g. a 0/0 statement).
CLAIM_ERRORS: tuple[type[BaseException], ...] = (ValueError, ZeroDivisionError, TypeError)


@contextlib.contextmanager
def session() -> Iterator[None]:
    """Within the block, a claim object is run at most once (keyed by identity)."""
    token = _SESSION.set({})
    try:
        yield
    finally:
        _SESSION.reset(token)


def _merge(*parts: Sequence[str]) -> tuple[str, ...]:
    return tuple(dict.fromkeys(x for p in parts for x in p))


def check(c: Claim) -> ProofResult:
    """Run one claim; its hypotheses are added to the result's.

    Nothing is memoised by id.  In a :func:`session` the result of this very
    object is reused.  An error of the claim's own run (e.g. a statement that
    is 0/0) gives UNDECIDED with the error as detail, never PROVED.
    """
    memo = _SESSION.get()
    if memo is not None and id(c) in memo and memo[id(c)][0] is c:
        return memo[id(c)][1]
    t0 = time.perf_counter()
    try:
        r = c.run()
    except CLAIM_ERRORS as exc:
        r = ProofResult(
            Status.UNDECIDED,
            f"error: {type(exc).__name__}",
            time.perf_counter() - t0,
            detail=str(exc)[:300],
        )
    r = dataclasses.replace(r, hypotheses=_merge(c.hypotheses, r.hypotheses))
    if memo is not None:
        memo[id(c)] = (c, r)
    return r


# -- combinators ------------------------------------------------------------------
def with_xi(expr: Any) -> Any:
    """``expr`` with μ_i replaced by tan ξ_i (eq. (22)): one friction variable per contact."""
    # internal: the catalogue's own expressions (built by code), never a user's text
    return sp.sympify(expr).xreplace({mu1: sp.tan(xi1), mu2: sp.tan(xi2)})


def conjunction(
    parts: Sequence[ProofResult | Claim], method: str, t0: float, own: Sequence[ProofResult] = ()
) -> ProofResult:
    """The result of a statement that is the conjunction of ``parts`` and ``own`` checks.

    PROVED when every part is; REFUTED (with that counterexample) when a part
    is, since a false conjunct makes the conjunction false; else UNDECIDED.
    Hypotheses, conditions and certificates of the parts are collected.
    """
    rs = [check(p) if isinstance(p, Claim) else p for p in parts] + list(own)
    hyp = _merge(*(r.hypotheses for r in rs))
    cond = _merge(*(r.conditions for r in rs))
    imp = tuple(x for x in _merge(*(r.implied for r in rs)) if x not in cond)
    certs = [r.certificate for r in rs if r.certificate is not None]
    cert = {"parts": certs} if certs else None
    kw: dict[str, Any] = dict(hypotheses=hyp, conditions=cond, implied=imp, certificate=cert)
    dt = time.perf_counter() - t0
    bad = next((r for r in rs if r.status is Status.REFUTED), None)
    if bad is not None:
        return ProofResult(
            Status.REFUTED, method, dt, bad.counterexample, bad.detail, bad.values, **kw
        )
    if all(r.proved for r in rs):
        return ProofResult(Status.PROVED, method, dt, **kw)
    worst = next(r for r in rs if not r.proved)
    return ProofResult(
        Status.UNDECIDED,
        method,
        dt,
        detail=f"a part is {worst.status.value}: {worst.method} {worst.detail}".strip(),
        **kw,
    )


def identity(
    lhs: Callable[..., Any],
    rhs: Callable[..., Any] | int = 0,
    assumptions: Callable[..., Sequence[Any]] | None = None,
) -> Callable[[], ProofResult]:
    """A claim runner for ``lhs == rhs`` (both built lazily)."""

    def run() -> ProofResult:
        a = list(assumptions()) if assumptions else ()
        return prove_identity(lhs(), rhs() if callable(rhs) else rhs, *([a] if a else []))

    return run


def sign(
    expr: Any,
    s: int,
    witness: Sequence[Any],
    intervals: dict | None = None,
    assumptions: Sequence[Any] = (),
    hypothesis: str = "",
) -> ProofResult:
    """``sign(expr) == s`` by :func:`prove_sign` with a witness; extra interval hypotheses
    (``intervals`` beyond condition (1)) must come with the matching ``assumptions`` so that
    counterexamples respect them, and are named in the result."""
    iv = dict(CONDITION_1)
    iv.update(intervals or {})
    kw: dict[str, Any] = {"witness": list(witness), "intervals": iv}
    if assumptions:
        kw["assumptions"] = list(assumptions)
    r = prove_sign(expr, s, **kw)
    if hypothesis:
        r = dataclasses.replace(r, hypotheses=_merge(r.hypotheses, (hypothesis,)))
    return r


def sign_lemma(expr: Any, expected: tuple[int, int], what: str) -> ProofResult:
    """A structural sign fact about fresh symbols (no parameters): ``sign_of(expr)``."""
    t0 = time.perf_counter()
    got = sign_of(sp.sympify(expr), {})  # internal: a catalogue expression
    ok = got == expected
    return ProofResult(
        Status.PROVED if ok else Status.UNDECIDED,
        f"sign rules: {what}",
        time.perf_counter() - t0,
        detail="" if ok else f"sign {got}",
    )


def propositional(
    atoms: Sequence[str],
    facts: Callable[[dict[str, bool]], bool],
    goal: Callable[[dict[str, bool]], bool],
    what: str,
) -> ProofResult:
    """``facts ⇒ goal`` for every truth assignment of ``atoms`` (a complete check)."""
    t0 = time.perf_counter()
    bad = None
    for vals in itertools.product((False, True), repeat=len(atoms)):
        v = dict(zip(atoms, vals))
        if facts(v) and not goal(v):
            bad = v
            break
    dt = time.perf_counter() - t0
    if bad is None:
        return ProofResult(
            Status.PROVED,
            f"propositional check over all {2 ** len(atoms)} truth assignments: {what}",
            dt,
        )
    return ProofResult(
        Status.UNDECIDED,
        f"propositional check: {what}",
        dt,
        detail="fails at " + ", ".join(f"{k}={int(b)}" for k, b in bad.items()),
    )


# -- the construction -------------------------------------------------------------
def _replay(upto: str | None):
    from ..construction.protocol import Construction, run_step
    from ..construction.recipe import diagram_specs
    from ..grasp import Grasp

    g = Grasp.symbolic("mu")
    env: dict = {}
    steps: list[Any] = []
    for spec in diagram_specs(g):
        st = run_step(spec, env, len(steps))
        env[spec.name] = st.obj
        steps.append(st)
        if spec.name == upto:
            break
    return Construction(tuple(steps), g)


@lru_cache(maxsize=1)
def symbolic_construction():
    """The recipe of §3.3 replayed with every parameter a symbol (μ form), circles included."""
    return _replay(None)


@lru_cache(maxsize=1)
def early_construction():
    """The recipe of §3.3 with every parameter a symbol, up to V4 (no circles)."""
    return _replay("V4")
