"""Speed of ``certify`` against the per-fact baseline, measured in the same run.

For each construction (the symbolic μ and ξ constructions, the exact presets) it
times :func:`graspcompass.proof.certify` (the construction itself is built
first and not timed) and a baseline on the *same facts*:

* symbolic: :func:`graspcompass.proof.prove_identity` on every fact, one at a
  time, without certify's shortcuts (one ring, cached conversions, cleared
  denominators);
* exact numbers: ``sympy.simplify(lhs - rhs) == 0`` on every fact.

The baseline stops at ``--limit`` seconds per construction; a stopped baseline
prints its ratio as a lower bound (``>``).  ``--quick`` certifies the μ
construction and one preset only.

Usage::

    python bench/bench_certify.py [--quick] [--limit 120]
"""

from __future__ import annotations

import argparse
import time

import sympy as sp

from graspcompass import Grasp, internal_force_diagram
from graspcompass.proof import prove_identity
from graspcompass.proof.certify import certify
from graspcompass.proof.certify_facts import facts_for
from graspcompass.proof.certify_paper import paper_model


def _baseline(construction, limit: float) -> tuple[float, bool]:
    """Seconds of the per-fact baseline, and whether it finished within ``limit``."""
    model = paper_model(construction.grasp)
    symbolic = any(sp.sympify(v).free_symbols for v in model.values.values())
    env: dict = {}
    t0 = time.perf_counter()
    for step in construction.steps:
        for f in facts_for(step, env, model):
            if f.kind != "eq":
                continue
            if symbolic:
                prove_identity(f.lhs, f.rhs)
            else:
                sp.simplify(sp.sympify(f.lhs - f.rhs))
            if time.perf_counter() - t0 > limit:
                return time.perf_counter() - t0, False
        env[step.name] = step.obj
    return time.perf_counter() - t0, True


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="μ construction and fig6 only")
    ap.add_argument(
        "--limit",
        type=float,
        default=120.0,
        help="seconds after which the baseline of one construction stops",
    )
    args = ap.parse_args()
    cases = [
        ("symbolic μ", lambda: Grasp.symbolic("mu")),
        ("symbolic ξ", lambda: Grasp.symbolic("xi")),
    ]
    cases += [(p, lambda p=p: Grasp.preset(p)) for p in ("fig6", "table1a", "table1b", "table1c")]
    if args.quick:
        cases = [cases[0], cases[2]]
        args.limit = min(args.limit, 30.0)
    print(
        f"{'construction':12} {'steps':>5} {'build s':>8} {'certify s':>9} "
        f"{'baseline s':>10} {'ratio':>8}  verdicts"
    )
    for label, make in cases:
        t = time.perf_counter()
        c = internal_force_diagram(make())
        build = time.perf_counter() - t
        t = time.perf_counter()
        certs = certify(c)
        ours = time.perf_counter() - t
        base, finished = _baseline(c, args.limit)
        ratio = f"{'' if finished else '>'}{base / ours:.1f}x"
        verdicts = ",".join(sorted({x.result.status.value for x in certs}))
        print(
            f"{label:12} {len(c.steps):5d} {build:8.2f} {ours:9.2f} "
            f"{base:10.2f} {ratio:>8}  {verdicts}",
            flush=True,
        )


if __name__ == "__main__":
    main()
