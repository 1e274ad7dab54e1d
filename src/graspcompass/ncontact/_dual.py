"""Vertices and recession directions of the dual polyhedron ``{u : a_r·u <= b_r}``.

The LP of a linear effort in standard form, ``min c'·x, A x = b', x >= 0`` (the
edge weights, plus one slack per sign constraint), has the dual
``max b'·u, A^T u <= c'``.  Its vertices are the **dual-feasible bases**: d
independent tight constraints whose solution satisfies all the others.  Exactly:

* ``D(S)``: the determinant of the d constraint normals of a subset S, in
  canonical form, cached (each is shared by many bases and rays);
* the slack of constraint k at the basic solution of B is ``E(B ∪ k) / D(B)`` up
  to the parity of the row order, with ``E`` the (d+1) × (d+1) determinant with
  the right-hand sides, expanded along that column into the cached ``D``;
* every sign is :func:`~graspcompass.ncontact._signs.sign` (``decide_sign``); the
  float values only choose the order in which the constraints are tried (the most
  violated first), never a result.

The float path does the same with numpy and a relative tolerance.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..geometry.exact import approx, canon
from ._signs import det, exact_sgn, sign
from .errors import DegenerateGraspError

__all__ = [
    "Dets",
    "DualVertex",
    "exact_rays",
    "exact_vertices",
    "float_rays",
    "float_vertices",
    "screened_vertices",
    "verify_basis",
]

#: Relative tolerance of the float path (feasibility, rank, duplicates).
TOL = 1e-9


@dataclass(frozen=True)
class DualVertex:
    """A basic feasible solution of the dual and its basis (constraint indices).

    Attributes
    ----------
    u : tuple
        Float path: the solution.  Exact path: the Cramer numerators of its first
        two coordinates (the solution is ``u / W``), polynomials in the kernel's
        generators: no quotient is ever reduced on the way.
    basis : tuple of int
        The d tight constraints of the basis.
    W : number
        The common denominator, the basis determinant ``D(B)`` (1 on the float path).
    tight : frozenset
        Every constraint tight at the solution (degenerate vertices have more than d).
    cone : tuple or None
        The cone of load directions e on which this basis is also primal feasible
        (optimal), ``(start, end)``; None when it has no interior (exact path only).
    """

    u: tuple
    basis: tuple[int, ...]
    W: Any = 1
    tight: frozenset = frozenset()
    cone: Any = None


class Dets:
    """Cached exact determinants of subsets of the constraint normals."""

    def __init__(self, rows: list[list[sp.Expr]], rhs: list[sp.Expr]) -> None:
        self.rows, self.rhs = rows, rhs
        self.d = len(rows[0])
        self._D: dict[tuple, sp.Expr] = {}
        self._sD: dict[tuple, int] = {}
        self._sE: dict[tuple, int] = {}

    def D(self, s: tuple) -> sp.Expr:
        v = self._D.get(s)
        if v is None:
            v = self._D[s] = canon(det([list(self.rows[i]) for i in s]))
        return v

    def sD(self, s: tuple) -> int:
        v = self._sD.get(s)
        if v is None:
            v = self._sD[s] = sign(self.D(s), f"the determinant of constraints {s}")
        return v

    def sE(self, s: tuple) -> int:
        """Sign of det [rows | rhs] of the (d+1) constraints s (sorted), by its last column."""
        v = self._sE.get(s)
        if v is None:
            d = self.d
            total = sp.Integer(0)
            for t, r in enumerate(s):
                if self.rhs[r] != 0:
                    total += (-1) ** (t + d) * self.rhs[r] * self.D(s[:t] + s[t + 1 :])
            v = self._sE[s] = sign(canon(total), f"a slack of constraints {s}")
        return v

    def slack_sign(self, basis: tuple, k: int) -> int:
        s = tuple(sorted((*basis, k)))
        parity = sum(1 for b in basis if b > k) % 2
        return (-1) ** parity * self.sE(s) * self.sD(basis)

    def numerators(self, basis: tuple, coords: int = 2) -> tuple:
        """Cramer numerators of the first ``coords`` coordinates (the solution is them / D)."""
        rows = [list(self.rows[i]) for i in basis]
        out = []
        for t in range(coords):
            m = [[*r[:t], self.rhs[i], *r[t + 1 :]] for r, i in zip(rows, basis)]
            out.append(canon(det(m)))
        return tuple(out)

    def primal_cone(self, basis: tuple) -> Any:
        """The directions e where the basis is primal feasible: ``x_B(e) >= 0``.

        ``x_B = M^{-1} (-e, 0, ...)`` with M the basis' constraint normals as columns,
        so ``x_t >= 0`` iff ``m_t · e <= 0`` with ``m_t = sign(D) (adj M)[t, 0:2]``
        (cofactors: (d-1) × (d-1) minors, polynomials).
        """
        from ._hull import feasible_cone

        sD = self.sD(basis)
        ms = []
        for t in range(self.d):
            rest = [self.rows[r] for j, r in enumerate(basis) if j != t]
            m = []
            for k in (0, 1):
                minor = [[v for c, v in enumerate(row) if c != k] for row in rest]
                m.append(canon(sD * (-1) ** (t + k) * det(minor)))
            if any(exact_sgn(v, "a cofactor") != 0 for v in m):
                ms.append(tuple(m))
        return feasible_cone(ms, exact_sgn)


def _float_rows(rows, rhs) -> tuple[np.ndarray, np.ndarray]:
    A = np.array([[float(approx(v, 20)) for v in r] for r in rows], dtype=float)
    b = np.array([float(approx(v, 20)) for v in rhs], dtype=float)
    return A, b


def _float_solutions(A: np.ndarray, b: np.ndarray):
    """All d-subsets, their float solutions and slacks (nan for singular ones)."""
    R, d = A.shape
    combos = np.array(list(itertools.combinations(range(R), d)), dtype=int).reshape(-1, d)
    M = A[combos]
    dets = np.linalg.det(M)
    scale = np.prod(np.linalg.norm(M, axis=2), axis=1)
    ok = np.abs(dets) > 1e-12 * np.maximum(scale, 1e-300)
    U = np.full((len(combos), d), np.nan)
    if ok.any():
        U[ok] = np.linalg.solve(M[ok], b[combos[ok]][..., None])[..., 0]
    slack = b[None, :] - U @ A.T
    tol = TOL * (
        np.linalg.norm(A, axis=1)[None, :] * np.linalg.norm(U, axis=1)[:, None]
        + np.abs(b)[None, :]
        + 1e-300
    )
    return combos, ok, U, slack, tol


def exact_vertices(
    rows: list[list[sp.Expr]], rhs: list[sp.Expr], dets: Dets | None = None
) -> list[DualVertex]:
    """Every dual-feasible basis of ``{u : rows·u <= rhs}``, exactly, with its primal cone.

    Raises
    ------
    DegenerateGraspError
        When the normals have rank < d (the polyhedron has no vertex).
    UndecidedSignError
        When a sign cannot be decided exactly.
    """
    dets = dets or Dets(rows, rhs)
    A, b = _float_rows(rows, rhs)
    combos, ok, _U, slack, tol = _float_solutions(A, b)
    tol_scale = tol.max(axis=1) / TOL
    R = len(rows)
    out: list[DualVertex] = []
    rank_full = False
    for ci, row in enumerate(combos):
        basis = tuple(int(v) for v in row)
        if dets.sD(basis) == 0:
            continue
        rank_full = True
        others = [k for k in range(R) if k not in basis]
        if ok[ci]:  # most violated first: an infeasible basis is refuted by one exact sign,
            # and among the clearly violated ones those whose determinant is already known
            def key(k: int, ci: int = ci, basis: tuple = basis) -> tuple:
                known = tuple(sorted((*basis, k))) in dets._sE
                return (not (known and slack[ci, k] < -1e-6 * tol_scale[ci]), slack[ci, k])

            others.sort(key=key)
        tight = set(basis)
        for k in others:
            s = dets.slack_sign(basis, k)
            if s < 0:
                break
            if s == 0:
                tight.add(k)
        else:
            s0 = dets.sD(basis)  # W = |D| > 0: homogeneous coordinates with a positive weight
            nums = tuple(canon(s0 * v) for v in dets.numerators(basis))
            out.append(
                DualVertex(
                    nums,
                    basis,
                    canon(s0 * dets.D(basis)),
                    frozenset(tight),
                    dets.primal_cone(basis),
                )
            )
    if not rank_full:
        raise DegenerateGraspError(
            "the edge wrenches do not span the three dimensions of "
            "planar wrenches (all lines of action concurrent or "
            "parallel): the grasp cannot resist some loads at all"
        )
    return out


def _float_cone_has_interior(A: np.ndarray, basis: tuple) -> bool:
    """Float screen: is the basis primal feasible on an open cone of directions?"""
    M = A[list(basis)].T
    try:
        m = np.linalg.inv(M)[:, :2]
    except np.linalg.LinAlgError:
        return False
    m = m[np.linalg.norm(m, axis=1) > 1e-12 * np.abs(m).max()]
    # sample the circle finely: an open cone of width > 1e-6 rad contains a sample
    t = np.linspace(0, 2 * np.pi, 20001)
    e = np.stack([np.cos(t), np.sin(t)])
    return bool(np.any(np.all(m @ e < -1e-12, axis=0)))


def screened_vertices(
    rows: list[list[sp.Expr]], rhs: list[sp.Expr], dets: Dets
) -> tuple[list[DualVertex], list[tuple]]:
    """The bases that float arithmetic finds dual feasible and optimal on an open cone.

    Returns ``(active, passive)``: the active ones verified exactly (dual
    feasibility by exact slack signs, the primal cone exactly); the passive ones
    (float-feasible, not active) as bare bases, for :func:`verify_basis` later.
    The float screen decides nothing by itself: the caller certifies that the
    exact cones of the active bases cover the feasible directions
    (:func:`graspcompass.ncontact.polygon.covers`), else falls back to
    :func:`exact_vertices`.
    """
    A, b = _float_rows(rows, rhs)
    combos, ok, _U, slack, tol = _float_solutions(A, b)
    feas = ok & np.all(slack >= -1e-6 * (tol / TOL), axis=1)
    active, passive = [], []
    for ci in np.flatnonzero(feas):
        basis = tuple(int(v) for v in combos[ci])
        if _float_cone_has_interior(A, basis):
            v = verify_basis(dets, basis)
            if v is None or v.cone is None:
                return [], []  # the screen was wrong: the caller enumerates exactly
            active.append(v)
        else:
            passive.append(basis)
    return active, passive


def verify_basis(dets: Dets, basis: tuple) -> DualVertex | None:
    """The exact dual vertex of a basis, or None when it is singular or infeasible."""
    if dets.sD(basis) == 0:
        return None
    tight = set(basis)
    for k in range(len(dets.rows)):
        if k in basis:
            continue
        s = dets.slack_sign(basis, k)
        if s < 0:
            return None
        if s == 0:
            tight.add(k)
    s0 = dets.sD(basis)
    nums = tuple(canon(s0 * v) for v in dets.numerators(basis))
    return DualVertex(
        nums, basis, canon(s0 * dets.D(basis)), frozenset(tight), dets.primal_cone(basis)
    )


def exact_rays(rows: list[list[sp.Expr]], dets: Dets | None = None) -> list[tuple]:
    """Extreme rays ``r`` of the cone ``{r : rows·r <= 0}`` (pointed; exact).

    Each is a generalised cross product of d - 1 independent normals; its dot
    product with another normal is a d × d determinant of the same cache.
    """
    d = len(rows[0])
    dets = dets or Dets(rows, [sp.Integer(0)] * len(rows))
    R = len(rows)
    found: list[tuple] = []
    for S in itertools.combinations(range(R), d - 1):
        r = []
        for t in range(d):
            m = [list(rows[i][:t]) + list(rows[i][t + 1 :]) for i in S]
            r.append(canon((-1) ** t * det(m)))
        if all(sign(v, "a recession direction") == 0 for v in r):
            continue
        signs = []
        for k in range(R):
            if k in S:
                continue
            s = tuple(sorted((*S, k)))
            pos = sum(1 for i in S if i < k)
            signs.append((-1) ** pos * dets.sD(s))
        if all(s == 0 for s in signs):
            raise DegenerateGraspError("the dual polyhedron contains a line (rank < 3)")
        for sg in (1, -1):
            if all(sg * s <= 0 for s in signs):
                found.append(tuple(sg * v for v in r))
    return found


def float_vertices(A: np.ndarray, b: np.ndarray) -> list[DualVertex]:
    """The float path of :func:`exact_vertices` (relative tolerance :data:`TOL`)."""
    combos, ok, U, slack, tol = _float_solutions(A, b)
    if not ok.any():
        raise DegenerateGraspError(
            "the edge wrenches do not span the three dimensions of planar wrenches (rank < 3)"
        )
    feas = ok & np.all(slack >= -tol, axis=1)
    return [
        DualVertex(tuple(U[i].tolist()), tuple(combos[i].tolist())) for i in np.flatnonzero(feas)
    ]


def float_rays(A: np.ndarray) -> list[tuple]:
    """The float path of :func:`exact_rays` (vectorised over the (d-1)-subsets of rows)."""
    R, d = A.shape
    combos = np.array(list(itertools.combinations(range(R), d - 1)), dtype=int)
    if combos.size == 0:
        return []
    sub = A[combos]  # (C, d-1, d)
    if d == 2:
        r = np.stack([sub[:, 0, 1], -sub[:, 0, 0]], axis=1)
    else:
        r = np.stack(
            [(-1) ** t * np.linalg.det(np.delete(sub, t, axis=2)) for t in range(d)], axis=1
        )
    nr = np.linalg.norm(r, axis=1)
    keep = nr > 1e-12 * np.prod(np.linalg.norm(sub, axis=2), axis=1)
    r = r[keep] / nr[keep, None]
    dots = r @ A.T  # (C', R)
    tol = TOL * np.linalg.norm(A, axis=1)
    found = []
    for k in range(len(r)):
        for sg in (1, -1):
            if np.all(sg * dots[k] <= tol):
                found.append(tuple((sg * r[k]).tolist()))
    return found
