"""numpy, imported on its first use.

The exact paths (``check``, ``verify``, ``steps`` of a preset) never compute with numpy,
and importing it costs 80 ms of wall time and twice that in CPU time (its BLAS starts
threads).  The modules that need numpy for their float paths write
``from ..boundary._numpy import np``: the first attribute read imports numpy, later
reads are plain attribute reads of this object.  A type test against a numpy type
asks :func:`loaded` first: no numpy object exists before numpy is imported.
"""

from __future__ import annotations

import importlib
import sys
from types import ModuleType
from typing import Any

__all__ = ["is_a", "loaded", "np"]


class _Numpy:
    """The numpy module, imported when one of its names is first read."""

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        value = getattr(importlib.import_module("numpy"), name)
        setattr(self, name, value)  # later reads skip __getattr__
        return value


np: Any = _Numpy()


def loaded() -> ModuleType | None:
    """The numpy module if it is imported already, else None (then no value is a numpy
    object).

    Examples
    --------
    >>> import numpy
    >>> loaded() is numpy
    True
    """
    return sys.modules.get("numpy")


def is_a(value: object, *names: str) -> bool:
    """``isinstance(value, (numpy.<name>, ...))``, False without importing numpy when it
    is not imported yet.

    Examples
    --------
    >>> import numpy
    >>> is_a(numpy.float32(1), "floating"), is_a(1.0, "floating", "integer")
    (True, False)
    """
    module = sys.modules.get("numpy")
    return module is not None and isinstance(value, tuple(getattr(module, n) for n in names))
