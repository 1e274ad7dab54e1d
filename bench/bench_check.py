"""``graspcompass check --against paper`` of the shipped recipe: under 10 s (issue 11 §2).

Times, in one process and in the same run:

(a) ``check_program(paper_program(), against="paper")``: the fully symbolic replay
    of ``recipes/paper.gc`` (47 steps, circles and their break points), the
    certification of every step, the 9 claims and the 19 targets graded against
    the paper (§3.3, eqs. (28)-(39)); kernel caches cleared before each run;
(b) the symbolic replay alone (the floor: what any checker of this file must do);
(c) the baseline: the same 19 targets decided by ``sympy.simplify(file − paper) == 0``
    on the same symbolic objects, coordinate by coordinate, stopped at ``--limit`` s
    (a stopped baseline gives its ratio as a lower bound, ``>``).

(d) the command itself, ``graspcompass check recipes/paper.gc --against paper``, each
    run in a fresh process (interpreter, imports and output included), wall and CPU
    time, against ``python -c "import sympy"`` in the same run.

Prints median times of ``--runs`` runs, the ratio (c)/(a minus b) of the deciding
work and the targets: (a) under 10 s (issue 11), (d) under 1.5 s (issue 20).  Nothing
is asserted.

Run:  PYTHONPATH=src python bench/bench_check.py [--quick] [--runs 3] [--limit 120]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import sympy as sp

from graspcompass.construction.language import paper_program, replay
from graspcompass.geometry.exact import clear_caches
from graspcompass.proof._program_targets import _paper_model, _paper_object
from graspcompass.proof.program_check import PAPER_TARGETS, check_program
from graspcompass.proof.program_decide import coords

TARGET_S = 10.0
#: The whole command, cold (issue 20).
TARGET_COLD_S = 1.5


def _cold(args: list[str]) -> tuple[float, float]:
    """Wall and CPU time (user + system) of ``python args`` in a fresh process."""
    import os
    import resource
    import subprocess

    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(
            [os.path.join(os.path.dirname(__file__), "..", "src"), os.environ.get("PYTHONPATH", "")]
        ),
    }

    def cpu() -> float:
        r = resource.getrusage(resource.RUSAGE_CHILDREN)
        return r.ru_utime + r.ru_stime

    t0, c0 = time.perf_counter(), cpu()
    subprocess.run([sys.executable, *args], env=env, check=True, capture_output=True)
    return time.perf_counter() - t0, cpu() - c0


def _timed(fn) -> tuple[float, object]:
    clear_caches()
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def _baseline(limit: float) -> tuple[float, bool, int]:
    prog = paper_program()
    env = {s.name: s.obj for s in replay(prog).steps}
    model = _paper_model(prog)
    t0, proved = time.perf_counter(), 0
    for name in PAPER_TARGETS:
        if name not in env:
            continue
        for h, w in zip(coords(env[name]), _paper_object(model, name)):
            if sp.simplify(h - w) != 0:
                break
        else:
            proved += 1
        if time.perf_counter() - t0 > limit:
            return time.perf_counter() - t0, False, proved
    return time.perf_counter() - t0, True, proved


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--limit", type=float, default=120.0)
    ap.add_argument("--quick", action="store_true", help="one run, baseline limit 30 s")
    o = ap.parse_args()
    runs, limit = (1, 30.0) if o.quick else (o.runs, o.limit)
    prog = paper_program()
    checks, replays = [], []
    report = None
    for _ in range(runs):
        t, report = _timed(lambda: check_program(prog, "paper"))
        checks.append(t)
        replays.append(_timed(lambda: replay(prog))[0])
    assert report is not None
    check_t, replay_t = statistics.median(checks), statistics.median(replays)
    decide_t = max(check_t - replay_t, 1e-6)
    base_t, finished, proved = _baseline(limit)
    statuses = {r.status.value for r in report.rows}
    print(
        f"(a) check --against paper, shipped recipe: {check_t:.2f} s "
        f"(runs: {', '.join(f'{t:.2f}' for t in checks)}); verdicts {sorted(statuses)}; "
        f"{len(report.targets)} targets, {len(report.claims)} claims, {len(report.steps)} "
        "steps"
    )
    print(f"(b) symbolic replay alone: {replay_t:.2f} s; deciding: {decide_t:.2f} s")
    print(
        f"(c) baseline sympy.simplify on the 19 targets: {base_t:.2f} s"
        f"{'' if finished else ' (stopped)'}, {proved} proved"
    )
    print(f"ratio (c)/(deciding): {'>' if not finished else ''}{base_t / decide_t:.0f}x")
    recipe = str(
        Path(__file__).resolve().parents[1]
        / "src"
        / "graspcompass"
        / "construction"
        / "recipes"
        / "paper.gc"
    )
    cmd = [
        "-c",
        "import sys; from graspcompass.cli import main; "
        f"sys.exit(main(['check', {recipe!r}, '--against', 'paper']))",
    ]
    cold = [_cold(cmd) for _ in range(runs)]
    ref = [_cold(["-c", "import sympy"]) for _ in range(runs)]
    cw, cc = (statistics.median(c[i] for c in cold) for i in (0, 1))
    rw, rc = (statistics.median(c[i] for c in ref) for i in (0, 1))
    print(
        f"(d) the command, fresh process: {cw:.2f} s wall, {cc:.2f} s CPU; "
        f"python -c 'import sympy': {rw:.2f} s wall, {rc:.2f} s CPU "
        f"(the command = {cc / rc:.1f}x the sympy import in CPU time)"
    )
    print(
        "target (a) < 10 s met"
        if check_t < TARGET_S and report.exit_status == 0
        else "target (a) NOT met"
    )
    print(
        f"target (d) < {TARGET_COLD_S} s cold:",
        "met"
        if cw < TARGET_COLD_S
        else ("met in CPU time (wall stretched by the load)" if cc < TARGET_COLD_S else "NOT met"),
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
