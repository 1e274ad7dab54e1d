"""The explorer's widgets and events: sliders, mouse and keys, the Jupyter controls.

Private to :mod:`graspcompass.render.explorer` (issue 21: the explorer under 600 lines).
:class:`_Events` holds the :class:`~graspcompass.render.explorer.Explorer`'s handlers of
slider, mouse and key events; :func:`notebook_box` the ipywidgets of
:func:`~graspcompass.render.explorer.explore_notebook`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from matplotlib.widgets import Slider

__all__ = ["PARAMS", "notebook_box"]

#: Slider name, label, unit factor to the model (degrees for φ and θ).
PARAMS = (
    ("x1", "$x_1$", 1.0),
    ("x2", "$x_2$", 1.0),
    ("y", "$y$", 1.0),
    ("phi1", r"$\varphi_1$ (°)", math.pi / 180),
    ("phi2", r"$\varphi_2$ (°)", math.pi / 180),
    ("mu1", r"$\mu_1$", 1.0),
    ("mu2", r"$\mu_2$", 1.0),
    ("theta", r"$\theta$ (°)", math.pi / 180),
)
_UNIT = {p[0]: p[2] for p in PARAMS}
_PICK_PX = 12.0


class _Slider(Slider):
    """A :class:`~matplotlib.widgets.Slider` that ignores clicks on other axes at once.

    Every slider sees every mouse event; a plain Slider tests a press with
    ``Axes.contains`` (about 1 ms each, eight sliders per click), this one
    compares ``event.inaxes`` first.  Behaviour is unchanged: a slider that is
    not being dragged does nothing with a press outside its axes.
    """

    def ignore(self, event: Any) -> bool:
        return super().ignore(event) or (
            not self.drag_active and getattr(event, "inaxes", self.ax) is not self.ax
        )


class _Events:
    """The Explorer's event handlers (a mixin: the Explorer holds the state)."""

    params: dict[str, float]
    sliders: dict[str, Any]
    ax: Any
    fig: Any
    _syncing: bool
    _dragging: str | None

    if TYPE_CHECKING:  # the Explorer's own methods

        def update(self, changed: Iterable[str] | None = None) -> None: ...
        def drag(self, point: str, x: float, y: float) -> None: ...
        def fit(self) -> None: ...
        def set_params(self, **values: float) -> None: ...

    def _sync_sliders(self, values: dict[str, float]) -> None:
        self._syncing = True
        try:
            for k, v in values.items():
                unit = _UNIT[k]
                s = self.sliders[k]
                s.set_val(min(max(float(v) / unit, s.valmin), s.valmax))
        finally:
            self._syncing = False

    def _on_slider(self, name: str, val: float) -> None:
        if self._syncing:
            return
        self.params[name] = float(val) * _UNIT[name]
        self.update((name,))

    def _press(self, event: Any) -> None:
        if event.inaxes is not self.ax or event.button != 1:
            return
        for name in ("P1", "P2"):
            px, py = self.ax.transData.transform(
                (self.params["x1"], self.params["y"])
                if name == "P1"
                else (-self.params["x2"], self.params["y"])
            )
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

        static = rcsetup.non_interactive_bk  # type: ignore[attr-defined]  # gone in 3.9
    name = backend.lower()
    return name not in {b.lower() for b in static} and "inline" not in name


def notebook_box(ex: Any, w: Any) -> Any:
    """The ipywidgets (module ``w``) of the Explorer ``ex``: sliders above its image."""
    image = w.Image(format="png")

    def render(*_: Any) -> None:
        image.value = ex.png()

    controls = []
    for name, label, unit in PARAMS:
        s = ex.sliders[name]
        c = w.FloatSlider(
            value=s.val,
            min=s.valmin,
            max=s.valmax,
            step=(s.valmax - s.valmin) / 400,
            description=label.replace("$", "").replace("\\", ""),
        )

        def moved(ch: Any, n: str = name, u: Any = unit) -> None:
            ex.set_params(**{n: ch["new"] * u})
            render()

        c.observe(moved, names="value")
        controls.append(c)
    render()
    box = w.VBox([w.HBox([w.VBox(controls[:4]), w.VBox(controls[4:])]), image])
    box.explorer = ex
    return box
