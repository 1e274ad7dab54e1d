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
Python (the program's data, the checks and the builder live in
:mod:`graspcompass.construction.program`).  Errors are
:class:`ConstructionSyntaxError` (``FILE:LINE:COL: what``) and, at replay,
:class:`DegenerateStepError` (the step, its line and objects).

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

import math
import re
from collections.abc import Mapping
from functools import lru_cache
from importlib import resources
from typing import TYPE_CHECKING, Any

import mpmath
import sympy as sp

from .._floatpath import mpf
from ..errors import InputError
from ..geometry import GeometryError
from ..geometry.exact import Frac, NotAFraction, canon, decide_sign, has_float
from ..geometry.trig import sincos
from .operations import OPERATIONS
from .program import (
    _CLAIM_KINDS,
    _ENVELOPE,
    _KEYWORDS,
    _NAME,
    _RELATIONS,
    _TOKEN,
    DOMAINS,
    HYPOTHESES,
    MAX_LINE_LENGTH,
    MAX_LINES,
    Claim,
    ConstructionBuilder,
    ConstructionSyntaxError,
    DegenerateStepError,
    Param,
    PointValue,
    Program,
    Ref,
    Statement,
    Value,
    _Checker,
    _Problem,
)
from .protocol import Construction, Step, StepSpec, run_step

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = [
    "DOMAINS",
    "EXAMPLES",
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
    "example_text",
    "paper_program",
    "paper_text",
    "parse",
    "replay",
]

_FLOAT_DIGITS = 40  # working digits of a float grasp's values, rounded once to doubles


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
    graspcompass.construction.program.ConstructionSyntaxError: f.gc:1:18: unknown name 'A' ...
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


# -- replay ---------------------------------------------------------------------------------
def _bindings(program: Program, grasp: Grasp | Mapping[str, Any] | None
              ) -> dict[sp.Basic, sp.Expr]:
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
        if isinstance(grasp, Mapping):
            _check_domain(program, p, given[p.name])
    if any(has_float(v) for v in table.values()):
        return table  # floats: each step's value is evaluated from them (_float_value)
    known = {}  # the grasp's own exact sin φi, cos φi (computed when it was made)
    if not isinstance(grasp, Mapping):
        known = {getattr(grasp, f"phi{i}"): (getattr(grasp, f"s{i}"), getattr(grasp, f"c{i}"))
                 for i in (1, 2)}
    for atom in program.trig_atoms:  # exact sines of the grasp's angles (no nested radicals)
        angle = atom.args[0].xreplace(table)
        s, c = known[angle] if angle in known else sincos(angle)
        table[atom] = s if isinstance(atom, sp.sin) else c
    return table


#: Domain -> (bound, sign of value - bound, whether the bound itself is allowed).
_BOUNDS = {"positive": ((0, 1, False),), "friction": ((0, 1, False),),
           "nonnegative": ((0, 1, True),), "angle": ((0, 1, False), (sp.pi, -1, True)),
           "half_angle": ((0, 1, False), (sp.pi / 2, -1, False))}


def _check_domain(program: Program, p: Param, value: sp.Expr) -> None:
    """Refuse a value outside the parameter's declared domain (when its sign is decided)."""
    for bound, direction, equal in _BOUNDS.get(p.domain, ()):
        sign = decide_sign(value - bound)
        if sign is not None and sign != direction and not (sign == 0 and equal):
            raise InputError(f"{program.file}:{p.line}:1: {p.name} = {value} is outside its "
                             f"domain ({p.domain}: {DOMAINS[p.domain]})")


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
    try:
        with mpmath.workdps(_FLOAT_DIGITS):
            value = float(_mp(v, table))
    except (ArithmeticError, TypeError, ValueError):  # 1/0, a complex root
        value = float("nan")
    if not math.isfinite(value):
        raise InputError(f"the value {v} is not a finite real number for these parameters")
    return canon(sp.Float(value))


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


def replay(program: Program, grasp: Grasp | Mapping[str, Any] | None = None
           ) -> Construction:
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
            steps.append(Step(len(steps), s.name, _ENVELOPE, "compass", ins,
                              outer_envelope(_by_role(steps, env)), (), s.caption, s.ref, (),
                              s.key, s.role, s.n))
            env[s.name] = steps[-1].obj
            continue
        try:
            if floats:
                values = tuple(_float_value(v, table) for v in s.values)
            else:
                values = tuple(_exact_value(v, table) if v.free_symbols else v
                               for v in s.values) if table else s.values
        except (InputError, ArithmeticError, ValueError) as exc:
            raise InputError(f"{program.file}:{s.line}:1: step {s.name}: {exc}") from None
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


def _by_role(steps: list[Step], env: dict[str, Any]) -> dict[str, Any]:
    """The objects the envelope reads, found by role: ``role V n`` is V_n and
    ``role break_point n m`` is B_nm, whatever the file names them (eq. (25))."""
    out = dict(env)
    for st in steps:
        if st.role == "V" and len(st.n) == 1:
            out[f"V{st.n[0]}"] = st.obj
        elif st.role == "break_point" and len(st.n) == 2:
            out[f"B{st.n[0]}{st.n[1]}"] = st.obj
    return out


def _exact_value(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> sp.Expr:
    """A step's value for exact parameters, in canonical form (:func:`canon`).

    Computed with the kernel's fractions of polynomials (no sympy trees built on the
    way), or by substitution where they cannot hold it.
    """
    try:
        return _frac(v, table).expr()
    except (NotAFraction, ZeroDivisionError):
        pass
    value = v.xreplace(table)
    if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise InputError(f"the value {v} is not finite for these parameters")
    if value.has(sp.I):
        raise InputError(f"the value {v} is not a real number for these parameters")
    return value if value.is_Atom else canon(value)


def _frac(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> Frac:
    if v.is_Rational:
        return Frac.of(v)
    hit = table.get(v)
    if hit is not None:
        return Frac.of(hit)
    if v.is_Add or v.is_Mul:
        parts = [_frac(a, table) for a in v.args]
        out = parts[0]
        for f in parts[1:]:
            out = out + f if v.is_Add else out * f
        return out
    if v.is_Pow and v.exp.is_Integer and abs(int(v.exp)) <= 64:
        base, out = _frac(v.base, table), Frac.of(sp.Integer(1))
        for _ in range(abs(int(v.exp))):
            out = out * base
        return out if v.exp > 0 else Frac.of(sp.Integer(1)) / out
    return Frac.of(v.xreplace(table))


# -- the shipped recipe -------------------------------------------------------------------------
def paper_text() -> str:
    """The text of the paper's recipe as shipped (``recipes/paper.gc``).

    Examples
    --------
    >>> paper_text().splitlines()[0]
    '# The internal force diagram of a two-point grasp, drawn by ruler and compass:'
    """
    return resources.files(__package__).joinpath("recipes", "paper.gc").read_text("utf-8")


def example_text(name: str) -> str:
    """A construction file shipped with the package beside the recipe: ``thales.gc``
    (Fig. 3) or ``exercise-v3.gc`` (a student's V3 with one slip, for grading).

    Examples
    --------
    >>> parse(example_text("thales.gc")).claims[0].kind
    'on'
    """
    if name not in EXAMPLES:
        raise InputError(f"no shipped example {name!r}: choose one of {', '.join(EXAMPLES)}")
    return resources.files(__package__).joinpath("recipes", name).read_text("utf-8")


#: The example files shipped beside the recipe.
EXAMPLES = ("thales.gc", "exercise-v3.gc")


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

