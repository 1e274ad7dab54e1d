"""One root for every error graspcompass raises on purpose.

Every named error is a :class:`GraspCompassError`, itself a :class:`ValueError`,
so ``except ValueError`` keeps working and ``except GraspCompassError`` catches
exactly the package's own refusals.  This module is a leaf: it imports nothing
from the package, so every layer can raise from it.

Errors about values that came from outside (text, numbers, arrays, files) are
:class:`InputError`; the command line prints their message on one line and
exits with status 2.

Examples
--------
>>> from graspcompass.errors import GraspCompassError, InputError, NonFiniteValueError
>>> issubclass(NonFiniteValueError, InputError) and issubclass(InputError, ValueError)
True
"""

from __future__ import annotations

__all__ = [
    "ComplexValueError",
    "GraspCompassError",
    "InputError",
    "InputTooLargeError",
    "NonFiniteValueError",
    "NotTextError",
    "OutputError",
    "SymbolicValueError",
    "WrongTypeError",
]


class GraspCompassError(ValueError):
    """Root of the package's named errors; the message says what is wrong, with the values."""


class InputError(GraspCompassError):
    """A value from outside (text, number, array, file) that graspcompass refuses."""


class ComplexValueError(InputError):
    """A value with a non-zero imaginary part where a real number is needed."""


class NonFiniteValueError(InputError):
    """``nan``, ``inf`` or a value too large for the computation (``oo``, ``zoo``)."""


class WrongTypeError(InputError):
    """A value of a kind that cannot be a number here (``None``, ``True``, a dict, ...)."""


class NotTextError(WrongTypeError, TypeError):
    """Something other than text where text is read (``parse_exact(None)``, bytes).

    Also a :class:`TypeError`, as Python raises for the wrong type of argument.
    """


class InputTooLargeError(InputError):
    """Text, an array, a file or an exponent beyond the documented limits."""


class SymbolicValueError(InputError, TypeError):
    """A value with free symbols where a number is needed (a float θ on a symbolic grasp).

    Also a :class:`TypeError`, as Python raises for ``float(sympy.Symbol("x"))``.
    """


class OutputError(GraspCompassError):
    """An output that cannot be written (missing folder, full disk, no permission)."""


for _cls in (
    GraspCompassError,
    InputError,
    ComplexValueError,
    NonFiniteValueError,
    WrongTypeError,
    NotTextError,
    InputTooLargeError,
    SymbolicValueError,
    OutputError,
):
    _cls.__module__ = "graspcompass.errors"  # pickled and documented under the public path
del _cls
