"""The geometry-class corpus of issue 24: verdict rates and check times.

Checks every file of ``tests/corpus_geometry`` (two worker processes) and prints, per
file, the verdict of each claim against its textbook truth, then the totals: true claims
PROVED, false claims REFUTED, internal errors, files the language cannot read
(BLOCKED) and the median check time, against the targets of issue 24.  The baseline,
measured when the corpus was written (before its operations and claims existed): 39 of
46 files BLOCKED, 12/113 true claims PROVED, 3/28 false ones REFUTED.  Nothing is
asserted (the soundness assertions
are in ``tests/test_corpus_geometry.py``).

Run:  PYTHONPATH=src python bench/bench_corpus.py [--jobs 2] [FILE...]
"""

from __future__ import annotations

import argparse
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
import _corpus


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("files", nargs="*")
    args = ap.parse_args()
    paths = [Path(f) for f in args.files] or _corpus.files()
    with ProcessPoolExecutor(args.jobs) as pool:
        records = list(pool.map(_corpus.run, paths))
    for r in records:
        marks = " ".join(("T" if e else "F") + ":" + s for e, s, _ in r["claims"])
        print(f"{r['file']:34s} {r['seconds']:6.2f}s  {marks}")
        if r["error"]:
            print("    " + r["error"].strip().splitlines()[-1][:160])
    s = _corpus.summary(records)
    print(
        f"\nfiles {s['files']} (blocked {s['blocked_files']}, internal errors "
        f"{s['internal_errors']}); true claims PROVED {s['true_proved']}/{s['true']} "
        f"({100 * s['true_proved'] / max(s['true'], 1):.0f} %), true REFUTED "
        f"{s['true_refuted']}; false claims REFUTED {s['false_refuted']}/{s['false']}, "
        f"false PROVED {s['false_proved']}; median check {s['median_s']:.2f} s"
    )
    met = (
        s["true_proved"] >= 0.95 * s["true"]
        and s["false_refuted"] == s["false"]
        and s["internal_errors"] == 0
        and s["false_proved"] == 0
        and s["median_s"] < 2.0
    )
    print(
        "targets (issue 24): >= 95 % of true claims PROVED, every false one REFUTED, "
        f"0 internal errors, median < 2 s: target {'met' if met else 'NOT met'}"
    )


if __name__ == "__main__":
    main()
