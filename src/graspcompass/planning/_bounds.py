"""Lower bounds of the squeeze over boxes of edge parameters, for :mod:`._exact`."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ._interval import (
    _J,
    _add,
    _div_pos,
    _dn,
    _dot,
    _half,
    _lin,
    _mul,
    _neg,
    _norm,
    _pt,
    _sq_hi,
    _sq_lo,
    _stack,
    _sub,
    _up,
    _vadd,
    _vec,
    _vscale,
)

if TYPE_CHECKING:
    from ._exact import EdgePair, Load

_SIDES = ((0, 1), (0, -1), (1, 1), (1, -1))  # (contact 0 = a / 1 = b, cone side ±)
#: The sign ``d × c`` has on the force-closure set, per side of _SIDES.
_SIGN = (1.0, -1.0, -1.0, 1.0)


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
        a0, ea, b0, eb, o = (
            tuple(_pt(v) for v in p) for p in (pair.a0, pair.ea, pair.b0, pair.eb, pair.com)
        )
        if pair.a1 is not None and pair.b1 is not None:  # the exact differences, enclosed
            ea = tuple(_sub(_pt(pair.a1[k]), a0[k]) for k in (0, 1))
            eb = tuple(_sub(_pt(pair.b1[k]), b0[k]) for k in (0, 1))
        zero = (_pt(0.0), _pt(0.0))
        d = _vec((_sub(a0[0], b0[0]), _sub(a0[1], b0[1])), ea, (_neg(eb[0]), _neg(eb[1])))
        r = (
            _vec((_sub(a0[0], o[0]), _sub(a0[1], o[1])), ea, zero),
            _vec((_sub(b0[0], o[0]), _sub(b0[1], o[1])), zero, eb),
        )
        mu = _pt(pair.mu)
        nums, dens, rjs = [], [], []
        for (i, sgn), sig in zip(_SIDES, _SIGN):
            e = ea if i == 0 else eb
            n = (_neg(e[1]), e[0])
            me = (_mul(mu, e[0]), _mul(mu, e[1]))
            c = (
                (_add(n[0], me[0]), _add(n[1], me[1]))
                if sgn > 0
                else (_sub(n[0], me[0]), _sub(n[1], me[1]))
            )
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
        self.vertex = _Vertex.of(pair, self.num, self.den)

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
        out = {"v": v, "may": dd[1] > 0, "rnorm": _norm(rj), "kappa": kappa, "jr": jr}
        if grad:
            den2 = (_sq_lo(dd), _sq_hi(dd))
            for k in ("fs", "ft"):
                # κ' = (num' den − num den') / den²;  V' = h d'/2 − κ' J r − κ J r'
                kp = _div_pos(
                    _sub(_mul(getattr(self.num, k), dd), _mul(nn, getattr(self.den, k))), den2
                )
                dk = (getattr(self.d[0], k), getattr(self.d[1], k))
                jrk = _J((getattr(self.rj[0], k), getattr(self.rj[1], k)))
                out[k] = _vadd(
                    _vadd((_half(dk[0], self.h), _half(dk[1], self.h)), _vscale(_neg(kp), jr)),
                    _vscale(_neg(kappa), jrk),
                )
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
        # |κ| from its interval (unbounded near the boundary of (1)), at least cot 2ξ
        kap = f["kappa"]
        kmag = np.maximum(
            np.where(kap[0] > 0, kap[0], np.where(kap[1] < 0, -kap[1], 0.0)), self.kmin
        )
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            norm_lo = np.maximum(norm_lo, _dn(_dn(kmag * f["rnorm"][0]) - _up(l4[1] * 0.5)))
            natural = _over_length(self._top(v, norm_lo), l4)
            if self.vertex is not None and ld.any_orientation:
                # max_n |V_n| >= K − |d|/2, K jointly over the sides (μ >= 1 at a vertex)
                k = self.vertex.least(s, t, f["rnorm"][0])
                joint = _dn(_dn(k / l4[1][0]) - 0.5) * _dn(np.float64(ld.g) + np.float64(ld.accel))
                natural = np.maximum(natural, np.where(np.isnan(joint), -np.inf, joint)[None])
            if not ld.any_orientation:
                natural = np.maximum(natural, _over_length(self._blow(d, f, norm_lo, l4, s, t), l4))
            # the mean-value form of φ = V·U/|d| around the centre
            vc = fc["v"]
            cx, cy = (vc[0][0] + vc[0][1]) / 2, (vc[1][0] + vc[1][1]) / 2
            nc = np.hypot(cx, cy)
            ux, uy = cx / nc, cy / nc
            if ld.any_orientation:
                U = (ux * (ld.g + ld.accel), uy * (ld.g + ld.accel))
            else:
                assert ld.gravity is not None and ld.tau is not None  # a given orientation
                gx, gy = ld.g * ld.gravity[0], ld.g * ld.gravity[1]
                rho = np.clip(np.arctan2(cy * gx - cx * gy, cx * gx + cy * gy), -ld.tau, ld.tau)
                cr, sr = np.cos(rho), np.sin(rho)
                U = (cr * gx - sr * gy + ld.accel * ux, sr * gx + cr * gy + ld.accel * uy)
            du = 1e-15 * (ld.g + ld.accel)
            Ui = ((U[0] - du, U[0] + du), (U[1] - du, U[1] + du))
            lc4 = (lc[0][None], lc[1][None])
            phic = _div_pos(_dot(vc, Ui), lc4)
            l2 = (_sq_lo(l4), _sq_hi(l4))
            vu = _dot(v, Ui)
            steps, grads = [], []
            for key, step in (
                ("fs", (_dn(s[0] - sc), _up(s[1] - sc))),
                ("ft", (_dn(t[0] - tc), _up(t[1] - tc))),
            ):
                # φ' = V'·U/|d| − (V·U) |d|'/|d|²,  |d|' = d·d'/|d|
                dk = (getattr(self.d[0], key), getattr(self.d[1], key))
                lk = _div_pos(_dot(d, dk), length)
                lk = (lk[0][None], lk[1][None])
                grads.append(_sub(_div_pos(_dot(f[key], Ui), l4), _div_pos(_mul(vu, lk), l2)))
                steps.append((step[0][None], step[1][None]))
            ok = f["strict"] & (l4[0] > 0) & (nc > 0) & np.isfinite(phic[0])
            for g_ in grads:
                ok &= np.isfinite(g_[0]) & np.isfinite(g_[1])
            forms = _forms(phic, grads, steps, ok)
            straddle = feasible & ~f["strict"].all(axis=0)  # boxes across the boundary of (1)
            if straddle.any():
                # the forms are concave in the step: over the force-closure part of the
                # box (a polygon), their least value is at one of its corners
                k = np.flatnonzero(straddle)
                pts = self._corners((s[0][k], s[1][k]), (t[0][k], t[1][k]))
                ps = np.concatenate([p_[0] for p_ in pts])  # corner j of box i at j·n + i
                pt = np.concatenate([p_[1] for p_ in pts])
                kk = np.tile(k, len(pts))
                st_ = [
                    ((_dn(p_ - c_[kk])[None], _up(p_ - c_[kk])[None]))
                    for p_, c_ in ((ps, sc), (pt, tc))
                ]
                val = _forms(
                    (phic[0][:, kk], phic[1][:, kk]),
                    [((g[0][:, kk], g[1][:, kk])) for g in grads],
                    st_,
                    ok[:, kk],
                )
                val = np.where(np.isnan(ps), np.inf, val).reshape(10, len(pts), k.size)
                least = val.min(axis=1)
                forms[:, k] = np.maximum(
                    forms[:, k], np.where(np.isfinite(least), least, forms[:, k])
                )
            best = np.maximum(
                np.where(np.isnan(natural), -np.inf, natural).max(axis=0), forms.max(axis=0)
            )
        if not ld.any_orientation:
            best = np.maximum(best, 0.0)
        self.straddle = straddle
        return np.where(feasible, best, np.inf), feasible

    def _corners(self, s: tuple, t: tuple) -> list:
        """Points (s, t) per box whose hull holds the box's force-closure part (nan: none).

        The box's corners, where its sides cross the lines ``d × c_n = 0`` and where
        those lines cross, kept when inside the box and on the force-closure side of
        every line, each line moved outwards by 1e-12 of its size (covering the
        rounding of its coefficients and of these points).
        """
        den = self.den
        lines = []
        for n in range(4):
            a, b, c = (
                (getattr(den, k)[0][n, 0] + getattr(den, k)[1][n, 0]) / 2
                for k in ("f0", "fs", "ft")
            )
            size = abs(a) + abs(b) + abs(c)
            lines.append((a + 1e-12 * size, b, c, size))
        pts = [(s[i], t[j]) for i in (0, 1) for j in (0, 1)]
        with np.errstate(divide="ignore", invalid="ignore"):
            for a, b, c, _ in lines:
                for i in (0, 1):
                    pts.append((s[i], -(a + b * s[i]) / c * np.ones_like(s[i])))
                    pts.append((-(a + c * t[i]) / b * np.ones_like(t[i]), t[i]))
            for n in range(4):
                for m in range(n + 1, 4):
                    (a1, b1, c1, _), (a2, b2, c2, _) = lines[n], lines[m]
                    det = b1 * c2 - b2 * c1
                    ps, pt = (c1 * a2 - c2 * a1) / det, (b2 * a1 - b1 * a2) / det
                    pts.append((np.full_like(s[0], ps), np.full_like(s[0], pt)))
        out = []
        for ps, pt in pts:
            ps, pt = np.clip(ps, s[0], s[1]), np.clip(pt, t[0], t[1])
            good = np.isfinite(ps) & np.isfinite(pt)
            for a, b, c, size in lines:
                good &= a + b * ps + c * pt >= -1e-12 * size
            out.append((np.where(good, ps, np.nan), np.where(good, pt, np.nan)))
        return out

    def _blow(
        self, d: tuple, f: dict, norm_lo: np.ndarray, l4: tuple, s: tuple, t: tuple
    ) -> np.ndarray:
        """A lower bound of ``M_n + A|V_n|`` that sees κ_n grow without bound, per side.

        With ``V = h d/2 − κ J r`` and a tilt ρ (``w = R_ρ g ĝ``; ``M >= V·w``):
        ``V·w + A|V| >= h (d·w)/2 + κ (±A|r| − Jr·w) − A|d|/2`` for κ of one sign
        (``|V| >= |κ||r| − |d|/2``), the product taken as one interval: near the
        boundary of (1), where κ → ±∞, it tends to +∞ or −∞ as the pair's squeeze
        does (the natural extension, component by component, loses the sign).
        """
        ld = self.load
        kap, jr, (rlo, rhi) = f["kappa"], f["jr"], f["rnorm"]
        A = np.float64(ld.accel)
        arl, arh = _dn(A * rlo), _up(A * rhi)
        dl = _up(A * _up(l4[1] * 0.5))
        best = np.full(norm_lo.shape, -np.inf)
        for wx, wy in self._tilts(f, s, t):
            w = ((wx[0], wx[1]), (wy[0], wy[1]))
            dw = _dot(((d[0][0][None], d[0][1][None]), (d[1][0][None], d[1][1][None])), w)
            base = _half(dw, self.h)
            jw = _dot(jr, w)
            pos = _sub(base, _mul(kap, jw))
            best = np.maximum(best, _dn(pos[0] + _dn(A * norm_lo)))
            for sel, x in (
                (kap[0] >= 0, _sub((arl, arh), jw)),
                (kap[1] <= 0, _sub(_neg(jw), (arl, arh))),
            ):
                b = _sub(_add(base, _mul(kap, x)), (dl, dl))[0]
                best = np.where(sel, np.maximum(best, b), best)
        return best

    def _tilts(self, f: dict, s: tuple, t: tuple) -> list:
        """Gravity ``g R_ρ ĝ`` (as intervals covering its rounding) at a few tilts |ρ| <= τ.

        The ends and 0, and per box the worst tilt for ``±J r`` at the box's centre.
        """
        ld = self.load
        gx, gy = ld.g * ld.gravity[0], ld.g * ld.gravity[1]  # type: ignore[index]
        tau = float(ld.tau)  # type: ignore[arg-type]
        jr = f["jr"]
        cx, cy = (jr[0][0] + jr[0][1]) / 2, (jr[1][0] + jr[1][1]) / 2
        rhos = [np.float64(-tau), np.float64(0.0), np.float64(tau)]
        for sg in (1.0, -1.0):
            with np.errstate(invalid="ignore"):
                r = np.arctan2(sg * (cy * gx - cx * gy), sg * (cx * gx + cy * gy))
            rhos.append(np.clip(np.where(np.isfinite(r), r, 0.0), -tau, tau))
        dw = 1e-15 * ld.g * 4  # covers the rounding of cos, sin and R_ρ w
        out = []
        for rho in rhos:
            cr, sr = np.cos(rho), np.sin(rho)
            wx, wy = cr * gx - sr * gy, sr * gx + cr * gy
            out.append(((wx - dw, wx + dw), (wy - dw, wy + dw)))
        return out

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


class _Vertex:
    """Where the two edges meet at a vertex: a lower bound of ``max_n |κ_n| |r_n|`` by direction.

    With ``(s, t) = (sv, tv)`` the common vertex (exactly, in the float data) and
    ``σ = |s − sv|``, ``τ = |t − tv|``, ``d`` is linear in (σ, τ) and so are the
    numerator and denominator of each κ_n: κ_n depends on ``λ = τ/(σ + τ)`` alone.
    For μ >= 1 some κ_n vanish (a cone side ⟂ d), so no single side's |V_n| is
    bounded away from 0 near the vertex, but not all at once: a table of interval
    bounds of each |κ_n| over 256 cells of λ (cells off condition (1) dropped)
    gives ``max_n |V_n| >= min over the box's λ of max_n |κ_n| |r_n| − |d|/2``, and
    q grows like 1/|d| towards the vertex.
    """

    CELLS = 256

    def __init__(self, sv: float, tv: float, kabs: np.ndarray, ok: np.ndarray) -> None:
        self.sv, self.tv, self.kabs, self.ok = sv, tv, kabs, ok

    @classmethod
    def of(cls, pair: EdgePair, num: Any, den: Any) -> _Vertex | None:
        from fractions import Fraction as F

        def ends(p0: tuple, p1: tuple | None, e: tuple) -> tuple:
            far = p1 if p1 is not None else tuple(F(p0[k]) + F(e[k]) for k in (0, 1))
            return tuple(F(v) for v in p0), tuple(F(v) for v in far)

        ea, eb = ends(pair.a0, pair.a1, pair.ea), ends(pair.b0, pair.b1, pair.eb)
        for sv, tv in ((1, 0), (0, 1), (0, 0), (1, 1)):
            if ea[sv] == eb[tv]:
                break
        else:
            return None
        # s − sv = sa σ, t − tv = sb τ: the forms are ρ ((1 − λ) sa f_s + λ sb f_t), ρ = σ + τ
        sa, sb = (1.0 if sv == 0 else -1.0), (1.0 if tv == 0 else -1.0)
        k = np.arange(cls.CELLS + 1) / cls.CELLS  # exact
        lam = (k[:-1], k[1:])
        one = (_dn(1.0 - lam[1]), _up(1.0 - lam[0]))

        def form(f: Any) -> tuple:
            fs = (f.fs[0] * sa, f.fs[1] * sa) if sa > 0 else (-f.fs[1], -f.fs[0])
            ft = (f.ft[0] * sb, f.ft[1] * sb) if sb > 0 else (-f.ft[1], -f.ft[0])
            return _add(
                _mul((one[0][None], one[1][None]), fs), _mul((lam[0][None], lam[1][None]), ft)
            )

        with np.errstate(all="ignore"):
            kap = _div_pos(form(num), form(den))
        kabs = np.where(kap[0] > 0, kap[0], np.where(kap[1] < 0, -kap[1], 0.0))
        ok = (form(den)[1] > 0).all(axis=0)
        return cls(sv, tv, kabs, ok)

    def least(self, s: tuple, t: tuple, rlo: np.ndarray) -> np.ndarray:
        """Per box, a lower bound of ``max_n |κ_n| |r_n|`` (``rlo``: |r_n| >= rlo, (4, boxes))."""
        sig = (s[0] - self.sv, s[1] - self.sv) if self.sv == 0 else (self.sv - s[1], self.sv - s[0])
        tau = (t[0] - self.tv, t[1] - self.tv) if self.tv == 0 else (self.tv - t[1], self.tv - t[0])
        sig = (np.maximum(sig[0], 0.0), sig[1])
        tau = (np.maximum(tau[0], 0.0), tau[1])
        with np.errstate(invalid="ignore", divide="ignore"):
            lo = np.where(tau[0] > 0, _dn(tau[0] / _up(sig[1] + tau[0])), 0.0)
            hi = np.where(tau[1] > 0, _up(tau[1] / _dn(sig[0] + tau[1])), 1.0)
        n = self.CELLS
        first = np.clip(np.floor(np.nan_to_num(lo, nan=0.0) * n), 0, n - 1).astype(int)
        last = np.clip(np.ceil(np.nan_to_num(hi, nan=1.0) * n), 1, n).astype(int)
        cells = np.arange(n)
        inside = (cells[:, None] >= first[None]) & (cells[:, None] < last[None]) & self.ok[:, None]
        # max over the sides of |κ_n| |r_n| in each cell, then the least over the box's cells
        m = _dn(self.kabs[:, :, None] * rlo[:, None, :]).max(axis=0)
        return np.where(inside, m, np.inf).min(axis=0)


def _over_length(x: np.ndarray, l4: tuple) -> np.ndarray:
    """A lower bound of ``X / |d|`` from ``X >= x`` and ``|d|`` in ``l4`` (> 0 on (1))."""
    with np.errstate(invalid="ignore", divide="ignore"):
        q = np.where(x >= 0, _dn(x / l4[1]), _dn(x / l4[0]))
    return np.where(np.isnan(q), -np.inf, q)


def _forms(phic: tuple, grads: list, steps: list, ok: np.ndarray) -> np.ndarray:
    """The mean-value forms' lower ends, per side (4 rows) and per pair of sides (6 rows)."""
    mv = _add(_add(phic, _mul(steps[0], grads[0])), _mul(steps[1], grads[1]))[0]
    return np.concatenate(
        [np.where(ok & ~np.isnan(mv), mv, -np.inf), _pairs(phic, grads, steps, ok)]
    )


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
    return np.where(good, val[0], -np.inf)
