"""The input limits: :mod:`graspcompass.boundary.limits` under its public path.

The input boundary lives in :mod:`graspcompass.boundary` (issue 21); this module keeps
``graspcompass.limits`` importable with every name of its ``__all__``.
"""

from __future__ import annotations

from .boundary.limits import (
    COMMAND_SECONDS,
    EXACT_ANGLES,
    EXACT_VALUES,
    MAX_ANGLES,
    MAX_ARGUMENT_BITS,
    MAX_BITS,
    MAX_DEGREE,
    MAX_DEPTH,
    MAX_EXPONENT,
    MAX_INT_BITS,
    MAX_LENGTH,
    MAX_LIST_LENGTH,
    MAX_NODES,
    MAX_TERMS,
    MAX_WORK_BITS,
)

__all__ = [
    "COMMAND_SECONDS",
    "EXACT_ANGLES",
    "EXACT_VALUES",
    "MAX_ANGLES",
    "MAX_ARGUMENT_BITS",
    "MAX_BITS",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_INT_BITS",
    "MAX_LENGTH",
    "MAX_LIST_LENGTH",
    "MAX_NODES",
    "MAX_TERMS",
    "MAX_WORK_BITS",
]
