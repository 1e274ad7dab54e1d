"""Lazy public names of a package (PEP 562), as scientific Python's ``lazy_loader`` does.

A package lists where each public name lives; the name's module is imported on
first use.  So ``import graspcompass`` and the command line start without
loading sympy, numpy or matplotlib, and a usage error is refused in a tenth
of a second.

Examples
--------
>>> getattr_, dir_ = attach("graspcompass", {"PRESETS": "presets"})
>>> sorted(getattr_("PRESETS"))[0]
'fig6'
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["attach"]


def attach(
    package: str, homes: Mapping[str, str]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``(__getattr__, __dir__)`` for ``package``, whose names live in ``homes``.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    homes : mapping of str to str
        Public name to the submodule (relative to ``package``) that defines it;
        a name that maps to itself is a submodule.

    Returns
    -------
    tuple of callable
        The module-level ``__getattr__`` and ``__dir__`` of PEP 562.
    """

    def __getattr__(name: str) -> Any:
        home = homes.get(name)
        if home is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        module = importlib.import_module(f"{package}.{home}")
        value = module if home == name else getattr(module, name)
        setattr(sys.modules[package], name, value)  # later uses skip __getattr__
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(homes))

    return __getattr__, __dir__
