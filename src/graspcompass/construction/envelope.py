"""The outer envelope of the four circles: k_grasp(θ) as exact arcs (eq. (25), Fig. 5).

In the direction e(θ) the polar graph of k_n is the circle on the diameter
O V_n (Thales, eq. (31)); k_grasp(θ) = max(k_1, ..., k_4, 0) is the outermost
circle, and the origin O where every k_n(θ) ≤ 0.  The arcs' break points are
the second intersections of two circles (where k_n = k_m > 0) or O (where the
largest k_n falls to 0).  Which circle wins on which interval is decided by
evaluation at interval midpoints (to 30 significant digits); the break points
and their angles are exact.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from itertools import combinations
from typing import Any

import numpy as np
import sympy as sp

from ..geometry import Point, angle_of
from ..geometry.exact import canon, decide_sign

__all__ = ["Arc", "Envelope", "outer_envelope"]

_TWO_PI = 2 * np.pi
_PREC = 30


@dataclass(frozen=True)
class Arc:
    """One piece of the envelope, for θ from ``theta_start`` to ``theta_end``.

    ``n`` is the index of the circle (1-4) that is outermost there, or 0 for
    the zero region where every k_n(θ) ≤ 0 and the envelope stays at O.  Angles
    are exact, ``0 <= theta_start < 2π`` and ``theta_start < theta_end <=
    theta_start + 2π``; ``start`` and ``end`` are the exact envelope points.
    """

    n: int
    theta_start: sp.Expr
    theta_end: sp.Expr
    start: Point
    end: Point

    @property
    def is_zero(self) -> bool:
        """True for the zero region (k_grasp = 0)."""
        return self.n == 0


@dataclass(frozen=True)
class Envelope:
    """The polar graph of k_grasp(θ) as a cyclic list of exact arcs."""

    arcs: tuple[Arc, ...]
    V: tuple[Point, ...]

    @property
    def breakpoints(self) -> tuple[Point, ...]:
        """The exact points where the outermost circle changes (O included)."""
        return tuple(a.start for a in self.arcs)

    @property
    def zero_region(self) -> tuple[tuple[sp.Expr, sp.Expr], ...]:
        """The θ intervals where k_grasp(θ) = 0."""
        return tuple((a.theta_start, a.theta_end) for a in self.arcs if a.is_zero)

    def winner(self, theta: Any) -> np.ndarray:
        """Index of the outermost circle (0 in the zero region) for numeric θ."""
        t = np.mod(np.asarray(theta, dtype=float), _TWO_PI)
        starts = np.array([float(a.theta_start) for a in self.arcs])
        ns = np.array([a.n for a in self.arcs])
        order = np.argsort(starts)
        idx = np.searchsorted(starts[order], t, side="right") - 1
        return ns[order][idx]  # idx == -1 wraps to the last arc, as it should

    def k(self, theta: Any) -> np.ndarray:
        """k_grasp(θ) read off the envelope (numeric), for checking against eq. (25)."""
        t = np.asarray(theta, dtype=float)
        w = self.winner(t)
        S = np.array([0.0] + [float(v.x) for v in self.V])
        C = np.array([0.0] + [float(v.y) for v in self.V])
        return S[w] * np.sin(t) - C[w] * np.cos(t)

    def polyline(self, samples: int = 720) -> np.ndarray:
        """Points ``(x, y)`` along the envelope, shape ``(samples, 2)``, for drawing."""
        t = np.linspace(0.0, _TWO_PI, samples)
        r = self.k(t)
        return np.column_stack([r * np.sin(t), -r * np.cos(t)])


def _angle(vector: Point) -> sp.Expr:
    """Exact θ in [0, 2π) with e(θ) along ``vector``."""
    a = angle_of(vector)
    return canon(a + 2 * sp.pi) if decide_sign(a) == -1 else canon(a)


def _f(expr: sp.Expr) -> float:
    return float(sp.N(expr, _PREC))


def outer_envelope(objects: Mapping[str, Any]) -> Envelope:
    """The envelope of the circles on O V_n, from the named construction objects.

    Uses ``V1``..``V4`` and the second intersections ``Bnm`` of the construction.
    """
    V = tuple(objects[f"V{n}"] for n in (1, 2, 3, 4))
    Vf = [(_f(v.x), _f(v.y)) for v in V]
    # candidate angles (floats): where two k's are equal, or where one k is zero; each
    # remembers the vector w it is perpendicular to (index n, or the pair a, b)
    cands: list[tuple[float, tuple[int, ...], int]] = []
    for key in [(n,) for n in range(4)] + list(combinations(range(4), 2)):
        wx = Vf[key[0]][0] - (Vf[key[1]][0] if len(key) == 2 else 0.0)
        wy = Vf[key[0]][1] - (Vf[key[1]][1] if len(key) == 2 else 0.0)
        if wx or wy:
            for sign in (1, -1):  # e = ±perp(w) = ±(-wy, wx), θ = atan2(e.x, -e.y)
                cands.append((float(np.mod(np.arctan2(-sign * wy, -sign * wx), _TWO_PI)),
                              key, sign))
    cands.sort(key=lambda c: c[0])
    cuts: list[tuple[float, tuple[int, ...], int]] = []
    for cand in cands:
        if not cuts or cand[0] - cuts[-1][0] > 1e-12:
            cuts.append(cand)

    def best(t: float) -> int:
        s, c = np.sin(t), np.cos(t)
        ks = [0.0] + [x * s - y * c for x, y in Vf]
        return int(np.argmax(ks))  # ties go to the lowest index

    m = len(cuts)
    winners = []
    for i in range(m):
        a, b = cuts[i][0], cuts[(i + 1) % m][0] + (_TWO_PI if i + 1 == m else 0.0)
        winners.append(best((a + b) / 2))
    # boundaries between different winners: cut i separates interval i-1 and i
    bounds = [i for i in range(m) if winners[i - 1] != winners[i]]
    origin = Point(0, 0)

    def exact_direction(i: int) -> Point:
        _, key, sign = cuts[i]
        w = V[key[0]] if len(key) == 1 else V[key[0]] - V[key[1]]
        return w.perp() if sign == 1 else -w.perp()

    def point_at(i: int) -> tuple[sp.Expr, Point]:
        a, b = sorted((winners[i - 1], winners[i]))
        p = objects.get(f"B{a}{b}") if a else None
        if p is None:  # the largest k falls to 0 here (or tangent circles): the break is O
            return _angle(exact_direction(i)), origin
        return _angle(p), p

    exact = {i: point_at(i) for i in bounds}
    arcs = []
    for j, i in enumerate(bounds):
        nxt = bounds[(j + 1) % len(bounds)]
        t0, p0 = exact[i]
        t1, p1 = exact[nxt]
        if cuts[nxt][0] <= cuts[i][0]:  # the arc wraps past θ = 2π
            t1 = canon(t1 + 2 * sp.pi)
        arcs.append(Arc(winners[i], t0, t1, p0, p1))
    return Envelope(tuple(arcs), V)
