"""The placed grasp: a paper-frame grasp and the rigid motion to the world frame.

A :class:`WorldGrasp` holds the :class:`~graspcompass.Grasp` of §2.2.1 and the
rotation and translation between the paper's frame and the world frame, and
reads points, vectors, angles θ (eq. (26)) and forces (eqs. (16), (17), (25))
in the world frame.  It is documented, pickled and doctested as
:class:`graspcompass.world.WorldGrasp` (the examples there use
:func:`~graspcompass.place_grasp`).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import sympy as sp

from ..boundary.errors import InputError
from ..boundary.inputs import real_value
from ..geometry.exact import has_float
from ..grasp import Grasp
from ._arith import Vec, _c, _dot, _no_symbols, _sign, _sqrt, _sub, _vec

__all__ = ["WorldGrasp"]


@dataclasses.dataclass(frozen=True)
class WorldGrasp:
    """A paper-frame grasp with the rigid motion that places it in the world frame.

    A world point ``w`` has paper coordinates ``((w - origin)·ex, (w - origin)·ey)``;
    a paper point ``p`` is at ``origin + p.x ex + p.y ey`` in the world.

    Attributes
    ----------
    grasp : Grasp
        The grasp in the paper's frame (§2.2.1).
    origin : tuple
        The centre of mass O in world coordinates.
    ex, ey : tuple
        The paper's x- and y-axis as world unit vectors (``ey`` is ``ex`` turned
        counter-clockwise by a quarter turn: a rotation, never a reflection).
    beta : sympy.Expr or float
        The angle of ``ex`` from the world's x-axis (counter-clockwise): a
        paper-frame angle θ (eq. (26)) is the world angle ``θ + beta``.
    names : tuple of str
        The names of the paper's P1 and P2 (``("B", "A")`` when the contacts swapped).
    contacts, normals : tuple
        The world contact points and inward unit normals, as P1, P2.
    """

    grasp: Grasp
    origin: Vec
    ex: Vec
    ey: Vec
    beta: Any
    names: tuple[str, str]
    contacts: tuple[Vec, Vec]
    normals: tuple[Vec, Vec]

    @property
    def exact(self) -> bool:
        """True for an exact grasp, False on the numeric path (floats)."""
        return not self.grasp.numeric

    @property
    def swapped(self) -> bool:
        """True when the second contact given became the paper's P1."""
        return self.names[0] != self._given_first

    _given_first: str = dataclasses.field(default="A", repr=False)

    def to_paper(self, point: Any) -> Vec:
        """Paper-frame coordinates of a world point.

        Examples
        --------
        >>> from graspcompass import place_grasp
        >>> wg = place_grasp([(3, 5), (-1, 5)], [(-1, 0), (1, 0)], mu=(1, 1), com=(1, 4))
        >>> wg.to_paper((3, 5)), wg.to_world((2, 1))
        ((2, 1), (3, 5))
        """
        p, num = self._read(point, "point")
        o, ex, ey = self._frame(num)
        w = _sub(p, o)
        return _c((_dot(w, ex), _dot(w, ey)), not num)

    def to_world(self, point: Any) -> Vec:
        """World coordinates of a paper-frame point."""
        p, num = self._read(point, "point")
        o, ex, ey = self._frame(num)
        return _c((o[0] + p[0] * ex[0] + p[1] * ey[0], o[1] + p[0] * ex[1] + p[1] * ey[1]), not num)

    def vector_to_paper(self, vector: Any) -> Vec:
        """Paper-frame components of a world vector (a force, a direction)."""
        v, num = self._read(vector, "vector")
        _, ex, ey = self._frame(num)
        return _c((_dot(v, ex), _dot(v, ey)), not num)

    def vector_to_world(self, vector: Any) -> Vec:
        """World components of a paper-frame vector."""
        v, num = self._read(vector, "vector")
        _, ex, ey = self._frame(num)
        return _c((v[0] * ex[0] + v[1] * ey[0], v[0] * ex[1] + v[1] * ey[1]), not num)

    def theta_to_world(self, theta: Any) -> Any:
        """The world angle of the paper-frame direction e(θ) (eq. (26)): ``θ + beta``.

        Both angles are counter-clockwise from the negative y-axis of their frame;
        a float θ (or a float grasp) gives a float.

        Examples
        --------
        >>> from graspcompass import place_grasp
        >>> wg = place_grasp([(0, 1), (0, -1)], [(0, -1), (0, 1)], mu=(1, 1), com=(-1, 0))
        >>> wg.names, wg.ey  # the contacts swapped: the paper's y-axis is the world's +x
        (('B', 'A'), (1, 0))
        >>> wg.beta, wg.theta_to_world(0)  # the paper's "down" (θ = 0) is the world's -x
        (-pi/2, -pi/2)
        """
        t = real_value(theta, "theta")
        return t + self.beta if self._exact_value(t) else float(t) + float(self.beta)

    def theta_to_paper(self, theta_world: Any) -> Any:
        """The paper-frame θ of a world angle: ``theta_world - beta``."""
        t = real_value(theta_world, "theta_world")
        return t - self.beta if self._exact_value(t) else float(t) - float(self.beta)

    def world_degrees(self, theta: Any) -> float:
        """The world angle of a paper-frame θ in degrees, in [0, 360): for reports.

        Examples
        --------
        >>> from graspcompass import place_grasp
        >>> wg = place_grasp([(0, 1), (0, -1)], [(0, -1), (0, 1)], mu=(1, 1), com=(-1, 0))
        >>> wg.world_degrees(0), wg.world_degrees("pi/2")  # the paper's down, its +x
        (270.0, 0.0)
        """
        return math.degrees(float(self.theta_to_world(theta))) % 360.0

    def external_force(self, force: Any) -> tuple[Any, Any]:
        """``(θ, F_e)`` in the paper's frame of a world external force vector at O.

        θ is the paper-frame angle of eq. (26) (``e(θ) = (sin θ, -cos θ)``) and F_e
        the magnitude; exact for an exact grasp and force, floats when either has a
        float.  A zero force is refused.
        """
        f = self.vector_to_paper(force)
        num = isinstance(f[0], float)
        fe = _sqrt(_dot(f, f), not num)
        if _sign(fe, not num) != 1:
            raise InputError("force: the external force must not be zero")
        if num:
            return math.atan2(f[0], -f[1]), fe
        return sp.atan2(f[0], -f[1]), fe

    def internal_force(self, force: Any) -> Any:
        """The least internal force (squeeze along P1P2) for a world external force at O.

        ``F_int = k_grasp(θ)/(x1 + x2) · F_e``, eqs. (17), (25), with θ and F_e read
        off the world vector.  Exact for an exact grasp and force, else a float.
        """
        theta, fe = self.external_force(force)
        return self.grasp.internal_force(theta, fe)

    def contact_forces(self, force: Any) -> dict[str, Vec]:
        """The contact forces at the least internal force, as world vectors by contact name.

        ``F = F_T + k_grasp F_N`` (eq. (16)) in the paper's frame, the normal and
        tangential parts put together with ``n1 = (-s1, -c1)``, ``t1 = (-c1, s1)``,
        ``n2 = (s2, -c2)``, ``t2 = (c2, s2)`` (the columns of L, eq. (5)), then
        turned into the world frame.  They balance the external force and its
        moment about O.  Exact for an exact grasp and force, else floats.
        """
        theta, fe = self.external_force(force)
        g = self.grasp
        F = g.contact_forces(theta, g.k_grasp(theta), fe)
        sc: tuple[Any, ...] = (g.s1, g.c1, g.s2, g.c2)
        if isinstance(theta, float):
            F, sc = [float(v) for v in F], tuple(float(v) for v in sc)
        N1, F1, N2, F2 = F
        s1, c1, s2, c2 = sc
        f1 = (-N1 * s1 - F1 * c1, -N1 * c1 + F1 * s1)
        f2 = (N2 * s2 + F2 * c2, -N2 * c2 + F2 * s2)
        return {self.names[0]: self.vector_to_world(f1), self.names[1]: self.vector_to_world(f2)}

    def _exact_value(self, v: Any) -> bool:
        return self.exact and not has_float(v)

    def _read(self, v: Any, what: str) -> tuple[Vec, bool]:
        """A world or paper vector from outside, and whether it takes the numeric path."""
        p = _vec(v, what)
        _no_symbols(list(p))
        if self._exact_value(p[0]) and self._exact_value(p[1]):
            return p, False
        return (float(p[0]), float(p[1])), True

    def _frame(self, numeric: bool) -> tuple[Vec, Vec, Vec]:
        """The origin and axes, as floats for the numeric path."""
        if not numeric:
            return self.origin, self.ex, self.ey
        o, ex, ey = ((float(v[0]), float(v[1])) for v in (self.origin, self.ex, self.ey))
        return o, ex, ey


# public, documented and pickled as graspcompass.world's (which re-exports them)
WorldGrasp.__module__ = "graspcompass.world"
# so its methods' examples run here (doctest skips a class whose __module__ is another's)
__test__ = {
    f"WorldGrasp.{k}": v
    for k, v in vars(WorldGrasp).items()
    if callable(v) and ">>>" in (v.__doc__ or "")
}
