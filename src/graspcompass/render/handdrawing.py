"""A printable worksheet: draw the internal force diagram by hand (§3.3).

:func:`worksheet` writes a two-page A4 portrait PDF.  Page 1 shows the grasp
(the object outline when the grasp has a shape, the axes, O, P1, P2 and the
friction cones) at a stated scale, "1 unit = s mm", with room to draw, and the
drawing steps of §3.3 of Ito, Tanaka and Sasaki (Robotica 30(5), 2012) as
numbered instructions in words, numbered as ``graspcompass steps`` numbers the
protocol.  Page 2 shows the solution at the same scale, in the same place on
the page, so that the two sheets can be laid on each other against a window,
with the values of the signed lengths to check the drawing with a ruler.

The scale is exact on paper: the page is 210 mm × 297 mm and the drawing axes
are placed so that one unit of the grasp is ``scale`` millimetres (checked by
:attr:`Worksheet.mm_per_unit`); a bar of 100 mm on the page tells whether the
printer kept the size.

The signs follow the paper: ``O_M X_n = X_n.x − O_M.x`` and ``O Y_n = Y_n.y``
(positive to the right and upwards), and ``V_n = (−O_M X_n, −O Y_n) = (S_n, C_n)``
by eqs. (28)-(30), (33)-(39) and the Appendix, eqs. (A7)-(A8).  The length
``O_M X_n`` is measured from ``O_M`` but laid off from ``O``.

The worksheet is made here; its parts are private modules, every name still
importable from here: the steps and the instructions in words (``_hand_steps``),
the page geometry and the text set word by word (``_hand_text``), the parts
of the pages (``_hand_page``), the cone angles, the read-off exercise, the legend and
the enlarged centre (``_hand_extra``), and the labels kept to the rules of every
picture as drawn (``_hand_labels``): on page 1 each name beside its point, on page 2
no label over a label or another point's marker and each nearer its own point, those
of the crowded points left to the enlarged centre, which names them.

Examples
--------
>>> import tempfile, pathlib
>>> from graspcompass import Grasp
>>> out = pathlib.Path(tempfile.mkdtemp()) / "fig6-V1.pdf"
>>> worksheet(Grasp.preset("fig6"), out, steps="V1").name
'fig6-V1.pdf'
>>> ws = worksheet_pages(Grasp.preset("fig6"), steps="V1", scale=15)
>>> round(ws.mm_per_unit(), 9)
15.0
>>> [i.steps for i in ws.instructions][:4]
[(5,), (9,), (10,), (11,)]
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.text import Annotation, Text

from ..scene.layout import numeric_objects, share_numeric, view_box
from . import _hand_extra as extra
from ._hand_page import (
    _cones,
    _finish_axes,
    _header,
    _intro,
    _new_page,
    _params_lines,
    _place_axes,
    _solution_rows,
    _sub_construction,
    _transfer_marks,
    _unit_bar,
    round_scale,
)
from ._hand_steps import (
    _COMMON,  # noqa: F401
    _GREEK,  # noqa: F401
    _WORD,  # noqa: F401
    GIVEN_LEVELS,
    STEP_CHOICES,
    Instruction,
    _brief_block,  # noqa: F401
    _m,  # noqa: F401
    _n_of,  # noqa: F401
    _ref_bits,  # noqa: F401
    _side_parts,  # noqa: F401
    _text,  # noqa: F401
    given_names,
    instructions_for,
    selected_names,
)
from ._hand_text import (
    _BOTTOM,  # noqa: F401
    _COL_GAP,  # noqa: F401
    _FONTS,
    _GAP,  # noqa: F401
    _HEADER,  # noqa: F401
    _LINE,  # noqa: F401
    _MARGIN,  # noqa: F401
    _MEASURE_DPI,  # noqa: F401
    _MM,
    _NUMBER_W,  # noqa: F401
    _TOP,  # noqa: F401
    A4_MM,
    _Block,  # noqa: F401
    _columns,  # noqa: F401
    _draw_blocks,
    _fits,  # noqa: F401
    _height,
    _layout_blocks,
    _line_text,  # noqa: F401
    _Plan,  # noqa: F401
    _plans,
    _renderer,  # noqa: F401
    _rules,
    _runs,  # noqa: F401
    _width_mm,  # noqa: F401
    _Word,  # noqa: F401
    _words,  # noqa: F401
    _wrap,  # noqa: F401
)
from .figure import draw_construction
from .theme import DEFAULT_THEME, PAPER_THEME

__all__ = [
    "A4_MM",
    "GIVEN_LEVELS",
    "STEP_CHOICES",
    "Instruction",
    "Worksheet",
    "given_names",
    "instructions_for",
    "round_scale",
    "selected_names",
    "worksheet",
    "worksheet_pages",
]

#: Smallest and largest scale (mm per unit) accepted; the unit of the grasp is anything.
SCALE_RANGE = (1e-6, 1e6)
#: Smallest width of the drawing, mm: a smaller scale is refused.
MIN_DRAWING_MM = 20.0


@dataclass
class Worksheet:
    """The two pages of a worksheet, before they are written.

    Attributes
    ----------
    figures : tuple of Figure
        Page 1 (the exercise) and page 2 (the solution), A4 portrait.
    axes : tuple of Axes
        The drawing axes of both pages, at the same place on the page.
    scale : float
        Millimetres per unit on paper.
    box : tuple of float
        ``(xmin, xmax, ymin, ymax)`` of the drawing, in units.
    construction : Construction
        The steps drawn on page 2 (the given steps first, then the student's).
    given : tuple of str
        Names of the objects drawn on page 1.
    instructions : list of Instruction
        The numbered instructions of page 1, in protocol order.
    artists : tuple of dict
        Name -> artists of page 1 and page 2 (as :func:`draw_construction` returns).
    scale_bar : Line2D
        The bar of page 1 that is one unit long in the drawing's coordinates.
    check_bar : Line2D
        The bar of page 1 that is 100 mm long on the page.
    """

    figures: tuple[Figure, Figure]
    axes: tuple[Axes, Axes]
    scale: float
    box: tuple[float, float, float, float]
    construction: Any
    given: tuple[str, ...]
    instructions: list[Instruction]
    artists: tuple[dict[str, list[Artist]], dict[str, list[Artist]]]
    scale_bar: Line2D
    check_bar: Line2D
    texts: list[str] = field(default_factory=list)

    def mm_per_unit(self, page: int = 0) -> float:
        """Millimetres on paper of one unit along x on ``page`` (0 or 1), from the figure.

        Computed from the figure size, the axes position and the axis limits
        (what the PDF backend uses), not from :attr:`scale`.
        """
        fig, ax = self.figures[page], self.axes[page]
        width_mm = ax.get_position().width * fig.get_figwidth() / _MM
        lo, hi = ax.get_xlim()
        return float(width_mm / (hi - lo))

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write both pages to the PDF file ``path`` (A4 portrait, no resizing); return it."""
        out = Path(path)
        title = getattr(self.construction.grasp, "title", None) or "a two-point grasp"
        with PdfPages(
            out, metadata={"Title": f"Worksheet: {title}", "Creator": "graspcompass"}
        ) as pdf:
            for fig in self.figures:
                pdf.savefig(fig)  # never bbox_inches="tight": the page size is the scale
        return out

    def save_png(self, path: str | os.PathLike[str], page: int = 0, dpi: float = 150) -> Path:
        """Write one page (0 or 1) as a PNG picture, e.g. for a web page.

        The text is set from measured widths, so it is rendered without font
        hinting, which would change the widths at screen resolutions.
        """
        import matplotlib

        out = Path(path)
        with matplotlib.rc_context({"text.hinting": "no_hinting"}):
            self.figures[page].savefig(out, format="png", dpi=dpi)
        return out

    def page_mm(self, page: int, xy: tuple[float, float]) -> tuple[float, float]:
        """Where the point ``xy`` (units) lies on ``page``, in mm from the lower left corner."""
        fig, ax = self.figures[page], self.axes[page]
        px, py = ax.transData.transform(xy)
        return float(px / fig.dpi / _MM), float(py / fig.dpi / _MM)


def worksheet_pages(
    construction_or_grasp: Any,
    *,
    steps: str = "all",
    given: str | Iterable[str] = "grasp",
    scale: float | None = None,
) -> Worksheet:
    """Make the two pages of the worksheet (see :func:`worksheet`) without writing them.

    Returns
    -------
    Worksheet
        The figures, the drawing axes, the scale, the instructions and the
        artists, for tests and for other uses.
    """
    from ..construction import Construction, internal_force_diagram
    from ..grasp import Grasp

    c = construction_or_grasp
    if isinstance(c, str):
        c = Grasp.preset(c)
    if not isinstance(c, Construction):
        if not isinstance(c, Grasp):
            raise TypeError(
                f"expected a Construction, a Grasp or a preset name, got {type(c).__name__}"
            )
        c = internal_force_diagram(c)
    if c.grasp is None:
        raise ValueError("the construction has no grasp to draw")
    if scale is not None and (
        isinstance(scale, bool)
        or not isinstance(scale, (int, float))
        or not math.isfinite(scale)
        or not SCALE_RANGE[0] <= scale <= SCALE_RANGE[1]
    ):
        raise ValueError(
            f"scale must be a number of mm per unit from {SCALE_RANGE[0]:g} "
            f"to {SCALE_RANGE[1]:g}, got {scale!r}"
        )
    selected = selected_names(c, steps)
    gnames = given_names(selected, given)
    sub = _sub_construction(c, selected, gnames)
    num = numeric_objects(sub)
    # the box draw_construction frames the same steps with, so that its labels are placed
    # in the final geometry
    box = view_box(c.grasp, num)
    instructions = instructions_for(c, selected, gnames, num=num)  # num: computed once
    ex = extra.exercise(sub, num)
    items = [(i.number, i.text) for i in instructions]
    if ex is not None:
        items.append(("read", extra.exercise_text(ex)))

    plans = [p for size in _FONTS for p in _plans(box, [_intro(c, gnames), _rules()], items, size)]
    if not plans:
        raise ValueError("the instructions do not leave room for a drawing on A4")
    # the largest drawing at the stated (rounded) scale, then the larger print
    plan, text_cols = max(plans, key=lambda p: (round_scale(p[0].fit), p[0].font))
    fit = plan.fit
    if scale is None:
        scale = round_scale(fit)
    elif scale > fit * (1 + 1e-12):
        raise ValueError(
            f"at {scale:g} mm per unit the drawing needs {(box[1] - box[0]) * scale:.0f} mm × "
            f"{(box[3] - box[2]) * scale:.0f} mm; at most {round_scale(fit):g} mm per unit "
            f"fits the {plan.area[2]:.0f} mm × {plan.area[3]:.0f} mm left on the page"
        )
    elif (box[1] - box[0]) * scale < MIN_DRAWING_MM:
        raise ValueError(
            f"at {scale:g} mm per unit the drawing is "
            f"{(box[1] - box[0]) * scale:.2g} mm wide, too small to draw in; give at "
            f"least {MIN_DRAWING_MM / (box[1] - box[0]):.2g} mm per unit"
        )
    scale = float(scale)
    which = (
        "all of §3.3" if steps == "all" else f"{steps} (§3.3, Fig. 4({'abcd'[int(steps[1]) - 1]}))"
    )
    title = getattr(c.grasp, "title", None) or "A two-point grasp"
    cone_len = extra.side_length(c.grasp, box, scale)  # 25-40 mm: a ruler lies along it
    figs, axes, arts = [], [], []
    texts: list[str] = []
    bars: list[Line2D] = []
    for page in (0, 1):
        fig = _new_page()
        head = (
            "Draw the internal force diagram by hand: "
            if page == 0
            else "Solution, at the same scale: "
        ) + which
        bars.append(_header(fig, head, [title, *_params_lines(c.grasp)], scale))
        ax = _place_axes(fig, box, scale, plan.area)
        theme = PAPER_THEME if page == 0 else DEFAULT_THEME
        # page 1: the given steps alone, labelled in this box (a cut of ``sub`` at their
        # number left the feet unnamed: the scene cuts by protocol index, ``sub`` keeps
        # the protocol's indices with the givens first)
        givens = Construction(sub.steps[: len(gnames)], sub.grasp, ())
        share_numeric(givens, num)  # computed once per worksheet
        out = draw_construction(
            sub if page == 1 else givens,
            ax=ax,
            theme=theme,
            num=num,
            box=box if page == 0 else None,
        )
        for key in ("cone1", "cone2"):
            for a in out.pop(key, []):
                a.remove()
        for key in ("x-axis", "y-axis"):  # their names go to the edge of this drawing
            for a in [a for a in out.get(key, []) if isinstance(a, Text)]:
                a.remove()
                out[key].remove(a)
        out["cones"] = _cones(ax, c.grasp, theme, cone_len)
        out["cone angles"] = extra.cone_angles(ax, c.grasp, cone_len) if page == 0 else []
        _finish_axes(ax, box)
        if page == 0:  # the givens alone: each name beside its point, no leader line
            for drawn in out.values():
                for a in [a for a in drawn if isinstance(a, Line2D) and a.get_gid() == "leader"]:
                    drawn.remove(a)
                    if a.axes is not None:
                        a.remove()
        point_labels = list(
            {
                id(a): a
                for k, drawn in out.items()
                if k in num
                for a in drawn
                if isinstance(a, Annotation) and a.axes is ax
            }.values()
        )
        if page == 0:  # P1, P2, O beside their points, clear of the sides and angles
            extra.mend_labels(
                ax,
                point_labels,
                [a for a in out["cones"] if isinstance(a, Line2D)],
                out["cone angles"],
                near=True,
            )
        unit_bar = _unit_bar(ax, box, scale)
        if page == 0:
            bars.append(unit_bar)
            for (x0, top, _), col in zip(plan.columns, text_cols):
                texts += _draw_blocks(fig, col, x0, top, plan.font)
        else:
            _transfer_marks(ax, sub, num, theme)
            x0, top, colw = plan.columns[0]
            rows = _solution_rows(sub, num, scale)
            if ex is not None:
                out["read off"] = extra.draw_ray(
                    ax, ex, theme, 1.15 * max(ex["k"], 0.2 * (box[1] - box[0]))
                )
                rows.append(("read", extra.exercise_answer(ex, scale)))
            sol = _layout_blocks(rows, colw, plan.font)
            _draw_blocks(fig, sol, x0, top, plan.font)
            out["inset"] = extra.page2_extras(
                fig,
                ax,
                sub,
                num,
                box,
                theme,
                plan.font,
                (x0, top - _height(sol, plan.font) - 3, colw),
                main=out,
            )
        figs.append(fig)
        axes.append(ax)
        arts.append(out)
    return Worksheet(
        (figs[0], figs[1]),
        (axes[0], axes[1]),
        scale,
        box,
        sub,
        gnames,
        instructions,
        (arts[0], arts[1]),
        bars[1],
        bars[0],
        texts,
    )


def worksheet(
    construction_or_grasp: Any,
    path: str | os.PathLike[str],
    *,
    steps: str = "all",
    given: str | Iterable[str] = "grasp",
    scale: float | None = None,
) -> Path:
    """Write a printable worksheet for drawing the internal force diagram by hand.

    Parameters
    ----------
    construction_or_grasp : Construction, Grasp or str
        The construction (:func:`graspcompass.internal_force_diagram`), a grasp
        with numeric parameters, or a preset name.
    path : str or path-like
        The PDF file to write (two A4 portrait pages).
    steps : {"all", "V1", "V2", "V3", "V4"}
        Instructions for every step of §3.3 and the outside extraction
        (eq. (25)), or for one V_n (eqs. (30)/(33)) and its circle (eq. (31)).
    given : str or iterable of str
        What page 1 already shows: a level of :data:`GIVEN_LEVELS` or step
        names (see :func:`given_names`).  The student draws the rest.
    scale : float, optional
        Millimetres per unit on paper (any unit: the grasp's numbers are
        unitless); by default the largest round value that fits the drawing on
        the page (:func:`round_scale`: whole millimetres from 10 mm up).

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    ValueError
        For a bad ``steps`` or ``given``, a symbolic grasp, or a ``scale``
        at which the drawing does not fit (the message names the largest that does).
    """
    ws = worksheet_pages(construction_or_grasp, steps=steps, given=given, scale=scale)
    return ws.save(path)
