"""Interactive explorer: sliders for x1, x2, y, φ1, φ2, μ1, μ2, θ and draggable P1, P2.

:class:`Explorer` builds a matplotlib :class:`~matplotlib.figure.Figure` (no
pyplot) with eight :class:`matplotlib.widgets.Slider`\\ s and the diagram:
friction cones, cone sides, perpendiculars, P_nx, O_M, X_n, Y_n, V_n, the four
circles on O V_n (eq. (31)), the envelope k_grasp (eq. (25)), the direction
e(θ) of the external force with the point H = k_grasp(θ) e(θ) of the envelope,
and the worst and best case (largest and smallest k_grasp over the directions θ,
with F_int = k / (x1 + x2) · F_e, eq. (17)).  Parameters that violate
condition (1) (or any other check of the model) show the failing inequality on
the canvas, worded as :class:`graspcompass.Grasp` words it.

Dragging P1 = (x1, y) moves x1 and y, dragging P2 = (−x2, y) moves x2 and y;
the sliders follow.  :func:`explore` opens the window (the only pyplot use in
the package); :func:`explore_notebook` is the Jupyter variant (ipywidgets).

Notes
-----
A change stays under 30 ms (issue 12 §1; ``bench/bench_explorer.py``):

* The geometry is computed in double precision from the closed form of §3.3
  (eqs. (23), (28)-(39); :func:`._explorer_scene.float_scene`, about 0.2 ms),
  not by replaying the exact construction.  Only near a bound of condition (1)
  (within 1e-6 rad, or a cone side so nearly horizontal that the double
  evaluation cancels) or for invalid parameters is a :class:`~graspcompass.Grasp`
  built: it words the failing inequality, or gives correctly rounded values.
* The artists are made once and only moved (``set_data``, ``set_xy``,
  ``set_center``, ``set_radius``, ``set_text``); axes, ticks, legend and the
  sliders' tracks and labels are never rebuilt.
* The canvas is redrawn by blitting: a background without the moving artists is
  rendered once (again after a resize, a zoom or ``f``), and each change
  restores it, draws the moving artists (``Figure.draw_artist``) and blits.
  A canvas that cannot blit gets ``draw_idle()``.
"""

from __future__ import annotations

import functools
import io
import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.transforms import Bbox, TransformedBbox
from matplotlib.widgets import Slider

from ..geometry import evaluate
from ..grasp import Grasp
from ._explorer_artists import _Artists
from ._explorer_events import PARAMS, _Events, _interactive, _Slider, notebook_box
from ._explorer_scene import GRASP_KEYS, Scene, ThetaGrid, float_scene, grasp_scene
from ._pathtext import GlyphCache, PathText

if TYPE_CHECKING:
    from ..construction.protocol import Construction

__all__ = ["PARAMS", "Explorer", "explore", "explore_notebook"]


class Explorer(_Events, _Artists):
    """The live diagram of a grasp, usable headless (``set_params``, ``drag``).

    A change (slider, drag, :meth:`set_params`) recomputes the picture from the
    closed form in double precision, moves the existing artists and blits them
    onto a cached background (see the module docstring); the picture is the
    one a new ``Explorer`` on the changed grasp draws, apart from the view
    limits, which stay until :meth:`fit` (key ``f``).

    Parameters
    ----------
    grasp : Grasp, optional
        Start values (numbers); defaults to the paper's Fig. 6 grasp.
    fig : matplotlib.figure.Figure, optional
        Figure to draw into (e.g. from pyplot); a new Agg figure if None.
    samples : int
        Points of the envelope polyline (θ from 0 to 2π).
    theta : float
        Start direction θ of the external force (radians, eq. (26)).
    blit : bool
        Redraw a change by blitting (default); False: ``canvas.draw_idle()``,
        which re-renders the whole figure (slow, for canvases that misbehave).

    Attributes
    ----------
    params : dict of str to float
        Current x1, x2, y, phi1, phi2 (radians), mu1, mu2 and theta (radians).
    scene : Scene or None
        The float picture of the last valid grasp (V_n, sides, perpendiculars,
        points, envelope); None until the first valid grasp.
    error : str or None
        The failing inequality while the parameters are not a valid grasp.
    envelope_xy : ndarray, shape (samples, 2)
        The envelope k_grasp(θ) e(θ) of the last valid grasp.
    worst, best : tuple of float
        ``(θ, k_grasp)`` where k_grasp is largest and smallest.
    sliders : dict of str to matplotlib.widgets.Slider
        The eight sliders, keyed like :attr:`params` (φ and θ in degrees).
    """

    def __init__(
        self,
        grasp: Grasp | None = None,
        fig: Figure | None = None,
        samples: int = 720,
        theta: float = 0.0,
        blit: bool = True,
    ) -> None:
        g = grasp if grasp is not None else Grasp.preset("fig6")
        self.params = {k: float(evaluate(g.params[k])) for k in GRASP_KEYS}
        self.params["theta"] = float(theta)
        self.samples = samples
        self.blit = blit
        self._grid = ThetaGrid(samples)
        self.fig = fig if fig is not None else Figure(figsize=(11, 7.5))
        if self.fig.canvas is None or type(self.fig.canvas).__name__ == "FigureCanvasBase":
            FigureCanvasAgg(self.fig)
        self.ax = self.fig.add_axes((0.04, 0.06, 0.58, 0.88))
        self.ax.set_aspect("equal", adjustable="box")
        self.scene: Scene | None = None
        self.error: str | None = None
        self.envelope_xy = np.zeros((0, 2))
        self.worst = self.best = (0.0, 0.0)
        self._dragging: str | None = None
        self._syncing = False
        self._key_done: tuple | None = None  # grasp parameters of the current scene/error
        self._construction: tuple[tuple, Any] | None = None
        self._capturing = False
        self._painted = False  # the canvas buffer shows the current picture
        self._make_artists()
        self.sliders: dict[str, Slider] = {}
        for i, (name, label, unit) in enumerate(PARAMS):
            sax = self.fig.add_axes((0.72, 0.88 - 0.055 * i, 0.22, 0.03))
            v = self.params[name] / unit
            lo, hi = (
                (0.0, 360.0)
                if name == "theta"
                else (1.0, 180.0)
                if name.startswith("phi")
                else (0.0 if name == "y" else 0.02, max(4.0, math.ceil(2 * v)))
            )
            s = _Slider(sax, label, lo, hi, valinit=min(max(v, lo), hi), valfmt="%.3g")
            s.drawon = False  # the explorer redraws (blits) after its own update
            s.on_changed(functools.partial(self._on_slider, name))
            self.sliders[name] = s
        mono = FontProperties(family="monospace", size=9)
        self.fig.text(
            0.67,
            0.42,
            "k_grasp(θ), eq. (25)\nF_int = k / (x1 + x2) · F_e, eq. (17)\n"
            "drag P1, P2; press f to fit the view",
            va="top",
            fontproperties=mono,
        )
        # outside the diagram: nothing moving is drawn over it (it stays in the background)
        self.fig.legend(
            handles=[
                self.envelope_line,
                self.direction,
                self.h_mark,
                self.worst_mark,
                self.best_mark,
            ],
            loc="lower left",
            bbox_to_anchor=(0.665, 0.01),
            fontsize=8,
        )
        self._info_box = Bbox([[0.665, 0.17], [1.0, 0.34]])  # figure coordinates
        self.info = self.fig.add_artist(
            PathText(
                "",
                (0.67, 0.315),
                self.fig.transFigure,
                self.fig.dpi_scale_trans,
                glyphs=GlyphCache(mono),
                zorder=3,
                clip_box=TransformedBbox(self._info_box, self.fig.transFigure),
            )
        )
        self._groups = self._draw_order()
        self._dynamic = [a for arts in self._groups.values() for a in arts]
        self._regions: dict[str, Any] = {}
        for ev, fn in (
            ("button_press_event", self._press),
            ("motion_notify_event", self._move),
            ("button_release_event", self._release),
            ("key_press_event", self._key),
            ("draw_event", self._on_draw),
        ):
            self.fig.canvas.mpl_connect(ev, fn)
        self._apply()
        self.fit()

    # -- drawing ---------------------------------------------------------------
    def fit(self) -> None:
        """Fit the view to the current diagram (the next change re-renders the background)."""
        pts = [self.envelope_xy] if len(self.envelope_xy) else []
        pts.append(
            np.array(
                [
                    [self.params["x1"], self.params["y"]],
                    [-self.params["x2"], self.params["y"]],
                    [0.0, 0.0],
                ]
            )
        )
        if self.scene is not None:
            c, r = self.scene.centres, self.scene.radii[:, None]
            pts += [c - r, c + r]
        xy = np.vstack(pts)
        lo, hi = xy.min(axis=0), xy.max(axis=0)
        pad = 0.08 * float(max(hi - lo)) + 1e-9
        self.ax.set_xlim(lo[0] - pad, hi[0] + pad)
        self.ax.set_ylim(lo[1] - pad, hi[1] + pad)
        if self.scene is not None:
            for i in range(4):
                self._arc(i, float(self.scene.S[i]), float(self.scene.C[i]))
        self._regions = {}
        self._painted = False

    def update(self, changed: Iterable[str] | None = None) -> None:
        """Recompute the picture for :attr:`params` and redraw it (message if invalid).

        Parameters
        ----------
        changed : iterable of str, optional
            The parameters that changed (their sliders are redrawn with the
            diagram and the numbers); None redraws every slider.
        """
        self._apply()
        if changed is None:
            self.redraw()
        else:
            self.redraw({"main", "info", *(f"slider:{k}" for k in changed)})

    def redraw(self, groups: Iterable[str] | None = None) -> None:
        """Show the artists' current state by blitting them onto the cached background.

        Parameters
        ----------
        groups : iterable of str, optional
            The regions to redraw: ``"main"`` (the diagram), ``"info"`` (the
            numbers), ``"slider:NAME"``; None (or a stale canvas) redraws all.

        Notes
        -----
        The background (the figure without the moving artists) is rendered on
        the first call and again after any full draw of the canvas (resize,
        zoom, savefig, :meth:`fit`), and kept per region
        (``canvas.copy_from_bbox``).  A redraw restores the regions
        (``restore_region``), draws their moving artists (``Figure.draw_artist``)
        and blits them.  Without blitting (``blit=False`` or a canvas that
        cannot) this is ``canvas.draw_idle()``, a full render.
        """
        canvas = self.fig.canvas
        if not (self.blit and getattr(canvas, "supports_blit", False)):
            canvas.draw_idle()
            return
        if not self._regions:
            self._capture()
        names = (
            list(self._groups)
            if groups is None or not self._painted
            else [g for g in self._groups if g in set(groups)]
        )
        for g in names:
            canvas.restore_region(self._regions[g][1])
        for g in names:
            for a in self._groups[g]:
                self.fig.draw_artist(a)
        for g in names:
            canvas.blit(self._regions[g][0])
        self._painted = True

    def _capture(self) -> None:
        """Render the figure without the moving artists and keep its regions."""
        canvas = self.fig.canvas
        for a in self._dynamic:
            a.set_animated(True)
        self._capturing = True
        try:
            canvas.draw()
        finally:
            self._capturing = False
            for a in self._dynamic:
                a.set_animated(False)
        self._painted = False  # the moving artists are not on the canvas yet
        for g in self._groups:
            box = self._region(g)
            self._regions[g] = (box, canvas.copy_from_bbox(box))

    def _on_draw(self, event: Any) -> None:
        if not self._capturing:  # a full draw (resize, zoom, savefig): background is stale
            self._regions = {}
            self._painted = True

    def _apply(self) -> None:
        """Move the artists to the picture of :attr:`params` (no drawing)."""
        p = self.params
        key = tuple(p[k] for k in GRASP_KEYS)
        if key != self._key_done:
            self._key_done = key
            try:
                scene = self._compute()
            except (ValueError, ArithmeticError) as exc:  # InvalidGraspError, GeometryError
                self._show_error(str(exc))
                return
            self._show_scene(scene)
        elif self.error is not None:
            return
        self._show_theta()

    def _compute(self) -> Scene:
        """The picture of :attr:`params`: double precision, or the Grasp near a bound.

        Raises :class:`~graspcompass.grasp.InvalidGraspError` (a ValueError) with
        the failing inequality when the parameters are not a valid grasp.
        """
        scene = float_scene(self.params, self._grid)
        if scene is None:  # invalid, or too close to a bound for doubles: ask the Grasp
            scene = grasp_scene(self.grasp(), self._grid)
        return scene

    def grasp(self) -> Grasp:
        """The :class:`~graspcompass.Grasp` of the current parameters (validated).

        Raises
        ------
        InvalidGraspError
            With the failing inequality, when the parameters are not a grasp.
        """
        p = self.params
        return Grasp(p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], mu1=p["mu1"], mu2=p["mu2"])

    @property
    def construction(self) -> Construction | None:
        """The exact-kernel construction of the current grasp, built on first access.

        :func:`graspcompass.internal_force_diagram` of :meth:`grasp`; None while
        the parameters are invalid.  Not used for drawing (it takes tens of ms).
        """
        if self.error is not None:
            return None
        key = tuple(self.params[k] for k in GRASP_KEYS)
        if self._construction is None or self._construction[0] != key:
            from ..construction import internal_force_diagram

            self._construction = (key, internal_force_diagram(self.grasp()))
        return self._construction[1]

    def png(self, compress_level: int = 1) -> bytes:
        """The current picture as PNG bytes, encoded from the canvas buffer.

        Nothing is re-rendered when the canvas already shows the picture (after
        a change); the first call draws the figure once.  Needs an Agg canvas.
        """
        from PIL import Image

        canvas = self.fig.canvas
        if not self._painted:
            self.redraw()
        w, h = canvas.get_width_height(physical=True)
        img = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
        buf = io.BytesIO()
        img.convert("RGB").save(buf, format="png", compress_level=compress_level)
        return buf.getvalue()

    # -- interaction -----------------------------------------------------------
    def set_params(self, **values: float) -> None:
        """Set parameters and redraw.

        Parameters
        ----------
        **values : float
            Any of x1, x2, y, phi1, phi2 (radians), mu1, mu2, theta (radians).
            The sliders move to the new values (clipped to their range for
            display).

        Raises
        ------
        ValueError
            For an unknown parameter name.
        """
        unknown = set(values) - set(self.params)
        if unknown:
            raise ValueError(
                f"unknown parameter(s) {', '.join(sorted(unknown))}; use {', '.join(self.params)}"
            )
        self.params.update({k: float(v) for k, v in values.items()})
        self._sync_sliders(values)
        self.update(values)

    def drag(self, point: str, x: float, y: float) -> None:
        """Move contact ``"P1"`` or ``"P2"`` to ``(x, y)`` as a mouse drag would."""
        if point == "P1":
            self.set_params(x1=x, y=y)
        elif point == "P2":
            self.set_params(x2=-x, y=y)
        else:
            raise ValueError(f"only P1 and P2 can be dragged, not {point!r}")


def explore(grasp: Grasp | None = None, *, timeout: float | None = None) -> Explorer:
    """Open the explorer in a window (pyplot); returns it after the window closes.

    Parameters
    ----------
    grasp : Grasp, optional
        The grasp first shown (the paper's Fig. 6 by default).
    timeout : float, optional
        Seconds the first drawing may take before the window opens
        (:class:`~graspcompass._deadline.OutOfTime` after it); the window then stays.

    Raises
    ------
    ValueError
        When matplotlib has no interactive backend (no display).
    """
    import matplotlib
    from matplotlib import pyplot as plt

    from ..boundary._deadline import command_deadline

    backend = matplotlib.get_backend()
    if not _interactive(backend):
        raise ValueError(
            f"cannot open the explorer window: matplotlib's backend {backend!r} "
            "cannot show windows (no display?): graspcompass export --format html -o "
            "explorer.html writes the same explorer as one offline web page; in "
            "Jupyter use explore_notebook()"
        )
    with command_deadline(timeout):
        fig = plt.figure(figsize=(11, 7.5))
        ex = Explorer(grasp, fig=fig)
    plt.show()
    return ex


def explore_notebook(grasp: Grasp | None = None) -> Any:
    """The Jupyter explorer: ipywidgets sliders over the diagram, as an image.

    The diagram is an :class:`Explorer` on its own Agg figure (80 dpi); a change
    of a slider updates it as in the window (float closed form, blitting) and
    the image is the canvas buffer encoded once as PNG (:meth:`Explorer.png`),
    with no second rendering of the figure.

    Parameters
    ----------
    grasp : Grasp, optional
        Start values; defaults to the paper's Fig. 6 grasp.

    Returns
    -------
    ipywidgets.VBox
        Eight sliders (x1, x2, y, φ1, φ2, μ1, μ2, θ; angles in degrees) above the
        image; display it as a cell's last expression.  Its ``explorer``
        attribute is the :class:`Explorer`.

    Raises
    ------
    ImportError
        When ipywidgets is not installed.
    """
    try:
        import ipywidgets as w
    except ImportError as exc:
        raise ImportError("explore_notebook needs ipywidgets: pip install ipywidgets") from exc
    ex = Explorer(grasp, fig=Figure(figsize=(11, 7.5), dpi=80))
    return notebook_box(ex, w)
