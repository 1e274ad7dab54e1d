"""The side panel of a lecture animation: under the caption, what is made so far.

Below the caption of the ``side`` layout (``--quality lecture``) the panel lists the
results of the construction as they are made, with their values: the contacts
:math:`P_1, P_2`; the feet :math:`P_{1x}, P_{2x}` and the midpoint :math:`O_M` on the
x-axis; for each n the two signed lengths :math:`O_M X_n`, :math:`O\\,Y_n` and the point
:math:`V_n = (-O_M X_n, -O\\,Y_n)` (eq. (30)); the circles on :math:`OV_n` (eq. (31));
the break points.  From the envelope's step on, the list gives way to the plot of
:math:`k_\\mathrm{grasp}(\\theta)` (eq. (25)), traced with the envelope.  An entry appears
when its step's stroke is done (as a point's label does) and is highlighted during its
step; nothing made after the current step is shown.  Private to
:mod:`graspcompass.render.animate`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.text import Text

from ..scene.layout import tex
from ._anim_layout import drawn_width

__all__: list[str] = []

#: Gap between the cells of a line, in ems of the panel's font.
GAP = 0.9
#: The list's heading.
HEADING = "Made so far"
#: Line height, in ems.
LEADING = 1.55


def _num(v: float) -> str:
    """A value to two decimals in mathtext, without a negative zero; a sign is not spaced
    as a binary minus."""
    v = 0.0 if abs(v) < 5e-3 else v
    return f"{{-}}{-v:.2f}" if v < 0 else f"{v:.2f}"


def _xy(v: Any) -> str:
    return f"({_num(v[0])}, {_num(v[1])})"


def _lines(steps: Any, num: dict[str, Any]) -> list[list[tuple[str, int]]]:
    """The lines of the list: each cell's mathtext and the index of the step making it.

    A line's lead word (``on the x-axis:``) comes with its first cell."""
    by_role: dict[str, list[Any]] = {}
    for s in steps:
        by_role.setdefault(s.role, []).append(s)
    lines: list[list[tuple[str, int]]] = []

    def line(lead: str, cells: list[tuple[str, int]]) -> None:
        if cells:
            first = min(i for _, i in cells)
            lines.append(([(lead, first)] if lead else []) + cells)

    line(
        "",
        [
            (f"${tex(s.name, False)} = {_xy(num[s.name])}$", s.index)
            for s in by_role.get("contact", [])
        ],
    )
    on_x = by_role.get("foot", []) + by_role.get("midpoint", [])
    line(
        "on the $x$-axis:",
        [(f"${tex(s.name, False)} = {_num(num[s.name][0])}$", s.index) for s in on_x],
    )
    lengths = {(s.role, s.n[0]): s for s in steps if s.role in ("S_length", "C_length")}
    for v in by_role.get("V", []):
        cells = []
        for role in ("S_length", "C_length"):
            s = lengths.get((role, v.n[0]))
            if s is not None:
                a, b = (tex(n, False) for n in s.inputs[:2])
                cells.append((f"${a}\\,{b} = {_num(num[s.name])}$", s.index))
        cells.append((f"${tex(v.name, False)} = {_xy(num[v.name])}$", v.index))
        line("", cells)
    circles = by_role.get("circle", [])
    line(
        "circles on",
        [(f"$O{tex(s.inputs[-1], False)}$", s.index) for s in circles],
    )
    line(
        "break points",
        [(f"${tex(s.name, False)}$", s.index) for s in by_role.get("break_point", [])],
    )
    if lines:
        lines.insert(0, [(HEADING, min(i for cells in lines for _, i in cells))])
    return lines


class SidePanel:
    """The list of what is made so far and the plot of k_grasp(θ), in the panel's box
    ``(left, right, bottom, top, plot_top)`` (pixels from the figure's lower left corner;
    the plot's top under the captions of the envelope and of the hold).  Its text is at
    least ``least_pt`` points."""

    def __init__(self, anim: Any, box: tuple[float, ...], least_pt: float) -> None:
        fig, th = anim.figure, anim.theme
        self.figure, self.theme = fig, th
        renderer = anim._canvas.get_renderer()
        W, H = fig.get_size_inches() * fig.dpi
        left, right, bottom, top, plot_top = box
        steps = anim.construction.steps
        env = [s for s in steps if s.kind == "envelope"]
        self.envelope = env[0].index if env else len(steps)
        lines = _lines(steps, anim._num)
        px = fig.dpi / 72.0
        self.cells: list[tuple[Text, int]] = [
            (
                fig.text(0, 0, text, va="top", fontweight="bold" if text == HEADING else "normal"),
                i,
            )
            for cells in lines
            for text, i in cells
        ]
        ends = np.cumsum([len(cells) for cells in lines])  # a line's cells end there
        height = top - bottom
        # the largest font, from the caption's down to the least, at which every line of
        # the list fits the panel's width unbroken and all its lines its height; at the
        # least a line too long goes on over the next
        size = max(anim._caption.get_fontsize() * 0.9, least_pt)
        while True:
            rows, broken, x = 0, False, left
            places: list[tuple[float, int]] = []
            for k, (t, _) in enumerate(self.cells):
                t.set_fontsize(size)
                w = drawn_width(t, renderer)
                first = k == 0 or k in ends
                if first or x + w > right:
                    broken |= not first
                    rows += 1
                    x = left
                places.append((x, rows))
                x += w + GAP * size * px
            if (not broken and rows * LEADING * size * px <= height) or size <= least_pt:
                break
            size = max(least_pt, size * 0.94)
        # the lines spread over the panel's height, up to twice the font size apart
        lead = min(2.0, max(LEADING, height / max(1, rows) / (size * px))) * size * px
        for (t, _), (x, row) in zip(self.cells, places):
            t.set_position((x / W, (top - (row - 1) * lead) / H))
            t.set_visible(False)
        self.size = size
        # the plot of k_grasp(θ), from the envelope's step on, under the last captions
        self.axes: Axes | None = None
        self.trace = self.cursor = None
        room = 5 * size * px  # the least width and height of the plot, with its labels
        if env and right - left >= room and plot_top - bottom >= room:
            self._plot(anim, env[0], (left, right, bottom, plot_top), renderer, size, least_pt)
        self.artists: list[Artist] = [t for t, _ in self.cells]
        if self.axes is not None:
            self.artists.append(self.axes)

    def _plot(
        self, anim: Any, env: Any, box: Any, renderer: Any, size: float, least_pt: float
    ) -> None:
        fig, th = self.figure, self.theme
        W, H = fig.get_size_inches() * fig.dpi
        left, right, bottom, top = box
        samples = len(anim.artists[env.name][0].get_xdata())
        self.theta = np.linspace(0.0, 2 * math.pi, samples)  # as the envelope is traced
        self.k = np.asarray(anim._num[env.name].k(self.theta), dtype=float)
        ax = fig.add_axes((left / W, bottom / H, (right - left) / W, (top - bottom) / H))
        (self.trace,) = ax.plot([], [], color=th.envelope_color, lw=th.envelope_width * 0.6)
        (self.cursor,) = ax.plot([], [], "o", color=th.highlight_color, ms=th.point_size * 1.2)
        ax.set_xlim(0, 360)
        ax.set_xticks([0, 90, 180, 270, 360])
        ax.set_ylim(0, 1.12 * max(float(np.max(self.k)), 1e-9))
        ax.tick_params(labelsize=max(size * 0.85, least_pt))
        ax.set_xlabel(r"$\theta$ (degrees)", fontsize=size)
        ax.set_ylabel(r"$k_\mathrm{grasp}(\theta)$", fontsize=size)
        ax.set_title(r"$k_\mathrm{grasp}(\theta)$, eq. (25)", fontsize=size, loc="left")
        ax.grid(True, lw=0.5, alpha=0.4)
        # shrink the axes so that its ticks, labels and title stay inside the box
        tight = ax.get_tightbbox(renderer)
        pos = ax.get_window_extent(renderer)
        if tight is not None:
            x0 = pos.x0 + (left - tight.x0)
            x1 = pos.x1 - (tight.x1 - right)
            y0 = pos.y0 + (bottom - tight.y0)
            y1 = pos.y1 - (tight.y1 - top)
            ax.set_position((x0 / W, y0 / H, max(1.0, x1 - x0) / W, max(1.0, y1 - y0) / H))
        ax.set_visible(False)
        self.axes = ax

    def movers(self, step: int) -> list[Artist]:
        """The panel's artists changing within ``step``: its own entries; the plot while
        the envelope is traced."""
        out: list[Artist] = [t for t, i in self.cells if i == step]
        if step == self.envelope and self.axes is not None:
            out.append(self.axes)
        return out

    def apply(self, step: int, kind: str, progress: float, hold: bool, title: bool) -> None:
        """Show what is made by a frame of ``step`` (``kind``, ``progress``)."""
        done = kind != "draw" or progress >= 1.0
        plot = self.axes is not None and not title and (hold or step >= self.envelope)
        for t, i in self.cells:
            made = not title and (hold or i < step or (i == step and done))
            t.set_visible(made and not plot)
            t.set_color(
                self.theme.highlight_color if i == step and not hold else self.theme.label_color
            )
        if self.axes is None or self.trace is None or self.cursor is None:
            return
        self.axes.set_visible(plot)
        if not plot:
            return
        p = 1.0 if hold or step > self.envelope or done else progress
        m = max(2, math.ceil(p * len(self.theta)))
        deg = np.degrees(self.theta[:m])
        self.trace.set_data(deg, self.k[:m])
        drawing = step == self.envelope and not hold
        self.trace.set_color(self.theme.highlight_color if drawing else self.theme.envelope_color)
        self.cursor.set_data([deg[-1]], [self.k[m - 1]])
        self.cursor.set_visible(p < 1.0)
