"""The n-contact web page's update time in headless Chromium (issue 25).

The page of ``graspcompass export --format html --contact ...`` (six contacts on a
circle, the sum of normal forces) is opened in Debian's Chromium through Playwright.
Timed *in the page* (``performance.now()``):

(a) ``--moves`` calls of ``graspcompass.set({...})`` moving contact 1 (recompute Q,
    redraw circles, envelope and cones: ``graspcompass.lastUpdateMs``);
(b) ``--moves`` calls of ``graspcompass.compute(state)`` alone (Q, no drawing).

Baseline of the same run: the Python float path building Q for the same states
(``NContactGrasp(...).polygon()``, a fresh grasp each time).  It prints the median
and 95th percentile of each, the ratio of (a) to one 60 Hz frame (16 ms) and of (b)
to the Python baseline.  Nothing is asserted; the machine may be loaded.

Run:  PYTHONPATH=src python bench/bench_web_ncontact.py [--moves 100] [--n 6]
"""

from __future__ import annotations

import argparse
import math
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

BUDGET_MS = 16.0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--moves", type=int, default=100)
    ap.add_argument("--n", type=int, default=6)
    args = ap.parse_args()
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        print("Playwright is not installed (pip install playwright)")
        return 0
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        print("Chromium is not installed (apt-get install chromium)")
        return 0
    from graspcompass.export.ncontact_html import write_ncontact_html
    from graspcompass.ncontact import NContactGrasp

    angles = [2 * math.pi * i / args.n + 0.1 * i for i in range(args.n)]
    contacts = [(math.cos(a), math.sin(a), a + math.pi, 0.5) for a in angles]
    xs = [1.0 + 0.3 * i / args.moves for i in range(args.moves)]
    py = []
    for x in xs:
        t0 = time.perf_counter()
        NContactGrasp([(x, *contacts[0][1:]), *contacts[1:]]).polygon()
        py.append((time.perf_counter() - t0) * 1e3)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "page.html"
        write_ncontact_html(NContactGrasp(contacts), path)
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=exe, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1280, "height": 800})
            page.goto(path.as_uri())
            page.wait_for_selector("body[data-ready='1']", timeout=30_000)
            upd = page.evaluate(
                """xs => xs.map(x => { graspcompass.set({contacts: [{x}]});
                return graspcompass.lastUpdateMs; })""",
                xs,
            )
            comp = page.evaluate(
                """xs => xs.map(x => { const s = graspcompass.state();
                s.contacts[0].x = x; const t0 = performance.now(); graspcompass.compute(s);
                return performance.now() - t0; })""",
                xs,
            )
            browser.close()

    def stats(v: list[float]) -> tuple[float, float]:
        v = sorted(v)
        return statistics.median(v), v[min(len(v) - 1, int(0.95 * len(v)))]

    (um, up), (cm, cp), (pm, pp) = stats(upd), stats(comp), stats(py)
    print(f"n = {args.n}, {args.moves} moves")
    print(
        f"(a) page update (Q + redraw): median {um:.1f} ms, p95 {up:.1f} ms "
        f"({um / BUDGET_MS:.2f}x / {up / BUDGET_MS:.2f}x one 60 Hz frame)"
    )
    print(f"(b) page compute(Q) alone:    median {cm:.2f} ms, p95 {cp:.2f} ms")
    print(
        f"baseline: Python float Q:     median {pm:.2f} ms, p95 {pp:.2f} ms "
        f"(page/Python {cm / pm:.2f}x)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
