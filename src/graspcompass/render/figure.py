"""Drawing the ruler-and-compass construction of the internal force diagram.

:func:`draw_construction` draws the state of a
:class:`~graspcompass.construction.Construction` after any step: the object,
its friction cones (Fig. 2), the cone sides and perpendiculars of §3.3
(Fig. 4), the points V_n, the circles on O V_n (eq. (31), Fig. 3) and their
outer envelope k_grasp (eq. (25), Fig. 5).  :func:`figure_diagram` makes the
complete Fig. 6 style figure, with the computer plot of Fig. 6(b) on top.
Only :class:`matplotlib.figure.Figure` is used, never pyplot.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import Polygon
from matplotlib.text import Annotation

from ..scene import labelling
from ..scene.layout import numeric_objects, shape_extent
from ..scene.picture import INSET_PT, NUMBER_SCALE, build_scene, grasp_title, scene_of
from ._figure_parts import (
    _CORNER,
    _draw_givens,
    _draw_instruments,
    _draw_length,
    _draw_line,
    _n,
    box_patch,
)
from .output import FORMATS, save_figure
from .polar import draw_k_polar, figure_k_plot
from .theme import DEFAULT_THEME, Theme

if TYPE_CHECKING:
    from ..construction.protocol import Construction

__all__ = [
    "EXTRA_KEYS",
    "FORMATS",
    "draw_construction",
    "draw_k_polar",
    "figure_diagram",
    "figure_k_plot",
    "grasp_title",
    "label_artists",
    "save_figure",
]

#: Keys of :func:`draw_construction`'s result that are not construction objects.
EXTRA_KEYS = ("object", "cone1", "cone2", "computer plot")

_LABEL_ORDER = "VPOXY"


def draw_construction(
    construction: Construction,
    step: int | None = None,
    ax: Axes | None = None,
    theme: Theme = DEFAULT_THEME,
    labels: bool = True,
    show_computer_plot: bool = False,
    highlight_last: bool = False,
    num: dict[str, Any] | None = None,
    box: tuple[float, float, float, float] | None = None,
    view: str = "whole",
    break_points: bool = False,
    inset: int = 0,
) -> dict[str, list[Artist]]:
    """Draw the construction of the internal force diagram after step ``step``.

    Parameters
    ----------
    construction : Construction
        From :func:`graspcompass.internal_force_diagram`, numeric parameters.
    step : int, optional
        Draw the state ``construction.upto(step)``; None draws every step.
        The view box is that of the whole construction, the same for every
        step, and the given data (the object outline from ``grasp.shape`` and
        the friction cones) are drawn at every step.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new :class:`~matplotlib.figure.Figure` is made if None.
    theme : Theme
        Colours, widths and font size.
    labels : bool
        Label the points as in the paper (P_1, P_{1x}, O_M, X_n, Y_n, V_n).
    show_computer_plot : bool
        Also draw the numeric polar plot of k_grasp (Fig. 6(b), eq. (25)).
    highlight_last : bool
        Draw the object of the last step drawn in ``theme.highlight_color``.
    num : dict, optional
        ``layout.numeric_objects(construction)`` when the caller has it already (a
        worksheet draws the same construction on two pages): computed once, passed on.
    box : tuple of float, optional
        ``(xmin, xmax, ymin, ymax)`` to draw instead of the one view box of every picture
        (an enlargement of a crowded region): lines are clipped to it and the labels placed
        in it.
    view : {"whole", "beside", "inset"}
        ``"whole"`` labels every point in the whole view; ``"beside"`` leaves the
        labels of the crowded points to the zoomed insets drawn beside it
        (:attr:`graspcompass.scene.picture.Scene.insets`); ``"inset"`` draws the
        ``inset``-th of them: a crowd, zoomed, with its labels.
    break_points : bool
        Label the break points on the envelope
        (:func:`graspcompass.scene.picture.build_scene`); the others stay unlabelled.
    inset : int
        Which inset ``view="inset"`` draws (0: the first, the crowded region's).

    Returns
    -------
    dict of str to list of Artist
        For every object name of the state, its artists (a point's marker and
        label, a line clipped to the view, a dashed circle, a length's double
        arrow, the envelope's bold line and filling); and the
        :data:`EXTRA_KEYS` ``"object"``, ``"cone1"``, ``"cone2"``,
        ``"computer plot"`` when drawn.  The geometry is only read.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> c = internal_force_diagram(Grasp.preset("fig6"))
    >>> arts = draw_construction(c, step=17)
    >>> sorted(set(arts) - set(EXTRA_KEYS)) == sorted(c.upto(17).names)
    True
    """
    state = construction if step is None else construction.upto(step)
    if ax is None:
        ax = Figure(figsize=(7, 7)).add_subplot()
    num_all = numeric_objects(construction) if num is None else num
    num = {k: num_all[k] for k in state.names}
    # an enlargement of a region (box given): its own scene, labelled in it
    given_box = box
    scene = (
        scene_of(construction, break_points=break_points)
        if box is None
        else build_scene(construction, box=box, break_points=break_points)
    ).upto(step)
    box = scene.box
    span = box[1] - box[0]
    shown = scene.labels
    zoomed = scene.insets[inset] if view == "inset" and inset < len(scene.insets) else None
    if view == "beside" and scene.insets:
        shown = scene.insets[0].main
    elif zoomed is not None:
        shown = zoomed.labels
    lim = zoomed.box if zoomed is not None else box
    ax.set_xlim(lim[0], lim[1])
    ax.set_ylim(lim[2], lim[3])
    ax.set_aspect("equal", adjustable="box")
    ax.apply_aspect()
    # labels larger or smaller against these axes than FONT_PT against FRAME_PT (an
    # animation's theme, axes of the user's own): placed again at the size drawn
    k = 1.0
    if view == "whole" and ax.figure is not None:
        frame_pt = ax.bbox.width * 72.0 / ax.figure.dpi
        k = frame_pt / labelling.FRAME_PT
        font_pt = theme.font_size / k
        if frame_pt > 0 and abs(font_pt - labelling.FONT_PT) > 0.05:
            again = (
                scene_of(construction, break_points=break_points, font_pt=font_pt)
                if given_box is None
                else build_scene(construction, box=box, break_points=break_points, font_pt=font_pt)
            )
            shown = again.upto(step).labels
    out: dict[str, list[Artist]] = {}
    _draw_givens(ax, construction, scene, theme, out)
    instruments: dict[str, list[Artist]] = {}
    zoom = zoomed.zoom if zoomed is not None else None
    _draw_instruments(ax, scene, theme, instruments, zoom)
    last = state.steps[-1].name if highlight_last else None
    for s in state.steps:
        v = num[s.name]
        hl = dict(color=theme.highlight_color, lw=2.0 * theme.line_width) if s.name == last else {}
        if s.kind == "point":
            small = s.role == "break_point"  # break points: small (labelled on request)
            out[s.name] = list(
                ax.plot(
                    [v[0]],
                    [v[1]],
                    "o",
                    ms=theme.point_size * (labelling.SMALL_MARKER if small else 1.0),
                    zorder=5,
                    mfc="white" if small else hl.get("color", theme.point_color),
                    mec=hl.get("color", theme.point_color),
                    mew=0.8,
                )
            )
        elif s.kind == "line":
            out[s.name] = _draw_line(ax, s.name, s, v, box, theme, hl)
        elif s.kind == "circle":
            n = _n(s)
            (cx, cy), r = v
            patch = CirclePatch(
                (cx, cy),
                r,
                fill=False,
                zorder=3,
                edgecolor=hl.get("color", theme.circle_color(n)),
                ls=theme.circle_style(n),
                lw=hl.get("lw", theme.line_width),
                label=f"circle on $OV_{n}$: $k_{n}(\\theta)$, eq. (31)"
                if s.role == "circle"
                else "_nolegend_",
            )
            out[s.name] = [ax.add_patch(patch)]
        elif s.kind == "length":
            out[s.name] = _draw_length(ax, s, num, box, span, theme, hl)
        else:  # the envelope, eq. (25)
            xy = v.polyline()
            fill = Polygon(
                xy,
                closed=True,
                facecolor=theme.envelope_fill,
                edgecolor="none",
                alpha=theme.envelope_alpha,
                zorder=1.5,
            )
            line = ax.plot(
                xy[:, 0],
                xy[:, 1],
                color=hl.get("color", theme.envelope_color),
                lw=theme.envelope_width,
                zorder=4,
                solid_joinstyle="round",
                label=r"envelope: $k_{grasp}(\theta)$, eq. (25)",
            )
            out[s.name] = [*line, ax.add_patch(fill)]
    for name, arts in instruments.items():  # after the step's own artists
        out.setdefault(name, []).extend(arts)
    if show_computer_plot and construction.grasp is not None:
        out["computer plot"] = draw_k_polar(construction.grasp, ax=ax, theme=theme)["k_grasp"]
    if labels:
        _label_points(ax, shown, theme, out, k)
    return out


_HA = {1: "left", -1: "right", 0: "center"}
_VA = {1: "bottom", -1: "top", 0: "center"}


def label_artists(
    ax: Axes, lab: Any, theme: Theme, k: float = 1.0, clip: bool = False
) -> tuple[Annotation, Line2D | None]:
    """The text of one of the scene's labels (:class:`graspcompass.scene.picture.Label`)
    at its offset in points from its point (``k`` times it: axes ``k`` times the
    placement's frame), and its leader line from the point to the label's box (a label set
    far away), or None.  ``clip``: drawn only inside the axes (a zoomed view)."""
    leader = None
    if lab.leader:  # a thin line from the point to its label set far away
        x0, y0, x1, y1 = lab.box
        near = (min(max(lab.point[0], x0), x1), min(max(lab.point[1], y0), y1))
        (leader,) = ax.plot(
            [lab.point[0], near[0]],
            [lab.point[1], near[1]],
            color=theme.label_color,
            lw=0.5,
            zorder=5.5,
            gid="leader",
        )
    text = ax.annotate(
        f"${lab.tex()}$",
        lab.point,
        xytext=(lab.offset[0] * k, lab.offset[1] * k),
        textcoords="offset points",
        ha=_HA[lab.direction[0]],
        va=_VA[lab.direction[1]],
        fontsize=theme.font_size,
        annotation_clip=clip,
        color=theme.label_color,
        zorder=6,
        bbox=dict(boxstyle="round,pad=0.08", fc="white", ec="none", alpha=0.65),
    )
    text.set_clip_on(clip)
    return text, leader


def _label_points(
    ax: Axes, labels: Any, theme: Theme, out: dict[str, list[Artist]], k: float = 1.0
) -> None:
    """The scene's labels (:attr:`Scene.labels`), one per group ``O = O_M = Y_4`` (§3.3).

    Placed once for every painter (:func:`graspcompass.scene.labelling.place`), at
    their offsets in points from their points (``k`` times them: axes ``k`` times the
    placement's frame); a group shows the names made so far.
    """
    for lab in labels:
        text, leader = label_artists(ax, lab, theme, k)
        for n in lab.names:  # the leader made with its label, not before
            out.setdefault(n, []).extend([text] if leader is None else [leader, text])


def figure_diagram(
    construction: Construction,
    step: int | None = None,
    overlay: bool = True,
    title: str | None = None,
    figsize: tuple[float, float] = (7.0, 7.0),
    theme: Theme = DEFAULT_THEME,
    labels: bool = True,
    inset: bool = True,
    break_points: bool = False,
) -> Figure:
    """A complete figure of the internal force diagram, as in Fig. 6 and Fig. 7.

    The construction (:func:`draw_construction`) in an equal-aspect frame
    without grid, titled ``title`` or the grasp's title (a grasp without one
    by its parameters), with a legend; when ``overlay`` is true the computer
    plot of Fig. 6(b) (eq. (25), evaluated numerically) is drawn over the
    finished envelope as a thin contrasting curve, so that the two coincide as
    §4.1 reports (not over a ``step`` before the envelope).  Where points crowd
    (:attr:`graspcompass.scene.picture.Scene.insets`) and ``inset`` is true, a
    zoomed view of each crowd stands right of the diagram, one above the other
    (the figure is wider by them), with their labels; their regions are dashed
    squares in the diagram, numbered when there are several.  ``break_points``
    labels the break points on the envelope (:func:`draw_construction`).

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> fig = figure_diagram(internal_force_diagram(Grasp.preset("table1b")))
    >>> fig.axes[0].get_aspect()
    1.0
    """
    scene = scene_of(construction, break_points=break_points)
    zooms = scene.insets if inset else ()
    side = labelling.FRAME_PT / 72.0  # the placement's frame: the axes' side in inches
    zs = INSET_PT / 72.0  # an inset's side, its labels placed at this size
    gap = 0.55  # between two insets of the column: room for the lower one's title
    extra = zs + 0.9 if zooms else 0.0
    w, h = figsize
    h += 0.4  # room for a title of two lines
    # the insets, one above the other right of the diagram: the figure taller by what
    # their column exceeds the diagram, the tops level
    column = len(zooms) * zs + (len(zooms) - 1) * gap if zooms else 0.0
    taller = max(0.0, column - side)
    h += taller
    bottom = 1.4 / h
    fig = Figure(figsize=(w + extra, h))
    ax = fig.add_axes((0.08 * w / (w + extra), bottom + taller / h, side / (w + extra), side / h))
    last = len(construction.steps) - 1
    full = step is None or step % len(construction.steps) == last
    draw_construction(
        construction,
        step=step,
        ax=ax,
        theme=theme,
        labels=labels,
        show_computer_plot=overlay and full,
        break_points=break_points,
        view="beside" if zooms else "whole",
    )
    ax.grid(False)
    ax.tick_params(labelsize=theme.font_size * 0.8)
    grasp = construction.grasp
    text = title if title is not None else grasp_title(grasp)
    if not full and step is not None:
        text += f"\nafter step {step % len(construction.steps)} of 0–{last}"
    room = (side + 2 * 0.08 * w) * 72.0  # the axes and the margin each side, in points
    ax.set_title(_title_lines(text, theme.font_size * 1.05, room), fontsize=theme.font_size * 1.05)
    for k, zoom in enumerate(zooms):
        left = (0.08 * w + side + 0.5) / (w + extra)
        top = bottom + (side + taller) / h - k * (zs + gap) / h
        zax = fig.add_axes((left, top - zs / h, zs / (w + extra), zs / h))
        drawn = draw_construction(
            construction,
            step=step,
            ax=zax,
            theme=theme,
            labels=labels,
            view="inset",
            break_points=break_points,
            inset=k,
        )
        for arts in drawn.values():  # the length arrows too stay inside the inset
            for a in arts:
                patch = getattr(a, "arrow_patch", None)
                if patch is not None:
                    patch.set_clip_box(zax.bbox)
                    patch.set_clip_on(True)
        zax.set_xticks([])
        zax.set_yticks([])
        times = zoom.zoom * (scene.box[1] - scene.box[0]) / labelling.FRAME_PT
        which = "the dashed square" if len(zooms) == 1 else f"dashed square {k + 1}"
        zax.set_title(f"{which}, {times:.1f}× larger", fontsize=theme.font_size * 0.9)
        b = zoom.box
        ax.add_patch(
            box_patch(b, fill=False, lw=0.8, ls=(0, (3, 2)), edgecolor=theme.axis_color, zorder=6)
        )
        if zoom.number is not None:  # the squares numbered as their insets
            ax.annotate(
                str(k + 1),
                zoom.number,
                ha="center",
                va="center",
                fontsize=theme.font_size * NUMBER_SCALE,
                color=theme.axis_color,
                zorder=6,
            )
    handles, names = ax.get_legend_handles_labels()
    handles, names = (
        [*handles, *_legend_extra(construction, step, theme)[0]],
        [*names, *_legend_extra(construction, step, theme)[1]],
    )
    if handles:
        fig.legend(
            handles,
            names,
            loc="lower center",
            ncol=3 if len(handles) > 12 else 2,
            frameon=False,
            fontsize=theme.font_size * 0.85,
        )
    return fig


def _title_lines(text: str, size: float, room: float) -> str:
    """``text`` with its first line broken at the comma nearest its middle when wider than
    ``room`` points at ``size`` (DejaVu Sans: at most 0.62 em a character here)."""
    first, _, rest = text.partition("\n")
    if len(first) * 0.62 * size <= room or ", " not in first:
        return text
    cuts = [i for i in range(len(first)) if first.startswith(", ", i)]
    i = min(cuts, key=lambda i: abs(2 * i - len(first)))
    return first[: i + 1] + "\n" + first[i + 2 :] + ("\n" + rest if rest else "")


def _legend_extra(
    construction: Construction, step: int | None, theme: Theme
) -> tuple[list[Artist], list[str]]:
    """Legend proxies of what has no labelled artist: the object, the dashed
    perpendiculars, the length arrows and the break points (those drawn by ``step``)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch as PatchProxy

    state = construction if step is None else construction.upto(step)
    roles = {s.role for s in state.steps} | {s.op for s in state.steps}
    drawn = {i.role for i in scene_of(construction).upto(step).instruments}
    kinds = {s.kind for s in state.steps}
    out: list[tuple[Artist, str]] = []
    if shape_extent(getattr(construction.grasp, "shape", None)) is not None:
        out.append(
            (PatchProxy(facecolor=theme.object_face, edgecolor=theme.object_edge), "the object")
        )
    if "perpendicular" in roles:
        out.append(
            (
                Line2D([], [], color=theme.construction_color, lw=theme.thin_width, ls=(0, (4, 2))),
                "perpendiculars to the cone sides",
            )
        )
    arcs = [
        w
        for r, w in (
            ("bisection_arc", "bisection"),
            ("measure_arc", "lengths taken"),
            ("transfer_arc", "carried from $O$"),
        )
        if r in drawn
    ]
    if arcs:
        out.append(
            (
                Line2D([], [], color=theme.construction_color, lw=theme.thin_width),
                "compass arcs: " + ", ".join(arcs),
            )
        )
    if "coordinate" in drawn:
        out.append(
            (
                Line2D([], [], color=theme.circle_color(1), lw=theme.thin_width, ls=(0, (1, 1.5))),
                "$V_n$ from its coordinates $-O_MX_n$, $-OY_n$",
            )
        )
    if "right_angle" in drawn:
        out.append(
            (
                Line2D(
                    [],
                    [],
                    ls="none",
                    marker=_CORNER,
                    ms=7,
                    mfc="none",
                    mew=theme.thin_width * 1.5,
                    color=theme.construction_color,
                ),
                "right angles",
            )
        )
    if "length" in kinds:
        out.append(
            (
                Line2D([], [], color=theme.circle_color(1), lw=theme.thin_width, marker=">", ms=4),
                "signed lengths $O_MX_n$, $OY_n$",
            )
        )
    if "break_point" in roles:
        out.append(
            (
                Line2D(
                    [],
                    [],
                    ls="none",
                    marker="o",
                    mfc="white",
                    mec=theme.point_color,
                    ms=theme.point_size * 0.6,
                ),
                "break points: $k_i = k_j$",
            )
        )
    return [a for a, _ in out], [t for _, t in out]
