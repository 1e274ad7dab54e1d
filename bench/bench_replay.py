"""Exact replay of the internal force diagram: graspcompass vs sympy.geometry.

(a) Fig. 6 grasp, exact numbers: ``internal_force_diagram(Grasp(**FIG6_EXACT))`` (the
    grasp built and validated from the same sympy values the baseline gets, then the
    whole diagram: V_n, circles, break points, envelope) against the same drawing steps
    with ``sympy.geometry`` (``_baseline_sympy_geometry.replay(**FIG6)``).  Target: >= 50x
    faster.  Reading the preset's text (``Grasp.preset("fig6")``, the parser) is shown
    on its own line: the baseline starts from sympy values, not from text.
(e) The same Fig. 6 replay, each run in a **fresh process** for both sides (the imports
    done first and not timed: the first call pays for every first-time set-up, as a
    user's ``graspcompass steps`` does).  Target: >= 50x faster.  The shipped recipe is
    parsed when ``graspcompass`` is imported (a constant of the package, ~3 ms); the
    imports of both sides are printed beside it, with import + first call.
(d) Fully symbolic grasp: ``internal_force_diagram(Grasp.symbolic("mu"))`` against
    ``replay(**symbolic_params())``, both up to V4 (no circles) and in full (with the
    circles and their intersections; the sympy.geometry run goes to a subprocess
    with a time limit, and a run that does not finish gives a lower bound).
    Target: >= 20x faster.

sympy's cache and graspcompass's own memo are cleared before *every* timed run of
both sides, so no run profits from an earlier one; the median of N runs is shown.

Run:  PYTHONPATH=src python bench/bench_replay.py [--quick] [--timeout SECONDS]
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import os
import queue
import random
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import _baseline_sympy_geometry as baseline
import sympy as sp
from sympy.core.cache import clear_cache

import graspcompass as gc
import graspcompass.geometry.exact as gc_exact
from graspcompass import symbols as gc_symbols
from graspcompass.construction.protocol import run_step
from graspcompass.construction.recipe import diagram_specs

TARGET_EXACT = 50.0
TARGET_SYMBOLIC = 20.0


@dataclass(frozen=True)
class Timing:
    wall: float  # median wall-clock seconds
    cpu: float  # median CPU seconds of this process
    n: int


def clear_all_caches() -> None:
    """Forget everything sympy and graspcompass remember between calls."""
    clear_cache()
    gc_exact.clear_caches()


def median_times(fns: list[Callable[[], Any]], reps: int) -> tuple[list[Timing], list[Any]]:
    """Median wall and CPU time of ``reps`` cold runs of each function.

    The repetitions are interleaved (a, b, a, b, ...) so a change of machine load
    hits both sides alike; caches are cleared before every single run.
    """
    walls: list[list[float]] = [[] for _ in fns]
    cpus: list[list[float]] = [[] for _ in fns]
    outs: list[Any] = [None] * len(fns)
    for _ in range(reps):
        for i, fn in enumerate(fns):
            clear_all_caches()
            w0, c0 = time.perf_counter(), time.process_time()
            outs[i] = fn()
            cpus[i].append(time.process_time() - c0)
            walls[i].append(time.perf_counter() - w0)
    return [
        Timing(statistics.median(w), statistics.median(c), len(w)) for w, c in zip(walls, cpus)
    ], outs


# --------------------------------------------------------------------------- workloads

#: The Fig. 6 grasp as sympy values, made once like the baseline's ``FIG6``.
FIG6_EXACT = dict(
    x1=sp.sqrt(3) / 2,
    x2=sp.sqrt(3) / 2,
    y=sp.Rational(1, 2),
    phi1=sp.pi / 3,
    phi2=sp.pi / 3,
    xi1=sp.pi / 4,
    xi2=sp.pi / 3,
)


def gc_fig6() -> gc.Construction:
    return gc.internal_force_diagram(gc.Grasp(**FIG6_EXACT))


def gc_fig6_from_text() -> gc.Construction:
    return gc.internal_force_diagram(gc.Grasp.preset("fig6"))


def gc_steps(grasp: gc.Grasp, stop_after: str | None = None) -> dict[str, Any]:
    """The recipe's steps run one by one (no envelope), optionally stopping early."""
    env: dict[str, Any] = {}
    for i, spec in enumerate(diagram_specs(grasp)):
        try:
            env[spec.name] = run_step(spec, env, i).obj
        except gc.GeometryError:
            if spec.op != "second_intersection":
                raise
        if spec.name == stop_after:
            break
    return env


def gc_fig6_no_envelope() -> dict[str, Any]:
    return gc_steps(gc.Grasp(**FIG6_EXACT))


def gc_symbolic_full() -> gc.Construction:
    return gc.internal_force_diagram(gc.Grasp.symbolic("mu"))


def gc_symbolic_upto_v4() -> dict[str, Any]:
    return gc_steps(gc.Grasp.symbolic("mu"), stop_after="V4")


def sympy_fig6() -> dict[str, Any]:
    return baseline.replay(**baseline.FIG6)


def sympy_symbolic_upto_v4() -> dict[str, Any]:
    return baseline.replay(**baseline.symbolic_params(), circles=False)


def _sympy_symbolic_full_child(started: Any, results: Any) -> None:
    """Child process: the full symbolic sympy.geometry replay, cold."""
    clear_cache()
    params = baseline.symbolic_params()
    started.set()
    w0, c0 = time.perf_counter(), time.process_time()
    baseline.replay(**params, circles=True)
    results.put((time.perf_counter() - w0, time.process_time() - c0))


_FRESH = r"""
import sys, time
sys.path.insert(0, {bench!r})
side = sys.argv[1]
i0 = time.perf_counter()
import sympy as sp
if side in ("ours", "preset"):
    import graspcompass as gc
    import graspcompass.construction.envelope, graspcompass.construction.recipe
else:
    import sympy.geometry
    import _baseline_sympy_geometry as baseline
imports = time.perf_counter() - i0
FIG6 = dict(x1=sp.sqrt(3) / 2, x2=sp.sqrt(3) / 2, y=sp.Rational(1, 2), phi1=sp.pi / 3,
            phi2=sp.pi / 3, xi1=sp.pi / 4, xi2=sp.pi / 3)
w0, c0 = time.perf_counter(), time.process_time()
if side == "ours":
    gc.internal_force_diagram(gc.Grasp(**FIG6))
elif side == "preset":  # the issue's own call: the preset read from its text
    gc.internal_force_diagram(gc.Grasp.preset("fig6"))
else:
    baseline.replay(**baseline.FIG6)
print(time.perf_counter() - w0, time.process_time() - c0, imports)
"""


def fresh_process(side: str, reps: int) -> tuple[Timing, Timing]:
    """Median wall and CPU time of the Fig. 6 replay, each run in a new interpreter,
    and (as a Timing whose cpu is nan) the median wall time of its imports."""
    import subprocess

    code = _FRESH.format(bench=os.path.dirname(os.path.abspath(__file__)))
    walls, cpus, imports = [], [], []
    for _ in range(reps):
        out = subprocess.run(
            [sys.executable, "-c", code, side],
            capture_output=True,
            text=True,
            check=True,
            timeout=600,
        ).stdout.split()
        walls.append(float(out[0]))
        cpus.append(float(out[1]))
        imports.append(float(out[2]))
    return (
        Timing(statistics.median(walls), statistics.median(cpus), reps),
        Timing(statistics.median(imports), float("nan"), reps),
    )


def _cpu_seconds(pid: int) -> float | None:
    """CPU time (user + system) used so far by process ``pid`` (Linux /proc only)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def sympy_symbolic_full(timeout: float) -> tuple[float, float | None, bool]:
    """(wall s, CPU s, finished): run in a fresh process, stopped after ``timeout`` s.

    When the run is stopped, the CPU time is the child's total so far (it includes
    the child's imports, a second or so), read just before it is terminated.
    """
    ctx = mp.get_context("spawn")
    started, results = ctx.Event(), ctx.Queue()
    proc = ctx.Process(target=_sympy_symbolic_full_child, args=(started, results), daemon=True)
    proc.start()
    if not started.wait(120):
        proc.terminate()
        proc.join()
        raise RuntimeError("the sympy.geometry child process did not start")
    cpu_at_start = _cpu_seconds(proc.pid) or 0.0
    t0 = time.perf_counter()
    try:
        wall, cpu = results.get(timeout=timeout)
        finished = True
    except queue.Empty:
        wall, finished = time.perf_counter() - t0, False
        cpu_now = _cpu_seconds(proc.pid)
        cpu = None if cpu_now is None else cpu_now - cpu_at_start
    if proc.is_alive():
        proc.terminate()
    proc.join()
    return wall, cpu, finished


# --------------------------------------------------------------------------- checks


def same_number(u: sp.Expr, v: sp.Expr) -> bool:
    d = sp.expand(sp.radsimp(sp.expand(u - v)))
    return d == 0 or abs(sp.N(d, 30)) < 1e-25


def check_fig6(ours: gc.Construction, theirs: dict[str, Any]) -> bool:
    return all(
        same_number(ours[f"V{n}"].x, theirs[f"V{n}"].x)
        and same_number(ours[f"V{n}"].y, theirs[f"V{n}"].y)
        for n in (1, 2, 3, 4)
    )


def check_symbolic(ours: dict[str, Any], theirs: dict[str, Any]) -> bool:
    """Compare V1..V4 at a random admissible point (the symbols differ in assumptions)."""
    rng = random.Random(7)
    vals = dict(
        x1=rng.uniform(0.5, 2),
        x2=rng.uniform(0.5, 2),
        y=rng.uniform(0.1, 2),
        phi1=rng.uniform(1.2, 1.9),
        phi2=rng.uniform(1.2, 1.9),
        mu1=rng.uniform(0.2, 0.8),
        mu2=rng.uniform(0.2, 0.8),
    )
    ours_subs = {getattr(gc_symbols, k): v for k, v in vals.items()}
    theirs_subs = {baseline.symbolic_params()[k]: v for k, v in vals.items()}
    for n in (1, 2, 3, 4):
        p, q = ours[f"V{n}"], theirs[f"V{n}"]
        for u, v in ((p.x, q.x), (p.y, q.y)):
            fu, fv = float(u.subs(ours_subs)), float(v.subs(theirs_subs))
            if abs(fu - fv) > 1e-9 * max(1.0, abs(fv)):
                return False
    return True


# --------------------------------------------------------------------------- report


def verdict(ratio: float, target: float, lower_bound: bool = False) -> str:
    if ratio >= target:
        return "target met"
    return "target NOT met (lower bound only)" if lower_bound else "target NOT met"


def row(
    case: str, ours: Timing, theirs: Timing | str, ratio: str, cpu_ratio: str, note: str
) -> None:
    theirs_s = theirs if isinstance(theirs, str) else f"{theirs.wall * 1e3:10.1f}"
    print(f"{case:<32} {ours.wall * 1e3:9.1f} {theirs_s:>11} {ratio:>8} {cpu_ratio:>9}  {note}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repetitions")
    ap.add_argument(
        "--timeout",
        type=float,
        default=120.0,
        help="limit for the full symbolic sympy.geometry run (s), default 120",
    )
    args = ap.parse_args()
    n_fig6, n_sym_gc, n_sym_sp = (3, 2, 1) if args.quick else (9, 3, 3)

    print(
        f"python {sys.version.split()[0]}, sympy {sp.__version__}, "
        f"graspcompass {gc.__version__}; caches cleared before every run; "
        f"median of N interleaved runs; verdict on the wall-clock ratio"
    )
    # warm-up (imports and first-call set-up, not measured)
    gc_fig6()
    sympy_fig6()

    print(f"\n{'case':<32} {'ours ms':>9} {'sympy.geo':>11} {'ratio':>8} {'CPU ratio':>9}  note")
    print("-" * 100)

    # (a) Fig. 6, exact
    (t_ours, t_ne, t_text, t_sp), (ours, _, _, theirs) = median_times(
        [gc_fig6, gc_fig6_no_envelope, gc_fig6_from_text, sympy_fig6], n_fig6
    )
    ratio_a = t_sp.wall / t_ours.wall
    row(
        "(a) fig6 exact, full diagram",
        t_ours,
        t_sp,
        f"{ratio_a:.1f}x",
        f"{t_sp.cpu / t_ours.cpu:.1f}x",
        f"N={n_fig6}; {verdict(ratio_a, TARGET_EXACT)} (>= {TARGET_EXACT:g}x)",
    )
    row(
        "    fig6 exact, no envelope",
        t_ne,
        t_sp,
        f"{t_sp.wall / t_ne.wall:.1f}x",
        f"{t_sp.cpu / t_ne.cpu:.1f}x",
        "info: the baseline's steps (no envelope)",
    )
    row(
        "    fig6 from the preset's text",
        t_text,
        t_sp,
        f"{t_sp.wall / t_text.wall:.1f}x",
        f"{t_sp.cpu / t_text.cpu:.1f}x",
        "info: + parsing the text of Grasp.preset",
    )
    print(f"    V1..V4 agree with sympy.geometry: {check_fig6(ours, theirs)}")

    # (e) Fig. 6, each run in a fresh process (imports done, not timed)
    reps = 3 if args.quick else 7
    (t_fresh, t_imp), (t_fresh_sp, t_imp_sp) = (
        fresh_process("ours", reps),
        fresh_process("sympy", reps),
    )
    ratio_e = t_fresh_sp.wall / t_fresh.wall
    row(
        "(e) fig6 exact, fresh process",
        t_fresh,
        t_fresh_sp,
        f"{ratio_e:.1f}x",
        f"{t_fresh_sp.cpu / t_fresh.cpu:.1f}x",
        f"N={reps}; {verdict(ratio_e, TARGET_EXACT)} (>= {TARGET_EXACT:g}x)",
    )
    t_pre, _ = fresh_process("preset", reps)
    row(
        "    fig6 from the preset, fresh",
        t_pre,
        t_fresh_sp,
        f"{t_fresh_sp.wall / t_pre.wall:.1f}x",
        f"{t_fresh_sp.cpu / t_pre.cpu:.1f}x",
        'info: internal_force_diagram(Grasp.preset("fig6")), the text parsed in the run',
    )
    both, both_sp = t_imp.wall + t_fresh.wall, t_imp_sp.wall + t_fresh_sp.wall
    print(
        f"    imports, not timed above: graspcompass {1e3 * t_imp.wall:.0f} ms "
        f"(it parses the shipped recipe, ~3 ms), sympy.geometry {1e3 * t_imp_sp.wall:.0f} ms; "
        f"import + first call: {both_sp / both:.1f}x"
    )

    # (d) fully symbolic, up to V4
    (t_v4, t_sp_v4), (ours_v4, theirs_v4) = median_times(
        [gc_symbolic_upto_v4, sympy_symbolic_upto_v4], n_sym_sp
    )
    ratio_v4 = t_sp_v4.wall / t_v4.wall
    row(
        "(d) symbolic, up to V4",
        t_v4,
        t_sp_v4,
        f"{ratio_v4:.1f}x",
        f"{t_sp_v4.cpu / t_v4.cpu:.1f}x",
        f"N={n_sym_sp}; {verdict(ratio_v4, TARGET_SYMBOLIC)} (>= {TARGET_SYMBOLIC:g}x)",
    )
    print(
        f"    V1..V4 agree with sympy.geometry (numeric check): "
        f"{check_symbolic(ours_v4, theirs_v4)}"
    )

    # (d) fully symbolic, full diagram (the baseline in a subprocess, with a time limit)
    (t_full,), _ = median_times([gc_symbolic_full], n_sym_gc)
    wall, cpu, finished = sympy_symbolic_full(args.timeout)
    ratio_full = wall / t_full.wall
    cpu_s = "n/a" if cpu is None else f"{cpu / t_full.cpu:.0f}x"
    if finished:
        theirs_full = Timing(wall, cpu or float("nan"), 1)
        row(
            "(d) symbolic, full diagram",
            t_full,
            theirs_full,
            f"{ratio_full:.1f}x",
            cpu_s,
            f"N={n_sym_gc}/1; {verdict(ratio_full, TARGET_SYMBOLIC)} (>= {TARGET_SYMBOLIC:g}x)",
        )
    else:
        row(
            "(d) symbolic, full diagram",
            t_full,
            f"> {wall:.0f} s",
            f"> {ratio_full:.0f}x",
            "> " + cpu_s if cpu is not None else cpu_s,
            f"N={n_sym_gc}/1; sympy.geometry stopped after {args.timeout:g} s; "
            f"{verdict(ratio_full, TARGET_SYMBOLIC, lower_bound=True)} "
            f"(>= {TARGET_SYMBOLIC:g}x)",
        )
        if cpu is not None:
            print(f"    the stopped sympy.geometry child had used {cpu:.0f} s of CPU")


if __name__ == "__main__":
    main()
