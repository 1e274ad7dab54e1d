"""What an outside value is, in words, and how many entries a nested list has.

Private helpers of :mod:`graspcompass.boundary.inputs` (which reads them from here).
"""

from __future__ import annotations

from ._numpy import is_a


def _kind(value: object) -> str:
    kinds = {
        type(None): "None",
        bool: "a bool",
        dict: "a dict",
        list: "a list",
        tuple: "a tuple",
        set: "a set",
        bytes: "bytes",
    }
    if is_a(value, "bool_"):
        return "a bool"
    kind = type(value).__name__
    return kinds.get(type(value), f"{'an' if kind[:1].lower() in 'aeiou' else 'a'} {kind}")


def _nested_size(value: list | tuple) -> int:
    """The entries a nested list would have, from the lengths of its first elements."""
    size, item = 1, value
    for _ in range(32):
        if not isinstance(item, (list, tuple)):
            break
        size *= len(item)
        if not item:
            break
        item = item[0]
    if is_a(item, "ndarray"):
        size *= getattr(item, "size", 1)  # an array: its number of entries
    return size
