"""Interactive explorer: sliders for x1, x2, y, φ1, φ2, μ1, μ2 and draggable P1, P2.

:class:`Explorer` builds a matplotlib :class:`~matplotlib.figure.Figure` (no
pyplot) with seven :class:`matplotlib.widgets.Slider`\\ s and the diagram:
friction cones, cone sides, perpendiculars, P_nx, O_M, X_n, Y_n, V_n, the four
circles on O V_n (eq. (31)), the envelope k_grasp (eq. (25)) and its worst and
best case (largest and smallest k_grasp over the directions θ of the external
force, with F_int = k / (x1 + x2) · F_e, eq. (17)).  Every change replays the
construction through the public API (:func:`graspcompass.internal_force_diagram`
on a float :class:`graspcompass.Grasp`).  Parameters that violate condition (1)
(or any other check of the model) show the failing inequality on the canvas.

Dragging P1 = (x1, y) moves x1 and y, dragging P2 = (−x2, y) moves x2 and y;
the sliders follow.  :func:`explore` opens the window (the only pyplot use in
the package); :func:`explore_notebook` is the Jupyter variant (ipywidgets).
"""

from __future__ import annotations

import io
import math
import textwrap
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import Polygon
from matplotlib.widgets import Slider

from ..construction import internal_force_diagram
from ..geometry import GeometryError, evaluate
from ..grasp import Grasp, InvalidGraspError
from ..layout import wedge
from .theme import DEFAULT_THEME

__all__ = ["PARAMS", "Explorer", "explore", "explore_notebook"]

#: Slider name, label, unit factor to the model (degrees for φ).
PARAMS = (("x1", "$x_1$", 1.0), ("x2", "$x_2$", 1.0), ("y", "$y$", 1.0),
          ("phi1", r"$\varphi_1$ (°)", math.pi / 180), ("phi2", r"$\varphi_2$ (°)", math.pi / 180),
          ("mu1", r"$\mu_1$", 1.0), ("mu2", r"$\mu_2$", 1.0))
_UNIT = {p[0]: p[2] for p in PARAMS}
_PICK_PX = 12.0


class Explorer:
    """The live diagram of a grasp, usable headless (``set_params``, ``drag``).

    Parameters
    ----------
    grasp : Grasp, optional
        Start values (numbers); defaults to the paper's Fig. 6 grasp.
    fig : matplotlib.figure.Figure, optional
        Figure to draw into (e.g. from pyplot); a new Agg figure if None.
    samples : int
        Points of the envelope polyline.

    Attributes
    ----------
    params : dict of str to float
        Current x1, x2, y, phi1, phi2 (radians), mu1, mu2.
    construction : Construction or None
        The last valid construction; ``error`` is the message when invalid.
    envelope_xy : ndarray, shape (samples, 2)
        The envelope k_grasp(θ) e(θ) of the last valid construction.
    worst, best : tuple of float
        ``(θ, k_grasp)`` where k_grasp is largest and smallest.
    """

    def __init__(self, grasp: Grasp | None = None, fig: Figure | None = None,
                 samples: int = 720) -> None:
        g = grasp if grasp is not None else Grasp.preset("fig6")
        self.params = {p[0]: float(evaluate(g.params[p[0]])) for p in PARAMS}
        self.samples = samples
        self.fig = fig if fig is not None else Figure(figsize=(11, 7.5))
        if self.fig.canvas is None or type(self.fig.canvas).__name__ == "FigureCanvasBase":
            FigureCanvasAgg(self.fig)
        self.ax = self.fig.add_axes((0.04, 0.06, 0.58, 0.88))
        self.ax.set_aspect("equal", adjustable="box")
        self.construction: Any = None
        self.error: str | None = None
        self.envelope_xy = np.zeros((0, 2))
        self.worst = self.best = (0.0, 0.0)
        self._dragging: str | None = None
        self._syncing = False
        self._make_artists()
        self.sliders: dict[str, Slider] = {}
        for i, (name, label, unit) in enumerate(PARAMS):
            sax = self.fig.add_axes((0.72, 0.88 - 0.06 * i, 0.22, 0.03))
            v = self.params[name] / unit
            lo, hi = ((1.0, 180.0) if name.startswith("phi") else
                      (0.0 if name == "y" else 0.02, max(4.0, math.ceil(2 * v))))
            s = Slider(sax, label, lo, hi, valinit=v, valfmt="%.3g")
            s.on_changed(lambda val, n=name: self._on_slider(n, val))
            self.sliders[name] = s
        self.info = self.fig.text(0.67, 0.4, "", va="top", fontsize=9, family="monospace")
        for ev, fn in (("button_press_event", self._press), ("motion_notify_event", self._move),
                       ("button_release_event", self._release), ("key_press_event", self._key)):
            self.fig.canvas.mpl_connect(ev, fn)
        self.update()
        self.fit()

    # -- drawing --------------------------------------------------------------
    def _make_artists(self) -> None:
        ax, th = self.ax, DEFAULT_THEME
        ax.axhline(0, color=th.axis_color, lw=0.8)
        ax.axvline(0, color=th.axis_color, lw=0.8)
        self.cones = [ax.add_patch(Polygon(np.zeros((3, 2)), facecolor=th.cone_face,
                                           alpha=th.cone_alpha, edgecolor="none"))
                      for _ in range(2)]
        self.sides = [ax.plot([], [], color=th.side_color, lw=1.0)[0] for _ in range(4)]
        self.perps = [ax.plot([], [], color=th.construction_color, lw=0.7, ls="--")[0]
                      for _ in range(4)]
        self.circles = [ax.add_patch(CirclePatch((0, 0), 1, fill=False, ls="--", lw=1.2,
                                                 edgecolor=th.circle_color(n)))
                        for n in (1, 2, 3, 4)]
        self.fill = ax.add_patch(Polygon(np.zeros((3, 2)), facecolor=th.envelope_fill,
                                         alpha=0.25, edgecolor="none", zorder=0.5))
        (self.envelope_line,) = ax.plot([], [], color=th.envelope_color, lw=2.2,
                                        label=r"envelope $k_{grasp}(\theta)$, eq. (25)")
        (self.points,) = ax.plot([], [], "o", ms=3.5, color=th.point_color)
        (self.contacts,) = ax.plot([], [], "o", ms=9, color=th.highlight_color, picker=True)
        (self.worst_mark,) = ax.plot([], [], "*", ms=14, color="#d62728", label="worst case")
        (self.best_mark,) = ax.plot([], [], "D", ms=8, color="#2ca02c", label="best case")
        self.labels = {n: ax.annotate(n, (0, 0), xytext=(4, 4), textcoords="offset points",
                                      fontsize=9) for n in ("P1", "P2", "V1", "V2", "V3", "V4")}
        self.message = ax.text(0.5, 0.5, "", transform=ax.transAxes, ha="center", va="center",
                               fontsize=10, color="#b00020", visible=False, zorder=10,
                               bbox=dict(boxstyle="round", fc="#fff3f3", ec="#b00020"))
        ax.legend(loc="lower left", fontsize=8)
        self._alphas = {a: a.get_alpha() for a in (
            *self.sides, *self.perps, *self.circles, *self.cones, self.fill,
            self.envelope_line, self.points, self.worst_mark, self.best_mark)}

    def fit(self) -> None:
        """Fit the view to the current diagram."""
        pts = [self.envelope_xy] if len(self.envelope_xy) else []
        pts.append(np.array([[self.params["x1"], self.params["y"]],
                             [-self.params["x2"], self.params["y"]], [0.0, 0.0]]))
        if self.construction is not None:
            for n in (1, 2, 3, 4):
                (cx, cy), r = evaluate(self.construction[f"circle{n}"])
                pts.append(np.array([[cx - r, cy - r], [cx + r, cy + r]]))
        xy = np.vstack(pts)
        lo, hi = xy.min(axis=0), xy.max(axis=0)
        pad = 0.08 * float(max(hi - lo)) + 1e-9
        self.ax.set_xlim(lo[0] - pad, hi[0] + pad)
        self.ax.set_ylim(lo[1] - pad, hi[1] + pad)

    def update(self) -> None:
        """Replay the construction for :attr:`params` and redraw (message if invalid)."""
        p = self.params
        try:
            g = Grasp(p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], mu1=p["mu1"], mu2=p["mu2"])
            c = internal_force_diagram(g)
        except (InvalidGraspError, GeometryError, ValueError) as exc:
            self._show_error(str(exc))
            return
        self.construction, self.error = c, None
        self.message.set_visible(False)
        num = {s.name: evaluate(s.obj) for s in c.steps if s.kind in ("point", "line", "circle")}
        span = 100.0 * (1.0 + max(abs(v) for v in p.values()))

        def far(line: Any) -> tuple[list[float], list[float]]:  # a long segment of a line
            (px, py), (dx, dy) = line
            return [px - span * dx, px + span * dx], [py - span * dy, py + span * dy]

        for i, n in enumerate((1, 2, 3, 4)):
            self.sides[i].set_data(*far(num[f"side{n}"]))
            self.perps[i].set_data(*far(num[f"perp{n}"]))
            (cx, cy), r = num[f"circle{n}"]
            self.circles[i].set_center((cx, cy))
            self.circles[i].set_radius(r)
        reach = 0.6 * math.dist(num["P1"], num["P2"])
        for i, (a, b) in enumerate(((1, 3), (2, 4))):
            self.cones[i].set_xy(wedge(num[f"P{i + 1}"], num[f"side{a}"][1], num[f"side{b}"][1],
                                       reach))
        names = ("P1x", "P2x", "O_M", *(f"{k}{n}" for k in "XYV" for n in (1, 2, 3, 4)))
        self.points.set_data([num[k][0] for k in names], [num[k][1] for k in names])
        self.contacts.set_data([num["P1"][0], num["P2"][0]], [num["P1"][1], num["P2"][1]])
        for name, text in self.labels.items():
            text.xy = num[name]
        env = c["envelope"]
        theta = np.linspace(0.0, 2 * np.pi, self.samples)
        self.envelope_xy = env.polyline(self.samples)
        k = env.k(theta)
        self.envelope_line.set_data(self.envelope_xy[:, 0], self.envelope_xy[:, 1])
        self.fill.set_xy(self.envelope_xy)
        iw, ib = int(np.argmax(k)), int(np.argmin(k))
        self.worst, self.best = (float(theta[iw]), float(k[iw])), (float(theta[ib]), float(k[ib]))
        self.worst_mark.set_data([self.envelope_xy[iw, 0]], [self.envelope_xy[iw, 1]])
        self.best_mark.set_data([self.envelope_xy[ib, 0]], [self.envelope_xy[ib, 1]])
        d = p["x1"] + p["x2"]
        self.info.set_text(
            "k_grasp(θ), eq. (25)\nF_int = k / (x1 + x2) · F_e, eq. (17)\n\n"
            f"worst case: θ = {math.degrees(self.worst[0]):.1f}°\n"
            f"  k = {self.worst[1]:.4g}, F_int/F_e = {self.worst[1] / d:.4g}\n"
            f"best case:  θ = {math.degrees(self.best[0]):.1f}°\n"
            f"  k = {self.best[1]:.4g}, F_int/F_e = {self.best[1] / d:.4g}\n\n"
            "drag P1, P2; press f to fit the view")
        self._set_faded(False)
        self.fig.canvas.draw_idle()

    def _show_error(self, text: str) -> None:
        self.error = text
        self.message.set_text("Not a valid grasp:\n" + textwrap.fill(text, 58))
        self.message.set_visible(True)
        self.info.set_text("(no diagram: see the message)")
        self._set_faded(True)
        self.fig.canvas.draw_idle()

    def _set_faded(self, faded: bool) -> None:
        for a, alpha in self._alphas.items():
            a.set_alpha(0.15 * (alpha or 1.0) if faded else alpha)

    # -- interaction ----------------------------------------------------------
    def set_params(self, **values: float) -> None:
        """Set parameters (x1, x2, y, phi1, phi2 in radians, mu1, mu2) and redraw.

        The sliders move to the new values (clipped to their range for display).
        """
        unknown = set(values) - set(self.params)
        if unknown:
            raise ValueError(f"unknown parameter(s) {', '.join(sorted(unknown))}; "
                             f"use {', '.join(self.params)}")
        self.params.update({k: float(v) for k, v in values.items()})
        self._sync_sliders(values)
        self.update()

    def drag(self, point: str, x: float, y: float) -> None:
        """Move contact ``"P1"`` or ``"P2"`` to ``(x, y)`` as a mouse drag would."""
        if point == "P1":
            self.set_params(x1=x, y=y)
        elif point == "P2":
            self.set_params(x2=-x, y=y)
        else:
            raise ValueError(f"only P1 and P2 can be dragged, not {point!r}")

    def _sync_sliders(self, values: dict[str, float]) -> None:
        self._syncing = True
        try:
            for k, v in values.items():
                unit = _UNIT[k]
                s = self.sliders[k]
                s.set_val(min(max(v / unit, s.valmin), s.valmax))
        finally:
            self._syncing = False

    def _on_slider(self, name: str, val: float) -> None:
        if self._syncing:
            return
        self.params[name] = float(val) * _UNIT[name]
        self.update()

    def _press(self, event: Any) -> None:
        if event.inaxes is not self.ax or event.button != 1:
            return
        for name in ("P1", "P2"):
            px, py = self.ax.transData.transform(
                (self.params["x1"], self.params["y"]) if name == "P1"
                else (-self.params["x2"], self.params["y"]))
            if math.hypot(event.x - px, event.y - py) <= _PICK_PX:
                self._dragging = name
                return

    def _move(self, event: Any) -> None:
        if self._dragging and event.inaxes is self.ax and event.xdata is not None:
            self.drag(self._dragging, float(event.xdata), float(event.ydata))

    def _release(self, event: Any) -> None:
        self._dragging = None

    def _key(self, event: Any) -> None:
        if event.key == "f":
            self.fit()
            self.fig.canvas.draw_idle()


def _interactive(backend: str) -> bool:
    """Whether matplotlib's ``backend`` can show a window."""
    try:
        from matplotlib.backends import BackendFilter, backend_registry

        static = backend_registry.list_builtin(BackendFilter.NON_INTERACTIVE)
    except ImportError:  # matplotlib < 3.9
        from matplotlib import rcsetup

        static = rcsetup.non_interactive_bk
    name = backend.lower()
    return name not in {b.lower() for b in static} and "inline" not in name


def explore(grasp: Grasp | None = None) -> Explorer:
    """Open the explorer in a window (pyplot); returns it after the window closes.

    Raises
    ------
    ValueError
        When matplotlib has no interactive backend (no display).
    """
    import matplotlib
    from matplotlib import pyplot as plt

    backend = matplotlib.get_backend()
    if not _interactive(backend):
        raise ValueError(f"cannot open the explorer window: matplotlib's backend {backend!r} "
                         "cannot show windows (no display?); in Jupyter use explore_notebook()")
    fig = plt.figure(figsize=(11, 7.5))
    ex = Explorer(grasp, fig=fig)
    plt.show()
    return ex


def explore_notebook(grasp: Grasp | None = None) -> Any:
    """The Jupyter explorer: ipywidgets sliders over the diagram, as an image.

    Returns an ``ipywidgets.VBox``; display it as a cell's last expression.

    Raises
    ------
    ImportError
        When ipywidgets is not installed.
    """
    try:
        import ipywidgets as w
    except ImportError as exc:
        raise ImportError("explore_notebook needs ipywidgets: pip install ipywidgets") from exc
    ex, image = Explorer(grasp), w.Image(format="png")

    def render(*_: Any) -> None:
        buf = io.BytesIO()
        ex.fig.savefig(buf, format="png", dpi=80)
        image.value = buf.getvalue()

    controls = []
    for name, label, unit in PARAMS:
        s = ex.sliders[name]
        c = w.FloatSlider(value=s.val, min=s.valmin, max=s.valmax, step=(s.valmax - s.valmin) / 400,
                          description=label.replace("$", "").replace("\\", ""))
        c.observe(lambda ch, n=name, u=unit: (ex.set_params(**{n: ch["new"] * u}), render()),
                  names="value")
        controls.append(c)
    render()
    box = w.VBox([w.HBox([w.VBox(controls[:4]), w.VBox(controls[4:])]), image])
    box.explorer = ex
    return box
