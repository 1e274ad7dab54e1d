"""Baseline for the bench scripts: the internal force diagram drawn with ``sympy.geometry``.

This replays the ruler-and-compass construction of the two-point grasp internal force
diagram (Ito, Tanaka, Sasaki, Robotica 2012) the way a typical user of ``sympy.geometry``
would write it (Point, Line, Circle and their methods, no shortcuts).  It is deliberately
*not* optimised: bench scripts time ``graspcompass`` against it.

Frame: O=(0,0) is the object's CoM, contacts P1=(x1, y) and P2=(-x2, y); the friction-cone
side lines n=1,3 pass through P1 and n=2,4 through P2.
"""

from __future__ import annotations

import multiprocessing as mp
import time
from itertools import combinations
from typing import Any

from sympy import Expr, Rational, Symbol, cos, pi, simplify, sin, sqrt, tan
from sympy.geometry import Circle, Line, Point


def _directions(phi1: Expr, phi2: Expr, mu1: Expr, mu2: Expr) -> dict[int, tuple[Expr, Expr]]:
    s1, c1, s2, c2 = sin(phi1), cos(phi1), sin(phi2), cos(phi2)
    return {
        1: (-(s1 + c1 * mu1), -(c1 - s1 * mu1)),
        2: ((s2 + c2 * mu2), -(c2 - s2 * mu2)),
        3: (-(s1 - c1 * mu1), -(c1 + s1 * mu1)),
        4: ((s2 - c2 * mu2), -(c2 + s2 * mu2)),
    }


def replay(
    x1: Expr,
    x2: Expr,
    y: Expr,
    phi1: Expr,
    phi2: Expr,
    mu1: Expr,
    mu2: Expr,
    *,
    circles: bool = True,
) -> dict[str, object]:
    """Run the drawing steps with ``sympy.geometry``; return the named constructed objects."""
    out: dict[str, object] = {}
    # 1. frame and contacts
    O = Point(0, 0)  # noqa: E741
    xaxis = Line(O, Point(1, 0))
    yaxis = Line(O, Point(0, 1))
    P1 = Point(x1, y)
    P2 = Point(-x2, y)
    # 2. friction-cone side lines
    sides = {
        n: Line(P, P + Point(*d))
        for n, d in _directions(phi1, phi2, mu1, mu2).items()
        for P in [P1 if n in (1, 3) else P2]
    }
    # 3. feet of the contacts on the x-axis and their midpoint
    P1x = xaxis.projection(P1)
    P2x = xaxis.projection(P2)
    OM = P1x.midpoint(P2x)
    out["OM"] = OM
    # 4. X_n, Y_n, V_n
    V: dict[int, Point] = {}
    for n in (1, 2, 3, 4):
        Xn = sides[n].intersection(xaxis)[0]
        perp = sides[n].perpendicular_line(P2x if n in (1, 3) else P1x)
        Yn = perp.intersection(yaxis)[0]
        V[n] = Point(-(Xn.x - OM.x), -(Yn.y))
        out[f"X{n}"], out[f"Y{n}"], out[f"V{n}"] = Xn, Yn, V[n]
    if not circles:
        return out
    # 5. circles on the diameters O V_n
    C = {n: Circle(O.midpoint(V[n]), O.distance(V[n]) / 2) for n in V}
    for n, c in C.items():
        out[f"circle{n}"] = c
    # 6. pairwise intersections (all circles pass through O)
    for n, m in combinations(C, 2):
        out[f"circle{n}&circle{m}"] = C[n].intersection(C[m])
    return out


FIG6: dict[str, Expr] = dict(
    x1=sqrt(3) / 2,
    x2=sqrt(3) / 2,
    y=Rational(1, 2),
    phi1=pi / 3,
    phi2=pi / 3,
    mu1=tan(pi / 4),
    mu2=tan(pi / 3),
)


def symbolic_params() -> dict[str, Expr]:
    """Fully symbolic parameters (same keys as FIG6)."""
    pos = dict(positive=True)
    return dict(
        x1=Symbol("x1", **pos),
        x2=Symbol("x2", **pos),
        y=Symbol("y", **pos),
        phi1=Symbol("phi1", real=True),
        phi2=Symbol("phi2", real=True),
        mu1=Symbol("mu1", **pos),
        mu2=Symbol("mu2", **pos),
    )


def _timed(params: dict[str, Expr], circles: bool) -> tuple[float, dict[str, Any]]:
    t0 = time.perf_counter()
    res = replay(**params, circles=circles)
    return time.perf_counter() - t0, res


def _symbolic_circles_child(q: Any) -> None:
    dt, _ = _timed(symbolic_params(), circles=True)
    q.put(dt)


def _assert_point(p: Any, expected: tuple[Expr, Expr]) -> None:
    assert simplify(p.x - expected[0]) == 0 and simplify(p.y - expected[1]) == 0, (p, expected)


if __name__ == "__main__":
    dt, fig = _timed(FIG6, circles=True)
    print(f"FIG6 replay (circles=True): {dt:.3f} s")
    for k in ("V1", "V2", "V3", "V4"):
        print(f"  {k} = {fig[k]}")
    _assert_point(fig["V1"], (-1 - sqrt(3), Rational(-3, 2) - sqrt(3)))
    _assert_point(fig["V2"], (sqrt(3), Rational(-3, 2)))
    print("  FIG6 V1, V2 match hand-derived values")

    sp = symbolic_params()
    dt, sym = _timed(sp, circles=False)
    print(f"symbolic replay (circles=False): {dt:.3f} s")
    for k in ("V1", "V2", "V3", "V4"):
        print(f"  {k} = {sym[k]}")
    s1, c1 = sin(sp["phi1"]), cos(sp["phi1"])
    T1 = (s1 + c1 * sp["mu1"]) / (c1 - s1 * sp["mu1"])
    t0 = time.perf_counter()
    _assert_point(sym["V1"], (-(sp["x1"] + sp["x2"]) / 2 + sp["y"] * T1, sp["x2"] * T1))
    print(f"  symbolic V1 matches closed form (simplify took {time.perf_counter() - t0:.3f} s)")

    limit = 120
    q: Any = mp.Queue()
    proc = mp.Process(target=_symbolic_circles_child, args=(q,))
    proc.start()
    proc.join(limit)
    if proc.is_alive():
        proc.terminate()
        proc.join()
        print(f"symbolic replay (circles=True): did not finish in {limit} s")
    else:
        print(f"symbolic replay (circles=True): {q.get():.3f} s")
