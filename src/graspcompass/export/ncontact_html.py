"""The n-contact web page: n draggable contacts, Q, its Thales circles and their envelope.

One self-contained HTML file (no network: JSXGraph, the page's script and style and
the grasp's data are inlined), the n-contact sibling of the explorer page of
:mod:`graspcompass.export.html`.  Each contact is a draggable point with a handle
for the direction of its inward normal, its friction cone drawn from it, and a μ
slider; an effort menu and a θ slider sit beside the board.  The page recomputes
the polygon Q of :class:`graspcompass.ncontact.NContactGrasp` on every change with
the same float algorithm as the Python float path (``_web/ncontact.js``, a port of
``ncontact/_dual.py``, ``maxnormal.py``, ``polygon.py`` and ``_hull.py``): the
dual-feasible bases, the hull, the recession directions and the arc of loads that
can be held, ``v(θ) = max_q q·e(θ)`` with ``e(θ) = (sin θ, -cos θ)`` (eq. (26)).
It draws the vertices q of Q, the Thales circles on O q (dashed grey for the
redundant dual vertices), their outer envelope (the polar plot of v) and the load;
on request the construction of one vertex (the cost lines through the cost points,
the homologous triangles A12 A13 / A'12 A'13, R and the quarter turn of
:mod:`graspcompass.construction.ncontact_recipe`), with its steps as a caption.
A grasp that can hold no load (an empty dual, a rank-deficient grasp, no open arc
of loads) keeps the last valid drawing and shows why.

The page's script exposes ``window.graspcompass``: ``set({contacts: [{x, y, angle,
mu}, ...], effort, theta})``, ``state()``, ``vertices()``, ``redundant()``,
``rays()``, ``arc()``, ``k(θ)``, ``closure()``, ``error()``, ``construct(k)``,
``showConstruction(k)``, ``toScreen(i)``, ``handleToScreen(i)``, ``fit()``, ``lastUpdateMs``
and, on any state, ``compute(state)``, ``support(Q, θ)``, ``arcOf(Q)`` and
``constructOf(Q, k, com)``.

The export layer does not import :mod:`graspcompass.ncontact` (a higher layer): the
functions read the grasp's ``contacts`` (``p``, ``n``, ``mu``), ``com`` and
``effort.name`` attributes.

Examples
--------
>>> from graspcompass.ncontact import NContactGrasp
>>> g = NContactGrasp([(1, 0, -1, 0, "1/2"), (-1, 0, 1, 0, "1/2"), (0, -1, 0, 1, "1/2")])
>>> page = to_ncontact_html(g)
>>> page.startswith("<!DOCTYPE html>"), "window.graspcompass" in page, "<script src" in page
(True, True, False)
"""

from __future__ import annotations

import math
import re
from importlib import resources
from pathlib import Path
from typing import Any

from .._version import __version__
from ..geometry.numeric import to_float
from ..scene.palette import PALETTE
from .html import _fill_page

__all__ = ["NCONTACT_FILES", "ncontact_page_data", "to_ncontact_html", "write_ncontact_html"]

#: The page's own files in ``graspcompass/export/_web`` (JSXGraph and the style are shared).
NCONTACT_FILES = ("ncontact.html", "ncontact.js")

_EFFORTS = re.compile(r"paper|sum-normal|max-normal|pair:\d+,\d+")


def _own_file(name: str) -> str:
    return resources.files("graspcompass.export").joinpath("_web").joinpath(name).read_text("utf-8")


def _f(v: Any, name: str) -> float:
    if getattr(v, "free_symbols", None):
        raise ValueError(f"the n-contact page needs numeric contacts; {name} = {v} is symbolic")
    x = float(v) if isinstance(v, (int, float)) else to_float(v, 30)
    if not math.isfinite(x):
        raise ValueError(f"the n-contact page needs finite values; {name} = {x}")
    return x


def ncontact_page_data(grasp: Any, theta: float = 0.0, title: str | None = None) -> dict[str, Any]:
    """The JSON data the page starts from.

    Parameters
    ----------
    grasp : NContactGrasp
        The grasp (exact or float): its contacts, centre of mass and named effort.
    theta : float, optional
        The load direction shown first (radians, eq. (26)).
    title : str, optional
        Title of the page (default: the number of contacts and the effort).

    Returns
    -------
    dict
        ``state`` (``contacts``: x, y, angle of the inward normal, μ as floats;
        ``com``; ``effort``; ``theta``), ``handle`` (length of the normal handles),
        ``colors`` (:data:`graspcompass.palette.PALETTE`), ``title``, ``version``.

    Raises
    ------
    ValueError
        For a custom effort (the page redraws the named efforts only).
    """
    effort = grasp.effort.name
    if not _EFFORTS.fullmatch(effort):
        raise ValueError(
            f"the n-contact page redraws the named efforts only (paper, "
            f"sum-normal, pair:I,J, max-normal), not {effort!r}"
        )
    contacts = []
    for i, c in enumerate(grasp.contacts, start=1):
        x, y = (_f(v, f"contact {i} {k}") for v, k in zip(c.p, "xy"))
        nx, ny = (_f(v, f"contact {i} n{k}") for v, k in zip(c.n, "xy"))
        contacts.append(
            {"x": x, "y": y, "angle": math.atan2(ny, nx), "mu": _f(c.mu, f"contact {i} mu")}
        )
    com = [_f(v, f"com {k}") for v, k in zip(grasp.com, "xy")]
    spread = max(math.hypot(c["x"] - com[0], c["y"] - com[1]) for c in contacts)
    n = len(contacts)
    return {
        "state": {"contacts": contacts, "com": com, "effort": effort, "theta": float(theta)},
        "handle": 0.3 * (spread or 1.0),
        "colors": dict(PALETTE),
        "title": title or f"graspcompass: {n} contacts, effort {effort}",
        "version": __version__,
    }


def to_ncontact_html(grasp: Any, theta: float = 0.0, title: str | None = None) -> str:
    """The self-contained n-contact page of ``grasp`` (one HTML document).

    Raises
    ------
    ValueError
        For symbolic contacts or a custom effort.
    """
    data = ncontact_page_data(grasp, theta, title)
    scripts = {"NCONTACT_JS": _own_file("ncontact.js")}
    return _fill_page(_own_file("ncontact.html"), data, scripts)


def write_ncontact_html(
    grasp: Any, path: Any, theta: float = 0.0, title: str | None = None
) -> Path:
    """Write the n-contact page of ``grasp`` to ``path`` (its folder must exist).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For symbolic contacts or a custom effort.
    graspcompass.errors.OutputError
        If ``path`` cannot be written (checked before any work; a half-written
        file is removed).
    """
    from ..boundary._output import write_output

    return write_output(path, lambda: to_ncontact_html(grasp, theta, title))
