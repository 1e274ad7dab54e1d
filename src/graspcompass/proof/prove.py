"""The checker: identities and sign claims, PROVED, REFUTED (with a counterexample) or UNDECIDED.

* Identities are reduced to polynomial form (:mod:`graspcompass.proof.reduce`);
  a zero normal form is a proof for every admissible parameter.
* A non-zero normal form is not yet a refutation: the checker then looks for
  admissible exact parameter values (satisfying the assumptions) where the two
  sides differ, checks them by exact substitution evaluated to 50 digits, and
  reports them.  If it finds none, the claim is UNDECIDED.
* A sign claim ``expr > 0`` (or ``< 0``) is PROVED from a *witness*: factors
  whose product is ``expr`` (an identity, checked as above) and whose signs
  follow from interval bounds on angles (``cos u < 0`` for ``u`` in
  ``(π/2, 3π/2)``), from the symbols' signs, or from signs of numbers.
  Random admissible points that violate the claim REFUTE it.
"""

from __future__ import annotations

import enum
import random
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from .. import symbols as S
from .reduce import reduce_expr

__all__ = [
    "CONDITION_1",
    "Intervals",
    "ProofResult",
    "Status",
    "find_counterexample",
    "prove_identity",
    "prove_sign",
    "sign_of",
]

Intervals = Mapping[sp.Expr, tuple[sp.Expr, sp.Expr]]

#: Open intervals of the angle forms under the domain and condition (1).
CONDITION_1: dict[sp.Expr, tuple[sp.Expr, sp.Expr]] = {
    S.xi1: (0, sp.pi / 2), S.xi2: (0, sp.pi / 2),
    S.phi1: (0, sp.pi), S.phi2: (0, sp.pi),  # φ ≤ π, and φ = π is excluded by (1)
    S.phi1 + S.xi1: (sp.pi / 2, 3 * sp.pi / 2), S.phi2 + S.xi2: (sp.pi / 2, 3 * sp.pi / 2),
    S.phi1 - S.xi1: (-sp.pi / 2, sp.pi / 2), S.phi2 - S.xi2: (-sp.pi / 2, sp.pi / 2),
}


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


# -- admissible samples --------------------------------------------------------
_LENGTHS = [sp.Rational(n, d) for n, d in ((1, 3), (1, 2), (2, 3), (1, 1), (3, 2), (2, 1),
                                           (5, 2), (3, 1), (7, 5), (4, 5))]


def _sample(sym: sp.Symbol, rng: random.Random) -> sp.Expr:
    name = sym.name
    if name.startswith("phi"):
        return sp.pi * sp.Rational(rng.randint(1, 23), 24)
    if name.startswith("xi"):
        return sp.pi * sp.Rational(rng.randint(1, 11), 24)
    if name in ("theta",) or name.startswith("alpha"):
        return sp.pi * sp.Rational(rng.randint(-23, 23), 24) + sp.Rational(1, 7)
    if name == "y" and rng.random() < 0.15:
        return sp.Integer(0)
    value = rng.choice(_LENGTHS)
    if sym.is_positive or sym.is_nonnegative or name.startswith(("x", "mu", "F", "r")):
        return value
    return value * rng.choice([-1, 1])


def _holds(rel: Any, values: Mapping) -> bool:
    try:
        return bool(sp.sympify(rel).subs(values))
    except TypeError:
        return bool(sp.N(sp.sympify(rel).subs(values), 30))


def find_counterexample(
    test: Callable[[Mapping[sp.Symbol, sp.Expr]], bool],
    symbols: Sequence[sp.Symbol],
    assumptions: Sequence[Any] = (),
    tries: int = 60,
    seed: int = 2012,
) -> dict[sp.Symbol, sp.Expr] | None:
    """Admissible exact values where ``test(values)`` is True, or None.

    ``test`` must decide exactly (e.g. by a 50-digit evaluation of an exact
    expression); candidates violating an assumption are skipped.
    """
    rng = random.Random(seed)
    syms = sorted(set(symbols), key=str)
    for _ in range(tries * 4):
        values = {s: _sample(s, rng) for s in syms}
        if not all(_holds(a, values) for a in assumptions):
            continue
        try:
            if test(values):
                return values
        except (ZeroDivisionError, TypeError, ValueError):
            continue
        tries -= 1
        if tries <= 0:
            break
    return None


def _nonzero_at(expr: sp.Expr, values: Mapping) -> bool:
    v = sp.N(expr.subs(values), 50)
    if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not v.is_number:
        raise ValueError("undefined at this point")
    return abs(v) > sp.Float(10) ** -30


def _cx(values: Mapping | None) -> dict[str, str] | None:
    return None if values is None else {str(k): str(v) for k, v in values.items()}


def prove_identity(lhs: Any, rhs: Any = 0, assumptions: Sequence[Any] = ()) -> ProofResult:
    """Check ``lhs == rhs`` for every admissible value of the symbols.

    Counterexamples satisfy ``assumptions`` (default: the domains of the
    symbols and the contact point conditions (1) for the angles present).

    Examples
    --------
    >>> from graspcompass.symbols import phi1, mu1, xi1
    >>> prove_identity(sp.tan(phi1 + xi1), (sp.tan(phi1) + mu1) / (1 - sp.tan(phi1) * mu1)).status
    <Status.PROVED: 'PROVED'>
    >>> r = prove_identity(sp.sin(2 * phi1), 2 * sp.sin(phi1))
    >>> r.status, sorted(r.counterexample)
    (<Status.REFUTED: 'REFUTED'>, ['phi1'])
    """
    t0 = time.perf_counter()
    lhs, rhs = sp.sympify(lhs), sp.sympify(rhs)
    if isinstance(lhs, sp.MatrixBase) and not isinstance(rhs, sp.MatrixBase) and rhs == 0:
        rhs = sp.zeros(*lhs.shape)
    diff = lhs - rhs
    if isinstance(diff, sp.MatrixBase):
        entries = list(diff)
    else:
        entries = [diff]
    bad = []
    for e in entries:
        if not reduce_expr(e).is_zero:
            bad.append(e)
    if not bad:
        return ProofResult(Status.PROVED, "polynomial reduction", time.perf_counter() - t0)
    syms = set().union(*(e.free_symbols for e in bad))
    conds = list(assumptions) or _condition_1_relations(sp.Add(*bad))
    found = find_counterexample(lambda v: any(_nonzero_at(e, v) for e in bad), list(syms),
                                conds)
    if found is not None:
        vals = {"lhs - rhs": float(sp.N(bad[0].subs(found), 17))} if not isinstance(
            diff, sp.MatrixBase) else {}
        return ProofResult(Status.REFUTED, "polynomial reduction + exact substitution",
                           time.perf_counter() - t0, _cx(found), values=vals)
    return ProofResult(Status.UNDECIDED, "polynomial reduction (non-zero normal form, "
                       "no admissible counterexample found)", time.perf_counter() - t0)


# -- signs ---------------------------------------------------------------------
def _coeffs(form: sp.Expr) -> dict[sp.Expr, sp.Expr]:
    return sp.expand(form).as_coefficients_dict()


def _interval(form: sp.Expr, intervals: Intervals) -> tuple[sp.Expr, sp.Expr] | None:
    """Open interval of a linear angle form: looked up, or summed from known parts.

    Parts are taken greedily, longest first, and only when every term of the
    part occurs in what is left with the same sign (so nothing is overshot).
    """
    form = sp.expand(form)
    if form in intervals:
        return intervals[form]
    lo, hi = sp.Integer(0), sp.Integer(0)
    rest = _coeffs(form)
    for key, (a, b) in sorted(intervals.items(), key=lambda kv: -len(sp.Add.make_args(kv[0]))):
        kc = _coeffs(key)
        for sign in (1, -1):
            if all(t in rest and rest[t] * sign * v > 0 and abs(rest[t]) >= abs(v)
                   for t, v in kc.items()):
                for t, v in kc.items():
                    rest[t] -= sign * v
                lo, hi = (lo + a, hi + b) if sign == 1 else (lo - b, hi - a)
                break
    left = sp.Add(*(v * t for t, v in rest.items()))
    if left.free_symbols:
        return None
    return lo + left, hi + left


Sign = tuple[int, int]  # the range [lo, hi] of the sign, within {-1, 0, 1}
_POS, _NEG, _NONNEG, _NONPOS = (1, 1), (-1, -1), (0, 1), (-1, 0)


def _trig_sign(f: sp.Expr, intervals: Intervals) -> Sign | None:
    iv = _interval(f.args[0], intervals)
    if iv is None:
        return None
    lo, hi = (float(v / sp.pi) for v in iv)  # in units of π
    shift = 0.5 if isinstance(f, sp.cos) else 0.0  # cos u = sin(u + π/2)
    lo, hi = lo + shift, hi + shift
    k = int(lo // 1)
    if hi <= k + 1 + 1e-15:  # (lo, hi) inside one half-turn (k, k + 1)
        return _POS if k % 2 == 0 else _NEG
    return None


def _mul(a: Sign, b: Sign) -> Sign:
    prods = [p * q for p in a for q in b]
    return min(prods), max(prods)


def _add(a: Sign, b: Sign) -> Sign | None:
    if a[0] >= 0 and b[0] >= 0:  # both >= 0: positive if either is
        return (1 if max(a[0], b[0]) > 0 else 0), 1
    if a[1] <= 0 and b[1] <= 0:
        return -1, (-1 if min(a[1], b[1]) < 0 else 0)
    return None


def sign_of(f: sp.Expr, intervals: Intervals = CONDITION_1) -> Sign | None:
    """Range of the sign of ``f`` from its structure, or None if unknown.

    Numbers, symbols with sign assumptions, sin/cos of angle forms with known
    intervals, and products, powers and sums of those.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, y, x1
    >>> sign_of(-x1 / 2 + y * sp.sin(phi1 + xi1) / sp.cos(phi1 + xi1),
    ...         {phi1 + xi1: (sp.pi / 2, sp.pi)})
    (-1, -1)
    """
    f = sp.sympify(f)
    if f.is_Number:
        return (0, 0) if f == 0 else (_POS if f > 0 else _NEG)
    if isinstance(f, (sp.sin, sp.cos)):
        return _trig_sign(f, intervals)
    if f.is_Pow and f.exp.is_Integer:
        b = sign_of(f.base, intervals)
        if b is None:
            return None
        out: Sign = (1, 1)
        for _ in range(abs(int(f.exp))):
            out = _mul(out, b)
        return out
    if f.is_Mul or f.is_Add:
        parts = [sign_of(a, intervals) for a in f.args]
        if any(p is None for p in parts):
            return None
        acc = parts[0]
        for p in parts[1:]:
            acc = _mul(acc, p) if f.is_Mul else _add(acc, p)  # type: ignore[arg-type]
            if acc is None:
                return None
        return acc
    if f.is_positive:
        return _POS
    if f.is_negative:
        return _NEG
    if f.is_nonnegative:
        return _NONNEG
    if f.is_nonpositive:
        return _NONPOS
    return None


def prove_sign(
    expr: Any,
    sign: int,
    witness: Sequence[Any] | None = None,
    assumptions: Sequence[Any] = (),
    intervals: Intervals = CONDITION_1,
    subs: Mapping | None = None,
) -> ProofResult:
    """Check ``sign(expr) == sign`` (+1 or -1) for every admissible parameter.

    ``witness`` lists factors whose product equals ``expr`` (after ``subs``,
    a change of variables such as ``x1 + x2 = 2 r sin α``); each factor's sign
    must follow from ``intervals`` or from the symbols' signs.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, mu1
    >>> c1, s1 = sp.cos(phi1), sp.sin(phi1)
    >>> prove_sign(mu1 * s1 - c1, +1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)]).status
    <Status.PROVED: 'PROVED'>
    >>> prove_sign(mu1 * s1 - c1, -1, witness=[-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)]).status
    <Status.REFUTED: 'REFUTED'>
    """
    t0 = time.perf_counter()
    e = sp.sympify(expr)
    conds = list(assumptions) or _condition_1_relations(e)
    found = find_counterexample(lambda v: _wrong_sign(e, sign, v), list(e.free_symbols), conds)
    if found is not None:
        return ProofResult(Status.REFUTED, "exact substitution", time.perf_counter() - t0,
                           _cx(found), values={"expr": float(sp.N(e.subs(found), 17))})
    if witness is None:
        return ProofResult(Status.UNDECIDED, "no witness; no counterexample found",
                           time.perf_counter() - t0)
    target = e.subs(subs) if subs else e
    ident = prove_identity(target, sp.Mul(*witness))
    if not ident.proved:
        return ProofResult(Status.UNDECIDED, "the witness factorisation did not check",
                           time.perf_counter() - t0, detail=ident.status.value)
    found_sign = sign_of(sp.Mul(*witness, evaluate=False), intervals)
    if found_sign is None or found_sign[0] != found_sign[1]:
        return ProofResult(Status.UNDECIDED, "a witness factor has no known strict sign",
                           time.perf_counter() - t0)
    status = Status.PROVED if found_sign[0] == sign else Status.REFUTED
    return ProofResult(status, "witness factorisation + interval signs",
                       time.perf_counter() - t0)


def _wrong_sign(e: sp.Expr, sign: int, values: Mapping) -> bool:
    v = sp.N(e.subs(values), 50)
    if not v.is_number or v.has(sp.zoo, sp.nan):
        raise ValueError("undefined")
    return bool(v * sign <= 0)


def _condition_1_relations(e: sp.Expr) -> list[Any]:
    fs = e.free_symbols
    rels: list[Any] = []
    for phi, xi, mu in ((S.phi1, S.xi1, S.mu1), (S.phi2, S.xi2, S.mu2)):
        fric = xi if xi in fs else sp.atan(mu) if mu in fs else None
        if fric is not None and phi in fs:
            rels += [phi + fric > sp.pi / 2, phi + fric < 3 * sp.pi / 2,
                     phi - fric < sp.pi / 2, phi - fric > -sp.pi / 2]
        if phi in fs:
            rels.append(phi <= sp.pi)
        if xi in fs:
            rels.append(xi < sp.pi / 2)
    return rels
