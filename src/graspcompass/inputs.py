"""Reading a value from outside: :mod:`graspcompass.boundary.inputs` under its public path.

The input boundary lives in :mod:`graspcompass.boundary` (issue 21); this module keeps
``graspcompass.inputs`` importable with every name of its ``__all__``.
"""

from __future__ import annotations

from .boundary.inputs import (
    MAX_ARRAY_SIZE,
    MAX_SUBSTITUTIONS,
    angle_values,
    exact_denominators,
    exact_sign,
    float_array,
    float_value,
    force_value,
    real_value,
    substitutions,
)

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
