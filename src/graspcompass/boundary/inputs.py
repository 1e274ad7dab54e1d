"""The one boundary where values from outside enter graspcompass.

Every public function that takes a number, an angle, a force, an array or a
mapping of symbol values from its caller passes it through this module first;
the code behind it trusts what it gets.  What is accepted:

* **text** is read by the safe parser :func:`graspcompass.expr.parse_exact`
  (a whitelist walk of :mod:`ast`; never ``eval``, ``sympify`` or
  ``parse_expr``), exactly (``"1.2"`` is 6/5, ``"108deg"`` is 3π/5), within the
  parser's limits (``docs/security.md``);
* ``int``, :class:`fractions.Fraction`, :class:`decimal.Decimal` and numpy
  integers become exact sympy numbers; ``float`` and numpy floats stay floats
  (they select the numeric path) and must be finite;
* sympy expressions are taken as they are (they are Python objects built by
  code, which is trusted), but must be finite and must not be known to be
  complex; symbols are allowed (the symbolic path);
* float arrays (or lists of floats) are accepted where the API is vectorised,
  up to :data:`MAX_ARRAY_SIZE` entries.

**nan and infinities are refused everywhere**: a scalar ``nan`` and an array
holding a ``nan`` both raise :class:`~graspcompass.errors.NonFiniteValueError`
(naming the first bad index), so the scalar and the vectorised path agree and
no number is ever computed from a value that is not one.

Everything else is refused with a named :class:`~graspcompass.errors.InputError`
whose message starts with the parameter's name and says what is wrong with the
value: :class:`~graspcompass.errors.WrongTypeError` (``None``, ``True``, a dict,
a list where one number is needed, text in an array),
:class:`~graspcompass.errors.ComplexValueError` (``1j``, ``sympy.I``,
``'asin(2)'``), :class:`~graspcompass.errors.NonFiniteValueError` (``nan``,
``inf``, ``oo``, ``zoo``), :class:`~graspcompass.errors.InputTooLargeError`
(arrays beyond :data:`MAX_ARRAY_SIZE`) and
:class:`~graspcompass.expr.ExpressionError` (text the parser refuses).

Behind this boundary, ``sympy.sympify`` may only be applied to sympy objects
the package built itself, never to text or other values from outside (``sympify``
parses strings with ``eval``, also inside lists and numpy arrays).  This module
imports nothing from the package but :mod:`graspcompass.expr` and
:mod:`graspcompass.errors`, so the geometry kernel can use it too.

Examples
--------
>>> from graspcompass.errors import ComplexValueError, NonFiniteValueError
>>> real_value("1.2", "x1"), real_value("108deg", "phi1"), real_value(3, "y")
(6/5, 3*pi/5, 3)
>>> try:
...     real_value("asin(2)", "mu1")
... except ComplexValueError as err:
...     print(err)  # doctest: +ELLIPSIS
mu1: cannot read 'asin(2)': asin(2) = 1.57 - 1.32*I is not a real number (...)
>>> try:
...     angle_values(float("nan"))
... except NonFiniteValueError as err:
...     print(err)
theta: expected a finite number, got nan
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable, Mapping
from decimal import Decimal
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import sympy as sp

from ._kinds import _kind, _nested_size
from ._numpy import is_a
from .errors import (
    ComplexValueError,
    InputError,
    InputTooLargeError,
    NonFiniteValueError,
    WrongTypeError,
)
from .expr import ExpressionError, parse_exact, real_sign
from .limits import MAX_INT_BITS

if TYPE_CHECKING:
    import numpy as np
else:
    from ._numpy import np

__all__ = [
    "MAX_ARRAY_SIZE",
    "MAX_SUBSTITUTIONS",
    "angle_values",
    "exact_denominators",
    "exact_sign",
    "float_array",
    "float_value",
    "force_value",
    "real_value",
    "substitutions",
]

#: Most entries of an array of angles (or of values broadcast with them) in one call:
#: ten million doubles, 80 MB (``k`` returns four times as much).
MAX_ARRAY_SIZE = 10_000_000
#: Most entries of a mapping of symbol values (:meth:`Grasp.subs <graspcompass.Grasp.subs>`).
MAX_SUBSTITUTIONS = 64

_NOT_FINITE = (sp.nan, sp.zoo, sp.oo, sp.S.NegativeInfinity)


def _shown(value: object) -> str:
    """A short ``repr`` of an outside value for a message (never the whole of a big one)."""
    try:
        text = repr(value)
    except Exception:  # a hostile __repr__ must not hide the real error
        text = f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _renamed(exc: InputError, name: str) -> InputError:
    """The same error, its message prefixed with the parameter's name."""
    return type(exc)(f"{name}: {exc}")


def _complex(name: str, value: object, approx: object = None) -> ComplexValueError:
    shown = _shown(value) if approx is None else f"{_shown(value)} = {approx}"
    return ComplexValueError(f"{name}: expected a real number, got {shown} (complex)")


def exact_denominators(value: sp.Expr, name: str) -> sp.Expr:
    """``value``, refused if one of its denominators is exactly zero in disguise.

    The parser refuses ``1/0``; ``1/(sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6)))`` divides by
    a number that only the kernel's exact zero test
    (:func:`graspcompass.geometry.exact.decide_zero`, after denesting the square roots,
    :func:`sympy.sqrtdenest`) shows to be 0.  Every power with a negative exponent whose
    base is a number is tested; a base that cannot be decided is refused too (a value the
    kernel could not divide by safely).

    Raises
    ------
    NonFiniteValueError
        The value divides by an exact zero, or by a number not shown to be nonzero.
    """
    if value.is_Atom or value.free_symbols:
        return value
    from ..geometry.exact import canon, decide_zero, has_float

    for node in sp.preorder_traversal(value):
        if not (node.is_Pow and node.exp.is_negative) or node.base.is_Atom or has_float(node.base):
            continue
        zero = decide_zero(node.base)
        if zero is None:
            zero = decide_zero(canon(sp.sqrtdenest(node.base)))
        if zero is not False:
            what = "which is exactly 0" if zero else "which cannot be shown to be nonzero"
            raise NonFiniteValueError(f"{name}: the value divides by {_shown(node.base)}, {what}")
    return value


def exact_sign(value: sp.Expr) -> int | None:
    """The sign of a number, by the kernel's :func:`~graspcompass.geometry.exact.decide_sign`.

    Its square roots are denested when that does not settle it: a zero in disguise such as
    ``sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6))`` is 0, not the sign of rounding noise.
    """
    from ..geometry.exact import canon, decide_sign

    sign = decide_sign(value)
    if sign is None or (sign != 0 and real_sign(value) is None):
        denested = decide_sign(canon(sp.sqrtdenest(value)))
        sign = denested if denested is not None else sign
    return sign


def _int_bits(name: str, *ints: int) -> None:
    """Refuse integers of more than :data:`~graspcompass.boundary.limits.MAX_INT_BITS` bits."""
    for i in ints:
        if i.bit_length() > MAX_INT_BITS:
            raise InputTooLargeError(
                f"{name}: a number of {i.bit_length()} bits; at most "
                f"{MAX_INT_BITS} bits (about {MAX_INT_BITS * 3 // 10} "
                "decimal digits) are allowed"
            )


def _sympy_value(value: sp.Basic, name: str, shown: object) -> sp.Expr:
    """Check a sympy object: an expression, finite, not complex, of bounded size."""
    if (
        not isinstance(value, sp.Expr)
        or isinstance(value, sp.MatrixBase)
        or value.has(sp.AccumBounds)
    ):
        raise WrongTypeError(f"{name}: expected a number, got {_kind(value)} {_shown(shown)}")
    for atom in value.atoms(sp.Rational):
        _int_bits(name, int(atom.p), int(atom.q))
    exact_denominators(value, name)
    if value.has(*_NOT_FINITE):
        raise NonFiniteValueError(f"{name}: expected a finite number, got {_shown(shown)}")
    real = value.is_extended_real
    if real is False:
        raise _complex(name, shown, _approx(value))
    if real is None and not value.free_symbols:
        im = sp.im(value)
        if im != 0 and real_sign(im) != 0:
            raise _complex(name, shown, _approx(value))
    return value


def _approx(value: sp.Expr) -> str:
    try:
        return str(sp.N(value, 3))
    except Exception:  # only for the message
        return "a complex number"


def real_value(value: Any, name: str) -> sp.Expr:
    """One real, finite number (or a sympy expression in symbols) from outside.

    Parameters
    ----------
    value : str, int, Fraction, Decimal, float, numpy scalar or sympy expression
        Text is read exactly by :func:`~graspcompass.expr.parse_exact`; a float
        stays a float (:class:`sympy.Float`, the numeric path).
    name : str
        The parameter's name, the first word of every error message.

    Returns
    -------
    sympy.Expr
        An exact number, a :class:`sympy.Float`, or an expression in symbols.

    Raises
    ------
    WrongTypeError
        ``None``, a bool, a container, or any other object that is not a number.
    ComplexValueError
        A complex number (``1j``, ``sympy.I``, ``'sqrt(-1)'``).
    NonFiniteValueError
        ``nan``, ``inf``, ``oo``, ``zoo``.
    ExpressionError
        Text the parser refuses.

    Examples
    --------
    >>> from fractions import Fraction
    >>> real_value(Fraction(1, 3), "y"), real_value(0.5, "y"), real_value("sqrt(3)/2", "y")
    (1/3, 0.500000000000000, sqrt(3)/2)
    >>> try:
    ...     real_value(None, "x1")
    ... except WrongTypeError as err:
    ...     print(err)
    x1: expected a number, got None
    """
    if isinstance(value, str):
        try:
            return exact_denominators(parse_exact(value), name)
        except ExpressionError as exc:
            raise _renamed(exc, name) from None
    if isinstance(value, bool) or value is None or is_a(value, "bool_"):
        raise WrongTypeError(f"{name}: expected a number, got {_shown(value)}")
    if isinstance(value, sp.Basic):
        return _sympy_value(value, name, value)
    if isinstance(value, numbers.Integral) or is_a(value, "integer"):
        _int_bits(name, int(value))
        return sp.Integer(int(value))
    if isinstance(value, (Fraction, numbers.Rational)):
        _int_bits(name, int(value.numerator), int(value.denominator))
        return sp.Rational(int(value.numerator), int(value.denominator))
    if isinstance(value, float) or is_a(value, "floating"):
        return sp.Float(float_value(value, name))
    if isinstance(value, Decimal):
        if not value.is_finite():
            raise NonFiniteValueError(f"{name}: expected a finite number, got {_shown(value)}")
        digits, exponent = value.as_tuple()[1:]
        if (len(digits) + abs(int(exponent))) * 3.33 > MAX_INT_BITS:  # before 10**exponent
            raise InputTooLargeError(
                f"{name}: the Decimal {_shown(value)} has more than "
                f"{MAX_INT_BITS} bits; at most {MAX_INT_BITS} bits "
                f"(about {MAX_INT_BITS * 3 // 10} decimal digits)"
            )
        exact = Fraction(value)
        return sp.Rational(exact.numerator, exact.denominator)
    if isinstance(value, complex) or is_a(value, "complexfloating"):
        raise _complex(name, value)
    if is_a(value, "ndarray") and value.ndim == 0:
        return real_value(value.item(), name)
    what = (
        "one number"
        if isinstance(value, (list, tuple, set)) or is_a(value, "ndarray")
        else "a number"
    )
    raise WrongTypeError(f"{name}: expected {what}, got {_kind(value)} {_shown(value)}")


def float_value(value: Any, name: str) -> float:
    """One finite float from a Python or numpy float (the numeric path).

    Parameters
    ----------
    value : float or numpy floating scalar
        A finite number; an overflowing numpy ``longdouble`` counts as infinite.
    name : str
        The parameter's name, for messages.

    Returns
    -------
    float

    Examples
    --------
    >>> float_value(np.float32(0.5), "theta")
    0.5
    >>> try:
    ...     float_value(float("inf"), "theta")
    ... except NonFiniteValueError as err:
    ...     print(err)
    theta: expected a finite number, got inf
    """
    if type(value) is float:  # not a numpy float: no long double to overflow
        out = value
    elif (
        isinstance(value, bool)
        or is_a(value, "bool_")
        or not (isinstance(value, float) or is_a(value, "floating"))
    ):
        raise WrongTypeError(f"{name}: expected a float, got {_kind(value)} {_shown(value)}")
    else:
        with np.errstate(over="ignore", invalid="ignore"):  # a long double beyond a double
            out = float(value)
    if not math.isfinite(out):
        raise NonFiniteValueError(f"{name}: expected a finite number, got {_shown(out)}")
    return out


def float_array(value: Any, name: str) -> np.ndarray:
    """A finite float64 array from a numpy array or a (nested) list or tuple of numbers.

    Parameters
    ----------
    value : numpy.ndarray, list or tuple
        Real numbers of a numeric dtype (int or float); at most
        :data:`MAX_ARRAY_SIZE` entries.
    name : str
        The parameter's name, for messages.

    Returns
    -------
    numpy.ndarray
        The values as float64 (the array itself when it already is one).

    Raises
    ------
    WrongTypeError
        Text, bools, objects, ragged lists.
    ComplexValueError
        A complex dtype.
    NonFiniteValueError
        A ``nan`` or an infinity; the message names the first one.
    InputTooLargeError
        More than :data:`MAX_ARRAY_SIZE` entries.

    Examples
    --------
    >>> float_array([0, 0.5], "theta")
    array([0. , 0.5])
    >>> try:
    ...     float_array(np.array([0.0, np.nan]), "theta")
    ... except NonFiniteValueError as err:
    ...     print(err)
    theta: expected finite numbers, got theta[1] = nan
    """
    if isinstance(value, (list, tuple)) and _nested_size(value) > MAX_ARRAY_SIZE:
        raise InputTooLargeError(
            f"{name}: more than {MAX_ARRAY_SIZE} values (a list of "
            f"about {_nested_size(value)}), refused before it is copied"
        )
    if not isinstance(value, np.ndarray):
        if not isinstance(value, (list, tuple)):
            raise WrongTypeError(f"{name}: expected an array of floats, got {_kind(value)}")
        try:
            value = np.asarray(value)
        except (ValueError, TypeError, OverflowError):
            raise WrongTypeError(
                f"{name}: expected an array of numbers, got a ragged or mixed {_kind(value)[2:]}"
            ) from None
    if value.size > MAX_ARRAY_SIZE:
        raise InputTooLargeError(
            f"{name}: an array of {value.size} values; at most {MAX_ARRAY_SIZE} are allowed"
        )
    kind = value.dtype.kind
    if kind == "c":
        raise ComplexValueError(
            f"{name}: expected real numbers, got a complex array ({value.dtype})"
        )
    if kind not in "iuf":
        what = {"b": "bools", "U": "text", "S": "bytes", "O": "Python objects"}.get(
            kind, str(value.dtype)
        )
        raise WrongTypeError(
            f"{name}: expected an array of floats, got an array of {what}"
            + (" (give exact values one at a time, as text)" if kind in "UO" else "")
        )
    out = np.asarray(value, dtype=float)
    finite = np.isfinite(out)
    if not finite.all():
        where = tuple(int(i) for i in np.argwhere(~finite)[0])
        index = ", ".join(map(str, where))
        raise NonFiniteValueError(
            f"{name}: expected finite numbers, got {name}[{index}] = {float(out[where])!r}"
        )
    return out


def angle_values(theta: Any, name: str = "theta") -> sp.Expr | float | np.ndarray:
    """An angle θ (or many) for the grasp's ``k``, ``k_grasp``, ``F_T``, ...

    Parameters
    ----------
    theta : float, array-like of floats, str, int, Fraction or sympy expression
        A float or an array selects the vectorised numeric path; anything else
        the exact path (text is read exactly: ``"30deg"`` is π/6).
    name : str, optional
        The parameter's name, for messages.

    Returns
    -------
    float, numpy.ndarray or sympy.Expr

    Examples
    --------
    >>> angle_values("30deg"), angle_values(0.25), angle_values([0.0, 1.0])
    (pi/6, 0.25, array([0., 1.]))
    """
    if isinstance(theta, float) or is_a(theta, "floating"):
        return float_value(theta, name)
    array = is_a(theta, "ndarray")
    if isinstance(theta, (list, tuple)) or (array and theta.ndim):
        return float_array(theta, name)
    if array:  # 0-d: a float one stays on the numeric path
        return float_array(theta, name) if theta.dtype.kind == "f" else real_value(theta, name)
    return real_value(theta, name)


def force_value(value: Any, name: str = "external_force") -> sp.Expr | float:
    """The magnitude of a force: a finite, non-negative number (or a symbol).

    A float stays a float (numeric path); anything else is exact.

    Parameters
    ----------
    value : float, str, int, Fraction or sympy expression
        The magnitude ``F_e >= 0``.
    name : str, optional
        The parameter's name, for messages.

    Returns
    -------
    float or sympy.Expr

    Examples
    --------
    >>> force_value("5/2"), force_value(2.0)
    (5/2, 2.0)
    >>> try:
    ...     force_value(-1)
    ... except InputError as err:
    ...     print(err)
    external_force: a magnitude cannot be negative, got -1
    """
    if isinstance(value, float) or is_a(value, "floating"):
        out: sp.Expr | float = float_value(value, name)
        negative = out < 0  # type: ignore[operator]
    else:
        out = real_value(value, name)
        sign = None if out.free_symbols else exact_sign(out)  # type: ignore[union-attr]
        negative = sign == -1
        if sign == 0:
            out = sp.Integer(0)
    if negative:
        raise InputError(f"{name}: a magnitude cannot be negative, got {_shown(value)}")
    return out


def substitutions(
    values: Any, symbols: Iterable[sp.Symbol], name: str = "values", *, strict: bool = True
) -> dict[sp.Symbol, sp.Expr]:
    """Symbol values from outside, for ``expr.xreplace``: keys matched to known symbols.

    Keys are sympy symbols or their names (a name is matched against
    ``symbols``, never parsed); values go through :func:`real_value`.

    Parameters
    ----------
    values : Mapping
        ``{symbol or name: value}``, at most :data:`MAX_SUBSTITUTIONS` entries.
    symbols : iterable of sympy.Symbol
        The symbols that may be given values.
    name : str, optional
        The parameter's name, for messages.
    strict : bool, optional
        Refuse keys that are not among ``symbols`` (default); else drop them.

    Returns
    -------
    dict
        ``{symbol: value}``.

    Examples
    --------
    >>> x = sp.Symbol("x", positive=True)
    >>> substitutions({"x": "1/2"}, [x]) == {x: sp.Rational(1, 2)}
    True
    """
    if not isinstance(values, Mapping):
        raise WrongTypeError(
            f"{name}: expected a mapping of symbols to values, got {_kind(values)}"
        )
    if len(values) > MAX_SUBSTITUTIONS:
        raise InputTooLargeError(f"{name}: more than {MAX_SUBSTITUTIONS} entries")
    known = {s.name: s for s in symbols}
    out: dict[sp.Symbol, sp.Expr] = {}
    for key, value in values.items():
        if isinstance(key, sp.Symbol):
            symbol = key if known.get(key.name) == key else None
        elif isinstance(key, str):
            symbol = known.get(key)
        else:
            raise WrongTypeError(
                f"{name}: keys must be symbols or their names, got {_kind(key)} {_shown(key)}"
            )
        if symbol is None:
            if strict:
                have = ", ".join(sorted(known)) or "none"
                raise InputError(f"{name}: {_shown(key)} is not a symbol here (symbols: {have})")
            continue
        out[symbol] = real_value(value, f"{name}[{symbol.name}]")
    return out
