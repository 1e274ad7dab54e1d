"""The 2-D convex hull and the cone tests of Q, generic over an exact or a float sign.

Every predicate is the sign of an orientation determinant or of a dot product,
given by ``sgn``: :func:`~graspcompass.ncontact._signs.sign` (exact, through
``decide_sign``) or a float sign with a tolerance.  The code does the same
arithmetic on sympy expressions and on floats.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cmp_to_key
from typing import Any

__all__ = ["feasible_cone", "hull", "inside_cone", "open_cones_meet"]

Sgn = Callable[[Any, str], int]


def _cross(o: Sequence, a: Sequence, b: Sequence) -> Any:
    """det [o; a; b] of homogeneous points (X, Y, W): the orientation when all W > 0."""
    return (
        o[0] * (a[1] * b[2] - a[2] * b[1])
        - o[1] * (a[0] * b[2] - a[2] * b[0])
        + o[2] * (a[0] * b[1] - a[1] * b[0])
    )


def hull(points: Sequence[Sequence], sgn: Sgn) -> list[int]:
    """Indices of the strict vertices of the convex hull, counter-clockwise.

    Points are homogeneous ``(X, Y, W)`` with W > 0 (no quotient is formed).
    Andrew's monotone chain; equal points count once (the first index), points on
    an edge are not vertices.  One point gives ``[i]``, a segment its two ends.
    """

    def cmp(i: int, j: int) -> int:
        a, b = points[i], points[j]
        s = sgn(a[0] * b[2] - b[0] * a[2], "a difference of x coordinates")
        if s == 0:
            s = sgn(a[1] * b[2] - b[1] * a[2], "a difference of y coordinates")
        return s

    order = sorted(range(len(points)), key=cmp_to_key(cmp))
    uniq: list[int] = []
    for i in order:
        if not uniq or cmp(uniq[-1], i) != 0:
            uniq.append(i)
    if len(uniq) <= 2:
        return uniq

    def chain(seq: list[int]) -> list[int]:
        out: list[int] = []
        for i in seq:
            while (
                len(out) >= 2
                and sgn(
                    _cross(points[out[-2]], points[out[-1]], points[i]),
                    "an orientation determinant",
                )
                <= 0
            ):
                out.pop()
            out.append(i)
        return out

    lower, upper = chain(uniq), chain(uniq[::-1])
    h = lower[:-1] + upper[:-1]
    return h if len(h) >= 2 else uniq[:1] + uniq[-1:]


def inside_cone(x: Sequence, rays: Sequence[Sequence], sgn: Sgn) -> bool:
    """True when ``x·r < 0`` for every ray r: x points into the open feasible cone."""
    return all(
        sgn(x[0] * r[0] + x[1] * r[1], "a dot product with a recession direction") < 0 for r in rays
    )


def feasible_cone(rays: Sequence[Sequence], sgn: Sgn) -> tuple | None:
    """The cone ``{e : e·r <= 0 for all r}`` as ``(start, end)``, counter-clockwise.

    Returns None when it has no interior (the rays span a half-plane or more).
    With no rays the cone is the whole plane: ``()``.  Each orientation and dot
    product of a pair of rays is decided once.
    """
    if not rays:
        return ()
    crosses: dict[tuple[int, int], int] = {}
    dots: dict[tuple[int, int], int] = {}

    def cross(i: int, j: int) -> int:
        if i == j:
            return 0
        if (j, i) in crosses:
            return -crosses[(j, i)]
        if (i, j) not in crosses:
            a, r = rays[i], rays[j]
            crosses[(i, j)] = sgn(a[0] * r[1] - a[1] * r[0], "an orientation of two directions")
        return crosses[(i, j)]

    def dot(i: int, j: int) -> int:
        if i == j:
            return 1
        key = (min(i, j), max(i, j))
        if key not in dots:
            a, r = rays[i], rays[j]
            dots[key] = sgn(a[0] * r[0] + a[1] * r[1], "a dot product of two directions")
        return dots[key]

    def first(ccw: bool) -> int | None:
        for i in range(len(rays)):
            ok = True
            for j in range(len(rays)):
                c = cross(i, j) if ccw else -cross(i, j)
                if c < 0 or (c == 0 and dot(i, j) < 0):
                    ok = False
                    break
            if ok:
                return i
        return None

    ia = first(True)  # every ray is counter-clockwise of ra (within π)
    ib = first(False)  # every ray is clockwise of rb
    if ia is None or ib is None:
        return None
    ra, rb = rays[ia], rays[ib]
    # the rays span [ra, rb]; the feasible cone runs from J rb to J^T ra (J: quarter turn ccw)
    start = (-rb[1], rb[0])
    end = (ra[1], -ra[0])
    c = cross(ia, ib)  # start × end = ra × rb
    if c == 0:
        if ia == ib or dot(ia, ib) > 0:  # one ray direction: a half-plane
            return (start, end)
        return None
    return (start, end) if c > 0 else None


def _in_open(x: Sequence, cone: tuple, sgn: Sgn) -> bool:
    (a, b) = cone
    ca = sgn(a[0] * x[1] - a[1] * x[0], "an orientation")
    cb = sgn(x[0] * b[1] - x[1] * b[0], "an orientation")
    if sgn(a[0] * b[1] - a[1] * b[0], "an orientation") == 0:  # a half-plane
        return ca > 0
    return ca > 0 and cb > 0


def _same(a: Sequence, b: Sequence, sgn: Sgn) -> bool:
    return (
        sgn(a[0] * b[1] - a[1] * b[0], "an orientation") == 0
        and sgn(a[0] * b[0] + a[1] * b[1], "a dot product") > 0
    )


def open_cones_meet(c1: tuple, c2: tuple, sgn: Sgn) -> bool:
    """Whether the interiors of two planar cones ``(start, end)`` of width <= π meet.

    ``()`` is the whole plane.  Two open arcs of positive length meet iff one holds
    the other's start, or they start in the same direction.
    """
    if c1 == () or c2 == ():
        return True
    return _in_open(c2[0], c1, sgn) or _in_open(c1[0], c2, sgn) or _same(c1[0], c2[0], sgn)
