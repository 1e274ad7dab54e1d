"""The worst case in closed form: over orientations, a range of tilts and an acceleration ball.

The least squeeze per jaw for a load vector f is ``max(0, max_n V_n · f) /
(x1 + x2)`` (eqs. (17), (25), (27)), with ``V_n = (S_n, C_n)`` (eqs.
(28)-(39)).  Over the disc of loads of centre ``m R_ρ w`` and radius ``m A``
the maximum of ``V · f`` is ``m (V·R_ρ w + A|V|)`` (Cauchy-Schwarz), and over ρ
in ``[−τ, τ]`` the maximum of ``V · R_ρ w`` is ``|V||w|`` when V is within τ of
w, else the larger end ``cos τ (V·w) + sin τ |V × w|`` (:func:`_arc_max`).
:func:`_evaluate` gives the squeeze of a case and where it is reached,
:func:`_best` the least squeeze over the orientations of the case and
:func:`_slip` the contact that slips (the derivation is in
:mod:`graspcompass.sizing.core`).

Examples
--------
>>> _arc_max(-3, -2, 13 ** 0.5, (0, -10), 10, None, False)[0] == 10 * 13 ** 0.5
True
>>> _arc_max(-3, -2, 13 ** 0.5, (0, -10), 10, 0, False)  # k_1(0) = -C_1 = 2, times 10
(20.0, 0)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import sympy as sp

from ..geometry.exact import canon
from ..geometry.trig import sincos
from ..world import WorldGrasp
from ._case import Vec, _Case, _cmp, _sqrt

__all__: list[str] = []


def _arc_max(S: Any, C: Any, r: Any, w: Vec, wn: Any, tau: Any, exact: bool) -> tuple[Any, Any]:
    """``max over ρ in [−τ, τ] of V·R_ρ w`` and the maximising ρ (τ None or τ >= π: any ρ).

    R_ρ turns counter-clockwise; ``V·R_ρ w = cos ρ (V·w) + sin ρ (V·Jw)`` with
    ``Jw = (−w_y, w_x)``.
    """
    p = S * w[0] + C * w[1]
    q = -S * w[1] + C * w[0]
    atan2 = sp.atan2 if exact else math.atan2
    if _cmp(wn, 0, exact) == 0 or _cmp(r, 0, exact) == 0:
        return (sp.Integer(0) if exact else 0.0), (sp.Integer(0) if exact else 0.0)
    if tau is None or tau == "any" or _cmp(tau, sp.pi if exact else math.pi, exact) >= 0:
        return r * wn, atan2(q, p)  # an arc of ±τ >= ±π: every orientation
    if exact:
        s, c = sincos(tau)
    else:
        s, c = math.sin(tau), math.cos(tau)
    if _cmp(p, r * wn * c, exact) >= 0:  # V within τ of w: the unconstrained maximum
        return r * wn, atan2(q, p)
    sq = 1 if _cmp(q, 0, exact) >= 0 else -1
    return c * p + s * sq * q, sq * tau


def _evaluate(wg: WorldGrasp, case: _Case, any_orientation: bool) -> dict[str, Any]:
    """The squeeze per jaw of the case (or of every orientation) and where it is reached."""
    gr, exact = wg.grasp, case.exact
    if exact:
        S, C = list(gr.S), list(gr.C)
    else:
        Sf, Cf = gr._floats()
        S, C = [float(v) for v in Sf], [float(v) for v in Cf]
    D = gr.D if exact else float(gr.D)
    m, A = case.mass, case.A
    gdir_world = (
        case.gravity
        if case.gravity is not None
        else ((sp.Integer(0), sp.Integer(-1)) if exact else (0.0, -1.0))
    )
    w_world = (case.g * gdir_world[0], case.g * gdir_world[1])
    if case.accel is not None:
        w_world = (w_world[0] - case.accel[0], w_world[1] - case.accel[1])
    w = _to_paper(wg, w_world, exact)
    ghat = _to_paper(wg, gdir_world, exact)
    wn = _sqrt(w[0] ** 2 + w[1] ** 2, exact) if exact else math.hypot(*w)
    tau = (
        None
        if (any_orientation or case.tilt == "any" or case.gravity is None)
        else (case.tilt if case.tilt is not None else (sp.Integer(0) if exact else 0.0))
    )
    vals, rhos, rs = [], [], []
    for Sn, Cn in zip(S, C):
        r = _sqrt(Sn**2 + Cn**2, exact) if exact else math.hypot(Sn, Cn)
        top, rho = _arc_max(Sn, Cn, r, w, wn, tau, exact)
        vals.append(top + A * r)
        rhos.append(rho)
        rs.append(r)
    best = 0
    for n in range(1, 4):
        if _cmp(vals[n], vals[best], exact) > 0:
            best = n
    top = vals[best]
    positive = _cmp(top, 0, exact) > 0
    per_jaw = (m * top / D * case.safety) if positive else (sp.Integer(0) if exact else 0.0)
    if exact:
        per_jaw = canon(per_jaw)
    rho = rhos[best]
    # the worst load, in the paper's frame: m (R_ρ w + A V/|V|)
    cr, sr = math.cos(float(rho)), math.sin(float(rho))
    wf = (float(w[0]), float(w[1]))
    rw = (cr * wf[0] - sr * wf[1], sr * wf[0] + cr * wf[1])
    rf = float(rs[best])
    u = (float(S[best]) / rf, float(C[best]) / rf) if rf > 0 else (0.0, 0.0)
    load = (rw[0] + float(A) * u[0], rw[1] + float(A) * u[1])
    gh = (float(ghat[0]), float(ghat[1]))
    grav = (cr * gh[0] - sr * gh[1], sr * gh[0] + cr * gh[1])
    return {
        "per_jaw": per_jaw,
        "side": best + 1,
        "positive": positive,
        "load": _world_vec(wg, load),
        "gravity": _world_vec(wg, grav),
        "accel": _world_vec(wg, (-u[0], -u[1])) if float(A) > 0 and rf > 0 else None,
        "S": S,
        "C": C,
        "D": D,
        "w": w,
        "ghat": ghat,
        "rs": rs,
        "tau": tau,
    }


def _to_paper(wg: WorldGrasp, v: Vec, exact: bool) -> Vec:
    ex, ey = wg.ex, wg.ey
    if exact:
        return (canon(v[0] * ex[0] + v[1] * ex[1]), canon(v[0] * ey[0] + v[1] * ey[1]))
    exf, eyf = (float(ex[0]), float(ex[1])), (float(ey[0]), float(ey[1]))
    return (
        float(v[0]) * exf[0] + float(v[1]) * exf[1],
        float(v[0]) * eyf[0] + float(v[1]) * eyf[1],
    )


def _world_vec(wg: WorldGrasp, v: tuple[float, float]) -> tuple[float, float]:
    ex, ey = (float(wg.ex[0]), float(wg.ex[1])), (float(wg.ey[0]), float(wg.ey[1]))
    return (v[0] * ex[0] + v[1] * ey[0], v[0] * ex[1] + v[1] * ey[1])


def _slip(wg: WorldGrasp, side: int) -> tuple[str, tuple[float, float]]:
    """The contact of cone side n and the world direction the part slides along there.

    At side n the contact force lies on the upper (n = 1, 2: F_i = +μ_i N_i,
    inequalities (8), (9)) or lower (n = 3, 4: F_i = −μ_i N_i, (10), (11)) side of
    its cone; friction pushes the part along ±t_i, so it starts to slide along
    ∓t_i, with t1 = (−cos φ1, sin φ1), t2 = (cos φ2, sin φ2) (the columns of L, eq. (5)).
    """
    g = wg.grasp
    if side in (1, 3):
        t = (-float(g.c1), float(g.s1))
    else:
        t = (float(g.c2), float(g.s2))
    sign = -1.0 if side in (1, 2) else 1.0
    v = _world_vec(wg, (sign * t[0], sign * t[1]))
    return wg.names[0 if side in (1, 3) else 1], (v[0] + 0.0, v[1] + 0.0)


def _best(ev: dict[str, Any], case: _Case) -> tuple[float, tuple[float, float]]:
    """The least squeeze per jaw over the orientations of the case, and ĝ there (paper frame).

    Minimises ``h(ρ) = max_n (a_n cos ρ + b_n sin ρ + c_n)`` over ρ in [−τ, τ]
    (a_n = V_n·w, b_n = V_n·Jw, c_n = A‖V_n‖): the minimum is at an end of the
    range, at the minimum ``ρ = atan2(−b_n, −a_n)`` of one term, or where two terms
    are equal; every such candidate is evaluated.
    """
    S = np.array([float(v) for v in ev["S"]])
    C = np.array([float(v) for v in ev["C"]])
    w = (float(ev["w"][0]), float(ev["w"][1]))
    a = S * w[0] + C * w[1]
    b = -S * w[1] + C * w[0]
    c = float(case.A) * np.hypot(S, C)
    tau = ev["tau"]
    cands = [np.arctan2(-b, -a)]
    for i in range(4):
        for j in range(i + 1, 4):
            da, db, dc = a[i] - a[j], b[i] - b[j], c[j] - c[i]
            R = math.hypot(da, db)
            if R > 0 and abs(dc) <= R:
                phi, off = math.atan2(db, da), math.acos(max(-1.0, min(1.0, dc / R)))
                cands.append(np.array([phi + off, phi - off]))
    rho = np.concatenate([np.atleast_1d(x) for x in cands])
    rho = (rho + math.pi) % (2 * math.pi) - math.pi
    if tau is not None:
        t = float(tau)
        rho = np.concatenate([np.clip(rho, -t, t), [-t, t]])
    h = (np.multiply.outer(np.cos(rho), a) + np.multiply.outer(np.sin(rho), b) + c).max(axis=1)
    k = int(np.argmin(h))
    value = max(0.0, float(h[k])) * float(case.mass) / float(ev["D"]) * float(case.safety)
    cr, sr = math.cos(rho[k]), math.sin(rho[k])
    gh = (float(ev["ghat"][0]), float(ev["ghat"][1]))
    return value, (cr * gh[0] - sr * gh[1], sr * gh[0] + cr * gh[1])


def _need_float(wg: WorldGrasp, case: _Case, S: np.ndarray, C: np.ndarray, D: float) -> float:
    """The case's squeeze per jaw for float S_n, C_n (same as :func:`_evaluate`, floats)."""
    gdir = case.gravity if case.gravity is not None else (0.0, -1.0)
    w_world = (case.g * gdir[0], case.g * gdir[1])
    if case.accel is not None:
        w_world = (w_world[0] - case.accel[0], w_world[1] - case.accel[1])
    w = _to_paper(wg, w_world, False)
    wn = math.hypot(*w)
    tau = (
        None
        if (case.tilt == "any" or case.gravity is None)
        else (case.tilt if case.tilt is not None else 0.0)
    )
    top = -math.inf
    for Sn, Cn in zip(S.tolist(), C.tolist()):
        r = math.hypot(Sn, Cn)
        v, _ = _arc_max(Sn, Cn, r, w, wn, tau, False)
        top = max(top, v + case.A * r)
    return max(0.0, top) * case.mass / D * case.safety
