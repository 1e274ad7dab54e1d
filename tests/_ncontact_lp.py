"""An independent LP for the n-contact tests (scipy HiGHS), written from first principles.

Not the model's code: the edge wrenches are rebuilt here from the contacts.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import linprog


def edge_matrix(contacts, com=(0.0, 0.0)):
    """G (3 × 2n) and the edge-to-contact map, from (x, y, nx, ny, mu) floats."""
    cols, owner = [], []
    for i, (x, y, nx, ny, mu) in enumerate(contacts):
        r = math.hypot(nx, ny)
        nx, ny = nx / r, ny / r
        for s in (1, -1):
            dx, dy = nx - s * mu * ny, ny + s * mu * nx   # n ± μ J n, J = quarter turn ccw
            px, py = x - com[0], y - com[1]
            cols.append((dx, dy, px * dy - py * dx))
            owner.append(i)
    return np.array(cols).T, np.array(owner)


def lp_value(contacts, theta, effort, com=(0.0, 0.0)):
    """The least effort for the load e(θ) = (sin θ, -cos θ) at the centre of mass; inf if none."""
    G, owner = edge_matrix(contacts, com)
    n2 = G.shape[1]
    b = -np.array([math.sin(theta), -math.cos(theta), 0.0])
    normals = np.array([(c[2], c[3]) / np.hypot(c[2], c[3]) for c in contacts])
    edges = G[:2].T
    named = isinstance(effort, str)
    if named and effort == "max-normal":
        n = len(contacts)
        A_eq = np.hstack([G, np.zeros((3, 1))])
        A_ub = np.zeros((n, n2 + 1))
        for j in range(n2):
            A_ub[owner[j], j] = 1.0
        A_ub[:, -1] = -1.0
        c = np.zeros(n2 + 1)
        c[-1] = 1.0
        res = linprog(c, A_ub=A_ub, b_ub=np.zeros(n), A_eq=A_eq, b_eq=b, bounds=(0, None),
                      method="highs")
    else:
        if not named:  # custom weights of the normal forces
            w = normals * np.asarray(effort, dtype=float)[:, None]
        elif effort == "sum-normal":
            w = normals
        elif effort.startswith("pair:"):
            i, j = (int(v) - 1 for v in effort[5:].split(","))
            w = np.array([normals[k] if k in (i, j) else (0.0, 0.0)
                          for k in range(len(contacts))])
        else:
            assert effort == "paper"
            p1, p2 = np.array(contacts[0][:2]), np.array(contacts[1][:2])
            w = np.array([(p2 - p1) / 2, (p1 - p2) / 2])
        c = np.einsum("jk,jk->j", w[owner], edges)
        kw = {}
        if named and effort == "paper":  # k >= 0 (eq. (25))
            kw = dict(A_ub=-c[None, :], b_ub=[0.0])
        res = linprog(c, A_eq=G, b_eq=b, bounds=(0, None), method="highs", **kw)
    if res.status == 2:
        return math.inf
    assert res.status == 0, res.message
    return res.fun


def force_closure(contacts, com=(0.0, 0.0)):
    """Every unit wrench ±e_k is a nonnegative combination of the edge wrenches."""
    G, _ = edge_matrix(contacts, com)
    for k in range(3):
        for s in (1, -1):
            b = np.zeros(3)
            b[k] = s
            res = linprog(np.zeros(G.shape[1]), A_eq=G, b_eq=b, bounds=(0, None),
                          method="highs")
            if res.status != 0:
                return False
    return True


def random_contacts(rng, n, closure=True):
    """Contacts near a unit circle around a shifted centre, inward normals tilted ±0.5 rad.

    ``closure=False`` puts them on an arc of 100°-160° (often not in force closure).
    """
    cx, cy = rng.uniform(-0.3, 0.3, 2)
    if closure:
        angles = np.sort(rng.uniform(0, 2 * math.pi, n))
    else:
        angles = np.sort(rng.uniform(0, rng.uniform(1.7, 2.8), n))
    out = []
    for a in angles:
        r = rng.uniform(0.8, 1.2)
        x, y = cx + r * math.cos(a), cy + r * math.sin(a)
        t = a + math.pi + rng.uniform(-0.5, 0.5)
        out.append((x, y, math.cos(t), math.sin(t), rng.uniform(0.15, 0.8)))
    return out
