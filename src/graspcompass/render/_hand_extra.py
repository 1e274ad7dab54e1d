"""The parts of a worksheet that make it readable: cone sides with their angles, labels
clear of them, the read-off exercise (k_grasp(θ), F_int), a legend and the zoomed centre.

* Each cone side is drawn long enough to lay a ruler on (25-40 mm) and marked with its
  angle from the negative y-axis, clockwise at P1 and counter-clockwise at P2 (§2.2.1:
  the normal makes φ_1 (CW) and φ_2 (CCW) with it, the sides φ_i ± ξ_i, ξ_i the apex
  angle of eq. (1)).
* The exercise: read k_grasp(θ) (eq. (25)) off the drawn envelope along e(θ) =
  (sin θ, −cos θ) (eq. (26)), or k_n(θ) off the circle on O V_n (eq. (32)) when the
  worksheet draws one V_n, and compute F_int = k / (x1 + x2) · F_e (eq. (17)).
* Page 2: a legend of what is drawn and, when points crowd, the crowded region again at
  a larger scale.

Private to :mod:`graspcompass.render.handdrawing`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.text import Annotation

from ._figure_parts import _CORNER, box_patch
from ._hand_labels import _renderer, mend_labels
from ._hand_text import A4_MM
from .figure import draw_construction
from .theme import Theme

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp

#: Cone sides on the page: at least and at most this long, mm.
SIDE_MM = (25.0, 40.0)


def side_length(grasp: Grasp, box: tuple[float, float, float, float], scale: float) -> float:
    """Length of the drawn cone sides, units: 0.9 |P1 P2|, kept within :data:`SIDE_MM`."""
    d = math.dist((float(grasp.P1.x), float(grasp.P1.y)), (float(grasp.P2.x), float(grasp.P2.y)))
    return min(max(0.9 * d, SIDE_MM[0] / scale), SIDE_MM[1] / scale)


def _deg(x: float) -> str:
    t = f"{x:.1f}"
    return (t[:-2] if t.endswith(".0") else t).replace("-", "−") + "°"


def cone_angles(ax: Axes, grasp: Grasp, length: float, font: float = 7.0) -> list[Artist]:
    """At each contact the negative y-axis direction (dotted, the reference of §2.2.1) and,
    at the end of each cone side, its angle φ_i ± ξ_i from it (CW at P1, CCW at P2)."""
    arts: list[Artist] = []
    spread: list[tuple[Annotation, tuple[float, float, float, float]]] = []
    for i, sides in ((1, (1, 3)), (2, (2, 4))):
        P = grasp.P1 if i == 1 else grasp.P2
        px, py = float(P.x), float(P.y)
        arts += ax.plot(
            [px, px],
            [py, py - 0.55 * length],
            color="#555555",
            lw=0.6,
            ls=(0, (1, 1.5)),
            zorder=2.6,
        )
        phi, xi = float(grasp.params[f"phi{i}"]), float(grasp.params[f"xi{i}"])
        for n, sign in zip(sides, (1, -1)):
            d = grasp.side_direction(n)
            dx, dy = float(d.x), float(d.y)
            k = length / math.hypot(dx, dy)
            end = (px + k * dx, py + k * dy)
            sym = "+" if sign > 0 else "-"
            label = f"$\\varphi_{i} {sym} \\xi_{i}$ = {_deg(math.degrees(phi + sign * xi))}"
            ux, uy = dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)
            note = ax.annotate(
                label,
                end,
                xytext=(4 * ux, 4 * uy),
                textcoords="offset points",
                gid=f"side{n}",
                ha="left" if ux > 0.3 else "right" if ux < -0.3 else "center",
                va="bottom" if uy > 0.3 else "top" if uy < -0.3 else "center",
                fontsize=font,
                zorder=6,
                annotation_clip=False,
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8),
            )
            arts.append(note)
            spread.append((note, (px, py, k * dx, k * dy)))
    _spread(ax, spread)
    return arts


def _spread(ax: Axes, labels: list[tuple[Annotation, tuple[float, float, float, float]]]) -> None:
    """Angle labels that overlap one placed before move inwards along their side (to 3/4,
    then 1/2 of its length); each label comes with its side (px, py, dx, dy)."""
    renderer = _renderer(ax)
    placed: list[Any] = []
    for t, (px, py, dx, dy) in labels:
        for f in (1.0, 0.75, 0.5, 0.35):
            t.xy = (px + f * dx, py + f * dy)
            bb = t.get_window_extent(renderer)
            if not any(bb.overlaps(o) for o in placed):
                break
        placed.append(t.get_window_extent(renderer))


def exercise(construction: Construction, num: dict[str, Any]) -> dict[str, Any] | None:
    """The read-off exercise: θ (a multiple of 15° near the worst orientation, where k > 0),
    what to read (k_grasp, or k_n of the one circle drawn), its value and F_int / F_e."""
    names = set(construction.names)
    grasp = construction.grasp
    if grasp is None:  # a construction without a grasp has no k_grasp to read off
        return None
    D = float(grasp.x1 + grasp.x2)
    if "envelope" in names:
        V = [num[f"V{n}"] for n in (1, 2, 3, 4)]
        what, n = "k_grasp", None
    else:
        ns = [n for n in (1, 2, 3, 4) if f"circle{n}" in names]
        if not ns:
            return None
        n = ns[0]
        V = [num[f"V{n}"]]
        what = f"k_{n}"
    worst = max(V, key=lambda v: math.hypot(*v))
    # e(θ) = (sin θ, −cos θ) along V: θ = atan2(S, −C), eq. (26)
    t_worst = math.degrees(math.atan2(worst[0], -worst[1])) % 360
    theta = (15 * round(t_worst / 15)) % 360
    t = math.radians(theta)
    k = max([0.0] + [v[0] * math.sin(t) - v[1] * math.cos(t) for v in V])  # (25), (32)
    return dict(theta=theta, what=what, n=n, k=k, F=k / D, D=D)


def exercise_text(ex: dict[str, Any]) -> str:
    """The instruction of page 1 (numbered "read")."""
    th = ex["theta"]
    if ex["n"] is None:
        curve, sym = "the envelope", "$k_{grasp}$"
        ref = "eq. (25)"
    else:
        curve, sym = f"the circle on $OV_{ex['n']}$", f"$k_{ex['n']}$"
        ref = "eq. (32)"
    return (
        f"Read off: draw the ray from $O$ at $\\theta$ = {th}° (from the negative y-axis, "
        f"counter-clockwise: the direction $e(\\theta)$ of $F_e$, eq. (26)) to {curve}; "
        f"its length is {sym}({th}°) [{ref}].  Compute "
        f"$F_{{int}} = k\\,/\\,(x_1 + x_2) \\cdot F_e$ [eq. (17)]."
    )


def exercise_answer(ex: dict[str, Any], scale: float) -> str:
    sym = "k_{grasp}" if ex["n"] is None else f"k_{ex['n']}"
    return (
        f"Read off at $\\theta$ = {ex['theta']}°: ${sym}$ = {ex['k']:.3f} "
        f"({ex['k'] * scale:.1f} mm on the page), so $F_{{int}}$ = {ex['k']:.3f} / "
        f"{ex['D']:.3f} $\\cdot F_e$ = {ex['F']:.3f} $F_e$ (eqs. (25)/(32), (17))."
    )


def draw_ray(ax: Axes, ex: dict[str, Any], theme: Theme, reach: float) -> list[Artist]:
    """The ray e(θ) from O and the point read off at distance k (page 2)."""
    t = math.radians(ex["theta"])
    e = (math.sin(t), -math.cos(t))
    arts: list[Artist] = list(
        ax.plot([0, reach * e[0]], [0, reach * e[1]], color="black", lw=0.8, ls="--", zorder=4.5)
    )
    arts += ax.plot(
        [ex["k"] * e[0]], [ex["k"] * e[1]], "s", ms=4, mfc="white", mec="black", mew=0.9, zorder=6
    )
    return arts


def _legend_roles(sub: Any, main: dict[str, list[Artist]]) -> set[str]:
    """What the solution draws, for its legend: ``object`` (the outline), the roles of the
    instruments (compass arcs, right angles) and ``read off`` (the exercise's ray)."""
    from ..scene.picture import scene_of

    roles = {i.role for i in scene_of(sub).instruments}
    roles |= {k for k in ("object", "read off") if main.get(k)}
    return roles


def legend(
    fig: Figure,
    where: tuple[float, float, float, float],
    theme: Theme,
    font: float,
    roles: set[str] | None = None,
) -> Any:
    """A legend of what page 2 draws, in ``where`` (x0, y0, w, h as figure fractions):
    each kind of line and mark with the colour and style it is drawn in (``roles``: the
    optional ones drawn, :func:`_legend_roles`; all when None)."""
    c = [theme.circle_color(n) for n in (1, 2, 3, 4)]

    def on(role: str) -> bool:
        return roles is None or role in roles

    handles: list[Artist] = []
    if on("object"):
        handles.append(
            Patch(facecolor=theme.object_face, edgecolor=theme.object_edge, label="the object")
        )
    handles += [
        Patch(facecolor=theme.cone_face, alpha=theme.cone_alpha, label="friction cone"),
        Line2D([], [], color="black", lw=1.0, label="cone side, as given on page 1"),
        Line2D([], [], color=theme.side_color, lw=1.0, label="cone side, extended (§3.3)"),
        Line2D([], [], color="#888888", lw=0.8, ls="--", label="perpendicular to a side"),
    ]
    if on("right_angle"):
        handles.append(
            Line2D(
                [],
                [],
                ls="none",
                marker=_CORNER,
                ms=6,
                mfc="none",
                mew=0.9,
                color=theme.construction_color,
                label="right angle",
            )
        )
    arcs = [
        w
        for r, w in (
            ("bisection_arc", "bisection"),
            ("measure_arc", "length taken"),
            ("transfer_arc", "carried to $O$"),
        )
        if on(r)
    ]
    if arcs:
        handles.append(
            Line2D(
                [],
                [],
                color=theme.construction_color,
                lw=theme.thin_width,
                label="compass arcs: " + ", ".join(arcs),
            )
        )
    handles += [
        Line2D(
            [],
            [],
            color=c[0],
            lw=0.8,
            marker=">",
            ms=4,
            label=r"signed length $\overline{O_MX_n}$, $\overline{OY_n}$",
        ),
        Line2D([], [], color=c[0], lw=0.6, ls=":", label=r"transfer to $O$: $V_n$"),
        Line2D(
            [],
            [],
            color=c[0],
            lw=1.0,
            ls="--",
            label=r"circle on $OV_n$: $k_n(\theta)$ (colour of $n$)",
        ),
        Line2D([], [], color=theme.envelope_color, lw=2.0, label=r"envelope $k_{grasp}(\theta)$"),
        Line2D(
            [],
            [],
            ls="none",
            marker="o",
            ms=3,
            mfc="white",
            mec="black",
            label=r"break point $B_{nm}$",
        ),
    ]
    if on("read off"):
        handles.append(
            Line2D(
                [],
                [],
                color="black",
                lw=0.8,
                ls="--",
                marker="s",
                ms=4,
                mfc="white",
                label=r"ray $e(\theta)$, the value read off",
            )
        )
    return fig.legend(
        handles=handles,
        loc="upper left",
        bbox_to_anchor=where,
        frameon=False,
        fontsize=font,
        title="Legend",
        title_fontsize=font + 0.5,
        handlelength=2.4,
        borderaxespad=0,
    )


def page2_extras(
    fig: Figure,
    ax: Axes,
    sub: Any,
    num: dict[str, Any],
    box: tuple[float, float, float, float],
    theme: Any,
    font: float,
    room: tuple[float, float, float],
    main: dict[str, list[Artist]] | None = None,
) -> list[Any]:
    """Below the solution rows (``room``: x0, top, width in mm): the crowded centre at a
    larger scale (marked on the drawing by a thin frame) and the legend.

    The labels of ``main`` (the drawing's artists by name) and of the inset keep the
    rules of every picture (:func:`mend_labels`); with the inset drawn, those of the
    points in the frame that crowd there, or that have no place keeping the rules, are
    left to the inset, which names those points."""
    W, H = A4_MM
    x0, top, width = room
    height = top - 12.0
    if height < 30:
        return []
    inset_of = _inset_at_size(ax, sub, theme)
    kept = {lab.names[0] for lab in inset_of.main} if inset_of is not None else set()
    taken = [lab.point for lab in inset_of.labels if lab.names[0] not in kept] if inset_of else []
    mine = [a for arts in (main or {}).values() for a in arts if isinstance(a, Annotation)]
    _, broken = mend_labels(ax, mine)  # what the drawing cannot name by the rules
    zoom = _frame_of([*taken, *(t.xy for t in broken)], box, inset_of)
    legend_w = 72.0
    arts: list[Any] = []
    if zoom is not None and width - legend_w >= 50:
        side = min(height - 5, width - legend_w - 6, 80.0)
        inset = fig.add_axes((x0 / W, (top - 5 - side) / H, side / W, side / H))
        drawn = draw_construction(
            sub, ax=inset, num=num, box=zoom, theme=theme.with_(font_size=theme.font_size * 0.85)
        )
        for key in ("cone1", "cone2"):  # the centre, not the given cones
            for a in drawn.pop(key, []):
                a.remove()
        inset.set_xticks([])
        inset.set_yticks([])
        for a in inset.get_children():  # labels and arrows of points outside stay out
            a.set_clip_on(True)
            a.set_clip_box(inset.bbox)
            if isinstance(a, Annotation):  # a Text with an ``xy``: an annotation
                a.set_annotation_clip(True)
        k = (box[1] - box[0]) / (zoom[1] - zoom[0])
        inset.set_title(f"The framed centre, enlarged {k:.1f}×", fontsize=font, loc="left", pad=3)
        arts += [
            inset,
            ax.add_patch(box_patch(zoom, fill=False, lw=0.6, ec="#555555", zorder=7)),
        ]
        mend_labels(
            inset,
            [a for arts in drawn.values() for a in arts if isinstance(a, Annotation)],
        )
        if main is not None:
            _leave_to_inset(ax, main, kept if inset_of is not None else None, zoom)
        x0 += side + 6
    arts.append(
        legend(
            fig,
            (x0 / W, (top - height) / H, legend_w / W, height / H),
            theme,
            font,
            _legend_roles(sub, main or {}),
        )
    )
    return arts


def _inset_at_size(ax: Axes, sub: Any, theme: Any) -> Any:
    """The zoomed inset of the one picture model (:attr:`Scene.inset
    <graspcompass.scene.picture.Scene.inset>`: the region where labels crowd, chosen from
    the geometry) for labels of ``theme.font_size`` on the drawing ``ax`` as drawn, or
    None when nothing crowds.  The page's drawing is smaller than the placement's frame,
    so its labels are relatively larger: the scene :func:`draw_construction` placed them
    in, at the size drawn."""
    from ..scene import labelling
    from ..scene.picture import scene_of

    frame_pt = ax.bbox.width * 72.0 / ax.figure.dpi  # type: ignore[union-attr]
    if frame_pt <= 0:
        return None
    return scene_of(sub, font_pt=theme.font_size * labelling.FRAME_PT / frame_pt).inset


def _frame_of(
    pts: list[Any], box: tuple[float, float, float, float], inset_of: Any
) -> tuple[float, float, float, float] | None:
    """The square region the inset enlarges: round the points ``pts`` (those the scene's
    inset names and those whose labels the drawing cannot place by the rules), padded;
    the scene's own inset region when they spread over more than 0.6 of the view, None
    when there are none."""
    if not pts:
        return None
    span = box[1] - box[0]
    xs, ys = [float(p[0]) for p in pts], [float(p[1]) for p in pts]
    half = max(max(xs) - min(xs), max(ys) - min(ys)) / 2 * 1.25 + 0.04 * span
    if half > 0.3 * span:
        return inset_of.box if inset_of is not None else None
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    return (cx - half, cx + half, cy - half, cy + half)


def _leave_to_inset(
    ax: Axes,
    main: dict[str, list[Artist]],
    kept: set[str] | None,
    zoom: tuple[float, float, float, float],
) -> None:
    """On the drawing ``ax``: the labels (and their leader lines) of the points in the
    frame ``zoom`` that the inset takes (those of no group in ``kept``, the first names
    of the scene's labels left on the main view) removed: the inset names them; the
    others kept to the rules (:func:`mend_labels`), and removed too when in the frame
    with no place that keeps them."""

    def inside(t: Annotation) -> bool:
        x, y = t.xy
        return bool(zoom[0] <= x <= zoom[1] and zoom[2] <= y <= zoom[3])

    owners: dict[int, list[str]] = {}
    labels: dict[int, Annotation] = {}
    for name, arts in main.items():
        for a in arts:
            if isinstance(a, Annotation) and a.axes is ax and str(a.get_text()).startswith("$"):
                labels[id(a)] = a
                owners.setdefault(id(a), []).append(name)

    def forget(t: Annotation) -> None:  # its leader lines go with it
        for name in owners[id(t)]:
            for a in list(main.get(name, [])):
                if a is t or (isinstance(a, Line2D) and a.get_gid() == "leader"):
                    main[name].remove(a)
                    if a.axes is not None:
                        a.remove()

    for key, t in list(labels.items()):
        if inside(t) and kept is not None and not kept & set(owners[key]):
            forget(t)
            del labels[key]
    for t in mend_labels(ax, list(labels.values()), drop=inside)[0]:
        forget(t)
