"""Independent numerical cross-check: the closed form against a linear program.

For a grasp and a direction θ, the least internal force is also the optimum of
a linear program in the contact forces F = (N1, F1, N2, F2): L F = M (eq. (2)),
the friction inequalities (8)-(11) (closed), and k ≥ 0, minimising
k = F·F_N / |F_N|² (F = F_T + k F_N with F_T ⊥ F_N, eqs. (14)-(16)).
scipy's ``linprog`` (HiGHS) solves it without knowing any of the paper's
closed forms; L is built here from first principles, not from the model.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..grasp import Grasp
from ..progress import Progress

__all__ = ["CrossCheck", "k_linprog", "random_grasps", "run_crosscheck"]


def _require_scipy():
    try:
        from scipy.optimize import linprog
    except ImportError as exc:  # pragma: no cover - scipy is in the test extra
        raise ValueError("the cross-check needs scipy: pip install 'graspcompass[test]'") from exc
    return linprog


def k_linprog(
    x1: float, x2: float, y: float, phi1: float, phi2: float, mu1: float, mu2: float, theta: float
) -> float:
    """Least k ≥ 0 satisfying L F = M and (8)-(11), by linear programming (F_e = 1)."""
    linprog = _require_scipy()
    s1, c1, s2, c2 = np.sin(phi1), np.cos(phi1), np.sin(phi2), np.cos(phi2)
    # columns: unit normal / tangential forces at P1, P2 and their moments about O
    forces = [
        ((x1, y), (-s1, -c1)),
        ((x1, y), (-c1, s1)),
        ((-x2, y), (s2, -c2)),
        ((-x2, y), (c2, s2)),
    ]
    L = np.array(
        [
            [fx for _, (fx, _) in forces],
            [fy for _, (_, fy) in forces],
            [px * fy - py * fx for (px, py), (fx, fy) in forces],
        ]
    )
    M = np.array([-np.sin(theta), np.cos(theta), 0.0])
    fn = np.array([s1, c1, s2, c2]) / (x1 + x2)
    obj = fn / fn.dot(fn)  # k = F·F_N / |F_N|²
    A_ub = -np.array(
        [[mu1, -1, 0, 0], [0, 0, mu2, -1], [mu1, 1, 0, 0], [0, 0, mu2, 1], obj]
    )  # μN ∓ F ≥ 0 and k ≥ 0, as -(...) ≤ 0
    res = linprog(
        obj,
        A_ub=A_ub,
        b_ub=np.zeros(5),
        A_eq=L,
        b_eq=M,
        bounds=[(None, None)] * 4,
        method="highs",
        options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10},
    )
    if res.status != 0:
        raise ValueError(f"linprog failed: {res.message}")
    return float(res.fun)


def random_grasps(n: int, seed: int = 0) -> list[Grasp]:
    """``n`` random valid grasps (floats) satisfying condition (1) with a margin."""
    rng = np.random.default_rng(seed)
    out: list[Grasp] = []
    while len(out) < n:
        x1, x2 = rng.uniform(0.2, 3.0, 2).tolist()
        y = float(rng.uniform(0.0, 3.0))
        phi = rng.uniform(0.1, np.pi, 2)
        xi = rng.uniform(0.05, np.pi / 2 - 0.05, 2)
        try:
            out.append(
                Grasp(
                    x1,
                    x2,
                    y,
                    float(phi[0]),
                    float(phi[1]),
                    mu1=float(np.tan(xi[0])),
                    mu2=float(np.tan(xi[1])),
                )
            )
        except ValueError:
            continue
    return out


@dataclass(frozen=True)
class CrossCheck:
    """Largest difference between the closed form and linprog, over grasps × θ."""

    grasps: int
    thetas: int
    max_abs_diff: float
    worst: tuple[Grasp, float] | None


def run_crosscheck(
    grasps: Sequence[Grasp] | int = 20, thetas: int = 36, seed: int = 0, quiet: bool = False
) -> CrossCheck:
    """Compare ``Grasp.k_grasp`` with :func:`k_linprog` on grasps × a θ grid."""
    gs = random_grasps(grasps, seed) if isinstance(grasps, int) else list(grasps)
    grid = np.linspace(0.0, 2 * np.pi, thetas, endpoint=False)
    worst, worst_at = 0.0, None
    with Progress(len(gs), "crosscheck", quiet=quiet) as bar:
        for g in gs:
            x1, x2, y, phi1, phi2, mu1, mu2 = (
                float(g.params[k]) for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")
            )
            closed = np.asarray(g.k_grasp(grid))
            for t, kc in zip(grid, closed):
                d = abs(k_linprog(x1, x2, y, phi1, phi2, mu1, mu2, float(t)) - kc)
                if d > worst:
                    worst, worst_at = d, (g, float(t))
            bar.update()
    return CrossCheck(len(gs), thetas, worst, worst_at)
