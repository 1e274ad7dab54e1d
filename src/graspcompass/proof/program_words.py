"""The conditions of a checked row, tidied: factored, deduplicated, discharged, in words.

A row's non-degeneracy conditions come from the parser (divisors, radicands), the
kernel (a denominator of each step) and the operations (``the circles k1 and k2
meet``); the same expression then recurs with and without its words, as ``≠`` and
``!=``, and with factors whose sign the domains decide (``b ≠ 0`` under ``param b > 0``,
``t² + 1 ≠ 0``).  :func:`tidy` factors each condition (small ones), drops the factors
of known sign (sympy's assumptions on the parameters' symbols: a ``> 0`` parameter is
positive, a ``real`` one real), moves a condition all of whose factors have a known
sign to the implied ones, and merges the conditions on one expression into one, with
all their words.

The kernel's own ``≠ 0`` conditions of a step (what it divides by) are worded by
:func:`kernel_worded` as GCLC words them: ``the lines AB and CD are not parallel``.

Examples
--------
>>> import sympy as sp
>>> b = sp.Symbol("b", positive=True)
>>> p = sp.Symbol("p", real=True)
>>> tidy(["b**2*(p**2 + 1) != 0", "b*(p - 1) ≠ 0 (A and B are distinct)",
...       "b*(p - 1) ≠ 0"], [], {"b": b, "p": p})
(['p - 1 ≠ 0 (A and B are distinct)'], ['b**2*(p**2 + 1) ≠ 0 (sign from the domains)'])
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from functools import lru_cache

import sympy as sp

__all__ = ["kernel_worded", "parse_condition", "tidy"]

_COND = re.compile(r"^(?P<e>.+?) (?P<rel>≠|!=|≥|>=|>) 0(?P<rest>(?: \(.*\))?)$", re.S)
_MAX_CHARS = 300  # longer conditions are kept as they are (factoring would cost more)


def _factored(e: sp.Expr, rel: str) -> tuple[sp.Expr | None, bool]:
    """``(e without its factors of known sign, whether any was dropped)``; None: every
    factor has a known sign and the condition holds (≠ 0 of non-zero factors, or ≥/>
    of positive ones)."""
    if e.is_positive or (rel == "≠" and e.is_negative):
        return None, True
    if rel == "≥" and e.is_polynomial():
        from ..geometry.roots import nonnegative

        if nonnegative(sp.expand(e)):  # ≥ 0 for every value (a sum of squares, ...)
            return None, True
    try:
        num, den = sp.fraction(sp.together(e)) if e.is_Mul or e.is_Pow else (e, 1)
        c, factors = sp.factor_list(num)
        if den != 1:  # N/D: D's factors of known sign go; for ≠ 0 the others stay
            cd, fd = sp.factor_list(den)
            if rel != "≠" and (cd < 0 or not all(f.is_positive for f, _ in fd)):
                return e, False
            c = c / cd
            factors = [*factors, *((f, -m) for f, m in fd)]
    except (sp.PolynomialError, NotImplementedError, ValueError, TypeError):
        return e, False
    kept, dropped = [], False
    for f, m in factors:
        pos, neg = f.is_positive, f.is_negative
        if pos or (rel == "≠" and neg):
            dropped = True
            continue
        if rel == "≠":  # f**m ≠ 0 iff f ≠ 0, and a divisor must not vanish either
            dropped = dropped or m != 1
            kept.append(f)
            continue
        kept.append(f**m)
    if not kept:
        return (None, True) if (rel == "≠" and c != 0) or c > 0 else (e, False)
    if rel != "≠" and c < 0:
        return e, False  # a negative constant flips the sign: keep it as written
    return sp.Mul(*kept), dropped


@lru_cache(maxsize=8192)
def _one(t: str, symbols: tuple) -> tuple[str, str, str, str]:
    """``(bucket, expression text, relation, words)`` of one condition text; bucket is
    ``"implied"`` (every factor's sign is known), ``"extra"`` or ``"as is"``."""
    m = _COND.match(t.replace("!=", "≠").replace(">=", "≥"))
    if m is None:
        return "as is", t, "", ""
    rel = m["rel"]
    text, words = m["e"], m["rest"].strip()[1:-1] if m["rest"] else ""
    if len(text) <= _MAX_CHARS:
        try:
            e = sp.sympify(text, locals=dict(symbols))
            f, dropped = _factored(e, rel)
        except (sp.SympifyError, TypeError, ValueError, SyntaxError):
            return "extra", text, rel, words
        if f is None:
            why = f"{words}: sign from the domains" if words else "sign from the domains"
            return "implied", f"{text} {rel} 0 ({why})", rel, words
        if dropped:
            text = sp.sstr(f)
    return "extra", text, rel, words


def _words_of(texts: Iterable[str], key: tuple) -> dict[tuple[str, str], list[str]]:
    """Canonical key -> the first words of each worded condition among ``texts``."""
    out: dict[tuple[str, str], list[str]] = {}
    for t in texts:
        m = _COND.match(t.replace("!=", "≠").replace(">=", "≥"))
        if m is None or not m["rest"]:
            continue
        words = m["rest"].strip()[1:].split(")")[0]
        if words and "sign from" not in words:
            out.setdefault((_canonical(m["e"], m["rel"], key), m["rel"]), []).append(words)
    return out


@lru_cache(maxsize=8192)
def _canonical(text: str, rel: str, symbols: tuple) -> str:
    """One key for the same condition written two ways (expanded or not, times a
    constant, with the opposite sign for ``≠``): conditions on it are merged."""
    if not rel or len(text) > _MAX_CHARS:
        return text
    try:
        e = sp.expand(sp.sympify(text, locals=dict(symbols)))
        _, e = e.as_content_primitive()
    except (sp.SympifyError, TypeError, ValueError, SyntaxError, AttributeError):
        return text
    if rel == "≠" and e.could_extract_minus_sign():
        e = -e
    return sp.srepr(e)


def tidy(
    extra: Iterable[str], implied: Iterable[str], symbols: Mapping[str, sp.Symbol]
) -> tuple[list[str], list[str]]:
    """``(extra, implied)`` tidied (see the module); texts that are not ``EXPR ≠ 0``,
    ``≥ 0`` or ``> 0`` are kept as they are."""
    implied = list(dict.fromkeys(t.replace(" != 0", " ≠ 0") for t in implied))
    key = tuple(sorted(symbols.items()))
    groups: dict[tuple[str, str], list[str]] = {}
    shown: dict[tuple[str, str], str] = {}  # canonical key -> the first text written
    for t in extra:
        bucket, text, rel, words = _one(t, key)
        if bucket == "implied":
            implied.append(text)
            continue
        k = (_canonical(text, rel, key), rel)
        text = shown.setdefault(k, text)
        ws = groups.setdefault((text, rel), [])
        if words and words not in ws:
            ws.append(words)
    said = _words_of(implied, key)
    out = []
    for (text, rel), ws in groups.items():
        if rel and not ws:  # the same expression worded elsewhere (an operation's own)
            ws = said.get((_canonical(text, rel, key), rel), [])
        if not rel:
            out.append(text)
            continue
        out.append(f"{text} {rel} 0" + (f" ({'; '.join(ws)})" if ws else ""))
    return out, list(dict.fromkeys(implied))


def parse_condition(t: str, symbols: Mapping[str, sp.Symbol]) -> tuple[sp.Expr, str] | None:
    """``(expression, relation ≠ ≥ >)`` of a condition text ``EXPR REL 0 (words)``; None:
    not of that form, or too long to read again."""
    m = _COND.match(t.replace("!=", "≠").replace(">=", "≥"))
    if m is None or len(m["e"]) > _MAX_CHARS:
        return None
    try:
        return sp.sympify(m["e"], locals=dict(symbols)), m["rel"]
    except (sp.SympifyError, TypeError, ValueError, SyntaxError):
        return None


def _line_words(name: str, statements: Mapping[str, object]) -> str:
    """``AB`` for a line made by ``line_through A B`` (as GCLC names lines), else its name."""
    st = statements.get(name)
    if getattr(st, "op", "") == "line_through":
        a, b = st.inputs  # type: ignore[attr-defined]
        return f"{a}{b}" if len(a) == len(b) == 1 else f"{name} ({a} {b})"
    return name


def kernel_worded(
    texts: Iterable[str], op: str, inputs: tuple[str, ...], statements: Mapping[str, object]
) -> list[str]:
    """The kernel's conditions ``EXPR ≠ 0`` of one step with what they say: each new
    denominator of ``meet`` is the cross product of the two directions, of ``foot``,
    ``reflect``, ``signed_length`` and a line's intersection with a circle the squared
    direction, of ``circumcircle`` twice the signed area of the triangle."""
    names = [_line_words(n, statements) for n in inputs]
    words = {
        "meet": lambda: f"the lines {names[0]} and {names[1]} are not parallel",
        "foot": lambda: f"the line {names[1]} has a direction",
        "reflect": lambda: f"the line {names[1]} has a direction",
        "signed_length": lambda: f"the line {names[2]} has a direction",
        "intersect_line_circle": lambda: f"the line {names[0]} has a direction",
        "circumcircle": lambda: f"{', '.join(inputs)} are not collinear",
    }.get(op)
    if words is None:
        return list(texts)
    say = words()
    return [t if t.endswith(")") or not t.endswith("≠ 0") else f"{t} ({say})" for t in texts]
