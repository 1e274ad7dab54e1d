"""A counterexample drawn: the file's object and the paper's, side by side (issue 11 §2).

``graspcompass check FILE --against paper --draw OUT.png`` draws, for the first
object of the file that the checker refuted, the grasp of its counterexample
twice: on the left the file's construction replayed at that grasp, on the right
the paper's (§3.3), the object in question highlighted in both.

Examples
--------
>>> from graspcompass.construction.language import parse, paper_text
>>> wrong = paper_text().replace("perpendicular side1 P2x", "perpendicular side1 P1x")
>>> fig = figure_counterexample(parse(wrong), "V1", {"x1": "2", "x2": "1", "y": "1/2",
...     "phi1": "pi/2", "phi2": "pi/2", "mu1": "3/4", "mu2": "1"})
>>> [ax.get_title().split(":")[0] for ax in fig.axes]
['the file', 'the paper (§3.3)']
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from matplotlib.figure import Figure

from ..construction import internal_force_diagram
from ..construction.language import replay
from ..construction.program import Program
from ..grasp import Grasp
from .figure import draw_construction
from .theme import DEFAULT_THEME, Theme

__all__ = ["figure_counterexample"]


def _highlight(artists: list[Any], theme: Theme) -> None:
    for a in artists:
        for setter, value in (
            ("set_color", theme.highlight_color),
            ("set_linewidth", 2.6),
            ("set_markersize", 10),
            ("set_zorder", 20),
        ):
            if hasattr(a, setter):
                try:
                    getattr(a, setter)(value)
                except (TypeError, ValueError, AttributeError):
                    pass


def _points(obj: Any) -> list[tuple[float, float]]:
    """Points that show ``obj``: a point itself; a circle's box corners."""
    try:
        if hasattr(obj, "center"):
            (x, y), r = obj.center.evalf(), float(obj.radius)
            return [(x - r, y - r), (x + r, y + r)]
        return [obj.evalf()]
    except (AttributeError, TypeError, ValueError):
        return []


def _short(obj: Any) -> str:
    """``≈ (x, y)`` to 4 digits for a point, the centre and radius of a circle."""
    try:
        if hasattr(obj, "center"):
            x, y = obj.center.evalf()
            return f"centre ≈ ({x:.4g}, {y:.4g}), r ≈ {float(obj.radius):.4g}"
        x, y = obj.evalf()
        return f"≈ ({x:.4g}, {y:.4g})"
    except (AttributeError, TypeError, ValueError):
        return ""


def figure_counterexample(
    program: Program, name: str, point: Mapping[str, Any], theme: Theme = DEFAULT_THEME
) -> Figure:
    """The grasp ``point`` drawn by ``program`` (left) and by the paper (right).

    Parameters
    ----------
    program : Program
        The checked file; it declares the paper's parameters.
    name : str
        The refuted object (``"V3"``, ``"X1"``, ...), highlighted in both panels.
    point : mapping of str to str
        The counterexample (parameter name -> exact text), a grasp that satisfies
        condition (1): :attr:`graspcompass.proof.program_check.CheckRow.counterexample`.
    theme : Theme
        Colours and sizes.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes, titled ``"the file: NAME ≈ (x, y)"`` and ``"the paper (§3.3): NAME ≈ ..."``.
    """
    grasp = Grasp(**dict(point))
    mine, paper = replay(program, grasp), internal_force_diagram(grasp)
    fig = Figure(figsize=(12, 6), layout="constrained")
    axes = fig.subplots(1, 2)
    panels = ((axes[0], mine, "the file"), (axes[1], paper, "the paper (§3.3)"))
    for ax, c, _ in panels:
        upto = c.names.index(name) if c is paper and name in c else None  # up to the object
        _highlight(draw_construction(c, step=upto, ax=ax, theme=theme).get(name, []), theme)
    # one view box: the file's, widened to show the paper's object too
    (x0, x1), (y0, y1) = axes[0].get_xlim(), axes[0].get_ylim()
    for px, py in _points(paper[name]) if name in paper else ():
        pad = 0.1 * max(x1 - x0, y1 - y0)
        x0, x1, y0, y1 = min(x0, px - pad), max(x1, px + pad), min(y0, py - pad), max(y1, py + pad)
    for ax, c, who in panels:
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        for art in (*ax.texts, *ax.patches, *ax.lines, *ax.collections):
            art.set_clip_on(True)  # labels and arrows of objects outside the view stay out
            if hasattr(art, "set_annotation_clip"):
                art.set_annotation_clip(True)
        ax.set_title(
            f"{who}: {name} {_short(c[name]) if name in c else 'is not made'}",
            fontsize=theme.font_size,
        )
    values = ", ".join(f"{k} = {v}" for k, v in point.items())
    fig.suptitle(f"Counterexample for {name}: {values}", fontsize=theme.font_size + 1)
    return fig
