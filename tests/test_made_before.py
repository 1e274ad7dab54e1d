"""Nothing before it is made (issue 23): the picture cut at step N of the recipe (the
scene, the PNG's artists, the SVG, an animation frame) draws and names nothing made after
N; a friction cone only once both its sides exist.  The steps made by N are read from the
protocol itself (``c.upto(N).names``), the cones' sides from their roles."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import matplotlib
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram
from graspcompass.export import to_svg
from graspcompass.scene.layout import label_tex
from graspcompass.scene.picture import scene_of

matplotlib.use("Agg")

PRESETS = ["fig6", "table1a", "table1b", "table1c"]
NS = {"s": "http://www.w3.org/2000/svg"}


def _sides(c) -> dict[str, set[str]]:
    """cone i -> the names of its two sides (roles ``cone_side`` i and i + 2)."""
    side = {s.n[0]: s.name for s in c.steps if s.role == "cone_side"}
    return {"cone1": {side[1], side[3]}, "cone2": {side[2], side[4]}}


def _names_of_label(text: str, names: list[str]) -> set[str]:
    by_tex = {label_tex(n): n for n in names}
    return {by_tex[p] for p in re.split(" = |, ", text.strip("$"))}


def _check_scene(c, n: int) -> None:
    made = set(c.upto(n).names)
    cut = scene_of(c).upto(n)
    drawn = (
        {x[0] for x in cut.lines}
        | {x[0] for x in cut.lengths}
        | {x[0] for x in cut.circles}
        | {m for g, _ in cut.points for m in g}
    )
    assert drawn <= made, (n, drawn - made)
    named = {m for lab in cut.labels for m in lab.names}
    assert named <= made, (n, named - made)
    used = {i.step for i in cut.instruments}  # compass arcs, right angles, guides
    assert used <= made, (n, used - made)
    assert bool(cut.envelope) == ("envelope" in made)
    sides = _sides(c)
    assert len(cut.cones) == sum(sides[k] <= made for k in ("cone1", "cone2")), n


def _check_svg(c, n: int) -> None:
    made = set(c.upto(n).names)
    names = [s.name for s in c.steps]
    root = ET.fromstring(to_svg(c, step=n).encode())
    ids = {
        re.sub(r"^inset\d*-", "", g.get("id"))  # the panels' ids: inset-, inset2-, ...
        for g in root.iterfind(".//s:g", NS)
        if g.get("id") and g.get("class") not in ("panel", "drawing")
    }
    assert ids <= made, (n, ids - made)
    for t in root.iterfind(".//s:g[@class='point']/s:text", NS):
        text = (t.text or "") + "".join(("_" + (sub.text or "")) + (sub.tail or "") for sub in t)
        parts = {p.strip() for p in re.split("[=,]", text)}
        by_svg = {label_tex(m).replace("{", "").replace("}", ""): m for m in names}
        assert {by_svg[p] for p in parts} <= made, (n, text)
    used = {
        p.get("data-step")
        for p in root.iterfind(".//s:polyline", NS)
        if "instrument" in (p.get("class") or "")
    }
    assert used <= made, (n, used - made)
    if n == len(c.steps) - 1:
        assert used, "the compass arcs and right angles of the whole construction"
    cones = {re.sub(r"^inset\d*-", "", p.get("id")) for p in root.iterfind(".//s:polygon", NS)}
    sides = _sides(c)
    assert cones == {k for k in ("cone1", "cone2") if sides[k] <= made}, n


def _check_png(c, n: int) -> None:
    from matplotlib.text import Annotation

    from graspcompass.render.figure import EXTRA_KEYS, draw_construction

    made = set(c.upto(n).names)
    names = [s.name for s in c.steps]
    arts = draw_construction(c, step=n)
    assert set(arts) - set(EXTRA_KEYS) <= made
    ax0 = arts["O"][0].axes
    shown = {a for a in ax0.lines if (a.get_gid() or "").startswith("instrument:")}
    assert len(shown) == len(scene_of(c).upto(n).instruments), n
    sides = _sides(c)
    assert {k for k in ("cone1", "cone2") if k in arts} == {
        k for k in ("cone1", "cone2") if sides[k] <= made
    }
    ax = arts["O"][0].axes
    for t in ax.texts:
        if isinstance(t, Annotation) and t.get_text().startswith("$"):
            assert _names_of_label(t.get_text(), names) <= made, (n, t.get_text())


@pytest.mark.parametrize("preset", PRESETS)
def test_every_step_of_the_presets(preset: str) -> None:
    c = internal_force_diagram(Grasp.preset(preset))
    for n in range(len(c.steps)):
        _check_scene(c, n)
    for n in (5, 6, 8, 10, 11, 17, 30, 32, 35, 40, len(c.steps) - 1):
        _check_svg(c, n)
    for n in (5, 6, 8, 11, 32):
        _check_png(c, n)


def _grasp(draw) -> Grasp:
    def angle() -> tuple[int, int]:
        phi = draw(st.integers(20, 160))
        xi = draw(st.integers(abs(phi - 90) + 2, 85))
        return phi, xi

    (p1, k1), (p2, k2) = angle(), angle()
    x1, x2 = draw(st.integers(10, 200)) / 100, draw(st.integers(10, 200)) / 100
    y = draw(st.integers(0, 150)) / 100
    return Grasp(x1, x2, y, f"{p1}*pi/180", f"{p2}*pi/180", xi1=f"{k1}*pi/180", xi2=f"{k2}*pi/180")


@settings(max_examples=6, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.data())
def test_every_step_of_random_grasps(data) -> None:
    c = internal_force_diagram(_grasp(data.draw))
    for n in range(len(c.steps)):
        _check_scene(c, n)
    n = data.draw(st.integers(0, len(c.steps) - 1))
    _check_svg(c, n)


#: A grasp whose label joins points apart but closer than a marker: ``O, X_4`` (X4 at step 30).
NEAR = Grasp(13 / 10, 3 / 5, 7 / 10, "70*pi/180", "75*pi/180", xi1="40*pi/180", xi2="35*pi/180")


@pytest.mark.parametrize("grasp", [Grasp.preset("fig6"), NEAR], ids=["fig6", "near"])
def test_animation_frames_show_nothing_before_it_is_made(grasp) -> None:
    from matplotlib.patches import Polygon
    from matplotlib.text import Annotation

    from graspcompass.render.animate import animate_construction

    c = internal_force_diagram(grasp)
    names = [s.name for s in c.steps]
    anim = animate_construction(
        c,
        frames_per_step=3,
        pause_frames=1,
        hold_frames=1,
        dpi=30,
        caption_seconds=0,
        reading_rate=0,
    )
    sides = _sides(c)
    cones = {k: anim.artists[k][0] for k in ("cone1", "cone2")}
    index = {s.name: s.index for s in c.steps}
    instrument_step = {}  # artist -> the first step drawing it (its owner)
    for s in reversed(c.steps):
        for a in anim.artists.get(s.name, []):
            instrument_step[id(a)] = s.name
    assert any((a.get_gid() or "").startswith("instrument:") for a in anim.axes.lines)
    for n in (6, 8, 9, 11, 13, 15, 17, 30, 32, 35):
        for f in anim.timeline.frames_of_step(n):
            st_ = anim.timeline.at(f)
            anim._apply(f)
            # made by this frame: the steps before n, and n once its stroke is done
            done = st_.kind != "draw" or st_.progress >= 1.0
            made = set(c.upto(n if done else n - 1).names)
            for t in anim.axes.texts:
                if (
                    isinstance(t, Annotation)
                    and t.get_visible()
                    and re.fullmatch(r"\$.*\$", t.get_text())
                ):
                    assert _names_of_label(t.get_text(), names) <= made, (n, f, t.get_text())
            for k, poly in cones.items():
                assert isinstance(poly, Polygon)
                if poly.get_visible():
                    assert sides[k] <= made, (n, f, k)
            # the compass arcs, right angles and guides of a step (their gid names their
            # role) are drawn with it, never before; a label's leader line with its label
            for line in anim.axes.lines:
                gid = line.get_gid() or ""
                if not line.get_visible() or not gid:
                    continue
                owner = instrument_step[id(line)]
                if gid == "leader":
                    assert owner in made, (n, f, owner)
                else:
                    assert index[owner] <= n, (n, f, owner, gid)


def _names_in_math(text: str, names: list[str]) -> set[str]:
    """The points a mathtext names: each ``$…$`` part's capitals with their subscripts
    (``P_{1x}``, ``O_M``, ``V_3``, ``O``) read as the recipe's names; a capital that is no
    point's letter (``F_\\mathrm{int}``) is no point."""
    by_tex = {label_tex(n): n for n in names}
    letters = {t[0] for t in by_tex}
    out = set()
    for part in re.findall(r"(?<!\\)\$(.*?)(?<!\\)\$", text):
        for tok in re.findall(r"[A-Z](?:_\{[^}]*\}|_[A-Za-z0-9])?", part):
            if tok[0] in letters:
                assert tok in by_tex, (text, tok)
                out.add(by_tex[tok])
    return out


@pytest.mark.parametrize("grasp", [Grasp.preset("fig6"), NEAR], ids=["fig6", "near"])
def test_the_lecture_side_panel_shows_nothing_before_it_is_made(grasp) -> None:
    _check_side_panel(internal_force_diagram(grasp))


@settings(max_examples=2, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.data())
def test_the_lecture_side_panel_of_random_grasps(data) -> None:
    _check_side_panel(internal_force_diagram(_grasp(data.draw)))


def _check_side_panel(c) -> None:
    """The lecture video's right panel (issue 23): every figure text right of the diagram
    names only points made by the frame (the caption: made by the end of its step), and
    the plot of k_grasp(θ) is there only from the envelope's step on, no further traced
    than the envelope in the diagram."""
    from graspcompass.render.animate import animate_construction

    names = [s.name for s in c.steps]
    anim = animate_construction(
        c,
        quality="lecture",
        frames_per_step=3,
        pause_frames=1,
        hold_frames=1,
        caption_seconds=0,
        reading_rate=0,
    )
    right = anim.axes.get_position().x1  # the diagram's right edge, figure fraction
    env = c.step("envelope").index
    trace = anim.artists["envelope"][0]
    listed: set[str] = set()
    upto = {n: set(names[: n + 1]) for n in range(-1, len(names))}  # the steps 0 to n
    plotted = False
    for f in range(anim.frame_count):
        st_ = anim.timeline.at(f)
        anim._apply(f)
        n = st_.step
        if st_.kind in ("hold", "inset", "title"):  # the finished figure, the title card
            continue
        done = st_.kind != "draw" or st_.progress >= 1.0
        made = upto[n if done else n - 1]
        for t in anim.figure.texts:
            if not t.get_visible() or t.get_position()[0] <= right:
                continue
            shown = _names_in_math(t.get_text(), names)
            if t is anim._caption:
                # the text after the paper's reference ("§3.3 V_1 (1), Fig. 4(a): ...", the
                # goal the step works towards) names the step's object and its inputs
                body = t.get_text().split("\n", 1)[1].split(": ", 1)[1]
                shown = _names_in_math(body, names)
                assert shown <= upto[n], (n, f, body)
            else:
                assert shown <= made, (n, f, t.get_text())
                listed |= shown
        plots = [a for a in anim.figure.axes if a is not anim.axes and a.get_visible()]
        assert not plots or n >= env, (n, f)
        for a in plots:
            plotted = True
            for line in a.lines:
                if line.get_visible() and len(line.get_xdata()):
                    # the plot has no more θ than the envelope traced in the diagram
                    assert len(line.get_xdata()) <= max(1, len(trace.get_xdata())), (n, f)
    # the panel is in use: it listed the points, and it plotted k_grasp
    assert {"P1", "P2", "V1", "V4", "B34"} <= listed and plotted
