"""A construction program written back in the language (:meth:`Program.to_text`)."""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

import sympy as sp

__all__ = ["format_program"]


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _expr(v: sp.Expr) -> str:
    return sp.sstr(v)


def _term(t: Any) -> str:
    if hasattr(t, "name"):  # a Ref
        return str(t.name)
    if hasattr(t, "x"):  # a PointValue
        return f"point({_expr(t.x)}, {_expr(t.y)})"
    return _expr(t.expr)


def format_program(p: Any, value_claims: Collection[str]) -> str:
    """A :class:`~graspcompass.construction.program.Program` written in the language again
    (``parse(format_program(p)) == p``); ``value_claims`` are the claim kinds written
    ``claim KIND A B ... == VALUE``."""
    out: list[str] = []
    for q in p.params:
        dom = {"positive": "> 0", "nonnegative": ">= 0"}.get(q.domain, q.domain)
        out.append(f"param {q.name} {dom}")
    out += [f"hypothesis {h}" for h in p.hypotheses]
    out += [f"hypothesis {h.text}" for h in getattr(p, "inequalities", ())]
    out += [f"let {n} = {_expr(v)}" for n, v in p.lets]
    for s in p.steps:
        parts = [s.name, "=", s.op, *s.inputs]
        if s.values:
            parts.append("(" + ", ".join(_expr(v) for v in s.values) + ")")
        if s.role:
            parts += ["role", s.role, *map(str, s.n)]
        parts += ["key"] * s.key + ["optional"] * s.optional
        if s.ref:
            parts += ["ref", _quote(s.ref)]
        parts.append(_quote(s.caption))
        out.append(" ".join(parts))
    for c in p.claims:
        if c.kind in value_claims:
            line = (
                f"claim {c.kind} "
                + " ".join(_term(t) for t in c.terms[:-1])
                + " == "
                + _term(c.terms[-1])
            )
        elif c.kind in ("equal", "sign"):
            body = f"{_term(c.terms[0])} {c.relation} {_term(c.terms[1])}"
            line = f"claim {'sign ' * (c.kind == 'sign')}{body}"
        else:
            line = f"claim {c.kind} " + " ".join(_term(t) for t in c.terms)
        out.append(
            line + "".join(f" under {h}" if i == 0 else f" {h}" for i, h in enumerate(c.under))
        )
    return "\n".join(out) + "\n"
