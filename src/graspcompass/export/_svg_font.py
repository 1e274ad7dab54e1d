"""The labels' font embedded in the SVG: the same glyph widths in every browser.

The labels are placed with the metrics of DejaVu Sans (:mod:`graspcompass.scene.metrics`).
A browser without that font (most Windows and macOS ones) sets them in another, wider or
narrower: a hostile run of issue 23 found 18 of 244 SVGs breaking the label rules in
DejaVu Serif and 184 in a Times-like font.  So the SVG carries a subset of DejaVu Sans
(the one matplotlib ships, Bitstream Vera licence: embedding allowed) as a WOFF
``@font-face`` under a name of its own, with the system's DejaVu Sans and sans-serif
after it for glyphs outside the subset.  The subset (printable ASCII and the symbols
the pictures use) is made once per process with fontTools (a dependency of matplotlib).
"""

from __future__ import annotations

import base64
import importlib.util
import io
import os
from functools import lru_cache

__all__ = ["EMBEDDED", "FONT_STACK", "font_face"]

#: The embedded font's family name.
EMBEDDED = "graspcompass DejaVu Sans"

#: The ``font-family`` of the labels: the embedded subset, then the system's.
FONT_STACK = f"'{EMBEDDED}', 'DejaVu Sans', sans-serif"

#: Every character of the subset: printable ASCII and the pictures' symbols.
CHARS = "".join(chr(c) for c in range(32, 127)) + "°×−–·≈√πθξφμαγΔ²³₁₂₃₄ⁿ…"


def _font_path(file: str) -> str | None:
    """A font file as matplotlib ships it (found without importing matplotlib)."""
    spec = importlib.util.find_spec("matplotlib")
    for root in (spec.submodule_search_locations or []) if spec else []:
        path = os.path.join(root, "mpl-data", "fonts", "ttf", file)
        if os.path.isfile(path):
            return path
    return None


@lru_cache(maxsize=1)
def font_face() -> str:
    """The ``@font-face`` rules of the subsets, as CSS: DejaVu Sans upright (the squares'
    numbers) and Oblique (the labels, italic as mathtext sets them); empty where the
    fonts or fontTools are missing (the SVG then names the system's DejaVu Sans).

    >>> rule = font_face()
    >>> rule.count("@font-face") == 2 and "data:font/woff;base64," in rule
    True
    """
    rules = []
    for file, style in (("DejaVuSans.ttf", "normal"), ("DejaVuSans-Oblique.ttf", "italic")):
        data = _subset(file)
        if data:
            rules.append(
                f"@font-face {{ font-family: '{EMBEDDED}'; font-style: {style}; "
                f"src: url(data:font/woff;base64,{data}) format('woff'); }}"
            )
    return "\n".join(rules)


def _subset(file: str) -> str:
    """The WOFF subset of ``file`` (:data:`CHARS`) in base64, or "" without it."""
    path = _font_path(file)
    try:
        from fontTools import subset
        from fontTools.ttLib import TTFont
    except ImportError:  # pragma: no cover - fontTools comes with matplotlib
        return ""
    if path is None:  # pragma: no cover
        return ""
    options = subset.Options()
    options.flavor = "woff"
    options.hinting = False
    options.layout_features = ["kern"]
    options.name_IDs = [0, 1, 2]  # the copyright and family names stay with the glyphs
    options.drop_tables += ["FFTM"]  # FontForge's timestamps: nothing to subset
    font = TTFont(path, recalcTimestamp=False)
    sub = subset.Subsetter(options)
    sub.populate(text=CHARS)
    sub.subset(font)
    font.flavor = "woff"
    buf = io.BytesIO()
    font.save(buf)
    return base64.b64encode(buf.getvalue()).decode("ascii")
