"""The safe expression parser, under their public path ``graspcompass.expr``.

The code lives in :mod:`graspcompass.boundary.expr` (the input boundary's folder, issue 21);
this module re-exports every name of its ``__all__`` and takes its documentation.
"""

from __future__ import annotations

from .boundary import expr as _home
from .boundary.expr import (
    MAX_ANGLES,
    MAX_ARGUMENT_BITS,
    MAX_BITS,
    MAX_DEGREE,
    MAX_DEPTH,
    MAX_EXPONENT,
    MAX_LENGTH,
    MAX_NODES,
    MAX_TERMS,
    MAX_WORK_BITS,
    ComplexExpressionError,
    Condition,
    ExpressionError,
    parse_angles,
    parse_exact,
    parse_with_conditions,
    real_sign,
    to_exact,
    tree_conditions,
)

__all__ = [
    "MAX_ANGLES",
    "MAX_ARGUMENT_BITS",
    "MAX_BITS",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "MAX_NODES",
    "MAX_TERMS",
    "MAX_WORK_BITS",
    "ComplexExpressionError",
    "Condition",
    "ExpressionError",
    "parse_angles",
    "parse_exact",
    "parse_with_conditions",
    "real_sign",
    "to_exact",
    "tree_conditions",
]

__doc__ = _home.__doc__  # the API page shows the module's own documentation
