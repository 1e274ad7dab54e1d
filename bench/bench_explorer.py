"""The matplotlib explorer's time per change (issue 12 §1: under 30 ms).

:class:`graspcompass.render.explorer.Explorer` on the Fig. 6 grasp, headless on
the Agg backend, driven by the events a user makes (``canvas.callbacks.process``
of matplotlib ``MouseEvent``\\ s, as ``tests/test_explorer.py`` does):

(a) ``--moves`` slider moves, cycling over x1, x2, y, φ1, φ2, μ1, μ2, θ (a press
    and a release on the slider at a new value inside condition (1));
(b) ``--moves`` mouse moves while dragging P1 (press on P1, then motion events
    along a loop of 60 × 30 pixels);
(c) ``--moves // 4`` changes into parameters that are not a grasp (condition (1)
    fails: the message with the failing inequality is drawn), for reference.

Each change is timed from the event to the end of the redraw (the blit; on Agg
the picture is then in the canvas buffer).  Baseline of the same run: the same
events on ``NaiveExplorer``, the explorer as it was before issue 12 §1 -- the
ruler-and-compass construction replayed per change
(:func:`graspcompass.internal_force_diagram`, every step evaluated) and the
whole figure rendered again (``draw_idle``, which on Agg renders at once, by the
slider that moved and again by the explorer).  It prints the median, 95th
percentile and maximum ms per change, the ratio of the medians, and "target
met" when the median of (a) and (b) together is under 30 ms.  Nothing is
asserted; the machine may be loaded.

Run:  PYTHONPATH=src MPLBACKEND=agg python bench/bench_explorer.py [--quick] [--moves 200]
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from typing import Any

os.environ.setdefault("MPLBACKEND", "agg")

TARGET_MS = 30.0
#: slider ranges inside condition (1) for the Fig. 6 grasp (φ, θ in degrees)
RANGES = {
    "x1": (0.4, 2.0),
    "x2": (0.4, 2.0),
    "y": (0.0, 1.5),
    "phi1": (50, 70),
    "phi2": (50, 70),
    "mu1": (0.9, 1.6),
    "mu2": (1.5, 2.2),
    "theta": (0, 360),
}


def pct(values: list[float], q: float) -> float:
    """The ``q``-th percentile (nearest rank) of ``values``."""
    s = sorted(values)
    return s[min(len(s) - 1, max(0, math.ceil(q / 100 * len(s)) - 1))]


def naive_explorer_class() -> type:
    """The explorer before issue 12 §1 (construction per change, full renders)."""
    from graspcompass.render._explorer_scene import construction_scene
    from graspcompass.render.explorer import Explorer

    class NaiveExplorer(Explorer):
        """Replays the construction per change and renders the whole figure."""

        def __init__(self, *args: Any, **kwargs: Any) -> None:
            super().__init__(*args, blit=False, **kwargs)
            for s in self.sliders.values():
                s.drawon = True  # the slider renders the figure, as before

        def _compute(self) -> Any:
            return construction_scene(self.params, self._grid)

    return NaiveExplorer


def _mouse(ex: Any, name: str, xy: Any) -> float:
    from matplotlib.backend_bases import MouseEvent

    ev = MouseEvent(name, ex.fig.canvas, float(xy[0]), float(xy[1]), button=1)
    t0 = time.perf_counter()
    ex.fig.canvas.callbacks.process(name, ev)
    return 1000 * (time.perf_counter() - t0)


def slider_moves(ex: Any, moves: int, start: int = 0) -> list[float]:
    """ms per slider move (press + release), cycling over the eight sliders."""
    names = list(RANGES)
    ms = []
    for i in range(start, start + moves):
        name = names[i % len(names)]
        lo, hi = RANGES[name]
        value = lo + (hi - lo) * (0.5 + 0.5 * math.sin(0.37 * i))
        px = ex.sliders[name].ax.transData.transform((value, 0.5))
        ms.append(_mouse(ex, "button_press_event", px) + _mouse(ex, "button_release_event", px))
    return ms


def drag_moves(ex: Any, moves: int) -> list[float]:
    """ms per mouse move while dragging P1 along a loop of 60 × 30 pixels."""
    ex.set_params(x1=math.sqrt(3) / 2, x2=math.sqrt(3) / 2, y=0.5)
    x0, y0 = ex.ax.transData.transform((ex.params["x1"], ex.params["y"]))
    _mouse(ex, "button_press_event", (x0, y0))
    ms = []
    for i in range(moves):
        a = 2 * math.pi * (i + 1) / moves
        ms.append(
            _mouse(ex, "motion_notify_event", (x0 + 60 * math.sin(a), y0 + 30 * (1 - math.cos(a))))
        )
    _mouse(ex, "button_release_event", (x0, y0))
    return ms


def invalid_moves(ex: Any, moves: int) -> list[float]:
    """ms per change into φ1 + ξ1 < π/2 (condition (1) fails: the message)."""
    ms = []
    for i in range(moves):
        t0 = time.perf_counter()
        ex.set_params(phi1=math.radians(20.0), mu1=0.1 + 0.001 * i)
        ms.append(1000 * (time.perf_counter() - t0))
        assert ex.error is not None
    ex.set_params(phi1=math.pi / 3, mu1=1.0)
    return ms


def run(cls: type, moves: int, invalid: int) -> dict[str, list[float]]:
    from graspcompass import Grasp

    ex = cls(Grasp.preset("fig6"))
    ex.fig.canvas.draw()  # the window's first paint
    slider_moves(ex, 8, start=1000)  # warm-up: the background, glyph caches
    out = {"(a) slider moves": slider_moves(ex, moves), "(b) dragging P1": drag_moves(ex, moves)}
    if invalid:
        out["(c) not a grasp (message)"] = invalid_moves(ex, invalid)
    return out


def row(name: str, ms: list[float]) -> str:
    return (
        f"{name:<44} {len(ms):>5} {statistics.median(ms):>9.2f} {pct(ms, 95):>9.2f} {max(ms):>9.2f}"
    )


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="48 moves per kind, 8 for the baseline")
    ap.add_argument("--moves", type=int, default=200, help="moves per kind (default 200)")
    ap.add_argument(
        "--baseline-moves",
        type=int,
        default=16,
        help="moves per kind of the baseline (about 1 s each; default 16)",
    )
    args = ap.parse_args(argv)
    moves = 48 if args.quick else args.moves
    base_moves = 8 if args.quick else args.baseline_moves

    import matplotlib

    from graspcompass.render.explorer import Explorer

    new = run(Explorer, moves, max(4, moves // 4))
    old = run(naive_explorer_class(), base_moves, 0)
    print(
        f"matplotlib explorer, ms per change (event to end of redraw), backend "
        f"{matplotlib.get_backend()}; target: median < {TARGET_MS:g} ms"
    )
    print(f"{'':<44} {'n':>5} {'median':>9} {'p95':>9} {'max':>9}")
    for name, ms in new.items():
        print(row(name, ms))
    new_all = new["(a) slider moves"] + new["(b) dragging P1"]
    print(row("(a)+(b) explorer (float path, blitting)", new_all))
    for name, ms in old.items():
        print(row("baseline " + name, ms))
    old_all = [m for ms in old.values() for m in ms]
    print(row("(a)+(b) baseline (construction, full render)", old_all))
    med, p95 = statistics.median(new_all), pct(new_all, 95)
    ratio = statistics.median(old_all) / med
    print(
        f"median {med:.2f} ms (p95 {p95:.2f} ms) against {statistics.median(old_all):.0f} ms "
        f"before: {ratio:.0f}x faster"
    )
    print(
        f"median {med:.2f} ms vs {TARGET_MS:g} ms: target {'met' if med < TARGET_MS else 'NOT met'}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
