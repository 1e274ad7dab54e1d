"""The data of a construction program: its words, errors and frozen records.

Private to :mod:`graspcompass.construction.program`, which re-exports every public
name (their ``__module__`` is that module's: documented and pickled there).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import sympy as sp

from .. import symbols as _model
from ..boundary.errors import InputError
from ..boundary.expr import Condition
from ..geometry import GeometryError
from ._hypotheses import Inequality
from ._program_text import format_program
from .operations import OPERATIONS

__all__ = [
    "DOMAINS",
    "HYPOTHESES",
    "MAX_LINES",
    "MAX_LINE_LENGTH",
    "Claim",
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

#: Longest line read (characters).
MAX_LINE_LENGTH = 1000
#: Most lines in one file.
MAX_LINES = 10_000
#: Domain words of ``param NAME DOMAIN`` -> what they mean.
DOMAINS: Mapping[str, str] = {
    "positive": "> 0",
    "nonnegative": ">= 0",
    "angle": "0 < value <= pi (a normal angle φ)",
    "friction": "a friction coefficient μ > 0",
    "half_angle": "0 < ξ < pi/2 (tan ξ = μ)",
    "real": "any real number",
}
#: Hypotheses a file may name (``hypothesis NAME``, ``claim ... under NAME``).
HYPOTHESES: Mapping[str, str] = {
    "condition1": "condition (1), §2.2.2: each friction cone contains the other contact "
    "(−π/2 < φi − ξi < π/2 < φi + ξi < 3π/2)",
}
_ENVELOPE = "envelope"
_RELATIONS = ("==", "!=", ">=", "<=", ">", "<")
_CLAIM_KINDS = {
    "collinear": ("point", 3),
    "concurrent": ("line", 3),
    "concyclic": ("point", 4),
    "perpendicular": ("line", 2),
    "parallel": ("line", 2),
    "congruent": ("point", 4),
    "equal_angles": ("point", 6),
    "tangent": (None, 2),
}
#: Claims of names followed by ``== VALUE``: a ratio of lengths, a sum of directed angles.
_VALUE_CLAIMS = {"ratio": 4, "angles": 3}
_KEYWORDS = frozenset(
    {
        "param",
        "hypothesis",
        "let",
        "claim",
        "ref",
        "role",
        "key",
        "optional",
        "under",
        "sign",
        "on",
        *_CLAIM_KINDS,
        *_VALUE_CLAIMS,
        "point",
        "pi",
        "deg",
    }
)
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:-[A-Za-z0-9_]+)*")
_TOKEN = re.compile(
    r"""\s*(?:(?P<string>"(?:[^"\\\n]|\\.)*")|(?P<word>[A-Za-z_][A-Za-z0-9_]*
    (?:-[A-Za-z0-9_]+)*)|(?P<int>\d+)|(?P<rel>==|!=|>=|<=|>|<|=)|(?P<open>\())""",
    re.X,
)


# -- errors ---------------------------------------------------------------------------
class ConstructionSyntaxError(InputError):
    """A construction file that cannot be read: ``FILE:LINE:COL: what is wrong``.

    Examples
    --------
    >>> from graspcompass.construction.language import parse
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
    #: The conditions its values need as written (divisors ≠ 0, radicands ≥ 0, ...:
    #: :func:`graspcompass.expr.parse_with_conditions`), proved or listed by the checker.
    conditions: tuple[Condition, ...] = field(default=(), compare=False)


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
    #: The conditions its values need as written (see :attr:`Statement.conditions`).
    conditions: tuple[Condition, ...] = field(default=(), compare=False)


@dataclass(frozen=True)
class Program:
    """A parsed construction file: parameters, hypotheses, named values, steps, claims."""

    params: tuple[Param, ...] = ()
    hypotheses: tuple[str, ...] = ()
    lets: tuple[tuple[str, sp.Expr], ...] = ()
    steps: tuple[Statement, ...] = ()
    claims: tuple[Claim, ...] = ()
    file: str = field(default="<text>", compare=False)
    #: Named inequalities on the parameters (``hypothesis NAME: A > B``), for the whole file.
    inequalities: tuple[Inequality, ...] = ()

    @cached_property
    def trig_atoms(self) -> frozenset:
        """``sin(a)`` and ``cos(a)`` of expressions in the parameters, in the steps' values
        (replay gives them the grasp's exact values; computed once per program)."""
        return frozenset(
            a
            for s in self.steps
            for v in s.values
            for a in v.atoms(sp.sin, sp.cos)
            if a.free_symbols
        )

    @property
    def kinds(self) -> dict[str, str]:
        """Name -> kind of every object the steps make (``envelope`` for the envelope)."""
        return {s.name: _makes(s.op) for s in self.steps}

    def to_text(self) -> str:
        """The program written in the language again (``parse(p.to_text()) == p``)."""
        return format_program(self, _VALUE_CLAIMS)


def _makes(op: str) -> str:
    return _ENVELOPE if op == _ENVELOPE else OPERATIONS[op].makes


def _symbol(name: str, domain: str) -> sp.Symbol:
    model = getattr(_model, name, None) if name in _model.__all__ else None
    if isinstance(model, sp.Symbol):
        return model
    if domain in ("positive", "friction", "half_angle", "angle"):
        return sp.Symbol(name, positive=True)
    return (
        sp.Symbol(name, nonnegative=True) if domain == "nonnegative" else sp.Symbol(name, real=True)
    )


# documented and pickled as graspcompass.construction.program's (which re-exports them)
for _cls in (
    ConstructionSyntaxError,
    DegenerateStepError,
    Param,
    Statement,
    Ref,
    Value,
    PointValue,
    Claim,
    Program,
):
    _cls.__module__ = "graspcompass.construction.program"
