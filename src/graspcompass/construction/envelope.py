"""The outer envelope of the four circles: k_grasp(θ) as arcs (eq. (25), Fig. 5).

In the direction e(θ) the polar graph of k_n is the circle on the diameter
O V_n (Thales, eq. (31)); k_grasp(θ) = max(k_1, ..., k_4, 0) is the outermost
circle, and the origin O where every k_n(θ) ≤ 0.  The arcs' break points are
the second intersections of two circles (where k_n = k_m > 0) or O (where the
largest k_n falls to 0).

Which circle wins where is decided in high precision (mpmath, ``_DPS`` digits)
from the values of V_n: every angle where two k's are equal (e(θ) ⊥ V_n − V_m)
or one k is zero (e(θ) ⊥ V_n) is a candidate break angle, and the winner of
each interval between candidates is the largest k at its midpoint.  A float
V_n is taken as the exact binary number it is, so circles that nearly (or
exactly) coincide are ordered correctly and no arc runs backwards.

*Exact V_n* (exact grasps): the break points are the construction's exact
second intersections ``Bnm`` (or O), and the angles are exact.

*Float V_n* (float grasps): the break points are computed, not taken from the
construction (the intersection of two nearly coincident circles is
ill-conditioned in double precision): at the break angle θ the point is
k(θ) e(θ), on both circles to rounding.  Arcs shorter than ``_FLOAT_MERGE``
(1e-13 rad) are merged into their neighbours, which changes k_grasp by at most
2e-13 max|V_n|; so the float arcs partition [θ0, θ0 + 2π) in strictly
increasing double angles, and :meth:`Envelope.k` equals max(k_1..k_4, 0) of the
envelope's own V_n to about 1e-13 max|V_n| (measured: a few 1e-16).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from itertools import combinations
from typing import TYPE_CHECKING, Any

import mpmath
import sympy as sp

from ..boundary.errors import GraspCompassError
from ..geometry import Point, angle_of
from ..geometry.exact import (
    Frac,
    NotAFraction,
    canon,
    decide_sign,
    decide_zero,
    free,
    has_float,
)
from ..geometry.numeric import to_float
from ..grasp._floatpath import mpf

if TYPE_CHECKING:
    import numpy as np
else:
    from ..boundary._numpy import np

__all__ = ["Arc", "Envelope", "EnvelopeError", "outer_envelope"]

_TWO_PI = 2 * math.pi
#: Working digits of the winner decisions.
_DPS = 40
#: Digits tried in turn when an exact break point does not check at fewer (cancellation
#: between V_n of very different size, e.g. x1 = 10**300).
_PRECISIONS = (_DPS, 160, 640, 2600)
#: Candidate angles closer than this (rad) are one break angle (exact V_n).
_EXACT_MERGE = 1e-25
#: Float arcs shorter than this (rad) are merged into their neighbours.
_FLOAT_MERGE = 1e-13


class EnvelopeError(GraspCompassError):
    """The construction's break point does not lie at the computed break angle."""


@dataclass(frozen=True)
class Arc:
    """One piece of the envelope, for θ from ``theta_start`` to ``theta_end``.

    ``n`` is the index of the circle (1-4) that is outermost there, or 0 for
    the zero region where every k_n(θ) ≤ 0 and the envelope stays at O.
    ``0 <= theta_start < 2π`` and ``theta_start < theta_end <= theta_start + 2π``;
    ``start`` and ``end`` are the envelope points there.  Angles and points are
    exact for exact V_n, sympy Floats (double precision) for float V_n.
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
    """The polar graph of k_grasp(θ) as a cyclic list of arcs, in increasing θ."""

    arcs: tuple[Arc, ...]
    V: tuple[Point, ...]

    @property
    def breakpoints(self) -> tuple[Point, ...]:
        """The points where the outermost circle changes (O included)."""
        return tuple(a.start for a in self.arcs)

    @property
    def zero_region(self) -> tuple[tuple[sp.Expr, sp.Expr], ...]:
        """The θ intervals where k_grasp(θ) = 0."""
        return tuple((a.theta_start, a.theta_end) for a in self.arcs if a.is_zero)

    def winner(self, theta: Any) -> np.ndarray:
        """Index of the outermost circle (0 in the zero region) for numeric θ."""
        t = np.mod(np.asarray(theta, dtype=float), _TWO_PI)
        starts = np.array([_float(a.theta_start) for a in self.arcs])
        ns = np.array([a.n for a in self.arcs])
        order = np.argsort(starts)
        idx = np.searchsorted(starts[order], t, side="right") - 1
        return ns[order][idx]  # idx == -1 wraps to the last arc, as it should

    def k(self, theta: Any) -> np.ndarray:
        """k_grasp(θ) read off the envelope (numeric), for checking against eq. (25)."""
        t = np.asarray(theta, dtype=float)
        w = self.winner(t)
        S = np.array([0.0] + [_float(v.x) for v in self.V])
        C = np.array([0.0] + [_float(v.y) for v in self.V])
        return S[w] * np.sin(t) - C[w] * np.cos(t)

    def polyline(self, samples: int = 720) -> np.ndarray:
        """Points ``(x, y)`` along the envelope, shape ``(samples, 2)``, for drawing."""
        t = np.linspace(0.0, _TWO_PI, samples)
        r = self.k(t)
        return np.column_stack([r * np.sin(t), -r * np.cos(t)])


def _angle(vector: Point, approx: Any = None) -> sp.Expr:
    """Exact θ in [0, 2π) with e(θ) along ``vector``.

    ``approx`` (θ in [0, 2π) from mpmath) decides the branch without evaluating
    the exact arctangent, unless θ is within 1e-20 of π.
    """
    a = angle_of(vector)  # in (−π, π]
    if approx is not None and abs(approx - mpmath.pi) > 1e-20:
        negative = approx > mpmath.pi
    else:
        negative = decide_sign(a) == -1
    # angle_of returns atan(canonical) + kπ, already in canonical form; only a
    # symbolic angle (atan2 of expressions) needs the canonical form again
    exact = canon if free(a) else (lambda e: e)
    return exact(a + 2 * sp.pi) if negative else exact(a)


def _float(value: Any) -> float:
    """``float(value)`` of an exact number from its canonical form (sympy's evalf of a
    long exact expression takes seconds)."""
    return to_float(value, 20)


def _parallel(p: Point, e: Point) -> bool:
    """Whether the exact vectors ``p`` and ``e`` are parallel (cross product 0, decided)."""
    try:
        fx, fy, gx, gy = (Frac.of(v) for v in (p.x, p.y, e.x, e.y))
    except NotAFraction:
        return bool(decide_zero(p.x * e.y - p.y * e.x))
    return bool((fx * gy - fy * gx).is_zero())


def numeric_point(p: Point) -> bool:
    """True when a coordinate of ``p`` holds a float."""
    return has_float(p.x) or has_float(p.y)


def _plus_2pi(angle: sp.Expr) -> sp.Expr:
    return canon(angle + 2 * sp.pi) if free(angle) else angle + 2 * sp.pi


def _theta(wx: mpmath.mpf, wy: mpmath.mpf) -> mpmath.mpf:
    """θ in [0, 2π) with e(θ) = (sin θ, −cos θ) along ``(wx, wy)``."""
    return mpmath.atan2(wx, -wy) % (2 * mpmath.pi)


def _ks(Vm: list[tuple[mpmath.mpf, mpmath.mpf]], t: mpmath.mpf) -> list[mpmath.mpf]:
    """``[0, k_1(θ), .., k_4(θ)]`` with k_n = S_n sin θ − C_n cos θ (32)."""
    s, c = mpmath.sin(t), mpmath.cos(t)
    return [mpmath.mpf(0)] + [x * s - y * c for x, y in Vm]


def _breaks(Vm: list[tuple[mpmath.mpf, mpmath.mpf]], merge: float) -> list[tuple[Any, int, int]]:
    """The break angles in increasing order: ``(θ, winner before, winner after)``.

    Candidates are the angles with e(θ) ⊥ V_n (k_n = 0) and e(θ) ⊥ V_n − V_m
    (k_n = k_m); between two neighbouring candidates the order of the k's does
    not change, so the midpoint decides the winner (ties: the lowest index).
    """
    cands = []
    for key in [(n,) for n in range(4)] + list(combinations(range(4), 2)):
        wx = Vm[key[0]][0] - (Vm[key[1]][0] if len(key) == 2 else 0)
        wy = Vm[key[0]][1] - (Vm[key[1]][1] if len(key) == 2 else 0)
        if wx or wy:
            t = _theta(-wy, wx)  # e ⊥ w: e = ±(−wy, wx)
            cands += [t, (t + mpmath.pi) % (2 * mpmath.pi)]
    cands.sort()
    cuts: list[Any] = []
    for t in cands:
        if not cuts or t - cuts[-1] > merge:
            cuts.append(t)
    if len(cuts) > 1 and cuts[0] + 2 * mpmath.pi - cuts[-1] <= merge:
        cuts.pop()
    if not cuts:  # every V_n = O: k_grasp = 0 everywhere
        return []
    m = len(cuts)
    Vf = [(float(x), float(y)) for x, y in Vm]
    clear = 1e-12 * max(1.0, *(abs(x) + abs(y) for x, y in Vf))
    win = []
    for i in range(m):
        b = cuts[i + 1] if i + 1 < m else cuts[0] + 2 * mpmath.pi
        mid = (cuts[i] + b) / 2
        # in double precision when the largest k leads by far more than rounding
        s, c = math.sin(float(mid)), math.cos(float(mid))
        kf = sorted(
            [(0.0, 0), *((x * s - y * c, -n) for n, (x, y) in enumerate(Vf, 1))], reverse=True
        )
        if kf[0][0] - kf[1][0] > clear:
            win.append(-kf[0][1])
            continue
        ks = _ks(Vm, mid)
        win.append(max(range(5), key=lambda n: (ks[n], -n)))
    return [(cuts[i], win[i - 1], win[i]) for i in range(m) if win[i - 1] != win[i]]


def _merge_short(breaks: list[tuple[Any, int, int]], tol: float) -> list[tuple[Any, int, int]]:
    """Drop arcs shorter than ``tol`` (rad): the neighbours meet at the first break."""
    out = list(breaks)
    while len(out) > 2:
        m = len(out)
        lengths = [(out[(j + 1) % m][0] - out[j][0]) % (2 * mpmath.pi) for j in range(m)]
        j = min(range(m), key=lambda j: lengths[j])
        if lengths[j] >= tol:
            break
        t, before, _ = out[j]
        after = out[(j + 1) % m][2]
        drop = {j, (j + 1) % m}
        rest = [b for i, b in enumerate(out) if i not in drop]
        if before != after:
            rest.append((t, before, after))
        out = sorted(rest, key=lambda b: b[0])
    return out


def _float_arcs(
    Vm: list[tuple[mpmath.mpf, mpmath.mpf]], breaks: list[tuple[Any, int, int]]
) -> list[Arc]:
    points = []
    for t, a, b in breaks:
        if a == 0 or b == 0:
            points.append(Point(0, 0))
            continue
        ks = _ks(Vm, t)
        k = max((ks[a] + ks[b]) / 2, 0)
        points.append(
            Point(sp.Float(float(k * mpmath.sin(t))), sp.Float(float(-k * mpmath.cos(t))))
        )
    thetas = [sp.Float(float(t)) for t, _, _ in breaks]
    m = len(breaks)
    return [
        Arc(
            breaks[j][2],
            thetas[j],
            thetas[j + 1] if j + 1 < m else sp.Float(float(breaks[0][0] + 2 * mpmath.pi)),
            points[j],
            points[(j + 1) % m],
        )
        for j in range(m)
    ]


def _gap(a: Any, b: Any) -> Any:
    """Distance of two angles on the circle (mpmath)."""
    return abs((a - b + mpmath.pi) % (2 * mpmath.pi) - mpmath.pi)


def _exact_arcs(
    objects: Mapping[str, Any], V: tuple[Point, ...], breaks: list[tuple[Any, int, int]]
) -> list[Arc]:
    found = []  # (θ numeric, θ exact, point)
    for t, a, b in breaks:
        lo, hi = sorted((a, b))
        p = objects.get(f"B{lo}{hi}") if lo else None
        # the break lies at the angle with e(θ) ⊥ w = V_lo − V_hi (eq. (32): k_lo = k_hi),
        # of the two the one the numeric break angle found: B_lo,hi, the foot of O on the
        # line V_lo V_hi, is a multiple of perp(w), so its angle is that of ±perp(w) (a
        # far smaller exact number than B's own coordinates); where the largest k falls
        # to 0 (or the circles touch at O) the break is O, at the same angle
        w = V[hi - 1] if not lo else V[lo - 1] - V[hi - 1]
        e = w.perp()
        te = _theta(mpf(e.x, mpmath.mp.dps), mpf(e.y, mpmath.mp.dps))
        if _gap(te, t) > mpmath.pi / 2:
            e, te = -e, (te + mpmath.pi) % (2 * mpmath.pi)
        if p is not None and not (p.x == 0 and p.y == 0):
            tp = _theta(mpf(p.x, mpmath.mp.dps), mpf(p.y, mpmath.mp.dps))
            if _gap(tp, t) > 1e-20 or _gap(tp, te) > 1e-20:
                raise EnvelopeError(
                    f"B{lo}{hi} = {p} lies at θ = {mpmath.nstr(tp, 17)}, not at the break "
                    f"angle {mpmath.nstr(t, 17)} where k{lo} = k{hi} is largest"
                )
            # e's angle is B's exactly when B is a multiple of e (a file's own B need not be)
            along = not numeric_point(p) and _parallel(p, e)
            found.append((tp, _angle(e if along else p, tp), p))
            continue
        found.append((te, _angle(e, te), Point(0, 0)))
    # sorted by the angles themselves: a break just below 2π comes last
    order = sorted(range(len(found)), key=lambda j: found[j][0])
    m = len(order)
    arcs = []
    for j, i in enumerate(order):
        nxt = order[(j + 1) % m]
        t1 = found[nxt][1] if j + 1 < m else _plus_2pi(found[nxt][1])
        arcs.append(Arc(breaks[i][2], found[i][1], t1, found[i][2], found[nxt][2]))
    return arcs


def outer_envelope(objects: Mapping[str, Any]) -> Envelope:
    """The envelope of the circles on O V_n, from the named construction objects.

    Uses ``V1``..``V4`` and, for exact V_n, the second intersections ``Bnm`` of
    the construction as the exact break points.

    Raises
    ------
    EnvelopeError
        If an exact ``Bnm`` is not at the break angle computed from the V_n (a
        construction that does not match its own V_n), or a V_n is missing.

    Examples
    --------
    Two cone sides through O make V3 = V4 to rounding (x1 ≠ x2): the arcs still
    run forwards and cover the circle once.

    >>> import math
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> g = Grasp(1.0, 2.0, 1.0, 1.4, 1.5, mu1=math.tan(1.4 - math.atan(1.0)),
    ...           mu2=math.tan(1.5 - math.atan(2.0)))
    >>> env = internal_force_diagram(g)["envelope"]
    >>> all(float(a.theta_end) > float(a.theta_start) for a in env.arcs)
    True
    >>> round(sum(float(a.theta_end - a.theta_start) for a in env.arcs) / math.pi, 12)
    2.0
    """
    missing = [f"V{n}" for n in (1, 2, 3, 4) if not isinstance(objects.get(f"V{n}"), Point)]
    if missing:
        raise EnvelopeError(
            f"the envelope is drawn from the four points V1..V4 (eq. (25)): "
            f"{', '.join(missing)} missing (a step with role V n, or named "
            "so, for each of them)"
        )
    V = tuple(objects[f"V{n}"] for n in (1, 2, 3, 4))
    numeric = any(has_float(c) for v in V for c in (v.x, v.y))
    for dps in _PRECISIONS:  # exact V_n of very different sizes need more digits
        try:
            return _envelope(objects, V, numeric, dps)
        except EnvelopeError:
            if numeric or dps == _PRECISIONS[-1]:
                raise
    raise AssertionError("unreachable")  # pragma: no cover


def _envelope(
    objects: Mapping[str, Any], V: tuple[Point, ...], numeric: bool, dps: int
) -> Envelope:
    with mpmath.workdps(dps):
        Vm = [(mpf(v.x, dps), mpf(v.y, dps)) for v in V]
        breaks = _breaks(Vm, _EXACT_MERGE)
        if numeric:
            breaks = _merge_short(breaks, _FLOAT_MERGE)
        if not breaks:  # k_grasp = 0 everywhere (or one circle: impossible for V ≠ O)
            o = Point(0, 0)
            return Envelope((Arc(0, sp.Integer(0), 2 * sp.pi, o, o),), V)
        arcs = _float_arcs(Vm, breaks) if numeric else _exact_arcs(objects, V, breaks)
    return Envelope(tuple(arcs), V)
