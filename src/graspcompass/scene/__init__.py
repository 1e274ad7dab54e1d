"""The one picture model of a construction (issue 23), free of matplotlib.

Built once per construction (:func:`scene_of`) and read by every painter: the
matplotlib drawing (:mod:`graspcompass.render`), the SVG, TikZ and GeoGebra writers
(:mod:`graspcompass.export`).  It holds the objects by role, the view box
(:func:`~graspcompass.scene.layout.view_box`), the palette
(:mod:`~graspcompass.scene.palette`), the label placement
(:mod:`~graspcompass.scene.labelling`) and the step at which each object is made
(:meth:`Scene.upto`: nothing is drawn or named before it is made).

Modules
-------
layout
    Float values of the objects (computed once), the view box, clipping, wedges.
instruments
    Compass arcs, right-angle marks and the guides of V_n, by role.
labelling
    Greedy label placement in points.
palette
    The colours of every picture.
picture
    :class:`Scene` and :func:`build_scene`.
"""

from __future__ import annotations

from .._lazy import attach

__all__ = [
    "Instrument",
    "Label",
    "Scene",
    "build_scene",
    "instruments",
    "labelling",
    "layout",
    "palette",
    "picture",
    "scene_of",
]

__getattr__, __dir__ = attach(
    __name__,
    {
        "Instrument": "instruments",
        "instruments": "instruments",
        "Label": "picture",
        "Scene": "picture",
        "build_scene": "picture",
        "scene_of": "picture",
        "labelling": "labelling",
        "layout": "layout",
        "palette": "palette",
        "picture": "picture",
    },
)
