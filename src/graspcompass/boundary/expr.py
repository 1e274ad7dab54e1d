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
import keyword
import numbers
import re
import warnings
from collections.abc import Mapping

import sympy

from ._reader import (
    _CONSTANTS,
    _DEGREE,
    ComplexExpressionError,
    Condition,
    ExpressionError,
    _fail,
    _Reader,
    _split_unit,
    real_sign,
)
from ._reader_values import _SYMPY_FAILURES
from .errors import NotTextError
from .limits import (  # the limits, stated once
    MAX_ANGLES,
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
from .limits import MAX_LIST_LENGTH as _MAX_LIST_LENGTH

__all__ = [
    "MAX_ANGLES",
    "MAX_ARGUMENT_BITS",
    "MAX_BITS",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "MAX_NODES",
    "MAX_TERMS",
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

#: A small integer literal (no leading zeros, as Python reads them) or a bare name.
_PLAIN = re.compile(r"\s*(-?(?:0|[1-9][0-9]{0,8}))\s*|\s*([A-Za-z_][A-Za-z0-9_]*)\s*")


def _parse(
    text: str,
    symbols: Mapping[str, sympy.Expr] | None,
    inherited: Mapping[str, tuple[Condition, ...]] | None = None,
    out: list[Condition] | None = None,
) -> sympy.Expr:
    if not isinstance(text, str):
        raise NotTextError(f"expected a str, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise _fail(text, f"the text is longer than {MAX_LENGTH} characters")
    plain = _PLAIN.fullmatch(text)
    if plain is not None and all(isinstance(v, sympy.Expr) for v in (symbols or {}).values()):
        # a small integer or a declared name: what the reader makes of it, without it
        if plain.group(1) is not None:
            return sympy.Integer(int(plain.group(1)))
        name = plain.group(2)
        value = (symbols or {}).get(name)
        if (
            isinstance(value, sympy.Symbol)
            and name not in _CONSTANTS
            and not name.endswith("deg")
            and not name.startswith("__")
            and not keyword.iskeyword(name)
        ):
            if out is not None:
                out += [c for c in dict.fromkeys((inherited or {}).get(name, ())) if c not in out]
            return value
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


def parse_with_conditions(
    text: str,
    *,
    symbols: Mapping[str, sympy.Expr] | None = None,
    inherited: Mapping[str, tuple[Condition, ...]] | None = None,
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
