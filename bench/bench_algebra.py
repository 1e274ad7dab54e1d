"""The exact algebra, candidates side by side (issue 20): sympy rings, flint, half-angle.

For random whole grasps (φ1, φ2, ξ1, ξ2 typed in degrees, lengths with one or two
decimals) the V_n of the exact construction are taken as data, and the heaviest
operation of the drawing — the second common points B_nm of the circles on O V_n and
O V_m (eq. (31); B = −(V_n × V_m)/|V_m − V_n|² · perp(V_m − V_n)) and the tangent of the
break angle, B_x / B_y — is computed with each candidate representation of the
numbers:

* ``sympy``: sparse polynomials of ``sympy.polys.rings`` in sin a, cos a (and √p), the
  fraction cancelled by sympy's gcd after every operation, the numerator reduced
  modulo sin² + cos² = 1 when that makes it shorter — the kernel's algebra before
  issue 20;
* ``flint``: the kernel's algebra now (``geometry.exact.Frac``: python-flint
  ``fmpq_mpoly``, the relations applied before any gcd, cross-cancelled products);
* ``half-angle``: the same flint fractions in t = tan(a/2) per angle (sin a =
  2t/(1 + t²), cos a = (1 − t²)/(1 + t²)): a field of rational functions with no
  relation at all, the fraction cancelled by its gcd (canonical).

It prints per candidate the median and slowest time and the median number of terms of
B's numerator and denominator; the ratio is against ``sympy`` (the baseline of the same
run).  The verdict is on the slowest grasp (a user's grasp is any grasp): the kernel
keeps ``flint``, whose slowest case is the fastest and whose values are the shortest
(the half-angle fractions, canonical as they are, run ten times longer: every later
step, the printed protocol and the floats of the drawing pay for that).

Run:  PYTHONPATH=src python bench/bench_algebra.py [--quick] [-n 30] [--seed 2]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

import sympy as sp

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from bench_whole_grasps import random_grasps

import graspcompass as gc
from graspcompass.geometry.exact import _MEMO, Frac
from graspcompass.geometry.trig import OpaqueCos, OpaqueSin


class SympyFrac:
    """A fraction of sympy ring elements with the pre-issue-20 canonical form."""

    def __init__(self, R, rels, n, d) -> None:
        self.R, self.rels, self.n, self.d = R, rels, n, d

    def _new(self, n, d) -> SympyFrac:
        n, d = n.cancel(d)
        if self.rels and n:
            nr = n.rem(self.rels)
            if len(nr) < len(n):
                n = nr
        return SympyFrac(self.R, self.rels, n, d)

    def __add__(self, o):
        return self._new(self.n * o.d + o.n * self.d, self.d * o.d)

    def __sub__(self, o):
        return self._new(self.n * o.d - o.n * self.d, self.d * o.d)

    def __mul__(self, o):
        return self._new(self.n * o.n, self.d * o.d)

    def __truediv__(self, o):
        return self._new(self.n * o.d, self.d * o.n)

    def __neg__(self):
        return SympyFrac(self.R, self.rels, -self.n, self.d)

    def size(self) -> tuple[int, int]:
        return len(self.n), len(self.d)


def _flint_size(f: Frac) -> tuple[int, int]:
    return len(f.n), len(f.d)


def _sympy_ring(values: list[sp.Expr]):
    """The sympy ring of the kernel's generators of ``values``, with the relations."""
    gens = sorted({g for v in values for g in _MEMO[v][0].symbols}, key=sp.default_sort_key)
    R, *G = sp.ring(gens, sp.QQ, sp.lex)
    index = dict(zip(gens, G))
    rels = [
        index[g] ** 2 + index[OpaqueCos(g.args[0])] ** 2 - 1
        for g in gens
        if isinstance(g, OpaqueSin) and OpaqueCos(g.args[0]) in index
    ]
    rels += [index[g] ** 2 - int(g.base) for g in gens if g.is_Pow]
    return R, rels


def _to_sympy(v: sp.Expr, R, rels) -> SympyFrac:
    ring, n, d = _MEMO[v]

    def conv(p):
        out = R.zero
        for monom, c in p.terms():
            term = R(sp.Rational(int(c.p), int(c.q)))
            for g, e in zip(ring.symbols, monom):
                if e:
                    term *= R(g) ** int(e)
            out += term
        return out

    return SympyFrac(R, rels, conv(n), conv(d))


def _half_angle(v: sp.Expr, table: dict) -> Frac:
    return Frac.of(gc.geometry.exact.canon(v.xreplace(table)))


def _breaks(V: list[tuple]) -> list:
    """B_nm for n < m and their B_x / B_y, in whatever arithmetic the V's are."""
    out = []
    for i in range(4):
        for j in range(i + 1, 4):
            (ax, ay), (bx, by) = V[i], V[j]
            wx, wy = bx - ax, by - ay
            k = (ax * by - ay * bx) / (wx * wx + wy * wy)
            Bx, By = k * wy, -(k * wx)
            try:
                out.append((Bx, By, Bx / By))
            except ZeroDivisionError:  # B on the x-axis: no tangent to compare
                out.append((Bx, By, Bx))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=30, help="random whole grasps (default 30)")
    ap.add_argument("--seed", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="8 grasps")
    args = ap.parse_args()
    grasps = random_grasps(8 if args.quick else args.n, args.seed)
    times: dict[str, list[float]] = {"sympy": [], "flint": [], "half-angle": []}
    sizes: dict[str, list[int]] = {k: [] for k in times}
    for p in grasps:
        c = gc.internal_force_diagram(gc.Grasp(**p))
        vals = [c[f"V{n}"] for n in (1, 2, 3, 4)]
        exprs = [e for v in vals for e in (v.x, v.y)]
        if not all(e in _MEMO for e in exprs):
            continue  # a rational V (no generator): nothing to compare
        R, rels = _sympy_ring(exprs)
        atoms = {a for e in exprs for a in e.atoms(OpaqueSin, OpaqueCos)}
        table, seen = {}, set()
        for a in atoms:
            arg = a.args[0]
            if arg in seen:
                continue
            seen.add(arg)
            t = sp.Symbol(f"t_{len(seen)}")
            table[OpaqueSin(arg)] = 2 * t / (1 + t**2)
            table[OpaqueCos(arg)] = (1 - t**2) / (1 + t**2)
        cases = {  # the V's in each representation (converting is not timed)
            "sympy": [(_to_sympy(v.x, R, rels), _to_sympy(v.y, R, rels)) for v in vals],
            "flint": [(Frac.of(v.x), Frac.of(v.y)) for v in vals],
            "half-angle": [(_half_angle(v.x, table), _half_angle(v.y, table)) for v in vals],
        }
        for name, V in cases.items():
            t0 = time.perf_counter()
            out = _breaks(V)
            if name != "sympy":
                out = [(bx.reduced(), by.reduced(), r.reduced()) for bx, by, r in out]
            times[name].append(time.perf_counter() - t0)
            size = (lambda f: f.size()) if name == "sympy" else _flint_size
            sizes[name].append(statistics.median(sum(size(b[0])) for b in out))
    base = statistics.median(times["sympy"])
    print(
        f"{len(times['sympy'])} random whole grasps (seed {args.seed}): the six B_nm and "
        "their tangents from V1..V4"
    )
    print(f"{'candidate':12} {'median s':>9} {'slowest s':>10} {'ratio':>7} {'terms of B':>11}")
    for name in times:
        med = statistics.median(times[name])
        print(
            f"{name:12} {med:9.4f} {max(times[name]):10.4f} {base / med:6.1f}x "
            f"{statistics.median(sizes[name]):11.0f}"
        )
    best = min(times, key=lambda k: max(times[k]))  # a user's grasp is any grasp: the slowest
    print(
        f"fastest on the slowest grasp: {best}; the kernel uses flint "
        f"({'target met' if best == 'flint' else 'target NOT met'})"
    )


if __name__ == "__main__":
    main()
