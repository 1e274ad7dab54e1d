"""Values from outside, under their public path ``graspcompass.inputs``.

The code lives in :mod:`graspcompass.boundary.inputs` (the input boundary's folder, issue 21);
this module re-exports every name of its ``__all__`` and takes its documentation.
"""

from __future__ import annotations

from .boundary import inputs as _home
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

__doc__ = _home.__doc__  # the API page shows the module's own documentation
