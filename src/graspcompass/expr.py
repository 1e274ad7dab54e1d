"""The safe expression parser: :mod:`graspcompass.boundary.expr` under its public path.

The input boundary lives in :mod:`graspcompass.boundary` (issue 21); this module keeps
``graspcompass.expr`` importable with every name of its ``__all__``.
"""

from __future__ import annotations

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
