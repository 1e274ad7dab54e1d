"""The instruments of the construction as data: compass arcs, right-angle marks, guides.

Part of the one picture model (:mod:`graspcompass.scene`), read by every painter
(issue 23).  What the ruler and the compass did to make a point, found from the
steps' operations, never their names:

``bisection_arc`` and ``bisector``
    The bisection of a ``midpoint`` step A B: arcs of radius AB about A and
    about B cross at two points, the line through them meets A B at the midpoint.
``measure_arc``
    A ``signed_length`` A B: the compass opened from A to B (a short arc through B).
``transfer_arc``
    A ``point_from_lengths`` V: each length laid off from O on its axis, to the
    foot of V on that axis (a short arc about O through the foot).
``coordinate``
    From those feet to V, perpendicular to the axes: why V_n is where it is.
``drop``
    The perpendicular dropped from P onto a line (a ``foot`` step).
``right_angle``
    A small square at the foot of every perpendicular (``foot`` and
    ``perpendicular`` steps; at the feet of the coordinates of V_n too).

Each :class:`Instrument` belongs to the step it shows (``step``: that step's name),
so that :meth:`graspcompass.scene.picture.Scene.upto` cuts it with its step.
Nothing here imports matplotlib.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

__all__ = ["ROLES", "Instrument", "in_view", "instruments_of"]

XY = tuple[float, float]
Box = tuple[float, float, float, float]

#: The roles of the instruments, in drawing order.
ROLES = (
    "bisection_arc",
    "bisector",
    "measure_arc",
    "transfer_arc",
    "coordinate",
    "drop",
    "right_angle",
)


@dataclass(frozen=True)
class Instrument:
    """One stroke of an instrument: a polyline ``points`` in the frame of the paper.

    ``role`` is one of :data:`ROLES`; ``step`` the name of the step it belongs to;
    ``n`` that step's index of the paper (1 without one).
    """

    role: str
    step: str
    n: int
    points: tuple[XY, ...]


def _unit(v: XY) -> XY | None:
    r = math.hypot(*v)
    return None if r == 0 or not math.isfinite(r) else (v[0] / r, v[1] / r)


def _arc(c: XY, r: float, through: XY, half: float, samples: int = 13) -> tuple[XY, ...]:
    """A short arc about ``c`` of radius ``r`` through ``through``, ``half`` radians
    either side of it."""
    t0 = math.atan2(through[1] - c[1], through[0] - c[0])
    ts = [t0 - half + 2 * half * k / (samples - 1) for k in range(samples)]
    return tuple((c[0] + r * math.cos(t), c[1] + r * math.sin(t)) for t in ts)


def _square(at: XY, u: XY, w: XY, a: float) -> tuple[XY, ...]:
    """The right-angle mark at ``at`` between the unit directions ``u`` and ``w``."""
    return (
        (at[0] + a * u[0], at[1] + a * u[1]),
        (at[0] + a * (u[0] + w[0]), at[1] + a * (u[1] + w[1])),
        (at[0] + a * w[0], at[1] + a * w[1]),
    )


def in_view(instruments: tuple[Instrument, ...], scale: float) -> tuple[Instrument, ...]:
    """The instruments as drawn in a view ``scale`` times the diagram's width.

    A zoomed inset has ``scale`` < 1: its right-angle marks are shrunk by ``scale``
    about their corners, so that they keep the size they have on screen in the diagram
    (the marks are sized by the diagram's view, :func:`instruments_of`); every other
    stroke lies on the geometry and is kept.  Every painter draws an inset with it.

    Examples
    --------
    >>> mark = Instrument("right_angle", "Y1", 1, ((1.0, 0.0), (1.0, 1.0), (0.0, 1.0)))
    >>> in_view((mark,), 0.5)[0].points
    ((0.5, 0.0), (0.5, 0.5), (0.0, 0.5))
    """
    if scale == 1.0:
        return instruments
    out = []
    for ins in instruments:
        if ins.role == "right_angle" and len(ins.points) == 3:
            (ax, ay), (bx, by), (cx, cy) = ins.points
            kx, ky = ax + cx - bx, ay + cy - by  # the corner: the foot of the perpendicular
            pts = tuple((kx + scale * (x - kx), ky + scale * (y - ky)) for x, y in ins.points)
            ins = Instrument(ins.role, ins.step, ins.n, pts)
        out.append(ins)
    return tuple(out)


def _foot(p: XY, line: Any) -> XY:
    (qx, qy), d = line
    u = _unit(d) or (1.0, 0.0)
    t = (p[0] - qx) * u[0] + (p[1] - qy) * u[1]
    return qx + t * u[0], qy + t * u[1]


def _inside(p: XY, box: Box) -> bool:
    return box[0] <= p[0] <= box[1] and box[2] <= p[1] <= box[3]


def instruments_of(construction: Any, num: Mapping[str, Any], box: Box) -> tuple[Instrument, ...]:
    """The instruments of every step of ``construction`` (numbers ``num``, view ``box``).

    Marks are sized by the view: a right-angle square 1.6 % of its width, a short
    arc about 7 % long (at most 25° either side).  A length of (nearly) zero or a
    foot outside the view gets no mark.
    """
    span = box[1] - box[0]
    tiny = 1e-9 * span
    mark = 0.016 * span
    steps = {s.name: s for s in construction.steps}
    out: list[Instrument] = []

    def arc(role: str, s: Any, c: XY, through: XY) -> None:
        r = math.dist(c, through)
        if r > tiny and _inside(through, box):
            half = min(math.radians(25), 0.035 * span / r)
            out.append(Instrument(role, s.name, _n(s), _arc(c, r, through, half)))

    def square(s: Any, at: XY, toward_a: XY, toward_b: XY) -> None:
        u = _unit((toward_a[0] - at[0], toward_a[1] - at[1]))
        w = _unit((toward_b[0] - at[0], toward_b[1] - at[1]))
        if u is not None and w is not None and _inside(at, box):
            out.append(Instrument("right_angle", s.name, _n(s), _square(at, u, w, mark)))

    for s in construction.steps:
        ins: list[Any] = [num.get(k) for k in s.inputs]
        if s.op == "midpoint" and len(ins) == 2:
            a, b = ins
            d = math.dist(a, b)
            if d <= tiny:
                continue
            m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            u = ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
            h = d * math.sqrt(3) / 2  # circles of radius |AB| about A and B
            cross = [(m[0] - sg * h * u[1], m[1] + sg * h * u[0]) for sg in (1, -1)]
            for q in cross:
                for c in (a, b):
                    arc("bisection_arc", s, c, q)
            out.append(Instrument("bisector", s.name, 1, tuple(cross)))
        elif s.op == "foot" and len(ins) == 2:
            p, foot = ins[0], num[s.name]
            if math.dist(p, foot) <= tiny:
                continue
            out.append(Instrument("drop", s.name, _n(s), (p, foot)))
            along = _unit(ins[1][1])
            if along is not None:
                toward_o = -1.0 if (foot[0] * along[0] + foot[1] * along[1]) > 0 else 1.0
                side = (foot[0] + toward_o * along[0], foot[1] + toward_o * along[1])
                square(s, foot, p, side)
        elif s.op == "perpendicular" and len(ins) == 2:
            line, p = ins
            foot = _foot(p, line)
            if math.dist(p, foot) <= tiny:
                continue
            along = _unit(line[1])
            if along is None:
                continue
            square(s, foot, p, (foot[0] + along[0], foot[1] + along[1]))
        elif s.op == "signed_length" and len(ins) >= 2:
            arc("measure_arc", s, ins[0], ins[1])
        elif s.op == "point_from_lengths" and len(ins) == 2:
            v = num[s.name]
            for k in s.inputs:
                length = steps.get(k)
                if length is None or len(length.inputs) < 3:
                    continue
                axis = num.get(length.inputs[2])
                if axis is None:
                    continue
                q = _foot(v, axis)
                origin = axis[0]
                arc("transfer_arc", s, origin, q)
                if math.dist(q, v) > tiny:
                    out.append(Instrument("coordinate", s.name, _n(s), (q, v)))
                    if _unit(axis[1]) is not None and math.dist(q, origin) > tiny:
                        back = (
                            q[0] + (origin[0] - q[0]) / math.dist(q, origin),
                            q[1] + (origin[1] - q[1]) / math.dist(q, origin),
                        )
                        square(s, q, v, back)
    return tuple(out)


def _n(step: Any) -> int:
    n = getattr(step, "n", ())
    return int(n[0]) if n else 1
