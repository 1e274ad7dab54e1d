"""Hypotheses as named inequalities on the parameters (``hypothesis NAME: A > B``).

A file restricts its parameters beyond their domains with named inequalities::

    param p real
    param q real
    hypothesis outside: p**2 + q**2 > 1     # P outside the unit circle

Each is an :class:`Inequality` of the :class:`~graspcompass.construction.program.Program`
(``program.inequalities``): it holds for the whole file, as a domain does.  The checker
uses it to discharge non-degeneracy conditions and to prove signs, states it in every
result, and seeks counterexamples only among the points where it holds.  The values
are exact expressions in the parameters and ``let`` names (read by the same safe parser
as every value); the relation is one of ``> >= < <= !=``.

Examples
--------
>>> import sympy as sp
>>> p = sp.Symbol("p", real=True)
>>> h = Inequality("outside", ">", p**2, sp.Integer(1))
>>> h.text, h.relation0, h.expr0
('outside: p**2 > 1', '>', p**2 - 1)
>>> h.holds({p: 2}), h.holds({p: sp.Rational(1, 2)})
(True, False)
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

__all__ = ["HYPOTHESIS_LINE", "RELATIONS", "Inequality"]

#: The relations an inequality hypothesis may use.
RELATIONS = ("!=", ">=", "<=", ">", "<")
#: ``hypothesis NAME: LEFT REL RIGHT`` (the name, then the relation text after the colon).
HYPOTHESIS_LINE = re.compile(r"\s*hypothesis\s+(?P<name>\S+?)\s*:\s*(?P<rel>.*\S)\s*$")
_FLIP = {">": "<", ">=": "<=", "<": ">", "<=": ">=", "!=": "!="}


@dataclass(frozen=True)
class Inequality:
    """A named hypothesis ``lhs relation rhs`` on the parameters.

    Attributes
    ----------
    name : str
        Its name, as results state it.
    relation : str
        One of :data:`RELATIONS`.
    lhs, rhs : sympy.Expr
        Exact expressions in the parameters.
    line : int
        The line of the file that declares it.
    """

    name: str
    relation: str
    lhs: sp.Expr
    rhs: sp.Expr
    line: int = field(default=0, compare=False)

    @property
    def text(self) -> str:
        """``NAME: LEFT REL RIGHT``, as the file writes it (``to_text`` and reports)."""
        return f"{self.name}: {sp.sstr(self.lhs)} {self.relation} {sp.sstr(self.rhs)}"

    @property
    def relation0(self) -> str:
        """The relation of :attr:`expr0` to 0: ``>``, ``>=`` or ``!=``."""
        return self.relation if self.relation in (">", ">=", "!=") else _FLIP[self.relation]

    @property
    def expr0(self) -> sp.Expr:
        """The hypothesis as ``expr0 relation0 0``."""
        d = self.lhs - self.rhs
        return sp.expand(d if self.relation in (">", ">=", "!=") else -d)

    def holds(self, point: Mapping[Any, Any]) -> bool:
        """Whether it holds, exactly, at ``point`` (symbol or name -> exact value)."""
        subs = {
            (s if isinstance(s, sp.Symbol) else sp.Symbol(str(s))): sp.sympify(v)
            for s, v in point.items()
        }
        by_name = {str(s): v for s, v in subs.items()}
        e = self.expr0
        v = e.xreplace({s: by_name[str(s)] for s in e.free_symbols if str(s) in by_name})
        v = sp.nsimplify(v) if v.has(sp.Float) else v
        if v.free_symbols:
            return False
        z = sp.simplify(v) if not v.is_Rational else v
        if self.relation0 == "!=":
            return bool(z != 0)
        sign = z.is_positive if self.relation0 == ">" else z.is_nonnegative
        if sign is None:
            sign = bool(sp.N(z, 50) > 0) if self.relation0 == ">" else bool(sp.N(z, 50) >= 0)
        return bool(sign)
