"""The statements of the construction language: lines split into tokens and checked.

A line loses its comment (:func:`_strip_comment`), is split into tokens
(:class:`_Line`, values in parentheses kept as raw text) and read as a ``param``,
``hypothesis``, ``let``, step or ``claim`` statement into the
:class:`~graspcompass.construction.program._Checker` that builds the
:class:`~graspcompass.construction.program.Program`.  Private to
:mod:`graspcompass.construction.language`, whose :func:`~graspcompass.construction.language.parse`
drives it and which re-exports these names.
"""

from __future__ import annotations

import re
from typing import Any

from ._hypotheses import HYPOTHESIS_LINE
from ._program_checker import read_inequality
from .operations import OPERATIONS
from .program import (
    _CLAIM_KINDS,
    _ENVELOPE,
    _KEYWORDS,
    _NAME,
    _RELATIONS,
    _TOKEN,
    _VALUE_CLAIMS,
    _Checker,
    _Problem,
)


def _strip_comment(text: str) -> str:
    if "#" not in text:
        return text
    if '"' not in text:
        return text[: text.index("#")]
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


_SPACE = re.compile(r"\s*")  # the whitespace str.strip() strips


class _Line:
    """The tokens of one line: (kind, text, column), values kept as raw text."""

    def __init__(self, text: str, err: Any) -> None:
        self.text, self.err, self.tokens = text, err, []
        pos = 0
        while pos < len(text):
            start = _SPACE.match(text, pos).end()  # type: ignore[union-attr]
            if start == len(text):
                break
            m = _TOKEN.match(text, pos)
            col = start + 1
            if m is None or m.lastgroup is None:
                if text[col - 1] == '"':
                    raise err("unterminated string", col)
                raise err(f"unexpected character {text[col - 1]!r}", col)
            if m.lastgroup == "open":
                end = _group_end(text, m.end() - 1)
                if end < 0:
                    raise err("unbalanced parenthesis: '(' is not closed", col)
                self.tokens.append(("values", text[m.end() : end - 1], col))
                pos = end
                continue
            if m.lastgroup == "string":
                raw = m.group("string")[1:-1]
                self.tokens.append(
                    ("string", re.sub(r"\\(.)", r"\1", raw) if "\\" in raw else raw, col)
                )
            else:
                self.tokens.append((m.lastgroup, m.group(m.lastgroup), col))
            pos = m.end()


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
        m = HYPOTHESIS_LINE.match(body) if head == "hypothesis" else None
        if m is not None:  # hypothesis NAME: LEFT REL RIGHT
            slots["name"], slots["value"] = m.start("name") + 1, m.start("rel") + 1
            read_inequality(chk, m["name"], m["rel"], number)
            return None
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
                raise _Problem(
                    "write hypothesis NAME (e.g. condition1) or hypothesis NAME: VALUE > VALUE",
                    "name",
                )
            return chk.hypothesis(toks[1][1])
        _step(toks, chk, number, slots)
    except _Problem as p:
        raise err(
            p.what,
            slots.get(p.slot, slots.get(p.slot[0] if isinstance(p.slot, tuple) else None, col)),
        ) from None


def _step(toks: list, chk: _Checker, number: int, slots: dict[Any, int]) -> None:
    if len(toks) < 3 or toks[0][0] != "word" or toks[1][:2] != ("rel", "=") or toks[2][0] != "word":
        slots["x"] = toks[min(1, len(toks) - 1)][2]
        raise _Problem(
            "expected NAME = OPERATION INPUT... (or param, hypothesis, let, claim)",
            "x" if toks[0][0] == "word" else "name",
        )
    slots["name"], slots["op"] = toks[0][2], toks[2][2]
    op = toks[2][1]
    arity = None if op == _ENVELOPE else (len(OPERATIONS[op].inputs) if op in OPERATIONS else None)
    if op not in OPERATIONS and op != _ENVELOPE:
        chk.step(toks[0][1], op, (), (), None, "", "", (), False, False, number)
    i = 3
    inputs: list[str] = []
    while (
        i < len(toks)
        and toks[i][0] == "word"
        and toks[i][1] not in _KEYWORDS
        and (arity is None or len(inputs) < arity)
    ):
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
            raise _Problem("the values go in one pair of parentheses, after the inputs", "clause")
        elif kind == "word" and arity and text not in _KEYWORDS:
            raise _Problem(f"too many inputs: {op} takes {arity}", "clause")
        else:
            raise _Problem(
                f'unexpected {text!r}: a caption "…", ref "…", role NAME N, '
                "key or optional may follow the inputs",
                "clause",
            )
        i += 1
    chk.step(toks[0][1], op, inputs, values, caption, ref, role, n, key, optional, number)


def _claim(body: str, chk: _Checker, number: int, err: Any) -> None:
    start = body.index("claim") + len("claim")
    under: list[str] = []
    slots_under: list[int] = []
    m = re.search(r"\bunder\b", body[start:])
    rest_end = len(body) if m is None else start + m.start()
    if m is not None:
        for u in re.finditer(r"\S+", body[start + m.end() :]):
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
        if words[0] in _VALUE_CLAIMS:
            head, eq, value = rest.partition("==")
            if not eq or not value.strip():
                raise _Problem(f"write claim {words[0]} NAMES... == VALUE", "kind")
            offs = [mm.start() + start + 1 for mm in re.finditer(r"\S+", head)]
            for i, o in enumerate(offs[1:]):
                slots[("term", i)] = slots[("input", i)] = o
            slots[("term", len(offs) - 1)] = start + len(head) + 3
            chk.claim(words[0], [*head.split()[1:], value.strip()], "==", under, number)
            return
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
            raise _Problem(
                "a claim is NAME == TERM, sign EXPR > EXPR, on P c, or one of "
                f"{', '.join(_CLAIM_KINDS)}",
                "x",
            )
        pos, sym = rel
        sides = [text[:pos], text[pos + len(sym) :]]
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
