"""Sizing grippers: the closed-form worst case against linear programs, per grasp and vectorised.

For N seeded random parallel- and tilted-jaw grasps (paper frame, float64) the
worst squeeze per jaw over all orientations with an acceleration bound is

(a) ``worst_squeeze_many``: the closed form S_f m (g + A) max_n |V_n| / (x1 + x2)
    (eqs. (17), (28)-(39)) vectorised over all grasps in one call;
(b) ``size_gripper`` on each float grasp (the library's scalar path, which also finds
    the worst direction, slipping contact, best orientation and vendor number);
(c) the baseline, measured in the same run: what one would write without the closed
    form — scipy ``linprog`` (HiGHS) on the contact forces, one LP per load direction,
    over a grid of ``--directions`` load directions on the circle |f| = m(g + A), max.
    It is timed on the first ``--lp-grasps`` grasps and scaled per grasp.

It prints sizings per second of each and the ratios, and checks that (a), (b) and
(c) agree (the grid under-estimates the maximum by at most 1 − cos(π/directions)).
Target: (a) ≥ 10^5 sizings/s and ≥ 1000× the LP baseline.

Run:  PYTHONPATH=src python bench/bench_sizing.py [--quick] [-n 100000]
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from scipy.optimize import linprog  # noqa: E402

from graspcompass import Grasp  # noqa: E402
from graspcompass.sizing import size_gripper, worst_squeeze_many  # noqa: E402

G, A, MASS = 9.80665, 2.0, 1.5
TARGET_RATE, TARGET_RATIO = 1e5, 1000.0


def random_grasps(n: int, seed: int = 1) -> dict[str, np.ndarray]:
    """Paper-frame parameters inside condition (1): jaws tilted up to 0.8 ξ."""
    rng = np.random.default_rng(seed)
    mu1, mu2 = rng.uniform(0.15, 1.5, n), rng.uniform(0.15, 1.5, n)
    return dict(
        x1=rng.uniform(0.005, 0.1, n),
        x2=rng.uniform(0.005, 0.1, n),
        y=rng.uniform(0, 0.05, n),
        phi1=math.pi / 2 + rng.uniform(-0.8, 0.8, n) * np.arctan(mu1),
        phi2=math.pi / 2 + rng.uniform(-0.8, 0.8, n) * np.arctan(mu2),
        mu1=mu1,
        mu2=mu2,
    )


def lp_worst(p: dict[str, float], directions: int) -> float:
    """Max over a grid of load directions of the least squeeze per jaw, one LP each."""
    x1, x2, y, f1, f2, m1, m2 = (p[k] for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"))
    p1, p2 = np.array([x1, y]), np.array([-x2, y])
    n1 = np.array([-math.sin(f1), -math.cos(f1)])
    n2 = np.array([math.sin(f2), -math.cos(f2)])
    t1, t2 = np.array([-n1[1], n1[0]]), np.array([-n2[1], n2[0]])
    A_eq = np.array([[1, 0, 1, 0], [0, 1, 0, 1], [-p1[1], p1[0], -p2[1], p2[0]]], float)
    rows = []
    for i, (n, t, mu) in enumerate(((n1, t1, m1), (n2, t2, m2))):
        for sg in (1, -1):
            row = np.zeros(4)
            row[2 * i : 2 * i + 2] = sg * t - mu * n
            rows.append(row)
    A_ub = np.array(rows)
    cost = np.array([-1.0, 0.0, 1.0, 0.0]) / 2  # (f2 − f1)·x̂ / 2
    best = 0.0
    for th in np.linspace(0, 2 * math.pi, directions, endpoint=False):
        f = MASS * (G + A) * np.array([math.sin(th), -math.cos(th)])
        res = linprog(
            cost,
            A_ub=A_ub,
            b_ub=np.zeros(4),
            A_eq=A_eq,
            b_eq=np.array([-f[0], -f[1], 0.0]),
            bounds=[(None, None)] * 4,
            method="highs",
        )
        best = max(best, res.fun)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer grasps and repetitions")
    ap.add_argument("-n", type=int, default=None, help="grasps for (a) (default 10^5)")
    ap.add_argument("--lp-grasps", type=int, default=None, help="grasps for (c) (default 10)")
    ap.add_argument("--directions", type=int, default=72, help="LP grid size (default 72)")
    args = ap.parse_args()
    n = args.n or (20_000 if args.quick else 100_000)
    n_lp = args.lp_grasps or (4 if args.quick else 10)
    n_scalar = 50 if args.quick else 200
    reps = 3 if args.quick else 5
    P = random_grasps(n)

    best_vec = math.inf
    for _ in range(reps):
        t0 = time.perf_counter()
        vec = worst_squeeze_many(
            *(P[k] for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")), MASS, accel=A
        )
        best_vec = min(best_vec, time.perf_counter() - t0)

    grasps = [
        Grasp(
            *(float(P[k][i]) for k in ("x1", "x2", "y", "phi1", "phi2")),
            mu1=float(P["mu1"][i]),
            mu2=float(P["mu2"][i]),
        )
        for i in range(n_scalar)
    ]
    t0 = time.perf_counter()
    scalar = [float(size_gripper(g, MASS, accel=A).worst_squeeze) for g in grasps]
    t_scalar = time.perf_counter() - t0

    t0 = time.perf_counter()
    lps = [lp_worst({k: float(v[i]) for k, v in P.items()}, args.directions) for i in range(n_lp)]
    t_lp = time.perf_counter() - t0

    err_scalar = max(abs(s - v) / v for s, v in zip(scalar, vec[:n_scalar]))
    slack = 1 - math.cos(math.pi / args.directions)
    lp_ok = all(
        v * (1 - slack) * (1 - 1e-7) <= lp <= v * (1 + 1e-7) for lp, v in zip(lps, vec[:n_lp])
    )
    rate_vec, rate_scalar, rate_lp = n / best_vec, n_scalar / t_scalar, n_lp / t_lp
    print(f"{n} random grasps, worst squeeze per jaw over all orientations, |a| <= {A} m/s^2")
    print(
        f"(a) worst_squeeze_many, vectorised float64 : {rate_vec:12,.0f} sizings/s "
        f"({best_vec * 1e3:.1f} ms for {n}, best of {reps})"
    )
    print(
        f"(b) size_gripper per float grasp (full)    : {rate_scalar:12,.0f} sizings/s "
        f"({n_scalar} grasps)"
    )
    print(
        f"(c) baseline: linprog x {args.directions} directions    : {rate_lp:12,.1f} sizings/s "
        f"({n_lp} grasps, {t_lp:.2f} s)"
    )
    print(
        f"ratios: (a)/(c) = {rate_vec / rate_lp:,.0f}x, (b)/(c) = {rate_scalar / rate_lp:,.1f}x,"
        f" (a)/(b) = {rate_vec / rate_scalar:,.0f}x"
    )
    print(
        f"agreement: max rel |(b) - (a)| = {err_scalar:.1e}; LP grid within "
        f"[1 - {slack:.1e}, 1] of (a): {lp_ok}"
    )
    met = (
        rate_vec >= TARGET_RATE
        and rate_vec / rate_lp >= TARGET_RATIO
        and lp_ok
        and err_scalar < 1e-9
    )
    print("target met" if met else "target NOT met")


if __name__ == "__main__":
    main()
