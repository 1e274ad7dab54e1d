"""The two slow runs of issue 19 item 7, measured: ``certify`` at typed angles and
``check --against paper`` of an equivalent recipe drawing the perpendicular of V1 as
``line_through P2x F1`` (F1 the foot of P2x on side1).

Each run is timed once (the construction of a grasp is built first and not timed) and
its verdicts are counted; ``--timeout`` bounds the check as on the command line.

Usage::

    python bench/bench_issue19.py [--timeout 600] [--skip-check]
"""

from __future__ import annotations

import argparse
import collections
import time

from graspcompass import PRESETS, Grasp, internal_force_diagram
from graspcompass.construction.language import paper_text, parse
from graspcompass.proof.certify import certify
from graspcompass.proof.program_check import check_program

ANGLES = [{"phi1": "3*pi/5"}, {"phi1": "3*pi/7"}, {"phi1": "6/5"}, {"phi1": "6/5", "xi1": "1/2"}]


def perpendicular_as_line_through() -> str:
    """The shipped recipe with perp1 drawn through P2x and its foot on side1."""
    old = "perp1 = perpendicular side1 P2x "
    text = paper_text()
    assert old in text
    return text.replace(old, "F1 = foot P2x side1\nperp1 = line_through P2x F1 ")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--skip-check", action="store_true")
    args = ap.parse_args()
    for angles in ANGLES:
        params = dict(PRESETS["fig6"]["params"], **angles)
        c = internal_force_diagram(Grasp(**params))
        t0 = time.perf_counter()
        certs = certify(c, timeout=args.timeout)
        n = collections.Counter(x.result.status.value for x in certs)
        print(f"certify fig6 {angles}: {time.perf_counter() - t0:6.2f} s  {dict(n)}")
    if not args.skip_check:
        t0 = time.perf_counter()
        r = check_program(parse(perpendicular_as_line_through()), "paper", timeout=args.timeout)
        n = collections.Counter(x.status.value for x in r.rows)
        print(
            f"check --against paper, perp1 = line_through P2x F1: "
            f"{time.perf_counter() - t0:6.1f} s  {dict(n)}  exit {r.exit_status}"
        )


if __name__ == "__main__":
    main()
