"""Text drawn as a filled path, for the explorer's moving labels and numbers.

Matplotlib's :class:`~matplotlib.text.Text` lays a string out with FreeType on
every draw (about 1 ms for ``"V1"`` and 4-7 ms for a line of 30 characters on
the project's machine), which alone would exceed the explorer's 30 ms budget
per change.  A :class:`PathText` is a :class:`~matplotlib.patches.PathPatch`:

* a fixed string (a point's label) is converted to a path once
  (:class:`~matplotlib.textpath.TextPath`) and only moved, by its transform;
* a changing string (the numbers) is set in a monospaced font from a cache of
  one path per character (:class:`GlyphCache`), so :meth:`PathText.set_text`
  only concatenates arrays (tens of µs);

and drawing it is one ``draw_path`` (about 0.05 ms).  Sizes are in points.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.font_manager import FontProperties
from matplotlib.patches import PathPatch
from matplotlib.path import Path
from matplotlib.textpath import TextPath
from matplotlib.transforms import Affine2D, ScaledTranslation, Transform

__all__ = ["GlyphCache", "PathText"]

_EMPTY = Path(np.zeros((1, 2)), [Path.MOVETO])


class GlyphCache:
    """One path per character of a monospaced font, in points, and its advance."""

    def __init__(self, prop: FontProperties, linespacing: float = 1.2) -> None:
        self.prop = prop
        self.size = prop.get_size_in_points()
        self.line = linespacing * self.size
        wide, one = (TextPath((0, 0), s, prop=prop).get_extents().x1 for s in ("0" * 11, "0"))
        self.advance = (wide - one) / 10
        self._paths: dict[str, tuple[np.ndarray, np.ndarray] | None] = {}

    def _glyph(self, ch: str) -> tuple[np.ndarray, np.ndarray] | None:
        if ch not in self._paths:
            p = TextPath((0, 0), ch, prop=self.prop) if not ch.isspace() else None
            self._paths[ch] = (
                None
                if p is None or len(p.vertices) == 0
                else (np.asarray(p.vertices, float), np.asarray(p.codes))
            )
        return self._paths[ch]

    def path(self, text: str) -> Path:
        """``text`` (lines split at ``\\n``) as one path; the first baseline at y = 0."""
        verts, codes = [], []
        for row, line in enumerate(text.split("\n")):
            for col, ch in enumerate(line):
                g = self._glyph(ch)
                if g is not None:
                    verts.append(g[0] + (col * self.advance, -row * self.line))
                    codes.append(g[1])
        if not verts:
            return _EMPTY
        return Path(np.concatenate(verts), np.concatenate(codes))


class PathText(PathPatch):
    """A string drawn as a path at ``xy`` in the coordinates of ``coords``.

    Parameters
    ----------
    text : str
        The string.
    xy : tuple of float
        Anchor (the first baseline's left end, plus ``offset``).
    coords : matplotlib.transforms.Transform
        The anchor's coordinate system (``ax.transData``, ``fig.transFigure``).
    dpi_trans : matplotlib.transforms.Transform
        The figure's ``dpi_scale_trans`` (inches to pixels).
    glyphs : GlyphCache, optional
        Set the (changing) text from this monospaced cache; else the string is
        converted once with ``prop``.
    prop : FontProperties, optional
        Font of a fixed string.
    offset : tuple of float
        Shift from the anchor, in points.
    **kwargs
        Passed to :class:`~matplotlib.patches.PathPatch` (``facecolor``, ``zorder``…).
    """

    def __init__(
        self,
        text: str,
        xy: tuple[float, float],
        coords: Transform,
        dpi_trans: Transform,
        glyphs: GlyphCache | None = None,
        prop: FontProperties | None = None,
        offset: tuple[float, float] = (0, 0),
        **kwargs: Any,
    ) -> None:
        self._glyphs, self._coords, self._text = glyphs, coords, text
        self._points = Affine2D().translate(*offset).scale(1 / 72) + dpi_trans
        path = glyphs.path(text) if glyphs is not None else TextPath((0, 0), text, prop=prop)
        kwargs.setdefault("linewidth", 0)
        kwargs.setdefault("facecolor", "black")
        super().__init__(path, **kwargs)
        self.set_position(xy)

    def set_position(self, xy: tuple[float, float]) -> None:
        """Move the anchor to ``xy`` (in ``coords``)."""
        self._xy = (float(xy[0]), float(xy[1]))
        # the stub asks an Affine2DBase; any transform of points (transData) works there
        self.set_transform(self._points + ScaledTranslation(*self._xy, self._coords))  # type: ignore[arg-type]

    def get_position(self) -> tuple[float, float]:
        """The anchor."""
        return self._xy

    def set_text(self, text: str) -> None:
        """Replace the string (needs ``glyphs``)."""
        if text != self._text:
            if self._glyphs is None:
                raise ValueError("this PathText has a fixed string (no glyph cache)")
            self._text = text
            self.set_path(self._glyphs.path(text))

    def get_text(self) -> str:
        """The string."""
        return self._text
