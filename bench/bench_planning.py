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

BRACKET = Path(__file__).resolve().parents[1] / "docs" / "_static" / "outlines" / "bracket.svg"
PLATE = [(-0.05, -0.03), (0.05, -0.03), (0.05, 0.03), (-0.05, 0.03)]
MU = 0.5


def ferrari_canny(points: np.ndarray, normals: np.ndarray, a: np.ndarray, b: np.ndarray,
                  com: tuple[float, float], mu: float, rho: float) -> np.ndarray:
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
        plan = plan_contacts(outline, mu=MU, mass=1.0, samples=samples)
        t.append(time.perf_counter() - t0)
    n_pairs = len(plan.i)
    per_a = min(t) / n_pairs
    ring = plan.outline
    rho = float(np.max(np.hypot(ring[:, 0] - plan.com[0], ring[:, 1] - plan.com[1])))
    sel = np.arange(n_pairs) if fc_pairs is None else np.random.default_rng(0).choice(
        n_pairs, min(fc_pairs, n_pairs), replace=False)
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
    print(f"{name}: {len(plan.points)} contacts, {n_pairs} pairs, "
          f"{int(plan.force_closure.sum())} force-closure (μ = {MU})")
    print(f"  (a) worst-case squeeze, vectorised: {per_a * 1e6:8.3f} µs/pair "
          f"({1 / per_a:,.0f} pairs/s, {min(t) * 1e3:.1f} ms for all)")
    print(f"  (b) Ferrari–Canny ε, qhull per pair: {per_b * 1e6:8.1f} µs/pair "
          f"(on {len(sel)} pairs) — {per_b / per_a:,.0f}× (a)")
    print(f"  force closure: the two agree on {agree} of {len(sel)} pairs")
    print(f"  rankings over {int(both.sum())} force-closure pairs: Spearman ρ(−squeeze, ε) = "
          f"{rho_s:.3f}; top-10 overlap {len(top_a & top_b)}/10")
    pa, pb = plan.pair(int(plan.order[0])), plan.pair(best_b)
    print(f"  best by squeeze: {pa.squeeze:.3f} N/kg at {_mm(pa.contacts)}; best by ε: "
          f"{pb.squeeze:.3f} N/kg at {_mm(pb.contacts)} "
          f"(ε = {eps[sel == best_b][0]:.4f} vs {_eps_of(plan, sel, eps, int(plan.order[0]))})")


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
    run("plate 100 × 60 mm", PLATE, samples, sub)


if __name__ == "__main__":
    main()
