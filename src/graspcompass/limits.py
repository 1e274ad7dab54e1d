"""The limits on outside input, under their public path ``graspcompass.limits``.

The code lives in :mod:`graspcompass.boundary.limits` (the input boundary's folder, issue 21);
this module re-exports every name of its ``__all__`` and takes its documentation.
"""

from __future__ import annotations

from .boundary import limits as _home
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

__doc__ = _home.__doc__  # the API page shows the module's own documentation
