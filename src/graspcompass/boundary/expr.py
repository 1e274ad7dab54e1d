"""Safe, exact parsing of user text into sympy expressions.

Text from the command line or from string parameters of the grasp model is
parsed with :mod:`ast` and walked with a strict whitelist; Python never
evaluates it (no ``eval``, ``sympify`` or ``parse_expr``).  Decimal literals are
read exactly (``"1.2"`` is ``6/5``) and a trailing ``deg`` or ``°`` turns
degrees into radians (``"60deg"`` is ``pi/3``).

Every text is bounded before sympy sees it, so that no text takes more than a
fraction of a second to read or refuse (``docs/security.md``):

* at most :data:`MAX_LENGTH` characters and :data:`MAX_DEPTH` nested calls and powers;
* exponents are rational numbers ``p/q`` with ``|p|, q <=`` :data:`MAX_EXPONENT`
  (``2**pi`` is refused: deciding its size needs numerical evaluation);
* no integer (numerator or denominator) in a value or an intermediate result has
  more than :data:`MAX_BITS` bits (``1e309`` still reads exactly, ``1e400`` does not),
  and the arguments of ``sin cos tan asin acos atan atan2`` hold integers of at
  most :data:`MAX_ARGUMENT_BITS` bits (``sin(10**60)`` is refused);
* the numbers that enter roots and functions add up to at most
  :data:`MAX_WORK_BITS` bits (a bound on the work of exact roots), and no value
  or intermediate result has more than :data:`MAX_NODES` nodes;
* every step is a real number: ``sqrt(-1)``, ``asin(2)`` and ``(-8)**(1/3)``
  (a principal root) are refused with :class:`ComplexExpressionError`, and so is
  a sign that cannot be decided (``sqrt(sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6)))``).

Every refusal is an :class:`ExpressionError` naming the text and the limit.
"""

from __future__ import annotations

import ast
import numbers
import operator
import re
import warnings
from collections.abc import Callable, Mapping
from fractions import Fraction

import mpmath
import sympy
from sympy.core.evalf import evalf as _evalf

from .errors import ComplexValueError, InputError, NotTextError
from .limits import (  # the limits, stated once
    MAX_ANGLES,
    MAX_ARGUMENT_BITS,
    MAX_BITS,
    MAX_DEPTH,
    MAX_EXPONENT,
    MAX_LENGTH,
    MAX_NODES,
    MAX_WORK_BITS,
)
from .limits import MAX_LIST_LENGTH as _MAX_LIST_LENGTH

__all__ = [
    "MAX_ANGLES",
    "MAX_ARGUMENT_BITS",
    "MAX_BITS",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "MAX_NODES",
    "MAX_WORK_BITS",
    "ComplexExpressionError",
    "Condition",
    "ExpressionError",
    "parse_angles",
    "parse_exact",
    "parse_with_conditions",
    "real_sign",
    "to_exact",
    "tree_conditions",
]

#: A condition under which a value is defined, as written: ``(relation, expr)`` with
#: relation ``"!="`` (a divisor, ``expr ≠ 0``), ``">="`` (a radicand, ``expr ≥ 0``) or
#: ``">"`` (a radicand under a negative power).  Kept before sympy evaluates the text, so
#: ``x/x`` keeps ``x ≠ 0`` although its value is 1.
Condition = tuple[str, sympy.Expr]

#: A function value sympy writes out in more nodes stays unevaluated (sin(pi/5) is written
#: out in radicals, 12 nodes; tan(pi/120), 313 nodes, stays tan(pi/120)).
_EXPANSION_NODES = 40
_MAX_DECIMAL_EXPONENT = 400  # bound on n in a literal such as 1e-n (checked before reading it)
#: What sympy may raise on a value it cannot handle; ``AttributeError`` is sympy's cache
#: wrapper failing on a lazy "cannot determine truth value" message (sympy 1.12-1.14).
_SYMPY_FAILURES = (ValueError, TypeError, ArithmeticError, AttributeError, RecursionError,
                   MemoryError, IndexError, KeyError, NotImplementedError)
_DEGREE = sympy.pi / 180
_ALLOWED = (
    "only numbers, + - * / **, pi, deg, sqrt, sin, cos, tan, asin, acos, atan, atan2"
    " and parentheses are allowed"
)
_FUNCTIONS: dict[str, tuple[Callable[..., sympy.Expr], int]] = {
    "sqrt": (sympy.sqrt, 1), "sin": (sympy.sin, 1), "cos": (sympy.cos, 1), "tan": (sympy.tan, 1),
    "asin": (sympy.asin, 1), "acos": (sympy.acos, 1), "atan": (sympy.atan, 1),
    "atan2": (sympy.atan2, 2),
}
_CONSTANTS: dict[str, sympy.Expr] = {"pi": sympy.pi, "deg": _DEGREE}
_BINOPS: dict[type, Callable[[sympy.Expr, sympy.Expr], sympy.Expr]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.Pow: operator.pow,
}
_OPERATORS = {ast.FloorDiv: "//", ast.Mod: "%", ast.MatMult: "@", ast.BitAnd: "&",
              ast.BitOr: "|", ast.BitXor: "^", ast.LShift: "<<", ast.RShift: ">>",
              ast.Invert: "~", ast.Not: "not"}
_FOUND = {ast.Attribute: "attribute access", ast.Subscript: "subscript", ast.Lambda: "lambda",
          ast.IfExp: "conditional expression", ast.Compare: "comparison",
          ast.BoolOp: "boolean operator", ast.List: "list", ast.Tuple: "tuple", ast.Set: "set",
          ast.Dict: "dict", ast.NamedExpr: "assignment", ast.JoinedStr: "f-string"}
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


def real_sign(value: sympy.Expr) -> int | None:
    """The sign (-1, 0 or 1) of a real number given exactly, or None if it cannot be decided.

    Rationals are decided exactly; other numbers by a numerical evaluation whose
    accuracy is known (up to about 600 bits), so a decided sign is always right.
    A number that is zero without being written as zero (``sqrt(2) + sqrt(3) -
    sqrt(5 + 2*sqrt(6))``) and numbers closer to zero than the evaluation sees
    give None.

    Examples
    --------
    >>> real_sign(sympy.Rational(-1, 3)), real_sign(sympy.pi - 3), real_sign(sympy.Integer(0))
    (-1, 1, 0)
    >>> print(real_sign(sympy.sqrt(2) + sympy.sqrt(3) - sympy.sqrt(5 + 2 * sympy.sqrt(6))))
    None
    """
    if value.is_Rational:
        return (value.p > 0) - (value.p < 0)  # type: ignore[attr-defined]
    if value == 0:
        return 0
    for bits in (64, 256, 640):
        try:
            re, im, re_acc, _ = _evalf(value, bits, {"maxprec": 2 * bits})
        except _SYMPY_FAILURES:
            return None
        if im or re is None:
            return None
        if re_acc is not None and re_acc >= 16 and re[1]:  # 16 correct bits of a nonzero value
            return -1 if re[0] else 1
    return None


def _fail(text: str, why: str) -> ExpressionError:
    shown = text if len(text) <= MAX_LENGTH else text[: MAX_LENGTH // 4] + "..."
    return ExpressionError(f"cannot read {shown!r}: {why}")


def _refuse(text: str, found: str) -> ExpressionError:
    if found == "tuple":  # a comma between numbers: 0,5 written for 0.5
        return _fail(text, "a comma is not part of a number: the decimal separator is a point "
                           "(0.5, not 0,5)")
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

    def __init__(self, source: str, text: str, symbols: Mapping[str, sympy.Expr] | None,
                 inherited: Mapping[str, tuple[Condition, ...]] | None = None):
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
        if value.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
            raise _fail(self.text, "the value is not finite (division by zero?)")
        if _max_bits(value) > MAX_BITS:
            raise _fail(self.text, f"a number in the value has more than {MAX_BITS} bits "
                        f"(about {_digits(MAX_BITS)} decimal digits)")
        if _too_many_nodes(value):
            raise _fail(self.text, f"the value grows beyond {MAX_NODES} nodes (sympy writes it "
                        "out at length); simplify the text")
        return value

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
            if isinstance(node.op, ast.Div) and _has_function(right) and not self._nonzero(right):
                raise _fail(self.text, "the value is not finite (division by zero)")
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
            raise _fail(self.text, f"the numbers in its roots and functions add up to more than "
                        f"{MAX_WORK_BITS} bits (too costly to compute exactly)")

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
                raise _fail(self.text, f"the argument of {name} holds a number of more than "
                            f"{MAX_ARGUMENT_BITS} bits (about {_digits(MAX_ARGUMENT_BITS)} "
                            "decimal digits)")
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
            raise _fail(self.text, f"cannot decide the sign of {_short(value)} exactly (it is "
                        f"zero or too close to zero to tell{where})")
        return sign

    def _complex(self, shown: sympy.Expr, approx: complex, why: str) -> None:
        sign = "-" if approx.imag < 0 else "+"
        value = f"{approx.real:.3g} {sign} {abs(approx.imag):.3g}*I"
        raise ComplexExpressionError(
            _fail(self.text, f"{_short(shown)} = {value} is not a real number ({why})").args[0])

    def _real_arcsine(self, name: str, arg: sympy.Expr) -> None:
        """Refuse ``asin(x)``, ``acos(x)`` for ``|x| > 1``: their values are complex."""
        if arg.free_symbols or _clearly_inside_unit(arg):
            return
        if -1 in (self._sign(1 - arg, arg), self._sign(1 + arg, arg)):
            with mpmath.workdps(50):
                x = _mpf(arg)
                approx = complex(mpmath.asin(x) if name == "asin" else mpmath.acos(x))
            self._complex(_FUNCTIONS[name][0](arg, evaluate=False), approx,
                          f"{name} needs -1 <= x <= 1")

    def _real_root(self, base: sympy.Expr, exponent: sympy.Rational) -> None:
        """Refuse a negative base under a root: its principal value is complex."""
        if base.free_symbols or exponent.q == 1 or self._sign(base, base) >= 0:
            return
        approx = complex(mpmath.power(_mpf(base), mpmath.mpf(exponent.p) / exponent.q))
        hint = ("a root of a negative number is complex" if exponent.q % 2 == 0 else
                "the principal root of a negative number is complex; write -(8**(1/3)) for "
                "the real cube root of -8")
        self._complex(sympy.Pow(base, exponent, evaluate=False), approx, hint)

    def _power(self, node: ast.BinOp) -> sympy.Expr:
        self._enter()
        base, exponent = self.read(node.left), self.read(node.right)
        if not exponent.is_Rational:
            raise _fail(self.text, f"exponents must be rational numbers such as 2, -1 or 1/3 "
                        f"(found {_short(exponent)})")
        if abs(exponent.p) > MAX_EXPONENT or exponent.q > MAX_EXPONENT:
            raise _fail(self.text, f"exponents p/q with |p| or q larger than {MAX_EXPONENT} are "
                        "refused (they could take forever to compute)")
        if _max_bits(base) * abs(exponent.p) > MAX_BITS:
            raise _fail(self.text, "the power is too large to compute exactly (more than "
                        f"{MAX_BITS} bits)")
        if exponent.q > 1:
            self._spend(base)  # an exact root may factor the integers of its base
            self._real_root(base, exponent)
            self._condition(">" if exponent < 0 else ">=", base)
        elif exponent < 0:
            self._condition("!=", base)
        self.depth -= 1
        if _has_function(base):  # as for functions: no sign queries through nested functions
            if exponent < 0 and not self._nonzero(base):
                raise _fail(self.text, "the value is not finite (division by zero)")
            return sympy.Pow(base, exponent, evaluate=False)
        return base**exponent


def _mpf(value: sympy.Expr) -> mpmath.mpf:
    """A real number (decided sign, bounded size) as an mpmath float, for messages."""
    return mpmath.mpf(sympy.Float(value.evalf(50))._mpf_)


def _short(value: sympy.Expr) -> str:
    shown = str(value)
    return shown if len(shown) <= 40 else shown[:37] + "..."


def _digits(bits: int) -> int:
    return int(bits * 0.30103)


def _clearly_inside_unit(value: sympy.Expr) -> bool:
    """``|value| < 1 - 2**-32`` by one evaluation of known accuracy (else: decide exactly)."""
    if value.is_Rational:
        return abs(value.p) < value.q  # type: ignore[attr-defined]
    try:
        re, im, re_acc, _ = _evalf(value, 64, {"maxprec": 128})
    except _SYMPY_FAILURES:
        return False
    if im or re is None:
        return re is None and im is None  # exactly zero
    return bool(re_acc is not None and re_acc >= 40 and mpmath.mpf(re) ** 2 < 1 - 2.0**-31)


def _has_function(value: sympy.Expr) -> bool:
    return bool(value.atoms(sympy.Function))


def _too_many_nodes(value: sympy.Expr, most: int = MAX_NODES) -> bool:
    for count, _ in enumerate(sympy.preorder_traversal(value), 1):
        if count > most:
            return True
    return False


def _max_bits(value: sympy.Expr) -> int:
    """Most bits of a numerator or a denominator in ``value``."""
    if isinstance(value, sympy.Rational):
        return max(int(value.p).bit_length(), int(value.q).bit_length())
    return max((_max_bits(r) for r in value.atoms(sympy.Rational)), default=0)


def _total_bits(value: sympy.Expr) -> int:
    """Bits of all the integers in ``value``: a bound on the work of a root of it."""
    return sum(int(r.p).bit_length() + int(r.q).bit_length() for r in value.atoms(sympy.Rational))


def _parse(text: str, symbols: Mapping[str, sympy.Expr] | None,
           inherited: Mapping[str, tuple[Condition, ...]] | None = None,
           out: list[Condition] | None = None) -> sympy.Expr:
    if not isinstance(text, str):
        raise NotTextError(f"expected a str, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise _fail(text, f"the text is longer than {MAX_LENGTH} characters")
    body, degrees = _split_unit(text)
    source = body.strip()
    if not source:
        raise _fail(text, "there is no number before the unit" if degrees else "the text is empty")
    reader = _Reader(source, text, symbols, inherited)
    try:
        with warnings.catch_warnings():  # "1if 1else 2" warns about its literals: refuse quietly
            warnings.simplefilter("ignore")
            tree = ast.parse(source, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise _fail(text, "incomplete or malformed expression") from None
    try:
        value = reader.read(tree.body)
    except ExpressionError:
        raise
    except RecursionError:
        raise _fail(text, "the expression is nested too deeply") from None
    except _SYMPY_FAILURES:
        raise _fail(text, "the value cannot be computed exactly") from None
    if out is not None:
        out += [c for c in reader.conditions if c not in out]
    return value * _DEGREE if degrees else value


def parse_exact(text: str, *, symbols: Mapping[str, sympy.Symbol] | None = None) -> sympy.Expr:
    """Read ``text`` as an exact sympy expression, refusing anything not whitelisted.

    Parameters
    ----------
    text : str
        Numbers (decimals are exact), ``+ - * / **``, parentheses, ``pi``, ``deg``
        (``pi/180``), ``sqrt sin cos tan asin acos atan atan2``; a trailing
        ``deg`` or ``°`` multiplies the whole value by ``pi/180``.
    symbols : Mapping[str, sympy.Symbol], optional
        Extra names allowed in ``text``, such as ``{"theta": Symbol("theta")}``.

    Returns
    -------
    sympy.Expr
        The exact, finite value.

    Raises
    ------
    ExpressionError
        If ``text`` is empty, malformed, too long, not finite or uses anything else.

    Examples
    --------
    >>> parse_exact("1.2"), parse_exact("sqrt(3)/2"), parse_exact("60deg")
    (6/5, sqrt(3)/2, pi/3)
    >>> parse_exact("2*theta + 30*deg", symbols={"theta": sympy.Symbol("theta")})
    2*theta + pi/6
    >>> try:
    ...     parse_exact("__import__('os')")
    ... except ExpressionError as err:
    ...     print(err)  # doctest: +ELLIPSIS
    cannot read "__import__('os')": only numbers, ... (found unknown function '__import__')
    """
    return _parse(text, symbols)


def parse_with_conditions(text: str, *, symbols: Mapping[str, sympy.Expr] | None = None,
                          inherited: Mapping[str, tuple[Condition, ...]] | None = None
                          ) -> tuple[sympy.Expr, tuple[Condition, ...]]:
    """:func:`parse_exact`, and the conditions under which the text is defined as written.

    sympy evaluates ``x*(x - y)/(x - y)`` to ``x`` and ``z/z`` to ``1`` as it builds the
    value; the conditions are collected from the syntax tree before that, so nothing a
    user divides by or takes the root of is lost: every divisor (``!=``: ≠ 0), every
    radicand (``>=``: ≥ 0; ``>`` under a negative power), ``1 − x²`` under ``asin`` and
    ``acos``, ``cos a`` under ``tan a``, ``x² + y²`` under ``atan2(y, x)``.  Only symbolic
    conditions are listed: a number is decided where it is read (``1/0`` and ``sqrt(-1)``
    are refused).

    Parameters
    ----------
    text : str
        As for :func:`parse_exact`.
    symbols : Mapping[str, sympy.Expr], optional
        Names allowed in ``text``.
    inherited : Mapping[str, tuple of Condition], optional
        The conditions of a named value (a ``let``), added where the name is used.

    Returns
    -------
    (sympy.Expr, tuple of Condition)
        The value and its conditions ``(relation, expr)``, in the order written.

    Examples
    --------
    >>> x, y = sympy.symbols("x y", positive=True)
    >>> parse_with_conditions("x*(x - y)/(x - y)", symbols={"x": x, "y": y})
    (x, (('!=', x - y),))
    >>> parse_with_conditions("sqrt(-x)", symbols={"x": x})[1]
    (('>=', -x),)
    """
    out: list[Condition] = []
    value = _parse(text, symbols, inherited, out)
    return value, tuple(out)


def tree_conditions(value: sympy.Expr) -> tuple[Condition, ...]:
    """The conditions visible in an expression tree already built (a value given as a
    sympy expression, not as text): negative powers, roots, ``tan``, ``asin``/``acos``,
    ``atan2`` and ``log`` of symbolic arguments.  What sympy has cancelled is gone: give
    text to :func:`parse_with_conditions` to keep it.

    Examples
    --------
    >>> x = sympy.Symbol("x", positive=True)
    >>> tree_conditions(1/(x - 1) + sympy.sqrt(2 - x))
    (('!=', x - 1), ('>=', 2 - x))
    """
    out: dict[Condition, None] = {}
    for node in sympy.preorder_traversal(value):
        if not getattr(node, "free_symbols", None):
            continue
        if node.is_Pow and node.exp.is_Rational and node.base.free_symbols:
            if node.exp.q > 1:
                out[(">" if node.exp < 0 else ">=", node.base)] = None
            elif node.exp < 0:
                out[("!=", node.base)] = None
        elif isinstance(node, sympy.tan):
            out[("!=", sympy.cos(node.args[0]))] = None
        elif isinstance(node, (sympy.asin, sympy.acos)):
            out[(">=", 1 - node.args[0] ** 2)] = None
        elif isinstance(node, sympy.atan2):
            out[("!=", node.args[0] ** 2 + node.args[1] ** 2)] = None
        elif isinstance(node, sympy.log):
            out[(">", node.args[0])] = None
    return tuple(out)


def to_exact(value: object) -> sympy.Expr:
    """Convert an int, Fraction, str or sympy expression to an exact sympy expression.

    Floats and bools are refused with :class:`ExpressionError` (a float is
    already rounded: pass a string such as ``"1.2"`` instead); other types
    raise :class:`TypeError`.  Sympy expressions are returned unchanged.

    Examples
    --------
    >>> from fractions import Fraction
    >>> to_exact(3), to_exact(Fraction(1, 3)), to_exact("0.5"), to_exact(sympy.pi)
    (3, 1/3, 1/2, pi)
    >>> try:
    ...     to_exact(1.2)
    ... except ExpressionError as err:
    ...     print(err)
    the float 1.2 is not exact: pass the string '1.2' instead
    """
    if isinstance(value, sympy.Expr):
        return value
    if isinstance(value, bool):
        raise ExpressionError(f"cannot use the bool {value!r} as a number")
    if isinstance(value, numbers.Integral):
        return sympy.Integer(int(value))
    if isinstance(value, numbers.Rational):
        return sympy.Rational(int(value.numerator), int(value.denominator))
    if isinstance(value, float):
        hint = f"pass the string '{value!r}' instead"
        raise ExpressionError(f"the float {value!r} is not exact: {hint}")
    if isinstance(value, str):
        return parse_exact(value)
    raise TypeError(f"cannot convert {type(value).__name__} to an exact sympy expression")


def _split_items(text: str) -> list[str]:
    """Split at commas outside parentheses (``atan2(1, 2)`` stays whole)."""
    items, depth, start = [], 0, 0
    for index, char in enumerate(text):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if char == "," and depth == 0:
            items.append(text[start:index])
            start = index + 1
    return [*items, text[start:]]


def _angle_range(item: str, budget: int) -> list[sympy.Expr]:
    body, degrees = _split_unit(item)
    parts = body.split(":")
    if len(parts) != 3 or not all(part.strip() for part in parts):
        raise _fail(item, "write a range as start:stop:step, e.g. '0:360:5deg' or '0:pi:pi/4'")
    if any(_split_unit(part)[1] for part in parts):
        raise _fail(item, "write the unit once, at the end of the range, e.g. '0:360:5deg'")
    start, stop, step = (parse_exact(part) for part in parts)
    if not all(v.is_number and v.is_extended_real for v in (start, stop, step)):
        raise _fail(item, "start, stop and step must be real numbers")
    if (step > 0) is not sympy.true:
        raise _fail(item, "the step must be positive")
    count = sympy.ceiling((stop - start) / step)
    if not count.is_Integer:
        raise _fail(item, "cannot count the values of this range exactly")
    if count <= 0:
        raise _fail(item, "the range is empty (stop is exclusive)")
    if count > budget:
        raise _fail(item, f"the range has {count} values; at most {MAX_ANGLES} angles are allowed")
    scale = _DEGREE if degrees else sympy.Integer(1)
    return [(start + i * step) * scale for i in range(int(count))]


def parse_angles(text: str) -> list[sympy.Expr]:
    """Read a comma-separated list of exact angles in radians.

    Each item is an angle (radians, or degrees with a ``deg``/``°`` suffix) or a
    range ``start:stop:step`` whose suffix applies to the whole item; ``stop``
    is exclusive, as in :func:`range`, and ``step`` must be positive.

    Examples
    --------
    >>> parse_angles("0:360:90deg")
    [0, pi/2, pi, 3*pi/2]
    >>> parse_angles("0:pi:pi/4, 30deg, atan2(1, 1)")
    [0, pi/4, pi/2, 3*pi/4, pi/6, pi/4]
    """
    if not isinstance(text, str):
        raise NotTextError(f"expected a str, got {type(text).__name__}")
    if len(text) > _MAX_LIST_LENGTH:
        raise _fail(text, f"the list is longer than {_MAX_LIST_LENGTH} characters")
    if not text.strip():
        raise _fail(text, "the list of angles is empty")
    angles: list[sympy.Expr] = []
    for item in _split_items(text):
        if not item.strip():
            raise _fail(text, "an item of the list of angles is empty")
        if ":" in item:
            angles.extend(_angle_range(item, MAX_ANGLES - len(angles)))
        else:
            angles.append(parse_exact(item))
        if len(angles) > MAX_ANGLES:
            raise _fail(text, f"more than {MAX_ANGLES} angles")
    return angles


ExpressionError.__module__ = ComplexExpressionError.__module__ = "graspcompass.expr"  # public path
