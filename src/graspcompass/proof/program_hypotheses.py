"""The file's inequality hypotheses in the checker: signs, conditions, admissible points.

A file may restrict its parameters with named inequalities (``hypothesis outside:
p**2 + q**2 > 1``, :class:`~graspcompass.construction._hypotheses.Inequality`); they
hold for the whole file.  Here:

* :func:`sign_from` — the sign of an expression from its factors: each factor's sign
  is known from the symbols' assumptions (the domains), or the factor is ±c·H (c > 0
  rational) of a hypothesis ``H > 0`` (``H ≠ 0`` for a factor to an even power or for
  ``≠``), or ``f − H`` is shown ≥ 0 for every value
  (:func:`graspcompass.geometry.roots.nonnegative`) with ``H > 0``, so ``f > 0``;
* :func:`discharge` — the conditions of a row whose sign follows so are moved to the
  implied ones, with the hypotheses they follow from;
* :func:`branch_roots` — the branch a construction took, decided by the hypotheses: a
  constructed root √(f²X) (√ ≥ 0, the kernel's branch) is |f|·√X, and |f| = ±f where the
  hypotheses give f's sign;
* :func:`~graspcompass.proof.program_search.witness_point` — a point where they all
  hold: without one (contradictory hypotheses) no claim is PROVED under them;
* :func:`holds` — a point is admissible only where every hypothesis holds, exactly (the
  counterexample search tries no other point).

Examples
--------
>>> import sympy as sp
>>> from graspcompass.construction._hypotheses import Inequality
>>> p, q = sp.symbols("p q", real=True)
>>> H = (Inequality("outside", ">", p**2 + q**2, sp.Integer(1)),)
>>> sign_from(p**2 + q**2 - 1, H), sign_from(2 - 2*p**2 - 2*q**2, H)
((1, ('outside',)), (-1, ('outside',)))
>>> sign_from(p**2 + q**2, H)
(1, ('outside',))
>>> sign_from(p - 1, H) is None
True
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import sympy as sp

__all__ = ["branch_roots", "discharge", "holds", "sign_from", "texts"]


def texts(program: Any) -> tuple[str, ...]:
    """``hypothesis NAME: ...`` of each inequality of the file, as results state them."""
    return tuple(f"hypothesis {h.text}" for h in getattr(program, "inequalities", ()))


def holds(program: Any, point: Mapping[str, Any]) -> bool:
    """Every inequality of ``program`` holds at ``point`` (parameter name -> exact value)."""
    hs = getattr(program, "inequalities", ())
    if not hs:
        return True
    at = {p.symbol: sp.sympify(point[p.name]) for p in program.params if p.name in point}
    return all(h.holds(at) for h in hs)


def _match(f: sp.Expr, hyps: Sequence[Any]) -> tuple[int, bool, str] | None:
    """``(sign, strict, name)``: f = ±c·H with c > 0 rational, or f − H ≥ 0 with H > 0."""
    from ..geometry.roots import nonnegative

    for h in hyps:
        g = h.expr0
        ratio = sp.cancel(f / g)
        if ratio.is_Rational and ratio != 0:
            return (1 if ratio > 0 else -1), h.relation0 == ">", h.name
        if h.relation0 == ">":
            for s in (1, -1):
                try:
                    if nonnegative(sp.expand(s * f - g)):
                        return s, True, h.name
                except (sp.PolynomialError, TypeError, ValueError):
                    continue
    return None


def _relation(name: str, hyps: Sequence[Any]) -> str:
    return next(h.relation0 for h in hyps if h.name == name)


def sign_from(
    e: sp.Expr, hyps: Sequence[Any], nonzero_only: bool = False
) -> tuple[int, tuple[str, ...]] | None:
    """``(sign of e, hypotheses used)`` shown from its factors (see the module), or None.
    With ``nonzero_only`` a factor ``H`` of a hypothesis ``H ≠ 0`` counts as non-zero
    (the sign returned is then only ``e ≠ 0``: 0 is returned for it)."""
    if not hyps:
        return None
    try:
        num, den = sp.fraction(sp.together(sp.sympify(e)))
        parts = [sp.factor_list(num), sp.factor_list(den)]
    except (sp.PolynomialError, NotImplementedError, ValueError, TypeError):
        return None
    sign, only_nonzero = 1, False
    used: list[str] = []
    for c, factors in parts:
        if c == 0:
            return None
        sign *= 1 if c > 0 else -1
        for f, m in factors:
            if not sp.sympify(m).is_Integer:  # f**(1/2): > 0 where f > 0
                inner = sign_from(sp.factor(f), hyps) if not f.is_positive else (1, ())
                if inner is None or inner[0] != 1:
                    return None
                used += inner[1]
                continue
            if f.is_positive:
                continue
            if f.is_negative:
                sign *= (-1) ** m
                continue
            if f.is_Pow and f.exp == sp.Rational(1, 2):  # √R > 0 where R > 0
                inner = sign_from(f.base, hyps)
                if inner is None or inner[0] != 1:
                    return None
                used += inner[1]
                continue
            got = _match(f, hyps)
            if got is None:
                whole = _match(sp.expand(num / c), hyps) if len(factors) > 1 else None
                if whole is not None and den == 1 and whole[1]:
                    return whole[0] * (1 if c > 0 else -1), (whole[2],)
                return None
            s, strict, name = got
            used.append(name)
            if not strict:  # H ≥ 0 says nothing of ≠ 0; H ≠ 0 only that
                if not nonzero_only or _relation(name, hyps) != "!=":
                    return None
                only_nonzero = True
            sign *= s**m
    return (0 if only_nonzero else sign), tuple(dict.fromkeys(used))


def discharge(
    conditions: Iterable[str], hyps: Sequence[Any], symbols: Mapping[str, sp.Symbol]
) -> tuple[list[str], list[str]]:
    """``(conditions kept, conditions implied by the hypotheses, with their names)`` of
    texts ``EXPR ≠ 0``, ``EXPR ≥ 0`` or ``EXPR > 0`` (with words in parentheses)."""
    from .program_words import parse_condition

    kept, implied = [], []
    for t in conditions:
        got = parse_condition(t, symbols) if hyps else None
        if got is None:
            kept.append(t)
            continue
        e, rel = got
        s = sign_from(e, hyps, nonzero_only=rel == "≠")
        if s is None or (rel != "≠" and s[0] != 1) or (rel == "≠" and s[0] is None):
            kept.append(t)
            continue
        implied.append(f"{t} (from the hypothesis {', '.join(s[1])})")
    return kept, implied


def branch_roots(e: Any, hyps: Sequence[Any]) -> Any:
    """``e`` with each square root √(f^2k·X) whose factor f has a sign given by the
    hypotheses written ±f^k·√X (the same number wherever the hypotheses hold)."""
    if not hyps or not isinstance(e, sp.Basic):
        return e
    roots = [a for a in e.atoms(sp.Pow) if a.exp == sp.Rational(1, 2) and a.base.free_symbols]
    subs = {}
    for r in roots:
        try:
            num, den = sp.fraction(sp.together(r.base))
            (cn, fn), (cd, fd) = sp.factor_list(num), sp.factor_list(den)
        except (sp.PolynomialError, NotImplementedError, ValueError, TypeError):
            continue
        out, inner, changed = sp.Integer(1), sp.Rational(cn, 1) / cd, False
        for factors, k in ((fn, 1), (fd, -1)):
            for f, m in factors:
                got = sign_from(f, hyps) if m >= 2 else None
                if got is None or got[0] == 0:
                    inner *= f ** (m * k)
                    continue
                changed = True
                out *= (got[0] * f) ** ((m // 2) * k)
                inner *= f ** ((m % 2) * k)
        if changed:
            subs[r] = out * sp.sqrt(inner)
    for a in e.atoms(sp.Abs):  # |f| as sympy writes √(f²) of a real f
        got = sign_from(a.args[0], hyps)
        if got is not None and got[0] != 0:
            subs[a] = got[0] * a.args[0]
    return e.xreplace(subs) if subs else e
