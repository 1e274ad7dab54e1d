"""The hooks that bound Python's JSON reader (step 2 of "Reading JSON files").

Duplicate keys are remembered (:class:`_Object`) and reported with their path,
``NaN`` and ``Infinity`` are refused, numbers that overflow a double and integers
of more than :data:`~graspcompass.export.json.MAX_INT_DIGITS` digits too.
Private to :mod:`graspcompass.export.json`, which re-exports these names.
"""

from __future__ import annotations

import math
from typing import Any

from ._json_limits import MAX_INT_DIGITS, JSONDocumentError, JSONTooLargeError
from ._json_schema import _show


class _Object(dict):
    """A JSON object; ``duplicate`` is a key that appeared twice (reported with its path)."""

    duplicate: str | None = None


def _pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    obj = _Object(pairs)
    if len(obj) != len(pairs):
        seen: set[str] = set()
        obj.duplicate = next(k for k, _ in pairs if k in seen or seen.add(k))  # type: ignore
    return obj


def _constant(name: str) -> float:
    raise JSONDocumentError(f"not JSON: {name} is not a JSON number (only finite numbers are)")


def _float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise JSONTooLargeError(f"not JSON: the number {_show(text)} does not fit a double")
    return value


def _int(text: str) -> int:
    if len(text.lstrip("-")) > MAX_INT_DIGITS:
        raise JSONTooLargeError(f"the integer {_show(text)} has more than {MAX_INT_DIGITS} digits")
    return int(text)
