"""The web explorer's update time in headless Chromium (issue 12 §1: each update < 16 ms).

The page of ``graspcompass export --format html`` (Fig. 6 grasp) is opened in
Debian's Chromium through Playwright.  Each update is timed *in the page*
(``performance.now()`` from the input event to the end of JSXGraph's redraw of
the board, ``graspcompass.timings()``):

(a) ``--moves`` slider moves, cycling over the eight sliders, as real input
    events (Playwright ``fill`` on the ``<input type=range>``);
(b) ``--moves`` mouse moves while dragging P1 (``page.mouse``);
(c) ``--moves`` calls of ``graspcompass.set({...})`` inside the page (no
    round trip to Playwright at all).

It prints the median, 95th percentile and maximum ms of each, and the ratio of
the median and of the 95th percentile to the budget of one 60 Hz frame (16 ms).
It also compares the page's V_n (eqs. (28)-(39)) and k_grasp (eq. (25)) on
``--moves`` random float grasps with ``graspcompass.Grasp(...).V`` and
``k_grasp`` and prints the largest deviation, relative to max(1, |V_n|).
Baseline of the same run: the matplotlib explorer (``graspcompass explore``)
as it was before issue 12 §1 (``bench_explorer.naive_explorer_class()``: the
construction replayed per change), ``set_params`` plus a full Agg draw, for a
few moves; the explorer of today blits a change in tens of ms
(``bench/bench_explorer.py``).  Nothing is asserted; the machine may be loaded.

Run:  PYTHONPATH=src python bench/bench_web.py [--quick] [--moves 200] [--out DIR]
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
from typing import Any

BUDGET_MS = 16.0


def pct(values: list[float], q: float) -> float:
    """The ``q``-th percentile (nearest rank) of ``values``."""
    s = sorted(values)
    return s[min(len(s) - 1, max(0, math.ceil(q / 100 * len(s)) - 1))]


def row(name: str, ms: list[float]) -> str:
    med, p95 = statistics.median(ms), pct(ms, 95)
    return (
        f"{name:<34} {len(ms):>5} {med:>8.2f} {p95:>8.2f} {max(ms):>8.2f} "
        f"{med / BUDGET_MS:>8.3f} {p95 / BUDGET_MS:>8.3f}"
    )


def slider_values(i: int) -> tuple[str, str]:
    """The i-th slider move: a parameter and a value inside condition (1) for Fig. 6."""
    names = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "theta")
    name = names[i % len(names)]
    t = 0.5 + 0.5 * math.sin(0.37 * i)  # in [0, 1], smooth
    lo, hi = {
        "x1": (0.4, 2.0),
        "x2": (0.4, 2.0),
        "y": (0.0, 1.5),
        "phi1": (50, 70),
        "phi2": (50, 70),
        "mu1": (0.9, 1.6),
        "mu2": (1.5, 2.2),
        "theta": (0, 360),
    }[name]
    return name, f"{lo + (hi - lo) * t:.3f}"


def random_grasps(count: int, seed: int = 7) -> list[dict[str, float]]:
    """Float grasps inside condition (1) with a margin of 0.02 rad."""
    import random

    rng = random.Random(seed)
    out: list[dict[str, float]] = []
    while len(out) < count:
        p = dict(x1=rng.uniform(0.05, 3), x2=rng.uniform(0.05, 3), y=rng.uniform(0, 3))
        for i in (1, 2):
            phi = rng.uniform(0.05, math.pi)
            lo = abs(phi - math.pi / 2) + 0.02
            if lo >= math.pi / 2 - 0.02:
                break
            p[f"phi{i}"], p[f"mu{i}"] = phi, math.tan(rng.uniform(lo, math.pi / 2 - 0.02))
        else:
            out.append(p)
    return out


def deviation(page: Any, count: int) -> float:
    """Largest |page − Python| of V_n and k_grasp over ``count`` random grasps (relative)."""
    from graspcompass import Grasp

    grasps = random_grasps(count)
    got = page.evaluate(
        """ps => ps.map(p => {
        const q = graspcompass.model.compute(Object.assign({theta: 0.7}, p));
        return [q.V, q.kgrasp]; })""",
        grasps,
    )
    worst = 0.0
    for p, (V, k) in zip(grasps, got):
        g = Grasp(**p)
        want = [(float(v.x), float(v.y)) for v in g.V]
        scale = max(1.0, *(math.hypot(*v) for v in want))
        worst = max(
            worst,
            *(math.dist(a, b) / scale for a, b in zip(V, want)),
            abs(k - g.k_grasp(0.7)) / scale,
        )
    return worst


def run_browser(page_path: Path, moves: int) -> tuple[dict[str, list[float]], float]:
    from playwright.sync_api import sync_playwright

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("Chromium is not installed (Debian: apt-get install chromium)")
    out: dict[str, list[float]] = {}
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.goto(page_path.as_uri())
        page.wait_for_selector("body[data-ready='1']", timeout=30_000)
        # warm-up: JIT and the first layout
        for i in range(20):
            name, value = slider_values(i)
            page.fill(f"#gc-slider-{name}", value)
        page.evaluate("graspcompass.resetTimings()")
        for i in range(moves):
            name, value = slider_values(i)
            page.fill(f"#gc-slider-{name}", value)
        out["(a) slider moves (input events)"] = page.evaluate("graspcompass.timings()")

        page.evaluate(
            "graspcompass.set({x1: Math.sqrt(3) / 2, x2: Math.sqrt(3) / 2, y: 0.5,"
            " phi1: Math.PI / 3, phi2: Math.PI / 3, mu1: 1, mu2: Math.sqrt(3)});"
            "graspcompass.fit(); graspcompass.resetTimings()"
        )
        x0, y0 = page.evaluate("graspcompass.toScreen('P1')")
        page.mouse.move(x0, y0)
        page.mouse.down()
        for i in range(moves):
            a = 2 * math.pi * i / moves
            page.mouse.move(x0 + 60 * math.sin(a), y0 - 30 * (1 - math.cos(a)))
        page.mouse.up()
        out["(b) dragging P1 (mouse moves)"] = page.evaluate("graspcompass.timings()")

        out["(c) graspcompass.set() in the page"] = page.evaluate(
            """n => { graspcompass.resetTimings();
                 for (let i = 0; i < n; i++) {
                   graspcompass.set({mu2: 1.5 + 0.7 * (0.5 + 0.5 * Math.sin(0.37 * i)),
                                     theta: 0.05 * i});
                 }
                 return graspcompass.timings(); }""",
            moves,
        )
        dev = deviation(page, moves)
        browser.close()
    return out, dev


def run_matplotlib(moves: int) -> list[float]:
    """ms per move of the matplotlib explorer before issue 12 §1: set_params, full Agg draw."""
    import os

    os.environ.setdefault("MPLBACKEND", "agg")
    sys.path.insert(0, str(Path(__file__).parent))
    from bench_explorer import naive_explorer_class

    ex = naive_explorer_class()()
    ex.fig.canvas.draw()
    ms = []
    for i in range(moves):
        t0 = time.perf_counter()
        ex.set_params(mu2=1.5 + 0.7 * (0.5 + 0.5 * math.sin(0.37 * i)))
        ex.fig.canvas.draw()
        ms.append(1000 * (time.perf_counter() - t0))
    return ms


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="50 moves, 3 matplotlib moves")
    ap.add_argument("--moves", type=int, default=200, help="moves per kind (default 200)")
    ap.add_argument("--out", type=Path, help="keep the page in this folder")
    args = ap.parse_args(argv)
    moves = 50 if args.quick else args.moves

    from graspcompass import Grasp, internal_force_diagram
    from graspcompass.export.html import write_html

    with tempfile.TemporaryDirectory() as tmp:
        folder = args.out or Path(tmp)
        page_path = write_html(
            internal_force_diagram(Grasp.preset("fig6")), folder / "explorer.html"
        )
        web, dev = run_browser(page_path, moves)
    mpl = run_matplotlib(3 if args.quick else 10)

    print(
        f"web explorer update time, ms per update, measured in the page "
        f"(budget {BUDGET_MS:g} ms = one 60 Hz frame)"
    )
    print(f"{'':<34} {'n':>5} {'median':>8} {'p95':>8} {'max':>8} {'med/16':>8} {'p95/16':>8}")
    for name, ms in web.items():
        print(row(name, ms))
    print(row("baseline: matplotlib explorer", mpl))
    print(
        f"largest deviation from Python's closed form (V_n, k_grasp; {moves} random grasps, "
        f"relative to max(1, |V_n|)): {dev:.2e}"
    )
    worst_p95 = max(pct(ms, 95) for ms in web.values())
    med_all = statistics.median([m for ms in web.values() for m in ms])
    print(
        f"median over all web updates {med_all:.2f} ms; matplotlib / web median = "
        f"{statistics.median(mpl) / med_all:.0f}x"
    )
    met = worst_p95 < BUDGET_MS
    print(
        f"worst 95th percentile {worst_p95:.2f} ms = {worst_p95 / BUDGET_MS:.2f} x budget: "
        f"target {'met' if met else 'NOT met'}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
