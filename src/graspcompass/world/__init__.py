"""Grasps in the user's frame: from world-frame contacts to the paper's frame and back.

The paper works in the object frame of §2.2.1 (Fig. 2): the origin at the centre
of mass O, the y-axis perpendicular to the line through the two contacts,
``P1 = (x1, y)`` and ``P2 = (-x2, y)`` with ``x1, x2 > 0`` and ``y >= 0`` (here
``x1 + x2 > 0``: the centre of mass may project beyond a contact, issue 13 §1), the
inward normal at P1 at the angle φ1 clockwise from the negative y-axis,
``n1 = (-sin φ1, -cos φ1)``, at P2 at φ2 counter-clockwise,
``n2 = (sin φ2, -cos φ2)`` (the columns of L in eq. (5)).

:func:`place_grasp` takes what a designer has in a CAD frame (a right-handed
world frame, y up when x points right): two contact points, their inward unit
normals or the outline they lie on, the friction of each contact (μ or the cone
half angle ξ, tan ξ = μ, eq. (22)) and the centre of mass (given, or the
outline's centroid for a uniform density).  It returns a :class:`WorldGrasp`:
the paper-frame :class:`~graspcompass.Grasp` and the rigid motion (a rotation
and a translation, never a reflection) between the two frames, so directions
and forces computed in the paper's frame are read in the world frame.

How the frame is chosen.  The x-axis runs along the line through the contacts,
the y-axis is its counter-clockwise perpendicular.  Of the two directions of the
line, the one that gives the contacts ``y >= 0`` is taken: P1 is the
contact that makes the line's direction P2 → P1 point along +x with the centre
of mass below the line.  When the centre of mass lies on the line (``y = 0``)
both directions qualify and P1 is the first contact given.  The friction of a
contact follows it, whichever of P1, P2 it becomes.

Outlines.  A contact on an edge of the outline takes that edge's inward unit
normal.  At a vertex the normal is undefined: ``at_vertex="refuse"`` (the
default) raises :class:`VertexContactError`, ``at_vertex="bisector"`` takes the
normalised sum of the two adjacent edges' inward normals; a normal given for
that contact (``normals=(n, None)``) is used instead of either.

Exact input stays exact: text (``"1/20"``, ``"sqrt(2)/2"``), ints, Fractions and
sympy numbers give an exact grasp (the lengths then hold square roots of
rationals, the contacts' distance ``sqrt(...)``); a float anywhere (a shapely
outline's coordinates are floats) selects the numeric path for all values.

Angles in the world frame use the paper's convention for θ (eq. (26)): measured
counter-clockwise from the world's negative y-axis, so the world's gravity
``(0, -1)`` is at θ = 0.  A paper-frame θ is the world angle ``θ + β``, β the
angle of the paper's x-axis in the world frame (:attr:`WorldGrasp.beta`).

The code: the errors are in ``world._errors``, :class:`WorldGrasp` in
``world._grasp``, :func:`place_grasp` in ``world._place``, the outlines in
``world._outline`` and the exact-or-float helpers in ``world._arith``; the public
names are importable from here and the classes are documented and pickled as this
module's.

Examples
--------
>>> wg = place_grasp([("3", "5"), ("-1", "5")], [(-1, 0), (1, 0)], mu=("1", "6/5"),
...                  com=("1", "4"))
>>> wg.grasp == Grasp(2, 2, 1, "pi/2", "pi/2", mu1=1, mu2="6/5")  # Table I(a)
True
>>> wg.internal_force((0, -10))  # 10 N straight down in the world: k_grasp(0) = 2 (x1 = 2)
5
"""

from __future__ import annotations

from ..grasp import Grasp  # noqa: F401  (the examples)
from ._errors import (
    CenterOfMassError,
    CoincidentContactsError,
    ContactOffOutlineError,
    FrictionConeError,
    NormalNotUnitError,
    NormalOutwardError,
    OutlineError,
    VertexContactError,
    WorldGraspError,
)
from ._grasp import WorldGrasp
from ._place import place_grasp

__all__ = [
    "CenterOfMassError",
    "CoincidentContactsError",
    "ContactOffOutlineError",
    "FrictionConeError",
    "NormalNotUnitError",
    "NormalOutwardError",
    "OutlineError",
    "VertexContactError",
    "WorldGrasp",
    "WorldGraspError",
    "place_grasp",
]
