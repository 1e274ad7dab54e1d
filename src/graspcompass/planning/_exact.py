"""The least worst-case squeeze along a pair of polygon edges, proved by branch and bound.

For contacts ``a(s) = A0 + s eA`` and ``b(t) = B0 + t eB`` (0 <= s, t <= 1) on two
straight edges of a counter-clockwise outline, each with its edge's inward normal
``N = J e`` (``J(x, y) = (−y, x)``), the paper's V_n (eqs. (28)-(39)) has a
closed form in the world frame.  With ``d = a − b``, the cone sides of a contact
``c± = N ± μ e`` (at ±ξ from N, tan ξ = μ, eq. (22); any positive length will
do) and O the centre of mass,

    V = −(±d/2 + κ J r),   κ = (c·d) / (d × c),

the sign + and ``r = b − O`` for a side at a, − and ``r = a − O`` for a side at b.
(From equilibrium: with contact i's force on side c and the other contact's
force balancing the load f and the moment about O, the squeeze per jaw is
``−V·f / |d|``; in the paper frame this is ``S_n = ∓(x1 + x2)/2 ± y t_n``,
``C_n = x_j t_n`` with ``t_n = tan(φ ± ξ)``, eqs. (28)-(39), which the tests
check against :func:`graspcompass.batch.closed_form`.)  Condition (1) is that
each cone contains the other contact: ``(b − a) × cA+ < 0 < (b − a) × cA−`` and
``d × cB+ < 0 < d × cB−``, four inequalities linear in (s, t), the signs of the
four denominators ``d × c``.  The squeeze per unit of ``S_f m`` is

    q(s, t) = (g + A) max_n |V_n| / |d|           (every orientation, §5),
    q(s, t) = max(0, max_n M_n + A |V_n|) / |d|   (tilts |ρ| <= τ of gravity g ĝ),

``M_n = max_{|ρ|<=τ} V_n · R_ρ (g ĝ)`` (:func:`graspcompass.sizing._arc.arc_max_many`).

:func:`refine_edge_pair` minimises q over the force-closure part of the square
by branch and bound: every affine form above (``d``, ``r``, ``c·d``, ``d × c``) is
evaluated over a box exactly in interval arithmetic, each operation rounded
outward (:func:`numpy.nextafter`), κ over the force-closure part of the box only
(where ``d × c`` has its sign: κ may be unbounded near the boundary of (1),
where q grows without bound), and ``|V_n|``, ``|d|``, ``M_n`` bounded from them.
A box is dropped when its lower bound is at least ``(1 − tol)`` times the best
value found at a force-closure point; when none is left, the least q over the
edge pair lies in ``[lower, value]``, ``value − lower <= tol · value``: a proof up
to the data's float values (vertices, centre of mass, μ), not an optimiser's
guess.  The upper end is the float value at the reported point (relative error
about 1e-15).

**The boundary of condition (1).**  Boxes whose four denominators cannot all
have their sign (an outward-rounded test) hold no force-closure pair and are
dropped: they are not candidates.  Over every orientation q grows without bound
towards the boundary (``|V_n| → ∞``).  Under a tilt range it need not: ``M_n +
A|V_n|`` tends to −∞ where ``V_n`` turns away from every tilted gravity, and q
stays finite, so its infimum may be approached on the boundary, by pairs at the
edge of a friction cone, and attained by none.  Boxes that straddle the
boundary are bounded with κ over their force-closure part as an interval
unbounded at one end, the product ``κ (±A|r| − Jr·w)`` taken as one interval so
that its sign survives (``_Bounds._blow``), and split until the bound closes; the
points of the boundary nearest them (the force-closure set is a convex polygon
of (s, t), four half-planes in the square), moved ``1e-3 tol`` inside, are tried
as upper bounds.  The result then states it: ``on_boundary`` when the reported
pair is within :data:`BOUNDARY` radians of (1) (:func:`cone_margin`), ``value``
within ``tol`` of the infimum over the force-closure pairs (q tends to a finite
limit on part of the boundary, where the blowing ``V_n`` turns away from every
tilted load, and to +∞ on the rest; the infimum can sit where the two meet).

Examples
--------
A 100 × 60 mm plate, μ = 0.5, its two long sides: the centred pair with
``q = g sqrt(1 + 1/μ²)/2`` (the docstring of :mod:`graspcompass.planning`):

>>> import numpy as np
>>> pair = EdgePair.of((-0.05, -0.03), (0.05, -0.03), (0.05, 0.03), (-0.05, 0.03),
...                    (0.0, 0.0), 0.5)
>>> opt = refine_edge_pair(pair, Load(g=9.81), tol=1e-6)
>>> opt.certified, round(opt.s, 4), round(opt.t, 4)
(True, 0.5, 0.5)
>>> bool(opt.lower <= 9.81 * np.sqrt(5) / 2 <= opt.value <= opt.lower * (1 + 1e-6))
True
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from ..sizing._arc import arc_max_many
from ._bounds import _SIDES, _SIGN, _Bounds

__all__ = ["EdgeOptimum", "EdgePair", "Load", "cone_margin", "edge_pair_values", "refine_edge_pair"]

#: Default relative tolerance of the proof: value − lower <= tol · value.
DEFAULT_TOL = 1e-6
#: A pair at most this far inside condition (1) (radians, :func:`cone_margin`) is reported
#: as on its boundary.
BOUNDARY = 1e-6
#: Most boxes bounded before the search gives up (then ``certified`` is False).
MAX_BOXES = 20_000


@dataclasses.dataclass(frozen=True)
class Load:
    """The load of the question: every orientation, or tilts of a given gravity.

    Attributes
    ----------
    g, accel : float
        Gravity and the acceleration bound A (m/s²).
    gravity : (float, float) or None
        Gravity's unit direction in the outline's frame; None: every orientation.
    tau : float or None
        With ``gravity``: the tilt bound τ (rad); 0 the given orientation.
    """

    g: float
    accel: float = 0.0
    gravity: tuple[float, float] | None = None
    tau: float | None = None

    @property
    def any_orientation(self) -> bool:
        """True when the worst case is over every orientation (max_n |V_n|)."""
        return self.gravity is None or (self.tau is not None and self.tau >= math.pi)


@dataclasses.dataclass(frozen=True)
class EdgePair:
    """Two edges of a counter-clockwise outline, the centre of mass and μ (float data)."""

    a0: tuple[float, float]
    ea: tuple[float, float]
    b0: tuple[float, float]
    eb: tuple[float, float]
    com: tuple[float, float]
    mu: float
    #: The edges' second vertices, when given (:meth:`of`): the proof is then about the
    #: segments ``a0 → a1``, ``b0 → b1`` exactly (``ea``, ``eb`` are their rounded
    #: differences, for the float evaluation only), so that edges sharing a vertex meet.
    a1: tuple[float, float] | None = None
    b1: tuple[float, float] | None = None

    @classmethod
    def of(cls, a0: Any, a1: Any, b0: Any, b1: Any, com: Any, mu: float) -> EdgePair:
        """The edges ``a0 → a1`` and ``b0 → b1`` (counter-clockwise: material on the left)."""
        f = [(float(p[0]), float(p[1])) for p in (a0, a1, b0, b1, com)]
        return cls(
            f[0],
            (f[1][0] - f[0][0], f[1][1] - f[0][1]),
            f[2],
            (f[3][0] - f[2][0], f[3][1] - f[2][1]),
            f[4],
            float(mu),
            f[1],
            f[3],
        )

    def points(self, s: Any, t: Any) -> tuple[np.ndarray, np.ndarray]:
        """The contacts a(s), b(t), shape (..., 2)."""
        s, t = np.asarray(s, float)[..., None], np.asarray(t, float)[..., None]
        return np.asarray(self.a0) + s * np.asarray(self.ea), np.asarray(self.b0) + t * np.asarray(
            self.eb
        )

    def normals(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """The inward unit normals of the two edges."""
        out = []
        for e in (self.ea, self.eb):
            n = math.hypot(*e)
            out.append((-e[1] / n, e[0] / n))
        return out[0], out[1]


def _cones(e: tuple[float, float], mu: float) -> tuple[np.ndarray, np.ndarray]:
    n = np.array([-e[1], e[0]])
    ev = np.array(e)
    return n + mu * ev, n - mu * ev


def edge_pair_values(pair: EdgePair, load: Load, s: Any, t: Any) -> np.ndarray:
    """``q(s, t)`` of the module docstring in float64, ``nan`` where (1) fails.

    Parameters
    ----------
    pair : EdgePair
    load : Load
    s, t : array
        Edge parameters (broadcasting).

    Returns
    -------
    ndarray
        The squeeze per jaw per unit of ``S_f m`` (N/kg with S_f = 1).
    """
    a, b = pair.points(s, t)
    d = a - b
    o = np.asarray(pair.com)
    cones = (*_cones(pair.ea, pair.mu), *_cones(pair.eb, pair.mu))
    length = np.hypot(d[..., 0], d[..., 1])
    ok = np.ones(length.shape, bool)
    vs = []
    for (i, _), c, sig in zip(_SIDES, cones, _SIGN):
        num = d[..., 0] * c[0] + d[..., 1] * c[1]
        den = d[..., 0] * c[1] - d[..., 1] * c[0]
        ok &= sig * den > 0
        with np.errstate(divide="ignore", invalid="ignore"):
            kappa = num / den
        r = (b if i == 0 else a) - o
        half = 0.5 if i == 0 else -0.5
        vs.append(
            (-(half * d[..., 0] - kappa * r[..., 1]), -(half * d[..., 1] + kappa * r[..., 0]))
        )
    q = _combine(vs, load, length)
    return np.where(ok, q, np.nan)


def cone_margin(pair: EdgePair, s: Any, t: Any) -> np.ndarray:
    """How far inside condition (1) the pairs are: the least angle (radians) by which the
    line of contact is inside a friction cone's side, over the four sides (< 0: outside).
    """
    a, b = pair.points(s, t)
    d = a - b
    length = np.hypot(d[..., 0], d[..., 1])
    out = np.full(length.shape, np.inf)
    for c, sig in zip((*_cones(pair.ea, pair.mu), *_cones(pair.eb, pair.mu)), _SIGN):
        den = d[..., 0] * c[1] - d[..., 1] * c[0]
        with np.errstate(divide="ignore", invalid="ignore"):
            sin = sig * den / (length * math.hypot(c[0], c[1]))
        out = np.minimum(out, np.arcsin(np.clip(sin, -1.0, 1.0)))
    return out


def _combine(vs: list, load: Load, length: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):
        if load.any_orientation:
            top = np.max([np.hypot(vx, vy) for vx, vy in vs], axis=0) * (load.g + load.accel)
        else:
            w = (load.g * load.gravity[0], load.g * load.gravity[1])  # type: ignore[index]
            top = np.max(
                [
                    arc_max_many(vx, vy, w, load.tau) + load.accel * np.hypot(vx, vy)
                    for vx, vy in vs
                ],
                axis=0,
            )
            top = np.maximum(top, 0.0)
        return top / length


def _closure_polygon(bounds: _Bounds) -> np.ndarray | None:
    """The corners of ``{(s, t) in [0, 1]²: d × c has its sign for the four sides}`` (float).

    Condition (1) is four inequalities linear in (s, t) (module docstring): the
    square clipped by four half-planes (Sutherland–Hodgman), None when empty.
    """
    den = bounds.den
    coef = [
        (
            (den.f0[0][n, 0] + den.f0[1][n, 0]) / 2,
            (den.fs[0][n, 0] + den.fs[1][n, 0]) / 2,
            (den.ft[0][n, 0] + den.ft[1][n, 0]) / 2,
        )
        for n in range(4)
    ]
    poly = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    for c0, cs, ct in coef:
        out = []
        for k, p in enumerate(poly):
            q = poly[k - 1]
            fp, fq = c0 + cs * p[0] + ct * p[1], c0 + cs * q[0] + ct * q[1]
            if (fp >= 0) != (fq >= 0):
                u = fq / (fq - fp)
                out.append((q[0] + u * (p[0] - q[0]), q[1] + u * (p[1] - q[1])))
            if fp >= 0:
                out.append(p)
        poly = out
        if not poly:
            return None
    return np.array(poly)


def _inside(
    poly: np.ndarray, s: np.ndarray, t: np.ndarray, eps: float
) -> tuple[np.ndarray, np.ndarray]:
    """The nearest points of the polygon's boundary to (s, t), moved ``eps`` to its centroid."""
    s, t = np.atleast_1d(s), np.atleast_1d(t)
    if not s.size:
        return s, t
    a, b = poly, np.roll(poly, -1, axis=0)
    e = b - a
    ee = np.where((e * e).sum(axis=1) > 0, (e * e).sum(axis=1), 1.0)
    ps = np.stack([s, t], axis=-1)[:, None, :]
    u = np.clip(((ps - a) * e).sum(axis=-1) / ee, 0.0, 1.0)
    foot = a + u[..., None] * e
    k = np.argmin(((foot - ps) ** 2).sum(axis=-1), axis=1)
    p = foot[np.arange(len(s)), k]
    p = p + eps * (poly.mean(axis=0) - p)
    return np.clip(p[:, 0], 0.0, 1.0), np.clip(p[:, 1], 0.0, 1.0)


def _halve(
    lo: np.ndarray, hi: np.ndarray, olo: np.ndarray, ohi: np.ndarray, which: np.ndarray
) -> tuple[np.ndarray, ...]:
    """Split the boxes marked ``which`` in two along (lo, hi); the others stay whole."""
    mid = (lo + hi) / 2
    w = which
    return (
        np.concatenate([lo, mid[w]]),
        np.concatenate([np.where(w, mid, hi), hi[w]]),
        np.concatenate([olo, olo[w]]),
        np.concatenate([ohi, ohi[w]]),
    )


@dataclasses.dataclass(frozen=True)
class EdgeOptimum:
    """The proved least q along an edge pair.

    Attributes
    ----------
    s, t : float
        The edge parameters of the best point found (0 at the edges' first vertices).
    value : float
        q there (an upper bound of the least q over the force-closure pairs).
    lower : float
        A proved lower bound of q over every force-closure pair of the two edges.
    tol : float
        The relative tolerance asked; ``certified``: ``value − lower <= tol · value``.
    certified : bool
        False when the search stopped at :data:`MAX_BOXES` (then ``lower`` still holds).
    boxes : int
        Boxes bounded in all.
    margin : float
        How far inside condition (1) the reported pair is (:func:`cone_margin`, radians).
    on_boundary : bool
        ``margin <= BOUNDARY``: the least squeeze is approached on the boundary of
        condition (1) (under a tilt range it stays finite there); the pair reported
        is force-closure, just inside it, and ``value`` is within ``tol`` of the
        infimum, which no force-closure pair attains.
    """

    s: float
    t: float
    value: float
    lower: float
    tol: float
    certified: bool
    boxes: int
    margin: float = math.nan
    on_boundary: bool = False


def refine_edge_pair(
    pair: EdgePair,
    load: Load,
    *,
    tol: float = DEFAULT_TOL,
    start: Any = (),
    max_boxes: int = MAX_BOXES,
) -> EdgeOptimum | None:
    """The least ``q(s, t)`` over the force-closure pairs of two edges, proved within ``tol``.

    Parameters
    ----------
    pair : EdgePair
    load : Load
    tol : float
        Relative tolerance of the proof (> 0).
    start : sequence of (s, t)
        Points to try first (e.g. the sampled contacts on these edges); the result
        is never worse than the best of them.
    max_boxes : int
        Give up (``certified`` False, ``lower`` still proved) after bounding this
        many boxes.

    Returns
    -------
    EdgeOptimum or None
        None when no pair of points of the two edges meets condition (1).
    """
    with np.errstate(all="ignore"):
        return _search(pair, load, float(tol), start, int(max_boxes))


def _search(
    pair: EdgePair, load: Load, tol: float, start: Any, max_boxes: int
) -> EdgeOptimum | None:
    bounds = _Bounds(pair, load)
    best_v, best_st = np.inf, (math.nan, math.nan)

    def consider(s: np.ndarray, t: np.ndarray) -> None:
        nonlocal best_v, best_st
        if not s.size:
            return
        v = edge_pair_values(pair, load, s, t)
        if np.isfinite(v).any():
            k = int(np.nanargmin(v))
            if v[k] < best_v:
                best_v, best_st = float(v[k]), (float(s[k]), float(t[k]))

    st = np.asarray(list(start), float).reshape(-1, 2)
    consider(st[:, 0], st[:, 1])
    # the force-closure set is a convex polygon of (s, t): its corners (nudged inside), and
    # below the points of its boundary nearest the boxes that straddle it, are tried too
    # (where the least squeeze is approached on the boundary of (1) under a tilt range)
    poly = _closure_polygon(bounds)
    nudge = max(1e-3 * tol, 1e-12)
    if poly is not None:
        consider(*_inside(poly, poly[:, 0], poly[:, 1], nudge))
    n0 = 8
    g = np.arange(n0 + 1) / n0
    s0, t0 = np.meshgrid(g[:-1], g[:-1], indexing="ij")
    s_lo, t_lo = s0.ravel(), t0.ravel()
    s_hi, t_hi = s_lo + 1 / n0, t_lo + 1 / n0
    la, lb = math.hypot(*pair.ea), math.hypot(*pair.eb)
    pruned: float = np.inf
    count = 0
    certified = True
    while s_lo.size:
        consider(
            np.concatenate([(s_lo + s_hi) / 2, s_lo, s_lo, s_hi, s_hi]),
            np.concatenate([(t_lo + t_hi) / 2, t_lo, t_hi, t_lo, t_hi]),
        )
        lower, feas = bounds.lower((s_lo, s_hi), (t_lo, t_hi))
        if poly is not None and not load.any_orientation:
            near = feas & bounds.straddle & (lower < best_v * (1 - tol))
            consider(
                *_inside(poly, (s_lo[near] + s_hi[near]) / 2, (t_lo[near] + t_hi[near]) / 2, nudge)
            )
        count += s_lo.size
        keep = feas & (lower < best_v * (1 - tol))
        drop = feas & ~keep
        if drop.any():
            pruned = min(pruned, float(lower[drop].min()))
        s_lo, s_hi, t_lo, t_hi, lower = (v[keep] for v in (s_lo, s_hi, t_lo, t_hi, lower))
        if s_lo.size and count + 2 * s_lo.size > max_boxes:
            certified = False
            pruned = min(pruned, float(lower.min()))
            break
        # halve each box along each side at least half as long as the other (in metres)
        ws, wt = (s_hi - s_lo) * la, (t_hi - t_lo) * lb
        cut_s, cut_t = 2 * ws >= wt, 2 * wt >= ws
        s_lo, s_hi, t_lo, t_hi = _halve(s_lo, s_hi, t_lo, t_hi, cut_s)
        t_lo, t_hi, s_lo, s_hi = _halve(
            t_lo, t_hi, s_lo, s_hi, np.concatenate([cut_t, cut_t[cut_s]])
        )
    if not np.isfinite(best_v):
        return None  # no force-closure pair (or none at a box's centre or corner)
    if poly is not None and not load.any_orientation:
        # the nearest point of the boundary of (1), if no worse: where the least is approached
        consider(*_inside(poly, np.array([best_st[0]]), np.array([best_st[1]]), nudge))
    least = max(0.0, min(pruned, best_v))  # q >= 0
    margin = float(cone_margin(pair, *best_st))
    return EdgeOptimum(
        best_st[0],
        best_st[1],
        best_v,
        least,
        float(tol),
        certified and best_v - least <= tol * best_v,
        count,
        margin,
        margin <= BOUNDARY,
    )
