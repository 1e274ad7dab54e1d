"""Sizing a two-jaw gripper in newtons (issue 13 §2): ``graspcompass size``.

:func:`size_gripper` gives the squeeze a part needs, per jaw or in total (every
result says which), for a given orientation, a range of tilts or any
orientation, with an acceleration bound or vector and a safety factor; the
worst direction, the contact that slips and which way, the best orientation,
and the vendor formula beside it.  :func:`least_mu` and :func:`force_closure`
answer the inverse questions; :mod:`graspcompass.sizing.units` reads values
with units (``"100mm"``, ``"500g"``).  The derivation is in
:mod:`graspcompass.sizing.core`.

The names are imported on first use, so that the command line can read units
without loading sympy.

Examples
--------
>>> from graspcompass import Grasp
>>> from graspcompass.sizing import size_gripper
>>> s = size_gripper(Grasp.preset("table1a"), "2kg", g=10)
>>> s.worst_squeeze, s.per
(5*sqrt(13), 'jaw')
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:
    from .core import (
        ForceClosure,
        LeastMu,
        NotForceClosureError,
        Sizing,
        SizingError,
        force_closure,
        least_mu,
        size_gripper,
        vendor_squeeze,
        worst_squeeze_many,
    )
    from .units import MissingUnitError, UnitError, UnknownUnitError

__all__ = [
    "ForceClosure",
    "LeastMu",
    "MissingUnitError",
    "NotForceClosureError",
    "Sizing",
    "SizingError",
    "UnitError",
    "UnknownUnitError",
    "force_closure",
    "least_mu",
    "size_gripper",
    "vendor_squeeze",
    "worst_squeeze_many",
]

_HOMES = {name: "core" for name in __all__}
_HOMES.update(
    {
        "MissingUnitError": "units",
        "UnitError": "units",
        "UnknownUnitError": "units",
        "core": "core",
        "units": "units",
    }
)
__getattr__, __dir__ = attach(__name__, _HOMES)
