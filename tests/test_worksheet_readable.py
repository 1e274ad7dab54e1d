"""The worksheet read as a student reads it (issue 23).

No text over text (an overline of one line once cut through the line above); cone sides
long enough to lay a ruler on, each with its angle φ_i ± ξ_i from the negative y-axis
(§2.2.1); the contact labels clear of the sides; an exercise that reads k_grasp(θ) off
the drawing and computes F_int (eqs. (25), (17)), answered on page 2 with the values of
the closed form (eqs. (28)-(39), written out here again); a legend and the crowded
centre enlarged on page 2; the numeric objects computed once per worksheet.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

pytest.importorskip("matplotlib")

import matplotlib
from matplotlib.lines import Line2D
from matplotlib.text import Text

from graspcompass import Grasp, layout
from graspcompass.render.handdrawing import Worksheet, worksheet_pages

OWN = dict(
    x1="1.2",
    x2="0.3",
    y="0.4",
    phi1="61*pi/180",
    phi2="118*pi/180",
    xi1="67*pi/180",
    xi2="49*pi/180",
)


@pytest.fixture(scope="module")
def fig6() -> Worksheet:
    return worksheet_pages(Grasp.preset("fig6"))


@pytest.fixture(scope="module")
def own() -> Worksheet:
    return worksheet_pages(Grasp(**OWN))


def _boxes(ws: Worksheet, page: int) -> list[tuple[str, object]]:
    fig = ws.figures[page]
    with matplotlib.rc_context({"text.hinting": "no_hinting"}):
        r = fig.canvas.get_renderer()
        return [(t.get_text(), t.get_window_extent(r)) for t in fig.texts if t.get_text()]


@pytest.mark.parametrize("which", ["fig6", "own"])
@pytest.mark.parametrize("page", [0, 1])
def test_no_text_over_text(which: str, page: int, request: pytest.FixtureRequest) -> None:
    """Measured boxes of every text of the page (overlines included) do not overlap; lines
    keep at least 0.5 pt between them (an overline once touched the line above)."""
    ws = request.getfixturevalue(which)
    boxes = _boxes(ws, page)
    assert len(boxes) > 40
    for i, (ta, a) in enumerate(boxes):
        for tb, b in boxes[i + 1 :]:
            w = min(a.x1, b.x1) - max(a.x0, b.x0)
            h = min(a.y1, b.y1) - max(a.y0, b.y0)
            assert w <= 0.3 or h <= -0.5, (ta, tb, w, h)


def test_cone_sides_are_long_and_carry_their_angles(fig6: Worksheet) -> None:
    sides = [a for a in fig6.artists[0]["cones"] if isinstance(a, Line2D)]
    assert len(sides) == 4
    for ln in sides:
        (x0, x1), (y0, y1) = ln.get_xdata(), ln.get_ydata()
        assert math.hypot(x1 - x0, y1 - y0) * fig6.scale >= 25 - 1e-9  # mm on paper
    # Fig. 6: φ1 = φ2 = 60°, ξ1 = 45°, ξ2 = 60°: the sides at 105°, 15° (P1, clockwise)
    # and 120°, 0° (P2, counter-clockwise) from the negative y-axis
    texts = [a.get_text() for a in fig6.artists[0]["cone angles"] if isinstance(a, Text)]
    got = sorted(re.search(r"= (\S+)°", t).group(1) for t in texts)
    assert got == sorted(["105", "15", "120", "0"])
    assert any("clockwise at $P_1$" in t for t in fig6.texts)


@pytest.mark.parametrize("which", ["fig6", "own"])
def test_contact_labels_clear_of_the_cone_sides(which: str, request: pytest.FixtureRequest) -> None:
    ws = request.getfixturevalue(which)
    ax = ws.axes[0]
    r = ws.figures[0].canvas.get_renderer()
    sides = [a for a in ws.artists[0]["cones"] if isinstance(a, Line2D)]
    for name in ("P1", "P2"):
        (label,) = [a for a in ws.artists[0][name] if isinstance(a, Text)]
        bb = label.get_window_extent(r)
        for ln in sides:
            xy = np.column_stack(
                [np.linspace(*ln.get_xdata()[:2], 200), np.linspace(*ln.get_ydata()[:2], 200)]
            )
            px = ax.transData.transform(xy)
            inside = (
                (px[:, 0] > bb.x0) & (px[:, 0] < bb.x1) & (px[:, 1] > bb.y0) & (px[:, 1] < bb.y1)
            )
            assert not inside.any(), (which, name)


def _closed_form_k(g: Grasp, theta: float) -> float:
    """k_grasp(θ) = max(0, S_n sin θ − C_n cos θ) with S_n, C_n of eqs. (28)-(39)."""
    x1, x2, y = (float(g.params[k]) for k in ("x1", "x2", "y"))
    h = (x1 + x2) / 2
    ks = [0.0]
    for i, (xa, sgn) in ((1, (x2, -1)), (2, (x1, 1))):
        phi, xi = float(g.params[f"phi{i}"]), float(g.params[f"xi{i}"])
        for t in (math.tan(phi + xi), math.tan(phi - xi)):
            S, C = sgn * h - sgn * y * t, xa * t
            ks.append(S * math.sin(theta) - C * math.cos(theta))
    return max(ks)


@pytest.mark.parametrize("which", ["fig6", "own"])
def test_read_off_exercise_and_its_answer(which: str, request: pytest.FixtureRequest) -> None:
    ws = request.getfixturevalue(which)
    g = ws.construction.grasp
    page1 = " ".join(ws.texts)
    m = re.search(r"Read off: draw the ray from \$O\$ at \$\\theta\$ = (\d+)°", page1)
    assert m and "$F_{int}" in page1 and "eq. (17)" in page1
    theta = int(m.group(1))
    assert theta % 15 == 0
    page2 = " ".join(t for t, _ in _boxes(ws, 1))
    k = _closed_form_k(g, math.radians(theta))
    F = k / float(g.params["x1"] + g.params["x2"])
    assert k > 0
    assert f"= {k:.3f}" in page2 and f"= {F:.3f} $F_e$" in page2, page2[-400:]
    assert "read off" in ws.artists[1]  # the ray drawn on the solution


def test_solution_has_a_legend_and_the_centre_enlarged(fig6: Worksheet) -> None:
    fig = fig6.figures[1]
    (leg,) = fig.legends
    entries = [t.get_text() for t in leg.get_texts()]
    for want in ("perpendicular", "signed length", "break point", "envelope", "circle on"):
        assert any(want in e for e in entries), (want, entries)
    inset = fig6.artists[1]["inset"][0]
    x0, x1 = inset.get_xlim()
    assert (x1 - x0) < 0.5 * (fig6.box[1] - fig6.box[0])  # the crowded centre, larger
    assert x0 < 0 < x1  # O, O_M, Y4 crowd there (Fig. 6)


def test_numeric_objects_once_per_worksheet(monkeypatch: pytest.MonkeyPatch) -> None:
    """The float values of the objects are computed once per worksheet (they were computed
    four times): every reader goes through the scene's one computation."""
    calls = []
    real = layout._numeric

    def counted(c: object) -> object:
        calls.append(1)
        return real(c)

    monkeypatch.setattr(layout, "_numeric", counted)
    worksheet_pages(Grasp.preset("table1c"))
    assert len(calls) == 1


# --- the labels as drawn: each names its point (issue 23) -------------------------------------
def _drawn_labels(ax) -> tuple[list, list]:
    """The point labels of ``ax`` as drawn (text, box, own point, pixels) and the round
    markers (centre, radius, pixels), measured by matplotlib's renderer: what the PDF shows."""
    from matplotlib.text import Annotation

    r = ax.figure.canvas.get_renderer()
    labels = [
        (t.get_text(), t.get_window_extent(r), ax.transData.transform(t.xy))
        for t in ax.texts
        if isinstance(t, Annotation)
        and t.get_visible()
        and t.get_text().startswith("$")
        and "°" not in t.get_text()  # not a cone side's angle
    ]
    marks = []
    for ln in ax.lines:
        if ln.get_visible() and ln.get_marker() == "o" and ln.get_linestyle() in ("None", "none"):
            xy = np.column_stack([ln.get_xdata(), ln.get_ydata()]).astype(float)
            rad = ln.get_markersize() * ax.figure.dpi / 72 / 2
            marks += [(p, rad) for p in ax.transData.transform(xy)]
    return labels, marks


def _to_box(p, bb) -> float:
    return math.hypot(max(bb.x0 - p[0], 0, p[0] - bb.x1), max(bb.y0 - p[1], 0, p[1] - bb.y1))


def _rule_faults(ax) -> list[str]:
    """Labels over labels, over another point's marker, nearer another point than their own."""
    labels, marks = _drawn_labels(ax)
    bad = []
    for i, (ta, a, pa) in enumerate(labels):
        for tb, b, _ in labels[i + 1 :]:
            if min(a.x1, b.x1) > max(a.x0, b.x0) and min(a.y1, b.y1) > max(a.y0, b.y0):
                bad.append(f"{ta} over {tb}")
        own = _to_box(pa, a)
        for p, rad in marks:
            if math.dist(p, pa) < 0.5:  # its own marker
                continue
            if _to_box(p, a) < rad:
                bad.append(f"{ta} over the marker at {np.round(p)}")
            elif _to_box(p, a) <= own:
                bad.append(f"{ta} nearer the point at {np.round(p)}")
    return bad


@pytest.mark.parametrize("which", ["fig6", "own"])
def test_page1_labels_beside_their_points(which: str, request: pytest.FixtureRequest) -> None:
    """Page 1 shows only the givens: O, P1, P2 are each named within 2.5 mm of their
    point, clear of every rule (the name of O sat 9 mm away, on a cone side, where the
    finished drawing puts the label O = O_M = Y4)."""
    ws = request.getfixturevalue(which)
    ax = ws.axes[0]
    labels, _ = _drawn_labels(ax)
    names = sorted(t for t, _, _ in labels)
    assert names == ["$O$", "$P_1$", "$P_2$"], names
    mm = 25.4 / ws.figures[0].dpi
    for text, bb, p in labels:
        assert _to_box(p, bb) * mm <= 2.5, (text, _to_box(p, bb) * mm)
    assert _rule_faults(ax) == []


@pytest.mark.parametrize("which", ["fig6", "own"])
def test_solution_labels_name_their_points(which: str, request: pytest.FixtureRequest) -> None:
    """Page 2, the drawing and the enlarged centre: no label over a label or over another
    point's marker, each nearer its own point than any other (the crowded centre of the
    drawing had labels nearer other points, P_1x = V_4 over the marker of X_3: the inset
    names those points)."""
    ws = request.getfixturevalue(which)
    inset = ws.artists[1]["inset"][0]
    for ax in (ws.axes[1], inset):
        assert _rule_faults(ax) == [], which
    # every point of the drawing is named in the drawing or in the inset
    named = {t for ax in (ws.axes[1], inset) for t, _, _ in _drawn_labels(ax)[0]}
    for s in ws.construction.steps:
        if s.kind == "point" and s.role != "break_point":
            plain = {re.sub(r"[_{}$]", "", t) for t in named}
            assert any(s.name.replace("_", "") in re.split(" = |, ", t) for t in plain), s.name


def test_solution_legend_shows_every_line_as_drawn(fig6: Worksheet) -> None:
    """The extended cone sides are drawn in the side colour and the given ones in black:
    the legend shows both (it showed one black line for both), the object, the compass
    arcs and the right-angle marks drawn."""
    from matplotlib.colors import to_hex

    (leg,) = fig6.figures[1].legends
    entries = dict(zip([t.get_text() for t in leg.get_texts()], leg.legend_handles))
    drawn = {
        to_hex(ln.get_color())
        for ln in fig6.axes[1].lines
        if ln.get_linestyle() == "-" and ln.get_marker() in ("None", "none", "")
    }
    side = to_hex(fig6.artists[1]["side1"][0].get_color())
    assert side in drawn
    shown = {to_hex(h.get_color()) for h in entries.values() if isinstance(h, Line2D)}
    assert side in shown and "#000000" in shown
    for want in ("the object", "right angle", "compass arcs", "extended", "given"):
        assert any(want in e for e in entries), (want, list(entries))


def test_page1_names_every_given_point() -> None:
    """With the feet given (--given feet), page 1 draws P1x, P2x and O_M and names them
    (it drew their markers unnamed: the cut of the givens was made by position while the
    picture cuts by protocol index); Fig. 6 has O_M = O (x1 = x2), one label for both."""
    ws = worksheet_pages(Grasp.preset("fig6"), steps="V3", given="feet")
    labels, marks = _drawn_labels(ws.axes[0])
    texts = sorted(t for t, _, _ in labels)
    assert texts == ["$O = O_M$", "$P_1$", "$P_2$", "$P_{1x}$", "$P_{2x}$"], texts
    assert len({tuple(np.round(p, 3)) for p, _ in marks}) == 5  # O = O_M, P1, P2, P1x, P2x
    assert _rule_faults(ws.axes[0]) == []
