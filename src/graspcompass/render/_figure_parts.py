"""The objects of a figure drawn one by one: the givens (object outline, friction
cones), the instruments, the lines and the lengths (helpers of
:func:`~graspcompass.render.figure.draw_construction`)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import Polygon, Rectangle

from ..scene.layout import clip_line, clip_segment, shape_extent
from .theme import Theme

if TYPE_CHECKING:
    from ..construction.protocol import Construction, Step
    from ..scene.picture import Scene

__all__: list[str] = []


def box_patch(box: Any, **style: Any) -> Rectangle:
    """The rectangle of ``box`` ``(xmin, xmax, ymin, ymax)`` (the frame of the paper), styled:
    an object's outline, the dashed square of an inset or a zoom."""
    return Rectangle((box[0], box[2]), box[1] - box[0], box[3] - box[2], **style)


def _n(step: Step) -> int:
    """The index that goes with a step's role (``role circle 3`` -> 3); 1 without one."""
    n = getattr(step, "n", ())
    return int(n[0]) if n else 1


def _by_role(construction: Construction, role: str) -> dict[int, str]:
    """n -> name of the steps with ``role`` (the contacts, the cone sides), as data."""
    return {_n(s): s.name for s in construction.steps if getattr(s, "role", "") == role}


def _draw_givens(
    ax: Axes, construction: Construction, scene: Scene, theme: Theme, out: dict[str, list[Artist]]
) -> None:
    """The object outline and the friction cones, shaded towards the object (Fig. 2).

    The cones are the scene's (:attr:`Scene.cones`, between the cone sides i and
    i + 2 found by their roles), drawn once both sides are made.
    """
    grasp = construction.grasp
    shape = getattr(grasp, "shape", None)
    ext = shape_extent(shape)
    style: dict[str, Any] = dict(
        facecolor=theme.object_face, edgecolor=theme.object_edge, lw=theme.line_width, zorder=0.5
    )
    if ext is not None and shape:  # (ext is not None only for a shape)
        kind = shape[0]
        patch = (
            CirclePatch((0.0, 0.0), ext[1], **style)
            if kind == "circle"
            else box_patch(ext, **style)
        )
        out["object"] = [ax.add_patch(patch)]
    for i, cone in enumerate(scene.cones, start=1):
        if not scene.visible(f"cone{i}"):
            continue
        poly = Polygon(
            np.asarray(cone),
            closed=True,
            facecolor=theme.cone_face,
            alpha=theme.cone_alpha,
            edgecolor="none",
            zorder=1,
            label="friction cones" if i == 1 else "_nolegend_",
        )
        out[f"cone{i}"] = [ax.add_patch(poly)]


#: The instruments' looks (:mod:`graspcompass.scene.instruments`): thin, under the points, in
#: colours of at least 3 : 1 against white (a dimmed copy keeps it: render/_anim_ink.py).
_INSTRUMENT_STYLE: dict[str, dict[str, Any]] = {
    "bisector": dict(ls=(0, (1, 2))),
    "coordinate": dict(ls=(0, (1, 1.5))),
    "drop": dict(ls=(0, (4, 2))),
}


def _corner() -> Any:
    from matplotlib.path import Path

    return Path([(0.0, 1.0), (0.0, 0.0), (1.0, 0.0)], [Path.MOVETO, Path.LINETO, Path.LINETO])


_CORNER = _corner()


def _draw_instruments(
    ax: Axes, scene: Scene, theme: Theme, out: dict[str, list[Artist]], zoom: float | None = None
) -> None:
    """The scene's compass arcs, right-angle marks and the guides of V_n, thin and faint.

    Each artist goes with the step it belongs to (its gid ``instrument:ROLE``), so
    that a picture cut at a step, and the animation, show it with that step.
    ``zoom``: the points per unit of a zoomed view (:meth:`Scene.instruments_at`).
    """
    for ins in scene.instruments_at(zoom):
        xy = np.asarray(ins.points, dtype=float)
        color = theme.circle_color(ins.n) if ins.role == "coordinate" else theme.construction_color
        kw: dict[str, Any] = dict(
            color=color, lw=theme.thin_width, zorder=2.3, solid_capstyle="butt"
        )
        kw.update(_INSTRUMENT_STYLE.get(ins.role, {}))
        (art,) = ax.plot(xy[:, 0], xy[:, 1], **kw)
        art.set_gid(f"instrument:{ins.role}")
        out.setdefault(ins.step, []).append(art)


def _draw_line(
    ax: Axes, name: str, step: Step, line: Any, box: Any, theme: Theme, hl: dict[str, Any]
) -> list[Artist]:
    seg = clip_line(line[0], line[1], box)
    if seg is None:
        return [ax.plot([], [])[0]]
    (x0, y0), (x1, y1) = seg
    role = getattr(step, "role", "")
    if role == "axis":
        kw: dict[str, Any] = dict(color=theme.axis_color, lw=theme.line_width * 0.8, zorder=2)
    elif step.op == "perpendicular" or role in ("transfer", "cost_line"):
        kw = dict(color=theme.construction_color, lw=theme.thin_width, ls=(0, (4, 2)), zorder=2.5)
    else:
        kw = dict(
            color=theme.side_color,
            lw=theme.line_width,
            zorder=2.6,
            label="cone sides, extended (§3.3)"
            if role == "cone_side" and _n(step) == 1
            else "_nolegend_",
        )
    arts: list[Artist] = list(ax.plot([x0, x1], [y0, y1], **{**kw, **hl}))
    if role == "axis":
        end = (x1, y1) if (x1 - x0) + (y1 - y0) > 0 else (x0, y0)
        arts.append(
            ax.annotate(
                {1: "x", 2: "y"}.get(_n(step), name),
                end,
                xytext=(-4, -4),
                textcoords="offset points",
                color=theme.axis_color,
                fontsize=theme.font_size,
                style="italic",
                ha="right",
                va="top",
            )
        )
    return arts


def _draw_length(
    ax: Axes,
    step: Step,
    num: dict[str, Any],
    box: Any,
    span: float,
    theme: Theme,
    hl: dict[str, Any],
) -> list[Artist]:
    """A signed length as a thin double arrow along its axis, offset per n (§3.3)."""
    a, b, axis = (num[k] for k in step.inputs[:3])
    d = np.asarray(axis[1], dtype=float)
    d /= np.linalg.norm(d)
    side = np.array([d[1], -d[0]])  # below the x-axis, right of the y-axis
    off = side * (0.012 * span * (_n(step) + 0.5))
    color = hl.get("color", theme.circle_color(_n(step)))
    a, b = tuple(np.asarray(a) + off), tuple(np.asarray(b) + off)
    seg = clip_segment(a, b, box)
    if seg is None or math.dist(a, b) < 1e-9 * span:
        return list(ax.plot([a[0]], [a[1]], marker="|", color=color, ms=4, lw=0))
    tail = math.dist(seg[0], a) < 1e-12 * span  # an arrow head only where the length ends
    head = math.dist(seg[1], b) < 1e-12 * span  # inside the view ("<--" is no style)
    style = {(True, True): "<->", (True, False): "<-", (False, True): "->", (False, False): "-"}[
        tail, head
    ]
    arrow = ax.annotate(
        "",
        seg[1],
        xytext=seg[0],
        annotation_clip=False,
        zorder=2.4,
        arrowprops=dict(
            arrowstyle=style,
            color=color,
            lw=hl.get("lw", theme.thin_width),
            shrinkA=0,
            shrinkB=0,
            mutation_scale=7,
        ),
    )
    return [arrow]
