"""Sizing a gripper with n >= 2 jaws or fingers (issue 25): the worst squeeze in newtons.

Over every orientation of the part, the least effort is ``F_e max_q |q|`` for the
vertices q of the internal force polygon Q (:meth:`NContactGrasp.worst`): the load
``F_e = m (g + A) S`` (mass, gravity, an acceleration bound A in any direction, a
safety factor S) at the centre of mass in its worst direction.  With the effort
``sum-normal`` it is the sum of the fingers' normal forces, with ``max-normal`` the
largest finger's, with ``pair:I,J`` the two named fingers' sum.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from .units import acceleration_value, mass_value

if TYPE_CHECKING:
    from ..ncontact.model import NContactGrasp

__all__ = ["size_ncontact"]


def size_ncontact(
    grasp: NContactGrasp, mass: Any, g: Any = "9.80665", accel: Any = None, safety: Any = "1"
) -> dict[str, Any]:
    """The worst squeeze of an n-contact grasp over all orientations, in newtons.

    Parameters
    ----------
    grasp : NContactGrasp
        The contacts (any length unit: the effort is a sum of forces, scale-free).
    mass, g, accel : text or number
        Mass (kg unless a unit), gravity and an acceleration bound in any direction.
    safety : text or number
        Safety factor >= 1.

    Returns
    -------
    dict
        ``worst_N`` (``F_e max|q|``), ``theta_deg`` (the paper's θ of the worst load
        direction, eq. (26)), ``load_N`` (F_e), ``max_q`` (``max |q|``), ``effort``,
        ``vertices`` (the float vertices of Q) and ``force_closure``.

    Raises
    ------
    graspcompass.ncontact.UnboundedEffortError
        Without force closure (some orientation cannot be held at any squeeze).
    """
    from ..boundary.inputs import real_value
    from ..ncontact import UnboundedEffortError

    m = float(mass_value(mass, "--mass"))
    gv = float(acceleration_value(g, "--g"))
    a = 0.0 if accel is None else float(acceleration_value(accel, "--accel"))
    s = float(real_value(safety, "--safety"))
    if not s >= 1:
        raise ValueError(f"--safety must be >= 1, got {safety!r}")
    if not grasp.force_closure:
        raise UnboundedEffortError(
            "not force-closure: some orientation of the part cannot be "
            "held at any squeeze (the least effort is infinite there)"
        )
    load = m * (gv + a) * s
    value, theta = grasp.worst(1)
    q = float(value)
    return {
        "effort": grasp.effort.name,
        "contacts": grasp.n,
        "load_N": load,
        "max_q": q,
        "worst_N": load * q,
        "theta_deg": None if theta is None else math.degrees(float(theta)) % 360,
        "vertices": [list(v) for v in grasp.polygon().float_vertices().tolist()],
        "force_closure": True,
    }
