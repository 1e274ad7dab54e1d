"""The arguments of :mod:`graspcompass.batch` through the input boundary, and its refusals.

Each argument is a number, a list of them or an array (:func:`_outside`), the
arguments broadcast within :data:`MAX_ARRAY_SIZE` (:func:`_prepare`), and an invalid
grasp is refused with its first failed inequality in words (:func:`_refuse`).
Private to :mod:`graspcompass.batch`, which re-exports the public names (their
``__module__`` is that package's).
"""

from __future__ import annotations

import math
import numbers
from decimal import Decimal
from typing import Any

import numpy as np

from ..boundary.errors import ComplexValueError, InputError, InputTooLargeError, WrongTypeError
from ..boundary.inputs import _nested_size  # the entries of a nested list, before it is copied
from ._xp import _astype, _floats, _is, _namespace

__all__ = ["MAX_ARRAY_SIZE", "PARAMETERS", "InvalidGraspsError"]

#: The parameters every function takes first, in this order.
PARAMETERS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")

_ON_INVALID = ("raise", "nan")

#: Most entries of a list argument, and of a broadcast the arguments do not hold already
#: (as :data:`graspcompass.boundary.inputs.MAX_ARRAY_SIZE`).
MAX_ARRAY_SIZE = 10_000_000


class InvalidGraspsError(InputError):
    """Some grasps of a batch lie outside the domain (condition (1) and the ranges).

    A :class:`ValueError` (through :class:`~graspcompass.errors.InputError`).

    Attributes
    ----------
    index : tuple of int
        The index of the first invalid grasp (row-major) in the broadcast shape
        of the parameters.
    count : int
        How many grasps are invalid.
    reason : str
        What fails for that grasp, e.g. ``"φ1 + ξ1 > π/2 of condition (1)"``.
    """

    def __init__(self, message: str, index: tuple[int, ...], count: int, reason: str) -> None:
        super().__init__(message)
        self.index, self.count, self.reason = index, count, reason


def _reason(v: dict[str, float]) -> str:
    """The first failed inequality of one grasp (Python floats), in words."""
    for name in PARAMETERS:
        if not math.isfinite(v[name]):
            return f"{name} = {v[name]!r} is not finite"
    if not math.isfinite((v["x1"] + v["x2"]) * 0.5 + v["y"] + v["mu1"] + v["mu2"]):
        return "(x1 + x2)/2 + y + μ1 + μ2 below the largest double (about 1.8e308)"
    if not v["x1"] + v["x2"] > 0:
        return "x1 + x2 > 0 (P1 must lie right of P2)"
    if not v["y"] >= 0:
        return "y >= 0 (the frame of §2.2.1)"
    for i in (1, 2):
        phi, mu = v[f"phi{i}"], v[f"mu{i}"]
        if not 0 < phi <= math.pi:
            return f"0 < φ{i} <= π"
        if not mu > 0:
            return f"μ{i} > 0"
        if not math.cos(phi) - mu * math.sin(phi) < 0:
            return f"φ{i} + ξ{i} > π/2 of condition (1) (the friction cone misses P{3 - i})"
        if not math.cos(phi) + mu * math.sin(phi) > 0:
            return f"φ{i} − ξ{i} < π/2 of condition (1) (the friction cone misses P{3 - i})"
    return "condition (1) within the margin asked (or within rounding of a bound)"


def _refuse(xp: Any, p: list, ok: Any) -> None:
    """Raise :class:`InvalidGraspsError` when ``ok`` is False anywhere."""
    if bool(xp.all(ok)):
        return
    bad = xp.reshape(~ok, (-1,))
    count = int(xp.sum(_astype(xp, bad, xp.int64)))
    first = int(xp.argmax(_astype(xp, bad, xp.int8)))
    shape = tuple(ok.shape)
    index = tuple(int(i) for i in np.unravel_index(first, shape)) if shape else ()
    vals = {
        name: float(xp.reshape(xp.broadcast_to(a, shape), (-1,))[first])
        for name, a in zip(PARAMETERS, p)
    }
    reason = _reason(vals)
    shown = ", ".join(f"{k}={v!r}" for k, v in vals.items())
    raise InvalidGraspsError(
        f"{count} of {math.prod(shape)} grasps are invalid; the first, at index {index} "
        f"({shown}), fails {reason}. Pass on_invalid='nan' for nan results there, or "
        "select the valid ones with graspcompass.batch.valid",
        index,
        count,
        reason,
    )


def _outside(v: Any, name: str) -> Any:
    """One argument through the input boundary: numbers, lists of them, or arrays.

    Python numbers that are not floats (``Fraction``, ``Decimal``, sympy numbers) become
    floats through :func:`graspcompass.inputs.real_value` (bounded, real); text, ``None``
    and other objects are refused with a named error; a list is sized before it is copied
    and must not be ragged.  ``nan`` and infinities stay: they are invalid grasps.
    """
    if isinstance(v, (bool, np.bool_)):
        raise WrongTypeError(f"{name}: expected numbers, got a bool")
    if isinstance(v, (complex, np.complexfloating)):
        raise ComplexValueError(f"{name}: expected real numbers, got {v!r}")
    if isinstance(v, (int, float, np.number)):
        return v
    if isinstance(v, (list, tuple)):
        n = _nested_size(v)
        if n > MAX_ARRAY_SIZE:
            raise InputTooLargeError(
                f"{name}: a list of about {n} values; at most {MAX_ARRAY_SIZE} (give an array)"
            )
        try:
            return np.asarray(v)
        except (ValueError, TypeError, OverflowError):
            raise WrongTypeError(f"{name}: expected numbers, got a ragged or mixed list") from None
    if isinstance(v, (str, bytes, dict, set, type(None))):
        raise WrongTypeError(
            f"{name}: expected numbers or an array, got {type(v).__name__} {str(v)[:40]!r}"
        )
    if isinstance(v, (numbers.Real, Decimal)) or type(v).__module__.startswith("sympy"):
        from ..boundary.inputs import real_value  # loads sympy: only for such values

        exact = real_value(v, name)
        if getattr(exact, "free_symbols", None):
            raise WrongTypeError(f"{name}: expected numbers, got the expression {exact}")
        return float(exact)
    if not hasattr(v, "shape") or not hasattr(v, "dtype"):
        raise WrongTypeError(f"{name}: expected numbers or an array, got {type(v).__name__}")
    return v


def _prepare(values: tuple, extra: tuple = (), extra_names: tuple = ()) -> tuple:
    names = PARAMETERS + extra_names
    values = tuple(_outside(v, n) for v, n in zip(values + extra, names))
    try:
        xp = _namespace(*values)
    except TypeError as exc:
        raise WrongTypeError(
            f"the arguments mix array libraries or are not arrays: {str(exc)[:120]}"
        ) from None
    arrs = _floats(xp, values, names)
    shapes = [tuple(a.shape) for a in arrs]
    try:
        shape = np.broadcast_shapes(*shapes)
    except (ValueError, TypeError):  # dask's unknown sizes are None: not checked here
        if any(None in s or any(isinstance(d, float) for d in s) for s in shapes):
            return xp, arrs[: len(PARAMETERS)], arrs[len(PARAMETERS) :]
        raise InputError(
            "the arguments do not broadcast together: shapes "
            + ", ".join(f"{n} {s}" for n, s in zip(names, shapes))
        ) from None
    size, largest = math.prod(shape), max((math.prod(s) for s in shapes), default=1)
    if size > MAX_ARRAY_SIZE and size > largest and not _is(xp, "dask"):
        raise InputTooLargeError(
            f"the arguments broadcast to shape {shape}, {size} grasps, from arrays of at most "
            f"{largest}: beyond {MAX_ARRAY_SIZE} the caller makes the full-size arrays"
        )
    return xp, arrs[: len(PARAMETERS)], arrs[len(PARAMETERS) :]


def _check_mode(on_invalid: str) -> None:
    if on_invalid not in _ON_INVALID:
        raise InputError(f"on_invalid: expected 'raise' or 'nan', got {on_invalid!r}")


InvalidGraspsError.__module__ = "graspcompass.batch"  # documented and pickled there
