"""How fast ``graspcompass`` refuses hostile input, as a process (issue 10: under 1 s each).

Each command line below is a user error or an attack from issue 10 (and the
classes behind them: complex and non-finite values, huge numbers, parser
limits, option bounds, outputs that cannot be written, missing folders).  Each
runs as a fresh ``graspcompass`` process (``python -m graspcompass``) ``--repeat``
times; the script checks that it exits with status 2 and one line on stderr,
and prints the median and the slowest wall time.

Baselines of the same run: ``python -c pass`` (the interpreter alone) and
``python -c "import sympy"`` (the floor for any command that must read an exact
value).  The ratio printed is the slowest refusal over the sympy floor; the
target is every refusal under 1 s.  Nothing is asserted; the machine may be
loaded.

Run:  PYTHONPATH=src python bench/bench_cli.py [--quick] [--repeat 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET_S = 1.0

#: (what, arguments): every one must be refused with status 2 and one line.
CASES: list[tuple[str, list[str]]] = [
    ("complex mu1", ["k", "--mu1", "asin(2)"]),
    ("complex x1", ["k", "--x1", "sqrt(-1)"]),
    ("I as a value", ["k", "--y", "I"]),
    ("code as a value", ["k", "--x1", "__import__('os').system('touch /tmp/x') or 1"]),
    ("nan", ["k", "--mu2", "nan"]),
    ("infinite", ["k", "--x2", "oo"]),
    ("huge value", ["k", "--x1", "1e309", "--x2", "1e309"]),
    ("too many digits", ["k", "--y", "1e400"]),
    ("tower exponent", ["k", "--x1", "10**10**10"]),
    ("deep nesting", ["k", "--x1", "sqrt(" * 40 + "2" + ")" * 40]),
    ("long text", ["k", "--x1", "1+" * 500 + "1"]),
    ("condition (1)", ["k", "--phi1", "pi/6"]),
    ("theta: too many", ["k", "--theta", "0:2000000:1"]),
    ("theta: complex", ["k", "--theta", "asin(3)"]),
    ("theta: nan", ["k", "--theta", "nan"]),
    ("force: negative", ["k", "--external-force", "-1"]),
    ("force: huge", ["k", "--external-force", "1e309"]),
    ("pdf to /dev/full", ["draw", "--format", "pdf", "-o", "/dev/full"]),
    ("missing folder", ["draw", "-o", "{tmp}/no/such/folder/x.png"]),
    ("fps 1e-300", ["animate", "--fps", "1e-300"]),
    ("dpi inf", ["animate", "--dpi", "inf"]),
    ("unknown preset", ["steps", "--preset", "fig7"]),
    ("step out of range", ["draw", "--step", "99999", "-o", "{tmp}/x.png"]),
    (
        "export: bad title",
        ["export", "--format", "svg", "-o", "{tmp}/x.svg", "--title", "\x1b[31m" * 3],
    ),
    ("export: no folder", ["export", "-o", "{tmp}/no/x.svg"]),
    ("export: extension", ["export", "-o", "{tmp}/x.zzz"]),
    ("animate: no folder", ["animate", "-o", "{tmp}/no/x.gif"]),
    ("animate: extension", ["animate", "-o", "{tmp}/x.avi"]),
    ("worksheet: no folder", ["worksheet", "-o", "{tmp}/no/x.pdf"]),
    ("recipe: no folder", ["recipe", "-o", "{tmp}/no/x.gc"]),
    ("verify: no folder", ["verify", "--markdown", "{tmp}/no/x.md"]),
    ("main job: no folder", ["--out", "{tmp}/no/such"]),
]


def _run(args: list[str], env: dict[str, str]) -> tuple[float, int, str]:
    t0 = time.perf_counter()
    p = subprocess.run(args, capture_output=True, text=True, env=env, timeout=60)
    return time.perf_counter() - t0, p.returncode, p.stderr


def _median_time(args: list[str], env: dict[str, str], repeat: int) -> tuple[float, float]:
    times = [_run(args, env)[0] for _ in range(repeat)]
    return statistics.median(times), max(times)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="--repeat 2")
    opts = ap.parse_args()
    repeat = 2 if opts.quick else opts.repeat
    env = dict(os.environ)
    env.setdefault("PYTHONPATH", str(Path(__file__).resolve().parents[1] / "src"))
    py = sys.executable
    with tempfile.TemporaryDirectory() as tmp:
        base_pass = _median_time([py, "-c", "pass"], env, repeat)
        # the floor of a value refusal: sympy loaded, and no teardown (cli.console freezes gc)
        base_sympy = _median_time([py, "-c", "import gc, sympy; gc.freeze()"], env, repeat)
        print(f"{'case':20} {'median s':>9} {'max s':>7}  status, stderr")
        print(f"{'python -c pass':20} {base_pass[0]:9.3f} {base_pass[1]:7.3f}  (baseline)")
        print(f"{'import sympy':20} {base_sympy[0]:9.3f} {base_sympy[1]:7.3f}  (baseline)")
        slowest, bad = 0.0, []
        for what, case in CASES:
            args = [py, "-m", "graspcompass", *(a.replace("{tmp}", tmp) for a in case)]
            times, last = [], (0.0, 0, "")
            for _ in range(repeat):
                last = _run(args, env)
                times.append(last[0])
            _, status, err = last
            lines = err.strip().splitlines()
            ok = status == 2 and len(lines) == 1
            if not ok:
                bad.append(what)
            slowest = max(slowest, max(times))
            shown = lines[0][:70] if lines else "(nothing)"
            print(
                f"{what:20} {statistics.median(times):9.3f} {max(times):7.3f}  {status}, "
                f"{shown}{'' if ok else '  <-- NOT ONE LINE/2'}"
            )
    print(
        f"\nslowest refusal {slowest:.3f} s = {slowest / base_sympy[0]:.2f}x the sympy import "
        f"floor ({base_sympy[0]:.3f} s); target {TARGET_S} s"
    )
    print(
        "target met"
        if slowest < TARGET_S and not bad
        else f"target NOT met{': wrong status or output for ' + ', '.join(bad) if bad else ''}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
