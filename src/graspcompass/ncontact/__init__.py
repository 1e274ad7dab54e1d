"""The internal force diagram for n planar contacts (beyond the paper's two).

For n >= 2 point contacts with Coulomb friction and a load ``F_e e(θ)`` at the
centre of mass (``e(θ) = (sin θ, -cos θ)``, eq. (26)), the least effort is
``v(θ) = F_e max_{q ∈ vert Q} q·e(θ)`` for a convex polygon Q found exactly by
basis enumeration of the LP's dual; its polar plot is the outer envelope of the
Thales circles on O q, as in the paper's Fig. 5 (there Q = conv{V_1..V_4, O}).

Modules: :mod:`.contact` (one contact), :mod:`.effort` (the efforts),
:mod:`.model` (:class:`NContactGrasp`), :mod:`.polygon` (Q and v(θ)),
:mod:`.maxnormal` (the sublinear effort), ``_dual`` (exact basis enumeration),
``_hull`` (exact 2-D hull), ``_forces`` (the optimal contact forces).
"""

from __future__ import annotations

from .contact import Contact, read_contact
from .effort import EFFORTS, Effort, read_effort
from .errors import (
    DegenerateGraspError,
    EffortError,
    InvalidContactError,
    NContactError,
    UnboundedEffortError,
    UndecidedSignError,
)
from .model import MAX_CONTACTS, NContactGrasp
from .polygon import Candidate, InternalForcePolygon

__all__ = [
    "EFFORTS",
    "MAX_CONTACTS",
    "Candidate",
    "Contact",
    "DegenerateGraspError",
    "Effort",
    "EffortError",
    "InternalForcePolygon",
    "InvalidContactError",
    "NContactError",
    "NContactGrasp",
    "UnboundedEffortError",
    "UndecidedSignError",
    "read_contact",
    "read_effort",
]
