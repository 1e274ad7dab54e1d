"""The construction language: a plain-text file of named ruler-and-compass steps.

One statement a line; ``#`` starts a comment.  The reference is ``docs/language.md``;
in short::

    param x1 > 0                      # parameters with their domains
    param phi1 angle                  # 0 < phi1 <= pi
    param mu1 friction                # mu1 > 0 (or: param xi1 half_angle)
    hypothesis condition1             # condition (1) of the paper, by name
    let S1 = -(x1 + x2)/2 + y*tan(phi1)   # a named value (safe expression syntax)
    P1 = point (x1, y)  role contact 1  ref "§2.2.1"  "Contact point P1"
    X1 = meet side1 x-axis  role X 1  "Extend the side to the x-axis: X1"
    B12 = second_intersection circle1 circle2 O  optional
    claim V1 == point(S1, C1)
    claim collinear O_M X1 X2
    claim sign x1 + x2 > 0 under condition1

A step is ``NAME = OPERATION INPUT... [(VALUE, ...)] [CLAUSE...]``: the
operation is a key of :data:`~graspcompass.construction.operations.OPERATIONS`
(or ``envelope``), the inputs are names of earlier objects of the kinds the
operation takes, the values (in one pair of parentheses) are read by the safe
parser :func:`graspcompass.expr.parse_exact` with the declared parameters and
``let`` names as symbols (never ``eval``).  The clauses are a caption (a
double-quoted string), ``ref "…"`` (the paper's section or equation), ``role
ROLE N...`` (:data:`~graspcompass.construction.operations.ROLES`), ``key`` (an
animation pauses there) and ``optional`` (a degenerate step is left out, as the
break points of tangent circles are).

:func:`parse` returns a :class:`Program` (plain data); :func:`replay` runs it
on a grasp; :class:`ConstructionBuilder` makes the same :class:`Program` from
Python.  Errors are :class:`ConstructionSyntaxError` (``FILE:LINE:COL: what``)
and, at replay, :class:`DegenerateStepError` (the step, its line and objects).

Examples
--------
>>> prog = parse('''
... A = point (0, 0)
... B = point (2, 0)
... M = midpoint A B  "the midpoint"
... claim M == point(1, 0)
... ''')
>>> [s.name for s in prog.steps], prog.claims[0].kind
(['A', 'B', 'M'], 'equal')
>>> replay(prog)["M"]
Point(1, 0)
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources
from typing import Any

import mpmath
import sympy as sp

from .. import symbols as _model
from .._floatpath import mpf
from ..errors import InputError
from ..expr import ExpressionError, parse_exact
from ..geometry import GeometryError
from ..geometry.exact import canon, has_float
from ..geometry.trig import sincos
from .operations import OPERATIONS, ROLES
from .protocol import Construction, Step, StepSpec, run_step

__all__ = [
    "DOMAINS",
    "HYPOTHESES",
    "MAX_LINES",
    "MAX_LINE_LENGTH",
    "Claim",
    "ConstructionBuilder",
    "ConstructionSyntaxError",
    "DegenerateStepError",
    "Param",
    "PointValue",
    "Program",
    "Ref",
    "Statement",
    "Value",
    "paper_program",
    "paper_text",
    "parse",
    "replay",
]

#: Longest line read (characters).
MAX_LINE_LENGTH = 1000
#: Most lines in one file.
MAX_LINES = 10_000
#: Domain words of ``param NAME DOMAIN`` -> what they mean.
DOMAINS: Mapping[str, str] = {
    "positive": "> 0", "nonnegative": ">= 0", "angle": "0 < value <= pi (a normal angle φ)",
    "friction": "a friction coefficient μ > 0", "half_angle": "0 < ξ < pi/2 (tan ξ = μ)",
    "real": "any real number",
}
#: Hypotheses a file may name (``hypothesis NAME``, ``claim ... under NAME``).
HYPOTHESES: Mapping[str, str] = {
    "condition1": "condition (1), §2.2.2: each friction cone contains the other contact "
                  "(−π/2 < φi − ξi < π/2 < φi + ξi < 3π/2)",
}
_ENVELOPE = "envelope"
_FLOAT_DIGITS = 40  # working digits of a float grasp's values, rounded once to doubles
_RELATIONS = ("==", "!=", ">=", "<=", ">", "<")
_CLAIM_KINDS = {"collinear": ("point", 3), "concurrent": ("line", 3),
                "perpendicular": ("line", 2), "parallel": ("line", 2)}
_KEYWORDS = frozenset({"param", "hypothesis", "let", "claim", "ref", "role", "key", "optional",
                       "under", "sign", "on", *_CLAIM_KINDS, "point", "pi", "deg"})
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:-[A-Za-z0-9_]+)*")
_TOKEN = re.compile(r"""\s*(?:(?P<string>"(?:[^"\\\n]|\\.)*")|(?P<word>[A-Za-z_][A-Za-z0-9_]*
    (?:-[A-Za-z0-9_]+)*)|(?P<int>\d+)|(?P<rel>==|!=|>=|<=|>|<|=)|(?P<open>\())""", re.X)


# -- errors ---------------------------------------------------------------------------
class ConstructionSyntaxError(InputError):
    """A construction file that cannot be read: ``FILE:LINE:COL: what is wrong``.

    Examples
    --------
    >>> try:
    ...     parse("A = point (0, 0)\\nB = meet A A", file="ex.gc")
    ... except ConstructionSyntaxError as err:
    ...     print(err, (err.line, err.column))
    ex.gc:2:10: wrong kind of input: meet takes a line as input 1, got the point 'A' (line 1)
     (2, 10)
    """

    def __init__(self, what: str, file: str = "<text>", line: int = 0, column: int = 0) -> None:
        super().__init__(f"{file}:{line}:{column}: {what}")
        self.what, self.file, self.line, self.column = what, file, line, column


class DegenerateStepError(GeometryError):
    """A step that the kernel cannot make for these values (parallel lines, ...).

    The message names the file, the line, the step and its inputs; ``objects``
    are the input objects, ``step`` the step's name.
    """

    def __init__(self, message: str, step: str, line: int, *objects: object) -> None:
        super().__init__(message, *objects)
        self.step, self.line = step, line


class _Problem(Exception):
    """A refusal inside the checker; ``slot`` says which part of the statement is wrong."""

    def __init__(self, what: str, slot: Any = None) -> None:
        super().__init__(what)
        self.what, self.slot = what, slot


# -- the program as data ----------------------------------------------------------------
@dataclass(frozen=True)
class Param:
    """A declared parameter: ``param NAME DOMAIN`` (a key of :data:`DOMAINS`)."""

    name: str
    domain: str
    line: int = field(default=0, compare=False)

    @property
    def symbol(self) -> sp.Symbol:
        """The sympy symbol of the parameter (the model's own for x1, phi1, mu1, ...)."""
        return _symbol(self.name, self.domain)


@dataclass(frozen=True)
class Statement:
    """One step of a program: ``NAME = OP INPUTS (VALUES) CLAUSES``."""

    name: str
    op: str
    inputs: tuple[str, ...]
    values: tuple[sp.Expr, ...]
    caption: str
    ref: str = ""
    role: str = ""
    n: tuple[int, ...] = ()
    key: bool = False
    optional: bool = False
    line: int = field(default=0, compare=False)


@dataclass(frozen=True)
class Ref:
    """A claim's term naming an object of the construction."""

    name: str


@dataclass(frozen=True)
class Value:
    """A claim's term: an exact expression in the parameters and the lengths."""

    expr: sp.Expr


@dataclass(frozen=True)
class PointValue:
    """A claim's term ``point(x, y)``."""

    x: sp.Expr
    y: sp.Expr


Term = Ref | Value | PointValue


@dataclass(frozen=True)
class Claim:
    """A claim to prove: ``kind`` is ``equal``, ``sign``, ``on``, ``collinear``,
    ``concurrent``, ``perpendicular`` or ``parallel``; ``relation`` is one of
    ``== != > >= < <=`` for ``equal`` and ``sign``; ``under`` names hypotheses."""

    kind: str
    terms: tuple[Term, ...]
    relation: str = ""
    under: tuple[str, ...] = ()
    line: int = field(default=0, compare=False)


@dataclass(frozen=True)
class Program:
    """A parsed construction file: parameters, hypotheses, named values, steps, claims."""

    params: tuple[Param, ...] = ()
    hypotheses: tuple[str, ...] = ()
    lets: tuple[tuple[str, sp.Expr], ...] = ()
    steps: tuple[Statement, ...] = ()
    claims: tuple[Claim, ...] = ()
    file: str = field(default="<text>", compare=False)

    @property
    def kinds(self) -> dict[str, str]:
        """Name -> kind of every object the steps make (``envelope`` for the envelope)."""
        return {s.name: _makes(s.op) for s in self.steps}

    def to_text(self) -> str:
        """The program written in the language again (``parse(p.to_text()) == p``)."""
        return _format(self)


def _makes(op: str) -> str:
    return _ENVELOPE if op == _ENVELOPE else OPERATIONS[op].makes


def _symbol(name: str, domain: str) -> sp.Symbol:
    model = getattr(_model, name, None) if name in _model.__all__ else None
    if isinstance(model, sp.Symbol):
        return model
    if domain in ("positive", "friction", "half_angle", "angle"):
        return sp.Symbol(name, positive=True)
    return sp.Symbol(name, nonnegative=True) if domain == "nonnegative" else sp.Symbol(
        name, real=True)


# -- the checker shared by the parser and the builder -----------------------------------
class _Checker:
    """Names, kinds and values of a program being made; refuses with :class:`_Problem`."""

    def __init__(self) -> None:
        self.params: list[Param] = []
        self.hypotheses: list[str] = []
        self.lets: list[tuple[str, sp.Expr]] = []
        self.steps: list[Statement] = []
        self.claims: list[Claim] = []
        self.symbols: dict[str, sp.Expr] = {}
        self.where: dict[str, int] = {}  # name -> line it was made on
        self.kinds: dict[str, str] = {}

    def _new_name(self, name: str, line: int, slot: Any = "name") -> None:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise _Problem(f"bad name {name!r}: a name is a letter or _ followed by letters, "
                           "digits, _ or single hyphens", slot)
        if name in _KEYWORDS or name in OPERATIONS:
            raise _Problem(f"{name!r} is a reserved word and cannot name an object", slot)
        if name in self.where:
            raise _Problem(f"duplicate name {name!r} (first defined on line "
                           f"{self.where[name]})", slot)
        self.where[name] = line

    def value(self, text: Any, slot: Any, extra: Mapping[str, sp.Expr] | None = None
              ) -> sp.Expr:
        if isinstance(text, sp.Expr):
            unknown = text.free_symbols - set(self.symbols.values()) - set((extra or {}).values())
            if unknown:
                raise _Problem(f"unknown name {sorted(map(str, unknown))[0]!r} in a value: "
                               "declare it with param", slot)
            return text
        if isinstance(text, bool) or not isinstance(text, (str, int)):
            raise _Problem(f"bad value {text!r}: give text (safe expression syntax), an int or "
                           "a sympy expression", slot)
        if isinstance(text, int):
            return sp.Integer(text)
        try:
            return parse_exact(text, symbols={**self.symbols, **(extra or {})})
        except ExpressionError as exc:
            raise _Problem(f"bad value: {exc}", slot) from None

    def param(self, name: str, domain: str, line: int) -> None:
        self._new_name(name, line)
        if domain not in DOMAINS:
            raise _Problem(f"unknown domain {domain!r}: use > 0, >= 0 or one of "
                           f"{', '.join(DOMAINS)}", "domain")
        p = Param(name, domain, line)
        self.params.append(p)
        self.symbols[name] = p.symbol

    def hypothesis(self, name: str) -> None:
        if name not in HYPOTHESES:
            raise _Problem(f"unknown hypothesis {name!r}: known are {', '.join(HYPOTHESES)}",
                           "name")
        if name in self.hypotheses:
            raise _Problem(f"hypothesis {name!r} declared twice", "name")
        self.hypotheses.append(name)

    def let(self, name: str, text: Any, line: int) -> None:
        self._new_name(name, line)
        value = self.value(text, "value")
        self.lets.append((name, value))
        self.symbols[name] = value

    def _input(self, name: Any, kind: str | None, op: str, i: int) -> str:
        if not isinstance(name, str) or name not in self.kinds:
            known = [n for n in self.kinds if n]
            near = difflib.get_close_matches(str(name), known, 1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            what = ("a parameter or a let value, not an object" if name in self.where
                    else "no earlier step makes it")
            raise _Problem(f"unknown name {name!r} as input {i + 1} of {op}: {what}{hint}",
                           ("input", i))
        have = self.kinds[name]
        if kind is not None and have != kind:
            raise _Problem(f"wrong kind of input: {op} takes a{'n' * (kind[0] in 'aeiou')} "
                           f"{kind} as input {i + 1}, got the {have} {name!r} (line "
                           f"{self.where[name]})", ("input", i))
        return name

    def step(self, name: str, op: str, inputs: Iterable[Any], values: Iterable[Any],
             caption: str | None, ref: str, role: str, n: Iterable[int], key: bool,
             optional: bool, line: int) -> Statement:
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
                raise _Problem(f"{op} takes {len(o.inputs)} input(s) ({', '.join(o.inputs)}), "
                               f"got {len(inputs)}", ("input", min(len(inputs),
                                                                   len(o.inputs))))
            for i, (a, k) in enumerate(zip(inputs, o.inputs)):
                self._input(a, k, op, i)
            if len(values) != len(o.params):
                raise _Problem(f"{op} takes {len(o.params)} value(s) "
                               f"({', '.join(o.params) or 'none'}), got {len(values)}",
                               "values")
            values = tuple(self.value(v, ("value", i)) for i, v in enumerate(values))
            for i, (v, k) in enumerate(zip(values, o.params)):
                if k == "branch" and v not in (0, 1):
                    raise _Problem(f"bad value: a branch is 0 or 1, got {v}", ("value", i))
        if role not in ROLES:
            raise _Problem(f"unknown role {role!r}: use one of {', '.join(r for r in ROLES if r)}",
                           "role")
        for text, slot in ((caption, "caption"), (ref, "ref")):
            if text is not None and (not isinstance(text, str) or any(
                    c in text for c in "\n\r\0")):
                raise _Problem(f"bad {slot}: one line of text", slot)
        self._new_name(name, line)
        if caption is None:
            caption = (OPERATIONS[op].caption_for(name, inputs, values) if op != _ENVELOPE
                       else f"{name}: the outer envelope")
        s = Statement(name, op, inputs, values, caption, ref, role, n, key, optional, line)
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
        lengths = {k: sp.Symbol(k, real=True) for k, v in self.kinds.items()
                   if v == "number" and "-" not in k}
        if isinstance(term, tuple) and len(term) == 2:
            return PointValue(*(self.value(t, slot, lengths) for t in term))
        return Value(self.value(term, slot, lengths))

    def claim(self, kind: str, terms: Iterable[Any], relation: str, under: Iterable[str],
              line: int) -> Claim:
        terms, under = tuple(terms), tuple(under)
        for i, h in enumerate(under):
            if h not in self.hypotheses:
                raise _Problem(f"unknown hypothesis {h!r} (declare it: hypothesis {h})",
                               ("under", i))
        if kind in _CLAIM_KINDS or kind == "on":
            need, least = _CLAIM_KINDS.get(kind, (None, 2))
            many = kind in ("collinear", "concurrent")
            if len(terms) < least or (not many and len(terms) != least):
                raise _Problem(f"claim {kind} takes {'at least ' * many}{least} names, got "
                               f"{len(terms)}", ("term", len(terms)))
            for i, t in enumerate(terms):
                self._input(t, need if kind != "on" else ("point" if i == 0 else None),
                            f"claim {kind}", i)
            if kind == "on" and self.kinds[terms[1]] not in ("line", "circle"):
                raise _Problem(f"wrong kind of input: claim on takes a line or a circle as "
                               f"input 2, got the {self.kinds[terms[1]]} {terms[1]!r}",
                               ("term", 1))
            c = Claim(kind, tuple(Ref(t) for t in terms), "", under, line)
        elif kind in ("equal", "sign"):
            if len(terms) != 2:
                raise _Problem(f"claim {kind} takes two sides, got {len(terms)}", ("term", 0))
            if relation not in _RELATIONS or (kind == "equal" and relation != "=="):
                raise _Problem(f"bad relation {relation!r}", "relation")
            ts = tuple(self.term(t, ("term", i)) for i, t in enumerate(terms))
            if kind == "sign" and not all(isinstance(t, Value) or (
                    isinstance(t, Ref) and self.kinds[t.name] == "number") for t in ts):
                raise _Problem("a sign claim compares numbers", ("term", 0))
            sides = [self.kinds[t.name] if isinstance(t, Ref) else
                     "point" if isinstance(t, PointValue) else "number" for t in ts]
            if kind == "equal" and sides[0] != sides[1]:
                raise _Problem(f"wrong kinds: cannot compare a {sides[0]} with a {sides[1]}",
                               ("term", 1))
            c = Claim(kind, ts, relation, under, line)
        else:
            raise _Problem(f"unknown claim {kind!r}: use ==, sign, on, "
                           f"{', '.join(_CLAIM_KINDS)}", "kind")
        self.claims.append(c)
        return c

    def program(self, file: str) -> Program:
        return Program(tuple(self.params), tuple(self.hypotheses), tuple(self.lets),
                       tuple(self.steps), tuple(self.claims), file)


# -- the parser ---------------------------------------------------------------------------
def _strip_comment(text: str) -> str:
    quoted = False
    i = 0
    while i < len(text):
        c = text[i]
        if c == "\\" and quoted:
            i += 2
            continue
        if c == '"':
            quoted = not quoted
        elif c == "#" and not quoted:
            return text[:i]
        i += 1
    return text


def _group_end(text: str, start: int) -> int:
    """Index after the parenthesis closing the one at ``start``, or -1."""
    depth = 0
    for i in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return i + 1
    return -1


def _split_items(text: str, offset: int) -> list[tuple[str, int]]:
    """Comma-separated items of ``(a, b)`` with their offsets (commas inside calls kept)."""
    items, depth, start = [], 0, 0
    for i, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if c == "," and depth == 0:
            items.append((text[start:i], offset + start))
            start = i + 1
    items.append((text[start:], offset + start))
    return items


class _Line:
    """The tokens of one line: (kind, text, column), values kept as raw text."""

    def __init__(self, text: str, err: Any) -> None:
        self.text, self.err, self.tokens = text, err, []
        pos = 0
        while pos < len(text):
            if text[pos:].strip() == "":
                break
            m = _TOKEN.match(text, pos)
            col = len(text[pos:]) - len(text[pos:].lstrip()) + pos + 1
            if m is None or m.lastgroup is None:
                if text[col - 1] == '"':
                    raise err("unterminated string", col)
                raise err(f"unexpected character {text[col - 1]!r}", col)
            if m.lastgroup == "open":
                end = _group_end(text, m.end() - 1)
                if end < 0:
                    raise err("unbalanced parenthesis: '(' is not closed", col)
                self.tokens.append(("values", text[m.end(): end - 1], col))
                pos = end
                continue
            if m.lastgroup == "string":
                raw = m.group("string")[1:-1]
                self.tokens.append(("string", re.sub(r"\\(.)", r"\1", raw), col))
            else:
                self.tokens.append((m.lastgroup, m.group(m.lastgroup), col))
            pos = m.end()


def parse(text: str, file: str = "<text>") -> Program:
    """Read a program in the construction language.

    Parameters
    ----------
    text : str
        The file's text (at most :data:`MAX_LINES` lines of :data:`MAX_LINE_LENGTH`).
    file : str
        The file's name, for messages.

    Returns
    -------
    Program
        Plain data: parameters, hypotheses, let values, steps and claims.

    Raises
    ------
    ConstructionSyntaxError
        ``FILE:LINE:COL: what`` for an unknown name or operation, inputs of the
        wrong kind, a duplicate name, a bad value or anything unreadable.

    Examples
    --------
    >>> p = parse("param a > 0\\nA = point (a, 0)\\nB = point (0, a)\\nl = line_through A B")
    >>> p.steps[2].op, p.steps[2].inputs, p.params[0].domain
    ('line_through', ('A', 'B'), 'positive')
    >>> parse("l = line_through A B", file="f.gc")
    Traceback (most recent call last):
    ...
    graspcompass.construction.language.ConstructionSyntaxError: f.gc:1:18: unknown name 'A' ...
    """
    if not isinstance(text, str):
        raise TypeError(f"expected the text of a construction file, got {type(text).__name__}")
    lines = text.split("\n")
    if len(lines) > MAX_LINES:
        raise ConstructionSyntaxError(f"more than {MAX_LINES} lines", file, MAX_LINES + 1, 1)
    chk = _Checker()
    for number, raw in enumerate(lines, 1):
        def err(what: str, col: int, number: int = number) -> ConstructionSyntaxError:
            return ConstructionSyntaxError(what, file, number, col)

        if len(raw) > MAX_LINE_LENGTH:
            raise err(f"the line is longer than {MAX_LINE_LENGTH} characters",
                      MAX_LINE_LENGTH + 1)
        body = _strip_comment(raw.rstrip("\r"))
        if not body.strip():
            continue
        _statement(body, chk, number, err)
    return chk.program(file)


def _statement(body: str, chk: _Checker, number: int, err: Any) -> None:
    head = body.split(None, 1)[0]
    col = len(body) - len(body.lstrip()) + 1
    if head == "claim":
        return _claim(body, chk, number, err)
    slots: dict[Any, int] = {"name": col}
    try:
        if head == "let":
            m = re.match(r"\s*let\s+(\S+)\s*=\s*(.*\S)\s*$", body)
            if m is None:
                raise _Problem("write let NAME = VALUE", "name")
            slots["name"], slots["value"] = m.start(1) + 1, m.start(2) + 1
            return chk.let(m.group(1), m.group(2), number)
        toks = _Line(body, err).tokens
        kind, first, col = toks[0]
        slots["name"] = toks[1][2] if len(toks) > 1 else col
        if kind == "word" and first == "param":
            if len(toks) < 3 or toks[1][0] != "word":
                raise _Problem("write param NAME > 0, >= 0 or a domain word", "name")
            if toks[2][0] == "rel":
                if len(toks) != 4 or toks[2][1] not in (">", ">=") or toks[3][1] != "0":
                    raise _Problem("a parameter's bound is > 0 or >= 0", "domain")
                domain = "positive" if toks[2][1] == ">" else "nonnegative"
            else:
                domain = toks[2][1]
                if len(toks) != 3:
                    raise _Problem("one domain per parameter", "extra")
            slots["domain"], slots["extra"] = toks[2][2], toks[-1][2]
            return chk.param(toks[1][1], domain, number)
        if kind == "word" and first == "hypothesis":
            if len(toks) != 2 or toks[1][0] != "word":
                raise _Problem("write hypothesis NAME (e.g. condition1)", "name")
            return chk.hypothesis(toks[1][1])
        _step(toks, chk, number, slots)
    except _Problem as p:
        raise err(p.what, slots.get(p.slot, slots.get(p.slot[0] if isinstance(p.slot, tuple)
                                                      else None, col))) from None


def _step(toks: list, chk: _Checker, number: int, slots: dict[Any, int]) -> None:
    if len(toks) < 3 or toks[0][0] != "word" or toks[1][:2] != ("rel", "=") \
            or toks[2][0] != "word":
        slots["x"] = toks[min(1, len(toks) - 1)][2]
        raise _Problem("expected NAME = OPERATION INPUT... (or param, hypothesis, let, "
                       "claim)", "x" if toks[0][0] == "word" else "name")
    slots["name"], slots["op"] = toks[0][2], toks[2][2]
    op = toks[2][1]
    arity = None if op == _ENVELOPE else (len(OPERATIONS[op].inputs) if op in OPERATIONS
                                          else None)
    if op not in OPERATIONS and op != _ENVELOPE:
        chk.step(toks[0][1], op, (), (), None, "", "", (), False, False, number)
    i, inputs = 3, []
    while i < len(toks) and toks[i][0] == "word" and toks[i][1] not in _KEYWORDS and (
            arity is None or len(inputs) < arity):
        slots[("input", len(inputs))] = toks[i][2]
        inputs.append(toks[i][1])
        i += 1
    slots[("input", len(inputs))] = toks[i][2] if i < len(toks) else toks[-1][2]
    values: list[str] = []
    if i < len(toks) and toks[i][0] == "values":
        slots["values"] = toks[i][2]
        for j, (item, off) in enumerate(_split_items(toks[i][1], toks[i][2])):
            slots[("value", j)] = off + len(item) - len(item.lstrip()) + 1
            values.append(item.strip())
        slots.setdefault(("value", 0), toks[i][2])
        i += 1
    else:
        slots[("value", 0)] = slots[("input", len(inputs))]
    caption, ref, role, n, key, optional = None, "", "", [], False, False
    while i < len(toks):
        kind, text, col = toks[i]
        slots["clause"] = col
        if kind == "string":
            if caption is not None:
                raise _Problem("a second caption (one quoted string per step)", "clause")
            caption, slots["caption"] = text, col
        elif kind == "word" and text == "ref":
            if i + 1 >= len(toks) or toks[i + 1][0] != "string":
                raise _Problem('write ref "…" (a quoted string)', "clause")
            i += 1
            ref, slots["ref"] = toks[i][1], toks[i][2]
        elif kind == "word" and text == "role":
            if i + 1 >= len(toks) or toks[i + 1][0] != "word":
                raise _Problem("write role NAME [N...]", "clause")
            i += 1
            role, slots["role"] = toks[i][1], toks[i][2]
            while i + 1 < len(toks) and toks[i + 1][0] == "int":
                i += 1
                if len(toks[i][1]) > 6:
                    slots["clause"] = toks[i][2]
                    raise _Problem("a role index has at most 6 digits", "clause")
                n.append(int(toks[i][1]))
        elif kind == "word" and text in ("key", "optional"):
            key, optional = key or text == "key", optional or text == "optional"
        elif kind == "values":
            raise _Problem("the values go in one pair of parentheses, after the inputs",
                           "clause")
        elif kind == "word" and arity and text not in _KEYWORDS:
            raise _Problem(f"too many inputs: {op} takes {arity}", "clause")
        else:
            raise _Problem(f"unexpected {text!r}: a caption \"…\", ref \"…\", role NAME N, "
                           "key or optional may follow the inputs", "clause")
        i += 1
    chk.step(toks[0][1], op, inputs, values, caption, ref, role, n, key, optional, number)


def _claim(body: str, chk: _Checker, number: int, err: Any) -> None:
    start = body.index("claim") + len("claim")
    under: list[str] = []
    slots_under: list[int] = []
    m = re.search(r"\bunder\b", body[start:])
    rest_end = len(body) if m is None else start + m.start()
    if m is not None:
        for u in re.finditer(r"\S+", body[start + m.end():]):
            under.append(u.group())
            slots_under.append(start + m.end() + u.start() + 1)
        if not under:
            raise err("write under HYPOTHESIS...", start + m.start() + 1)
    rest = body[start:rest_end]
    words = rest.split()
    col0 = start + len(rest) - len(rest.lstrip()) + 1
    slots: dict[Any, int] = {"kind": col0, **{("under", i): c for i, c in enumerate(slots_under)}}
    try:
        if not words:
            raise _Problem("an empty claim", "kind")
        if words[0] in (*_CLAIM_KINDS, "on"):
            offs = [mm.start() + start + 1 for mm in re.finditer(r"\S+", rest)]
            for i, o in enumerate(offs[1:]):
                slots[("term", i)] = o
            slots[("term", len(offs) - 1)] = offs[-1]
            for i in range(len(words)):
                slots[("input", i - 1)] = offs[i]
            chk.claim(words[0], words[1:], "", under, number)
            return
        kind = "sign" if words[0] == "sign" else "equal"
        text = rest.lstrip()[4:] if kind == "sign" else rest
        off = start + len(rest) - len(text)
        rel = _find_relation(text)
        if rel is None:
            slots["x"] = col0
            raise _Problem("a claim is NAME == TERM, sign EXPR > EXPR, on P c, or one of "
                           f"{', '.join(_CLAIM_KINDS)}", "x")
        pos, sym = rel
        sides = [text[:pos], text[pos + len(sym):]]
        offsets = [off, off + pos + len(sym)]
        terms: list[Any] = []
        for i, (s, o) in enumerate(zip(sides, offsets)):
            slots[("term", i)] = o + len(s) - len(s.lstrip()) + 1
            slots["relation"] = off + pos + 1
            terms.append(_term_text(s.strip()))
        chk.claim(kind, terms, sym, under, number)
    except _Problem as p:
        slot = p.slot
        col = slots.get(slot, slots.get(("term", 0), col0))
        raise err(p.what, col) from None


def _find_relation(text: str) -> tuple[int, str] | None:
    depth = 0
    for i, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth:
            continue
        for sym in _RELATIONS:
            if text.startswith(sym, i):
                return i, sym
    return None


def _term_text(s: str) -> Any:
    if _NAME.fullmatch(s) and s not in _KEYWORDS:
        return s  # a name: an object, or a parameter/let (the checker decides)
    m = re.fullmatch(r"point\s*\((.*)\)", s, re.S)
    if m:
        items = _split_items(m.group(1), 0)
        if len(items) == 2:
            return (items[0][0].strip(), items[1][0].strip())
    return s


# -- writing a program ------------------------------------------------------------------
def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _expr(v: sp.Expr) -> str:
    return sp.sstr(v)


def _term(t: Term) -> str:
    if isinstance(t, Ref):
        return t.name
    if isinstance(t, PointValue):
        return f"point({_expr(t.x)}, {_expr(t.y)})"
    return _expr(t.expr)


def _format(p: Program) -> str:
    out: list[str] = []
    for q in p.params:
        dom = {"positive": "> 0", "nonnegative": ">= 0"}.get(q.domain, q.domain)
        out.append(f"param {q.name} {dom}")
    out += [f"hypothesis {h}" for h in p.hypotheses]
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
        if c.kind in ("equal", "sign"):
            body = f"{_term(c.terms[0])} {c.relation} {_term(c.terms[1])}"
            line = f"claim {'sign ' * (c.kind == 'sign')}{body}"
        else:
            line = f"claim {c.kind} " + " ".join(_term(t) for t in c.terms)
        out.append(line + "".join(f" under {h}" if i == 0 else f" {h}"
                                  for i, h in enumerate(c.under)))
    return "\n".join(out) + "\n"


# -- replay ---------------------------------------------------------------------------------
def _bindings(program: Program, grasp: Any) -> dict[sp.Basic, sp.Expr]:
    """Symbol (and sin/cos of a parameter) -> value, from a Grasp or a mapping."""
    if grasp is None:
        return {}
    if isinstance(grasp, Mapping):
        from ..inputs import real_value

        given = {k: real_value(v, k) for k, v in grasp.items()}
    else:
        given = grasp.params
    table: dict[sp.Basic, sp.Expr] = {}
    for p in program.params:
        if p.name not in given:
            raise InputError(f"{program.file}:{p.line}:1: no value for the parameter "
                             f"{p.name!r}")
        table[p.symbol] = given[p.name]
    if any(has_float(v) for v in table.values()):
        return table  # floats: each step's value is evaluated from them (_float_value)
    for atom in _trig_atoms(program):  # exact sines of the grasp's angles (no nested radicals)
        s, c = sincos(atom.args[0].xreplace(table))
        table[atom] = s if isinstance(atom, sp.sin) else c
    return table


def _float_value(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> sp.Expr:
    """A step's value for a float grasp: a parameter (or its negative) as the double it
    is, a constant as written, anything else evaluated from the exact binary values of
    the parameters at 40 digits and rounded once, as
    :meth:`graspcompass.Grasp.side_direction` does (``cos φ ∓ μ sin φ`` cancels in
    double precision for a nearly horizontal cone side)."""
    if not v.free_symbols:
        return v
    if v.is_Symbol or (v.is_Mul and len(v.args) == 2 and v.args[0] == -1
                       and v.args[1].is_Symbol):
        return v.xreplace(table)
    with mpmath.workdps(_FLOAT_DIGITS):
        value = _mp(v, table)
    return canon(sp.Float(float(value)))


_MP_FUNCTIONS = {sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan,
                 sp.asin: mpmath.asin, sp.acos: mpmath.acos, sp.atan: mpmath.atan}


def _mp(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> mpmath.mpf:
    """``v`` in mpmath at the working precision, symbols from ``table`` (exact binary)."""
    if v.is_Symbol:
        return mpf(table[v])
    if v.is_Number or not v.free_symbols:
        return mpf(v)
    args = [_mp(a, table) for a in v.args]
    if v.is_Add:
        return mpmath.fsum(args)
    if v.is_Mul:
        return mpmath.fprod(args)
    if v.is_Pow:
        return args[0] ** args[1]
    if type(v) in _MP_FUNCTIONS:
        return _MP_FUNCTIONS[type(v)](*args)
    if isinstance(v, sp.atan2):
        return mpmath.atan2(*args)
    return mpf(v.xreplace(table))  # pragma: no cover - every function of the parser is above


def _trig_atoms(program: Program) -> set[sp.Basic]:
    out: set[sp.Basic] = set()
    for s in program.steps:
        for v in s.values:
            out |= {a for a in v.atoms(sp.sin, sp.cos) if a.free_symbols}
    return out


def replay(program: Program, grasp: Any = None) -> Construction:
    """Run a program's steps in order with the exact kernel.

    Parameters
    ----------
    program : Program
        From :func:`parse` or :meth:`ConstructionBuilder.build`.
    grasp : Grasp or Mapping, optional
        Values of the parameters: a :class:`~graspcompass.Grasp` (its ``params``:
        x1, x2, y, phi1, phi2, mu1, mu2, xi1, xi2) or a mapping name -> value
        (read at the input boundary).  ``sin`` and ``cos`` of a parameter take the
        grasp's exact values (:func:`graspcompass.geometry.trig.sincos`).  Without
        values the construction is symbolic, in the parameters' symbols.

    Returns
    -------
    Construction
        The steps (with caption, ref, role), the grasp, and the ``optional``
        steps left out as ``skipped``.  An ``envelope`` step is made only when
        no value is symbolic (§3.3, eq. (25)).

    Raises
    ------
    DegenerateStepError
        A step the kernel cannot make (not ``optional``), naming it and its line.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> c = replay(paper_program(), Grasp.preset("fig6"))
    >>> c.step("V1").role, c.step("V1").n, c.step("V1").ref
    ('V', (1,), '§3.3 V1 step (3), eq. (30)/(33)')
    """
    from .envelope import outer_envelope

    table = _bindings(program, grasp)
    floats = any(has_float(v) for v in table.values())
    env: dict[str, Any] = {}
    steps: list[Step] = []
    skipped: list[tuple[str, str]] = []
    symbolic = any(v.free_symbols for v in table.values()) if table else bool(program.params)
    for s in program.steps:
        if s.op == _ENVELOPE:
            if symbolic:
                continue
            ins = tuple(n for n in s.inputs if n in env)
            steps.append(Step(len(steps), s.name, _ENVELOPE, "compass", ins, outer_envelope(env),
                              (), s.caption, s.ref, (), s.key, s.role, s.n))
            env[s.name] = steps[-1].obj
            continue
        if floats:
            values = tuple(_float_value(v, table) for v in s.values)
        else:
            values = tuple(_canon(v.xreplace(table)) for v in s.values) if table else s.values
        spec = StepSpec(s.name, s.op, s.inputs, OPERATIONS[s.op].instrument, s.caption, s.ref,
                        values, s.key, s.role, s.n)
        try:
            step = run_step(spec, env, len(steps))
        except GeometryError as exc:
            if s.optional:
                skipped.append((s.name, str(exc)))
                continue
            raise DegenerateStepError(
                f"{program.file}:{s.line}:1: step {s.name} = {s.op} {' '.join(s.inputs)} is "
                f"degenerate: {exc}", s.name, s.line, *(env[n] for n in s.inputs)) from exc
        env[s.name] = step.obj
        steps.append(step)
    return Construction(tuple(steps), grasp if not isinstance(grasp, Mapping) else None,
                        tuple(skipped))


def _canon(v: sp.Expr) -> sp.Expr:
    return v if v.is_Atom else canon(v)


# -- the Python builder -----------------------------------------------------------------------
class ConstructionBuilder:
    """Make a :class:`Program` from Python, with the same checks as :func:`parse`.

    Every method refuses what the parser refuses, with a
    :class:`ConstructionSyntaxError` whose line is the number of the call.

    Examples
    --------
    >>> b = ConstructionBuilder()
    >>> b.param("a", "positive")
    >>> _ = b.step("A", "point", values=("a", 0), role="given")
    >>> _ = b.step("B", "point", values=(0, "a"))
    >>> _ = b.step("M", "midpoint", "A", "B", caption="the midpoint")
    >>> b.claim("equal", "M", ("a/2", "a/2"))
    >>> b.build() == parse('''param a > 0
    ... A = point (a, 0) role given "A: a given point"
    ... B = point (0, a)
    ... M = midpoint A B "the midpoint"
    ... claim M == point(a/2, a/2)''')
    True
    """

    def __init__(self, file: str = "<builder>") -> None:
        self._chk, self._file, self._calls = _Checker(), file, 0

    def _run(self, fn: Any, *args: Any) -> Any:
        self._calls += 1
        try:
            return fn(*args)
        except _Problem as p:
            raise ConstructionSyntaxError(p.what, self._file, self._calls, 0) from None

    def param(self, name: str, domain: str) -> None:
        """Declare a parameter with a domain of :data:`DOMAINS` (``"positive"``, ``"angle"``...)."""
        self._run(self._chk.param, name, domain, self._calls + 1)

    def hypothesis(self, name: str) -> None:
        """Make a hypothesis of :data:`HYPOTHESES` available to claims."""
        self._run(self._chk.hypothesis, name)

    def let(self, name: str, value: Any) -> None:
        """A named value (text in the safe expression syntax, an int or a sympy expression)."""
        self._run(self._chk.let, name, value, self._calls + 1)

    def step(self, name: str, op: str, *inputs: str, values: Iterable[Any] = (),
             caption: str | None = None, ref: str = "", role: str = "",
             n: Iterable[int] = (), key: bool = False, optional: bool = False) -> Statement:
        """Add the step ``name = op inputs (values)``; returns its :class:`Statement`.

        Parameters
        ----------
        name, op : str
            The new object's name and the operation (:data:`OPERATIONS` or ``"envelope"``).
        *inputs : str
            Names of earlier objects, of the kinds the operation takes.
        values : iterable
            The operation's parameters: text, ints or sympy expressions.
        caption, ref, role, n, key, optional
            As the clauses of the language (the caption defaults to the operation's).
        """
        return self._run(self._chk.step, name, op, inputs, values, caption, ref, role, n,
                         key, optional, self._calls + 1)

    def claim(self, kind: str, *terms: Any, relation: str = "==",
              under: Iterable[str] = ()) -> None:
        """A claim: ``kind`` is ``equal``, ``sign``, ``on``, ``collinear``, ``concurrent``,
        ``perpendicular`` or ``parallel``; terms are names, text, or ``(x, y)`` points."""
        rel = relation if kind in ("equal", "sign") else ""
        self._run(self._chk.claim, kind, terms, rel, under, self._calls + 1)

    def build(self) -> Program:
        """The program made so far."""
        return self._chk.program(self._file)


# -- the shipped recipe -------------------------------------------------------------------------
def paper_text() -> str:
    """The text of the paper's recipe as shipped (``recipes/paper.gc``).

    Examples
    --------
    >>> paper_text().splitlines()[0]
    '# The internal force diagram of a two-point grasp, drawn by ruler and compass:'
    """
    return resources.files(__package__).joinpath("recipes", "paper.gc").read_text("utf-8")


@lru_cache(maxsize=1)
def paper_program() -> Program:
    """The paper's recipe (§3.3, §3.2), parsed once; replay it with :func:`replay`.

    Examples
    --------
    >>> p = paper_program()
    >>> len(p.steps), [q.name for q in p.params][:3], p.hypotheses
    (47, ['x1', 'x2', 'y'], ('condition1',))
    """
    return parse(paper_text(), "paper.gc")

