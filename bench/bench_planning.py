"""Choosing contacts: the paper's worst-case squeeze against the Ferrari–Canny ε (issue 13 §3).

On the same contact pairs of an outline (the bracket of the docs, and a 100 × 60 mm
plate), sampled by :func:`graspcompass.planning.sample_contacts`:

(a) ``plan_contacts``: each pair's squeeze over all orientations,
    m g max_n |V_n| / (x1 + x2) per jaw (eqs. (17), (28)-(39)), with condition (1),
    vectorised over all pairs in one call;
(b) the baseline, the Ferrari–Canny L1 quality ε (Ferrari & Canny 1992): the
    distance from the origin of wrench space to the boundary of the convex hull
    of the four unit friction-cone edge wrenches (f_x, f_y, τ/ρ), ρ the largest
    distance from the centre of mass to the outline, through
    ``scipy.spatial.ConvexHull`` (qhull), one hull per pair (ε = 0 when the origin is
    outside: not force-closure).

(c) the exact refinement along the best edge pairs (branch and bound with interval
    bounds, proved within a relative tolerance of 1e-6, :mod:`graspcompass.planning._exact`),
    timed per edge pair against its baseline in the same run: a dense uniform grid of
    (s, t) on the same edge pair, refined until its least value is within the same
    1e-6 of the proved optimum or at its largest size (4096², 1024² with --quick;
    then the ratio is a lower bound of the speed-up), and proves nothing;
    and how much the proved optimum saves over the best sampled pair;
(d) the same under a tilt range (``plan --gravity --tilt``: the worst case over the tilts
    |ρ| <= τ of gravity), where the least squeeze may be approached on the boundary of
    condition (1) (a trapeze with an offset centre of mass shows it).

It prints the time per pair of each, whether both agree on force closure (they differ on
*expanding* grips, two contacts pushing apart, e.g. on the bracket's notch walls: ε > 0,
but the paper's model is a squeeze, condition (1) with 0 < φ_i <= π, so (a) leaves them
out), and how
the rankings differ: the Spearman rank correlation between −squeeze and ε over the
force-closure pairs, and the overlap of the two top-10 lists.

Run:  PYTHONPATH=src python bench/bench_planning.py [--quick] [--samples 200]
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy.spatial import ConvexHull, QhullError  # noqa: E402
from scipy.stats import spearmanr  # noqa: E402

from graspcompass.outlines import read_outline  # noqa: E402
from graspcompass.planning import plan_contacts  # noqa: E402
from graspcompass.planning._exact import (  # noqa: E402
    EdgePair,
    Load,
    edge_pair_values,
    refine_edge_pair,
)

BRACKET = Path(__file__).resolve().parents[1] / "docs" / "_static" / "outlines" / "bracket.svg"
PLATE = [(-0.05, -0.03), (0.05, -0.03), (0.05, 0.03), (-0.05, 0.03)]
TRAPEZE = [(-0.05, -0.03), (0.05, -0.03), (0.04, 0.03), (-0.05, 0.03)]
MU = 0.5


def ferrari_canny(
    points: np.ndarray,
    normals: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    com: tuple[float, float],
    mu: float,
    rho: float,
) -> np.ndarray:
    """ε of each pair (a[k], b[k]): the L1 Ferrari–Canny quality, one qhull call per pair."""
    xi = math.atan(mu)
    c, s = math.cos(xi), math.sin(xi)
    eps = np.zeros(len(a))
    for k, (i, j) in enumerate(zip(a, b)):
        w = []
        for m in (i, j):
            n = normals[m]
            t = np.array([-n[1], n[0]])
            r = points[m] - com
            for sg in (1.0, -1.0):
                f = c * n + sg * s * t
                w.append((f[0], f[1], (r[0] * f[1] - r[1] * f[0]) / rho))
        try:
            hull = ConvexHull(np.array(w))
        except QhullError:  # flat: the four wrenches span a plane, no force closure
            continue
        d = -hull.equations[:, 3]  # the origin's distance to each facet (inside: > 0)
        eps[k] = max(0.0, float(d.min()))
    return eps


def run(name: str, outline: object, samples: int, fc_pairs: int | None) -> None:
    t = []
    for _ in range(3):
        t0 = time.perf_counter()
        plan = plan_contacts(outline, mu=MU, mass=1.0, samples=samples, exact=0)
        t.append(time.perf_counter() - t0)
    n_pairs = len(plan.i)
    per_a = min(t) / n_pairs
    ring = plan.outline
    rho = float(np.max(np.hypot(ring[:, 0] - plan.com[0], ring[:, 1] - plan.com[1])))
    sel = (
        np.arange(n_pairs)
        if fc_pairs is None
        else np.random.default_rng(0).choice(n_pairs, min(fc_pairs, n_pairs), replace=False)
    )
    t0 = time.perf_counter()
    eps = ferrari_canny(plan.points, plan.normals, plan.i[sel], plan.j[sel], plan.com, MU, rho)
    per_b = (time.perf_counter() - t0) / len(sel)
    fc = plan.force_closure[sel]
    agree = int(np.sum(fc == (eps > 1e-12)))
    both = fc & (eps > 1e-12)
    rho_s = spearmanr(-plan.squeeze[sel][both], eps[both]).statistic
    top_a = set(sel[both][np.argsort(plan.squeeze[sel][both], kind="stable")[:10]].tolist())
    top_b = set(sel[both][np.argsort(-eps[both], kind="stable")[:10]].tolist())
    best_b = int(sel[both][np.argmax(eps[both])])
    print(
        f"{name}: {len(plan.points)} contacts, {n_pairs} pairs, "
        f"{int(plan.force_closure.sum())} force-closure (μ = {MU})"
    )
    print(
        f"  (a) worst-case squeeze, vectorised: {per_a * 1e6:8.3f} µs/pair "
        f"({1 / per_a:,.0f} pairs/s, {min(t) * 1e3:.1f} ms for all)"
    )
    print(
        f"  (b) Ferrari–Canny ε, qhull per pair: {per_b * 1e6:8.1f} µs/pair "
        f"(on {len(sel)} pairs) — {per_b / per_a:,.0f}× (a)"
    )
    print(f"  force closure: the two agree on {agree} of {len(sel)} pairs")
    print(
        f"  rankings over {int(both.sum())} force-closure pairs: Spearman ρ(−squeeze, ε) = "
        f"{rho_s:.3f}; top-10 overlap {len(top_a & top_b)}/10"
    )
    pa, pb = plan.pair(int(plan.order[0])), plan.pair(best_b)
    print(
        f"  best by squeeze: {pa.squeeze:.3f} N/kg at {_mm(pa.contacts)}; best by ε: "
        f"{pb.squeeze:.3f} N/kg at {_mm(pb.contacts)} "
        f"(ε = {eps[sel == best_b][0]:.4f} vs {_eps_of(plan, sel, eps, int(plan.order[0]))})"
    )


def exact(
    name: str,
    outline: object,
    samples: int,
    pairs: int,
    largest: int = 4096,
    gravity: tuple[float, float] | None = None,
    tilt_deg: float | None = None,
    com: tuple[float, float] | None = None,
) -> None:
    """(c): the proved optimum per edge pair, timed against a dense grid of the same accuracy.

    (d) with ``gravity`` and ``tilt_deg``: the same under the tilts |ρ| <= τ of gravity.
    """
    if gravity is None:
        plan = plan_contacts(outline, mu=MU, mass=1.0, samples=samples, exact=pairs, com=com)
        load = Load(g=9.80665)
        head = "(c) exact along"
    else:
        plan = plan_contacts(
            outline,
            mu=MU,
            mass=1.0,
            samples=samples,
            exact=pairs,
            com=com,
            gravity=gravity,
            tilt=f"{tilt_deg}deg",
        )
        load = Load(g=9.80665, gravity=_unit(gravity), tau=math.radians(tilt_deg))
        head = f"(d) {name}, tilts of ±{tilt_deg:g}° of gravity {gravity}: exact along"
    ring = np.asarray(plan.outline)
    print(f"  {head} the {len(plan.exact)} best edge pairs (tolerance 1e-6):")
    for p in plan.exact:
        ea, eb = p.edges
        ep = EdgePair.of(ring[ea], ring[ea + 1], ring[eb], ring[eb + 1], plan.com, MU)
        t = []
        for _ in range(3):
            t0 = time.perf_counter()
            opt = refine_edge_pair(ep, load)
            t.append(time.perf_counter() - t0)
        t_bb = min(t)
        # the baseline: a uniform n × n grid, n doubled until within 1e-6 of the proof
        n, t0 = 64, time.perf_counter()
        while True:
            g = (np.arange(n) + 0.5) / n
            q = np.nanmin(edge_pair_values(ep, load, g[:, None], g[None, :]))
            if q <= opt.value * (1 + 1e-6) or n >= largest:
                break
            n *= 2
        t_grid = time.perf_counter() - t0
        reached = "within 1e-6" if q <= opt.value * (1 + 1e-6) else f"{q / opt.value - 1:.1e} above"
        print(
            f"      edges {ea:>2},{eb:>2}: {p.squeeze:.6f} N/kg (proved >= {p.lower_bound:.6f}, "
            f"{'certified' if opt.certified else 'NOT closed'}, {opt.boxes} boxes"
            f"{', on the boundary of (1)' if opt.on_boundary else ''}), best "
            f"sample {p.sampled_squeeze:.6f}: {100 * p.improvement:.2f}% less"
        )
        print(
            f"        branch and bound {t_bb * 1e3:7.1f} ms; grid {n}×{n} ({reached}) "
            f"{t_grid * 1e3:7.1f} ms; ratio grid/B&B = {t_grid / t_bb:.2f}"
        )


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    n = math.hypot(*v)
    return v[0] / n, v[1] / n


def _mm(c: tuple) -> str:
    return " – ".join(f"({x * 1e3:.1f}, {y * 1e3:.1f})" for x, y in c)


def _eps_of(plan: object, sel: np.ndarray, eps: np.ndarray, k: int) -> str:
    hit = np.flatnonzero(sel == k)
    return f"{eps[hit[0]]:.4f}" if hit.size else "not in the subsample"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="80 samples, ε on 1000 pairs")
    ap.add_argument("--samples", type=int, default=200)
    args = ap.parse_args()
    samples = 80 if args.quick else args.samples
    sub = 1000 if args.quick else None
    run("bracket.svg", read_outline(BRACKET), samples, sub)
    largest = 1024 if args.quick else 4096
    exact("bracket.svg", read_outline(BRACKET), samples, 2 if args.quick else 3, largest)
    run("plate 100 × 60 mm", PLATE, samples, sub)
    exact("plate", PLATE, samples, 2, largest)
    print("under a tilt range (plan --gravity X,Y --tilt ANGLE):")
    exact(
        "bracket.svg",
        read_outline(BRACKET),
        samples,
        2 if args.quick else 3,
        largest,
        gravity=(0.6, -0.8),
        tilt_deg=30,
    )
    exact(
        "trapeze 100/90 × 60 mm",
        TRAPEZE,
        samples,
        2,
        largest,
        gravity=(0.0, -1.0),
        tilt_deg=25,
        com=(0.01, 0.005),
    )


if __name__ == "__main__":
    main()
