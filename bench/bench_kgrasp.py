"""Vectorised k_grasp(θ) on 10^6 angles (Fig. 6 grasp), on one core.

(b) ``Grasp.preset("fig6").k_grasp(theta)`` for a numpy array of 10^6 θ values,
    best of 5.  Target: < 50 ms.  Baseline measured in the same run: a naive numpy
    version that builds all four k_n into a (4, N) array, then ``.max(axis=0)`` and
    ``np.maximum(..., 0)`` (repetitions of the two are interleaved).  For context,
    the per-element time of a pure-Python loop (``math.sin``/``math.cos``) and of
    scalar ``k_grasp(float)`` calls on 10^4 values.

Run:  PYTHONPATH=src python bench/bench_kgrasp.py [--quick]
"""

from __future__ import annotations

import os

# one core: set before numpy is imported
for _var in (
    "OMP_NUM_THREADS",
    "OPENBLAS_NUM_THREADS",
    "MKL_NUM_THREADS",
    "NUMEXPR_NUM_THREADS",
    "VECLIB_MAXIMUM_THREADS",
    "BLIS_NUM_THREADS",
):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import graspcompass as gc  # noqa: E402

TARGET_S = 0.050
N = 10**6
N_LOOP = 10**4


def best_of(fn, reps: int) -> float:
    best = math.inf
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def best_of_interleaved(fns, reps: int) -> list[float]:
    """Best time of each function, repetitions interleaved (a, b, a, b, ...)."""
    best = [math.inf] * len(fns)
    for _ in range(reps):
        for i, fn in enumerate(fns):
            t0 = time.perf_counter()
            fn()
            best[i] = min(best[i], time.perf_counter() - t0)
    return best


def naive_k_grasp(S: np.ndarray, C: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """All four k_n = S_n sin θ − C_n cos θ in a (4, N) array, then the max and 0."""
    k = S[:, None] * np.sin(theta)[None, :] - C[:, None] * np.cos(theta)[None, :]
    return np.maximum(k.max(axis=0), 0.0)


def python_loop(S: list[float], C: list[float], theta: list[float]) -> list[float]:
    out = []
    for t in theta:
        s, c = math.sin(t), math.cos(t)
        best = 0.0
        for Sn, Cn in zip(S, C):
            k = Sn * s - Cn * c
            if k > best:
                best = k
        out.append(best)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repetitions")
    args = ap.parse_args()
    reps = 2 if args.quick else 5

    g = gc.Grasp.preset("fig6")
    theta = np.linspace(0.0, 2 * np.pi, N, endpoint=False)
    t0 = time.perf_counter()
    first = g.k_grasp(theta)  # first call also turns the exact S_n, C_n into floats
    t_first = time.perf_counter() - t0
    S = np.array([float(v) for v in g.S])
    C = np.array([float(v) for v in g.C])

    naive_k_grasp(S, C, theta)  # warm-up, like the first call above
    t_ours, t_naive = best_of_interleaved(
        [lambda: g.k_grasp(theta), lambda: naive_k_grasp(S, C, theta)], reps
    )
    diff = float(np.max(np.abs(first - naive_k_grasp(S, C, theta))))

    th_loop = theta[:: N // N_LOOP].tolist()
    S_l, C_l = S.tolist(), C.tolist()
    t_loop = best_of(lambda: python_loop(S_l, C_l, th_loop), max(1, reps // 2))
    t_scalar = best_of(lambda: [g.k_grasp(t) for t in th_loop], 1)
    loop_vals = np.array(python_loop(S_l, C_l, th_loop))
    loop_diff = float(np.max(np.abs(loop_vals - first[:: N // N_LOOP])))

    print(
        f"python {sys.version.split()[0]}, numpy {np.__version__}, "
        f"OMP/OPENBLAS threads = {os.environ['OMP_NUM_THREADS']}; best of {reps}"
    )
    print(f"\n{'case':<42} {'total':>11} {'per element':>12}")
    print("-" * 68)
    print(
        f"{'k_grasp(theta), N = 10^6 (graspcompass)':<42} {t_ours * 1e3:8.2f} ms "
        f"{t_ours / N * 1e9:9.2f} ns"
    )
    print(
        f"{'naive numpy (4, N) + max + maximum':<42} {t_naive * 1e3:8.2f} ms "
        f"{t_naive / N * 1e9:9.2f} ns"
    )
    print(f"{'first call (includes exact -> float)':<42} {t_first * 1e3:8.2f} ms")
    print(
        f"{'pure-Python loop, N = 10^4 (context)':<42} {t_loop * 1e3:8.2f} ms "
        f"{t_loop / N_LOOP * 1e9:9.0f} ns"
    )
    print(
        f"{'scalar k_grasp(float) calls, N = 10^4':<42} {t_scalar * 1e3:8.2f} ms "
        f"{t_scalar / N_LOOP * 1e9:9.0f} ns"
    )
    print(f"\nspeed-up over the naive numpy baseline: {t_naive / t_ours:.2f}x")
    print(
        f"speed-up per element over the pure-Python loop: {(t_loop / N_LOOP) / (t_ours / N):.0f}x"
    )
    print(f"max |difference| vs naive: {diff:.2e}; vs Python loop: {loop_diff:.2e}")
    ok = t_ours < TARGET_S
    print(
        f"target (< {TARGET_S * 1e3:.0f} ms for 10^6 θ): "
        f"{'target met' if ok else 'target NOT met'} ({t_ours * 1e3:.2f} ms)"
    )


if __name__ == "__main__":
    main()
