"""The polygon Q of an n-contact grasp: v(θ) = F_e max_{q ∈ vert Q} q·e(θ).

By LP duality the least effort for the load ``F_e e(θ)`` at the centre of mass,
``e(θ) = (sin θ, -cos θ)`` (eq. (26)), is ``F_e h_Q(e)``, the support function of a
convex polygon Q (for n = 2 and the paper's k, Q = conv{V_1, ..., V_4, O}: eqs. (25),
(27)-(39)).  Its polar plot is the outer envelope of the Thales circles on O q
(Fig. 3, Fig. 5).  Without force closure Q is unbounded: ``v = +inf`` where
``e·r > 0`` for a recession direction r of Q, finite (the max over the vertices)
on the closed arc where ``e·r <= 0`` for all r.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from ..geometry import Point
from ..geometry.exact import approx, canon
from ..geometry.trig import sincos
from ..inputs import angle_values, force_value
from . import _hull
from ._signs import sign

__all__ = ["Candidate", "InternalForcePolygon"]


@dataclass(frozen=True)
class Candidate:
    """A point q = -u_f of a dual vertex, with the bases (or ties) that give it.

    Attributes
    ----------
    q : tuple
        Its coordinates (exact or float).
    bases : tuple of tuple of int
        The dual bases (constraint indices of the LP, see
        :meth:`graspcompass.ncontact.NContactGrasp.constraint_labels`) giving q.
    """

    q: tuple
    bases: tuple


def float_sgn(scale: float):
    """A float sign with an absolute tolerance of 1e-10 · scale² (the numeric path)."""
    tol = 1e-10 * max(1.0, scale) ** 2

    def sgn(v: Any, what: str) -> int:
        v = float(v)
        return 0 if abs(v) <= tol else (1 if v > 0 else -1)
    return sgn


def exact_sgn(v: Any, what: str) -> int:
    """:func:`~graspcompass.ncontact._signs.sign` of a (canonicalised) expression."""
    return sign(canon(v), what)


@dataclass
class InternalForcePolygon:
    """Q with its vertices, the redundant dual vertices and the recession directions.

    Attributes
    ----------
    candidates : list of Candidate
        The distinct projections q of the dual vertices.
    vertex_index : list of int
        Indices into ``candidates`` of the vertices of Q, counter-clockwise.
    rays : list of tuple
        Nonzero recession directions of Q (empty when Q is bounded).
    cone : tuple or None
        The closed cone of load directions ``e`` that can be held, ``(start, end)``
        counter-clockwise; ``()`` for all directions, None when no open arc can be held.
    numeric : bool
        True on the float path.
    """

    candidates: list[Candidate]
    vertex_index: list[int]
    rays: list[tuple]
    cone: tuple | None
    numeric: bool
    _floats: np.ndarray = field(default=None, repr=False)  # type: ignore[assignment]

    # -- construction -------------------------------------------------------------
    @classmethod
    def build(cls, points: list[tuple], bases: list[tuple], rays: list[tuple],
              numeric: bool) -> InternalForcePolygon:
        """Q from the dual vertices' projections, their bases and Q's recession directions."""
        if numeric:
            scale = max([1.0] + [abs(float(v)) for p in points for v in p])
            sgn = float_sgn(scale)
        else:
            sgn = exact_sgn
        groups: list[list[int]] = []
        for i, p in enumerate(points):
            for g in groups:
                q = points[g[0]]
                if sgn(p[0] - q[0], "a difference") == 0 and sgn(p[1] - q[1], "a difference") == 0:
                    g.append(i)
                    break
            else:
                groups.append([i])
        cands = [Candidate(points[g[0]], tuple(bases[i] for i in g)) for g in groups]
        rays = [r for r in rays if sgn(r[0], "a ray") != 0 or sgn(r[1], "a ray") != 0]
        cone = _hull.feasible_cone(rays, sgn)
        h = _hull.hull([c.q for c in cands], sgn) if cands else []
        if rays:
            h = [i for k, i in enumerate(h) if cone is not None and
                 _hull.open_cones_meet(_normal_cone([cands[j].q for j in h], k), cone, sgn)]
        return cls(cands, h, rays, cone, numeric)

    # -- what it holds ----------------------------------------------------------------
    @property
    def bounded(self) -> bool:
        """True when Q is a polygon (every load direction can be held)."""
        return not self.rays

    @property
    def vertices(self) -> list[Point]:
        """The vertices of Q, counter-clockwise (the diameters O q of the Thales circles)."""
        return [Point(*self.candidates[i].q) for i in self.vertex_index]

    @property
    def redundant(self) -> list[Candidate]:
        """Dual vertices whose point is not a vertex of Q: their circles never reach the envelope.

        In Table I(c) of the paper, V_4 = (4/7, 10/7) lies inside the triangle V_1 V_2 V_3.
        """
        keep = set(self.vertex_index)
        return [c for i, c in enumerate(self.candidates) if i not in keep]

    def float_vertices(self) -> np.ndarray:
        """The vertices as an array of shape (m, 2) of doubles (correctly rounded)."""
        if self._floats is None:
            qs = [self.candidates[i].q for i in self.vertex_index]
            self._floats = np.array([[float(v) if self.numeric else float(approx(v, 20))
                                      for v in q] for q in qs], dtype=float).reshape(-1, 2)
        return self._floats

    def _float_rays(self) -> np.ndarray:
        return np.array([[float(v) if self.numeric else float(approx(v, 20)) for v in r]
                         for r in self.rays], dtype=float).reshape(-1, 2)

    # -- the support function ---------------------------------------------------------
    def support(self, theta: Any, external_force: Any = 1) -> Any:
        """``v(θ) = F_e max_q q·e(θ)``; +inf (``oo`` exactly) where the load cannot be held.

        θ is read by :func:`graspcompass.inputs.angle_values`: floats and arrays give
        doubles (an array of the same shape), anything else an exact expression.
        """
        t = angle_values(theta)
        fe = force_value(external_force)
        if isinstance(t, (float, np.ndarray)) or self.numeric:
            return self._support_float(np.asarray(t, dtype=float), float(fe))
        return self.support_exact(t, fe)[0]

    def _support_float(self, t: np.ndarray, fe: float) -> Any:
        V, R = self.float_vertices(), self._float_rays()
        s, c = np.sin(t), np.cos(t)
        with np.errstate(invalid="ignore"):
            vals = np.multiply.outer(s, V[:, 0]) - np.multiply.outer(c, V[:, 1])
            out = vals.max(axis=-1) if V.size else np.full(t.shape, -np.inf)
            if R.size:
                bad = (np.multiply.outer(s, R[:, 0]) - np.multiply.outer(c, R[:, 1]) > 0).any(-1)
                out = np.where(bad, np.inf, out)
        out = out * fe if fe != 1 else out
        return float(out) if np.ndim(out) == 0 else out

    def support_exact(self, theta: sp.Expr, external_force: Any = 1) -> tuple[sp.Expr, int | None]:
        """``(v(θ), i)``: the exact value and the index (into :attr:`vertices`) of a maximiser.

        ``(oo, None)`` where the load cannot be held.
        """
        s, c = sincos(theta)
        e = (s, -c)
        for r in self.rays:
            if exact_sgn(e[0] * r[0] + e[1] * r[1], "e(θ)·r for a recession direction r") > 0:
                return sp.oo, None
        best, arg = None, None
        for k, i in enumerate(self.vertex_index):
            q = self.candidates[i].q
            val = canon(q[0] * e[0] + q[1] * e[1])
            if best is None or exact_sgn(val - best, "a difference of k values") > 0:
                best, arg = val, k
        if best is None:
            return sp.oo, None
        return canon(best * external_force), arg

    def arc(self) -> tuple[float, float] | None:
        """The closed arc of θ (radians, ``lo <= hi < lo + 2π``) where the load can be held.

        ``(0, 2π)`` for force closure; None when no open arc can be held.
        """
        if self.cone is None:
            return None
        if self.cone == ():
            return (0.0, 2 * math.pi)
        (a, b) = self.cone
        fa = [float(v) if self.numeric else float(approx(v, 20)) for v in a]
        fb = [float(v) if self.numeric else float(approx(v, 20)) for v in b]
        # e(θ) = (sin θ, -cos θ) has polar angle θ - π/2
        lo = math.atan2(fa[1], fa[0]) + math.pi / 2
        hi = math.atan2(fb[1], fb[0]) + math.pi / 2
        lo %= 2 * math.pi
        hi = lo + ((hi - lo) % (2 * math.pi) or (2 * math.pi if self.cone else 0.0))
        return (lo, hi)


def _normal_cone(poly: list[tuple], k: int) -> tuple:
    """The cone of outward normals at vertex k of a convex polygon (ccw), ``(start, end)``."""
    m = len(poly)
    if m == 1:
        return ()
    if m == 2:
        a, b = poly[k], poly[1 - k]
        u = (b[0] - a[0], b[1] - a[1])
        return ((-u[1], u[0]), (u[1], -u[0]))
    p, v, nx = poly[k - 1], poly[k], poly[(k + 1) % m]
    e1 = (v[0] - p[0], v[1] - p[1])
    e2 = (nx[0] - v[0], nx[1] - v[1])
    return ((e1[1], -e1[0]), (e2[1], -e2[0]))
