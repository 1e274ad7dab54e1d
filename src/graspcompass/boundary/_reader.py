"""The reader of the safe expression parser: the grammar, its checks and its limits.

Private to :mod:`graspcompass.expr` (issue 21: the parser's module under 600 lines).  The
text is parsed by :mod:`ast` and only the grammar that :mod:`graspcompass.expr` documents is
evaluated, node by node (:class:`_Reader`), each intermediate value checked against
:mod:`graspcompass.limits`.  :class:`ExpressionError` is documented and pickled as
``graspcompass.expr.ExpressionError``.
"""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Callable, Mapping
from fractions import Fraction

import mpmath
import sympy

from ._reader_values import (
    _TRIG,
    _algebraic_sign,
    _clearly_inside_unit,
    _degree,
    _digits,
    _has_function,
    _max_bits,
    _mpf,
    _plain_real,
    _scan,
    _short,
    _too_many_nodes,
    _total_bits,
    real_sign,
)
from .errors import ComplexValueError, InputError
from .limits import (  # the limits, stated once
    MAX_ARGUMENT_BITS,
    MAX_BITS,
    MAX_DEGREE,
    MAX_DEPTH,
    MAX_EXPONENT,
    MAX_LENGTH,
    MAX_NODES,
    MAX_TERMS,
    MAX_WORK_BITS,
)

__all__ = ["ComplexExpressionError", "Condition", "ExpressionError", "real_sign"]


#: A condition under which a value is defined, as written: ``(relation, expr)`` with
#: relation ``"!="`` (a divisor, ``expr ≠ 0``), ``">="`` (a radicand, ``expr ≥ 0``) or
#: ``">"`` (a radicand under a negative power).  Kept before sympy evaluates the text, so
#: ``x/x`` keeps ``x ≠ 0`` although its value is 1.
Condition = tuple[str, sympy.Expr]

#: A function value sympy writes out in more nodes stays unevaluated (sin(pi/5) is written
#: out in radicals, 12 nodes; tan(pi/120), 313 nodes, stays tan(pi/120)).
_EXPANSION_NODES = 40
_MAX_DECIMAL_EXPONENT = 400  # bound on n in a literal such as 1e-n (checked before reading it)
_DEGREE = sympy.pi / 180
_ALLOWED = (
    "only numbers, + - * / **, pi, deg, sqrt, sin, cos, tan, asin, acos, atan, atan2"
    " and parentheses are allowed"
)
_FUNCTIONS: dict[str, tuple[Callable[..., sympy.Expr], int]] = {
    "sqrt": (sympy.sqrt, 1),
    "sin": (sympy.sin, 1),
    "cos": (sympy.cos, 1),
    "tan": (sympy.tan, 1),
    "asin": (sympy.asin, 1),
    "acos": (sympy.acos, 1),
    "atan": (sympy.atan, 1),
    "atan2": (sympy.atan2, 2),
}
_CONSTANTS: dict[str, sympy.Expr] = {"pi": sympy.pi, "deg": _DEGREE}
_BINOPS: dict[type, Callable[[sympy.Expr, sympy.Expr], sympy.Expr]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.Pow: operator.pow,
}
_OPERATORS = {
    ast.FloorDiv: "//",
    ast.Mod: "%",
    ast.MatMult: "@",
    ast.BitAnd: "&",
    ast.BitOr: "|",
    ast.BitXor: "^",
    ast.LShift: "<<",
    ast.RShift: ">>",
    ast.Invert: "~",
    ast.Not: "not",
}
_FOUND = {
    ast.Attribute: "attribute access",
    ast.Subscript: "subscript",
    ast.Lambda: "lambda",
    ast.IfExp: "conditional expression",
    ast.Compare: "comparison",
    ast.BoolOp: "boolean operator",
    ast.List: "list",
    ast.Tuple: "tuple",
    ast.Set: "set",
    ast.Dict: "dict",
    ast.NamedExpr: "assignment",
    ast.JoinedStr: "f-string",
}
_DECIMAL_EXPONENT = re.compile(r"[eE]([-+]?\d+)$")
_NAME_TAIL = re.compile(r"[\w.]*$")


class ExpressionError(InputError):
    """User text that is not an allowed exact expression; the message says why.

    Examples
    --------
    >>> issubclass(ExpressionError, ValueError)
    True
    """


class ComplexExpressionError(ExpressionError, ComplexValueError):
    """Text whose value, or a step of it, is not a real number (``asin(2)``, ``sqrt(-1)``).

    Both an :class:`ExpressionError` and a :class:`~graspcompass.errors.ComplexValueError`.

    Examples
    --------
    >>> try:
    ...     parse_exact("1 + asin(2)")
    ... except ComplexExpressionError as err:
    ...     print(err)  # doctest: +ELLIPSIS
    cannot read '1 + asin(2)': asin(2) = 1.57 - 1.32*I is not a real number (asin needs ...)
    """


def _fail(text: str, why: str) -> ExpressionError:
    shown = text if len(text) <= MAX_LENGTH else text[: MAX_LENGTH // 4] + "..."
    return ExpressionError(f"cannot read {shown!r}: {why}")


def _refuse(text: str, found: str) -> ExpressionError:
    if found == "tuple":  # a comma between numbers: 0,5 written for 0.5
        return _fail(
            text, "a comma is not part of a number: the decimal separator is a point (0.5, not 0,5)"
        )
    return _fail(text, f"{_ALLOWED} (found {found})")


def _split_unit(text: str) -> tuple[str, bool]:
    """Strip a degree unit ``deg`` or ``°`` at the very end; say whether there was one."""
    body = text.rstrip()
    if body.endswith("°"):
        return body[:-1].rstrip(), True
    if not body.endswith("deg"):
        return body, False
    head = body[:-3]
    core = head.rstrip()
    if not core or core[-1] in "+-*/(,:":
        return body, False  # the name ``deg`` itself, as in "30*deg"
    tail = _NAME_TAIL.search(head).group()  # type: ignore[union-attr]
    if tail and not (tail[0].isdigit() or tail[0] == "."):
        return body, False  # the end of a longer name such as "pideg"
    return core, True


class _Reader:
    """Walk an :mod:`ast` tree with a whitelist, building sympy objects within the limits."""

    def __init__(
        self,
        source: str,
        text: str,
        symbols: Mapping[str, sympy.Expr] | None,
        inherited: Mapping[str, tuple[Condition, ...]] | None = None,
    ):
        self.source, self.text, self.symbols = source, text, dict(symbols or {})
        self.inherited = dict(inherited or {})  # a name's own conditions (a let value)
        self.conditions: dict[Condition, None] = {}  # collected as written, in order
        for name, value in self.symbols.items():
            if not isinstance(value, sympy.Expr):
                raise TypeError(f"symbol {name!r} must map to a sympy expression")
        self.depth = 0  # nested calls and powers now open
        self.work = 0  # bits that entered roots and functions so far

    def read(self, node: ast.AST) -> sympy.Expr:
        value = self._node(node)
        if value.is_Symbol or value is sympy.pi:
            return value  # a name or pi: nothing to bound
        infinite, bits, nodes = _scan(value)
        if infinite:
            raise _fail(self.text, "the value is not finite (division by zero?)")
        if bits > MAX_BITS:
            raise _fail(
                self.text,
                f"a number in the value has more than {MAX_BITS} bits "
                f"(about {_digits(MAX_BITS)} decimal digits)",
            )
        if nodes > MAX_NODES:
            raise _fail(
                self.text,
                f"the value grows beyond {MAX_NODES} nodes (sympy writes it "
                "out at length); simplify the text",
            )
        self._degree_at_most(_degree(value), value)
        return value

    def _degree_at_most(self, degree: int, value: sympy.Expr) -> None:
        """Refuse a value whose polynomial would be too large to compute with exactly:
        degree over :data:`MAX_DEGREE`, or more than :data:`MAX_TERMS` possible terms
        (``C(n + degree, n)`` in ``n`` names), known before anything is expanded."""
        if degree == 0 or (
            degree <= MAX_DEGREE and math.comb(len(self.symbols) + degree, degree) <= MAX_TERMS
        ):
            return  # within the budget whatever names the value uses
        names = sorted(map(str, value.free_symbols))
        shown = ", ".join(names)
        if degree > MAX_DEGREE:
            raise _fail(
                self.text,
                f"the value would have degree {degree} in {shown}, more "
                f"than {MAX_DEGREE} (too costly to compute exactly)",
            )
        terms = math.comb(len(names) + degree, degree)
        if terms > MAX_TERMS:
            raise _fail(
                self.text,
                f"the value would have degree {degree} in {len(names)} names "
                f"({shown}): up to {terms} terms, more than {MAX_TERMS} (too costly to "
                "compute exactly)",
            )

    def _divisor(self, value: sympy.Expr) -> None:
        """Refuse dividing by a number that is 0, also in disguise.

        ``sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6))`` is 0 although no finite evaluation
        shows it: where :func:`real_sign` cannot tell, the square roots are denested
        (:func:`sympy.sqrtdenest`) and the sign decided again.  A symbolic divisor
        becomes a condition instead (:meth:`_condition`).
        """
        if value.free_symbols or value.is_Rational:
            return  # a condition, or 1/0 (zoo, refused by read)
        sign = real_sign(value)
        if sign is None and not _has_function(value):
            sign = _algebraic_sign(value)
        if sign == 0:
            raise _fail(
                self.text,
                f"the value is not finite (division by {_short(value)}, which is exactly 0)",
            )
        if sign is None:
            self._sign(value, value)  # raises: cannot decide the sign

    def _node(self, node: ast.AST) -> sympy.Expr:
        if isinstance(node, ast.Constant):
            return self._constant(node)
        if isinstance(node, ast.Name):
            return self._name(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
            negative = False  # a chain such as ------1 is read in one step, not recursively
            while isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
                negative ^= isinstance(node.op, ast.USub)
                node = node.operand
            operand = self.read(node)
            return -operand if negative else operand
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            if isinstance(node.op, ast.Pow):
                return self._power(node)
            left, right = self.read(node.left), self.read(node.right)
            if isinstance(node.op, ast.Div):
                self._condition("!=", right)
                self._divisor(right)
            return _BINOPS[type(node.op)](left, right)
        if isinstance(node, ast.Call):
            return self._call(node)
        if isinstance(node, (ast.BinOp, ast.UnaryOp)):
            raise _refuse(self.text, f"operator {_OPERATORS.get(type(node.op), '?')}")
        raise _refuse(self.text, _FOUND.get(type(node), type(node).__name__))

    def _constant(self, node: ast.Constant) -> sympy.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            kind = {complex: "a complex number", str: "a string", bytes: "a string"}
            raise _refuse(self.text, kind.get(type(value), f"the constant {value!r}"))
        if isinstance(value, int):
            return sympy.Integer(value)
        literal = (ast.get_source_segment(self.source, node) or "").replace("_", "")
        exponent = _DECIMAL_EXPONENT.search(literal)
        if exponent and abs(int(exponent.group(1))) > _MAX_DECIMAL_EXPONENT:
            raise _fail(self.text, f"decimal exponents beyond {_MAX_DECIMAL_EXPONENT} are refused")
        exact = Fraction(literal)  # a Python float literal always reads
        return sympy.Rational(exact.numerator, exact.denominator)

    def _name(self, name: str) -> sympy.Expr:
        if name in _CONSTANTS:
            return _CONSTANTS[name]
        if name in self.symbols and not name.startswith("__"):
            self.conditions.update(dict.fromkeys(self.inherited.get(name, ())))
            return self.symbols[name]
        if name in _FUNCTIONS:
            raise _refuse(self.text, f"function {name!r} used without a call")
        raise _refuse(self.text, f"unknown name {name!r}")

    def _condition(self, relation: str, value: sympy.Expr) -> None:
        """Record that the text needs ``value relation 0`` (only symbolic values: a number
        is decided where it is read)."""
        if value.free_symbols:
            self.conditions[(relation, value)] = None

    def _enter(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise _fail(self.text, f"more than {MAX_DEPTH} nested function calls and powers")

    def _spend(self, value: sympy.Expr) -> None:
        self.work += _total_bits(value)
        if self.work > MAX_WORK_BITS:
            raise _fail(
                self.text,
                f"the numbers in its roots and functions add up to more than "
                f"{MAX_WORK_BITS} bits (too costly to compute exactly)",
            )

    def _call(self, node: ast.Call) -> sympy.Expr:
        if not isinstance(node.func, ast.Name):
            raise _refuse(self.text, "a call of something that is not a plain function name")
        name = node.func.id
        if name not in _FUNCTIONS:
            raise _refuse(self.text, f"unknown function {name!r}")
        if node.keywords:
            raise _refuse(self.text, "keyword arguments")
        if any(isinstance(arg, ast.Starred) for arg in node.args):
            raise _refuse(self.text, "starred arguments")
        function, arity = _FUNCTIONS[name]
        if len(node.args) != arity:
            plural = "s" if arity > 1 else ""
            raise _fail(self.text, f"{name} takes {arity} argument{plural}, got {len(node.args)}")
        self._enter()
        args = [self.read(arg) for arg in node.args]
        for arg in args:
            if name != "sqrt" and _max_bits(arg) > MAX_ARGUMENT_BITS:
                raise _fail(
                    self.text,
                    f"the argument of {name} holds a number of more than "
                    f"{MAX_ARGUMENT_BITS} bits (about {_digits(MAX_ARGUMENT_BITS)} "
                    "decimal digits)",
                )
            self._spend(arg)
        if name == "sqrt":
            self._real_root(args[0], sympy.Rational(1, 2))
            self._condition(">=", args[0])
        elif name in ("asin", "acos"):
            self._real_arcsine(name, args[0])
            self._condition(">=", 1 - args[0] ** 2)
        elif name == "tan":
            self._condition("!=", sympy.cos(args[0]))
        elif name == "atan2":
            self._condition("!=", args[0] ** 2 + args[1] ** 2)
        self.depth -= 1
        if name in _TRIG and _plain_real(args[0]):
            return function(args[0], evaluate=False)  # what sympy's eval leaves it as
        if not any(_has_function(arg) for arg in args):
            value = function(*args)
            if _too_many_nodes(value, _EXPANSION_NODES):  # tan(pi/120): 313 nodes of radicals
                return function(*args, evaluate=False)  # kept as the exact tan(pi/120)
            return value
        # sympy's own simplification of f(g(...)) queries the sign of g(...) again and again
        # (exponential in the depth): keep nested functions as they are, exact and unevaluated
        if name == "tan":
            self._sign(sympy.cos(args[0], evaluate=False), sympy.tan(args[0], evaluate=False))
        if name == "atan2" and not (self._nonzero(args[0]) or self._nonzero(args[1])):
            raise _fail(self.text, "atan2(0, 0) is not defined")
        return function(*args, evaluate=False)

    def _nonzero(self, value: sympy.Expr) -> bool:
        return bool(value.free_symbols) or self._sign(value, value) != 0

    def _sign(self, value: sympy.Expr, shown: sympy.Expr) -> int:
        sign = real_sign(value)
        if sign is None:
            where = "" if value == shown else f", needed for {_short(shown)}"
            raise _fail(
                self.text,
                f"cannot decide the sign of {_short(value)} exactly (it is "
                f"zero or too close to zero to tell{where})",
            )
        return sign

    def _complex(self, shown: sympy.Expr, approx: complex, why: str) -> None:
        sign = "-" if approx.imag < 0 else "+"
        value = f"{approx.real:.3g} {sign} {abs(approx.imag):.3g}*I"
        raise ComplexExpressionError(
            _fail(self.text, f"{_short(shown)} = {value} is not a real number ({why})").args[0]
        )

    def _real_arcsine(self, name: str, arg: sympy.Expr) -> None:
        """Refuse ``asin(x)``, ``acos(x)`` for ``|x| > 1``: their values are complex."""
        if arg.free_symbols or _clearly_inside_unit(arg):
            return
        if -1 in (self._sign(1 - arg, arg), self._sign(1 + arg, arg)):
            with mpmath.workdps(50):
                x = _mpf(arg)
                approx = complex(mpmath.asin(x) if name == "asin" else mpmath.acos(x))
            self._complex(
                _FUNCTIONS[name][0](arg, evaluate=False), approx, f"{name} needs -1 <= x <= 1"
            )

    def _real_root(self, base: sympy.Expr, exponent: sympy.Rational) -> None:
        """Refuse a negative base under a root: its principal value is complex."""
        if base.free_symbols or exponent.q == 1 or self._sign(base, base) >= 0:
            return
        approx = complex(mpmath.power(_mpf(base), mpmath.mpf(exponent.p) / exponent.q))
        hint = (
            "a root of a negative number is complex"
            if exponent.q % 2 == 0
            else "the principal root of a negative number is complex; write -(8**(1/3)) for "
            "the real cube root of -8"
        )
        self._complex(sympy.Pow(base, exponent, evaluate=False), approx, hint)

    def _power(self, node: ast.BinOp) -> sympy.Expr:
        self._enter()
        base, exponent = self.read(node.left), self.read(node.right)
        if not exponent.is_Rational:
            raise _fail(
                self.text,
                f"exponents must be rational numbers such as 2, -1 or 1/3 "
                f"(found {_short(exponent)})",
            )
        if abs(exponent.p) > MAX_EXPONENT or exponent.q > MAX_EXPONENT:
            raise _fail(
                self.text,
                f"exponents p/q with |p| or q larger than {MAX_EXPONENT} are "
                "refused (they could take forever to compute)",
            )
        self._degree_at_most(_degree(base) * abs(exponent.p), base)
        if _max_bits(base) * abs(exponent.p) > MAX_BITS:
            raise _fail(
                self.text, f"the power is too large to compute exactly (more than {MAX_BITS} bits)"
            )
        if exponent.q > 1:
            self._spend(base)  # an exact root may factor the integers of its base
            self._real_root(base, exponent)
            self._condition(">" if exponent < 0 else ">=", base)
        elif exponent < 0:
            self._condition("!=", base)
        if exponent < 0:
            self._divisor(base)
        self.depth -= 1
        if _has_function(base):  # as for functions: no sign queries through nested functions
            return sympy.Pow(base, exponent, evaluate=False)
        return base**exponent


ExpressionError.__module__ = ComplexExpressionError.__module__ = "graspcompass.expr"  # public path
