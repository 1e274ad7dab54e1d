"""The n-contact grasp: contacts with friction, a centre of mass and an effort.

The paper's model (§2) for any number n >= 2 of planar point contacts.  Each
contact has two cone edges ``d = n ± μ J n`` (normal component 1) with wrench
``g = (d, p × d)`` about the centre of mass O (``p × d = p_x d_y - p_y d_x``).  For
the load ``F_e e(θ)`` at O, ``e(θ) = (sin θ, -cos θ)`` (eq. (26)), the contacts must
supply ``-F_e (e, 0)`` (eq. (4)):

    v(θ) = min { c·a : G a = -F_e (e(θ), 0), a >= 0 }

for a linear effort ``c·a``, with its dual ``max { -F_e y_f·e : G^T y <= c }``, so
``v(θ) = F_e h_Q(e(θ))`` with ``Q = { -y_f : G^T y <= c }``
(:class:`~graspcompass.ncontact.polygon.InternalForcePolygon`).  For n = 2 with the
paper's effort, Q = conv{V_1, ..., V_4, O} (eqs. (25), (27)-(39)).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..boundary.errors import InputError
from ..boundary.inputs import force_value, real_value
from ..geometry import Point
from ..geometry.exact import canon
from . import _dual
from .contact import Contact, read_contact
from .effort import read_effort
from .errors import InvalidContactError, UnboundedEffortError
from .polygon import Candidate, InternalForcePolygon, covers, exact_sgn

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["NContactGrasp"]

#: Most contacts accepted (the exact enumeration is C(2n, 3) bases).
MAX_CONTACTS = 24


class NContactGrasp:
    """A planar object held at n >= 2 point contacts with Coulomb friction.

    Parameters
    ----------
    contacts : sequence
        One entry per contact: a :class:`~graspcompass.ncontact.contact.Contact`,
        ``(x, y, nx, ny, mu)``, ``(x, y, angle, mu)`` or a dict (see
        :func:`~graspcompass.ncontact.contact.read_contact`).  Text is read exactly
        (``"sqrt(3)/2"``, ``"60deg"``); a float anywhere selects the numeric path.
    com : pair, optional
        The centre of mass O (default the origin).
    effort : str or sequence, optional
        ``"sum-normal"`` (default), ``"pair:I,J"``, ``"paper"`` (n = 2),
        ``"max-normal"``, or custom weights (:mod:`~graspcompass.ncontact.effort`).
    exhaustive : bool, optional
        Exact path: decide every one of the C(2n, 3) bases exactly.  By default the
        bases are screened in double precision and the result is *certified*: the
        exact primal cones of the verified bases must cover the directions that can
        be held (else the exhaustive enumeration runs).  Q and v(θ) are exact
        either way; only the list of redundant dual vertices depends on the screen
        (a basis the screen finds infeasible by more than 1e-6 is not listed).

    Examples
    --------
    >>> g = NContactGrasp([(1, 0, -1, 0, "1/2"), (-1, 0, 1, 0, "1/2"), (0, -1, 0, 1, "1/2")])
    >>> g.force_closure
    True
    >>> g.k(0)
    1
    """

    def __init__(
        self,
        contacts: Sequence[Any],
        com: Any = (0, 0),
        effort: Any = "sum-normal",
        *,
        exhaustive: bool = False,
    ) -> None:
        if isinstance(contacts, (str, bytes)) or not isinstance(contacts, Sequence):
            raise InvalidContactError("contacts: expected a sequence of contacts")
        if not 2 <= len(contacts) <= MAX_CONTACTS:
            raise InvalidContactError(
                f"contacts: expected 2 to {MAX_CONTACTS} contacts, got {len(contacts)}"
            )
        cs = [read_contact(c, i + 1) for i, c in enumerate(contacts)]
        try:
            ox, oy = (real_value(v, f"com {k}") for v, k in zip(com, "xy"))
        except (TypeError, ValueError) as exc:
            if isinstance(exc, InputError):
                raise InvalidContactError(str(exc)) from None
            raise InvalidContactError("com: expected a pair (x, y)") from None
        if len(tuple(com)) != 2 or ox.free_symbols or oy.free_symbols:
            raise InvalidContactError("com: expected a pair of numbers (x, y)")
        self.numeric = any(c.numeric for c in cs) or ox.is_Float or oy.is_Float
        if self.numeric:
            cs = [
                Contact(
                    tuple(float(v) for v in c.p),
                    tuple(float(v) for v in c.n),
                    sp.Float(float(c.mu)),
                    True,
                )
                for c in cs
            ]
            self.com = (float(ox), float(oy))
        else:
            self.com = (canon(ox), canon(oy))
        self.contacts = tuple(cs)
        self.effort = read_effort(effort, self.contacts)
        self._polygon: InternalForcePolygon | None = None
        self._closure: bool | None = None
        self.exhaustive = bool(exhaustive)
        self._dets: Any = None

    @classmethod
    def from_grasp(cls, grasp: Grasp, effort: Any = "paper") -> NContactGrasp:
        """The n = 2 case: a :class:`~graspcompass.grasp.Grasp` (paper's effort by default).

        ``n1 = (-sin φ1, -cos φ1)`` at ``P1 = (x1, y)`` and ``n2 = (sin φ2, -cos φ2)`` at
        ``P2 = (-x2, y)`` (§2.2.1), the centre of mass at the origin.
        """
        if grasp.numeric:
            f = float
            c1 = (f(grasp.x1), f(grasp.y), -f(grasp.s1), -f(grasp.c1), f(grasp.mu1))
            c2 = (-f(grasp.x2), f(grasp.y), f(grasp.s2), -f(grasp.c2), f(grasp.mu2))
        else:
            c1 = (grasp.x1, grasp.y, -grasp.s1, -grasp.c1, grasp.mu1)
            c2 = (-grasp.x2, grasp.y, grasp.s2, -grasp.c2, grasp.mu2)
        return cls([c1, c2], effort=effort)

    def __repr__(self) -> str:
        cs = ", ".join(f"(p={c.p}, n={c.n}, mu={c.mu})" for c in self.contacts)
        return f"NContactGrasp([{cs}], com={self.com}, effort={self.effort.name!r})"

    @property
    def n(self) -> int:
        """The number of contacts."""
        return len(self.contacts)

    # -- the LP ----------------------------------------------------------------------
    def edges(self) -> list[tuple[int, int, tuple]]:
        """``(contact, side, d)`` of the 2n cone edges (side +1: ``n + μJn``, -1: ``n - μJn``)."""
        out = []
        for i, c in enumerate(self.contacts):
            dp, dm = c.edges()
            out += [(i, 1, dp), (i, -1, dm)]
        return out

    def wrenches(self) -> list[tuple]:
        """The edge wrenches ``g_j = (d_x, d_y, (p - O) × d)`` (the columns of G)."""
        out = []
        ox, oy = self.com
        for i, _, d in self.edges():
            px, py = self.contacts[i].p
            t = (px - ox) * d[1] - (py - oy) * d[0]
            out.append((d[0], d[1], t if self.numeric else canon(t)))
        return out

    def costs(self) -> list[Any]:
        """The cost ``c_j = w_i · d_j`` of a unit weight on each edge (linear efforts)."""
        weights = self.effort.weights  # None exactly when the effort is not linear
        if weights is None:
            raise InvalidContactError("the effort 'max-normal' is not linear: it has no edge costs")
        out = []
        for i, _, d in self.edges():
            w = weights[i]
            c = w[0] * d[0] + w[1] * d[1]
            out.append(c if self.numeric else canon(c))
        return out

    def constraint_labels(self) -> list[str]:
        """Names of the dual constraints: ``"P1+"``, ``"P1-"``, ..., ``"effort>=0"``."""
        labels = [f"P{i + 1}{'+' if s > 0 else '-'}" for i, s, _ in self.edges()]
        if self.effort.linear and self.effort.nonnegative:
            labels.append("k>=0" if self.effort.name == "paper" else "effort>=0")
        return labels

    def dual_system(self) -> tuple[list[list[Any]], list[Any]]:
        """The dual constraints ``rows · u <= rhs`` of a linear effort, u = (y, [z]).

        With the sign constraint ``c·a >= 0`` (the paper's ``k >= 0``) the dual has
        one more variable z >= 0: ``g_j·y + c_j z <= c_j`` and ``-z <= 0``.
        """
        G, c = self.wrenches(), self.costs()
        zero, one = (0.0, 1.0) if self.numeric else (sp.Integer(0), sp.Integer(1))
        if not self.effort.nonnegative:
            return [list(g) for g in G], list(c)
        rows = [[*g, cj] for g, cj in zip(G, c)] + [[zero, zero, zero, -one]]
        return rows, [*c, zero]

    # -- Q --------------------------------------------------------------------------
    def polygon(self) -> InternalForcePolygon:
        """Q (computed once): vertices, redundant dual vertices, recession directions."""
        if self._polygon is None:
            self._polygon = self._build()
        return self._polygon

    def _build(self) -> InternalForcePolygon:
        G = [list(g) for g in self.wrenches()]
        if not self.effort.linear:
            from . import maxnormal

            points, bases = maxnormal.candidates(self)
            if not points:
                raise UnboundedEffortError("no direction has a positive effort")
            return InternalForcePolygon.build(points, bases, self._q_rays(G), self.numeric)
        rows, rhs = self.dual_system()
        if self.numeric:
            verts = _dual.float_vertices(np.array(rows, dtype=float), np.array(rhs, dtype=float))
            if not verts:
                raise self._unbounded()
            pts = [(-v.u[0], -v.u[1], 1.0) for v in verts]
            rays = self._q_rays(rows)
            return InternalForcePolygon.build(pts, [v.basis for v in verts], rays, True)
        dets = self._dets = _dual.Dets(rows, rhs)
        if not self.exhaustive:  # float screen, certified by the exact coverage of the cones
            active, passive = _dual.screened_vertices(rows, rhs, dets)
            cones = [v.cone for v in active]
            if covers(cones, ()):  # every load direction is held: Q is bounded, no rays
                return InternalForcePolygon.from_cones(active, [], (dets, passive))
            rays = self._q_rays(rows, dets)
            Q = InternalForcePolygon.from_cones(active, rays, (dets, passive))
            if covers(cones, Q.cone):
                return Q
        else:
            rays = self._q_rays(rows, dets)
        verts = _dual.exact_vertices(rows, rhs, dets)
        if not verts:
            raise self._unbounded()
        return InternalForcePolygon.from_cones(verts, rays)

    @staticmethod
    def _unbounded() -> UnboundedEffortError:
        return UnboundedEffortError(
            "the effort can be made arbitrarily negative (its dual "
            "is empty): no least effort exists"
        )

    def _q_rays(self, rows: list, dets: Any = None) -> list[tuple]:
        """Recession directions of Q: minus the force part of the dual's extreme rays."""
        if self.numeric:
            r = _dual.float_rays(np.array(rows, dtype=float))
        else:
            r = _dual.exact_rays(rows, dets)
        if len(rows[0]) == 3:
            self._closure = not r  # the same cone as force closure's (rows = G)
        return [(-v[0], -v[1]) for v in r]

    @property
    def force_closure(self) -> bool:
        """True when the contacts can resist every wrench (the cone of G is all of R³).

        Decided exactly: by Farkas' lemma, iff ``{r : G^T r <= 0} = {0}``.
        """
        if self._closure is None:
            shared = (
                self.effort.linear
                and not self.effort.nonnegative
                and not self.numeric
                and self._polygon is not None
            )
            self._q_rays([list(g) for g in self.wrenches()], self._dets if shared else None)
        assert self._closure is not None  # set by _q_rays on the three-row wrenches
        return self._closure

    def vertices(self) -> list[Point]:
        """The vertices of Q, counter-clockwise."""
        return self.polygon().vertices

    def k(self, theta: Any, external_force: Any = 1) -> Any:
        """The least effort ``v(θ) = F_e max_q q·e(θ)`` (+inf where the load cannot be held).

        For n = 2 and the paper's effort this is ``k_grasp(θ)`` of eq. (25).  Exact for
        an exact θ, doubles for a float or an array (vectorised).
        """
        return self.polygon().support(theta, external_force)

    def arc(self) -> tuple[float, float] | None:
        """The closed arc of θ where the load can be held (see ``InternalForcePolygon.arc``)."""
        return self.polygon().arc()

    def worst(self, external_force: Any = 1) -> tuple[Any, Any]:
        """The largest least effort over all load directions and a direction that needs it.

        ``max_θ v(θ) = F_e max_q |q|`` (the support function's maximum is the farthest
        vertex): the worst squeeze of a three-jaw gripper over all orientations of the
        part.  Returns ``(value, θ)``; exact ``(F_e sqrt(|q|²), θ)`` with θ a float
        (radians) on the exact path, ``(inf, None)`` without force closure of the loads.
        """
        Q = self.polygon()
        fe = force_value(external_force)
        if not Q.bounded:
            return (float("inf") if self.numeric else sp.oo), None
        best: Any = None  # |q|²: a float, or (num, den) on the exact path
        arg: Candidate | None = None
        for i in Q.vertex_index:
            c = Q.candidates[i]
            if self.numeric:
                r2 = c.X * c.X + c.Y * c.Y
                if best is None or r2 > best:
                    best, arg = r2, c
            else:
                r2 = (c.X * c.X + c.Y * c.Y, c.W * c.W)  # |q|² = num / den
                if (
                    best is None
                    or exact_sgn(
                        r2[0] * best[1] - best[0] * r2[1], "a difference of squared lengths"
                    )
                    > 0
                ):
                    best, arg = r2, c
        assert arg is not None  # a bounded Q has vertices
        qx, qy = arg.floats()
        theta = math.atan2(qy, qx) + math.pi / 2  # e(θ) = (sin θ, -cos θ) along q
        theta %= 2 * math.pi
        if self.numeric:
            return float(fe) * math.sqrt(best), theta
        return canon(fe) * sp.sqrt(canon(best[0] / best[1])), theta

    def forces(self, theta: Any, external_force: Any = 1) -> dict[str, Any]:
        """The contact forces at the optimum for one θ and the tight edges.

        Returns a dict with ``effort`` (v(θ)), ``vertex`` (the maximising q),
        ``basis`` (labels of the tight dual constraints), ``weights`` (edge weight
        per edge label, the normal force it carries) and ``forces`` (the force at
        each contact, ``Σ a_j d_j``).  None values where the load cannot be held.

        For ``"max-normal"`` (min t with N_i <= t) ``basis`` lists the edges that
        carry load, and two more keys say what complementary slackness with the
        maximising dual direction allows: ``tight`` (every edge that may carry load)
        and ``largest`` (the contacts, 1-based, whose normal force is the largest,
        v(θ)).
        """
        from ._forces import optimal_forces

        return optimal_forces(self, theta, force_value(external_force))
