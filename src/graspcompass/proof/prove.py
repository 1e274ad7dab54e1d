"""The checker: identities and sign claims, PROVED, REFUTED (with a counterexample) or UNDECIDED.

* Identities are reduced to polynomial form (:mod:`graspcompass.proof.reduce`);
  a zero normal form is a proof wherever the expression is defined.  Every
  denominator met is either shown non-zero under the hypotheses (``implied``)
  or listed as a non-degeneracy condition of the result (``conditions``); a
  denominator that is 0 modulo the relations raises
  :class:`~graspcompass.proof.reduce.DegenerateClaimError`.
* A non-zero normal form is not yet a refutation: the checker then looks for
  points of the model (:mod:`graspcompass.proof.model`: domains, condition (1),
  eq. (22), the caller's relations) where the two sides differ, checks them by
  exact substitution evaluated to 50 digits, and reports them.  If it finds
  none, the claim is UNDECIDED.
* A sign claim ``expr > 0`` (or ``< 0``) is PROVED from a *witness*: factors
  whose product is ``expr`` (an identity, checked as above) and whose signs
  follow from interval bounds on angles (``cos u < 0`` for ``u`` in
  ``(π/2, 3π/2)``), from the symbols' signs, or from signs of numbers.
  The witness is tried first: a claim it proves at every point of the model
  (no non-degeneracy condition left) has no counterexample to look for.
  Otherwise random admissible points that violate the claim REFUTE it.
"""

from __future__ import annotations

import dataclasses
import enum
import functools
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from ..boundary.expr import tree_conditions
from .model import find_counterexample, nonzero_at, outside_expr, wrong_sign
from .reduce import DegenerateClaimError, reduce_expr
from .signs import CONDITION_1, Intervals, _interval, discharge, form_json, sign_of, sign_reason

__all__ = [
    "CONDITION_1",
    "CONDITION_1_NAME",
    "DegenerateClaimError",
    "Intervals",
    "ProofResult",
    "Status",
    "find_counterexample",
    "prove_identity",
    "prove_sign",
    "sign_of",
]

_ = _interval  # re-exported for callers that sum angle intervals

#: How condition (1) (with the domains of §2.2) is named in ``hypotheses``.
CONDITION_1_NAME = "condition (1)"


class Status(str, enum.Enum):
    """Outcome of a check.

    ``PROVED``: an exact argument for every admissible parameter (its hypotheses and
    non-degeneracy conditions are in the result); ``REFUTED``: a re-checked point of
    the model where the statement fails; ``UNDECIDED``: neither; ``GIVEN``: data of
    the problem, checked to match the grasp but not a consequence of anything;
    ``NUMERIC``: holds to rounding on a float construction (not a proof).
    """

    PROVED = "PROVED"
    REFUTED = "REFUTED"
    UNDECIDED = "UNDECIDED"
    GIVEN = "GIVEN"
    NUMERIC = "NUMERIC"


@dataclass(frozen=True)
class ProofResult:
    """Plain data: the outcome, how it was reached, and a counterexample if refuted.

    Attributes
    ----------
    status : Status
    method : str
        How the verdict was reached.
    seconds : float
    counterexample : dict of str to str, optional
        Exact parameter values (a point of the model, re-checked) where the claim fails.
    detail : str
    values : dict of str to float
    hypotheses : tuple of str
        Everything the verdict assumes beyond the symbols' domains: condition (1),
        interval hypotheses given by the caller, change-of-variable domains.
    conditions : tuple of str
        Non-degeneracy conditions (``expr != 0``) that the proof needs and that
        could not be shown to follow from the hypotheses: extra hypotheses.
    implied : tuple of str
        Non-degeneracy conditions shown to follow from the hypotheses.
    certificate : dict, optional
        JSON-ready data that an independent checker re-verifies by polynomial
        expansion (cofactors of the relations; sign witnesses with their intervals).
    """

    status: Status
    method: str
    seconds: float
    counterexample: dict[str, str] | None = None
    detail: str = ""
    values: dict[str, float] = field(default_factory=dict)
    hypotheses: tuple[str, ...] = ()
    conditions: tuple[str, ...] = ()
    implied: tuple[str, ...] = ()
    certificate: dict[str, Any] | None = None

    @property
    def proved(self) -> bool:
        """True for PROVED."""
        return self.status is Status.PROVED

    @property
    def holds(self) -> bool:
        """True for PROVED, GIVEN (matching the grasp) and NUMERIC (float, to rounding)."""
        return self.status in (Status.PROVED, Status.GIVEN, Status.NUMERIC)


# -- hypotheses ----------------------------------------------------------------
def _iv_text(form: sp.Expr, iv: tuple[Any, Any]) -> str:
    return f"{form} in ({iv[0]}, {iv[1]})"


def _interval_hypotheses(intervals: Intervals) -> tuple[list[str], list[Any]]:
    """Names of the interval hypotheses, and the extra relations they add to the model."""
    items = tuple((k, tuple(v)) for k, v in intervals.items())
    names, rels = _interval_hypotheses_of(items)
    return list(names), list(rels)


@functools.lru_cache(maxsize=512)
def _interval_hypotheses_of(items: tuple) -> tuple[tuple[str, ...], tuple[Any, ...]]:
    """:func:`_interval_hypotheses` by content (the catalogue asks again per claim)."""
    intervals = dict(items)
    names, rels = [], []
    if any(CONDITION_1.get(k) == tuple(v) for k, v in intervals.items()):
        names.append(CONDITION_1_NAME)
    for k, v in intervals.items():
        lo, hi = (sp.sympify(b) for b in v)  # internal: the caller's bounds, numbers
        if (lo - hi).is_number and not (lo - hi).free_symbols and bool(lo >= hi):
            raise DegenerateClaimError(
                f"the interval hypothesis {k} in ({lo}, {hi}) is empty: nothing would be proved"
            )
        if CONDITION_1.get(k) != tuple(v):
            names.append(_iv_text(k, v))
            rels += [
                sp.StrictGreaterThan(k, v[0], evaluate=False),
                sp.StrictLessThan(k, v[1], evaluate=False),
            ]
    return tuple(names), tuple(rels)


def _context(
    assumptions: Sequence[Any], domains: Mapping | None, subs: Mapping | None
) -> tuple[list[str], list[Any]]:
    names = [f"{a}" for a in assumptions]
    rels = list(assumptions)
    for s, (lo, hi) in (domains or {}).items():
        names.append(_iv_text(s, (lo, hi)) if hi is not None else f"{s} > {lo}")
        rels.append(sp.StrictGreaterThan(s, lo, evaluate=False))
        if hi is not None:
            rels.append(sp.StrictLessThan(s, hi, evaluate=False))
    if subs:
        names.append("change of variables " + ", ".join(f"{k} = {v}" for k, v in subs.items()))
    return names, rels


def _cx(values: Mapping | None) -> dict[str, str] | None:
    return None if values is None else {str(k): str(v) for k, v in values.items()}


def _intervals_json(intervals: Intervals) -> list[dict[str, Any]]:
    out = []
    for k, (lo, hi) in intervals.items():
        lo, hi = outside_expr(lo, f"interval of {k}"), outside_expr(hi, f"interval of {k}")
        f, a, b = form_json(k), sp.expand(lo / sp.pi), sp.expand(hi / sp.pi)
        if f is not None and a.is_Rational and b.is_Rational:
            out.append(
                {
                    "form": f,
                    "interval": [f"{a.p}/{a.q}", f"{b.p}/{b.q}"],
                    "source": "(1)" if CONDITION_1.get(k) == (lo, hi) else "hypothesis",
                }
            )
    return out


#: The text of an expression (factors recur from claim to claim: printed once).
_text = functools.lru_cache(maxsize=4096)(str)


def _denominators(
    factors: Sequence[sp.Expr],
    intervals: Intervals,
    iv_names: list[str],
    syms: set,
    extra: list[Any],
    domains: Mapping | None,
    subs: Mapping | None,
):
    """Split denominator factors into implied (shown non-zero) and conditions."""
    implied, conditions, rows = [], [], []
    src = ", ".join(n for n in iv_names if n == CONDITION_1_NAME) or "the hypotheses"
    src = "(1)" if src == CONDITION_1_NAME else src
    for f in factors:
        why = discharge(f, intervals)
        text = _text(f)
        if why is not None:
            implied.append(f"{text} != 0 (from {src})")
            rows.append({"factor": text, "status": "implied", "reason": why})
        else:
            _not_always_zero(f, syms | f.free_symbols, extra, domains, subs)
            conditions.append(f"{text} != 0")
            rows.append({"factor": text, "status": "condition", "reason": ""})
    return implied, conditions, rows


def _not_always_zero(
    f: sp.Expr, syms: set, extra: list[Any], domains: Mapping | None, subs: Mapping | None
) -> None:
    """Guard against a condition that fails at every point of the model (vacuous result)."""
    syms = {s for s in syms if s.is_Symbol}
    zero = find_counterexample(
        lambda v: not nonzero_at(f, v, screen=True),
        syms,
        extra,
        tries=3,
        seed=7,
        domains=domains,
        derived=subs,
    )
    if zero is None:
        return
    nonzero = find_counterexample(
        lambda v: nonzero_at(f, v), syms, extra, tries=8, seed=11, domains=domains, derived=subs
    )
    if nonzero is None:
        raise DegenerateClaimError(
            f"the non-degeneracy condition {f} != 0 fails at every "
            "point of the model tried: the claim is undefined there"
        )


def prove_identity(
    lhs: Any,
    rhs: Any = 0,
    assumptions: Sequence[Any] = (),
    *,
    intervals: Intervals = CONDITION_1,
    domains: Mapping | None = None,
    subs: Mapping | None = None,
) -> ProofResult:
    """Check ``lhs == rhs`` at every point of the model where both sides are defined.

    The denominators met are shown non-zero from ``intervals`` (condition (1) by
    default; listed in ``implied``) or listed in ``conditions``.  ``assumptions``
    are relations on top of the model (domains, (1), (22)) that counterexamples
    must satisfy; ``domains`` gives intervals of change-of-variable symbols and
    ``subs`` a change of variables applied to both sides (recorded in ``hypotheses``).
    A PROVED result carries a certificate (:mod:`graspcompass.proof.recheck`).

    Raises
    ------
    DegenerateClaimError
        If a side is 0/0 or undefined for every value of its symbols.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, mu1, xi1
    >>> r = prove_identity(sp.tan(phi1 + xi1), (sp.tan(phi1) + mu1) / (1 - sp.tan(phi1) * mu1))
    >>> r.status, r.conditions  # tan(phi1) is undefined at phi1 = pi/2, which (1) admits
    (<Status.PROVED: 'PROVED'>, ('cos(phi1) != 0',))
    >>> r = prove_identity(sp.sin(2 * phi1), 2 * sp.sin(phi1))
    >>> r.status, sorted(r.counterexample)
    (<Status.REFUTED: 'REFUTED'>, ['phi1'])
    """
    t0 = time.perf_counter()
    lhs, rhs = outside_expr(lhs, "lhs"), outside_expr(rhs, "rhs")  # never sympify
    assumptions = tuple(outside_expr(a, "assumption") for a in assumptions)
    if isinstance(lhs, sp.MatrixBase) and not isinstance(rhs, sp.MatrixBase) and rhs == 0:
        rhs = sp.zeros(*lhs.shape)
    try:
        key = (
            _frozen(lhs),
            _frozen(rhs),
            tuple(assumptions),
            _content(intervals),
            _content(domains),
            _content(subs),
        )
        hash(key)
    except TypeError:  # something unhashable: no reuse
        return _prove_identity(lhs, rhs, assumptions, intervals, domains, subs, t0)
    r = _IDENTITIES.get(key)
    if r is None:
        r = _IDENTITIES[key] = _prove_identity(lhs, rhs, assumptions, intervals, domains, subs, t0)
    return dataclasses.replace(r, seconds=time.perf_counter() - t0)


#: Results of :func:`prove_identity` by content: the two sides, the assumptions, the
#: intervals, domains and change of variables themselves (never by a claim's id).
_IDENTITIES: dict[tuple, ProofResult] = {}


def _frozen(x: Any) -> Any:
    return sp.ImmutableMatrix(x) if isinstance(x, sp.MatrixBase) else x


def _content(m: Mapping | None) -> frozenset | None:
    return (
        None
        if m is None
        else frozenset((k, tuple(v) if isinstance(v, list) else v) for k, v in m.items())
    )


def _prove_identity(
    lhs: Any,
    rhs: Any,
    assumptions: Sequence[Any],
    intervals: Intervals,
    domains: Mapping | None,
    subs: Mapping | None,
    t0: float,
) -> ProofResult:
    diff = lhs - rhs
    entries = list(diff) if isinstance(diff, sp.MatrixBase) else [diff]
    if subs:
        entries = [e.subs(subs) for e in entries]
    reds = [reduce_expr(e) for e in entries]
    factors = sorted({f for r in reds for f in r.factors}, key=sp.default_sort_key)
    iv_names, iv_rels = _interval_hypotheses(intervals)
    ctx_names, extra = _context(assumptions, domains, subs)
    extra += iv_rels
    syms = set().union(*(e.free_symbols for e in entries))
    implied, conditions, rows = _denominators(
        factors, intervals, iv_names, syms, extra, domains, subs
    )
    hyps = tuple((iv_names if implied else []) + ctx_names)
    bad = [e for e, r in zip(entries, reds) if not r.is_zero]
    common: dict[str, Any] = dict(
        hypotheses=hyps, conditions=tuple(conditions), implied=tuple(implied)
    )
    if not bad:
        cert = {"kind": "identity", "entries": [r.certificate for r in reds], "denominators": rows}
        return ProofResult(
            Status.PROVED,
            "polynomial reduction",
            time.perf_counter() - t0,
            certificate=cert,
            **common,
        )
    found = find_counterexample(
        lambda v: any(nonzero_at(e, v) for e in bad),
        list(set().union(*(e.free_symbols for e in bad))),
        extra,
        domains=domains,
        derived=subs,
    )
    if found is not None:
        vals = (
            {"lhs - rhs": float(sp.N(bad[0].xreplace(found), 17))}
            if not isinstance(diff, sp.MatrixBase)
            else {}
        )
        return ProofResult(
            Status.REFUTED,
            "polynomial reduction + exact substitution",
            time.perf_counter() - t0,
            _cx(found),
            values=vals,
            **common,
        )
    return ProofResult(
        Status.UNDECIDED,
        "polynomial reduction (non-zero normal form, "
        "no counterexample found among points of the model)",
        time.perf_counter() - t0,
        **common,
    )


# -- signs ---------------------------------------------------------------------
def prove_sign(
    expr: Any,
    sign: int,
    witness: Sequence[Any] | None = None,
    assumptions: Sequence[Any] = (),
    intervals: Intervals = CONDITION_1,
    subs: Mapping | None = None,
    *,
    domains: Mapping | None = None,
) -> ProofResult:
    """Check ``sign(expr) == sign`` (+1 or -1) at every point of the model.

    ``witness`` lists factors whose product equals ``expr`` (after ``subs``, a
    change of variables such as ``x1 + x2 = 2 r sin α``); each factor's sign must
    follow from ``intervals`` (condition (1) by default) or from the symbols'
    signs.  Every hypothesis used is recorded in ``hypotheses``: condition (1) by
    name, each interval the caller adds or changes, the change of variables, the
    ``domains`` of new symbols and the ``assumptions``; counterexamples are
    sought among the points of the model that satisfy all of them, unless the
    witness already proves the claim with no extra non-degeneracy condition.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, mu1
    >>> c1, s1 = sp.cos(phi1), sp.sin(phi1)
    >>> r = prove_sign(mu1 * s1 - c1, +1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)])
    >>> r.status, r.hypotheses
    (<Status.PROVED: 'PROVED'>, ('condition (1)',))
    >>> prove_sign(mu1 * s1 - c1, -1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)]).status
    <Status.REFUTED: 'REFUTED'>
    """
    t0 = time.perf_counter()
    e = outside_expr(expr, "expr")  # the caller's: never sympify
    assumptions = tuple(outside_expr(a, "assumption") for a in assumptions)
    if witness is not None:
        witness = [outside_expr(w, f"witness[{i}]") for i, w in enumerate(witness)]
    iv_names, iv_rels = _interval_hypotheses(intervals)
    ctx_names, extra = _context(assumptions, domains, subs)
    hyps = tuple(iv_names + ctx_names)
    extra = extra + iv_rels
    target = e.subs(subs) if subs else e
    proof: Any = None
    if witness is not None:
        try:
            proof = _witness_proof(target, sign, witness, intervals, domains, hyps)
        except (DegenerateClaimError, ValueError) as exc:  # raised below unless refuted
            proof = exc
    if isinstance(proof, tuple) and proof[0] is Status.PROVED and not proof[2]["conditions"]:
        # proved at every point of the model: no point can violate it, nothing to search
        return ProofResult(Status.PROVED, proof[1], time.perf_counter() - t0, **proof[2])
    sample_syms = set(target.free_symbols) | {s for r in iv_rels for s in r.free_symbols}
    if subs:
        sample_syms -= set(subs)
    where = tree_conditions(e)  # a counterexample is a point where e is defined (no 0/0)
    found = find_counterexample(
        lambda v: _defined_at(where, v) and wrong_sign(e, sign, v),
        list(sample_syms),
        extra,
        domains=domains,
        derived=subs,
    )
    if found is not None:
        return ProofResult(
            Status.REFUTED,
            "exact substitution",
            time.perf_counter() - t0,
            _cx(found),
            values={"expr": float(sp.N(e.xreplace(found), 17))},
            hypotheses=hyps,
        )
    if proof is None:
        return ProofResult(
            Status.UNDECIDED,
            "no witness; no counterexample found",
            time.perf_counter() - t0,
            hypotheses=hyps,
        )
    if isinstance(proof, Exception):
        raise proof
    return ProofResult(proof[0], proof[1], time.perf_counter() - t0, **proof[2])


def _defined_at(conditions: Sequence[tuple[str, sp.Expr]], values: Mapping) -> bool:
    """Every divisor of the expression non-zero and every radicand ≥ 0 at ``values``,
    decided exactly (undecided: not a point to report)."""
    from ..geometry.exact import decide_sign

    for rel, c in conditions:
        try:
            s = decide_sign(c.xreplace(values))
        except (ValueError, TypeError, ArithmeticError):
            return False
        if (
            s is None
            or (rel == "!=" and s == 0)
            or (rel == ">=" and s < 0)
            or (rel == ">" and s <= 0)
        ):
            return False
    return True


def _witness_proof(
    target: sp.Expr,
    sign: int,
    witness: Sequence[Any],
    intervals: Intervals,
    domains: Mapping | None,
    hyps: tuple[str, ...],
) -> tuple[Status, str, dict[str, Any]]:
    """The verdict of the witness alone: PROVED (with its certificate) or UNDECIDED."""
    ident = prove_identity(target, sp.Mul(*witness), intervals=intervals, domains=domains)
    common: dict[str, Any] = dict(
        hypotheses=hyps, conditions=ident.conditions, implied=ident.implied
    )
    if not ident.proved:
        return (
            Status.UNDECIDED,
            "the witness factorisation did not check",
            {**common, "detail": ident.status.value},
        )
    found = [sign_reason(w, intervals) for w in witness]
    reasons = [r for r in found if r is not None]
    if len(reasons) < len(found) or any(r[0][0] != r[0][1] or r[0][0] == 0 for r in reasons):
        return Status.UNDECIDED, "a witness factor has no known strict sign", common
    total = 1
    for r in reasons:
        total *= r[0][0]
    if total != sign:
        return (
            Status.UNDECIDED,
            "the witness proves the opposite sign, but no point of the model was found to show it",
            common,
        )
    declared = {
        s.name: [1, 1] if s.is_positive else [0, 1]
        for s in set().union(*(outside_expr(w, "witness").free_symbols for w in witness))
        if s.is_positive or s.is_nonnegative
    }
    cert = {
        "kind": "sign",
        "sign": sign,
        "identity": ident.certificate,
        "factors": [
            {"factor": _text(outside_expr(w, "witness")), "reason": r[1]}
            for w, r in zip(witness, reasons)
        ],
        "intervals": _intervals_json(intervals),
        "symbols": declared,
        "hypotheses": list(hyps),
    }
    return Status.PROVED, "witness factorisation + interval signs", {**common, "certificate": cert}
