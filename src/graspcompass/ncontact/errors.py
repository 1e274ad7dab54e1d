"""Named errors of the n-contact model (all :class:`~graspcompass.errors.GraspCompassError`).

Errors about values from outside are also :class:`~graspcompass.errors.InputError`,
so the command line prints them on one line with exit status 2.
"""

from __future__ import annotations

from ..boundary.errors import GraspCompassError, InputError

__all__ = [
    "DegenerateGraspError",
    "EffortError",
    "InvalidContactError",
    "NContactError",
    "UnboundedEffortError",
    "UndecidedSignError",
]


class NContactError(GraspCompassError):
    """Root of the n-contact model's errors."""


class InvalidContactError(NContactError, InputError):
    """A contact, a normal, a friction value or the centre of mass that is refused."""


class EffortError(InvalidContactError):
    """An effort that is not one of the named choices or not a valid custom one."""


class UndecidedSignError(NContactError):
    """A sign the exact kernel cannot decide (``decide_sign`` returned None): never guessed."""


class DegenerateGraspError(NContactError):
    """The edge wrenches do not span the plane's three wrench dimensions (rank < 3)."""


class UnboundedEffortError(NContactError):
    """A custom effort that can be made arbitrarily negative: the least effort is -inf."""
