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
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon
from matplotlib.text import Text

from ..layout import numeric_objects, view_box, wedge
from .figure import draw_construction
from .theme import DEFAULT_THEME, PAPER_THEME, Theme

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

#: Width and height of an A4 page in millimetres (portrait).
A4_MM = (210.0, 297.0)
#: Values of ``steps``: every step, or the steps of one V_n.
STEP_CHOICES = ("all", "V1", "V2", "V3", "V4")
#: Values of ``given``, each including the ones before it: what is drawn on page 1.
GIVEN_LEVELS = ("grasp", "feet", "sides", "perpendiculars")
#: Smallest and largest scale (mm per unit) accepted; the unit of the grasp is anything.
SCALE_RANGE = (1e-6, 1e6)
#: Smallest width of the drawing, mm: a smaller scale is refused.
MIN_DRAWING_MM = 20.0

_MM = 1 / 25.4  # inches per mm
_MARGIN = 12.0  # side margins, mm
_TOP = 10.0  # top margin, mm
_BOTTOM = 10.0
_HEADER = 30.0  # title, scale, check bar
_GAP = 5.0  # between the drawing and the text
_FONTS = (7.6, 7.2)  # instructions, pt: the smaller one when it gives a larger drawing
_LINE = 1.36  # line height, in font sizes
_NUMBER_W = 11.0  # width of the step number column, mm
_COL_GAP = 6.0
_WORD = {1: "upper", 2: "upper", 3: "lower", 4: "lower"}
_COMMON = ("O", "x-axis", "y-axis", "P1", "P2", "P1x", "P2x", "O_M")
_GREEK = {"phi": "φ", "mu": "μ", "xi": "ξ"}


@dataclass(frozen=True)
class Instruction:
    """One numbered instruction of the worksheet.

    Attributes
    ----------
    steps : tuple of int
        Protocol indices (as ``graspcompass steps`` prints them) the instruction makes.
    names : tuple of str
        Names of the objects made (``"X1"``).
    text : str
        The instruction in words, mathtext allowed (``$X_1$``), ending with the
        paper's reference in brackets.
    """

    steps: tuple[int, ...]
    names: tuple[str, ...]
    text: str

    @property
    def number(self) -> str:
        """The label printed before the text: ``"12"`` or ``"40–45"``."""
        a, b = self.steps[0], self.steps[-1]
        return str(a) if a == b else f"{a}–{b}"


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
        with PdfPages(out, metadata={"Title": f"Worksheet: {title}",
                                     "Creator": "graspcompass"}) as pdf:
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


# -- which steps -----------------------------------------------------------------------------
def _n_of(name: str) -> int | None:
    m = re.fullmatch(r"(?:side|X|perp|Y|OMX|OY|V|circle)([1-4])", name)
    return int(m.group(1)) if m else None


def selected_names(construction: Any, steps: str = "all") -> tuple[str, ...]:
    """Names of the protocol steps of a worksheet for ``steps``, in protocol order.

    ``"all"`` is every step; ``"Vn"`` the steps that draw V_n (§3.3): the axes,
    the contacts, the cone side n, P1x, P2x, O_M, X_n, the perpendicular, Y_n,
    the two signed lengths, V_n and the circle on O V_n (eq. (31)-(32)).

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> selected_names(internal_force_diagram(), "V2")[5:]
    ('side2', 'P1x', 'P2x', 'O_M', 'X2', 'perp2', 'Y2', 'OMX2', 'OY2', 'V2', 'circle2')
    """
    if steps not in STEP_CHOICES:
        raise ValueError(f"steps must be one of {', '.join(STEP_CHOICES)}, got {steps!r}")
    if steps == "all":
        return tuple(construction.names)
    want = int(steps[1])
    keep = []
    for s in construction.steps:
        n = _n_of(s.name)
        if n == want or (n is None and s.name in _COMMON):
            keep.append(s.name)
    return tuple(keep)


def given_names(selected: Sequence[str], given: str | Iterable[str] = "grasp") -> tuple[str, ...]:
    """Names of the objects drawn on page 1 (always O, the axes, P1 and P2).

    ``given`` is a level of :data:`GIVEN_LEVELS` (``"grasp"``: O, the axes,
    P1, P2 and the friction cones; ``"feet"``: also P1x, P2x, O_M; ``"sides"``:
    also the extended cone sides and X_n; ``"perpendiculars"``: also the
    perpendiculars and Y_n) or names of protocol steps (a list, or one string
    with commas), added to the grasp.

    Raises
    ------
    ValueError
        For an unknown level or a name that is not a step of the worksheet.

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> sel = selected_names(internal_force_diagram(), "V1")
    >>> given_names(sel, "sides")
    ('O', 'x-axis', 'y-axis', 'P1', 'P2', 'side1', 'P1x', 'P2x', 'O_M', 'X1')
    >>> given_names(sel, "P1x, P2x")
    ('O', 'x-axis', 'y-axis', 'P1', 'P2', 'P1x', 'P2x')
    """
    base = {"O", "x-axis", "y-axis", "P1", "P2"}
    if isinstance(given, str) and given.strip() in GIVEN_LEVELS:
        level = GIVEN_LEVELS.index(given.strip())
        want = set(base)
        if level >= 1:
            want |= {"P1x", "P2x", "O_M"}
        if level >= 2:
            want |= {s for s in selected if re.fullmatch(r"(side|X)[1-4]", s)}
        if level >= 3:
            want |= {s for s in selected if re.fullmatch(r"(perp|Y)[1-4]", s)}
    else:
        items = given.split(",") if isinstance(given, str) else list(given)
        names = [str(x).strip() for x in items if str(x).strip()]
        if not names:
            raise ValueError(f"given: expected one of {', '.join(GIVEN_LEVELS)} or names of "
                             "steps separated by commas")
        bad = [x for x in names if x not in selected]
        if bad:
            raise ValueError(
                f"given: {bad[0]!r} is not a step of this worksheet; use one of "
                f"{', '.join(GIVEN_LEVELS)} or names among {', '.join(selected[5:])}")
        want = base | set(names)
    return tuple(s for s in selected if s in want)


# -- the instructions ------------------------------------------------------------------------
def _m(name: str) -> str:
    """Mathtext of a point name: ``P1x`` -> ``$P_{1x}$``."""
    special = {"O_M": "O_M", "P1x": "P_{1x}", "P2x": "P_{2x}"}
    if name in special:
        return f"${special[name]}$"
    m = re.fullmatch(r"([A-Z])(\d+)", name)
    return f"${m.group(1)}_{{{m.group(2)}}}$" if m else name


def _side_parts(n: int) -> tuple[int, str, str]:
    """(contact i, foot of the perpendicular, word) of cone side n (§3.3)."""
    i = 1 if n in (1, 3) else 2
    return i, ("P2x" if i == 1 else "P1x"), _WORD[n]


def _text(step: Any, num: dict[str, Any]) -> str:
    """One step of the protocol in words, for a person with ruler and compass (§3.3)."""
    name, n = step.name, _n_of(step.name)
    if name in ("P1x", "P2x"):
        p = _m(name[:2])
        return (f"Drop the perpendicular from {p} to the x-axis (set square, or an arc about "
                f"{p} cutting the x-axis twice, then bisect): its foot is {_m(name)}.")
    if name == "O_M":
        same = ("  Here $x_1 = x_2$, so $O_M$ is $O$."
                if abs(num["O_M"][0]) <= 1e-12 * max(1.0, abs(num["P1"][0])) else "")
        return ("Bisect $P_{1x}P_{2x}$ with the compass (equal arcs about both ends, join "
                "their two crossings): the midpoint is $O_M$." + same)
    if name == "envelope":
        return ("Outside extraction: in every direction from $O$ trace the outermost arc of the "
                "circles (where every circle lies behind $O$, the outline passes through $O$): "
                "$k_{grasp}(\\theta)$, eq. (25), Fig. 5.")
    if n is None:
        return step.caption + "."
    i, foot, word = _side_parts(n)
    P, X, Y, V, F = (_m(f"P{i}"), _m(f"X{n}"), _m(f"Y{n}"), _m(f"V{n}"), _m(foot))
    omx, oy = f"$\\overline{{O_MX_{n}}}$", f"$\\overline{{OY_{n}}}$"
    kind = re.sub(r"[1-4]$", "", name)
    return {
        "side": (f"Lay the ruler along the {word} side of the friction cone at {P} and extend "
                 "it across the sheet, well past the x-axis."),
        "X": f"Mark where the extended {word} side of the cone at {P} meets the x-axis: {X}.",
        "perp": (f"Draw the perpendicular from {F} to the line {P}{X} (the {word} side at {P}), "
                 "long enough to cross the y-axis."),
        "Y": f"Mark where this perpendicular meets the y-axis: {Y}.",
        "OMX": (f"Open the compass from $O_M$ to {X}: the signed length {omx}, + if {X} lies "
                f"right of $O_M$, − if left (it is $-S_{n}$)."),
        "OY": (f"Open the compass from $O$ to {Y}: the signed length {oy}, + if {Y} lies above "
               f"$O$, − if below (it is $-C_{n}$)."),
        "V": (f"Transfer to $O$ (not $O_M$): mark the x-axis at the distance $O_MX_{n}$ from $O$ "
              f"on the side opposite to the direction $O_M \\to X_{n}$, and mark {Y} mirrored "
              f"through $O$ on the y-axis; the perpendiculars to the axes there meet at "
              f"{V} = $(-\\overline{{O_MX_{n}}}, -\\overline{{OY_{n}}})$."),
        "circle": (f"Bisect $OV_{n}$ for the centre and draw the circle through $O$ and {V}: "
                   f"the polar graph of $k_{n}(\\theta)$ (Thales, Fig. 3)."),
    }.get(kind, step.caption + ".")


def _ref_bits(ref: str) -> list[str]:
    return re.findall(r"Fig\. \d\(\w\)|eq\. \S+", ref)


def _brief_block(c: Any, n: int, todo: list[Any], first: int) -> Instruction:
    """The steps of V_n (n after the first) as one instruction, each step numbered."""
    i, foot, word = _side_parts(n)
    P, X, Y, V, F = (_m(f"P{i}"), _m(f"X{n}"), _m(f"Y{n}"), _m(f"V{n}"), _m(foot))
    parts = {
        "X": f"mark {X} where the {word} side at {P} meets the x-axis;",
        "perp": f"draw the perpendicular from {F} to the line {P}{X},",
        "Y": f"it meets the y-axis at {Y};",
        "OMX": f"measure $\\overline{{O_MX_{n}}}$",
        "OY": f"and $\\overline{{OY_{n}}}$ with their signs;",
        "V": f"lay them off from $O$: {V} = $(-\\overline{{O_MX_{n}}}, -\\overline{{OY_{n}}})$.",
    }
    words = [f"{V}, as {_m(f'V{first}')}:"]
    for s in todo:
        words.append(f"#{s.index} {parts[re.sub(r'[1-4]$', '', s.name)]}")
    refs = _ref_bits(c.step(f"X{n}").ref) + _ref_bits(c.step(f"V{n}").ref)
    text = " ".join(words) + f" [§3.3 V{n} steps (1)-(3), {', '.join(refs)}]"
    return Instruction(tuple(s.index for s in todo), tuple(s.name for s in todo), text)


def instructions_for(construction: Any, names: Sequence[str],
                     given: Sequence[str] = ()) -> list[Instruction]:
    """The numbered instructions for the steps ``names`` not in ``given``, in protocol order.

    Each carries the protocol indices of its steps (as ``graspcompass steps``
    prints them) and ends with the paper's reference from the steps.  With one
    V_n, every step is an instruction.  With more, the first V_n is explained
    step by step and each further V_n is one instruction numbering its steps
    (``#18``, printed bold), and the cone sides, the feet, the circles and the
    second intersections are grouped.

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> c = internal_force_diagram()
    >>> ins = instructions_for(c, selected_names(c, "V1"), ("O", "x-axis", "y-axis", "P1", "P2"))
    >>> [(i.number, i.names[0]) for i in ins][4:7]
    [('12', 'X1'), ('13', 'perp1'), ('14', 'Y1')]
    >>> print(ins[4].text)  # doctest: +NORMALIZE_WHITESPACE
    Mark where the extended upper side of the cone at $P_{1}$ meets the x-axis: $X_{1}$.
    [§3.3 V1 step (1), Fig. 4(a)]
    >>> [i.number for i in instructions_for(c, c.names, ("O", "x-axis", "y-axis", "P1", "P2"))]
    ... # doctest: +NORMALIZE_WHITESPACE
    ['5–8', '9–10', '11', '12', '13', '14', '15', '16', '17', '18–23', '24–29', '30–35',
     '36–39', '40–45', '46']
    """
    num = numeric_objects(construction)
    given = set(given)
    todo = sorted((construction.step(n) for n in names if n not in given),
                  key=lambda s: s.index)
    ns = sorted({_n_of(s.name) for s in todo if _n_of(s.name) and not s.name.startswith(
        ("side", "circle"))})
    compact = len({_n_of(n) for n in names if _n_of(n)}) > 1
    first = ns[0] if ns else None
    out: list[Instruction] = []
    done: set[str] = set()

    def group(kind: str) -> list[Any]:
        return [s for s in todo if re.fullmatch(kind, s.name)]

    for s in todo:
        if s.name in done:
            continue
        n = _n_of(s.name)
        members: list[Any] = []
        if compact and s.name.startswith("side"):
            members = group(r"side[1-4]")
            listed = "; ".join(f"#{m.index} the {_WORD[_n_of(m.name) or 1]} side at "
                               f"{_m('P' + str(_side_parts(_n_of(m.name) or 1)[0]))}"
                               for m in members)
            text = (f"Extend the sides of the friction cones across the sheet with the ruler: "
                    f"{listed}. [{s.ref}]")
        elif compact and s.name in ("P1x", "P2x"):
            members = group(r"P[12]x")
            text = ("Drop the perpendiculars from " + " and ".join(
                f"#{m.index} {_m(m.name[:2])}" for m in members) + " to the x-axis: their "
                "feet are $P_{1x}$, $P_{2x}$. [§3.3]")
        elif compact and n is not None and n != first and not s.name.startswith(
                ("side", "circle")):
            members = [m for m in todo if _n_of(m.name) == n
                       and not m.name.startswith(("side", "circle"))]
            ins = _brief_block(construction, n, members, first or 1)
            out.append(ins)
            done.update(ins.names)
            continue
        elif compact and s.name.startswith("circle"):
            members = group(r"circle[1-4]")
            m0 = _n_of(members[0].name)
            more = ", ".join(f"#{m.index} $OV_{_n_of(m.name)}$" for m in members[1:])
            text = (f"#{members[0].index} Bisect $OV_{m0}$ for the centre and draw the circle "
                    f"through $O$ and $V_{m0}$: the polar graph of $k_{m0}(\\theta)$ (Thales, "
                    f"Fig. 3)" + (f"; likewise the circles on {more}." if more else ".")
                    + f" [{s.ref}]")
        elif s.op == "second_intersection":
            members = group(r"B\d\d")
            listed = ", ".join(f"#{b.index} $B_{{{b.name[1:]}}}$" for b in members)
            text = f"Mark where two circles cross besides $O$: {listed}. [{s.ref}]"
        if members:
            out.append(Instruction(tuple(m.index for m in members),
                                   tuple(m.name for m in members), text))
            done.update(m.name for m in members)
            continue
        out.append(Instruction((s.index,), (s.name,),
                               f"{_text(s, num)} [{s.ref}]"))
    return out


# -- text layout -----------------------------------------------------------------------------
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
    return ("Signs: $\\overline{O_MX_n} = x(X_n) - x(O_M)$ is positive when $X_n$ lies to "
            "the right of $O_M$, negative to the left; $\\overline{OY_n} = y(Y_n)$ is positive "
            "when $Y_n$ lies above $O$.  Transfer: $V_n = (-\\overline{O_MX_n}, "
            "-\\overline{OY_n})$ is laid off from $O$, not from $O_M$: its x-coordinate has "
            "the length $O_MX_n$ and points the other way; its y-coordinate is $Y_n$ mirrored "
            "through $O$ (eqs. (28)-(30), (33)-(39); Appendix (A7)-(A8)).")


@dataclass
class _Block:
    number: str
    lines: list[list[_Word]]


def _layout_blocks(items: list[tuple[str, str]], width: float, size: float) -> list[_Block]:
    return [_Block(num, _wrap(text, width - (_NUMBER_W if num else 0), size))
            for num, text in items]


def _columns(blocks: list[_Block], ncols: int) -> list[list[_Block]]:
    """Split the blocks into ``ncols`` columns of about equal height, in order."""
    total = sum(len(b.lines) + 0.6 for b in blocks)
    cols: list[list[_Block]] = [[]]
    used = 0.0
    for b in blocks:
        if (len(cols) < ncols and cols[-1]
                and used + (len(b.lines) + 0.6) / 2 > total * len(cols) / ncols):
            cols.append([])
        cols[-1].append(b)
        used += len(b.lines) + 0.6
    return cols


def _height(col: list[_Block], size: float) -> float:
    line = size * _LINE / 72 / _MM
    return sum(len(b.lines) + 0.6 for b in col) * line


def _draw_blocks(fig: Figure, col: list[_Block], x0: float, top_mm: float,
                 size: float) -> list[str]:
    """Set one column of blocks from ``(x0, top_mm)`` down; return its lines as text."""
    W, H = A4_MM
    line = size * _LINE / 72 / _MM
    ascent = 0.75 * size / 72 / _MM
    shown = []
    y = top_mm - ascent
    for b in col:
        if b.number:
            fig.text(x0 / W, y / H, b.number, fontsize=size, weight="bold", va="baseline")
        xt = x0 + (_NUMBER_W if b.number else 0)
        for j, ln in enumerate(b.lines):
            for dx, w, bold in _runs(ln, size):
                fig.text((xt + dx) / W, (y - j * line) / H, w, fontsize=size,
                         weight="bold" if bold else "normal", va="baseline")
            shown.append((b.number + " " if j == 0 and b.number else "") + _line_text(ln))
        y -= (len(b.lines) + 0.6) * line
    return shown


@dataclass
class _Plan:
    """Where things go on the page (mm from the lower left corner)."""

    area: tuple[float, float, float, float]  # the drawing: x0, y0, width, height
    columns: list[tuple[float, float, float]]  # text columns: x0, top, width
    fit: float  # the largest scale that fits, mm per unit
    font: float  # size of the instructions, pt


def _plans(box: tuple[float, float, float, float], intro: list[str],
           items: list[tuple[str, str]], size: float
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
            (_MARGIN + k * (colw + _COL_GAP), below, colw) for k in range(ncols)]
        out.append((_Plan(area, columns, _fits(box, area[2], area[3]), size), [head, *cols]))
    for colw in (62.0, 78.0):
        blocks = _layout_blocks([("", t) for t in intro] + items, colw, size)
        if _height(blocks, size) > top - _BOTTOM:
            continue
        area = (_MARGIN, _BOTTOM, width - colw - _COL_GAP, top - _BOTTOM)
        columns = [(W - _MARGIN - colw, top, colw)]
        out.append((_Plan(area, columns, _fits(box, area[2], area[3]), size), [blocks]))
    return out


# -- the pages -------------------------------------------------------------------------------
def _params_lines(grasp: Any, width_mm: float = A4_MM[0] - 2 * _MARGIN) -> list[str]:
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


def _sub_construction(construction: Any, selected: Sequence[str],
                      given: Sequence[str]) -> Any:
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


def _fits(box: tuple[float, float, float, float], w_mm: float, h_mm: float) -> float:
    return min(w_mm / (box[1] - box[0]), h_mm / (box[3] - box[2]))


def _new_page() -> Figure:
    fig = Figure(figsize=(A4_MM[0] * _MM, A4_MM[1] * _MM), dpi=72)
    FigureCanvasAgg(fig)
    return fig


def _place_axes(fig: Figure, box: tuple[float, float, float, float], scale: float,
                area: tuple[float, float, float, float]) -> Axes:
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
        ax.annotate("x", (box[1], 0.0), xytext=(-3, -3), textcoords="offset points",
                    ha="right", va="top", style="italic", fontsize=9)
    if box[0] < 0 < box[1]:
        ax.annotate("y", (0.0, box[3]), xytext=(3, -3), textcoords="offset points",
                    ha="left", va="top", style="italic", fontsize=9)


def _cones(ax: Axes, grasp: Any, theme: Theme, length: float) -> list[Artist]:
    """Both friction cones (Fig. 2) as shaded wedges with their two sides drawn, so that a
    ruler can be laid along each side (§3.3 step (1))."""
    arts: list[Artist] = []
    for i, (a, b) in ((1, (1, 3)), (2, (2, 4))):
        apex = (float(grasp.P1.x if i == 1 else grasp.P2.x),
                float(grasp.P1.y if i == 1 else grasp.P2.y))
        da, db = (tuple(float(v) for v in (d.x, d.y))
                  for d in (grasp.side_direction(a), grasp.side_direction(b)))
        poly = wedge(apex, da, db, length)
        arts.append(ax.add_patch(Polygon(poly, closed=True, facecolor=theme.cone_face,
                                         alpha=theme.cone_alpha, edgecolor="none",
                                         zorder=1)))
        for d in (da, db):
            k = length / math.hypot(*d)
            arts += ax.plot([apex[0], apex[0] + k * d[0]], [apex[1], apex[1] + k * d[1]],
                            color="black", lw=1.0, zorder=2.7, solid_capstyle="butt")
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
    bar = Line2D([x0 / W, (x0 + 100) / W], [y / H, y / H], transform=fig.transFigure,
                 color="black", lw=0.8, solid_capstyle="butt")
    fig.add_artist(bar)
    for k in range(11):
        t = 2.0 if k % 5 == 0 else 1.2
        fig.add_artist(Line2D([(x0 + 10 * k) / W] * 2, [y / H, (y + t) / H],
                              transform=fig.transFigure, color="black", lw=0.5))
    fig.text((x0 + 104) / W, (y + 1.5) / H, f"Scale: 1 unit = {scale:g} mm",
             fontsize=10, weight="bold", va="baseline")
    fig.text((x0 + 104) / W, (y - 2.2) / H,
             "The bar is 100 mm: print at actual size (100 %) and check it with a ruler.",
             fontsize=6.5, va="baseline")
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
    ax.annotate(f"1 unit = {scale:g} mm", ((x0 + x1) / 2, y), xytext=(0, 3),
                textcoords="offset points", ha="center", va="bottom", fontsize=7, zorder=7)
    return bar


def _transfer_marks(ax: Axes, construction: Any, num: dict[str, Any], theme: Theme) -> None:
    """On the solution: −O_M X_n and −O Y_n laid off from O, and the rectangle to V_n."""
    for s in construction.steps:
        n = _n_of(s.name)
        if not (s.name.startswith("V") and n):
            continue
        vx, vy = num[s.name]
        color = theme.circle_color(n)
        ax.plot([vx, vx, 0.0], [0.0, vy, vy], color=color, lw=0.6, ls=":", zorder=2.3)
        ax.plot([vx, 0.0], [0.0, vy], ls="none", marker="o", ms=3.0, mfc="white",
                mec=color, mew=0.8, zorder=5)


def _solution_rows(sub: Any, num: dict[str, Any], scale: float) -> list[tuple[str, str]]:
    rows = [("", "Check your drawing: lay this page on yours against a window, or measure "
                 "with a ruler.  Signed lengths in units and, in brackets, in mm on the page; "
                 "the dotted lines are the transfer to $O$ (eqs. (28)-(30), (33)-(39)).")]
    for n in (1, 2, 3, 4):
        if f"V{n}" not in num:
            continue
        omx, oy = num[f"OMX{n}"] + 0.0, num[f"OY{n}"] + 0.0  # no "-0.000"
        vx, vy = num[f"V{n}"][0] + 0.0, num[f"V{n}"][1] + 0.0
        rows.append((f"V{n}", (
            f"$\\overline{{O_MX_{n}}}$ = {omx:+.3f} ({omx * scale:+.1f} mm),  "
            f"$\\overline{{OY_{n}}}$ = {oy:+.3f} ({oy * scale:+.1f} mm),  so  "
            f"$V_{n}$ = ({vx:+.3f}, {vy:+.3f}), i.e. ({vx * scale:+.1f} mm, {vy * scale:+.1f} mm) "
            "from $O$.")))
    return rows


def _intro(c: Any, given: Sequence[str]) -> str:
    extra = [g for g in given if g not in ("O", "x-axis", "y-axis", "P1", "P2")]
    more = ""
    if extra:
        more = "; also " + ", ".join(f"#{c.step(g).index} {_m(g)}" for g in extra)
    return ("Already drawn (steps 0-4): $O$, the x- and y-axis, $P_1$, $P_2$ and the "
            f"friction cones with their sides{more}.  Draw the numbered steps in order with "
            "ruler, compass and set square (numbers as printed by graspcompass steps).")


def worksheet_pages(construction_or_grasp: Any, *, steps: str = "all",
                    given: str | Iterable[str] = "grasp",
                    scale: float | None = None) -> Worksheet:
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
            raise TypeError(f"expected a Construction, a Grasp or a preset name, got "
                            f"{type(c).__name__}")
        c = internal_force_diagram(c)
    if c.grasp is None:
        raise ValueError("the construction has no grasp to draw")
    if scale is not None and (isinstance(scale, bool) or not isinstance(scale, (int, float))
                              or not math.isfinite(scale)
                              or not SCALE_RANGE[0] <= scale <= SCALE_RANGE[1]):
        raise ValueError(f"scale must be a number of mm per unit from {SCALE_RANGE[0]:g} "
                         f"to {SCALE_RANGE[1]:g}, got {scale!r}")
    selected = selected_names(c, steps)
    gnames = given_names(selected, given)
    sub = _sub_construction(c, selected, gnames)
    num = numeric_objects(sub)
    # the box draw_construction frames the same steps with, so that its labels are placed
    # in the final geometry
    box = view_box(c.grasp, num)
    instructions = instructions_for(c, selected, gnames)

    plans = [p for size in _FONTS for p in _plans(
        box, [_intro(c, gnames), _rules()], [(i.number, i.text) for i in instructions], size)]
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
            f"fits the {plan.area[2]:.0f} mm × {plan.area[3]:.0f} mm left on the page")
    elif (box[1] - box[0]) * scale < MIN_DRAWING_MM:
        raise ValueError(f"at {scale:g} mm per unit the drawing is "
                         f"{(box[1] - box[0]) * scale:.2g} mm wide, too small to draw in; give at "
                         f"least {MIN_DRAWING_MM / (box[1] - box[0]):.2g} mm per unit")
    scale = float(scale)
    which = ("all of §3.3" if steps == "all" else
             f"{steps} (§3.3, Fig. 4({'abcd'[int(steps[1]) - 1]}))")
    title = getattr(c.grasp, "title", None) or "A two-point grasp"
    cone_len = min(0.45 * math.dist(num["P1"], num["P2"]), 22.0 / scale)  # at most 22 mm
    figs, axes, arts = [], [], []
    texts: list[str] = []
    bars: list[Line2D] = []
    for page in (0, 1):
        fig = _new_page()
        head = ("Draw the internal force diagram by hand: " if page == 0
                else "Solution, at the same scale: ") + which
        bars.append(_header(fig, head, [title, *_params_lines(c.grasp)], scale))
        ax = _place_axes(fig, box, scale, plan.area)
        theme = PAPER_THEME if page == 0 else DEFAULT_THEME
        out = draw_construction(sub, step=len(gnames) - 1 if page == 0 else None, ax=ax,
                                theme=theme)
        for key in ("cone1", "cone2"):
            for a in out.pop(key, []):
                a.remove()
        for key in ("x-axis", "y-axis"):  # their names go to the edge of this drawing
            for a in [a for a in out.get(key, []) if isinstance(a, Text)]:
                a.remove()
                out[key].remove(a)
        out["cones"] = _cones(ax, c.grasp, theme, cone_len)
        _finish_axes(ax, box)
        unit_bar = _unit_bar(ax, box, scale)
        if page == 0:
            bars.append(unit_bar)
            for (x0, top, _), col in zip(plan.columns, text_cols):
                texts += _draw_blocks(fig, col, x0, top, plan.font)
        else:
            _transfer_marks(ax, sub, num, theme)
            x0, top, colw = plan.columns[0]
            sol = _layout_blocks(_solution_rows(sub, num, scale), colw, plan.font)
            _draw_blocks(fig, sol, x0, top, plan.font)
        figs.append(fig)
        axes.append(ax)
        arts.append(out)
    return Worksheet((figs[0], figs[1]), (axes[0], axes[1]), scale, box, sub, gnames,
                     instructions, (arts[0], arts[1]), bars[1], bars[0], texts)


def worksheet(construction_or_grasp: Any, path: str | os.PathLike[str], *, steps: str = "all",
              given: str | Iterable[str] = "grasp", scale: float | None = None) -> Path:
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
