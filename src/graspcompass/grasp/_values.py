"""A grasp's parameters at the input boundary: its errors, checked values, formatting.

The errors a :class:`~graspcompass.grasp.Grasp` raises are defined here and shown
as ``graspcompass.grasp.*`` (their ``__module__``), where they are documented and
imported from.  A parameter is read by :func:`~graspcompass.inputs.real_value`;
:func:`_exact_kind` refuses exact values the kernel cannot compute with, and
:func:`_rounded_tan` gives μ = tan ξ (eq. (22)) of a float ξ correctly rounded.
Private to :mod:`graspcompass.grasp`, which re-exports these names.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..boundary._numpy import is_a
from ..boundary.errors import (
    ComplexValueError,
    GraspCompassError,
    InputError,
    NonFiniteValueError,
    SymbolicValueError,
    WrongTypeError,
)
from ..boundary.expr import ExpressionError
from ..boundary.inputs import angle_values, real_value
from ..geometry.exact import has_float

if TYPE_CHECKING:
    import numpy as np
else:
    from ..boundary._numpy import np


class FrozenGraspError(dataclasses.FrozenInstanceError):
    """Assignment to (or deletion of) a field of a :class:`Grasp`, an immutable value.

    An :class:`AttributeError`, like :class:`dataclasses.FrozenInstanceError`;
    :meth:`Grasp.replace` makes a modified copy instead.
    """


class InvalidGraspError(GraspCompassError):
    """The parameters do not describe a grasp the paper's method applies to."""


class ParameterTypeError(WrongTypeError, InvalidGraspError):
    """A grasp parameter that is not a number (``None``, ``True``, a list, a dict)."""


class ComplexParameterError(ComplexValueError, InvalidGraspError):
    """A grasp parameter given as a complex number (``1j``, ``sympy.I``)."""


class NonFiniteParameterError(NonFiniteValueError, InvalidGraspError):
    """A grasp parameter that is ``nan`` or infinite."""


class UnsupportedParameterError(InputError, InvalidGraspError):
    """An exact length or friction coefficient outside what the exact kernel computes
    with: other roots than square roots of rationals (cube roots, nested roots)."""


_PARAMETER_ERRORS: dict[type, type] = {
    WrongTypeError: ParameterTypeError,
    ComplexValueError: ComplexParameterError,
    NonFiniteValueError: NonFiniteParameterError,
}


def _rounded_tan(x: sp.Expr) -> sp.Float:
    """``tan x`` of a float angle, correctly rounded to a double (40-digit mpmath)."""
    import mpmath

    with mpmath.workdps(40):
        return sp.Float(float(mpmath.tan(mpmath.mpf(sp.Float(x, 53)._mpf_))), 53)


def _value(v: Any, name: str) -> sp.Expr:
    """A parameter through the input boundary; a refusal is also an :class:`InvalidGraspError`."""
    try:
        return real_value(v, name)
    except ExpressionError:
        raise  # text the parser refuses (a complex value: also a ComplexValueError)
    except InputError as exc:
        for base, kind in _PARAMETER_ERRORS.items():
            if isinstance(exc, base):
                raise kind(str(exc)) from None
        raise InvalidGraspError(str(exc)) from None


def _pi_multiple(a: sp.Expr) -> sp.Rational | None:
    """q with a = q π exactly, read off the expression (no arithmetic), or None."""
    if a is sp.pi:
        return sp.Integer(1)
    if a.is_Rational:
        return sp.Integer(0) if a == 0 else None
    if a.is_Mul and len(a.args) == 2 and a.args[1] is sp.pi and a.args[0].is_Rational:
        return a.args[0]
    return None


def _exact_kind(v: sp.Expr, name: str) -> sp.Expr:
    """Refuse exact lengths and friction coefficients the kernel cannot compute with.

    They may hold rationals, square roots of rationals, π, symbols and functions
    such as sin or atan of anything; a cube root or a nested root would make every
    canonical form of the construction explode, so it is refused (give a decimal,
    which is exact, or a float).
    """
    if has_float(v):
        return v
    for a in sp.preorder_traversal(v):
        if (
            a.is_Pow
            and not a.exp.is_Integer
            and not a.free_symbols
            and not (a.exp in (sp.S.Half, -sp.S.Half) and a.base.is_Rational)
        ):
            raise UnsupportedParameterError(
                f"{name} = {_fmt(v)} uses {a}: exact lengths and friction coefficients may "
                "hold square roots of rational numbers, not other roots; give the value as "
                "a decimal (read exactly) or a float"
            )
    return v


def _double(v: sp.Expr, what: str) -> float:
    """A grasp value as a double; a value beyond double precision is refused."""
    try:
        out = float(v)
    except OverflowError:
        out = math.inf
    except TypeError:
        raise SymbolicValueError(
            f"{what} = {v} is not a number: the numeric path (a float θ) "
            "needs numbers; give θ exactly or substitute values first"
        ) from None
    if not math.isfinite(out):
        raise NonFiniteValueError(
            f"{what} = {_fmt(v)} is beyond double precision (about 1.8e308): the numeric "
            "path cannot use it; give θ exactly (text such as 'pi/3') for exact values"
        )
    return out


def _finite(out: Any, what: str) -> Any:
    """Refuse a numeric result that overflowed double precision."""
    if not np.isfinite(out).all():
        raise NonFiniteValueError(
            f"{what} overflows double precision (|x| > 1.8e308) for these values; give θ "
            "and the force exactly (text such as 'pi/3') for exact values"
        )
    return out


def _fmt_angle(v: sp.Expr) -> str:
    try:
        f = float(v / sp.pi)
    except (TypeError, OverflowError):
        return str(v)
    return f"{f:.3g}π" if math.isfinite(f) and abs(f) < 1e6 else f"{sp.N(v, 4)} rad"


def _fmt(v: sp.Expr) -> str:
    try:
        f = float(v)
    except (TypeError, OverflowError):
        return str(v)
    return str(v) if v.is_Rational else f"{v} ≈ {f:.4g}"


_HALF_MAX = 0.5 * 1.7976931348623157e308  # k_n = S_n sin θ - C_n cos θ cannot overflow below


def _is_numeric(theta: Any) -> bool:
    """After :func:`angle_values`: a float or an array selects the numeric path."""
    return isinstance(theta, float) or is_a(theta, "ndarray")


def _sympy(value: sp.Expr | float) -> sp.Expr:
    """A checked value for the exact path (a float becomes a sympy Float)."""
    return sp.Float(value) if isinstance(value, float) else value


def _one_angle(theta: Any) -> sp.Expr:
    t = angle_values(theta)
    if is_a(t, "ndarray"):
        shape = getattr(t, "shape", None)
        raise WrongTypeError(f"theta: expected one angle, got an array of shape {shape}")
    return _sympy(t)


# documented, pickled and shown in tracebacks as graspcompass.grasp.*, where they belong
for _error in (
    FrozenGraspError,
    InvalidGraspError,
    ParameterTypeError,
    ComplexParameterError,
    NonFiniteParameterError,
    UnsupportedParameterError,
):
    _error.__module__ = "graspcompass.grasp"
del _error
