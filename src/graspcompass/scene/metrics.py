"""The metrics labels are placed with: DejaVu Sans (Oblique), the font they are drawn in.

The placement (:func:`graspcompass.scene.fit.fit`) needs the box a label's text
will take where it is drawn.  Every painter sets point labels in DejaVu Sans
Oblique (the SVG names it; it is matplotlib's mathtext italic and on every
Debian system, package ``fonts-dejavu-core``), subscripts at :data:`SUB_SCALE`
of the font size, their baseline :data:`SUB_SHIFT` font sizes lower.  The
advance widths below are the font's own (``hmtx`` of ``DejaVuSans.ttf``, the
same in the Oblique face, in units of 1/2048 em, characters 32 to 126), so the
box is the browser's layout (``getBoundingClientRect``) up to pixel rounding.
Nothing here imports matplotlib.

Examples
--------
>>> w, up, down = extent("$P_{1x}$", 10.0)
>>> round(w, 3), round(up, 3), round(down, 3)
(14.626, 9.282, 4.151)
"""

from __future__ import annotations

import re

__all__ = ["ASCENT", "DESCENT", "FAMILY", "SUB_SCALE", "SUB_SHIFT", "WIDTHS", "extent", "runs"]

#: The font family the labels are drawn in (the SVG's ``font-family``).
FAMILY = "DejaVu Sans"
#: Ascent and descent of the face (``hhea``), in em.
ASCENT = 1901 / 2048
DESCENT = 483 / 2048
#: A subscript's size and the drop of its baseline, in font sizes.
SUB_SCALE = 0.7
SUB_SHIFT = 0.25
#: Advance widths of the characters 32 (space) to 126 (~), in 1/2048 em.
WIDTHS = (
    651,
    821,
    942,
    1716,
    1303,
    1946,
    1597,
    563,
    799,
    799,
    1024,
    1716,
    651,
    739,
    651,
    690,
    1303,
    1303,
    1303,
    1303,
    1303,
    1303,
    1303,
    1303,
    1303,
    1303,
    690,
    690,
    1716,
    1716,
    1716,
    1087,
    2048,
    1401,
    1405,
    1430,
    1577,
    1294,
    1178,
    1587,
    1540,
    604,
    604,
    1343,
    1141,
    1767,
    1532,
    1612,
    1235,
    1612,
    1423,
    1300,
    1251,
    1499,
    1401,
    2025,
    1403,
    1251,
    1403,
    799,
    690,
    799,
    1716,
    1024,
    1024,
    1255,
    1300,
    1126,
    1300,
    1260,
    721,
    1300,
    1298,
    569,
    569,
    1186,
    569,
    1995,
    1298,
    1253,
    1300,
    1300,
    842,
    1067,
    803,
    1298,
    1212,
    1675,
    1212,
    1212,
    1075,
    1303,
    690,
    1303,
    1716,
)

_PIECE = re.compile(r"_\{([^}]*)\}|_(.)|([^_]+)")


def runs(text: str) -> list[tuple[str, bool]]:
    """The label ``text`` (TeX math body, ``$`` optional) as runs ``(chars, subscript)``.

    Examples
    --------
    >>> runs("O = O_M = Y_{4}")
    [('O = O', False), ('M', True), (' = Y', False), ('4', True)]
    """
    body = text.replace("$", "").replace("\\", "")
    out: list[tuple[str, bool]] = []
    for sub_braced, sub_one, main in _PIECE.findall(body):
        if main:
            out.append((main, False))
        else:
            out.append((sub_braced or sub_one, True))
    return [r for r in out if r[0]]


def _width(chars: str) -> float:
    return sum(WIDTHS[ord(c) - 32] if 32 <= ord(c) < 127 else 2048 for c in chars) / 2048


def extent(text: str, font_size: float) -> tuple[float, float, float]:
    """``(width, ascent, descent)`` of the label ``text`` set at ``font_size``.

    The ascent is above the baseline, the descent below it (a subscript's cell
    reaching lower deepens it); all in the unit of ``font_size``.
    """
    width, down = 0.0, DESCENT * font_size
    for chars, sub in runs(text):
        if sub:
            width += _width(chars) * SUB_SCALE * font_size
            down = max(down, (SUB_SHIFT + DESCENT * SUB_SCALE) * font_size)
        else:
            width += _width(chars) * font_size
    return width, ASCENT * font_size, down
