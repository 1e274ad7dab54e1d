"""Markdown of the proof reports: text escaped, formulas as MathJax math (issue 23).

The reports of ``graspcompass verify --markdown`` and ``graspcompass check --markdown``
carry text of the catalogue and of users' files (statements, hypotheses, exact values
such as ``5*pi/12``, conditions such as ``a1**2 - 2*a1*b1 != 0``).  As Markdown, ``*``
and ``_`` would turn into italics and bold, ``|`` would split a table cell, ``$`` would
open math and ``<`` raw HTML.  Here text is escaped character by character, and a
formula is read by the safe parser (:func:`graspcompass.expr.parse_exact`: nothing is
evaluated) and written as ``$…$`` math in LaTeX (sympy's printer), which MathJax
typesets; a long sum is cut into one ``$…$`` per term so that the line can break.  What
the parser does not read stays text, escaped.

Examples
--------
>>> print(md_text("a*b_c | <x> (1)"))
a\\*b\\_c \\| \\<x\\> (1)
>>> print(md_math("xi1 = 5*pi/12"))
$\\xi_{1} = \\frac{5 \\pi}{12}$
>>> md_math("sides 1, 2 not parallel")
'sides 1, 2 not parallel'
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from typing import Any

import sympy as sp

__all__ = ["md_counterexample", "md_items", "md_math", "md_text"]

_SPECIAL = set("\\`*_[]<>|$~^")
_FUNCTIONS = {"sin", "cos", "tan", "sqrt", "asin", "acos", "atan", "atan2", "pi", "deg"}
_RELATIONS = (
    ("!=", r"\ne"),
    ("<=", r"\le"),
    (">=", r"\ge"),
    ("==", "="),
    ("<", "<"),
    (">", ">"),
    ("=", "="),
)
#: Formulas longer than this (characters of source) are not typeset (a plain code span).
MAX_FORMULA = 2000
#: A sum whose LaTeX is longer than this is cut into one piece of math per term.
BREAK_AT = 90


def md_text(text: Any) -> str:
    """``text`` with every Markdown special character escaped (a backslash before it),
    line breaks as spaces: it reads as written, inside a paragraph or a table cell."""
    s = " ".join(str(text).split())
    out = "".join("\\" + ch if ch in _SPECIAL else ch for ch in s)
    # what would start a list, a heading, a quote or a definition at the start of a line
    return "\\" + out if out[:1] in ("-", "+", "#", ":", "=") or re.match(r"\d+[.)]", out) else out


def _side(text: str) -> sp.Expr | None:
    from ..boundary.expr import parse_exact

    names = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text)) - _FUNCTIONS
    if any(not re.fullmatch(r"[A-Za-z]+[0-9]*(_[A-Za-z0-9]+)?", n) for n in names):
        return None
    try:
        return parse_exact(text, symbols={n: sp.Symbol(n) for n in names})
    except (ValueError, TypeError, ArithmeticError, RecursionError):
        return None


def _terms(text: str) -> list[str]:
    """``text`` cut at its top-level `` + `` and `` - `` (outside parentheses), signs kept."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += (ch == "(") - (ch == ")")
        if depth == 0 and i > start and text[i - 1 : i + 2] in (" + ", " - "):
            out.append(text[start : i - 1])
            start = i
    out.append(text[start:])
    return [t.strip() for t in out if t.strip()]


def _side_pieces(text: str) -> list[str] | None:
    """The LaTeX of one side, in pieces that may break between them, or None if unread.
    A long sum is read term by term (the parser reads at most 200 characters at once)."""
    e = _side(text) if len(text) <= 200 else None
    if e is not None:
        return _latex_pieces(e)
    terms = _terms(text)
    if len(terms) < 2:
        return None
    pieces = []
    for k, t in enumerate(terms):
        sign = ""
        if t[:2] in ("+ ", "- "):
            sign, t = t[0], t[2:]
        e = _side(t) if len(t) <= 200 else None
        if e is None:
            return None
        tex = sp.latex(e)
        pieces.append(tex if k == 0 and not sign else f"{sign or '+'} {tex}")
    return pieces


def _latex_pieces(e: sp.Expr) -> list[str]:
    whole = sp.latex(e)
    if not (isinstance(e, sp.Add) and len(whole) > BREAK_AT):
        return [whole]
    out = []
    for k, term in enumerate(e.as_ordered_terms()):
        t = sp.latex(term)
        out.append(t if k == 0 else ("- " + t[1:].lstrip() if t.startswith("-") else "+ " + t))
    return out


def md_math(text: Any) -> str:
    """A formula ``lhs REL rhs`` (or one expression) as MathJax math, else escaped text.

    The sides are read by :func:`graspcompass.expr.parse_exact` (whitelisted, never
    evaluated as Python); ``!=``, ``<=``, ``>=`` print as ≠, ≤, ≥.
    """
    s = " ".join(str(text).split())
    if not s or len(s) > MAX_FORMULA or "|" in s or "$" in s:
        return md_text(s)
    for op, tex in _RELATIONS:
        if f" {op} " in s:
            left, right = s.split(f" {op} ", 1)
            a, b = _side_pieces(left), _side_pieces(right)
            if a is None or b is None:
                return md_text(s)
            pieces = [*a[:-1], f"{a[-1]} {tex} {b[0]}", *b[1:]]
            return " ".join(f"${p}$" for p in pieces)
    e = _side(s) if len(s) <= 200 else None
    if e is None or (not e.free_symbols and not any(ch.isdigit() for ch in s)):
        return md_text(s)
    return " ".join(f"${p}$" for p in _latex_pieces(e))


def md_items(items: Iterable[Any], prefix: str = "") -> list[str]:
    """Each item as math where it is a formula, else as escaped text."""
    return [prefix + md_math(x) for x in items]


def md_counterexample(values: Mapping[str, Any] | None) -> str:
    """``{"xi1": "5*pi/12", ...}`` as ``$\\xi_{1} = \\frac{5 \\pi}{12}$, …``."""
    return ", ".join(md_math(f"{k} = {v}") for k, v in (values or {}).items())
