"""Closed-form k_grasp(θ) against a linear program per θ (scipy ``linprog``).

(c) For N = 200 values of θ (Fig. 6 grasp) solve, with scipy's HiGHS,

        minimise   k = F · F_N / |F_N|²        over F = (N1, F1, N2, F2)
        subject to L F = M(θ)                   (force/moment balance, eqs. (4)-(5))
                   |F_i| <= μ_i N_i, i = 1, 2   (friction cones, as 4 inequalities)
                   k >= 0

    and compare with the closed form ``k_grasp`` (eq. (25)) on the same θ values:
    both the vectorised call on the whole array and scalar calls one θ at a time.
    Printed: times, ratios and the largest |k_LP − k_closed|.
    Targets (this script's own): agreement within 1e-6, and the scalar closed form
    >= 100x faster per θ than one linprog.

Run:  PYTHONPATH=src python bench/bench_linprog.py [--quick]
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np
import scipy
from scipy.optimize import linprog

import graspcompass as gc

TARGET_DIFF = 1e-6
TARGET_RATIO = 100.0


def lp_data(g: gc.Grasp) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Objective c, A_ub, b_ub and the equality matrix L (floats) of the grasp."""
    L = np.array(g.grasp_matrix().evalf(), dtype=float)  # eq. (5), 3 x 4
    FN = np.array(g.F_N().evalf(), dtype=float).ravel()  # eq. (15), null vector of L
    c = FN / FN.dot(FN)
    m1, m2 = float(g.mu1), float(g.mu2)
    A_ub = np.array(
        [
            [-m1, 1.0, 0.0, 0.0],  #  F1 - μ1 N1 <= 0
            [-m1, -1.0, 0.0, 0.0],  # -F1 - μ1 N1 <= 0
            [0.0, 0.0, -m2, 1.0],  #  F2 - μ2 N2 <= 0
            [0.0, 0.0, -m2, -1.0],  # -F2 - μ2 N2 <= 0
            -c,  #  k >= 0
        ]
    )
    return c, A_ub, np.zeros(len(A_ub)), L


def k_linprog(g: gc.Grasp, theta: np.ndarray) -> np.ndarray:
    c, A_ub, b_ub, L = lp_data(g)
    out = np.empty(len(theta))
    for i, t in enumerate(theta):
        res = linprog(
            c,
            A_ub=A_ub,
            b_ub=b_ub,
            A_eq=L,
            b_eq=[-np.sin(t), np.cos(t), 0.0],
            bounds=[(None, None)] * 4,
            method="highs",
        )
        if res.status != 0:
            raise RuntimeError(f"linprog failed at θ = {t}: {res.message}")
        out[i] = res.fun
    return out


def best_of(fn, reps: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repetitions")
    ap.add_argument("-n", type=int, default=200, help="number of θ values (default 200)")
    args = ap.parse_args()
    reps = 1 if args.quick else 3

    g = gc.Grasp.preset("fig6")
    theta = np.linspace(0.0, 2 * np.pi, args.n, endpoint=False)
    g.k_grasp(theta)  # warm-up: exact S_n, C_n -> floats once
    k_linprog(g, theta[:5])  # warm-up of scipy

    t_lp, k_lp = best_of(lambda: k_linprog(g, theta), reps)
    t_vec, k_vec = best_of(lambda: g.k_grasp(theta), max(reps, 5))
    t_sca, k_sca = best_of(lambda: np.array([g.k_grasp(float(t)) for t in theta]), reps)
    diff = float(np.max(np.abs(k_lp - k_vec)))
    diff_sca = float(np.max(np.abs(np.asarray(k_sca) - k_vec)))
    n = args.n

    print(
        f"python {sys.version.split()[0]}, numpy {np.__version__}, scipy {scipy.__version__}; "
        f"N = {n} θ values, best of {reps}"
    )
    print(f"\n{'case':<40} {'total':>11} {'per θ':>11}")
    print("-" * 64)
    print(
        f"{'scipy linprog (HiGHS), one LP per θ':<40} {t_lp * 1e3:8.2f} ms {t_lp / n * 1e6:8.1f} µs"
    )
    print(
        f"{'closed form k_grasp, scalar calls':<40} {t_sca * 1e3:8.2f} ms {t_sca / n * 1e6:8.1f} µs"
    )
    print(
        f"{'closed form k_grasp, one array call':<40} {t_vec * 1e3:8.3f} ms "
        f"{t_vec / n * 1e6:8.3f} µs"
    )
    ratio_sca, ratio_vec = t_lp / t_sca, t_lp / t_vec
    print(
        f"\nratio linprog / closed form: {ratio_sca:.0f}x (scalar calls), "
        f"{ratio_vec:.0f}x (array call)"
    )
    print(
        f"max |k_linprog − k_closed| = {diff:.2e} (scalar vs array: {diff_sca:.1e}); "
        f"max k = {k_vec.max():.6f}"
    )
    ok = diff <= TARGET_DIFF and ratio_sca >= TARGET_RATIO
    print(
        f"targets (|Δk| <= {TARGET_DIFF:g}, scalar closed form >= {TARGET_RATIO:g}x faster): "
        f"{'target met' if ok else 'target NOT met'}"
    )


if __name__ == "__main__":
    main()
