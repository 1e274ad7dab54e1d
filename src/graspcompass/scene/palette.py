"""The one palette of every picture: PNG/PDF, SVG, TikZ, GeoGebra, HTML (issue 12 §4).

Plain data, importing nothing: :class:`graspcompass.render.theme.Theme` takes its
defaults from here; the SVG/TikZ scene (:data:`graspcompass.export._scene.COLORS`),
the GeoGebra writer, the web page and the matplotlib explorer read the same entries,
so a construction has the same colours in every format.  Keys are the roles of the
drawing (``axis``, ``side`` for the cone sides, ``perp`` for the perpendiculars,
``circle1``-``circle4``, ...).

Examples
--------
>>> PALETTE["circle1"], rgb("circle1")
('#1f77b4', (31, 119, 180))
"""

from __future__ import annotations

__all__ = ["PALETTE", "rgb"]

#: Role -> colour (hex).  The circles are matplotlib's first, third, fifth and fourth
#: default colours; the envelope a dark blue with a light blue filling.
PALETTE: dict[str, str] = {
    "axis": "#404040",
    "side": "#b5651d",
    "perp": "#6c757d",
    "length": "#6c757d",
    "circle1": "#1f77b4",
    "circle2": "#2ca02c",
    "circle3": "#9467bd",
    "circle4": "#d62728",
    "envelope": "#0b1f4b",
    "fill": "#9ecae1",
    "cone": "#f4a261",
    "object": "#7f7f7f",
    "objectfill": "#f2f2f2",
    "point": "#111111",
    "computer": "#ffd60a",
    "highlight": "#e63946",
    # the explorers (the web page and the matplotlib one): break points, the direction of
    # the external force and its point H on the envelope, the worst and best orientation
    # (magenta and cyan: red and green are circles 4 and 2, drawn beside them),
    # the draggable contacts, the axes' ticks, the message of an invalid grasp
    "breakpoint": "#555555",
    "breakpointfill": "#ffffff",
    "force": "#333333",
    "marker": "#111111",
    "markerfill": "#ffd166",
    "worst": "#c51b7d",
    "best": "#17becf",
    "contact": "#0b1f4b",
    "contactfill": "#ffb703",
    "contacthover": "#fb8500",
    "tick": "#c8c8c8",
    "ticklabel": "#707070",
    "error": "#b00020",
    "errorfill": "#fff3f3",
}


def rgb(role: str) -> tuple[int, int, int]:
    """The colour of ``role`` as 0-255 integers (for GeoGebra's ``objColor``)."""
    h = PALETTE[role].lstrip("#")
    return int(h[0:2], 16), int(h[2:4], 16), int(h[4:6], 16)
