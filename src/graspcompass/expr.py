"""Safe, exact parsing of user text into sympy expressions.

Text from the command line or from string parameters of the grasp model is
parsed with :mod:`ast` and walked with a strict whitelist; Python never
evaluates it (no ``eval``, ``sympify`` or ``parse_expr``).  Decimal literals are
read exactly (``"1.2"`` is ``6/5``) and a trailing ``deg`` or ``°`` turns
degrees into radians (``"60deg"`` is ``pi/3``).
"""

from __future__ import annotations

import ast
import numbers
import operator
import re
from collections.abc import Callable, Mapping
from fractions import Fraction

import sympy

from .errors import InputError

__all__ = ["MAX_ANGLES", "MAX_EXPONENT", "MAX_LENGTH", "ExpressionError", "parse_angles",
           "parse_exact", "to_exact"]

#: Longest text :func:`parse_exact` reads.
MAX_LENGTH = 200
#: Largest absolute value of a numeric exponent (``10**10**10`` is refused).
MAX_EXPONENT = 64
#: Most angles :func:`parse_angles` returns.
MAX_ANGLES = 1_000_000

_MAX_LIST_LENGTH = 10 * MAX_LENGTH  # longest text parse_angles reads
_MAX_BITS = 1 << 13  # bound on the bits of the integers in a result (about 2466 digits)
_MAX_DECIMAL_EXPONENT = 1000  # bound on n in a literal such as 1e-n
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


def _fail(text: str, why: str) -> ExpressionError:
    shown = text if len(text) <= MAX_LENGTH else text[: MAX_LENGTH // 4] + "..."
    return ExpressionError(f"cannot read {shown!r}: {why}")


def _refuse(text: str, found: str) -> ExpressionError:
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
    """Walk an :mod:`ast` tree with a whitelist, building sympy objects."""

    def __init__(self, source: str, text: str, symbols: Mapping[str, sympy.Expr] | None):
        self.source, self.text, self.symbols = source, text, dict(symbols or {})
        for name, value in self.symbols.items():
            if not isinstance(value, sympy.Expr):
                raise TypeError(f"symbol {name!r} must map to a sympy expression")

    def read(self, node: ast.AST) -> sympy.Expr:
        value = self._node(node)
        if value.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
            raise _fail(self.text, "the value is not finite (division by zero?)")
        return value

    def _node(self, node: ast.AST) -> sympy.Expr:
        if isinstance(node, ast.Constant):
            return self._constant(node)
        if isinstance(node, ast.Name):
            return self._name(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
            operand = self.read(node.operand)
            return -operand if isinstance(node.op, ast.USub) else operand
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            left, right = self.read(node.left), self.read(node.right)
            if isinstance(node.op, ast.Pow):
                self._check_power(left, right)
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
            return self.symbols[name]
        if name in _FUNCTIONS:
            raise _refuse(self.text, f"function {name!r} used without a call")
        raise _refuse(self.text, f"unknown name {name!r}")

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
        return function(*(self.read(arg) for arg in node.args))

    def _check_power(self, base: sympy.Expr, exponent: sympy.Expr) -> None:
        if not exponent.is_number:
            return
        magnitude = sympy.Abs(exponent).evalf()
        if not magnitude.is_Number or float(magnitude) > MAX_EXPONENT:
            raise _fail(self.text, f"exponents larger than {MAX_EXPONENT} in absolute value are "
                        "refused (they could take forever to compute)")
        if base.is_number and _bits(base) * float(magnitude) > _MAX_BITS:
            raise _fail(self.text, "the power is too large to compute exactly")


def _bits(value: sympy.Expr) -> int:
    """Bits in all the integers of ``value``: a bound on the cost of powers of it."""
    return sum(int(r.p).bit_length() + int(r.q).bit_length() for r in value.atoms(sympy.Rational))


def _parse(text: str, symbols: Mapping[str, sympy.Expr] | None) -> sympy.Expr:
    if not isinstance(text, str):
        raise TypeError(f"expected a str, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise _fail(text, f"the text is longer than {MAX_LENGTH} characters")
    body, degrees = _split_unit(text)
    source = body.strip()
    if not source:
        raise _fail(text, "there is no number before the unit" if degrees else "the text is empty")
    reader = _Reader(source, text, symbols)
    try:
        tree = ast.parse(source, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise _fail(text, "incomplete or malformed expression") from None
    try:
        value = reader.read(tree.body)
    except ExpressionError:
        raise
    except (ValueError, TypeError, ArithmeticError, RecursionError):
        raise _fail(text, "the value cannot be computed exactly") from None
    if _bits(value) > _MAX_BITS:
        raise _fail(text, f"the numbers in the result have more than {_MAX_BITS} bits")
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
        raise TypeError(f"expected a str, got {type(text).__name__}")
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
