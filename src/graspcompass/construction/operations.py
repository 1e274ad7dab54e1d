"""One record per operation of the construction kernel.

Each :class:`Operation` says everything the package knows about one verb of the
ruler-and-compass kernel (:mod:`graspcompass.geometry.constructive`,
:mod:`graspcompass.geometry.measurement`): the kernel function, the instrument
that draws it, the kinds of its inputs and parameters, the kind of object it
makes, a caption template, the GeoGebra command that makes it again, and how
it is drawn.  :data:`OPERATIONS` maps each name to its record; the string
dispatch of :data:`graspcompass.construction.protocol.OPS` is derived from it.

The kinds are ``"point"``, ``"line"``, ``"circle"`` and ``"number"`` (a signed
length); parameter kinds are ``"number"`` (an exact value), ``"angle"`` (radians,
from the negative y-axis, counter-clockwise, as θ in e(θ) of eq. (26)) and
``"branch"`` (0 or 1: which of two intersection points, in the kernel's fixed
branch order).

Examples
--------
>>> op = OPERATIONS["meet"]
>>> op.inputs, op.makes, op.instrument
(('line', 'line'), 'point', 'ruler')
>>> op.caption_for("X1", ("side1", "x-axis"))
'X1: where side1 meets x-axis'
>>> op.ggb_for(("side1", "x-axis"), ())
'Intersect[side1, x-axis]'
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import sympy as sp

from ..geometry import Circle, Line, Point
from . import _ops_table as _table

__all__ = ["KINDS", "OPERATIONS", "PARAM_KINDS", "ROLES", "Operation", "kind_of"]

#: Kinds of objects a step makes or uses.
KINDS = ("point", "line", "circle", "number")
#: Kinds of parameters (exact values written after the inputs).
PARAM_KINDS = ("number", "angle", "branch")
#: Roles a step may play in a drawing (``""``: none), set by the recipe as data.
ROLES: tuple[str, ...] = (
    "",
    "given",
    "axis",
    "contact",
    "cone_side",
    "foot",
    "midpoint",
    "X",
    "perpendicular",
    "Y",
    "S_length",
    "C_length",
    "V",
    "circle",
    "break_point",
    "envelope",
)


def kind_of(obj: object) -> str:
    """The kind of a kernel object: ``"point"``, ``"line"``, ``"circle"`` or ``"number"``.

    Examples
    --------
    >>> kind_of(Point(0, 0)), kind_of(sp.Integer(2))
    ('point', 'number')
    """
    for cls, name in ((Point, "point"), (Line, "line"), (Circle, "circle")):
        if isinstance(obj, cls):
            return name
    return "number" if isinstance(obj, sp.Expr) else "other"


@dataclass(frozen=True)
class Operation:
    """What one kernel operation is: function, instrument, kinds, caption, GeoGebra, drawing.

    Attributes
    ----------
    name : str
        The operation's name in protocols and in the construction language.
    function : callable
        ``function(*inputs, *params)`` returns the object (the exact kernel).
    instrument : str
        One of :data:`graspcompass.construction.protocol.INSTRUMENTS`.
    inputs : tuple of str
        Kinds of the input objects (:data:`KINDS`), in order.
    params : tuple of str
        Kinds of the parameters (:data:`PARAM_KINDS`) written after the inputs.
    makes : str
        Kind of the object made.
    caption : str
        Template of a default caption: ``{name}`` and ``{0}``, ``{1}``, ... (inputs).
    ggb : str or None
        GeoGebra command template (``{0}``... inputs, ``{p0}``... parameters), or
        None where GeoGebra's own choice would differ from the kernel's.
    draws : str
        How it is drawn: ``"point"``, ``"line"``, ``"circle"``, ``"length"``
        (a measured segment) or ``"curve"``.
    doc : str
        One line: what the operation does, with the paper's equation where one applies.
    """

    name: str
    function: Callable[..., Any]
    instrument: str
    inputs: tuple[str, ...]
    params: tuple[str, ...]
    makes: str
    caption: str
    ggb: str | None
    draws: str
    doc: str

    def caption_for(self, name: str, inputs: tuple[str, ...], params: tuple[Any, ...] = ()) -> str:
        """The default caption of a step ``name`` made from ``inputs`` and ``params``."""
        values = {f"p{i}": str(p) for i, p in enumerate(params)}
        values.update({f"p{i}": "?" for i in range(len(params), len(self.params))})
        return self.caption.format(*inputs, name=name, **values)

    def ggb_for(self, inputs: tuple[str, ...], params: tuple[Any, ...]) -> str | None:
        """The GeoGebra command making the object again (labels as given), or None."""
        if self.ggb is None:
            return None
        values = {f"p{i}": str(p).replace("**", "^") for i, p in enumerate(params)}
        return self.ggb.format(*inputs, **values)


#: Name -> record of every operation of the kernel.
OPERATIONS: Mapping[str, Operation] = MappingProxyType(
    {row.name: Operation(*row) for row in _table.ROWS}
)

#: Roles of the n-contact vertex recipe (issue 25), kept apart from the paper's.
ROLES = (*ROLES, "edge", "cost_point", "cost_line", "transfer", "image")
