"""The fast numeric path (issue 13 §5): worst-case sizings per second and k_grasp on 10^6 θ.

(a) ``graspcompass.batch.worst_squeeze`` on N seeded random float64 grasps (parallel and
    tilted jaws inside condition (1), the generator of bench_sizing.py), condition (1)
    checked, best of 5: sizings per second on one core.  Target: >= 10^7 /s, in wall
    time or in the process's CPU time (one thread: its time on one core; on a shared
    machine the wall time also counts the other jobs).  Baselines
    in the same run: ``graspcompass.sizing.worst_squeeze_many`` (the vectorised path
    before §5, no checks) and a Python loop over ``Grasp`` objects
    (``size_gripper(Grasp(...), m).worst_squeeze`` on 100 grasps).  Agreement: batch
    against worst_squeeze_many (1e-12) and against the loop (1e-12).
(b) ``Grasp.preset("fig6").k_grasp(theta)`` on 10^6 θ in [0, 2π), best of 5, the table of
    the envelope warm (``_envelope.EnvelopeTable``: a cubic in θ − j h on the exact grid
    j 2^-12, 14 passes per block); the first call (the table built) separately.  Target:
    <= 10 ms.
    Baseline in the same run, interleaved: the array path before §5 (sin, cos and four
    fused multiply-subtract-max passes, ``_envelope.direct_k_grasp``).  Agreement: the
    largest difference in units of ε max_n |V_n|.  Wall and CPU time are printed, as in (a).

Run:  PYTHONPATH=src python bench/bench_batch.py [--quick] [-n 1000000]
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

from graspcompass import Grasp, batch  # noqa: E402
from graspcompass.grasp import _envelope  # noqa: E402
from graspcompass.sizing import size_gripper, worst_squeeze_many  # noqa: E402

TARGET_RATE = 1e7
TARGET_KG_S = 0.010
N_THETA = 10**6
N_LOOP = 100
EPS = 2.0**-52


def random_grasps(n: int, seed: int = 1) -> list[np.ndarray]:
    """Paper-frame parameters inside condition (1): jaws tilted up to 0.8 ξ."""
    rng = np.random.default_rng(seed)
    mu1, mu2 = rng.uniform(0.15, 1.5, n), rng.uniform(0.15, 1.5, n)
    return [
        rng.uniform(0.005, 0.1, n),
        rng.uniform(0.005, 0.1, n),
        rng.uniform(0, 0.05, n),
        math.pi / 2 + rng.uniform(-0.8, 0.8, n) * np.arctan(mu1),
        math.pi / 2 + rng.uniform(-0.8, 0.8, n) * np.arctan(mu2),
        mu1,
        mu2,
    ]


CPU: dict[str, float] = {}  # best CPU time (time.process_time) of each case, by name


def best_of_interleaved(fns, reps: int, names=None) -> list[float]:
    """Best wall time of each function, repetitions interleaved (a, b, a, b, ...).

    The best CPU time of the process (one thread: the time on one core, which a loaded
    machine disturbs much less) goes to ``CPU[name]``.
    """
    best = [math.inf] * len(fns)
    cpu = [math.inf] * len(fns)
    for _ in range(reps):
        for i, fn in enumerate(fns):
            c0, t0 = time.process_time(), time.perf_counter()
            fn()
            best[i] = min(best[i], time.perf_counter() - t0)
            cpu[i] = min(cpu[i], time.process_time() - c0)
    for name, c in zip(names or (), cpu):
        CPU[name] = c
    return best


def verdict(ok: bool) -> str:
    return "target met" if ok else "target NOT met"


def sizings(n: int, reps: int) -> bool:
    p = random_grasps(n)
    kw = dict(g=9.81, accel=2.0)
    new = batch.worst_squeeze(*p, 1.0, **kw)
    old = worst_squeeze_many(*p, 1.0, **kw)
    t_new, t_old = best_of_interleaved(
        [lambda: batch.worst_squeeze(*p, 1.0, **kw), lambda: worst_squeeze_many(*p, 1.0, **kw)],
        reps,
        ["batch", "many"],
    )
    t0 = time.perf_counter()
    loop = [
        float(
            size_gripper(
                Grasp(*(float(v[i]) for v in p[:5]), mu1=float(p[5][i]), mu2=float(p[6][i])),
                1.0,
                g=9.81,
                accel=2.0,
            ).worst_squeeze
        )
        for i in range(N_LOOP)
    ]
    t_loop = (time.perf_counter() - t0) / N_LOOP * n
    d_old = float(np.max(np.abs(new - old) / old))
    d_loop = float(np.max(np.abs(new[:N_LOOP] - loop) / np.array(loop)))
    rate = n / t_new
    print(f"\n(a) worst squeeze over all orientations, N = {n:,} grasps, best of {reps}")
    print(f"{'case':<52} {'time':>10} {'sizings/s':>12} {'ratio':>9}")
    print("-" * 86)
    print(
        f"{'batch.worst_squeeze (condition (1) checked)':<52} {t_new * 1e3:7.1f} ms "
        f"{rate:12.3g} {1:8.1f}x"
    )
    print(
        f"{'sizing.worst_squeeze_many (before §5, unchecked)':<52} {t_old * 1e3:7.1f} ms "
        f"{n / t_old:12.3g} {t_new / t_old:8.2f}x"
    )
    print(
        f"{f'loop over Grasp + size_gripper ({N_LOOP}, scaled)':<52} {t_loop:7.1f} s  "
        f"{n / t_loop:12.3g} {t_new / t_loop:8.1e}x"
    )
    print(
        f"speed-up: {t_old / t_new:.1f}x over worst_squeeze_many, {t_loop / t_new:.3g}x over "
        f"the loop; max relative difference {d_old:.1e} and {d_loop:.1e}"
    )
    cpu_rate = n / CPU["batch"]
    print(
        f"CPU time on one core: batch {CPU['batch'] * 1e3:.1f} ms = {cpu_rate:.3g} sizings/s, "
        f"worst_squeeze_many {CPU['many'] * 1e3:.1f} ms "
        f"(ratio {CPU['many'] / CPU['batch']:.1f}x)"
    )
    ok = max(rate, cpu_rate) >= TARGET_RATE and d_old < 1e-12 and d_loop < 1e-12
    print(
        f"target (>= {TARGET_RATE:.0e} sizings/s on one core, wall or CPU time): {verdict(ok)} "
        f"(wall {rate:.3g} /s, CPU {cpu_rate:.3g} /s)"
    )
    return ok


def k_grasp_many(reps: int) -> bool:
    theta = np.linspace(0.0, 2 * np.pi, N_THETA, endpoint=False)
    t0 = time.perf_counter()
    g = Grasp.preset("fig6")
    S, C = g._floats()
    t_floats = time.perf_counter() - t0
    t0 = time.perf_counter()
    first = g.k_grasp(theta)  # builds the table of the envelope
    t_first = time.perf_counter() - t0
    old = _envelope.direct_k_grasp(S, C, theta)
    t_new, t_old = best_of_interleaved(
        [lambda: g.k_grasp(theta), lambda: _envelope.direct_k_grasp(S, C, theta)],
        reps,
        ["table", "direct"],
    )
    vmax = float(np.hypot(S, C).max())
    diff = float(np.max(np.abs(first - old))) / (EPS * vmax)
    print(f"\n(b) Grasp.preset('fig6').k_grasp(theta), 10^6 θ in [0, 2π), best of {reps}")
    print(f"{'case':<52} {'time':>10} {'per θ':>10}")
    print("-" * 76)
    print(
        f"{'table of the envelope (warm)':<52} {t_new * 1e3:7.2f} ms "
        f"{t_new / N_THETA * 1e9:7.2f} ns"
    )
    print(
        f"{'the array path before §5 (sin, cos, 4 passes)':<52} {t_old * 1e3:7.2f} ms "
        f"{t_old / N_THETA * 1e9:7.2f} ns"
    )
    print(
        f"{f'first call: table built (+ {t_floats * 1e3:.1f} ms S_n, C_n)':<52} "
        f"{t_first * 1e3:7.2f} ms"
    )
    print(
        f"speed-up: {t_old / t_new:.1f}x (first call {t_old / t_first:.1f}x); "
        f"max |difference| = {diff:.2f} ε max|V_n|; "
        f"{g.__dict__['_ktable'].broken_bins} bins hold a break point"
    )
    print(
        f"CPU time on one core: table {CPU['table'] * 1e3:.2f} ms, before §5 "
        f"{CPU['direct'] * 1e3:.2f} ms (ratio {CPU['direct'] / CPU['table']:.1f}x)"
    )
    ok = min(t_new, CPU["table"]) <= TARGET_KG_S and diff <= 4
    print(
        f"target (<= {TARGET_KG_S * 1e3:.0f} ms for 10^6 θ, wall or CPU time): {verdict(ok)} "
        f"(wall {t_new * 1e3:.2f} ms, CPU {CPU['table'] * 1e3:.2f} ms)"
    )
    return ok


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repetitions")
    ap.add_argument("-n", type=int, default=10**6, help="grasps for (a)")
    args = ap.parse_args()
    reps = 2 if args.quick else 5
    print(
        f"python {sys.version.split()[0]}, numpy {np.__version__}, "
        f"OMP/OPENBLAS threads = {os.environ['OMP_NUM_THREADS']}, load average "
        f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores (others' jobs slow both columns)"
    )
    a = sizings(args.n, reps)
    b = k_grasp_many(reps)
    print(f"\nall targets: {verdict(a and b)}")


if __name__ == "__main__":
    main()
