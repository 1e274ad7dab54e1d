"""graspcompass: the internal force diagram of two-point grasps, by ruler and compass.

A ruler-and-compass construction engine for the diagram of Ito, Tanaka and
Sasaki, "A diagram of the minimum necessary internal force required to resist
external forces on two-point-grasped objects in two-dimensional space",
Robotica 30(5), 2012.

Layers, lowest first: :mod:`graspcompass.geometry` (exact kernel),
:mod:`graspcompass.grasp` (the model, eqs. (1)-(39)),
:mod:`graspcompass.construction` (the drawing recipe of §3.3),
:mod:`graspcompass.render` (matplotlib) and :mod:`graspcompass.cli`.

Examples
--------
>>> import graspcompass as gc
>>> c = gc.internal_force_diagram(gc.Grasp.preset("fig6"))
>>> c["V2"] == gc.Point("sqrt(3)", "-3/2")
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ._lazy import attach
from ._version import __version__

if TYPE_CHECKING:
    from .boundary.errors import GraspCompassError, InputError
    from .boundary.expr import ExpressionError, parse_exact
    from .construction import Construction, Step, internal_force_diagram
    from .geometry import Circle, GeometryError, Line, Point
    from .grasp import FrozenGraspError, Grasp, InvalidGraspError
    from .presets import PRESETS
    from .world import WorldGrasp, WorldGraspError, place_grasp


__all__ = [
    "PRESETS",
    "Circle",
    "Construction",
    "ExpressionError",
    "FrozenGraspError",
    "GeometryError",
    "Grasp",
    "GraspCompassError",
    "InputError",
    "InvalidGraspError",
    "Line",
    "Point",
    "Step",
    "WorldGrasp",
    "WorldGraspError",
    "__version__",
    "internal_force_diagram",
    "parse_exact",
    "place_grasp",
]

#: Where each public name lives; it is imported on first use (:mod:`graspcompass._lazy`).
_HOMES = {
    "Construction": "construction",
    "Step": "construction",
    "internal_force_diagram": "construction",
    "GraspCompassError": "errors",
    "InputError": "errors",
    "ExpressionError": "expr",
    "parse_exact": "expr",
    "Circle": "geometry",
    "GeometryError": "geometry",
    "Line": "geometry",
    "Point": "geometry",
    "FrozenGraspError": "grasp",
    "Grasp": "grasp",
    "InvalidGraspError": "grasp",
    "PRESETS": "presets",
    "WorldGrasp": "world",
    "WorldGraspError": "world",
    "place_grasp": "world",
}
__getattr__, __dir__ = attach(__name__, _HOMES)
