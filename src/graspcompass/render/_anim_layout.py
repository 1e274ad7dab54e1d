"""The layout of a construction animation: title, caption, progress bar and diagram.

The caption goes below the diagram (``standard``) or in a panel beside it
(``lecture``).  Its point names and formulas are typeset as mathtext (``$O_M\\ X_1$``,
``$k_\\mathrm{grasp}(\\theta)$``, ``$F_\\mathrm{int}$``; :func:`_mathtext`), each
formula whole in one ``$…$``; every caption is wrapped at the spaces outside its
formulas to the width it is given, measured as drawn (:func:`_wrap`,
:func:`_text_width`), and the diagram is placed so that the longest fits whole.
Private to :mod:`graspcompass.render.animate`, which re-exports these names.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.patches import Rectangle

from ..scene.layout import tex
from .figure import grasp_title
from .timeline import AnimationError

if TYPE_CHECKING:
    from .animate import ConstructionAnimation


#: The parts of a caption's formula: a name (``O_M``, ``P1x``, ``k_grasp``), a Greek
#: letter, a number, an operator, a bracket or comma.
_TOKEN = re.compile(
    r"(?P<name>[A-Za-z]_[A-Za-z]+(?![A-Za-z0-9])|[A-Za-z]\d+x?(?![A-Za-z0-9])"
    r"|[A-Z](?![A-Za-z0-9_'’])|[xye](?![A-Za-z0-9_'’]))"
    r"|(?P<greek>[θφξγμαβ]\d*(?![A-Za-z0-9]))"
    r"|(?P<num>\d+(?:\.\d+)?)"
    r"|(?P<op>[=+−·/×≤≥<>-])"
    r"|(?P<punct>[(),])"
    r"|(?P<space> )"
)
_GREEK = {"θ": "theta", "φ": "varphi", "ξ": "xi", "γ": "gamma", "μ": "mu", "α": "alpha"}
_GREEK["β"] = "beta"
_AXIS = re.compile(r"[xy]-axis")
#: a reference and its number are not parted: ``eq. (25)``, ``Fig. 5``
_REF = re.compile(r"\b(eqs?\.|Figs?\.) (?=[(\d])")
_OPS = {"−": "-", "·": r"\cdot ", "×": r"\times ", "≤": r"\leq ", "≥": r"\geq "}


def _kind(word: str) -> str:
    """``"math"`` (a formula's word, with a name or Greek letter), ``"op"`` (operators
    only) or ``"prose"``."""
    pos, kinds = 0, set()
    while pos < len(word):
        m = _TOKEN.match(word, pos)
        if m is None or m.lastgroup == "space":
            return "prose"
        kinds.add(m.lastgroup)
        pos = m.end()
    if kinds & {"name", "greek"}:
        return "math"
    return "op" if kinds == {"op"} else "prose"


def _math_body(formula: str) -> str:
    """The mathtext of a formula of caption words: ``"O_M X1 = −S1"`` ->
    ``"O_M\\ X_1 = -S_1"``; a space is kept (``\\ ``) only between two operands."""
    toks = [(m.lastgroup, m.group()) for m in _TOKEN.finditer(formula)]
    out: list[str] = []
    for i, (kind, t) in enumerate(toks):
        if kind == "space":
            before, after = toks[i - 1], toks[i + 1] if i + 1 < len(toks) else ("op", "")
            operand = before[0] != "op" and before[1] not in "(," and after[0] != "op"
            out.append("\\ " if operand and after[1] not in ",)" else " ")
        elif kind == "name":
            head, _, rest = t.partition("_")
            if len(rest) > 1 and rest.islower():  # a word: upright, as the paper's k_grasp
                out.append(f"{head}_\\mathrm{{{rest}}}")
            else:
                out.append(tex(t, math=False))
        elif kind == "greek":
            sub = t[1:]
            out.append(
                f"\\{_GREEK[t[0]]}" + (f"_{{{sub}}}" if len(sub) > 1 else f"_{sub}" if sub else "")
            )
        elif kind == "op":
            prev = next((u for k, u in toks[i - 1 :: -1] if k != "space"), "(") if i else "("
            m = _TOKEN.fullmatch(prev)
            unary = t in "−-+" and (prev in "(," or (m is not None and m.lastgroup == "op"))
            # a sign is not spaced as a binary operator: after a comma neither
            out.append(f"{{{_OPS.get(t, t)}}}" if unary else _OPS.get(t, t))
        else:
            out.append(t)
    return "".join(out).rstrip()


def _math_line(line: str) -> str:
    """One line of a caption with its formulas typeset (see :func:`_mathtext`)."""
    words = line.split(" ")
    pieces: list[tuple[str, bool]] = []  # (text, a formula)
    i = 0
    while i < len(words):
        core = words[i].rstrip(".,:;")
        if _AXIS.fullmatch(core):  # the x-axis
            pieces.append((f"${core[0]}${words[i][1:]}", True))
            i += 1
            continue
        if not core or _kind(core) != "math":
            pieces.append((words[i], False))
            i += 1
            continue
        # a formula: the math and operator words from here, up to a punctuation mark
        # (a comma inside brackets belongs to it) or a prose word
        items: list[tuple[str, str]] = []
        depth = 0
        while i < len(words):
            core = words[i].rstrip(".,:;")
            if not core or _kind(core) == "prose":
                break
            trail = words[i][len(core) :]
            depth += core.count("(") - core.count(")")
            i += 1
            if trail == "," and depth > 0:
                items.append((core + ",", ""))
                continue
            items.append((core, trail))
            if trail:
                break
        tail: list[str] = []
        while items and _kind(items[-1][0]) == "op":  # operators at the end stay prose
            tail.insert(0, "".join(items.pop()))
        formula, after = " ".join(c for c, _ in items), items[-1][1]
        lead = back = ""
        while formula.startswith("(") and formula.count("(") > formula.count(")"):
            lead, formula = lead + "(", formula[1:]
        while formula.endswith(")") and formula.count(")") > formula.count("("):
            back, formula = ")" + back, formula[:-1]
        pieces.append((f"{lead}${_math_body(formula)}${back}{after}", True))
        pieces += [(t, False) for t in tail]
    if not any(f for _, f in pieces):
        return line
    # a dollar of the prose is escaped on a line that has formulas
    return " ".join(t if f else t.replace("$", r"\$") for t, f in pieces)


def _mathtext(text: str) -> str:
    """``text`` with its point names and formulas typeset as mathtext: each formula whole
    in one ``$…$`` (so that :func:`_wrap` never breaks it), the prose as it is.

    Examples
    --------
    >>> print(_mathtext("Plot V1 = (−O_M X1, −O Y1)"))
    Plot $V_1 = ({-}O_M\\ X_1, {-}O\\ Y_1)$
    >>> print(_mathtext("Bisect P1x P2x: its midpoint O_M"))
    Bisect $P_{1x}\\ P_{2x}$: its midpoint $O_M$
    >>> print(_mathtext("The upper side (angle φ1 + ξ1) at P2, Fig. 2"))
    The upper side (angle $\\varphi_1 + \\xi_1$) at $P_2$, Fig.\u00a02
    >>> print(_mathtext("F_int = k_grasp/(x1 + x2)·F_e on the x-axis"))
    $F_\\mathrm{int} = k_\\mathrm{grasp}/(x_1 + x_2)\\cdot F_e$ on the $x$-axis
    >>> print(_mathtext("Step 13 of 0–46 · perpendicular"))
    Step 13 of 0–46 · perpendicular
    """
    return "\n".join(_math_line(_REF.sub("\\1\u00a0", p)) for p in text.split("\n"))


def _shown(text: str) -> str:
    """The characters of a caption as read (its formulas without their markup): the
    length by which it is paced.

    >>> _shown(r"plot $V_1 = ({-}O_M\\ X_1, {-}O\\ Y_1)$ of $k_\\mathrm{grasp}(\\theta)$")
    'plot V1 = (-OM X1, -O Y1) of kgrasp(θ)'
    """
    out = []
    for i, part in enumerate(re.split(r"(?<!\\)\$", text)):
        if i % 2 == 0:
            out.append(part.replace(r"\$", "$"))
            continue
        part = re.sub(r"\\mathrm\{([^}]*)\}", r"\1", part.replace("\\ ", " "))
        for name, letter in _GREEK.items():
            part = part.replace(f"\\{letter}", name)
        out.append(re.sub(r"\\[A-Za-z]+ ?", "·", part).translate({ord(c): None for c in "{}_"}))
    return "".join(out)


#: A word of a caption: up to a space outside a formula ``$…$``.
_WORD = re.compile(r"(?:\\\$|\$[^$]*\$|[^ $\\]|\\)+")


def _wrap(text: str, width: float, measure: Any) -> str:
    """``text`` broken at spaces outside its formulas ``$…$`` into lines no wider than
    ``width`` pixels; ``measure(s)`` is the width of ``s`` as drawn."""
    lines: list[str] = []
    for para in text.split("\n"):
        line = ""
        for word in _WORD.findall(para):
            trial = f"{line} {word}" if line else word
            if line and measure(trial) > width:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return "\n".join(lines)


#: Widths of caption words as drawn, by (word, mathtext, font, dpi): every animation of a
#: process lays out the same words (matplotlib keeps only the last 50 formulas parsed).
_WIDTHS: dict[tuple[str, bool, int, float], float] = {}
#: Widths of text artists as drawn, by (text, font, dpi).
_DRAWN: dict[tuple[str, int, float], float] = {}
#: Heights of wrapped captions as drawn, by (text, font, line spacing, dpi).
_HEIGHTS: dict[tuple[str, int, Any, float], float] = {}
_MOST = 20000  # entries of each, then it starts again


def drawn_width(t: Any, renderer: Any) -> float:
    """The width in pixels of the text artist ``t`` as drawn (once per text, font and dpi
    in a process: the side panel tries its list at several sizes)."""
    key = (t.get_text(), hash(t.get_fontproperties()), float(renderer.dpi))
    if key not in _DRAWN:
        if len(_DRAWN) > _MOST:
            _DRAWN.clear()
        _DRAWN[key] = t.get_window_extent(renderer).width
    return _DRAWN[key]


def _text_width(renderer: Any, prop: Any) -> Any:
    """A fast measure of text widths in pixels, mathtext as rendered: the sum of the
    words' widths (each measured once, a word with a formula by the mathtext parser)
    and of the spaces, 3 % wider for kerning and hinting."""
    cache: dict[str, float] = {}
    font, dpi = hash(prop), float(renderer.dpi)

    def width(w: str, math: bool) -> float:
        key = (w, math, font, dpi)
        if key not in _WIDTHS:
            if len(_WIDTHS) > _MOST:
                _WIDTHS.clear()
            _WIDTHS[key] = renderer.get_text_width_height_descent(w, prop, math)[0]
        return _WIDTHS[key]

    bar = width("||", False)
    space = width("| |", False) - bar

    def measure(s: str) -> float:
        words = _WORD.findall(s)
        total = space * (len(words) - 1)
        for w in words:
            if w not in cache:
                math = w.count("$") - w.count(r"\$") >= 2
                cache[w] = width(w, True) if math else width(f"|{w}|", False) - bar
            total += cache[w]
        return 1.03 * total

    return measure


def _layout(anim: ConstructionAnimation, layout: str, caption_pt: float) -> None:
    """Place the title, the caption, the progress bar and the diagram of ``anim`` so that
    the longest caption fits whole (measured as drawn)."""
    fig, ax, th = anim.figure, anim.axes, anim.theme
    if layout not in ("below", "side"):
        raise AnimationError(f"unknown layout {layout!r}; use 'below' or 'side'")
    anim.layout = layout
    W, H = fig.get_size_inches() * fig.dpi
    renderer = anim._canvas.get_renderer()
    px = fig.dpi / 72.0
    title_pt = max(
        th.font_size * 0.8 * (1.3 if layout == "side" else 1.0), getattr(anim, "_least_pt", 0.0)
    )
    title = fig.text(
        0.5,
        1 - 0.012 * W / H,
        grasp_title(anim.construction.grasp),
        ha="center",
        va="top",
        fontsize=title_pt,
    )
    bar_h = max(0.012, 4.0 / H) if layout == "side" else 0.012
    anim._bar = Rectangle(
        (0, 0), 0, bar_h, transform=fig.transFigure, color=th.highlight_color, zorder=10
    )
    fig.add_artist(anim._bar)
    margin = max(0.03 * W, 4.0)
    tick = th.font_size * 0.7 * px * 1.6  # the tick labels' room
    title_h = title_pt * px * 1.5 + 0.012 * W
    if layout == "below":
        width = W - 2 * margin
        x_cap = margin
    else:
        side = H - title_h - bar_h * H - tick - 2 * margin  # a square diagram on the left
        ax.set_position(
            (margin * 1.6 / W + tick / W, (bar_h * H + tick + margin) / H, side / W, side / H)
        )
        x_cap = margin * 1.6 + tick + side + 1.5 * margin
        width = W - x_cap - margin
    anim._caption = fig.text(
        x_cap / W, 0.5, "", va="top", linespacing=1.4, fontsize=caption_pt, fontweight="normal"
    )
    measure = _text_width(renderer, anim._caption.get_fontproperties())
    anim._wrapped = [_wrap(t, width, measure) for t in anim._texts]
    anim._hold_wrapped = _wrap(anim._hold_text, width, measure)
    anim._inset_wrapped = _wrap(anim._inset_text, width, measure)
    heights: dict[str, float] = {}
    font = (hash(anim._caption.get_fontproperties()), anim._caption.get_linespacing())
    for t in {*anim._wrapped, anim._hold_wrapped, anim._inset_wrapped}:
        key = (t, font[0], font[1], float(fig.dpi))
        if key not in _HEIGHTS:  # measured as drawn, once per process
            if len(_HEIGHTS) > _MOST:
                _HEIGHTS.clear()
            anim._caption.set_text(t)
            _HEIGHTS[key] = anim._caption.get_window_extent(renderer).height
        heights[t] = _HEIGHTS[key]
    tallest = max(heights.values())
    # the side panel's list is under the steps' captions but the last's; the plot of the
    # last step (the envelope) under its caption and the final hold's
    end = [anim._hold_wrapped, anim._inset_wrapped, *anim._wrapped[-1:]]
    tall_steps = max([heights[t] for t in anim._wrapped[:-1]] or [tallest])
    tall_end = max(heights[t] for t in end)
    anim._caption.set_text("")
    if layout == "below":
        top = bar_h * H + 0.6 * margin + tallest  # the caption's top, in pixels
        anim._caption.set_y(top / H)
        bottom = top + 0.4 * margin + tick
        ax.set_position((0.1, bottom / H, 0.86, max(0.05, 1 - bottom / H - title_h / H)))
        anim._fade_region = np.s_[: int(H - top - 2)]
        anim._panel_box = None
    else:
        cap_top = H - title_h - margin
        anim._caption.set_y(cap_top / H)
        anim._fade_region = np.s_[:, : int(x_cap - margin)]
        # under the longest caption, down to the diagram's foot: the panel of what is made
        anim._panel_box = (
            x_cap,
            W - margin,
            bar_h * H + tick + margin,
            cap_top - tall_steps - 0.6 * margin,
            cap_top - tall_end - 0.6 * margin,
        )
    anim._title = title
