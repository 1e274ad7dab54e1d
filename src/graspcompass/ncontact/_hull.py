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
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def hull(points: Sequence[Sequence], sgn: Sgn) -> list[int]:
    """Indices of the strict vertices of the convex hull, counter-clockwise.

    Andrew's monotone chain; equal points count once (the first index), points on
    an edge are not vertices.  One point gives ``[i]``, a segment its two ends.
    """
    def cmp(i: int, j: int) -> int:
        s = sgn(points[i][0] - points[j][0], "a difference of x coordinates")
        if s == 0:
            s = sgn(points[i][1] - points[j][1], "a difference of y coordinates")
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
            while len(out) >= 2 and sgn(_cross(points[out[-2]], points[out[-1]], points[i]),
                                        "an orientation determinant") <= 0:
                out.pop()
            out.append(i)
        return out

    lower, upper = chain(uniq), chain(uniq[::-1])
    h = lower[:-1] + upper[:-1]
    return h if len(h) >= 2 else uniq[:1] + uniq[-1:]


def inside_cone(x: Sequence, rays: Sequence[Sequence], sgn: Sgn) -> bool:
    """True when ``x·r < 0`` for every ray r: x points into the open feasible cone."""
    return all(sgn(x[0] * r[0] + x[1] * r[1], "a dot product with a recession direction") < 0
               for r in rays)


def feasible_cone(rays: Sequence[Sequence], sgn: Sgn) -> tuple | None:
    """The cone ``{e : e·r <= 0 for all r}`` as ``(start, end)``, counter-clockwise.

    Returns None when it has no interior (the rays span a half-plane or more).
    With no rays the cone is the whole plane: ``()``.
    """
    if not rays:
        return ()
    def first(cands: Sequence[Sequence], ccw: bool) -> Sequence | None:
        for a in cands:
            ok = True
            for r in rays:
                c = sgn(a[0] * r[1] - a[1] * r[0], "an orientation of recession directions")
                c = c if ccw else -c
                if c < 0 or (c == 0 and sgn(a[0] * r[0] + a[1] * r[1], "a dot product") < 0):
                    ok = False
                    break
            if ok:
                return a
        return None

    ra = first(rays, True)   # every ray is counter-clockwise of ra (within π)
    rb = first(rays, False)  # every ray is clockwise of rb
    if ra is None or rb is None:
        return None
    # the rays span [ra, rb]; the feasible cone runs from J rb to J^T ra (J: quarter turn ccw)
    start = (-rb[1], rb[0])
    end = (ra[1], -ra[0])
    if sgn(start[0] * end[1] - start[1] * end[0], "the feasible cone's width") == 0 and \
            sgn(start[0] * end[0] + start[1] * end[1], "the feasible cone's width") < 0:
        # a half-plane (one ray direction): interior nonempty
        return (start, end)
    if sgn(start[0] * end[1] - start[1] * end[0], "the feasible cone's width") <= 0:
        return None
    return (start, end)


def _in_open(x: Sequence, cone: tuple, sgn: Sgn) -> bool:
    (a, b) = cone
    ca = sgn(a[0] * x[1] - a[1] * x[0], "an orientation")
    cb = sgn(x[0] * b[1] - x[1] * b[0], "an orientation")
    if sgn(a[0] * b[1] - a[1] * b[0], "an orientation") == 0:  # a half-plane
        return ca > 0
    return ca > 0 and cb > 0


def _same(a: Sequence, b: Sequence, sgn: Sgn) -> bool:
    return (sgn(a[0] * b[1] - a[1] * b[0], "an orientation") == 0
            and sgn(a[0] * b[0] + a[1] * b[1], "a dot product") > 0)


def open_cones_meet(c1: tuple, c2: tuple, sgn: Sgn) -> bool:
    """Whether the interiors of two planar cones ``(start, end)`` of width <= π meet.

    ``()`` is the whole plane.  Two open arcs of length <= π meet iff one holds the
    other's start, or they have the same ends.
    """
    if c1 == () or c2 == ():
        return True
    return (_in_open(c2[0], c1, sgn) or _in_open(c1[0], c2, sgn)
            or (_same(c1[0], c2[0], sgn) and _same(c1[1], c2[1], sgn)))
