"""The data of a construction program and the checks shared by the parser and the builder.

A :class:`Program` is what :func:`graspcompass.construction.language.parse` reads
from a file and what :class:`ConstructionBuilder` makes from Python: declared
parameters (:class:`Param`), named hypotheses, ``let`` values, steps
(:class:`Statement`) and claims (:class:`Claim`), all plain frozen data.  Both
paths go through one checker, so they refuse the same things with the same
words (:class:`ConstructionSyntaxError`, ``FILE:LINE:COL: what``).

Examples
--------
>>> b = ConstructionBuilder()
>>> _ = b.step("A", "point", values=(0, 0))
>>> b.step("l", "meet", "A", "A")
Traceback (most recent call last):
...
graspcompass.construction.program.ConstructionSyntaxError: <builder>:2:0: wrong kind of input: ...
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ._program_checker import _Checker, read_inequality
from ._program_data import (  # noqa: F401  (the parser's words, read from here)
    _CLAIM_KINDS,
    _ENVELOPE,
    _KEYWORDS,
    _NAME,
    _RELATIONS,
    _TOKEN,
    _VALUE_CLAIMS,
    DOMAINS,
    HYPOTHESES,
    MAX_LINE_LENGTH,
    MAX_LINES,
    Claim,
    ConstructionSyntaxError,
    DegenerateStepError,
    Param,
    PointValue,
    Program,
    Ref,
    Statement,
    Term,
    Value,
    _Problem,
)

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
    "Term",
    "Value",
]


# -- the Python builder -----------------------------------------------------------------------
class ConstructionBuilder:
    """Make a :class:`Program` from Python, with the same checks as :func:`parse`.

    Every method refuses what the parser refuses, with a
    :class:`ConstructionSyntaxError` whose line is the number of the call.

    Examples
    --------
    >>> from graspcompass.construction.language import parse
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

    def hypothesis(self, name: str, inequality: str | None = None) -> None:
        """Make a hypothesis of :data:`HYPOTHESES` available to claims, or with
        ``inequality`` (``"p**2 + q**2 > 1"``) restrict the parameters for the whole file."""
        if inequality is None:
            return self._run(self._chk.hypothesis, name)
        self._run(read_inequality, self._chk, name, inequality, self._calls + 1)

    def let(self, name: str, value: Any) -> None:
        """A named value (text in the safe expression syntax, an int or a sympy expression)."""
        self._run(self._chk.let, name, value, self._calls + 1)

    def step(
        self,
        name: str,
        op: str,
        *inputs: str,
        values: Iterable[Any] = (),
        caption: str | None = None,
        ref: str = "",
        role: str = "",
        n: Iterable[int] = (),
        key: bool = False,
        optional: bool = False,
    ) -> Statement:
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
        return self._run(
            self._chk.step,
            name,
            op,
            inputs,
            values,
            caption,
            ref,
            role,
            n,
            key,
            optional,
            self._calls + 1,
        )

    def claim(
        self, kind: str, *terms: Any, relation: str = "==", under: Iterable[str] = ()
    ) -> None:
        """A claim: ``kind`` is ``equal``, ``sign``, ``on``, ``collinear``, ``concurrent``,
        ``perpendicular`` or ``parallel``; terms are names, text, or ``(x, y)`` points."""
        rel = relation if kind in ("equal", "sign") else ""
        self._run(self._chk.claim, kind, terms, rel, under, self._calls + 1)

    def build(self) -> Program:
        """The program made so far."""
        return self._chk.program(self._file)
