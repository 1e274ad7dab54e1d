"""The page geometry of a worksheet and its text, set word by word.

The page is A4 portrait, measured in millimetres.  Text is set word by word: each
word is its own :class:`~matplotlib.text.Text`, placed at a measured offset, so
that mathtext parses short strings only (long mathtext lines take tens of ms
each); :func:`_plans` finds where the drawing and the columns of instructions go.
Private to :mod:`graspcompass.render.handdrawing`, which re-exports these names.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties

#: Width and height of an A4 page in millimetres (portrait).
A4_MM = (210.0, 297.0)
_MM = 1 / 25.4  # inches per mm
_MARGIN = 12.0  # side margins, mm
_TOP = 10.0  # top margin, mm
_BOTTOM = 10.0
_HEADER = 30.0  # title, scale, check bar
_GAP = 5.0  # between the drawing and the text
_FONTS = (7.6, 7.2)  # instructions, pt: the smaller one when it gives a larger drawing
_LINE = 1.36  # line height, in font sizes
_OVER = 0.3  # extra space above a line with an overline ($\overline{O_MX_1}$), in font sizes
_NUMBER_W = 11.0  # width of the step number column, mm
_COL_GAP = 6.0


# Text is set word by word: each word is its own Text, placed at a measured offset, so that
# mathtext parses short strings only (long mathtext lines take tens of ms each).
_MEASURE_DPI = 1200  # text widths come in whole pixels: measure finely


@lru_cache(maxsize=1)
def _renderer() -> Any:
    fig = Figure(figsize=(1, 1), dpi=_MEASURE_DPI)
    return FigureCanvasAgg(fig).get_renderer()


#: One word of a line: offset from the line start (mm), the text, bold or not.
_Word = tuple[float, str, bool]


@lru_cache(maxsize=8192)
def _width_mm(text: str, size: float, bold: bool = False) -> float:
    r = _renderer()
    ismath: Any = text.count("$") >= 2 and text.count("$") % 2 == 0
    prop = FontProperties(size=size, weight="bold" if bold else "normal")
    w, _, _ = r.get_text_width_height_descent(text, prop, ismath=ismath)
    return w / _MEASURE_DPI / _MM


def _words(text: str) -> list[tuple[str, bool]]:
    """Words of ``text``, math kept whole; ``#12`` is the bold step number ``12``."""
    out: list[str] = []
    for part in re.findall(r"\S+", text):
        if out and out[-1].count("$") % 2 == 1:  # inside math: keep together
            out[-1] += " " + part
        else:
            out.append(part)
    return [(w[1:], True) if re.fullmatch(r"#\d+", w) else (w, False) for w in out]


def _wrap(text: str, width_mm: float, size: float) -> list[list[_Word]]:
    """Greedy line breaking at spaces outside ``$...$``; each word measured once."""
    space = _width_mm("a a", size) - _width_mm("aa", size)
    lines: list[list[_Word]] = []
    cur: list[_Word] = []
    x = 0.0
    for w, bold in _words(text):
        ww = _width_mm(w, size, bold)
        if cur and x + ww > width_mm:
            lines.append(cur)
            cur, x = [], 0.0
        cur.append((x, w, bold))
        x += ww + space
    if cur:
        lines.append(cur)
    return lines


def _runs(line: list[_Word], size: float) -> list[_Word]:
    """Consecutive plain words joined into one text (fewer artists, faster drawing), each
    run placed after the measured width of the one before."""
    merged: list[tuple[str, bool]] = []
    for _, w, bold in line:
        plain = not bold and "$" not in w
        if merged and plain and not merged[-1][1] and "$" not in merged[-1][0]:
            merged[-1] = (f"{merged[-1][0]} {w}", False)
        else:
            merged.append((w, bold))
    space = _width_mm("a a", size) - _width_mm("aa", size)
    out: list[_Word] = []
    x = 0.0
    for w, bold in merged:
        out.append((x, w, bold))
        x += _width_mm(w, size, bold) + space
    return out


def _line_text(line: list[_Word]) -> str:
    return " ".join(w for _, w, _ in line)


def _rules() -> str:
    return (
        "Signs: $\\overline{O_MX_n} = x(X_n) - x(O_M)$ is positive when $X_n$ lies to "
        "the right of $O_M$, negative to the left; $\\overline{OY_n} = y(Y_n)$ is positive "
        "when $Y_n$ lies above $O$.  Transfer: $V_n = (-\\overline{O_MX_n}, "
        "-\\overline{OY_n})$ is laid off from $O$, not from $O_M$: its x-coordinate has "
        "the length $O_MX_n$ and points the other way; its y-coordinate is $Y_n$ mirrored "
        "through $O$ (eqs. (28)-(30), (33)-(39); Appendix (A7)-(A8))."
    )


@dataclass
class _Block:
    number: str
    lines: list[list[_Word]]


def _layout_blocks(items: list[tuple[str, str]], width: float, size: float) -> list[_Block]:
    return [
        _Block(num, _wrap(text, width - (_NUMBER_W if num else 0), size)) for num, text in items
    ]


def _columns(blocks: list[_Block], ncols: int) -> list[list[_Block]]:
    """Split the blocks into ``ncols`` columns of about equal height, in order."""
    total = sum(len(b.lines) + 0.6 for b in blocks)
    cols: list[list[_Block]] = [[]]
    used = 0.0
    for b in blocks:
        if (
            len(cols) < ncols
            and cols[-1]
            and used + (len(b.lines) + 0.6) / 2 > total * len(cols) / ncols
        ):
            cols.append([])
        cols[-1].append(b)
        used += len(b.lines) + 0.6
    return cols


def _lead(ln: list[_Word]) -> float:
    """Height of one line in font sizes: more above a line with an overline, which mathtext
    sets above the capitals, so that it does not cut through the line above."""
    return _LINE + (_OVER if any("\\overline" in w for _, w, _ in ln) else 0.0)


def _block_lines(b: _Block) -> float:
    """Height of a block and the gap after it, in font sizes."""
    return sum(_lead(ln) for ln in b.lines) + 0.6 * _LINE


def _height(col: list[_Block], size: float) -> float:
    return sum(_block_lines(b) for b in col) * size / 72 / _MM


def _draw_blocks(
    fig: Figure, col: list[_Block], x0: float, top_mm: float, size: float
) -> list[str]:
    """Set one column of blocks from ``(x0, top_mm)`` down; return its lines as text."""
    W, H = A4_MM
    em = size / 72 / _MM  # one font size, mm
    shown = []
    y = top_mm - 0.75 * em
    for b in col:
        xt = x0 + (_NUMBER_W if b.number else 0)
        yl = y
        for j, ln in enumerate(b.lines):
            # the first line moves down by its extra lead, each further one by its lead
            yl -= (_lead(ln) - (_LINE if j == 0 else 0.0)) * em
            if j == 0 and b.number:
                fig.text(x0 / W, yl / H, b.number, fontsize=size, weight="bold", va="baseline")
            for dx, w, bold in _runs(ln, size):
                fig.text(
                    (xt + dx) / W,
                    yl / H,
                    w,
                    fontsize=size,
                    weight="bold" if bold else "normal",
                    va="baseline",
                )
            shown.append((b.number + " " if j == 0 and b.number else "") + _line_text(ln))
        y -= _block_lines(b) * em
    return shown


def _fits(box: tuple[float, float, float, float], w_mm: float, h_mm: float) -> float:
    return min(w_mm / (box[1] - box[0]), h_mm / (box[3] - box[2]))


@dataclass
class _Plan:
    """Where things go on the page (mm from the lower left corner)."""

    area: tuple[float, float, float, float]  # the drawing: x0, y0, width, height
    columns: list[tuple[float, float, float]]  # text columns: x0, top, width
    fit: float  # the largest scale that fits, mm per unit
    font: float  # size of the instructions, pt


def _plans(
    box: tuple[float, float, float, float],
    intro: list[str],
    items: list[tuple[str, str]],
    size: float,
) -> list[tuple[_Plan, list[list[_Block]]]]:
    """The ways to lay out page 1 that fit: the text below the drawing in one or two
    to three columns, or in a column to the right of it."""
    W, H = A4_MM
    width = W - 2 * _MARGIN
    top = H - _TOP - _HEADER
    out = []
    for ncols in (1, 2, 3):
        colw = (width - (ncols - 1) * _COL_GAP) / ncols
        head = _layout_blocks([("", t) for t in intro], width, size)
        cols = _columns(_layout_blocks(items, colw, size), ncols)
        text_h = _height(head, size) + max(_height(c, size) for c in cols)
        area_h = top - _BOTTOM - text_h - _GAP
        if area_h <= 10:
            continue
        area = (_MARGIN, top - area_h, width, area_h)
        below = area[1] - _GAP - _height(head, size)
        columns = [(_MARGIN, area[1] - _GAP, width)] + [
            (_MARGIN + k * (colw + _COL_GAP), below, colw) for k in range(ncols)
        ]
        out.append((_Plan(area, columns, _fits(box, area[2], area[3]), size), [head, *cols]))
    for colw in (62.0, 78.0):
        blocks = _layout_blocks([("", t) for t in intro] + items, colw, size)
        if _height(blocks, size) > top - _BOTTOM:
            continue
        area = (_MARGIN, _BOTTOM, width - colw - _COL_GAP, top - _BOTTOM)
        columns = [(W - _MARGIN - colw, top, colw)]
        out.append((_Plan(area, columns, _fits(box, area[2], area[3]), size), [blocks]))
    return out
