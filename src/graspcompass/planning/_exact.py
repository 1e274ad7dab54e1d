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

__all__ = ["EdgeOptimum", "EdgePair", "Load", "edge_pair_values", "refine_edge_pair"]

#: Default relative tolerance of the proof: value − lower <= tol · value.
DEFAULT_TOL = 1e-6
#: Most boxes bounded before the search gives up (then ``certified`` is False).
MAX_BOXES = 20_000
_SIDES = ((0, 1), (0, -1), (1, 1), (1, -1))  # (contact 0 = a / 1 = b, cone side ±)
#: The sign ``d × c`` has on the force-closure set, per side of _SIDES.
_SIGN = (1.0, -1.0, -1.0, 1.0)


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

    @classmethod
    def of(cls, a0: Any, a1: Any, b0: Any, b1: Any, com: Any, mu: float) -> EdgePair:
        """The edges ``a0 → a1`` and ``b0 → b1`` (counter-clockwise: material on the left)."""
        f = [(float(p[0]), float(p[1])) for p in (a0, a1, b0, b1, com)]
        return cls(f[0], (f[1][0] - f[0][0], f[1][1] - f[0][1]), f[2],
                   (f[3][0] - f[2][0], f[3][1] - f[2][1]), f[4], float(mu))

    def points(self, s: Any, t: Any) -> tuple[np.ndarray, np.ndarray]:
        """The contacts a(s), b(t), shape (..., 2)."""
        s, t = np.asarray(s, float)[..., None], np.asarray(t, float)[..., None]
        return np.asarray(self.a0) + s * np.asarray(self.ea), np.asarray(self.b0) + t * np.asarray(
            self.eb)

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
        vs.append((-(half * d[..., 0] - kappa * r[..., 1]),
                   -(half * d[..., 1] + kappa * r[..., 0])))
    q = _combine(vs, load, length)
    return np.where(ok, q, np.nan)


def _combine(vs: list, load: Load, length: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):
        if load.any_orientation:
            top = np.max([np.hypot(vx, vy) for vx, vy in vs], axis=0) * (load.g + load.accel)
        else:
            w = (load.g * load.gravity[0], load.g * load.gravity[1])  # type: ignore[index]
            top = np.max([arc_max_many(vx, vy, w, load.tau) + load.accel * np.hypot(vx, vy)
                          for vx, vy in vs], axis=0)
            top = np.maximum(top, 0.0)
        return top / length


# -- interval arithmetic, rounded outward ---------------------------------------------------
def _dn(x: Any) -> Any:
    return np.nextafter(x, -np.inf)


def _up(x: Any) -> Any:
    return np.nextafter(x, np.inf)


def _pt(x: float) -> tuple[np.ndarray, np.ndarray]:
    return np.float64(x), np.float64(x)


def _add(a: tuple, b: tuple) -> tuple:
    return _dn(a[0] + b[0]), _up(a[1] + b[1])


def _sub(a: tuple, b: tuple) -> tuple:
    return _dn(a[0] - b[1]), _up(a[1] - b[0])


def _neg(a: tuple) -> tuple:
    return -a[1], -a[0]


def _mul(a: tuple, b: tuple) -> tuple:
    # fmin/fmax skip the nan of 0 · inf: the endpoint 0 bounds the product by the others
    with np.errstate(invalid="ignore"):
        p0, p1, p2, p3 = a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1]
    lo = np.fmin(np.fmin(p0, p1), np.fmin(p2, p3))
    hi = np.fmax(np.fmax(p0, p1), np.fmax(p2, p3))
    return _dn(np.where(lo != lo, 0.0, lo)), _up(np.where(hi != hi, 0.0, hi))


def _half(a: tuple, sign: Any) -> tuple:
    """``sign · a / 2`` for signs ±1 (exact: a power of two)."""
    lo, hi = a[0] * (0.5 * sign), a[1] * (0.5 * sign)
    return np.minimum(lo, hi), np.maximum(lo, hi)


def _sq_lo(a: tuple) -> np.ndarray:
    m = np.where(a[0] > 0, a[0], np.where(a[1] < 0, -a[1], 0.0))
    return _dn(m * m)


def _sq_hi(a: tuple) -> np.ndarray:
    m = np.maximum(np.abs(a[0]), np.abs(a[1]))
    return _up(m * m)


def _dot(u: tuple, v: tuple) -> tuple:
    return _add(_mul(u[0], v[0]), _mul(u[1], v[1]))


def _cross(u: tuple, v: tuple) -> tuple:
    return _sub(_mul(u[0], v[1]), _mul(u[1], v[0]))


class _Affine:
    """Interval coefficients of ``f0 + s fs + t ft``: exact (outward rounded) over a box."""

    def __init__(self, f0: tuple, fs: tuple, ft: tuple) -> None:
        self.f0, self.fs, self.ft = f0, fs, ft

    def over(self, s: tuple, t: tuple) -> tuple:
        return _add(_add(self.f0, _mul(s, self.fs)), _mul(t, self.ft))

    def neg(self) -> _Affine:
        return _Affine(_neg(self.f0), _neg(self.fs), _neg(self.ft))


def _vec(f0: tuple, fs: tuple, ft: tuple) -> tuple[_Affine, _Affine]:
    """An affine vector field from coefficient vectors (each a pair of intervals)."""
    return _Affine(f0[0], fs[0], ft[0]), _Affine(f0[1], fs[1], ft[1])


def _lin(v: tuple[_Affine, _Affine], c: tuple, kind: str) -> _Affine:
    """The affine scalar ``v·c`` or ``v × c`` for a constant interval vector c."""
    op = _dot if kind == "dot" else _cross
    return _Affine(*(op((getattr(v[0], k), getattr(v[1], k)), c) for k in ("f0", "fs", "ft")))


def _vadd(u: tuple, v: tuple) -> tuple:
    return _add(u[0], v[0]), _add(u[1], v[1])


def _vscale(k: tuple, v: tuple) -> tuple:
    return _mul(k, v[0]), _mul(k, v[1])


def _J(v: tuple) -> tuple:
    return _neg(v[1]), v[0]


def _norm(v: tuple) -> tuple:
    lo = _dn(np.sqrt(np.maximum(_dn(_sq_lo(v[0]) + _sq_lo(v[1])), 0.0)))
    return lo, _up(np.sqrt(_up(_sq_hi(v[0]) + _sq_hi(v[1]))))


class _Bounds:
    """Lower bounds of q over boxes of (s, t), vectorised over the four cone sides and the boxes.

    Two bounds per cone side, the larger kept: the natural interval extension,
    and the mean-value form of the smooth minorant ``φ = V·U / |d|`` with U fixed
    in each box (``(g + A) V_c/|V_c|``, or ``R_ρc (g ĝ) + A V_c/|V_c|`` with ρc the
    worst tilt at the box's centre: ``V·U <= (g + A)|V|``, resp. ``<= M + A|V|``,
    with equality at the centre), whose error shrinks like the square of the box.
    The rounding of U is covered by an interval of ±1e-15 (g + A) around it.
    """

    def __init__(self, pair: EdgePair, load: Load) -> None:
        a0, ea, b0, eb, o = (tuple(_pt(v) for v in p) for p in (pair.a0, pair.ea, pair.b0,
                                                                  pair.eb, pair.com))
        zero = (_pt(0.0), _pt(0.0))
        d = _vec((_sub(a0[0], b0[0]), _sub(a0[1], b0[1])), ea, (_neg(eb[0]), _neg(eb[1])))
        r = (_vec((_sub(a0[0], o[0]), _sub(a0[1], o[1])), ea, zero),
             _vec((_sub(b0[0], o[0]), _sub(b0[1], o[1])), zero, eb))
        mu = _pt(pair.mu)
        nums, dens, rjs = [], [], []
        for (i, sgn), sig in zip(_SIDES, _SIGN):
            e = ea if i == 0 else eb
            n = (_neg(e[1]), e[0])
            me = (_mul(mu, e[0]), _mul(mu, e[1]))
            c = (_add(n[0], me[0]), _add(n[1], me[1])) if sgn > 0 else (
                _sub(n[0], me[0]), _sub(n[1], me[1]))
            num, den = _lin(d, c, "dot"), _lin(d, c, "cross")
            if sig < 0:
                num, den = num.neg(), den.neg()
            nums.append(num)
            dens.append(den)
            rjs.append(r[1 - i])
        # every coefficient as a column over the four sides, shape (4, 1)
        self.num, self.den = _stack(nums), _stack(dens)
        self.rj = (_stack([v[0] for v in rjs]), _stack([v[1] for v in rjs]))
        self.d = d
        self.h = np.array([[-1.0], [-1.0], [1.0], [1.0]])  # V = h d/2 − κ J r_j
        self.load = load
        # on (1) the angle between d and a cone side is in (0, 2ξ): |κ| >= cot 2ξ
        # = (1 − μ²)/(2μ) when μ < 1 (the margin covers its rounding)
        self.kmin = max(0.0, (1 - pair.mu**2) / (2 * pair.mu) * (1 - 1e-12) - 1e-300)

    def _fields(self, s: tuple, t: tuple, grad: bool) -> tuple:
        """d, |d| over the boxes; per side (rows): V, d × c may be > 0, V_s, V_t, d × c > 0."""
        d = (self.d[0].over(s, t), self.d[1].over(s, t))
        s4, t4 = (s[0][None], s[1][None]), (t[0][None], t[1][None])
        nn, dd = self.num.over(s4, t4), self.den.over(s4, t4)
        kappa = _div_pos(nn, dd)
        rj = (self.rj[0].over(s4, t4), self.rj[1].over(s4, t4))
        jr = _J(rj)
        d4 = ((d[0][0][None], d[0][1][None]), (d[1][0][None], d[1][1][None]))
        v = _vadd((_half(d4[0], self.h), _half(d4[1], self.h)), _vscale(_neg(kappa), jr))
        out = {"v": v, "may": dd[1] > 0, "rnorm": _norm(rj)[0]}
        if grad:
            den2 = (_sq_lo(dd), _sq_hi(dd))
            for k in ("fs", "ft"):
                # κ' = (num' den − num den') / den²;  V' = h d'/2 − κ' J r − κ J r'
                kp = _div_pos(_sub(_mul(getattr(self.num, k), dd),
                                   _mul(nn, getattr(self.den, k))), den2)
                dk = (getattr(self.d[0], k), getattr(self.d[1], k))
                jrk = _J((getattr(self.rj[0], k), getattr(self.rj[1], k)))
                out[k] = _vadd(_vadd((_half(dk[0], self.h), _half(dk[1], self.h)),
                                     _vscale(_neg(kp), jr)), _vscale(_neg(kappa), jrk))
            out["strict"] = dd[0] > 0
        return d, _norm(d), out

    def lower(self, s: tuple, t: tuple) -> tuple[np.ndarray, np.ndarray]:
        """Lower bounds of q over the boxes and whether each may meet condition (1)."""
        ld = self.load
        d, length, f = self._fields(s, t, True)
        sc, tc = (s[0] + s[1]) / 2, (t[0] + t[1]) / 2
        _, lc, fc = self._fields((sc, sc), (tc, tc), False)
        feasible = f["may"].all(axis=0)
        v = f["v"]
        norm_lo = _norm(v)[0]
        l4 = (length[0][None], length[1][None])
        # |V| >= |κ||r_j| − |d|/2: bounded away from 0 where two edges meet at a vertex
        norm_lo = np.maximum(norm_lo, _dn(_dn(self.kmin * f["rnorm"]) - _up(l4[1] * 0.5)))
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            natural = _dn(self._top(v, norm_lo) / l4[1])
            # the mean-value form of φ = V·U/|d| around the centre
            vc = fc["v"]
            cx, cy = (vc[0][0] + vc[0][1]) / 2, (vc[1][0] + vc[1][1]) / 2
            nc = np.hypot(cx, cy)
            ux, uy = cx / nc, cy / nc
            if ld.any_orientation:
                U = (ux * (ld.g + ld.accel), uy * (ld.g + ld.accel))
            else:
                gx, gy = ld.g * ld.gravity[0], ld.g * ld.gravity[1]  # type: ignore[index]
                rho = np.clip(np.arctan2(cy * gx - cx * gy, cx * gx + cy * gy),
                              -ld.tau, ld.tau)  # type: ignore[arg-type]
                cr, sr = np.cos(rho), np.sin(rho)
                U = (cr * gx - sr * gy + ld.accel * ux, sr * gx + cr * gy + ld.accel * uy)
            du = 1e-15 * (ld.g + ld.accel)
            Ui = ((U[0] - du, U[0] + du), (U[1] - du, U[1] + du))
            lc4 = (lc[0][None], lc[1][None])
            phic = _div_pos(_dot(vc, Ui), lc4)
            l2 = (_sq_lo(l4), _sq_hi(l4))
            vu = _dot(v, Ui)
            steps, grads = [], []
            for k, step in (("fs", (_dn(s[0] - sc), _up(s[1] - sc))),
                            ("ft", (_dn(t[0] - tc), _up(t[1] - tc)))):
                # φ' = V'·U/|d| − (V·U) |d|'/|d|²,  |d|' = d·d'/|d|
                dk = (getattr(self.d[0], k), getattr(self.d[1], k))
                lk = _div_pos(_dot(d, dk), length)
                lk = (lk[0][None], lk[1][None])
                grads.append(_sub(_div_pos(_dot(f[k], Ui), l4), _div_pos(_mul(vu, lk), l2)))
                steps.append((step[0][None], step[1][None]))
            ok = f["strict"] & (l4[0] > 0) & (nc > 0) & np.isfinite(phic[0])
            for g_ in grads:
                ok &= np.isfinite(g_[0]) & np.isfinite(g_[1])
            mv = _add(_add(phic, _mul(steps[0], grads[0])), _mul(steps[1], grads[1]))[0]
            best = np.maximum(np.where(np.isnan(natural), -np.inf, natural),
                              np.where(ok, mv, -np.inf)).max(axis=0)
            best = np.maximum(best, _pairs(phic, grads, steps, ok))
        if not ld.any_orientation:
            best = np.maximum(best, 0.0)
        return np.where(feasible, best, np.inf), feasible

    def _top(self, v: tuple, norm_lo: np.ndarray) -> np.ndarray:
        """A lower bound of (g + A)|V|, or of M + A|V|, over the box (natural extension)."""
        ld = self.load
        if ld.any_orientation:
            return _dn(norm_lo * _dn(np.float64(ld.g) + np.float64(ld.accel)))
        gx, gy = ld.gravity  # type: ignore[misc]
        best = np.full(norm_lo.shape, -np.inf)
        tau = float(ld.tau)  # type: ignore[arg-type]
        dw = 1e-15 * ld.g  # covers the rounding of R_ρ w
        for rho in (-tau, 0.0, tau):  # V·R_ρ w at three tilts: each a lower bound of M
            cr, sr = math.cos(rho), math.sin(rho)
            wx, wy = ld.g * (cr * gx - sr * gy), ld.g * (sr * gx + cr * gy)
            best = np.maximum(best, _dot(v, ((wx - dw, wx + dw), (wy - dw, wy + dw)))[0])
        return best + _dn(norm_lo * np.float64(ld.accel))


_PAIRS = np.array([(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]).T


def _pairs(phic: tuple, grads: list, steps: list, ok: np.ndarray) -> np.ndarray:
    """The mean-value form of ``λ φ_n + (1 − λ) φ_m <= max_n φ_n`` for the six pairs n < m.

    λ in [0, 1] makes the combination's gradient at the centre least: along a
    valley where two sides cross (a kink of the maximum), the combination is
    smooth and flat across it, so its bound is of second order there too.
    """
    n, m = _PAIRS
    gs = [((g[0] + g[1]) / 2) for g in grads]  # about the centre's gradient
    a = np.stack([gs[0][n], gs[1][n]])
    b = np.stack([gs[0][m], gs[1][m]])
    diff = a - b
    den = (diff * diff).sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        lam = np.clip(-(b * diff).sum(axis=0) / den, 0.0, 1.0)
    lam = np.where(np.isfinite(lam), lam, 0.5)
    mu = 1.0 - lam  # exact for λ in [0, 1]? not always: use the interval of 1 − λ
    li, mi = (lam, lam), (_dn(mu), _up(mu))
    val = _add(_mul(li, (phic[0][n], phic[1][n])), _mul(mi, (phic[0][m], phic[1][m])))
    for g, st in zip(grads, steps):
        gc = _add(_mul(li, (g[0][n], g[1][n])), _mul(mi, (g[0][m], g[1][m])))
        val = _add(val, _mul((st[0][0][None], st[1][0][None]), gc))
    good = ok[n] & ok[m] & np.isfinite(val[0])
    return np.where(good, val[0], -np.inf).max(axis=0)


def _stack(forms: list) -> _Affine:
    return _Affine(*((np.array([[f_.__dict__[k][0]] for f_ in forms]).reshape(4, 1),
                      np.array([[f_.__dict__[k][1]] for f_ in forms]).reshape(4, 1))
                     for k in ("f0", "fs", "ft")))


def _div_pos(n: tuple, d: tuple) -> tuple:
    """``n / d`` over the part of d that is > 0 (d's upper end > 0; else anything)."""
    dl, dh = np.maximum(d[0], 0.0), np.where(d[1] > 0, d[1], 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = [n[0] / dl, n[0] / dh, n[1] / dl, n[1] / dh]
        lo = _dn(np.minimum(np.minimum(q[0], q[1]), np.minimum(q[2], q[3])))
        hi = _up(np.maximum(np.maximum(q[0], q[1]), np.maximum(q[2], q[3])))
    open_ = dl <= 0  # d reaches 0: κ unbounded on the side of n's sign
    lo = np.where(open_, np.where(n[0] >= 0, _dn(n[0] / dh), -np.inf), lo)
    hi = np.where(open_, np.where(n[1] <= 0, _up(n[1] / dh), np.inf), hi)
    return np.where(np.isnan(lo), -np.inf, lo), np.where(np.isnan(hi), np.inf, hi)


def _halve(lo: np.ndarray, hi: np.ndarray, olo: np.ndarray, ohi: np.ndarray, which: np.ndarray
           ) -> tuple[np.ndarray, ...]:
    """Split the boxes marked ``which`` in two along (lo, hi); the others stay whole."""
    mid = (lo + hi) / 2
    w = which
    return (np.concatenate([lo, mid[w]]), np.concatenate([np.where(w, mid, hi), hi[w]]),
            np.concatenate([olo, olo[w]]), np.concatenate([ohi, ohi[w]]))


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
    """

    s: float
    t: float
    value: float
    lower: float
    tol: float
    certified: bool
    boxes: int


def refine_edge_pair(pair: EdgePair, load: Load, *, tol: float = DEFAULT_TOL,
                     start: Any = (), max_boxes: int = MAX_BOXES) -> EdgeOptimum | None:
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


def _search(pair: EdgePair, load: Load, tol: float, start: Any, max_boxes: int
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
    n0 = 8
    g = np.arange(n0 + 1) / n0
    s0, t0 = np.meshgrid(g[:-1], g[:-1], indexing="ij")
    s_lo, t_lo = s0.ravel(), t0.ravel()
    s_hi, t_hi = s_lo + 1 / n0, t_lo + 1 / n0
    la, lb = math.hypot(*pair.ea), math.hypot(*pair.eb)
    pruned = np.inf
    count = 0
    certified = True
    while s_lo.size:
        consider(np.concatenate([(s_lo + s_hi) / 2, s_lo, s_lo, s_hi, s_hi]),
                 np.concatenate([(t_lo + t_hi) / 2, t_lo, t_hi, t_lo, t_hi]))
        lower, feas = bounds.lower((s_lo, s_hi), (t_lo, t_hi))
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
        t_lo, t_hi, s_lo, s_hi = _halve(t_lo, t_hi, s_lo, s_hi,
                                        np.concatenate([cut_t, cut_t[cut_s]]))
    if not np.isfinite(best_v):
        return None  # no force-closure pair (or none at a box's centre or corner)
    lower = max(0.0, min(pruned, best_v))  # q >= 0
    return EdgeOptimum(best_st[0], best_st[1], best_v, lower, float(tol),
                       certified and best_v - lower <= tol * best_v, count)
