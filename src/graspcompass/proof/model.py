"""Points of the model: the admissibility check and exact admissible sampling.

A point of the model gives exact values to (some of) the symbols of §2.2 such
that

* each value lies in its domain (:data:`graspcompass.symbols.DOMAINS`:
  ``x1, x2 > 0``, ``y >= 0``, ``0 < phi <= pi``, ``0 < xi < pi/2``, ``mu > 0``);
* condition (1) holds at each contact: ``pi/2 < phi_i + xi_i < 3pi/2`` and
  ``-pi/2 < phi_i - xi_i < pi/2``, with ``xi_i = atan(mu_i)`` when only ``mu_i`` is
  given; when ``phi_i`` is given without a friction value the point must still
  admit one, i.e. ``phi_i < pi``;
* ``mu_i = tan(xi_i)`` (eq. (22)) when both are given;
* the extra relations of the claim (change-of-variable domains, caller hypotheses).

Every decision is exact: a 50-digit evaluation separated from zero by a margin
of 1e-40, or an exact zero test; what neither decides is reported as a violation.
"""

from __future__ import annotations

import numbers
import random
from collections.abc import Callable, Iterable, Mapping, Sequence
from functools import lru_cache
from typing import Any

import mpmath
import sympy as sp

from .. import symbols as S
from ..boundary._numpy import is_a
from ..boundary.errors import WrongTypeError
from ..boundary.expr import ExpressionError, parse_exact
from ..boundary.inputs import real_value

__all__ = [
    "CONTACTS",
    "find_counterexample",
    "nonzero_at",
    "outside_expr",
    "sample",
    "violations",
    "wrong_sign",
]

#: (phi_i, xi_i, mu_i) of the two contacts.
CONTACTS = ((S.phi1, S.xi1, S.mu1), (S.phi2, S.xi2, S.mu2))
_BY_NAME = {str(s): s for s in S.DOMAINS}
_MARGIN = sp.Float(10) ** -40
_LENGTHS = [
    sp.Rational(n, d)
    for n, d in ((1, 3), (1, 2), (2, 3), (1, 1), (3, 2), (2, 1), (5, 2), (3, 1), (7, 5), (4, 5))
]
_MUS = [
    sp.Rational(n, d)
    for n, d in ((1, 5), (1, 3), (1, 2), (3, 4), (1, 1), (6, 5), (7, 5), (2, 1), (3, 1), (5, 1))
]


def outside_expr(value: Any, name: str, known: Iterable[sp.Symbol] = ()) -> Any:
    """An expression, relation or value handed to the proof checker by its caller.

    The proof checker's boundary (:mod:`graspcompass.inputs` for its expressions):
    sympy objects and matrices are built by code and taken as they are; text is
    read by the safe parser :func:`~graspcompass.expr.parse_exact` (the model's
    symbols and ``known`` may occur in it); a list or tuple is read item by item;
    any other value must be a real number (:func:`~graspcompass.inputs.real_value`).
    Nothing from outside reaches ``sympy.sympify``, which runs text (also inside a
    list or a numpy array, or the ``str`` of an unknown object) through ``eval``.

    Parameters
    ----------
    value : sympy object, str, number, list or tuple
    name : str
        The parameter's name, the first word of an error message.
    known : iterable of sympy.Symbol, optional
        Symbols allowed in text besides those of the model.

    Raises
    ------
    InputError
        :class:`~graspcompass.errors.WrongTypeError` for anything else (``None``,
        a numpy array, a dict), :class:`~graspcompass.expr.ExpressionError` for
        text the parser refuses.

    Examples
    --------
    >>> outside_expr("mu1*sin(phi1) - cos(phi1)", "expr")
    mu1*sin(phi1) - cos(phi1)
    >>> import numpy as np
    >>> try:
    ...     outside_expr(np.array(["__import__('os')"]), "expr")
    ... except WrongTypeError as err:
    ...     print(err)  # doctest: +ELLIPSIS
    expr: expected a sympy expression, text or a number, got array([...]...) (type ndarray)
    """
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return value  # built by code: trusted (graspcompass.inputs)
    if isinstance(value, str):
        names = {**{str(s): s for s in known}, **_BY_NAME}
        try:
            return parse_exact(value, symbols=names)
        except ExpressionError as exc:
            raise type(exc)(f"{name}: {exc}") from None
    if isinstance(value, (list, tuple)):
        items = [outside_expr(v, f"{name}[{i}]", known) for i, v in enumerate(value)]
        return items if isinstance(value, list) else tuple(items)
    if value is None or isinstance(value, numbers.Number) or is_a(value, "generic"):
        return real_value(value, name)
    try:
        shown = repr(value)
    except Exception:  # a hostile __repr__ must not hide the real error
        shown = "..."
    shown = shown if len(shown) <= 60 else shown[:57] + "..."
    raise WrongTypeError(
        f"{name}: expected a sympy expression, text or a number, got "
        f"{shown} (type {type(value).__name__})"
    )


def _normalise(
    values: Mapping[Any, Any], known: Iterable[sp.Symbol] = ()
) -> dict[sp.Symbol, sp.Expr]:
    """Symbols for names (those of the model, else of ``known``), exact values for text.

    Values from the caller pass :func:`graspcompass.inputs.real_value` (text by the
    safe parser, never ``sympify``); sympy values are kept as they are, so that a
    complex one is reported by :func:`violations` rather than refused here.
    """
    names = {**{str(s): s for s in known}, **_BY_NAME}
    out: dict[sp.Symbol, sp.Expr] = {}
    for k, v in values.items():
        sym = k if isinstance(k, sp.Symbol) else names.get(str(k), sp.Symbol(str(k)))
        out[sym] = v if isinstance(v, sp.Basic) else real_value(v, str(sym))
    return out


#: (lower bound, open?, upper bound, open?) of each symbol of the model (§2.2).
_DOMAIN: dict[sp.Symbol, tuple[Any, bool, Any, bool]] = {
    S.x1: (0, True, None, False),
    S.x2: (0, True, None, False),
    S.y: (0, False, None, False),
    S.phi1: (0, True, sp.pi, False),
    S.phi2: (0, True, sp.pi, False),
    S.xi1: (0, True, sp.pi / 2, True),
    S.xi2: (0, True, sp.pi / 2, True),
    S.mu1: (0, True, None, False),
    S.mu2: (0, True, None, False),
    S.F_e: (0, True, None, False),
    S.theta: (None, False, None, False),
}


@lru_cache(maxsize=65536)
def _sign(d: sp.Expr) -> int | None:
    """Exact sign of the number ``d``: 50 digits with a margin, else an exact zero test."""
    d = sp.sympify(d)  # internal: d is built here from sympy values (or a Python int)
    if d.free_symbols:
        return None
    if d.is_Rational:
        return int(sp.sign(d))
    q = d / sp.pi
    if q.is_Add:
        q = sp.expand(q)
    if q.is_Rational:
        return int(sp.sign(q))
    v = sp.N(d, 50)
    if not v.is_number or v.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not v.is_real:
        return None
    if abs(v) > _MARGIN:
        return 1 if v > 0 else -1
    if sp.expand(d) == 0 or sp.radsimp(sp.expand(d)) == 0:
        return 0
    return None


_OPS = {
    sp.StrictGreaterThan: lambda s: s > 0,
    sp.GreaterThan: lambda s: s >= 0,
    sp.StrictLessThan: lambda s: s < 0,
    sp.LessThan: lambda s: s <= 0,
    sp.Equality: lambda s: s == 0,
    sp.Unequality: lambda s: s != 0,
}


def _check(rel: Any, values: Mapping[sp.Symbol, sp.Expr]) -> str | None:
    """None if ``rel`` holds at ``values``, else why not."""
    rel = outside_expr(rel, "assumption")  # a caller's hypothesis: never sympify
    if rel is sp.true:
        return None
    if rel is sp.false:
        return "False"
    if isinstance(rel, sp.And):
        for a in rel.args:
            bad = _check(a, values)
            if bad:
                return bad
        return None
    if type(rel) not in _OPS:
        return f"{rel}: not a relation"
    d = (rel.lhs - rel.rhs).xreplace(values)
    s = _sign(d)
    if s is None:
        return f"{rel}: undecided at {d}"
    return None if _OPS[type(rel)](s) else f"{rel} fails ({rel.lhs - rel.rhs} = {sp.N(d, 8)})"


def _condition_1(phi: sp.Expr, fric: sp.Expr) -> list[Any]:
    return [
        sp.StrictGreaterThan(phi + fric, sp.pi / 2, evaluate=False),
        sp.StrictLessThan(phi + fric, 3 * sp.pi / 2, evaluate=False),
        sp.StrictLessThan(phi - fric, sp.pi / 2, evaluate=False),
        sp.StrictGreaterThan(phi - fric, -sp.pi / 2, evaluate=False),
    ]


def violations(values: Mapping[Any, Any], extra: Iterable[Any] = ()) -> list[str]:
    """What keeps ``values`` from being a point of the model (empty list: none).

    Parameters
    ----------
    values : mapping of symbol (or its name) to exact value (or its text)
    extra : relations that must hold too (the claim's own hypotheses)

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, mu1
    >>> violations({phi1: sp.pi / 2, xi1: sp.pi / 4, mu1: 1})
    []
    >>> violations({phi1: sp.pi / 2, xi1: sp.pi / 4, mu1: 2})
    ['mu1 = tan(xi1) (eq. (22)) fails']
    >>> violations({phi1: sp.pi / 6, mu1: sp.Rational(1, 3)})
    ['condition (1) at contact 1: phi1 + atan(mu1) > pi/2 fails']
    """
    extra = [outside_expr(r, "assumption") for r in extra]
    v = _normalise(values, set().union(*(r.free_symbols for r in extra)))
    out: list[str] = []
    for sym, val in v.items():
        if val.is_real is False or val.has(sp.zoo, sp.nan, sp.I):
            out.append(f"{sym} = {val} is not real")
            continue
        lo, lo_open, hi, hi_open = _DOMAIN.get(sym) or (
            (0, True, None, False)
            if sym.is_positive
            else (0, False, None, False)
            if sym.is_nonnegative
            else (None, False, None, False)
        )
        for bound, is_open, side in ((lo, lo_open, 1), (hi, hi_open, -1)):
            if bound is None:
                continue
            s = _sign(side * (val - bound))
            if s is None or s < 0 or (s == 0 and is_open):
                op = (">" if side == 1 else "<") + ("" if is_open else "=")
                out.append(f"domain of {sym}: {sym} {op} {bound} fails at {sym} = {val}")
    for i, (phi, xi, mu) in enumerate(CONTACTS, 1):
        if xi in v and mu in v and _equal_tan(v[mu], v[xi]) is not True:
            out.append(f"{mu} = tan({xi}) (eq. (22)) fails")
        fric, name = (
            (xi, str(xi)) if xi in v else (sp.atan(mu), f"atan({mu})") if mu in v else (None, "")
        )
        qp, qf = _pi_q(v.get(phi)), _fric_q(v, xi, mu)
        if qp is not None and qf is not None:  # rational multiples of pi: exact at once
            if not (abs(qp + qf - 1) < sp.Rational(1, 2) and abs(qp - qf) < sp.Rational(1, 2)):
                out.append(
                    f"condition (1) at contact {i}: {phi} = {v[phi]}, {name} = "
                    f"{qf * sp.pi} break pi/2 < phi + xi < 3pi/2, |phi - xi| < pi/2"
                )
        elif phi in v and fric is not None:
            fv = fric.xreplace(v)
            for n, rel in enumerate(_condition_1(v[phi], fv)):
                if _check(rel, v):
                    text = (
                        f"{phi} + {name} > pi/2",
                        f"{phi} + {name} < 3*pi/2",
                        f"{phi} - {name} < pi/2",
                        f"{phi} - {name} > -pi/2",
                    )[n]
                    out.append(f"condition (1) at contact {i}: {text} fails")
        elif phi in v and _check(sp.StrictLessThan(v[phi], sp.pi, evaluate=False), v):
            out.append(
                f"condition (1) at contact {i}: {phi} < pi fails (no friction "
                "value admits this angle)"
            )
    for rel in extra:
        bad = _check(rel, v)
        if bad:
            out.append(f"hypothesis {bad}")
    return out


def _pi_q(val: sp.Expr | None) -> sp.Rational | None:
    """q when ``val`` is literally q*pi with rational q, else None."""
    if val is None:
        return None
    if val == 0:
        return sp.Integer(0)
    c, rest = val.as_coeff_Mul()
    return c if rest is sp.pi and c.is_Rational else None


def _fric_q(v: Mapping[sp.Symbol, sp.Expr], xi: sp.Symbol, mu: sp.Symbol) -> sp.Rational | None:
    if xi in v:
        return _pi_q(v[xi])
    m = v.get(mu)
    if isinstance(m, sp.tan):
        q = _pi_q(m.args[0])
        if q is not None and 0 < q < sp.Rational(1, 2):
            return q  # atan(tan(q*pi)) = q*pi on (0, pi/2)
    return None


def _equal_tan(mu: sp.Expr, xi: sp.Expr) -> bool | None:
    if isinstance(mu, sp.tan) and sp.expand(mu.args[0] - xi) == 0:
        return True
    s = _sign(sp.tan(xi) - mu)
    return None if s is None else s == 0


def _angle(rng: random.Random, lo: int, hi: int) -> sp.Expr:
    return sp.pi * sp.Rational(rng.randint(lo, hi), 24)


def sample(
    symbols: Sequence[sp.Symbol],
    rng: random.Random,
    domains: Mapping[sp.Symbol, tuple[Any, Any]] | None = None,
) -> dict[sp.Symbol, sp.Expr]:
    """An exact admissible point for ``symbols`` (condition (1), (22), the domains).

    ``xi_i`` is drawn first and ``mu_i = tan(xi_i)`` exactly when both occur; ``phi_i``
    is drawn so that (1) holds; a symbol outside the model takes a value strictly
    inside ``domains[sym] = (lo, hi)`` (``hi`` may be None), else one that respects
    its sympy sign assumptions.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, xi1, mu1
    >>> p = sample([phi1, xi1, mu1], random.Random(1))
    >>> violations(p)
    []
    """
    want = set(symbols)
    out: dict[sp.Symbol, sp.Expr] = {}
    for phi, xi, mu in CONTACTS:
        if xi in want or (mu in want and rng.random() < 0.7):
            while True:
                j, k = rng.randint(1, 23), rng.randint(1, 11)
                if abs(j - k) < 12 < j + k or phi not in want:
                    break
            if xi in want:
                out[xi] = sp.pi * sp.Rational(k, 24)
            if mu in want:
                out[mu] = sp.tan(sp.pi * sp.Rational(k, 24), evaluate=False)
            if phi in want:
                out[phi] = sp.pi * sp.Rational(j, 24)
        elif mu in want:
            out[mu] = rng.choice(_MUS)
            if phi in want:  # (1) with xi = atan(mu): phi in (pi/2 - xi, pi/2 + xi)
                out[phi] = sp.pi * sp.Rational(rng.choice(_phis_for(out[mu])), 24)
        elif phi in want:
            out[phi] = _angle(rng, 1, 23)
    for sym in sorted(want - set(out), key=str):
        out[sym] = _value(sym, rng, (domains or {}).get(sym))
    return out


@lru_cache(maxsize=64)
def _phis_for(mu: sp.Expr) -> tuple[int, ...]:
    """The j with phi = j*pi/24 satisfying (1) for this mu."""
    a = sp.N(24 * sp.atan(mu) / sp.pi, 50)  # (1): 12 - a < j < 12 + a; re-checked later
    return tuple(j for j in range(1, 24) if abs(j - 12) < a - _MARGIN)


def _value(sym: sp.Symbol, rng: random.Random, dom: tuple[Any, Any] | None) -> sp.Expr:
    if dom is not None:
        lo, hi = (outside_expr(d, f"domain of {sym}") if d is not None else None for d in dom)
        if hi is None:
            return lo + rng.choice(_LENGTHS)
        return lo + (hi - lo) * sp.Rational(rng.randint(1, 23), 24)
    if sym == S.theta:
        return _angle(rng, -23, 23) + sp.Rational(1, 7)
    if sym == S.y and rng.random() < 0.15:
        return sp.Integer(0)
    value = rng.choice(_LENGTHS)
    if sym.is_positive or sym.is_nonnegative:
        return value
    return value * rng.choice([-1, 1])


def find_counterexample(
    test: Callable[[Mapping[sp.Symbol, sp.Expr]], bool],
    symbols: Iterable[sp.Symbol],
    assumptions: Sequence[Any] = (),
    tries: int = 60,
    seed: int = 2012,
    *,
    domains: Mapping[sp.Symbol, tuple[Any, Any]] | None = None,
    derived: Mapping[sp.Symbol, sp.Expr] | None = None,
) -> dict[sp.Symbol, sp.Expr] | None:
    """A point of the model where ``test(values)`` is True, or None.

    ``test`` must decide exactly (e.g. by a 50-digit evaluation of an exact
    expression); it receives the whole point (sampled and derived values).
    ``assumptions`` are relations on top of the model (never a replacement
    for it); ``domains`` gives intervals of change-of-variable symbols;
    ``derived`` gives symbols of the model as functions of the sampled ones
    (``x1 = 2*r*sin(alpha) - x2``): their values join the point, and the whole
    point is re-checked with :func:`violations` before it is returned.

    Examples
    --------
    >>> from graspcompass.symbols import phi1, mu1
    >>> d = mu1 * sp.sin(phi1) - sp.cos(phi1)  # > 0 under (1): no counterexample
    >>> p = find_counterexample(lambda v: sp.N(d.xreplace(v), 50) <= 0, [phi1, mu1])
    >>> p is None
    True
    """
    rng = random.Random(seed)
    syms = sorted(set(symbols), key=str)
    for _ in range(tries * 4):
        values = sample(syms, rng, domains)
        full = dict(values)
        for s, e in (derived or {}).items():
            full[s] = e.xreplace(values)
        try:
            hit = test(full)
        except (ZeroDivisionError, TypeError, ValueError):
            continue
        if hit and not violations(full, assumptions):  # the exact re-check of the point
            return full
        tries -= 1
        if tries <= 0:
            break
    return None


# -- evaluation at a point -------------------------------------------------------
@lru_cache(maxsize=512)
def _mp(e: sp.Expr) -> tuple[Callable[..., Any], tuple[sp.Symbol, ...]]:
    syms = tuple(sorted(e.free_symbols, key=str))
    return sp.lambdify(syms, e, modules="mpmath"), syms


@lru_cache(maxsize=4096)
def _mpf(v: sp.Expr) -> Any:
    """An exact value as a 70-digit mpmath number (values of samples recur: cached)."""
    return mpmath.mpf(str(sp.N(v, 70)))


_SCREEN = mpmath.mpf(10) ** -20


def _fast(e: sp.Expr, values: Mapping) -> Any:
    """``e`` at ``values`` by mpmath at 60 digits (a screen), or None if not a real number."""
    f, syms = _mp(e)
    try:
        with mpmath.workdps(60):
            v = f(*(_mpf(values[s]) for s in syms))
    except (ZeroDivisionError, TypeError, ValueError, KeyError, OverflowError):
        return None
    return v if isinstance(v, mpmath.mpf) else None


def wrong_sign(e: sp.Expr, sign: int, values: Mapping) -> bool:
    """``sign * e <= 0`` at ``values``: a 60-digit mpmath screen, confirmed by ``evalf``."""
    fast = _fast(e, values)
    if fast is not None and fast * sign > _SCREEN:
        return False  # clearly of the claimed sign: no candidate here
    v = sp.N(e.xreplace(values), 50)
    if not v.is_number or v.has(sp.zoo, sp.nan) or not v.is_real:
        raise ValueError("undefined")
    return bool(v * sign <= 0)


def nonzero_at(expr: sp.Expr, values: Mapping, screen: bool = False) -> bool:
    """``expr != 0`` at ``values``: a 50-digit evaluation separated from 0 by 1e-30.

    With ``screen``, a 60-digit mpmath value of modulus above 1e-20 settles
    "non-zero" first (used only where "non-zero" ends a search, never for a verdict).
    """
    if screen:
        fast = _fast(expr, values)
        if fast is not None and abs(fast) > _SCREEN:
            return True
    v = sp.N(expr.xreplace(values), 50)
    if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not v.is_number:
        raise ValueError("undefined at this point")
    return abs(v) > sp.Float(10) ** -30
