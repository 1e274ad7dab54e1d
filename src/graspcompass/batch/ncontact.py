"""Many n-contact grasps at once: the least effort v(θ) for arrays of grasps (issue 25).

``contacts`` has shape ``(..., n, 5)``: per grasp n contacts ``(x, y, nx, ny, mu)``
(numpy, float).  For every grasp the dual of the LP of :mod:`graspcompass.ncontact`
is enumerated at once over its C(2n, 3) bases (batched 3 × 3 solves, no loop over
grasps): the dual-feasible basic solutions y give the points q = -(y_1, y_2) of Q,
and ``v(θ) = F_e max_q q·e(θ)`` (the maximum of a linear function over the dual
polyhedron is reached at a vertex, and every dual-feasible basic solution lies in
it).  Without force closure v = inf where ``e·ρ > 0`` for a recession direction ρ of
Q (batched over pairs of rows).  Linear efforts only: ``"sum-normal"``,
``"pair:I,J"`` or weights of the normal forces of shape ``(..., n)``.

Numpy only (not the Array API of :mod:`graspcompass.batch`): the bases are solved
with :func:`numpy.linalg.solve` on stacked matrices.  Relative tolerance 1e-9.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

__all__ = ["ncontact_k", "ncontact_worst"]

_TOL = 1e-9


def _rows(contacts: np.ndarray, weights: np.ndarray, com: np.ndarray) -> tuple:
    p = contacts[..., :2] - com[..., None, :]
    nrm = contacts[..., 2:4] / np.linalg.norm(contacts[..., 2:4], axis=-1, keepdims=True)
    mu = contacts[..., 4:5]
    jn = np.stack([-nrm[..., 1], nrm[..., 0]], axis=-1)
    d = np.stack([nrm + mu * jn, nrm - mu * jn], axis=-2)  # (..., n, 2, 2)
    pp = np.broadcast_to(p[..., None, :], d.shape)
    torque = pp[..., 0] * d[..., 1] - pp[..., 1] * d[..., 0]
    G = np.concatenate([d, torque[..., None]], axis=-1)  # (..., n, 2, 3)
    c = (weights[..., None] * np.ones(2)) * np.einsum("...k,...sk->...s", nrm, d)
    shape = (*G.shape[:-3], G.shape[-3] * 2)
    return G.reshape((*shape, 3)), c.reshape(shape)


def _q_rays(G: np.ndarray) -> np.ndarray:
    """Per grasp and pair of rows, both signs: is it a recession direction of the dual whose
    force part is non-zero (a direction in which Q is unbounded)?  Shape (..., 2·pairs)."""
    m = G.shape[-2]
    pairs = np.array(list(itertools.combinations(range(m), 2)))
    r = np.cross(G[..., pairs[:, 0], :], G[..., pairs[:, 1], :])
    r = r / np.maximum(np.linalg.norm(r, axis=-1, keepdims=True), 1e-300)
    dots = np.einsum("...jk,...pk->...pj", G, r)
    gn = np.linalg.norm(G, axis=-1)[..., None, :]
    moving = np.linalg.norm(r[..., :2], axis=-1) > 1e-12
    return np.concatenate(
        [np.all(sg * dots <= _TOL * gn, axis=-1) & moving for sg in (1.0, -1.0)], axis=-1
    )


def ncontact_k(
    contacts: Any,
    theta: Any,
    effort: Any = "sum-normal",
    com: Any = (0.0, 0.0),
    external_force: float = 1.0,
) -> np.ndarray:
    """The least effort of each grasp at each θ: shape ``broadcast(grasps) + θ.shape``.

    Parameters
    ----------
    contacts : array_like, shape (..., n, 5)
        ``(x, y, nx, ny, mu)`` per contact (the normal any nonzero vector).
    theta : array_like
        Load directions, e(θ) = (sin θ, -cos θ) (eq. (26)).
    effort : str or array_like
        ``"sum-normal"``, ``"pair:I,J"`` (1-based) or weights of shape (..., n).
    com : array_like, shape (..., 2)
        Centres of mass.
    external_force : float
        F_e.

    Returns
    -------
    numpy.ndarray
        ``inf`` where the load cannot be held.
    """
    P = np.asarray(contacts, dtype=float)
    if P.ndim < 2 or P.shape[-1] != 5 or P.shape[-2] < 2:
        raise ValueError(f"contacts: expected shape (..., n >= 2, 5), got {P.shape}")
    n = P.shape[-2]
    if isinstance(effort, str):
        if effort == "sum-normal":
            w = np.ones(P.shape[:-1])
        elif effort.startswith("pair:"):
            i, j = (int(v) - 1 for v in effort[5:].split(","))
            w = np.zeros(P.shape[:-1])
            w[..., [i, j]] = 1.0
        else:
            raise ValueError(f"effort {effort!r}: batch takes sum-normal, pair:I,J or weights")
    else:
        w = np.broadcast_to(np.asarray(effort, dtype=float), P.shape[:-1])
    com = np.broadcast_to(np.asarray(com, dtype=float), (*P.shape[:-2], 2))
    G, c = _rows(P, w, com)  # (..., 2n, 3), (..., 2n)
    combos = np.array(list(itertools.combinations(range(2 * n), 3)))
    A = G[..., combos, :]  # (..., C, 3, 3)
    b = c[..., combos]  # (..., C, 3)
    scale = np.prod(np.linalg.norm(A, axis=-1), axis=-1)
    det = np.linalg.det(A)
    ok = np.abs(det) > 1e-12 * scale
    A_safe = np.where(ok[..., None, None], A, np.eye(3))
    y = np.linalg.solve(A_safe, b[..., None])[..., 0]  # (..., C, 3)
    slack = c[..., None, :] - np.einsum("...jk,...ck->...cj", G, y)
    tol = _TOL * (
        1.0
        + np.abs(c)[..., None, :]
        + np.linalg.norm(G, axis=-1)[..., None, :] * np.linalg.norm(y, axis=-1)[..., None]
    )
    feas = ok & np.all(slack >= -tol, axis=-1)  # (..., C)
    q = -y[..., :2]
    th = np.asarray(theta, dtype=float)
    e = np.stack([np.sin(th), -np.cos(th)], axis=-1).reshape(-1, 2)
    val = np.einsum("...ck,tk->...ct", q, e)
    val = np.where(feas[..., None], val, -np.inf).max(axis=-2)  # (..., T)
    # recession directions of the dual: r with G r <= 0 (from pairs of rows, both signs)
    pairs = np.array(list(itertools.combinations(range(2 * n), 2)))
    r = np.cross(G[..., pairs[:, 0], :], G[..., pairs[:, 1], :])  # (..., Pp, 3)
    r = r / np.maximum(np.linalg.norm(r, axis=-1, keepdims=True), 1e-300)
    dots = np.einsum("...jk,...pk->...pj", G, r)
    gn = np.linalg.norm(G, axis=-1)[..., None, :]
    unbounded = np.zeros(val.shape, dtype=bool)
    for sg in (1.0, -1.0):
        ray = np.all(sg * dots <= _TOL * gn, axis=-1) & (
            np.linalg.norm(r[..., :2], axis=-1) > 1e-12
        )
        rho = -sg * r[..., :2]  # Q's direction: -r_f
        hit = np.einsum("...pk,tk->...pt", rho, e) > 1e-12
        unbounded |= np.any(ray[..., None] & hit, axis=-2)
    out = np.where(unbounded | ~np.isfinite(val), math.inf, val) * external_force
    return out.reshape(val.shape[:-1] + th.shape)


def ncontact_worst(
    contacts: Any, effort: Any = "sum-normal", com: Any = (0.0, 0.0), external_force: float = 1.0
) -> np.ndarray:
    """``F_e max_q |q|`` per grasp (the worst direction's least effort): shape ``(...)``.

    ``inf`` without force closure.  The maximum of ``|q|`` over Q is reached at a vertex and
    every dual-feasible basic solution lies in Q, so the maximum over them is it.
    """
    P = np.asarray(contacts, dtype=float)
    if P.ndim < 2 or P.shape[-1] != 5 or P.shape[-2] < 2:
        raise ValueError(f"contacts: expected shape (..., n >= 2, 5), got {P.shape}")
    n = P.shape[-2]
    w = (
        np.ones(P.shape[:-1])
        if isinstance(effort, str) and effort == "sum-normal"
        else np.broadcast_to(np.asarray(effort, dtype=float), P.shape[:-1])
    )
    comb = np.broadcast_to(np.asarray(com, dtype=float), (*P.shape[:-2], 2))
    G, c = _rows(P, w, comb)
    combos = np.array(list(itertools.combinations(range(2 * n), 3)))
    A = G[..., combos, :]
    scale = np.prod(np.linalg.norm(A, axis=-1), axis=-1)
    ok = np.abs(np.linalg.det(A)) > 1e-12 * scale
    y = np.linalg.solve(np.where(ok[..., None, None], A, np.eye(3)), c[..., combos][..., None])[
        ..., 0
    ]
    slack = c[..., None, :] - np.einsum("...jk,...ck->...cj", G, y)
    tol = _TOL * (
        1.0
        + np.abs(c)[..., None, :]
        + np.linalg.norm(G, axis=-1)[..., None, :] * np.linalg.norm(y, axis=-1)[..., None]
    )
    feas = ok & np.all(slack >= -tol, axis=-1)
    r2 = np.where(feas, y[..., 0] ** 2 + y[..., 1] ** 2, -np.inf).max(axis=-1)
    held = ~np.any(_q_rays(G), axis=-1)
    return np.where(held & np.isfinite(r2), np.sqrt(np.maximum(r2, 0.0)), math.inf) * external_force
