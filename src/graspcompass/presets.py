"""The paper's example grasps, as data (text values read by the safe parser).

Imports nothing, so the command line lists and checks preset names without
loading the model; :meth:`graspcompass.Grasp.preset` builds them.

Examples
--------
>>> from graspcompass.presets import PRESETS
>>> sorted(PRESETS)
['fig6', 'table1a', 'table1b', 'table1c']
>>> PRESETS["table1a"]["params"]["mu2"]
'1.2'
"""

from __future__ import annotations

from typing import Any

__all__ = ["PRESETS"]

#: The paper's grasps: Fig. 6 and the three rectangles of Fig. 7 / Table I.  Each has
#: ``params`` (keyword arguments of :class:`~graspcompass.Grasp`, as text), ``shape``
#: (the outline drawn) and ``title``.
PRESETS: dict[str, dict[str, Any]] = {
    "fig6": dict(
        params=dict(
            x1="sqrt(3)/2",
            x2="sqrt(3)/2",
            y="1/2",
            phi1="pi/3",
            phi2="pi/3",
            xi1="pi/4",
            xi2="pi/3",
        ),
        shape=("circle", 1),
        title="Fig. 6: circular object, P1 = (√3/2, 1/2), φ = π/3, ξ1 = π/4, ξ2 = π/3",
    ),
    "table1a": dict(
        params=dict(x1="2", x2="2", y="1", phi1="pi/2", phi2="pi/2", mu1="1.0", mu2="1.2"),
        shape=("rectangle", 4, 8),
        title="Fig. 7(a), Table I(a): rectangle, P1 = (2, 1), μ1 = 1.0, μ2 = 1.2",
    ),
    "table1b": dict(
        params=dict(x1="2", x2="2", y="3", phi1="pi/2", phi2="pi/2", mu1="1.0", mu2="1.2"),
        shape=("rectangle", 4, 8),
        title="Fig. 7(b), Table I(b): rectangle, P1 = (2, 3), μ1 = 1.0, μ2 = 1.2",
    ),
    "table1c": dict(
        params=dict(x1="2", x2="2", y="2", phi1="pi/2", phi2="pi/2", mu1="0.5", mu2="1.4"),
        shape=("rectangle", 4, 8),
        title="Fig. 7(c), Table I(c): rectangle, P1 = (2, 2), μ1 = 0.5, μ2 = 1.4",
    ),
}
