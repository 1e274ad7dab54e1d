"""The camera of a construction animation: the view follows the step being drawn.

For each step a target box is found from the geometry (the step's object and the
points it is made from, padded, at least :data:`LEAST` of the whole view, square,
inside the whole view); the whole view when the target would be nearly as large.
During a step's drawing the camera glides from the last target to the new one
(centre linearly, size geometrically, eased); it rests while the step rests and
shows the whole diagram in the final hold.  So it zooms in on X3, Y3, V3 of
Fig. 6, near O, and out for V1.  After the hold it zooms on the crowded region of the
finished diagram, rests there and comes back (:data:`ZOOM`).  Private to
:mod:`graspcompass.render.animate`.
"""

from __future__ import annotations

import math
from typing import Any

from .timeline import smoothstep

Box = tuple[float, float, float, float]

#: Least side of a target box, as a fraction of the whole view's.
LEAST = 0.35
#: A target larger than this fraction of the whole view is the whole view.
WHOLE = 0.75
#: Padding round a step's points, as a fraction of their extent (and of LEAST).
PAD = 0.35
#: The final zoom on the crowded region (an ``"inset"`` segment): the fractions of its
#: frames gliding in and gliding back out; the camera rests on the region between.
ZOOM = {"in": 0.25, "out": 0.15}


def _is_xy(v: Any) -> bool:
    return isinstance(v, tuple) and len(v) == 2 and all(isinstance(c, float) for c in v)


def _points_of(step: Any, num: dict[str, Any], steps: dict[str, Any]) -> list[Any] | None:
    """The points a step's view must hold; None for the whole view."""
    v: Any = num.get(step.name)
    if step.kind == "envelope" or step.role == "axis":
        return None
    pts: list[Any] = []
    if step.kind == "circle":
        (cx, cy), r = v
        return [(cx - r, cy - r), (cx + r, cy + r)]
    if _is_xy(v):
        pts.append(v)
    for k in step.inputs:
        w: Any = num.get(k)
        if _is_xy(w):
            pts.append(w)
        elif step.kind != "point" or step.op == "meet":
            if isinstance(w, tuple) and len(w) == 2 and _is_xy(w[0]) and _is_xy(w[1]):
                pts.append(w[0])  # a line: its anchor point
        if k in steps and steps[k].kind == "length":
            pts += [num[j] for j in steps[k].inputs[:2] if _is_xy(num.get(j))]
    if step.op == "point_from_lengths" and _is_xy(v):
        pts += [(v[0], 0.0), (0.0, v[1]), (0.0, 0.0)]
    return pts or None


def _fit(pts: list[Any] | None, whole: Box) -> Box:
    if pts is None:
        return whole
    span = whole[1] - whole[0]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    ext = max(max(xs) - min(xs), max(ys) - min(ys))
    side = max(ext * (1 + 2 * PAD), LEAST * span)
    if side >= WHOLE * span or not math.isfinite(side):
        return whole
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    h = side / 2
    cx = min(max(cx, whole[0] + h), whole[1] - h)
    cy = min(max(cy, whole[2] + h), whole[3] - h)
    return cx - h, cx + h, cy - h, cy + h


def step_boxes(
    construction: Any, num: dict[str, Any], whole: Box, instruments: Any = ()
) -> list[Box]:
    """The camera's target box of every step of ``construction`` (whole view ``whole``);
    a step's ``instruments`` (the scene's compass arcs of a bisection) are in its box."""
    steps = {s.name: s for s in construction.steps}
    out: list[Box] = []
    span = whole[1] - whole[0]
    for s in construction.steps:
        pts = _points_of(s, num, steps)
        if pts is not None:
            pts += [p for i in instruments if i.step == s.name for p in i.points]
        box = _fit(pts, whole)
        if out and box != whole and out[-1] != whole and _holds(out[-1], pts, span):
            box = out[-1]  # the last view still frames this step well: the camera rests
        out.append(box)
    return out


def _holds(box: Box, pts: list[Any] | None, span: float) -> bool:
    """Whether ``box`` holds ``pts`` with a margin and is not much larger than they need."""
    if pts is None:
        return False
    m = 0.05 * (box[1] - box[0])
    inside = all(box[0] + m <= p[0] <= box[1] - m and box[2] + m <= p[1] <= box[3] - m for p in pts)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    need = max(max(xs) - min(xs), max(ys) - min(ys), LEAST * span / (1 + 2 * PAD))
    return inside and (box[1] - box[0]) <= 1.6 * need * (1 + 2 * PAD)


def zoomed(raw: float) -> bool:
    """Whether the final zoom's labels show at linear progress ``raw`` of an ``"inset"``
    segment: from half way in to half way out."""
    return ZOOM["in"] / 2 <= raw <= 1.0 - ZOOM["out"] / 2


def _between(a: Box, b: Box, t: float) -> Box:
    """Box ``a`` glided to ``b`` by ``t`` in [0, 1]: centre linear, size geometric."""
    if t <= 0.0 or a == b:
        return a
    if t >= 1.0:
        return b
    ca = ((a[0] + a[1]) / 2, (a[2] + a[3]) / 2)
    cb = ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2)
    wa, wb = a[1] - a[0], b[1] - b[0]
    ha, hb = a[3] - a[2], b[3] - b[2]
    w, h = wa * (wb / wa) ** t, ha * (hb / ha) ** t
    # the centre moves with the size so that the zoom is smooth
    s = (w - wa) / (wb - wa) if abs(wb - wa) > 1e-12 * wa else t
    cx, cy = ca[0] + s * (cb[0] - ca[0]), ca[1] + s * (cb[1] - ca[1])
    return cx - w / 2, cx + w / 2, cy - h / 2, cy + h / 2


def camera_box(
    boxes: list[Box], whole: Box, step: int, kind: str, raw: float, zoom: Box | None = None
) -> Box:
    """Where the camera looks at a frame of ``step`` of ``kind`` at linear progress ``raw``:
    gliding during the first 60 % of the drawing, resting after; the whole in the hold;
    in an ``"inset"`` segment from the whole to ``zoom`` and back (:data:`ZOOM`)."""
    if kind == "inset" and zoom is not None:
        go, back = ZOOM["in"], ZOOM["out"]
        if raw < go:
            return _between(whole, zoom, smoothstep(raw / go))
        if raw <= 1.0 - back:
            return zoom
        return _between(zoom, whole, smoothstep((raw - 1.0 + back) / back))
    if kind in ("hold", "title", "inset"):
        return whole
    prev = boxes[step - 1] if step > 0 else whole
    if kind != "draw":
        return boxes[step]
    return _between(prev, boxes[step], smoothstep(min(1.0, raw / 0.6)))
