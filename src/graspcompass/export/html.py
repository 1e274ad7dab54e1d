"""The web explorer: one self-contained HTML page with JSXGraph (issue 12).

The page needs no network at all: JSXGraph (vendored in ``_web/``, MIT or
LGPL-3.0-or-later), the page's script and style and the data of the grasp are
inlined into the one file.  The data are the start parameters (floats), the
steps of the construction protocol with their captions and paper references
(numbered as ``graspcompass steps`` prints them), the palette of the other
pictures and the paper's presets.

In the page everything follows from the closed form of the paper, ported to
JavaScript from :meth:`graspcompass.Grasp.S`, :meth:`~graspcompass.Grasp.C` and
:func:`graspcompass.grasp._floatpath.closed_form_floats`: tan(φ ± ξ) in the μ form
of eq. (23), S_n and C_n of eqs. (28)-(29) and (34)-(39), V_n = (S_n, C_n) of
eq. (30)/(33), k_n(θ) = S_n sin θ − C_n cos θ of eq. (32), k_grasp of eq. (25)
and F_int = k / (x1 + x2) · F_e of eq. (17).  The drawing follows §3.3: X_n,
the perpendiculars, Y_n, the signed lengths, V_n, the circles on O V_n (eq.
(31)), their second intersections B_nm and the outer envelope (Fig. 5), with
the worst and best orientation of the external force.  Its labels are placed by
``labelling.js``, a port of :func:`graspcompass.labelling.place` reading the same
constants (:func:`graspcompass.labelling.spec`) and of
:func:`graspcompass.scene.fit.fit` (:func:`graspcompass.scene.fit.spec`), and its
colours are those of :data:`graspcompass.palette.PALETTE`: one picture in every
format (issue 12 §4).  A label with no place that keeps the rules on the board (no
label over a label or a marker, its centre nearer its own point than any other) goes
to a zoomed inset beside the board (``inset.js``, issue 23), a magnified copy of the
board's drawing about the points left out, whose labels are placed again there.
Parameters that break condition (1) (or any other check of
:class:`graspcompass.Grasp`) show the failing inequality, worded as the Python
model words it.

The page's script exposes ``window.graspcompass``: ``set({x1: …, mu2: …})``
(angles in radians, friction as μ), ``get(name)``, ``step(i)``,
``toScreen(name)`` (viewport pixels of a named point), ``lastUpdateMs`` and
``timings()`` (ms per update, measured in the page), ``envelope()``,
``kGrasp(θ)``, ``error()``, ``labelRects()`` and ``insetRects()`` (the drawn
rectangles of the board's and the insets' markers and labels).

Run ``python -m graspcompass.export.html FILE`` to write the page of the
Fig. 6 grasp (the docs' "Explore" page embeds it).

Examples
--------
>>> from graspcompass import Grasp, internal_force_diagram
>>> page = to_html(internal_force_diagram(Grasp.preset("table1a")))
>>> page.startswith("<!DOCTYPE html>"), "window.graspcompass" in page, "<script src" in page
(True, True, False)
"""

from __future__ import annotations

import json
import re
import sys
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._version import __version__
from ..geometry.numeric import to_float
from ..grasp import PRESETS, Grasp
from ..scene import fit as fitting
from ..scene import labelling
from ..scene.palette import PALETTE

if TYPE_CHECKING:
    from ..construction import Construction

__all__ = ["EXPLORER_SCRIPTS", "WEB_FILES", "page_data", "to_html", "web_file", "write_html"]

#: The files of ``graspcompass/export/_web`` that the page is made of (and the licences).
WEB_FILES = (
    "jsxgraph.min.js",
    "jsxgraph.css",
    "LICENSE.jsxgraph.MIT",
    "LICENSE.jsxgraph.LGPL",
    "jsxgraph.min.js.LICENSE.txt",
    "labelling.js",
    "inset.js",
    "model.js",
    "board.js",
    "placement.js",
    "controls.js",
    "explorer.js",
    "explorer.css",
    "explorer.html",
)

#: The modules of the page's script, in the order the page runs them (one ``<script>``):
#: the model (closed form, condition (1)), the board, what each step shows and the label
#: places, the controls, and ``explorer.js``, the state and the API that wire them.
EXPLORER_SCRIPTS = ("model.js", "board.js", "placement.js", "controls.js", "explorer.js")

#: Version of the vendored JSXGraph (npm package ``jsxgraph``).
JSXGRAPH_VERSION = "1.13.3"

_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")


def web_file(name: str) -> str:
    """The text of one of :data:`WEB_FILES`, read from the installed package."""
    if name not in WEB_FILES:
        raise ValueError(f"unknown web file {name!r}; one of {', '.join(WEB_FILES)}")
    return resources.files("graspcompass.export").joinpath("_web").joinpath(name).read_text("utf-8")


def _float(v: Any, name: str) -> float:
    if getattr(v, "free_symbols", None):
        raise ValueError(f"the web explorer needs numeric parameters; {name} = {v} is symbolic")
    return to_float(v, 30)


def _shape(shape: Any) -> list[Any] | None:
    if not shape:
        return None
    kind, *sizes = shape
    return [str(kind), *(float(s) for s in sizes)]


def _params(grasp: Grasp) -> dict[str, float]:
    p = grasp.params
    return {k: _float(p[k], k) for k in _PARAMS}


def page_data(construction: Construction, title: str | None = None) -> dict[str, Any]:
    """The JSON data the page starts from.

    Parameters
    ----------
    construction : Construction
        A numeric construction (any prefix ``c.upto(i)`` too: the navigator
        then ends, and starts, at its last step).
    title : str, optional
        Title of the page (default: the grasp's title).

    Returns
    -------
    dict
        ``params`` (x1, x2, y, phi1, phi2, mu1, mu2 as floats, θ = 0, radians),
        ``steps`` (index, name, caption, ref, instrument, key of each step),
        ``initial_step``, ``shape``, ``colors`` (:data:`graspcompass.palette.PALETTE`),
        ``presets``, ``title``, ``version``, ``labelling`` (the constants of the one label
        placement, :func:`graspcompass.labelling.spec`, read by the page's port of it),
        ``untitled`` (no title given: the heading shows the grasp's values).

    Raises
    ------
    ValueError
        For a symbolic construction (the page draws numbers).
    """
    grasp = construction.grasp
    if grasp is None:
        raise ValueError("the construction has no grasp to explore")
    params = _params(grasp)
    params["theta"] = 0.0  # e(0) = (0, −1): the external force straight down (26)
    steps = [
        dict(
            index=s.index,
            name=s.name,
            caption=s.caption,
            ref=s.ref,
            instrument=s.instrument,
            key=bool(s.key),
        )
        for s in construction.steps
    ]
    presets = {}
    for name, spec in PRESETS.items():
        g = Grasp(**spec["params"])
        presets[name] = dict(
            title=spec["title"], params=_params(g), shape=_shape(spec.get("shape"))
        )
    return dict(
        title=title or grasp.title or "graspcompass: the internal force diagram",
        version=__version__,
        params=params,
        steps=steps,
        initial_step=len(steps) - 1,
        shape=_shape(grasp.shape),
        colors=dict(PALETTE),
        presets=presets,
        labelling=labelling.spec(),
        fit=fitting.spec(),
        # no title of its own: the page's heading gives the grasp's values instead
        untitled=title is None and not grasp.title,
    )


def _script_safe(text: str) -> str:
    """Text that can stand inside ``<script>``: no ``</script``, no ``<!--``."""
    return re.sub(r"</(script)", r"<\\/\1", text, flags=re.I).replace("<!--", "<\\!--")


def _html_escape(text: str) -> str:
    return (
        text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
    )


def to_html(construction: Construction, title: str | None = None) -> str:
    """The self-contained explorer page of ``construction`` (one HTML document).

    The closed form (27)-(39), the envelope (25) and F_int (17) are computed in
    the page (see the module docstring); nothing is loaded from the network.

    Raises
    ------
    ValueError
        For a symbolic construction.
    """
    data = page_data(construction, title)
    scripts = {
        "LABELLING_JS": web_file("labelling.js") + "\n" + web_file("inset.js"),
        "EXPLORER_JS": "\n".join(web_file(name) for name in EXPLORER_SCRIPTS),
    }
    return _fill_page(web_file("explorer.html"), data, scripts)


def _fill_page(template: str, data: dict[str, Any], scripts: dict[str, str]) -> str:
    """``template`` with its ``{{NAME}}`` slots filled: the version, title, styles, the
    page data as JSON, JSXGraph and ``scripts`` (each made safe inside ``<script>``)."""
    js = re.sub(r"\n//# sourceMappingURL=\S*\s*$", "\n", web_file("jsxgraph.min.js"))
    parts = {
        "VERSION": __version__,
        "JSXGRAPH_VERSION": JSXGRAPH_VERSION,
        "TITLE": _html_escape(data["title"]),
        "JSXGRAPH_CSS": web_file("jsxgraph.css").replace("</", "<\\/"),
        "EXPLORER_CSS": web_file("explorer.css").replace("</", "<\\/"),
        # JSON inside <script>: "<\/" is the same string to JSON.parse
        "DATA": json.dumps(data, ensure_ascii=False).replace("</", "<\\/"),
        "JSXGRAPH_JS": _script_safe(js),
        **{name: _script_safe(text) for name, text in scripts.items()},
    }
    return re.sub(r"\{\{([A-Z_]+)\}\}", lambda m: parts[m.group(1)], template)


def write_html(construction: Construction, path: Any, title: str | None = None) -> Path:
    """Write the interactive web explorer of ``construction`` to ``path``.

    One HTML file that works offline (``file://``) and in any browser: sliders
    for x1, x2, y, φ1, φ2, μ1, μ2 and θ, draggable P1 and P2, the construction
    of §3.3 with V_n = (S_n, C_n) of eqs. (28)-(39), the circles of eq. (31),
    the envelope k_grasp of eq. (25) with its worst and best orientation and
    F_int of eq. (17), and a step navigator over the protocol.

    Parameters
    ----------
    construction : Construction
        Numeric parameters (e.g. ``internal_force_diagram(Grasp.preset("fig6"))``).
    path : str or path-like
        The file to write; its folder must exist (it is not made).
    title : str, optional
        Title of the page (default: the grasp's title).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For a symbolic construction.
    graspcompass.errors.OutputError
        If ``path`` cannot be written (a missing folder, no permission), checked
        before any work, or if the write fails (a half-written file is removed).
    """
    from ..boundary._output import write_output

    return write_output(path, lambda: to_html(construction, title))


def main(argv: list[str] | None = None) -> int:
    """``python -m graspcompass.export.html FILE [PRESET]``: write the page of a preset."""
    from ..construction import internal_force_diagram

    args = sys.argv[1:] if argv is None else argv
    if not 1 <= len(args) <= 2:
        print("usage: python -m graspcompass.export.html FILE [PRESET]", file=sys.stderr)
        return 2
    preset = args[1] if len(args) == 2 else "fig6"
    path = write_html(internal_force_diagram(Grasp.preset(preset)), args[0])
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
