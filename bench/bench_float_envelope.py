"""Accuracy and speed of the float path (issue 9) on hard random float grasps.

Random grasps (seeded) of four kinds: two cone sides of different contacts
through O (V_n ≈ V_m: near-coincident circles, offsets 0..1e-8 rad), a cone side
vertical (φ ± ξ = 0 or π, to rounding), a cone side within 10^-16.5..10^-4 rad of
horizontal (a bound of condition (1)), and generic.  For each grasp the reference
is the closed form (28)-(39) evaluated with mpmath at 50 digits on the exact
binary values of the floats.  Reported:

* refusals: InvalidGraspError where a margin of (1) is below 1e-12 of its bound,
  and any refusal above it or any other exception (should be none);
* ``k_grasp``: max |k_grasp(θ) − max(k_n, 0)| / max|V_n| on 721 angles;
* construction: max |V_n − V_n ref| / (ε max|V_n| / min|cos(φ ± ξ)|), the
  constant K of the stated accuracy K ε / min|cos(φ ± ξ)|;
* envelope: max |Envelope.k(θ) − max(k_n, 0) of the envelope's own V_n| / max|V_n|,
  arcs running backwards, break points off their circles;
* time of ``outer_envelope`` and of ``internal_force_diagram`` (median).

Target: no wrong number (every accepted grasp within the stated accuracy), K < 8,
envelope error < 1e-12 max|V_n|, no backwards arc.

Run:  PYTHONPATH=src python bench/bench_float_envelope.py [--quick] [-n 300]
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

import mpmath
import numpy as np
import sympy as sp

from graspcompass import Grasp, internal_force_diagram
from graspcompass.construction import outer_envelope
from graspcompass.grasp import InvalidGraspError

EPS = 2.0**-52
HALF_PI = math.pi / 2


def _mp(v: float) -> mpmath.mpf:
    return mpmath.mpf(sp.Float(v, 60))


def reference(x1, x2, y, phi1, phi2, mu1, mu2):
    """S_n, C_n (28)-(39) in the μ form of (23), 50 digits; min |cos(φ ± ξ)|; margin."""
    with mpmath.workdps(50):
        h = (_mp(x1) + _mp(x2)) / 2
        S, C, cosines, margin = [], [], [], math.inf
        for n in (1, 2, 3, 4):
            phi, mu = (_mp(phi1), _mp(mu1)) if n in (1, 3) else (_mp(phi2), _mp(mu2))
            s, c, sg = mpmath.sin(phi), mpmath.cos(phi), 1 if n in (1, 2) else -1
            t = (s + sg * c * mu) / (c - sg * s * mu)
            S.append(float((-h + _mp(y) * t) if n in (1, 3) else (h - _mp(y) * t)))
            C.append(float((_mp(x2) if n in (1, 3) else _mp(x1)) * t))
            a = phi + sg * mpmath.atan(mu)
            cosines.append(float(abs(mpmath.cos(a))))
            lo, hi = (
                (mpmath.pi / 2, 3 * mpmath.pi / 2) if sg == 1 else (-mpmath.pi / 2, mpmath.pi / 2)
            )
            margin = min(margin, float((a - lo) / abs(lo)), float((hi - a) / abs(hi)))
    return np.array(S), np.array(C), min(cosines), margin


def contact(a: float, upper: bool, u: float):
    if upper:
        lo, hi = max(0.0, a - math.pi, (a - HALF_PI) / 2), min(HALF_PI, a, (a + HALF_PI) / 2)
    else:
        lo, hi = max(0.0, -a, (HALF_PI - a) / 2), min(HALF_PI, math.pi - a, (3 * HALF_PI - a) / 2)
    if hi - lo < 1e-3:
        return None
    xi = lo + (hi - lo) * u
    return (a - xi if upper else a + xi), xi


def random_grasp(rng: np.random.Generator):
    kind = rng.choice(["coincident", "vertical", "horizontal", "generic"])
    x1, x2, y = rng.uniform(0.2, 3), rng.uniform(0.2, 3), rng.uniform(0.1, 3)
    up1, up2 = bool(rng.integers(2)), bool(rng.integers(2))
    tiny = [0.0, 1e-16, -1e-16, 1e-14, -1e-12, 1e-10, -1e-8]
    a2 = rng.uniform(-1.4, 1.4) + (math.pi if up2 else 0.0)
    if kind == "coincident":
        a1 = math.atan(x1 / y) + (math.pi if up1 else 0.0) + rng.choice(tiny)
        a2 = math.atan(x2 / y) + (math.pi if up2 else 0.0) + rng.choice(tiny)
    elif kind == "vertical":
        a1 = (math.pi if up1 else 0.0) + rng.choice(tiny)
    elif kind == "horizontal":
        m = 10.0 ** rng.uniform(-16.5, -4) * (1 if rng.random() < 0.75 else -1)
        low, high = (HALF_PI, 3 * HALF_PI) if up1 else (-HALF_PI, HALF_PI)
        a1 = low + m if rng.random() < 0.5 else high - m
    else:
        a1 = rng.uniform(-1.4, 1.4) + (math.pi if up1 else 0.0)
    c1, c2 = contact(a1, up1, rng.uniform(0.05, 0.95)), contact(a2, up2, rng.uniform(0.05, 0.95))
    if not (c1 and c2) or not (0 < c1[0] <= math.pi and 0 < c2[0] <= math.pi):
        return None
    return kind, (x1, x2, y, c1[0], c2[0], math.tan(c1[1]), math.tan(c2[1]))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="100 grasps")
    ap.add_argument("-n", type=int, default=300, help="number of grasps")
    ap.add_argument("--seed", type=int, default=9)
    args = ap.parse_args()
    n = 100 if args.quick else args.n
    rng = np.random.default_rng(args.seed)
    ts = np.linspace(0, 2 * np.pi, 721)
    counts = dict(accepted=0, refused=0, wrong_refusal=0, not_refused=0, other_error=0, backwards=0)
    worst_kg = worst_env = worst_K = worst_on = 0.0
    t_env, t_diag = [], []
    kinds: dict[str, int] = {}
    done = 0
    while done < n:
        got = random_grasp(rng)
        if got is None:
            continue
        done += 1
        kind, p = got
        kinds[str(kind)] = kinds.get(str(kind), 0) + 1
        S, C, cmin, margin = reference(*p)
        try:
            g = Grasp(*p[:5], mu1=p[5], mu2=p[6])
            t0 = time.perf_counter()
            c = internal_force_diagram(g)
            t_diag.append(time.perf_counter() - t0)
        except InvalidGraspError:
            counts["refused" if margin < 1e-12 else "wrong_refusal"] += 1
            continue
        except Exception:  # anything else is a failure of the float path
            counts["other_error"] += 1
            continue
        if margin < 1e-12:
            counts["not_refused"] += 1
        counts["accepted"] += 1
        Vmax = float(np.hypot(S, C).max())
        want = np.maximum((np.outer(S, np.sin(ts)) - np.outer(C, np.cos(ts))).max(axis=0), 0)
        worst_kg = max(worst_kg, float(np.abs(g.k_grasp(ts) - want).max()) / Vmax)
        V = [c[f"V{k}"] for k in (1, 2, 3, 4)]
        Vf = np.array([[float(v.x), float(v.y)] for v in V])
        err = float(np.hypot(Vf[:, 0] - S, Vf[:, 1] - C).max())
        worst_K = max(worst_K, err / (EPS * Vmax / cmin))
        env = c["envelope"]
        own = np.maximum(
            (np.outer(Vf[:, 0], np.sin(ts)) - np.outer(Vf[:, 1], np.cos(ts))).max(axis=0), 0
        )
        worst_env = max(worst_env, float(np.abs(env.k(ts) - own).max()) / Vmax)
        for a in env.arcs:
            if float(a.theta_end) <= float(a.theta_start):
                counts["backwards"] += 1
            if a.n:
                vx, vy = Vf[a.n - 1]
                for q in (a.start, a.end):
                    qx, qy = float(q.x), float(q.y)
                    worst_on = max(worst_on, abs(qx * (qx - vx) + qy * (qy - vy)) / Vmax**2)
        objs = {s.name: s.obj for s in c.steps}
        t0 = time.perf_counter()
        outer_envelope(objs)
        t_env.append(time.perf_counter() - t0)
    print(f"{n} random float grasps (seed {args.seed}): {kinds}")
    print(f"outcomes: {counts}")
    print(f"{'quantity':<58} {'measured':>10}")
    print("-" * 70)
    print(f"{'k_grasp: max |k_grasp − closed form| / max|V_n|':<58} {worst_kg:10.2e}")
    print(f"{'construction: K in |ΔV_n| <= K ε max|V_n| / min|cos(φ±ξ)|':<58} {worst_K:10.2f}")
    print(f"{'envelope: max |Envelope.k − max(k_n, 0)| / max|V_n|':<58} {worst_env:10.2e}")
    print(f"{'break points: max |q·(q − V_n)| / max|V_n|²':<58} {worst_on:10.2e}")
    print(f"{'outer_envelope, float, median':<58} {statistics.median(t_env) * 1e3:7.2f} ms")
    print(
        f"{'internal_force_diagram, float, median':<58} {statistics.median(t_diag) * 1e3:7.2f} ms"
    )
    ok = (
        counts["wrong_refusal"] == counts["not_refused"] == counts["backwards"] == 0
        and counts["other_error"] == 0
        and worst_K < 8
        and worst_env < 1e-12
        and worst_kg < 1e-14
    )
    print("target met" if ok else "target NOT met")


if __name__ == "__main__":
    main()
