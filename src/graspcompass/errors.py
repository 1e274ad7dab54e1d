"""The package's exceptions: :mod:`graspcompass.boundary.errors` under its public path.

The input boundary lives in :mod:`graspcompass.boundary` (issue 21); this module keeps
``graspcompass.errors`` importable with every name of its ``__all__``.
"""

from __future__ import annotations

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
