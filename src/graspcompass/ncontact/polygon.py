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
from functools import cmp_to_key
from typing import Any

import numpy as np
import sympy as sp

from ..boundary.inputs import angle_values, force_value
from ..geometry import Point
from ..geometry.exact import approx, canon
from ..geometry.trig import sincos
from . import _hull
from ._signs import exact_sgn

__all__ = ["Candidate", "InternalForcePolygon", "covers", "exact_sgn", "float_sgn"]


@dataclass
class Candidate:
    """A point q of Q's candidates, in homogeneous form ``q = (X, Y) / W`` (W > 0 exactly).

    Attributes
    ----------
    X, Y, W : number
        Homogeneous coordinates (exact polynomials in the kernel's generators, or
        floats with W = 1): quotients are reduced only when :attr:`q` is asked for.
    bases : tuple
        The dual bases (constraint indices, see
        :meth:`graspcompass.ncontact.NContactGrasp.constraint_labels`) giving q;
        for ``"max-normal"`` the two ties of its line.
    """

    X: Any
    Y: Any
    W: Any
    bases: tuple
    _q: tuple | None = field(default=None, repr=False)
    _f: tuple | None = field(default=None, repr=False)

    @property
    def q(self) -> tuple:
        """The coordinates ``(X/W, Y/W)`` (canonical form on the exact path)."""
        if self._q is None:
            if isinstance(self.W, float) or self.W == 1:
                self._q = (self.X, self.Y)
            else:
                self._q = (canon(self.X / self.W), canon(self.Y / self.W))
        return self._q

    def floats(self) -> tuple[float, float]:
        """``q`` in double precision (20-digit evaluations of X, Y, W)."""
        if self._f is None:
            if isinstance(self.W, float):
                self._f = (self.X / self.W, self.Y / self.W)
            else:
                w = approx(self.W, 25)
                self._f = (float(approx(self.X, 25) / w), float(approx(self.Y, 25) / w))
        return self._f


def float_sgn(scale: float):
    """A float sign with an absolute tolerance of 1e-10 · scale² (the numeric path)."""
    tol = 1e-10 * max(1.0, scale) ** 2

    def sgn(v: Any, what: str) -> int:
        v = float(v)
        return 0 if abs(v) <= tol else (1 if v > 0 else -1)

    return sgn


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
    _floats: np.ndarray | None = field(default=None, repr=False)
    _pending: tuple | None = field(default=None, repr=False)
    _alpha: np.ndarray | None = field(default=None, repr=False)
    _support_index: list | None = field(default=None, repr=False)
    _order: np.ndarray | None = field(default=None, repr=False)

    # -- construction -------------------------------------------------------------
    @classmethod
    def build(
        cls,
        points: list[tuple[Any, Any, Any]],
        bases: list[tuple],
        rays: list[tuple],
        numeric: bool,
    ) -> InternalForcePolygon:
        """Q as the hull of homogeneous points ``(X, Y, W)``, W > 0 (float path, max-normal)."""
        if numeric:
            return cls._build_float(points, bases, rays)
        sgn = exact_sgn
        groups: list[list[int]] = []
        for i, p in enumerate(points):
            for g in groups:
                if _equal(points[g[0]], p, sgn):
                    g.append(i)
                    break
            else:
                groups.append([i])
        cands = [Candidate(*points[g[0]], tuple(bases[i] for i in g)) for g in groups]
        rays = [r for r in rays if sgn(r[0], "a ray") != 0 or sgn(r[1], "a ray") != 0]
        cone = _hull.feasible_cone(rays, sgn)
        h = _hull.hull([(c.X, c.Y, c.W) for c in cands], sgn) if cands else []
        if rays:
            hp = [(cands[j].X, cands[j].Y, cands[j].W) for j in h]
            h = [
                i
                for k, i in enumerate(h)
                if cone is not None and _hull.open_cones_meet(_normal_cone(hp, k), cone, sgn)
            ]
        return cls(cands, h, rays, cone, numeric)

    @classmethod
    def _build_float(
        cls, points: list[tuple], bases: list[tuple], rays: list[tuple]
    ) -> InternalForcePolygon:
        """The float path: relative tolerances per predicate, never a global one.

        Points within 1e-9 of each other relative to the first (:func:`_float_close`, the
        web page's rule too) are one candidate: copies of one dual vertex from several
        bases round their own ways.  Near-collinear points are dropped only when within
        1e-12 of the relative orientation (their support values differ by less than
        that); v(θ) on the feasible arc is the max over every hull point (the vertices
        reported are those whose normal cone meets the open feasible cone).
        """
        P = np.array(
            [(float(p[0]) / float(p[2]), float(p[1]) / float(p[2])) for p in points], dtype=float
        ).reshape(-1, 2)
        groups: list[list[int]] = []
        for i in range(len(P)):
            for g in groups:
                if _float_close(P[g[0]], P[i]):
                    g.append(i)
                    break
            else:
                groups.append([i])
        cands = [
            Candidate(float(P[g[0], 0]), float(P[g[0], 1]), 1.0, tuple(bases[i] for i in g))
            for g in groups
        ]
        h = _float_hull(np.array([(c.X, c.Y) for c in cands]).reshape(-1, 2))
        unit = []
        for r in rays:
            n = math.hypot(float(r[0]), float(r[1]))
            if n > 1e-12:
                unit.append((float(r[0]) / n, float(r[1]) / n))
        sgn = float_sgn(1.0)  # unit vectors: 1e-10 absolute
        cone = _hull.feasible_cone(unit, sgn)
        keep = h
        if unit:
            hp = [(cands[j].X, cands[j].Y, 1.0) for j in h]
            keep = []
            for k, i in enumerate(h):
                nc = _normal_cone(hp, k)
                if nc != ():
                    nc = tuple(tuple(np.asarray(v) / (np.hypot(*v) or 1.0)) for v in nc)
                if cone is not None and _hull.open_cones_meet(nc, cone, sgn):
                    keep.append(i)
        out = cls(cands, keep, unit, cone, True)
        out._support_index = h
        return out

    @classmethod
    def from_cones(
        cls, verts: list, rays: list[tuple], pending: tuple | None = None
    ) -> InternalForcePolygon:
        """Q from exact dual vertices with their primal cones (no hull, no quotient).

        A dual vertex projects to a vertex of Q iff one of its bases is optimal on
        an open cone of directions (primal and dual feasible there); the vertices
        are ordered counter-clockwise by those cones.  The others are redundant.
        """
        sgn = exact_sgn
        groups: list[dict] = []  # the dual vertices: bases with the same solution
        for v in verts:
            for g in groups:
                if set(v.basis) <= g["tight"]:
                    g["members"].append(v)
                    break
            else:
                groups.append({"tight": v.tight, "members": [v]})
        active: list[Any] = []
        passive: list[Any] = []
        for g in groups:
            cones = [m.cone for m in g["members"] if m.cone is not None]
            (active if cones else passive).append((g, cones[0] if cones else None))

        def by_cone(a: tuple[dict, tuple], b: tuple[dict, tuple]) -> int:
            return _direction_cmp(a[1][0], b[1][0], sgn)

        active.sort(key=cmp_to_key(by_cone))

        def cand(g: dict) -> Candidate:
            m = g["members"][0]
            return Candidate(-m.u[0], -m.u[1], m.W, tuple(x.basis for x in g["members"]))

        cands: list[Candidate] = []
        for g, _ in active:
            c = cand(g)
            if cands and _close(cands[-1], c) and _equal_h(cands[-1], c, sgn):
                cands[-1].bases += c.bases
                continue
            cands.append(c)
        if len(cands) > 1 and _close(cands[0], cands[-1]) and _equal_h(cands[0], cands[-1], sgn):
            cands[0].bases += cands.pop().bases
        nv = len(cands)
        out = cls(cands, list(range(nv)), rays, _hull.feasible_cone(rays, sgn), False)
        out._add_passive([g["members"] for g, _ in passive])
        out._pending = pending
        return out

    def _add_passive(self, groups: list[list]) -> None:
        """Add dual vertices that are optimal on no open cone (redundant, or equal to a vertex)."""
        for members in groups:
            m = members[0]
            c = Candidate(-m.u[0], -m.u[1], m.W, tuple(x.basis for x in members))
            same = [d for d in self.candidates if _close(d, c) and _equal_h(d, c, exact_sgn)]
            if same:
                same[0].bases += c.bases
            else:
                self.candidates.append(c)

    def _resolve(self) -> None:
        """Decide exactly the float-screened passive bases (on the first ask for them)."""
        if self._pending is None:
            return
        from ._dual import verify_basis

        dets, bases = self._pending
        self._pending = None
        found = [v for v in (verify_basis(dets, b) for b in bases) if v is not None]
        groups: list[list] = []
        for v in found:
            for g in groups:
                if set(v.basis) <= g[0].tight:
                    g.append(v)
                    break
            else:
                groups.append([v])
        known = {b for c in self.candidates for b in c.bases}
        self._add_passive([g for g in groups if not {x.basis for x in g} & known])

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
        self._resolve()
        keep = set(self.vertex_index)
        return [c for i, c in enumerate(self.candidates) if i not in keep]

    def all_candidates(self) -> list[Candidate]:
        """Every distinct projected dual vertex: the vertices first, then the redundant ones."""
        self._resolve()
        return list(self.candidates)

    def float_vertices(self) -> np.ndarray:
        """The vertices as an array of shape (m, 2) of doubles (correctly rounded)."""
        if self._floats is None:
            self._floats = np.array(
                [self.candidates[i].floats() for i in self.vertex_index], dtype=float
            ).reshape(-1, 2)
        return self._floats

    def _normal_angles(self) -> tuple[np.ndarray, np.ndarray]:
        """Sorted polar angles where each vertex's normal cone starts, and the vertex of each."""
        if self._alpha is None or self._order is None:
            V = self.float_vertices()
            d = V - np.roll(V, 1, axis=0)  # edge from vertex k-1 to k; outward normal (dy, -dx)
            a = np.mod(np.arctan2(-d[:, 0], d[:, 1]), 2 * np.pi)
            order = np.argsort(a)
            self._alpha, self._order = a[order], order
        return self._alpha, self._order

    def _float_rays(self) -> np.ndarray:
        return np.array(
            [[float(v) if self.numeric else float(approx(v, 20)) for v in r] for r in self.rays],
            dtype=float,
        ).reshape(-1, 2)

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
        if R.size and self._support_index is not None:  # every hull point, not only vertices
            V = np.array(
                [self.candidates[i].floats() for i in self._support_index], dtype=float
            ).reshape(-1, 2)
        flat = t.reshape(-1)
        E = np.empty((flat.size, 2))
        np.sin(flat, out=E[:, 0])
        np.cos(flat, out=E[:, 1])
        E[:, 1] *= -1.0  # e(θ) = (sin θ, -cos θ), eq. (26)
        if not R.size and len(V) >= 3:  # the normal cone holding e: O(log m) per θ
            alpha, order = self._normal_angles()
            phi = np.mod(flat - np.pi / 2, 2 * np.pi)  # polar angle of e(θ)
            k = order[np.searchsorted(alpha, phi, side="right") - 1]
            out = V[k, 0] * E[:, 0] + V[k, 1] * E[:, 1]
        # broadcasting, not BLAS: (N, 2) @ (2, m) with m ~ 10 is faster without threads
        elif V.size:
            out = (E[:, :1] * V[:, 0] + E[:, 1:] * V[:, 1]).max(axis=1)
        else:
            out = np.full(flat.size, -np.inf)
        if R.size:
            out[((E[:, :1] * R[:, 0] + E[:, 1:] * R[:, 1]) > 0).any(axis=1)] = np.inf
        if fe != 1:
            out *= fe
        out = out.reshape(t.shape)
        return float(out) if out.ndim == 0 else out

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
            c = self.candidates[i]
            num = canon(c.X * e[0] + c.Y * e[1])  # q·e = num / W, W > 0
            if (
                best is None
                or exact_sgn(num * best[1] - best[0] * c.W, "a difference of k values") > 0
            ):
                best, arg = (num, c.W), k
        if best is None:
            return sp.oo, None
        return canon(best[0] * external_force / best[1]), arg

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


def _equal(a: tuple, b: tuple, sgn: Any) -> bool:
    """Homogeneous points ``(X, Y, W)`` equal (W > 0)."""
    return (
        sgn(a[0] * b[2] - b[0] * a[2], "a difference") == 0
        and sgn(a[1] * b[2] - b[1] * a[2], "a difference") == 0
    )


def _equal_h(a: Candidate, b: Candidate, sgn: Any) -> bool:
    return _equal((a.X, a.Y, a.W), (b.X, b.Y, b.W), sgn)


def _float_close(a: Any, b: Any) -> bool:
    """``|a - b|_1 <= 1e-9 (1 + |a|_1)`` for float points: one candidate on the float path
    (and on the web page, ``ncontact.js``: the same rule, in the same order)."""
    ax, ay, bx, by = float(a[0]), float(a[1]), float(b[0]), float(b[1])
    return abs(ax - bx) + abs(ay - by) <= 1e-9 * (1 + abs(ax) + abs(ay))


def _close(a: Candidate, b: Candidate) -> bool:
    """Within 1e-9 in double precision: only then is the exact (costly) equality tried.

    Points further apart are distinct: their 25-digit interval evaluations differ.
    """
    return _float_close(a.floats(), b.floats())


def _half(v: tuple, sgn: Any) -> int:
    sy = sgn(v[1], "a direction")
    return 0 if sy > 0 or (sy == 0 and sgn(v[0], "a direction") > 0) else 1


def _direction_cmp(a: tuple, b: tuple, sgn: Any) -> int:
    """Order of two directions by polar angle in [0, 2π)."""
    ha, hb = _half(a, sgn), _half(b, sgn)
    if ha != hb:
        return ha - hb
    return -sgn(a[0] * b[1] - a[1] * b[0], "an orientation")


def _normal_cone(poly: list[tuple], k: int) -> tuple:
    """The cone of outward normals at vertex k of a convex polygon (ccw, homogeneous)."""
    m = len(poly)
    if m == 1:
        return ()

    def edge(a: tuple, b: tuple) -> tuple:  # direction of b - a, scaled by W_a W_b > 0
        return (b[0] * a[2] - a[0] * b[2], b[1] * a[2] - a[1] * b[2])

    if m == 2:
        u = edge(poly[k], poly[1 - k])
        return ((-u[1], u[0]), (u[1], -u[0]))
    e1 = edge(poly[k - 1], poly[k])
    e2 = edge(poly[k], poly[(k + 1) % m])
    return ((e1[1], -e1[0]), (e2[1], -e2[0]))


def _same_direction(a: tuple, b: tuple) -> bool:
    return (
        exact_sgn(a[0] * b[1] - a[1] * b[0], "an orientation") == 0
        and exact_sgn(a[0] * b[0] + a[1] * b[1], "a dot product") > 0
    )


def covers(cones: list[tuple], feasible: tuple | None) -> bool:
    """Whether exact cones ``(start, end)`` cover the feasible directions.

    ``feasible`` is ``()`` for all directions (force closure) or the feasible
    cone.  When they do, every direction that can be held has an optimal basis among
    the cones' bases, so Q is the hull of their points and nothing is missing: the
    certificate of the float-screened enumeration.  The cones are swept in the order
    of their float start angles; each step (the next start lies in the arc covered so
    far) is decided exactly, so a wrong float order can only make the check fail.
    """
    if feasible is None or not cones:
        return False
    full = feasible == ()
    s0 = cones[0][0] if full else feasible[0]
    halves: dict[int, int] = {}

    def half(v: tuple) -> int:  # 0: in [s0, s0 + π), 1: in [s0 + π, s0 + 2π)
        key = id(v)
        if key not in halves:
            c = exact_sgn(s0[0] * v[1] - s0[1] * v[0], "an orientation")
            d = exact_sgn(s0[0] * v[0] + s0[1] * v[1], "a dot product") if c == 0 else 0
            halves[key] = 0 if c > 0 or (c == 0 and d > 0) else 1
        return halves[key]

    def rel(a: tuple, b: tuple) -> int:  # compare angles measured from s0 in [0, 2π)
        ha, hb = half(a), half(b)
        if ha != hb:
            return ha - hb
        return -exact_sgn(a[0] * b[1] - a[1] * b[0], "an orientation")

    def angle(v: tuple) -> float:
        f = [float(approx(x, 20)) for x in (*v, *s0)]
        return (math.atan2(f[1], f[0]) - math.atan2(f[3], f[2])) % (2 * math.pi)

    order = sorted(cones, key=lambda c: angle(c[0]))
    if not _same_direction(order[0][0], s0):
        return False
    reach = order[0][1]
    for c in order[1:]:
        if rel(c[0], reach) > 0:
            return False  # a gap (or a wrong float order)
        if full and rel(c[1], c[0]) <= 0:
            return True  # this cone runs past s0: the whole circle is covered
        if rel(c[1], reach) > 0:
            reach = c[1]
    if full:
        return _same_direction(reach, s0)
    return _same_direction(reach, feasible[1])


def _float_hull(P: np.ndarray) -> list[int]:
    """Strict convex hull (ccw indices) of float points, orientation relative to 1e-12."""
    m = len(P)
    if m <= 2:
        return list(range(m)) if m < 2 or np.any(P[0] != P[1]) else [0]
    tol = 1e-12 * max(1.0, float(np.abs(P).max()))

    def cmp(i: int, j: int) -> int:  # x within tol counts as equal: ties go by y
        dx = P[i, 0] - P[j, 0]
        if abs(dx) > tol:
            return -1 if dx < 0 else 1
        dy = P[i, 1] - P[j, 1]
        return 0 if dy == 0 else (-1 if dy < 0 else 1)

    order = sorted(range(m), key=cmp_to_key(cmp))

    def turn(o: int, a: int, b: int) -> bool:
        u, w = P[a] - P[o], P[b] - P[o]
        c = u[0] * w[1] - u[1] * w[0]
        return c > 1e-12 * math.hypot(*u) * math.hypot(*w)

    def chain(seq: list[int]) -> list[int]:
        out: list[int] = []
        for i in seq:
            while len(out) >= 2 and not turn(out[-2], out[-1], i):
                out.pop()
            out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    h = lower[:-1] + upper[:-1]
    return h if len(h) >= 2 else [order[0], order[-1]]
