"""The package's exceptions, under their public path ``graspcompass.errors``.

The code lives in :mod:`graspcompass.boundary.errors` (the input boundary's folder, issue 21);
this module re-exports every name of its ``__all__`` and takes its documentation.
"""

from __future__ import annotations

from .boundary import errors as _home
from .boundary.errors import (
    ComplexValueError,
    GraspCompassError,
    InputError,
    InputTooLargeError,
    NonFiniteValueError,
    NotTextError,
    OutputError,
    SymbolicValueError,
    WrongTypeError,
)

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

__doc__ = _home.__doc__  # the API page shows the module's own documentation
