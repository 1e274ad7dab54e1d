"""Signs from structure: interval hypotheses on angle forms, symbols' domains, numbers.

Every decision here is exact: interval endpoints are rational multiples of π,
compared as rationals.  :func:`sign_reason` also returns the reason as
JSON-ready data that :mod:`graspcompass.proof.recheck` re-verifies without
sympy; :func:`discharge` shows a denominator factor non-zero under the
hypotheses (condition (1) by default).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache
from typing import Any

import sympy as sp

from .. import symbols as S
from .model import outside_expr

__all__ = ["CONDITION_1", "Intervals", "discharge", "form_json", "sign_of", "sign_reason"]

Intervals = Mapping[sp.Expr, tuple[sp.Expr, sp.Expr]]

#: Open intervals of the angle forms under the domains and condition (1).
CONDITION_1: dict[sp.Expr, tuple[sp.Expr, sp.Expr]] = {
    S.xi1: (0, sp.pi / 2),
    S.xi2: (0, sp.pi / 2),
    S.phi1: (0, sp.pi),
    S.phi2: (0, sp.pi),  # φ ≤ π, and φ = π is excluded by (1)
    S.phi1 + S.xi1: (sp.pi / 2, 3 * sp.pi / 2),
    S.phi2 + S.xi2: (sp.pi / 2, 3 * sp.pi / 2),
    S.phi1 - S.xi1: (-sp.pi / 2, sp.pi / 2),
    S.phi2 - S.xi2: (-sp.pi / 2, sp.pi / 2),
}

Sign = tuple[int, int]  # the range [lo, hi] of the sign, within {-1, 0, 1}
_POS, _NEG, _NONNEG, _NONPOS = (1, 1), (-1, -1), (0, 1), (-1, 0)


def _frac(q: sp.Expr) -> str:
    q = sp.Rational(q)
    return f"{q.p}/{q.q}"


def form_json(form: sp.Expr) -> dict[str, int] | None:
    """A linear angle form with integer coefficients as ``{name: coefficient}``."""
    out: dict[str, int] = {}
    for t, c in sp.expand(form).as_coefficients_dict().items():
        if not (t.is_Symbol and c.is_Integer):
            return None
        out[str(t)] = int(c)
    return out


def _pi_multiple(v: sp.Expr) -> sp.Rational | None:
    q = sp.expand(outside_expr(v, "interval end") / sp.pi)  # may be a caller's: no sympify
    return q if q.is_Rational else None


def _interval(form: sp.Expr, intervals: Intervals) -> tuple[sp.Expr, sp.Expr] | None:
    """Open interval of a linear angle form: looked up, or summed from known parts."""
    got = _interval_pieces(form, intervals)
    return None if got is None else got[0]


def _interval_pieces(form: sp.Expr, intervals: Intervals):
    """Interval of ``form`` and the hypotheses used (greedy, longest parts first).

    Parts are taken only when every term of the part occurs in what is left with
    the same sign (so nothing is overshot); the leftover must be a constant.
    """
    form = sp.expand(form)
    if form in intervals:
        a, b = intervals[form]
        a, b = outside_expr(a, f"interval of {form}"), outside_expr(b, f"interval of {form}")
        return (a, b), [(form, 1, a, b)], sp.Integer(0)
    lo, hi = sp.Integer(0), sp.Integer(0)
    rest = form.as_coefficients_dict()
    rest = {t: v for t, v in rest.items()}
    pieces = []
    for key, (a, b) in sorted(
        intervals.items(),
        key=lambda kv: (-len(sp.Add.make_args(kv[0])), sp.default_sort_key(kv[0])),
    ):
        kc = sp.expand(key).as_coefficients_dict()
        for sign in (1, -1):
            if all(
                t in rest and rest[t] * sign * v > 0 and abs(rest[t]) >= abs(v)
                for t, v in kc.items()
            ):
                for t, v in kc.items():
                    rest[t] -= sign * v
                lo, hi = (lo + a, hi + b) if sign == 1 else (lo - b, hi - a)
                pieces.append((key, sign, a, b))
                break
    left = sp.Add(*(v * t for t, v in rest.items()))
    if left.free_symbols:
        return None
    return (lo + left, hi + left), pieces, left


#: ``_trig`` by content: (the sine or cosine, the intervals as items) -> its answer.
_TRIG_MEMO: dict[tuple, tuple[Sign, dict] | None] = {}


def _trig(f: sp.Expr, intervals: Intervals) -> tuple[Sign, dict] | None:
    key = (f, tuple(intervals.items()))
    if key not in _TRIG_MEMO:
        if len(_TRIG_MEMO) > 4096:
            _TRIG_MEMO.clear()
        _TRIG_MEMO[key] = _trig_sign(f, intervals)
    return _TRIG_MEMO[key]


def _trig_sign(f: sp.Expr, intervals: Intervals) -> tuple[Sign, dict] | None:
    got = _interval_pieces(f.args[0], intervals)
    if got is None:
        return None
    (lo, hi), pieces, const = got
    qlo, qhi, qc = _pi_multiple(lo), _pi_multiple(hi), _pi_multiple(const)
    if qlo is None or qhi is None or qc is None:
        return None
    shift = sp.Rational(1, 2) if isinstance(f, sp.cos) else 0  # cos u = sin(u + π/2)
    k = sp.floor(qlo + shift)
    if qhi + shift > k + 1:
        return None
    sign = _POS if k % 2 == 0 else _NEG
    fj = form_json(f.args[0] - const)
    pj = [form_json(p) for p, *_ in pieces]
    if fj is None or any(p is None for p in pj):
        return None
    return sign, {
        "type": "trig",
        "func": type(f).__name__,
        "form": fj,
        "const": _frac(qc),
        "pieces": [
            {"form": p, "coeff": s, "interval": [_frac(_pi_multiple(a)), _frac(_pi_multiple(b))]}
            for p, (_, s, a, b) in zip(pj, pieces)
        ],
        "interval": [_frac(qlo), _frac(qhi)],
        "sign": list(sign),
    }


def _mul(a: Sign, b: Sign) -> Sign:
    prods = [p * q for p in a for q in b]
    return min(prods), max(prods)


def _add(a: Sign, b: Sign) -> Sign | None:
    if a[0] >= 0 and b[0] >= 0:  # both >= 0: positive if either is
        return (1 if max(a[0], b[0]) > 0 else 0), 1
    if a[1] <= 0 and b[1] <= 0:
        return -1, (-1 if min(a[1], b[1]) < 0 else 0)
    return None


def sign_reason(f: Any, intervals: Intervals = CONDITION_1) -> tuple[Sign, dict] | None:
    """Range of the sign of ``f`` and its reason (JSON-ready), or None if unknown.

    Numbers, symbols with sign assumptions (the domains of §2.2), sin/cos of
    angle forms whose interval (summed from ``intervals``) lies in one
    half-turn, square roots of positive things, and products, integer powers
    and sums of those.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1
    >>> sign_reason(sp.cos(phi1 + xi1))[0]
    (-1, -1)
    """
    f = outside_expr(f, "f")  # the caller's: never sympify
    if f.is_Rational:
        s = (0, 0) if f == 0 else (_POS if f > 0 else _NEG)
        return s, {"type": "number", "value": _frac(f), "sign": list(s)}
    if f.is_number and not f.free_symbols and not f.has(sp.I):
        v = sp.N(f, 50)
        if not v.is_real or abs(v) < sp.Float(10) ** -40:
            return None
        r = sp.Rational(v)
        eps = sp.Rational(1, 10**40)
        s = _POS if v > 0 else _NEG
        return s, {
            "type": "enclosure",
            "expr": str(f),
            "lo": _frac(r - eps),
            "hi": _frac(r + eps),
            "sign": list(s),
        }
    if isinstance(f, (sp.sin, sp.cos)):
        return _trig(f, intervals)
    if f.is_Symbol:
        known: Sign | None = (
            _POS
            if f.is_positive
            else _NEG
            if f.is_negative
            else _NONNEG
            if f.is_nonnegative
            else _NONPOS
            if f.is_nonpositive
            else None
        )
        return (
            None
            if known is None
            else (known, {"type": "symbol", "name": str(f), "sign": list(known)})
        )
    if f.is_Pow and f.exp == sp.S.Half:
        b = sign_reason(f.base, intervals)
        if b is None or b[0][0] < 0:
            return None
        return b[0], {"type": "sqrt", "base": b[1], "sign": list(b[0])}
    if f.is_Pow and f.exp.is_Integer:
        b = sign_reason(f.base, intervals)
        if b is None or (f.exp < 0 and b[0][0] <= 0 <= b[0][1]):
            return None
        out: Sign = (1, 1)
        for _ in range(abs(int(f.exp))):
            out = _mul(out, b[0])
        return out, {"type": "pow", "base": b[1], "exp": int(f.exp), "sign": list(out)}
    if f.is_Mul or f.is_Add:
        parts = []
        acc: Sign | None = None
        for a in f.args:  # the first part of unknown sign settles it: no more work
            p = sign_reason(a, intervals)
            if p is None:
                return None
            parts.append(p)
            acc = p[0] if acc is None else _mul(acc, p[0]) if f.is_Mul else _add(acc, p[0])
            if acc is None:
                return None
        if acc is None:  # no arguments (sympy never builds such a Mul or Add)
            return None
        kind = "mul" if f.is_Mul else "add"
        return acc, {"type": kind, "args": [p[1] for p in parts], "sign": list(acc)}
    return None


def sign_of(f: Any, intervals: Intervals = CONDITION_1) -> Sign | None:
    """Range of the sign of ``f`` from its structure, or None if unknown.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, y, x1
    >>> sign_of(-x1 / 2 + y * sp.sin(phi1 + xi1) / sp.cos(phi1 + xi1),
    ...         {phi1 + xi1: (sp.pi / 2, sp.pi)})
    (-1, -1)
    """
    got = sign_reason(f, intervals)
    return None if got is None else got[0]


def _key(intervals: Intervals) -> frozenset:
    """The intervals by content (hashable; no printing, no sorting)."""
    return frozenset((k, tuple(v)) for k, v in intervals.items())


def discharge(factor: sp.Expr, intervals: Intervals = CONDITION_1) -> str | None:
    """Why ``factor != 0`` follows from ``intervals`` and the domains, or None.

    Tries the factor's sign from its structure, then ``factor = λ·t / cos(ξ)^k``
    with ``t`` the sine or cosine of a short angle form of strict sign (this is how
    ``mu1*sin(phi1) - cos(phi1) = -cos(phi1 + xi1)/cos(xi1)`` is shown non-zero, eq. (22)).

    Examples
    --------
    >>> from graspcompass.symbols import phi1, mu1
    >>> discharge(mu1 * sp.sin(phi1) - sp.cos(phi1))
    'sign of -cos(phi1 + xi1)/cos(xi1)'
    """
    return _discharge(factor, _key(intervals))


@lru_cache(maxsize=4096)
def _discharge(factor: sp.Expr, ikey: frozenset) -> str | None:
    from ._ring import to_ring

    intervals = {k: v for k, v in ikey}
    got = sign_reason(factor, intervals)
    if got is not None and got[0][0] == got[0][1] != 0:
        return "sign"
    g, angles, mult = factor, set(), sp.Integer(1)
    for mu, xi in ((S.mu1, S.xi1), (S.mu2, S.xi2)):
        if factor.has(mu):
            mult *= sp.cos(xi) ** sp.degree(factor, mu)  # > 0: 0 < xi < pi/2
            g = g.subs(mu, sp.sin(xi) / sp.cos(xi))
            angles.add(xi)
    g = g * mult
    for t in factor.atoms(sp.sin, sp.cos):
        angles |= t.args[0].free_symbols
    angles_l = sorted(angles, key=sp.default_sort_key)
    # t = sin or cos of u depends on every angle of u and only on those, as g must:
    # the forms are a, or a ± b when g involves two angles (no more are tried)
    if not angles_l or len(angles_l) > 2:
        return None
    forms = [angles_l[0] + sg * a for sg in (1, -1) for a in angles_l[1:]] or angles_l
    for u in forms:
        for fn in (sp.sin, sp.cos):
            cand = fn(u)
            cs = sign_reason(cand, intervals)
            if cs is None or cs[0][0] != cs[0][1] or cs[0][0] == 0:
                continue
            form = to_ring([g, cand])
            (ng, dg), (nc, dc) = form.values
            a, b = ng * dc, nc * dg
            if form.relations:
                a, b = a.rem(form.relations), b.rem(form.relations)
            if not a or not b:
                continue
            lam = a.LC / b.LC
            if a == b * lam:
                ratio = sp.Rational(int(lam.numerator), int(lam.denominator))
                return f"sign of {ratio * cand / mult}"
    return None
