"""The parts of a worksheet's pages: header, drawing axes at scale, cones, solution rows.

The drawing axes are placed so that one unit of the grasp is ``scale``
millimetres on paper (:func:`_place_axes`, :func:`round_scale`); page 2 adds the
values of the signed lengths ``O_M X_n`` and ``O Y_n`` to check the drawing with a
ruler (eqs. (28)-(30), (33)-(39), (A7)-(A8)).  Private to
:mod:`graspcompass.render.handdrawing`, which re-exports these names.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from ..scene.layout import wedge
from ._hand_steps import _GREEK, _m, _n_of
from ._hand_text import _MARGIN, _MM, _TOP, A4_MM, _width_mm
from .theme import Theme

if TYPE_CHECKING:
    from ..construction.protocol import Construction
    from ..grasp import Grasp


def _params_lines(grasp: Grasp, width_mm: float = A4_MM[0] - 2 * _MARGIN) -> list[str]:
    """The grasp's parameters, exact values with their decimals, on one or two lines."""
    parts = []
    for k, v in grasp.params.items():
        if k.startswith("xi"):
            continue
        name = k
        for g, u in _GREEK.items():
            name = name.replace(g, u)
        f = float(v)
        exact = str(v).replace("sqrt", "√").replace("pi", "π").replace("*", "")
        if getattr(v, "is_Float", False) or len(exact) > 14 or exact == f"{f:g}":
            parts.append(f"{name} = {f:.6g}")
        else:
            parts.append(f"{name} = {exact} ≈ {f:.4g}")
    one = ",  ".join(parts)
    if _width_mm(one, 7.5) <= width_mm:
        return [one]
    return [",  ".join(parts[:3]), ",  ".join(parts[3:])]


def _sub_construction(
    construction: Construction, selected: Sequence[str], given: Sequence[str]
) -> Any:
    """The selected steps, the given ones first (each keeps its protocol index)."""
    from ..construction import Construction

    first = [construction.step(n) for n in selected if n in set(given)]
    rest = [construction.step(n) for n in selected if n not in set(given)]
    return Construction(tuple(first + rest), construction.grasp, ())


def round_scale(fit: float) -> float:
    """The scale stated on the page: ``fit`` rounded down to whole mm per unit (at most three
    significant digits) from 10 up, to two significant digits below 10.

    Examples
    --------
    >>> round_scale(18.63), round_scale(1047.2), round_scale(0.987), round_scale(7.31)
    (18.0, 1040.0, 0.98, 7.3)
    """
    if fit >= 10:
        k = max(0, math.floor(math.log10(fit)) - 2)
        return float(math.floor(fit / 10**k) * 10**k)
    k = math.floor(math.log10(fit)) - 1
    return float(f"{math.floor(fit / 10**k + 1e-9) * 10**k:.3g}")


def _new_page() -> Figure:
    fig = Figure(figsize=(A4_MM[0] * _MM, A4_MM[1] * _MM), dpi=72)
    FigureCanvasAgg(fig)
    return fig


def _place_axes(
    fig: Figure,
    box: tuple[float, float, float, float],
    scale: float,
    area: tuple[float, float, float, float],
) -> Axes:
    """Axes whose data-to-paper factor is exactly ``scale`` mm per unit, centred in ``area``
    (x0, y0, width, height in mm from the lower left corner)."""
    W, H = A4_MM
    w, h = (box[1] - box[0]) * scale, (box[3] - box[2]) * scale
    x0 = area[0] + (area[2] - w) / 2
    y0 = area[1] + area[3] - h  # top-aligned under the header
    ax = fig.add_axes((x0 / W, y0 / H, w / W, h / H))
    return ax


def _finish_axes(ax: Axes, box: tuple[float, float, float, float]) -> None:
    """Exact position and limits, no ticks, a light frame round the drawing, axis names."""
    rect = ax.get_position(original=True)
    ax.set_aspect("auto")
    ax.set_position(rect, which="both")  # undo any shrinking for the equal aspect
    ax.set_xlim(box[0], box[1])
    ax.set_ylim(box[2], box[3])
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_color("#bbbbbb")
        spine.set_linewidth(0.5)
    if box[2] < 0 < box[3]:
        ax.annotate(
            "x",
            (box[1], 0.0),
            xytext=(-3, -3),
            textcoords="offset points",
            ha="right",
            va="top",
            style="italic",
            fontsize=9,
        )
    if box[0] < 0 < box[1]:
        ax.annotate(
            "y",
            (0.0, box[3]),
            xytext=(3, -3),
            textcoords="offset points",
            ha="left",
            va="top",
            style="italic",
            fontsize=9,
        )


def _cones(ax: Axes, grasp: Grasp, theme: Theme, length: float) -> list[Artist]:
    """Both friction cones (Fig. 2) as shaded wedges with their two sides drawn, so that a
    ruler can be laid along each side (§3.3 step (1))."""
    arts: list[Artist] = []
    for i, (a, b) in ((1, (1, 3)), (2, (2, 4))):
        apex = (
            float(grasp.P1.x if i == 1 else grasp.P2.x),
            float(grasp.P1.y if i == 1 else grasp.P2.y),
        )
        da, db = (
            (float(d.x), float(d.y)) for d in (grasp.side_direction(a), grasp.side_direction(b))
        )
        poly = wedge(apex, da, db, 0.6 * length)  # the shading short, the sides long
        arts.append(
            ax.add_patch(
                Polygon(
                    poly,
                    closed=True,
                    facecolor=theme.cone_face,
                    alpha=theme.cone_alpha,
                    edgecolor="none",
                    zorder=1,
                )
            )
        )
        for d in (da, db):
            k = length / math.hypot(*d)
            arts += ax.plot(
                [apex[0], apex[0] + k * d[0]],
                [apex[1], apex[1] + k * d[1]],
                color="black",
                lw=1.0,
                zorder=2.7,
                solid_capstyle="butt",
            )
    return arts


def _header(fig: Figure, title: str, lines: Sequence[str], scale: float) -> Line2D:
    """Title, the grasp, and the 100 mm check bar with the stated scale."""
    W, H = A4_MM
    top = H - _TOP
    fig.text(_MARGIN / W, top / H, title, fontsize=12, weight="bold", va="top")
    for k, text in enumerate(lines):
        fig.text(_MARGIN / W, (top - 6.5 - 3.6 * k) / H, text, fontsize=7.5, va="top")
    y = top - 22
    x0 = _MARGIN
    bar = Line2D(
        [x0 / W, (x0 + 100) / W],
        [y / H, y / H],
        transform=fig.transFigure,
        color="black",
        lw=0.8,
        solid_capstyle="butt",
    )
    fig.add_artist(bar)
    for k in range(11):
        t = 2.0 if k % 5 == 0 else 1.2
        fig.add_artist(
            Line2D(
                [(x0 + 10 * k) / W] * 2,
                [y / H, (y + t) / H],
                transform=fig.transFigure,
                color="black",
                lw=0.5,
            )
        )
    fig.text(
        (x0 + 104) / W,
        (y + 1.5) / H,
        f"Scale: 1 unit = {scale:g} mm",
        fontsize=10,
        weight="bold",
        va="baseline",
    )
    fig.text(
        (x0 + 104) / W,
        (y - 2.2) / H,
        "The bar is 100 mm: print at actual size (100 %) and check it with a ruler.",
        fontsize=6.5,
        va="baseline",
    )
    return bar


def _unit_bar(ax: Axes, box: tuple[float, float, float, float], scale: float) -> Line2D:
    """A bar one unit long in data coordinates, in the lower right corner of the drawing."""
    pad = 4.0 / scale  # 4 mm
    x1, y = box[1] - pad, box[2] + pad
    x0 = x1 - 1.0
    bar = Line2D([x0, x1], [y, y], color="black", lw=1.0, solid_capstyle="butt", zorder=7)
    ax.add_line(bar)
    tick = 1.2 / scale
    for x in (x0, x1):
        ax.add_line(Line2D([x, x], [y - tick, y + tick], color="black", lw=0.6, zorder=7))
    ax.annotate(
        f"1 unit = {scale:g} mm",
        ((x0 + x1) / 2, y),
        xytext=(0, 3),
        textcoords="offset points",
        ha="center",
        va="bottom",
        fontsize=7,
        zorder=7,
    )
    return bar


def _transfer_marks(
    ax: Axes, construction: Construction, num: dict[str, Any], theme: Theme
) -> None:
    """On the solution: −O_M X_n and −O Y_n laid off from O, and the rectangle to V_n."""
    for s in construction.steps:
        n = _n_of(s.name)
        if not (s.name.startswith("V") and n):
            continue
        vx, vy = num[s.name]
        color = theme.circle_color(n)
        ax.plot([vx, vx, 0.0], [0.0, vy, vy], color=color, lw=0.6, ls=":", zorder=2.3)
        ax.plot(
            [vx, 0.0],
            [0.0, vy],
            ls="none",
            marker="o",
            ms=3.0,
            mfc="white",
            mec=color,
            mew=0.8,
            zorder=5,
        )


def _solution_rows(sub: Any, num: dict[str, Any], scale: float) -> list[tuple[str, str]]:
    rows = [
        (
            "",
            "Check your drawing: lay this page on yours against a window, or measure "
            "with a ruler.  Signed lengths in units and, in brackets, in mm on the page; "
            "the dotted lines are the transfer to $O$ (eqs. (28)-(30), (33)-(39)).",
        )
    ]
    for n in (1, 2, 3, 4):
        if f"V{n}" not in num:
            continue
        omx, oy = num[f"OMX{n}"] + 0.0, num[f"OY{n}"] + 0.0  # no "-0.000"
        vx, vy = num[f"V{n}"][0] + 0.0, num[f"V{n}"][1] + 0.0
        rows.append(
            (
                f"V{n}",
                (
                    f"$\\overline{{O_MX_{n}}}$ = {omx:+.3f} ({omx * scale:+.1f} mm),  "
                    f"$\\overline{{OY_{n}}}$ = {oy:+.3f} ({oy * scale:+.1f} mm),  so  "
                    f"$V_{n}$ = ({vx:+.3f}, {vy:+.3f}), i.e. ({vx * scale:+.1f} mm, "
                    f"{vy * scale:+.1f} mm) from $O$."
                ),
            )
        )
    return rows


def _intro(c: Construction, given: Sequence[str]) -> str:
    extra = [g for g in given if g not in ("O", "x-axis", "y-axis", "P1", "P2")]
    more = ""
    if extra:
        more = "; also " + ", ".join(f"#{c.step(g).index} {_m(g)}" for g in extra)
    return (
        "Already drawn (steps 0-4): $O$, the x- and y-axis, $P_1$, $P_2$ and the "
        f"friction cones with their sides{more}; each side is marked with its angle "
        "$\\varphi_i \\pm \\xi_i$ from the negative y-axis (dotted), clockwise at $P_1$ "
        "and counter-clockwise at $P_2$ (§2.2.1).  Draw the numbered steps in order with "
        "ruler, compass and set square (numbers as printed by graspcompass steps)."
    )
