"""An independent LP for the n-contact tests (scipy HiGHS), written from first principles.

Not the model's code: the edge wrenches are rebuilt here from the contacts.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import linprog

try:  # scipy's own binding of HiGHS: one model, re-solved warm for each θ
    from scipy.optimize._highspy import _core as _hc
except ImportError:  # pragma: no cover - an older scipy: linprog per θ
    _hc = None


def edge_matrix(contacts, com=(0.0, 0.0)):
    """G (3 × 2n) and the edge-to-contact map, from (x, y, nx, ny, mu) floats."""
    cols, owner = [], []
    for i, (x, y, nx, ny, mu) in enumerate(contacts):
        r = math.hypot(nx, ny)
        nx, ny = nx / r, ny / r
        for s in (1, -1):
            dx, dy = nx - s * mu * ny, ny + s * mu * nx  # n ± μ J n, J = quarter turn ccw
            px, py = x - com[0], y - com[1]
            cols.append((dx, dy, px * dy - py * dx))
            owner.append(i)
    return np.array(cols).T, np.array(owner)


def lp_data(contacts, effort, com=(0.0, 0.0)):
    """(cost, A_eq, A_ub, b_ub) of the LP for one grasp and effort; the equality's
    right-hand side -(e(θ), 0) is the only part that depends on θ."""
    G, owner = edge_matrix(contacts, com)
    n2 = G.shape[1]
    normals = np.array([(c[2], c[3]) / np.hypot(c[2], c[3]) for c in contacts])
    edges = G[:2].T
    named = isinstance(effort, str)
    if named and effort == "max-normal":  # min t with N_i <= t
        n = len(contacts)
        A_eq = np.hstack([G, np.zeros((3, 1))])
        A_ub = np.zeros((n, n2 + 1))
        for j in range(n2):
            A_ub[owner[j], j] = 1.0
        A_ub[:, -1] = -1.0
        c = np.zeros(n2 + 1)
        c[-1] = 1.0
        return c, A_eq, A_ub, np.zeros(n)
    if not named:  # custom weights of the normal forces
        w = normals * np.asarray(effort, dtype=float)[:, None]
    elif effort == "sum-normal":
        w = normals
    elif effort.startswith("pair:"):
        i, j = (int(v) - 1 for v in effort[5:].split(","))
        w = np.array([normals[k] if k in (i, j) else (0.0, 0.0) for k in range(len(contacts))])
    else:
        assert effort == "paper"
        p1, p2 = np.array(contacts[0][:2]), np.array(contacts[1][:2])
        w = np.array([(p2 - p1) / 2, (p1 - p2) / 2])
    c = np.einsum("jk,jk->j", w[owner], edges)
    if named and effort == "paper":  # k >= 0 (eq. (25))
        return c, G, -c[None, :], np.zeros(1)
    return c, G, np.zeros((0, n2)), np.zeros(0)


class SweepLP:
    """One HiGHS model per grasp and effort, re-solved for each θ (only the equality's
    right-hand side changes, so the previous optimal basis is the warm start)."""

    def __init__(self, contacts, effort, com=(0.0, 0.0)):
        self.c, self.A_eq, self.A_ub, self.b_ub = lp_data(contacts, effort, com)
        self.h = None
        if _hc is None:
            return
        A = np.vstack([self.A_eq, self.A_ub])
        m, nv = A.shape
        h = _hc._Highs()
        h.setOptionValue("output_flag", False)
        h.setOptionValue("presolve", "off")
        lp = _hc.HighsLp()
        lp.num_col_, lp.num_row_ = nv, m
        lp.col_cost_ = self.c
        lp.col_lower_ = np.zeros(nv)
        lp.col_upper_ = np.full(nv, _hc.kHighsInf)
        lp.row_lower_ = np.concatenate([np.zeros(3), np.full(len(self.b_ub), -_hc.kHighsInf)])
        lp.row_upper_ = np.concatenate([np.zeros(3), self.b_ub])
        mat = lp.a_matrix_
        mat.format_ = _hc.MatrixFormat.kColwise
        mat.start_ = np.arange(0, m * nv + 1, m, dtype=np.int32)
        mat.index_ = np.tile(np.arange(m, dtype=np.int32), nv)
        mat.value_ = A.T.ravel()
        lp.a_matrix_ = mat
        h.passModel(lp)
        self.h = h

    def __call__(self, theta):
        """The LP's value at each θ (sorted θ make the warm starts short); inf if infeasible."""
        out = np.empty(len(theta))
        for k, t in enumerate(theta):
            b = (-math.sin(t), math.cos(t), 0.0)
            if self.h is None:
                kw = dict(A_ub=self.A_ub, b_ub=self.b_ub) if len(self.b_ub) else {}
                res = linprog(
                    self.c, A_eq=self.A_eq, b_eq=b, bounds=(0, None), method="highs", **kw
                )
                assert res.status in (0, 2), res.message
                out[k] = res.fun if res.status == 0 else math.inf
                continue
            for i in range(3):
                self.h.changeRowBounds(i, b[i], b[i])
            self.h.run()
            st = self.h.getModelStatus()
            if st == _hc.HighsModelStatus.kOptimal:
                out[k] = self.h.getInfo().objective_function_value
            else:
                assert st == _hc.HighsModelStatus.kInfeasible, self.h.modelStatusToString(st)
                out[k] = math.inf
        return out


def lp_value(contacts, theta, effort, com=(0.0, 0.0)):
    """The least effort for the load e(θ) = (sin θ, -cos θ) at the centre of mass; inf if none
    (scipy's ``linprog`` on :func:`lp_data`)."""
    c, A_eq, A_ub, b_ub = lp_data(contacts, effort, com)
    b = -np.array([math.sin(theta), -math.cos(theta), 0.0])
    kw = dict(A_ub=A_ub, b_ub=b_ub) if len(b_ub) else {}
    res = linprog(c, A_eq=A_eq, b_eq=b, bounds=(0, None), method="highs", **kw)
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
            res = linprog(np.zeros(G.shape[1]), A_eq=G, b_eq=b, bounds=(0, None), method="highs")
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
