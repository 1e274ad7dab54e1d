"""The errors of :func:`graspcompass.place_grasp`: world-frame data that make no grasp.

Every one is a :class:`WorldGraspError`, itself a
:class:`~graspcompass.grasp.InvalidGraspError`; the messages name the contact.
:class:`FrictionConeError` is condition (1) failing (a friction cone that does
not contain the other contact, Fig. 2).  They are documented, raised and
pickled as :mod:`graspcompass.world`'s.
"""

from __future__ import annotations

from ..grasp import InvalidGraspError


class WorldGraspError(InvalidGraspError):
    """World-frame data that do not make a grasp; the message names the contact."""


class CoincidentContactsError(WorldGraspError):
    """The two contacts are the same point."""


class NormalNotUnitError(WorldGraspError):
    """A given normal has no direction: the zero vector, or a float one of infinite length.

    (Any other length is scaled to 1, exactly for exact input; the name is kept from
    when only unit normals were taken.)
    """


class FrictionConeError(WorldGraspError):
    """Condition (1) fails: a contact's friction cone does not contain the other contact."""


class NormalOutwardError(FrictionConeError):
    """A normal points out of the object (away from the other contact or the outline)."""


class CenterOfMassError(WorldGraspError):
    """Not raised any more: the centre of mass may project beyond a contact (x1 <= 0 or
    x2 <= 0, issue 13 §1).  Kept so that code catching it keeps working."""


class OutlineError(WorldGraspError):
    """An outline that is not a simple polygon with area."""


class ContactOffOutlineError(WorldGraspError):
    """A contact that does not lie on the outline's boundary."""


class VertexContactError(WorldGraspError):
    """A contact at a vertex of the outline, where the normal is undefined."""


# public, documented and pickled as graspcompass.world's (which re-exports them)
for _cls in (
    WorldGraspError,
    CoincidentContactsError,
    NormalNotUnitError,
    FrictionConeError,
    NormalOutwardError,
    CenterOfMassError,
    OutlineError,
    ContactOffOutlineError,
    VertexContactError,
):
    _cls.__module__ = "graspcompass.world"
del _cls
