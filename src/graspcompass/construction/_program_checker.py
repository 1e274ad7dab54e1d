"""The checker shared by the parser and the builder of construction programs.

Names, kinds and values of a program being made, refused with one wording on both
paths.  Private to :mod:`graspcompass.construction.program` (the builder) and
:mod:`graspcompass.construction.language` (the parser).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Mapping
from typing import Any

import sympy as sp

from ..boundary.errors import InputError
from ..boundary.expr import Condition, ExpressionError, parse_with_conditions, tree_conditions
from ..boundary.inputs import exact_denominators
from ._hypotheses import RELATIONS, Inequality
from ._program_data import (
    _CLAIM_KINDS,
    _ENVELOPE,
    _KEYWORDS,
    _NAME,
    _RELATIONS,
    _VALUE_CLAIMS,
    DOMAINS,
    HYPOTHESES,
    Claim,
    Param,
    PointValue,
    Program,
    Ref,
    Statement,
    Term,
    Value,
    _makes,
    _Problem,
)
from .operations import OPERATIONS, ROLES


class _Checker:
    """Names, kinds and values of a program being made; refuses with :class:`_Problem`."""

    def __init__(self) -> None:
        self.params: list[Param] = []
        self.hypotheses: list[str] = []
        self.inequalities: list[Inequality] = []
        self.lets: list[tuple[str, sp.Expr]] = []
        self.steps: list[Statement] = []
        self.claims: list[Claim] = []
        self.symbols: dict[str, sp.Expr] = {}
        self.where: dict[str, int] = {}  # name -> line it was made on
        self.kinds: dict[str, str] = {}
        self.let_conditions: dict[str, tuple[Condition, ...]] = {}
        self.pending: list[Condition] = []  # conditions of the values read for a statement

    def _new_name(self, name: str, line: int, slot: Any = "name") -> None:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise _Problem(
                f"bad name {name!r}: a name is a letter or _ followed by letters, "
                "digits, _ or single hyphens",
                slot,
            )
        if name in _KEYWORDS or name in OPERATIONS:
            raise _Problem(f"{name!r} is a reserved word and cannot name an object", slot)
        if name in self.where:
            raise _Problem(
                f"duplicate name {name!r} (first defined on line {self.where[name]})", slot
            )
        self.where[name] = line

    def _pending(self) -> tuple[Condition, ...]:
        out, self.pending = tuple(dict.fromkeys(self.pending)), []
        return out

    def value(self, text: Any, slot: Any, extra: Mapping[str, sp.Expr] | None = None) -> sp.Expr:
        if isinstance(text, sp.Expr):
            unknown = text.free_symbols - set(self.symbols.values()) - set((extra or {}).values())
            if unknown:
                raise _Problem(
                    f"unknown name {sorted(map(str, unknown))[0]!r} in a value: "
                    "declare it with param",
                    slot,
                )
            if text.has(sp.I, sp.zoo, sp.nan, sp.oo, -sp.oo):
                raise _Problem(f"bad value {text}: not a finite real number", slot)
            try:  # a number divided by a zero in disguise, as the parser refuses it
                exact_denominators(text, "value")
            except InputError as exc:
                raise _Problem(f"bad value: {exc}", slot) from None
            self.pending += tree_conditions(text)
            return text
        if isinstance(text, bool) or not isinstance(text, (str, int)):
            raise _Problem(
                f"bad value {text!r}: give text (safe expression syntax), an int or "
                "a sympy expression",
                slot,
            )
        if isinstance(text, int):
            return sp.Integer(text)
        try:
            value, conds = parse_with_conditions(
                text, symbols={**self.symbols, **(extra or {})}, inherited=self.let_conditions
            )
        except ExpressionError as exc:
            raise _Problem(f"bad value: {exc}", slot) from None
        self.pending += conds
        return value

    def param(self, name: str, domain: str, line: int) -> None:
        self._new_name(name, line)
        if domain not in DOMAINS:
            raise _Problem(
                f"unknown domain {domain!r}: use > 0, >= 0 or one of {', '.join(DOMAINS)}", "domain"
            )
        p = Param(name, domain, line)
        self.params.append(p)
        self.symbols[name] = p.symbol

    def hypothesis(self, name: str) -> None:
        if name not in HYPOTHESES:
            raise _Problem(
                f"unknown hypothesis {name!r}: known are {', '.join(HYPOTHESES)}", "name"
            )
        if name in self.hypotheses:
            raise _Problem(f"hypothesis {name!r} declared twice", "name")
        self.hypotheses.append(name)

    def let(self, name: str, text: Any, line: int) -> None:
        self._new_name(name, line)
        self.pending = []
        value = self.value(text, "value")
        self.let_conditions[name] = self._pending()
        self.lets.append((name, value))
        self.symbols[name] = value

    def _input(self, name: Any, kind: str | None, op: str, i: int) -> str:
        if not isinstance(name, str) or name not in self.kinds:
            known = [n for n in self.kinds if n]
            near = difflib.get_close_matches(str(name), known, 1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            what = (
                "a parameter or a let value, not an object"
                if name in self.where
                else "no earlier step makes it"
            )
            raise _Problem(
                f"unknown name {name!r} as input {i + 1} of {op}: {what}{hint}", ("input", i)
            )
        have = self.kinds[name]
        if kind is not None and have != kind:
            raise _Problem(
                f"wrong kind of input: {op} takes a{'n' * (kind[0] in 'aeiou')} "
                f"{kind} as input {i + 1}, got the {have} {name!r} (line "
                f"{self.where[name]})",
                ("input", i),
            )
        return name

    def step(
        self,
        name: str,
        op: str,
        inputs: Iterable[Any],
        values: Iterable[Any],
        caption: str | None,
        ref: str,
        role: str,
        n: Iterable[int],
        key: bool,
        optional: bool,
        line: int,
    ) -> Statement:
        inputs, values, n = tuple(inputs), tuple(values), tuple(n)
        if op != _ENVELOPE and op not in OPERATIONS:
            near = difflib.get_close_matches(str(op), [*OPERATIONS, _ENVELOPE], 1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise _Problem(f"unknown operation {op!r}{hint}", "op")
        if op == _ENVELOPE:
            if not inputs:
                raise _Problem("envelope needs the circles (and break points) it bounds", "op")
            for i, a in enumerate(inputs):
                self._input(a, None, op, i)
            if values:
                raise _Problem("envelope takes no values", ("value", 0))
        else:
            o = OPERATIONS[op]
            if len(inputs) != len(o.inputs):
                raise _Problem(
                    f"{op} takes {len(o.inputs)} input(s) ({', '.join(o.inputs)}), "
                    f"got {len(inputs)}",
                    ("input", min(len(inputs), len(o.inputs))),
                )
            for i, (a, k) in enumerate(zip(inputs, o.inputs)):
                self._input(a, k, op, i)
            if len(values) != len(o.params):
                raise _Problem(
                    f"{op} takes {len(o.params)} value(s) "
                    f"({', '.join(o.params) or 'none'}), got {len(values)}",
                    "values",
                )
            self.pending = []
            values = tuple(self.value(v, ("value", i)) for i, v in enumerate(values))
            for i, (v, k) in enumerate(zip(values, o.params)):
                if k == "branch" and v not in (0, 1):
                    raise _Problem(f"bad value: a branch is 0 or 1, got {v}", ("value", i))
        if role not in ROLES:
            raise _Problem(
                f"unknown role {role!r}: use one of {', '.join(r for r in ROLES if r)}", "role"
            )
        for text, slot in ((caption, "caption"), (ref, "ref")):
            if text is not None and (not isinstance(text, str) or any(c in text for c in "\n\r\0")):
                raise _Problem(f"bad {slot}: one line of text", slot)
        self._new_name(name, line)
        if caption is None:
            caption = (
                OPERATIONS[op].caption_for(name, inputs, values)
                if op != _ENVELOPE
                else f"{name}: the outer envelope"
            )
        s = Statement(
            name, op, inputs, values, caption, ref, role, n, key, optional, line, self._pending()
        )
        self.steps.append(s)
        self.kinds[name] = _makes(op)
        return s

    def term(self, term: Any, slot: Any) -> Term:
        if isinstance(term, (Ref, Value, PointValue)):
            if isinstance(term, Ref) and term.name not in self.kinds:
                raise _Problem(f"unknown name {term.name!r} in the claim", slot)
            return term
        if isinstance(term, str) and term in self.kinds:
            return Ref(term)
        lengths = {
            k: sp.Symbol(k, real=True)
            for k, v in self.kinds.items()
            if v == "number" and "-" not in k
        }
        if isinstance(term, tuple) and len(term) == 2:
            return PointValue(*(self.value(t, slot, lengths) for t in term))
        return Value(self.value(term, slot, lengths))

    def claim(
        self, kind: str, terms: Iterable[Any], relation: str, under: Iterable[str], line: int
    ) -> Claim:
        terms, under = tuple(terms), tuple(under)
        for i, h in enumerate(under):
            if h not in self.hypotheses:
                raise _Problem(
                    f"unknown hypothesis {h!r} (declare it: hypothesis {h})", ("under", i)
                )
        if kind in _VALUE_CLAIMS:
            c = self._value_claim(kind, terms, under, line)
        elif kind in _CLAIM_KINDS or kind == "on":
            need, least = _CLAIM_KINDS.get(kind, (None, 2))
            many = kind in ("collinear", "concurrent", "concyclic")
            if len(terms) < least or (not many and len(terms) != least):
                raise _Problem(
                    f"claim {kind} takes {'at least ' * many}{least} names, got {len(terms)}",
                    ("term", len(terms)),
                )
            for i, t in enumerate(terms):
                self._input(
                    t, need if kind != "on" else ("point" if i == 0 else None), f"claim {kind}", i
                )
            if kind == "tangent" and (
                sorted(self.kinds[t] for t in terms)
                not in (["circle", "line"], ["circle", "circle"])
            ):
                raise _Problem(
                    "claim tangent takes a line and a circle or two circles, got "
                    f"the {self.kinds[terms[0]]} {terms[0]!r} and the "
                    f"{self.kinds[terms[1]]} {terms[1]!r}",
                    ("term", 0),
                )
            if kind == "on" and self.kinds[terms[1]] not in ("line", "circle"):
                raise _Problem(
                    f"wrong kind of input: claim on takes a line or a circle as "
                    f"input 2, got the {self.kinds[terms[1]]} {terms[1]!r}",
                    ("term", 1),
                )
            c = Claim(kind, tuple(Ref(t) for t in terms), "", under, line)
        elif kind in ("equal", "sign"):
            if len(terms) != 2:
                raise _Problem(f"claim {kind} takes two sides, got {len(terms)}", ("term", 0))
            if relation not in _RELATIONS or (kind == "equal" and relation != "=="):
                raise _Problem(f"bad relation {relation!r}", "relation")
            self.pending = []
            ts = tuple(self.term(t, ("term", i)) for i, t in enumerate(terms))
            if kind == "sign" and not all(
                isinstance(t, Value) or (isinstance(t, Ref) and self.kinds[t.name] == "number")
                for t in ts
            ):
                raise _Problem("a sign claim compares numbers", ("term", 0))
            sides = [
                self.kinds[t.name]
                if isinstance(t, Ref)
                else "point"
                if isinstance(t, PointValue)
                else "number"
                for t in ts
            ]
            if kind == "equal" and sides[0] != sides[1]:
                raise _Problem(
                    f"wrong kinds: cannot compare a {sides[0]} with a {sides[1]}", ("term", 1)
                )
            c = Claim(kind, ts, relation, under, line, self._pending())
        else:
            raise _Problem(
                f"unknown claim {kind!r}: use ==, sign, on, {', '.join(_CLAIM_KINDS)}", "kind"
            )
        self.claims.append(c)
        return c

    def _value_claim(self, kind: str, terms: tuple, under: tuple, line: int) -> Claim:
        """``ratio A B C D == k`` (|AB| = k·|CD|), ``angles A B C [D E F ...] == a`` (the
        directed angles ABC + DEF + ... ≡ a mod π)."""
        *names, value = terms
        group = _VALUE_CLAIMS[kind]
        if not names or len(names) % group or (kind == "ratio" and len(names) != 4):
            what = (
                "4 names" if kind == "ratio" else "names in groups of three (A B C: the angle at B)"
            )
            raise _Problem(
                f"claim {kind} takes {what} before ==, got {len(names)}", ("term", len(names))
            )
        for i, t in enumerate(names):
            self._input(t, "point", f"claim {kind}", i)
        self.pending = []
        v = self.term(value, ("term", len(names)))
        if not isinstance(v, Value):
            raise _Problem(f"claim {kind} compares with a value after ==", ("term", len(names)))
        return Claim(kind, (*(Ref(t) for t in names), v), "==", under, line, self._pending())

    def program(self, file: str) -> Program:
        return Program(
            tuple(self.params),
            tuple(self.hypotheses),
            tuple(self.lets),
            tuple(self.steps),
            tuple(self.claims),
            file,
            tuple(self.inequalities),
        )


def read_inequality(chk: Any, name: str, text: str, line: int) -> Inequality:
    """Read ``LEFT REL RIGHT`` of ``hypothesis NAME: ...`` with the program's checker
    ``chk`` (its names and values) and record it; refuses with the checker's problem."""
    if name in HYPOTHESES or name in {h.name for h in chk.inequalities} or name in chk.hypotheses:
        raise _Problem(f"hypothesis {name!r} declared twice or a reserved name", "name")
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise _Problem(
            f"bad hypothesis name {name!r}: a letter or _ then letters, digits, _", "name"
        )
    depth, at = 0, None
    for i, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth == 0 and at is None:
            for sym in ("==", *RELATIONS):
                if text.startswith(sym, i):
                    at = (i, sym)
                    break
    if at is None or at[1] == "==":
        raise _Problem(
            "write hypothesis NAME: VALUE REL VALUE with REL one of " + " ".join(RELATIONS), "value"
        )
    i, rel = at
    left, right = text[:i].strip(), text[i + len(rel) :].strip()
    if not left or not right:
        raise _Problem("a hypothesis compares two values", "value")
    chk.pending = []
    lhs, rhs = chk.value(left, "value"), chk.value(right, "value")
    chk.pending = []
    if not (lhs - rhs).free_symbols:
        raise _Problem(
            "a hypothesis is an inequality on the parameters (this one has none)", "value"
        )
    h = Inequality(name, rel, lhs, rhs, line)
    chk.inequalities.append(h)
    return h
