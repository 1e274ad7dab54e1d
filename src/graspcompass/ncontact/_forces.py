"""The contact forces at the optimum for one θ (the slip diagnosis, generalised).

On the arc of θ where a vertex q_B of Q is the maximiser, the primal basic
solution of its basis B is optimal (complementary slackness): the weights of the
tight edges solve ``A_B x = (-F_e e(θ), 0, [0])``; the other edges carry nothing.
For n = 2 and the paper's effort the tight edges of V_n are the cone side named
in k_n and both sides of the other contact (the sides on which (8)-(11) is tight).
The sublinear effort ``max-normal`` is solved by :mod:`._forces_max`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..boundary.inputs import angle_values
from ..geometry.exact import canon
from ..geometry.trig import sincos
from ._signs import det
from .errors import NContactError
from .polygon import exact_sgn

if TYPE_CHECKING:
    from .model import NContactGrasp

__all__ = ["optimal_forces"]


def _solve_exact(cols: list[list[sp.Expr]], b: list[sp.Expr]) -> list[sp.Expr] | None:
    d = len(b)
    M = [[cols[t][r] for t in range(d)] for r in range(d)]  # columns are the constraint rows
    D = canon(det(M))
    if exact_sgn(D, "a basis determinant") == 0:
        return None
    out = []
    for t in range(d):
        m = [[*row[:t], b[r], *row[t + 1 :]] for r, row in enumerate(M)]
        out.append(canon(det(m) / D))
    return out


def optimal_forces(g: NContactGrasp, theta: Any, fe: Any) -> dict[str, Any]:
    """See :meth:`graspcompass.ncontact.NContactGrasp.forces`."""
    t = angle_values(theta)
    Q = g.polygon()
    numeric = g.numeric or isinstance(t, (float, np.ndarray))
    if isinstance(t, np.ndarray):
        raise NContactError("forces() takes one θ at a time")
    none = {"effort": None, "vertex": None, "basis": None, "weights": None, "forces": None}
    if numeric:
        tf = float(t)
        e = (np.sin(tf), -np.cos(tf))
        val = Q.support(tf, float(fe))
        if not np.isfinite(val):
            return {**none, "effort": float("inf")}
        V = Q.float_vertices()
        vals = V[:, 0] * e[0] + V[:, 1] * e[1]
        tol = 1e-9 * (1 + np.abs(V).max())
        ks = [int(i) for i in np.argsort(-vals) if vals[i] >= vals.max() - tol]  # ties
    else:
        s, c = sincos(t)
        e = (s, -c)
        val, k = Q.support_exact(t, fe)
        if k is None:
            return {**none, "effort": sp.oo}
        ks = [k]
    zero = 0.0 if numeric else sp.Integer(0)
    if not g.effort.linear:  # the largest normal force: complementary slackness on d
        from ._forces_max import optimal_max_normal

        rhs = [-fe * e[0], -fe * e[1], zero]
        return optimal_max_normal(
            g, Q, ks, rhs if numeric else [canon(v) for v in rhs], val, numeric
        )
    rows, _ = g.dual_system()
    labels = g.constraint_labels()
    edges = g.edges()
    d = len(rows[0])
    b = [-fe * e[0], -fe * e[1]] + [zero] * (d - 2)
    if not numeric:
        b = [canon(v) for v in b]
    for basis, cand in (
        (b, c) for c in (Q.candidates[Q.vertex_index[k]] for k in ks) for b in c.bases
    ):
        cols = [list(rows[r]) for r in basis]
        x: list[Any] | None
        if numeric:
            M = np.array(cols, dtype=float).T
            try:
                sol = np.linalg.solve(M, np.array(b, dtype=float))
            except np.linalg.LinAlgError:
                continue
            if np.any(sol < -1e-9 * (1 + np.abs(sol).max())):
                continue
            x = [max(v, 0.0) for v in sol.tolist()]
        else:
            x = _solve_exact(cols, b)
            if x is None or any(exact_sgn(v, "an edge weight") < 0 for v in x):
                continue
        return _result(g, basis, x, cand.q, val, labels, edges, zero, numeric)
    if numeric:  # a degenerate vertex (coincident or parallel edges): any weights w >= 0
        # that balance the load at the least effort (rows^T w = b, costs . w = v) are optimal
        costs = g.dual_system()[1]
        M = np.array([[*r, c] for r, c in zip(rows, costs)], dtype=float).T
        load = np.array([*b, val], dtype=float)
        w = _nnls(M, load)
        if np.abs(M @ w - load).max() <= 1e-9 * (1 + np.abs(M).max() * (1 + w.sum())):
            used = [r for r in range(len(rows)) if w[r] > 0]
            x = [float(w[r]) for r in used]
            cand = Q.candidates[Q.vertex_index[ks[0]]]
            return _result(g, used, x, cand.q, val, labels, edges, zero, numeric)
        raise NContactError(
            f"the optimal contact forces at theta = {tf!r} are not resolved in double "
            "precision (the tight cone edges are nearly dependent); give the grasp "
            "exactly (values as text) for its exact forces"
        )
    raise NContactError(
        "no basis of the optimal vertex gives nonnegative edge weights "
        "(a degenerate case): please report the grasp"
    )


def _result(
    g: NContactGrasp,
    basis: list[int],
    x: list[Any],
    q: Any,
    val: Any,
    labels: list[str],
    edges: list[Any],
    zero: Any,
    numeric: bool,
) -> dict[str, Any]:
    """The forces of edge weights ``x`` on the constraints ``basis``."""
    n_edges = 2 * g.n
    weights = {labels[r]: x[i] for i, r in enumerate(basis) if r < n_edges}
    forces = []
    for i in range(g.n):
        fx = fy = zero
        for j, (ci, _, dj) in enumerate(edges):
            if ci == i and labels[j] in weights:
                fx = fx + weights[labels[j]] * dj[0]
                fy = fy + weights[labels[j]] * dj[1]
        forces.append((fx, fy) if numeric else (canon(fx), canon(fy)))
    return {
        "effort": val,
        "vertex": q,
        "basis": [labels[r] for r in basis],
        "weights": weights,
        "forces": forces,
    }


def _nnls(A: np.ndarray, b: np.ndarray, iters: int = 200) -> np.ndarray:
    """Least squares with x >= 0 (Lawson and Hanson's active-set method)."""
    n = A.shape[1]
    x = np.zeros(n)
    free = np.zeros(n, dtype=bool)
    tol = 1e-12 * (1 + np.abs(A).max()) * (1 + np.abs(b).max())
    for _ in range(iters):
        grad = A.T @ (b - A @ x)
        if free.all() or grad[~free].max(initial=-np.inf) <= tol:
            break
        free[int(np.argmax(np.where(free, -np.inf, grad)))] = True
        for _ in range(iters):
            z = np.zeros(n)
            z[free] = np.linalg.lstsq(A[:, free], b, rcond=None)[0]
            if (z[free] > 0).all():
                x = z
                break
            neg = free & (z <= 0)
            alpha = np.min(x[neg] / (x[neg] - z[neg]))
            x = x + alpha * (z - x)
            free &= x > tol
            x[~free] = 0.0
    return x
