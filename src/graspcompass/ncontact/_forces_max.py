"""The contact forces at the optimum for the effort ``max_i N_i`` (the largest normal force).

The LP is ``min t`` subject to ``G a = -F_e (e(θ), 0)``, ``N_i = a_{i+} + a_{i-} <= t`` and
``a >= 0`` (edge weights are normal forces).  Its dual optimum at θ is the direction d
of the maximising vertex q of Q (``q = -d_f / f(d)``, :mod:`.maxnormal`), with the
multipliers ``z_i = max(0, g_{i+}·d, g_{i-}·d)`` of ``N_i <= t``.  Complementary
slackness says which primal variables may be nonzero:

* an edge j of contact i carries a force only if it is *tight*, ``g_j·d = z_i``;
* a contact with ``z_i > 0`` carries the largest normal force, ``N_i = t``.

So the optimal forces solve ``G_S a_S = -F_e (e, 0)`` and ``N_i = t`` (``z_i > 0``) for a
set S of tight edges, with ``a_S >= 0``, ``N_i <= t`` elsewhere and ``t = v(θ)``: a
square system for the two ties of a generic vertex, and a choice of S among the tight
edges for a degenerate one (the first feasible choice is returned).  Exact signs on
the exact path (``decide_sign``), a relative tolerance on the float path.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..geometry.exact import canon
from ._signs import det
from .errors import NContactError
from .maxnormal import _cross, _dot, _ties
from .polygon import exact_sgn

if TYPE_CHECKING:
    from .model import NContactGrasp

__all__ = ["max_normal_forces"]


def _direction(G: list[tuple], cand: Any, numeric: bool) -> list[tuple]:
    """The dual directions d (one per basis of the candidate) with ``-d_f / f(d) = q``."""
    if numeric:
        G = [tuple(float(v) for v in w) for w in G]
    ties = _ties(G)
    labels = [f"P{i + 1}{name}" for i, name, _, _ in ties]
    out = []
    for basis in cand.bases:
        a, b = (labels.index(x) if isinstance(x, str) else int(x) for x in basis)
        c = _cross(ties[a][2], ties[b][2])
        for s in (1, -1):
            d = tuple(s * v for v in c)
            if numeric:
                d = tuple(float(v) for v in d)
                f = sum(
                    max(0.0, _dot(G[2 * i], d), _dot(G[2 * i + 1], d)) for i in range(len(G) // 2)
                )
                qx, qy = cand.floats()
                if f > 0 and abs(-d[0] / f - qx) + abs(-d[1] / f - qy) <= 1e-7 * (
                    1 + abs(qx) + abs(qy)
                ):
                    out.append(d)
            else:
                d = tuple(canon(v) for v in d)
                f = 0
                for i in range(len(G) // 2):
                    lp, lm = canon(_dot(G[2 * i], d)), canon(_dot(G[2 * i + 1], d))
                    m = lp if exact_sgn(lp - lm, "a comparison") >= 0 else lm
                    if exact_sgn(m, "a normal force's sign") > 0:
                        f = f + m
                # q = (X, Y) / W, W > 0, must be -d_f / f(d) with f(d) > 0
                if (
                    exact_sgn(canon(f), "the effort of a direction") > 0
                    and exact_sgn(canon(-d[0] * cand.W - cand.X * f), "q_x") == 0
                    and exact_sgn(canon(-d[1] * cand.W - cand.Y * f), "q_y") == 0
                ):
                    out.append(d)
    return out


def _solve(M: list[list[Any]], b: list[Any], numeric: bool) -> list[Any] | None:
    """The unique solution of the (possibly overdetermined) system ``M x = b``, or None."""
    m, k = len(M), len(M[0])
    for rows in itertools.combinations(range(m), k):
        sub = [M[r] for r in rows]
        if numeric:
            A = np.array(sub, dtype=float)
            scale = float(np.prod(np.linalg.norm(A, axis=1))) or 1.0
            if abs(np.linalg.det(A)) <= 1e-12 * scale:
                continue
            x = np.linalg.solve(A, np.array([b[r] for r in rows], dtype=float)).tolist()
            res = np.array(M, dtype=float) @ np.array(x) - np.array(b, dtype=float)
            tol = (
                1e-9
                * (1 + float(np.abs(np.array(b, dtype=float)).max()))
                * (1 + float(np.abs(x).max()))
            )
            return x if np.all(np.abs(res) <= tol) else None
        D = canon(det(sub))
        if exact_sgn(D, "a determinant of tight edges") == 0:
            continue
        x = []
        for t in range(k):
            mt = [[*row[:t], b[r], *row[t + 1 :]] for row, r in zip(sub, rows)]
            x.append(canon(det(mt) / D))
        for r in range(m):
            if (
                r not in rows
                and exact_sgn(
                    sum(M[r][t] * x[t] for t in range(k)) - b[r],
                    "a residual of the optimality system",
                )
                != 0
            ):
                return None
        return x
    return None


def max_normal_forces(
    g: NContactGrasp, d: tuple, rhs: list[Any], value: Any, numeric: bool
) -> dict[str, Any] | None:
    """The optimal forces for the dual direction d (None if no tight set is feasible)."""
    G = [tuple(w) for w in g.wrenches()]
    n = g.n
    if numeric:
        G = [tuple(float(v) for v in w) for w in G]
        scale = max(abs(v) for w in G for v in w) * max(abs(v) for v in d)
        tol = 1e-9 * scale

        def sgn(v: Any, what: str) -> int:
            return 0 if abs(v) <= tol else (1 if v > 0 else -1)
    else:
        sgn = exact_sgn
    vals = [_dot(w, d) if numeric else canon(_dot(w, d)) for w in G]
    z, tight, largest = [], [], []
    for i in range(n):
        a, b = vals[2 * i], vals[2 * i + 1]
        zi = a if sgn(a - b, "a comparison") >= 0 else b
        if sgn(zi, "a normal force's multiplier") <= 0:
            zi = 0.0 if numeric else sp.Integer(0)
        else:
            largest.append(i)
        z.append(zi)
        for j in (2 * i, 2 * i + 1):
            if sgn(vals[j] - zi, "a tight edge") == 0:
                tight.append(j)
    zero = 0.0 if numeric else sp.Integer(0)
    one = 1.0 if numeric else sp.Integer(1)
    need = 2 + len(largest)
    for size in range(min(need, len(tight)), -1, -1):
        for S in itertools.combinations(tight, size):
            # unknowns (t, a_S); rows: force and moment balance, then N_i - t = 0
            M = [[zero, *(G[j][r] for j in S)] for r in range(3)]
            M += [[-one, *(one if j // 2 == i else zero for j in S)] for i in largest]
            x = _solve(M, [*rhs, *([zero] * len(largest))], numeric)
            if x is None:
                continue
            t, a = x[0], dict(zip(S, x[1:]))
            if any(sgn(v, "an edge weight") < 0 for v in a.values()):
                continue
            N = [sum((a[j] for j in (2 * i, 2 * i + 1) if j in a), zero) for i in range(n)]
            if any(sgn(N[i] - t, "a normal force against the largest") > 0 for i in range(n)):
                continue
            if sgn(t - value, "the largest normal force against v(θ)") != 0:
                continue
            return {"t": t, "weights": a, "tight": tight, "largest": largest}
    return None


def optimal_max_normal(
    g: NContactGrasp, Q: Any, ks: list[int], rhs: list[Any], val: Any, numeric: bool
) -> dict[str, Any]:
    """The result dict of ``forces()`` for ``max-normal`` (see NContactGrasp.forces)."""
    labels = [f"P{i + 1}{'+' if s > 0 else '-'}" for i, s, _ in g.edges()]
    edges = [(ci, s, tuple(float(v) for v in dj) if numeric else dj) for ci, s, dj in g.edges()]
    G = [tuple(w) for w in g.wrenches()]
    zero = 0.0 if numeric else sp.Integer(0)
    for k in ks:
        cand = Q.candidates[Q.vertex_index[k]]
        for d in _direction(G, cand, numeric):
            r = max_normal_forces(g, d, rhs, val, numeric)
            if r is None:
                continue
            weights = {
                labels[j]: (max(float(v), 0.0) if numeric else v)
                for j, v in sorted(r["weights"].items())
            }
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
                "vertex": cand.q,
                "basis": list(weights),
                "weights": weights,
                "forces": forces,
                "tight": [labels[j] for j in r["tight"]],
                "largest": [i + 1 for i in r["largest"]],
            }
    raise NContactError(
        "no set of tight edges of the optimal vertex gives nonnegative "
        "weights (a degenerate case): please report the grasp"
    )
