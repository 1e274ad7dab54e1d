"""Q for the sublinear effort ``max_i N_i`` (the largest normal force).

The least largest normal force is ``v(θ) = F_e max { -y_f·e : f(y) <= 1 }`` with
``f(y) = Σ_i max(0, g_{i+}·y, g_{i-}·y)`` (the dual of ``min t, N_i <= t``, its
multipliers z_i eliminated).  ``f`` is convex, piecewise linear and positively
homogeneous, so a vertex of ``{f <= 1}`` lies on a line through the origin where
two *ties* hold (two of the three values of a contact equal and largest: the
planes ``g_{i+}·y = 0``, ``g_{i-}·y = 0``, ``(g_{i+} - g_{i-})·y = 0``): the
candidates are ``y = d / f(d)`` for ``d = ±h_1 × h_2`` with both ties valid at d.
Non-vertices among them project inside Q and are dropped by the hull.  Exact
signs throughout (``decide_sign``); the float path uses a tolerance.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any

import numpy as np

from ..geometry.exact import canon
from .polygon import exact_sgn

if TYPE_CHECKING:
    from .model import NContactGrasp

__all__ = ["candidates"]


def _ties(G: list[tuple]) -> list[tuple[int, str, tuple, tuple]]:
    """``(contact, name, h, other)``: the tie plane h·y = 0 and the third value's normal."""
    out = []
    zero = tuple(0 * v for v in G[0])
    for i in range(len(G) // 2):
        gp, gm = G[2 * i], G[2 * i + 1]
        out.append((i, "+0", gp, gm))  # g+·y = 0 >= g-·y
        out.append((i, "-0", gm, gp))  # g-·y = 0 >= g+·y
        out.append((i, "+-", tuple(a - b for a, b in zip(gp, gm)), zero))  # g+ = g- >= 0
    return out


def _cross(a: tuple, b: tuple) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a: tuple, b: tuple) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def candidates(g: NContactGrasp) -> tuple[list[tuple], list[tuple]]:
    """Homogeneous points ``(X, Y, W)`` (q = -y_f) of the candidate vertices, and their ties."""
    G = [tuple(w) for w in g.wrenches()]
    ties = _ties(G)
    labels = [f"P{i + 1}{name}" for i, name, _, _ in ties]
    if g.numeric:
        return _float(G, ties)
    points, bases = [], []
    for a, b in itertools.combinations(range(len(ties)), 2):
        d0 = tuple(canon(v) for v in _cross(ties[a][2], ties[b][2]))
        if all(exact_sgn(v, "a tie line") == 0 for v in d0):
            continue
        for sg in (1, -1):
            d = tuple(sg * v for v in d0)
            ok = True
            for t in (a, b):
                i, name, _h, other = ties[t]
                # the tied value (g+·d or 0) must be >= the third value of contact i
                tied = _dot(G[2 * i], d) if name in ("+0", "+-") else 0
                third = _dot(other, d) if name != "+-" else 0
                if exact_sgn(tied - third, "a tie's validity") < 0:
                    ok = False
                    break
            if not ok:
                continue
            f = 0
            for i in range(len(G) // 2):
                lp, lm = canon(_dot(G[2 * i], d)), canon(_dot(G[2 * i + 1], d))
                m = lp if exact_sgn(lp - lm, "a comparison") >= 0 else lm
                if exact_sgn(m, "a normal force's sign") > 0:
                    f = f + m
            f = canon(f)
            if exact_sgn(f, "the effort of a direction") <= 0:
                continue  # a recession direction, not a vertex
            points.append((canon(-d[0]), canon(-d[1]), f))  # q = (X, Y) / W, W = f > 0
            bases.append((labels[a], labels[b]))
    return points, bases


def _float(G: list[tuple], ties: list) -> tuple[list[tuple], list[tuple]]:
    A = np.array(G, dtype=float)
    scale = np.abs(A).max()
    points, bases = [], []
    Gp, Gm = A[0::2], A[1::2]
    for a, b in itertools.combinations(range(len(ties)), 2):
        ia, ib = ties[a][0], ties[b][0]
        if ia == ib:  # the three tie planes of one contact share one line, through g+ and g-:
            # one cross product for the three pairs, so they give one point bit for bit (from
            # h_a x h_b each rounds its own way: q = -d/f(d) carries an error ~eps |q|^2,
            # 8e-11 apart at |q| = 728, and a copy of a vertex was listed as redundant)
            d0 = np.cross(Gp[ia], Gm[ia])
        else:
            d0 = np.cross(np.array(ties[a][2], float), np.array(ties[b][2], float))
        nd = np.linalg.norm(d0)
        if nd <= 1e-12 * scale**2:
            continue
        d0 = d0 / nd
        for sg in (1.0, -1.0):
            d = sg * d0
            lp, lm = Gp @ d, Gm @ d
            mx = np.maximum(0.0, np.maximum(lp, lm))
            tol = 1e-9 * scale
            ok = True
            for t in (a, b):
                i, name, _, _ = ties[t]
                tied = lp[i] if name in ("+0", "+-") else 0.0
                if tied < mx[i] - tol:
                    ok = False
            if not ok:
                continue
            f = mx.sum()
            if f <= tol:
                continue
            points.append((-d[0] / f, -d[1] / f, 1.0))
            bases.append((a, b))
    return points, bases
