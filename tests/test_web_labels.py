"""One label placement and one palette in the web page too (issues 12 §4, 23).

The page of ``graspcompass export --format html`` places the paper's points' labels
with ``GCLabelling.fit`` (``labelling.js``), a port of :func:`graspcompass.scene.fit.fit`
(the hard rules of the SVG, TikZ and PNG labels), H's with the port of
:func:`graspcompass.labelling.place`, and reads its colours from
:data:`graspcompass.palette.PALETTE`.  Checked here:

* both ports give the Python functions' placements on random problems
  (hypothesis: anchors, texts, polylines with repeated and non-finite points,
  markers, frames; seeded crowded problems for ``fit``) and on the degenerate ones;
* the page, on the paper's four grasps at several steps and on random grasps, obeys
  the rules measured from the browser's layout: no label over a label or a marker,
  each nearer its own point than any other (a label with no such place is left out:
  zoom in); the page's placement is ``fit``'s on the page's own inputs after drags
  and zooms;
* the page's script writes no colour of its own.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _browser import chromium
from graspcompass import Grasp, internal_force_diagram, labelling
from graspcompass.export.html import EXPLORER_SCRIPTS, page_data, to_html, web_file
from graspcompass.palette import PALETTE
from graspcompass.scene.layout import label_tex

PRESETS = ["fig6", "table1a", "table1b", "table1c"]


# -- without a browser --------------------------------------------------------------------------
def test_page_script_has_no_colour_of_its_own() -> None:
    js = "\n".join(web_file(name) for name in EXPLORER_SCRIPTS)
    assert not re.findall(r"#[0-9a-fA-F]{3}(?:[0-9a-fA-F]{3})?\b", js)
    used = set(re.findall(r"COL\.(\w+)", js)) | set(re.findall(r'COL\["(\w+)"\]', js))
    used |= {f"circle{n}" for n in range(1, 5)} if 'COL["circle" + n]' in js else set()
    assert used, "the page reads no colour from the palette"
    assert used <= set(PALETTE), sorted(used - set(PALETTE))


def test_page_data_carries_the_palette_and_the_placement_rule() -> None:
    data = page_data(internal_force_diagram(Grasp.preset("fig6")))
    assert data["colors"] == PALETTE
    spec = data["labelling"]
    assert spec == json.loads(json.dumps(labelling.spec()))
    assert [tuple(o) for o in spec["offsets"]] == list(labelling.OFFSETS)
    assert spec["weights"] == labelling.WEIGHTS and spec["far"] == list(labelling.FAR)


# -- the port against the Python function -------------------------------------------------------
@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    with chromium("the web page's label placement") as b:
        yield b


@pytest.fixture(scope="module")
def port(browser: Any) -> Iterator[Any]:
    """A blank page with labelling.js and the constants of labelling.spec()."""
    page = browser.new_page()
    page.set_content("<!DOCTYPE html><html><body></body></html>")
    page.add_script_tag(content=web_file("labelling.js"))
    page.evaluate("s => { window.SPEC = s; }", labelling.spec())
    yield page
    page.close()


def _js_place(port: Any, problems: list[dict[str, Any]]) -> list[list[dict[str, Any]]]:
    return port.evaluate(
        "ps => ps.map(p => GCLabelling.place(p.anchors, p.texts, Object.assign({spec: SPEC}, "
        "p.opts)))",
        problems,
    )


def _py_place(p: dict[str, Any]) -> list[labelling.Placement]:
    o = p["opts"]
    return labelling.place(
        p["anchors"],
        p["texts"],
        curves=[np.asarray(c, dtype=float).reshape(-1, 2) for c in o.get("curves", [])],
        frame=tuple(o["frame"]) if o.get("frame") else None,
        avoid=[tuple(b) for b in o.get("avoid", [])],
        font_size=o.get("fontSize", labelling.FONT_PT),
        marker_size=o.get("markerSize", labelling.MARKER_PT),
        gap=o.get("gap", labelling.GAP_PT),
        obstacles=o.get("obstacles", []),
    )


def _same(js: list[dict[str, Any]], py: list[labelling.Placement]) -> None:
    assert len(js) == len(py)
    for i, (a, b) in enumerate(zip(js, py)):
        assert tuple(a["direction"]) == b.direction, (i, a, b)
        assert a["offset"] == pytest.approx(b.offset, abs=1e-9), i
        assert a["box"] == pytest.approx(b.box, abs=1e-9), i


NAMES = ["O", "O_M", "P1", "P2", "P1x", "V1", "V4", "X3", "Y2", "B12", "worst", "H"]
coord = st.floats(-40.0, 420.0, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord)
# polylines with repeated points, spikes and the odd non-finite vertex (dropped, as in Python)
huge = st.floats(-1e300, 1e300, allow_nan=False)
# huge vertices too: a circle near a bound of condition (1) is a huge polygon on the page
vertex = st.one_of(
    point,
    point,
    point,
    st.just((math.nan, 0.0)),
    st.just((math.inf, 5.0)),
    st.tuples(huge, coord),
    st.tuples(coord, huge),
)


@st.composite
def problems(draw) -> dict[str, Any]:
    n = draw(st.integers(1, 14))
    anchors = draw(st.lists(point, min_size=n, max_size=n))
    if n > 2 and draw(st.booleans()):  # coincident and near-coincident points
        anchors[1] = anchors[0]
        anchors[2] = (anchors[0][0] + 1e-9, anchors[0][1])
    texts = [
        "$" + " = ".join(draw(st.lists(st.sampled_from(NAMES), min_size=1, max_size=3))) + "$"
        for _ in range(n)
    ]
    curves = draw(st.lists(st.lists(vertex, min_size=0, max_size=12), max_size=5))
    if draw(st.booleans()):  # repeated vertices: zero-length segments
        curves.append([anchors[0], anchors[0], (anchors[0][0] + 30.0, anchors[0][1])])
    opts: dict[str, Any] = {
        "curves": [[list(v) for v in c] for c in curves],
        "obstacles": [list(v) for v in draw(st.lists(point, max_size=6))],
        "frame": draw(
            st.one_of(
                st.none(), st.just([0.0, 0.0, 388.08, 388.08]), st.just([0.0, 0.0, 388.08, 250.0])
            )
        ),
        "avoid": [[x, y, x + 20.0, y + 10.0] for x, y in draw(st.lists(point, max_size=3))],
    }
    if draw(st.booleans()):
        opts.update(
            fontSize=draw(st.sampled_from([8.0, 10.0, 14.5])),
            markerSize=draw(st.sampled_from([2.0, 4.0, 9.0])),
            gap=draw(st.sampled_from([0.0, 2.5, 6.0])),
        )
    return {"anchors": [list(a) for a in anchors], "texts": texts, "opts": opts}


@settings(
    max_examples=20,
    deadline=None,
    suppress_health_check=[
        HealthCheck.function_scoped_fixture,
        HealthCheck.too_slow,
        HealthCheck.data_too_large,
    ],
)
@given(st.lists(problems(), min_size=1, max_size=5))
def test_port_places_as_python(port: Any, batch: list[dict[str, Any]]) -> None:
    for js, p in zip(_js_place(port, batch), batch):
        _same(js, _py_place(p))


@settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(
    st.lists(st.lists(vertex, max_size=10), max_size=4),
    st.one_of(st.none(), st.tuples(coord, coord).map(lambda p: [p[0], p[1], p[0] + 90, p[1] + 60])),
)
def test_port_resamples_as_python(port: Any, curves: list, window: list | None) -> None:
    """The same samples of the curves, bit for bit; with a window, the same ones in it
    (without one, only curves of a sane size: a huge one has too many samples)."""
    if window is None:
        curves = [[v for v in c if max(map(abs, v)) < 1e4] for c in curves]
    got = port.evaluate(
        "([c, w]) => GCLabelling.resample(c, 1.5, w)",
        [[[list(v) for v in c] for c in curves], window],
    )
    js = np.asarray(got, dtype=float).reshape(-1, 2)
    py = labelling.resample(
        [np.asarray(c, dtype=float).reshape(-1, 2) for c in curves],
        1.5,
        window=tuple(window) if window else None,
    )
    if window is None:
        assert js.tolist() == py.tolist()
    else:
        x0, y0, x1, y1 = window

        def inside(a):
            return a[(a[:, 0] >= x0) & (a[:, 0] <= x1) & (a[:, 1] >= y0) & (a[:, 1] <= y1)]

        assert sorted(map(tuple, inside(js))) == sorted(map(tuple, inside(py)))


def test_port_on_a_crowd_on_a_grid(port: Any) -> None:
    """Points on a 12 pt grid and curves through the candidate boxes' edges: ties broken
    alike (the first best position), integer counts of samples alike."""
    xs = np.arange(100.0, 100.0 + 12.0 * 5, 12.0)
    anchors = [[float(x), float(y)] for x in xs for y in xs]
    curves = [[[0.0, float(y)], [388.08, float(y)]] for y in xs + 4.5]
    curves += [[[float(x) + 4.5, 0.0], [float(x) + 4.5, 388.08]] for x in xs]
    p = {
        "anchors": anchors,
        "texts": [f"$V_{{{i}}}$" for i in range(len(anchors))],
        "opts": {"curves": curves, "frame": [0.0, 0.0, 388.08, 388.08]},
    }
    (js,) = _js_place(port, [p])
    _same(js, _py_place(p))
    assert len({tuple(a["direction"]) for a in js}) > 3  # the crowd is spread, not one side


def test_port_sizes_texts_as_python(port: Any) -> None:
    texts = [
        "$O$",
        "$P_{1x}$",
        "$O = O_M = Y_4$",
        "$B_{12}$",
        "$\\theta_1$",
        "$worst$",
        "$$",
        "$_{}$",
        "$a b  c$",
    ]
    got = port.evaluate("ts => ts.map(t => GCLabelling.textSize(t, 10, SPEC))", texts)
    assert [tuple(g) for g in got] == [labelling.text_size(t, 10.0) for t in texts]


# -- the page -----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def explorer(browser: Any, tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    path = tmp_path_factory.mktemp("web") / "explorer.html"
    path.write_text(to_html(internal_force_diagram(Grasp.preset("fig6"))), encoding="utf-8")
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(path.as_uri())
    page.wait_for_selector("body[data-ready='1']", timeout=20_000)
    yield page
    page.close()


def _page_labels(page: Any, preset: str, step: int) -> list[tuple[tuple[str, ...], tuple]]:
    labels = page.evaluate(
        "([p, s]) => { const box = document.getElementById('gc-preset'); box.value = p; "
        "box.dispatchEvent(new Event('change')); graspcompass.step(s); graspcompass.fit(); "
        "return graspcompass.labels(); }",
        [preset, step],
    )
    return [
        (tuple(lab["names"]), tuple(lab["direction"]))
        for lab in labels
        if lab["names"][0] not in ("H", "worst", "best") and lab["shown"]
    ]


def test_page_labels_do_not_cover_each_other(explorer: Any) -> None:
    """The drawn labels' rectangles (measured in the browser, not estimated)."""
    for preset in PRESETS:
        _page_labels(explorer, preset, -1)
        rects = explorer.evaluate(
            "() => [...document.querySelectorAll('#gc-board text')]"
            ".filter(t => t.getAttribute('display') !== 'none' && "
            "t.style.visibility !== 'hidden' && t.textContent.trim() && "
            "!/^[−-]?[0-9.]+$/.test(t.textContent.trim()))"  # not the ticks
            ".map(t => { const r = t.getBoundingClientRect(); "
            "return [t.textContent, r.left, r.top, r.right, r.bottom]; })"
        )
        assert len(rects) >= 10, rects
        for i, a in enumerate(rects):
            for b in rects[i + 1 :]:
                w = min(a[3], b[3]) - max(a[1], b[1])
                h = min(a[4], b[4]) - max(a[2], b[2])
                assert w <= 1.0 or h <= 1.0, (preset, a, b)


def _page_vs_python(page: Any) -> None:
    """The page's last placement of the paper's points equals scene.fit.fit on what the page
    gave it (every label optional: one that no place suits is left out)."""
    from graspcompass.scene import fit as fitting

    got = page.evaluate("graspcompass.labels()")
    given_ = page.evaluate("graspcompass.labelInputs()")
    o = given_["opts"]
    want = fitting.fit(
        given_["anchors"],
        given_["texts"],
        curves=[np.array(c, dtype=float).reshape(-1, 2) for c in o["curves"]],
        frame=tuple(o["frame"]),
        obstacles=o["obstacles"],
        font_size=given_["fontSize"],
        marker_sizes=given_["markerSizes"],
        optional=[True] * len(given_["texts"]),
    )
    paper = [g for g in got if g["names"][0] not in ("H", "worst", "best")]
    assert len(paper) == len(want)
    for a, b in zip(paper, want):
        assert a["shown"] == (b is not None), (a, b)
        if b is not None:
            assert tuple(a["direction"]) == b.direction, (a, b)
            assert a["box"] == pytest.approx(list(b.box), abs=1e-6)


def test_page_places_as_python_after_drags_and_zooms(explorer: Any) -> None:
    """Random grasps set as the sliders would, then a zoom and a pan: each time the
    labels are placed again, as labelling.place places the page's own drawing."""
    rng = np.random.default_rng(12)
    explorer.evaluate("() => { graspcompass.step(-1); graspcompass.fit(); }")
    for _ in range(6):
        phi = rng.uniform(1.2, 1.9, 2)
        mu = rng.uniform(0.4, 1.5, 2)
        err = explorer.evaluate(
            "p => graspcompass.set(p)",
            {
                "x1": float(rng.uniform(0.3, 2)),
                "x2": float(rng.uniform(0.3, 2)),
                "y": float(rng.uniform(0, 1)),
                "phi1": float(phi[0]),
                "phi2": float(phi[1]),
                "mu1": float(mu[0]),
                "mu2": float(mu[1]),
                "theta": float(rng.uniform(0, 6)),
            },
        )
        if err:
            continue
        _page_vs_python(explorer)
    before = explorer.evaluate("graspcompass.labelInputs().anchors")
    explorer.evaluate("() => { graspcompass.board.zoomIn(); }")
    explorer.wait_for_timeout(100)
    _page_vs_python(explorer)
    explorer.evaluate(
        "() => { const b = graspcompass.board.getBoundingBox(); "
        "graspcompass.board.setBoundingBox([b[0] + 0.3, b[1], b[2] + 0.3, b[3]]); }"
    )
    explorer.wait_for_timeout(100)
    _page_vs_python(explorer)
    assert explorer.evaluate("graspcompass.labelInputs().anchors") != before


def test_page_near_a_bound_of_condition_1(explorer: Any) -> None:
    """φ1 + ξ1 → π/2: |V_1| grows like 1/cos(φ1 + ξ1) and its circle becomes a huge
    polygon on the board.  The labels still come (as labelling.place places them), and
    within rounding of the bound the page shows the refusal instead.  From Table I(a), not
    from whatever grasp an earlier test left (alone, from Fig. 6, the crowd about O goes
    to the insets and the board keeps five labels)."""
    explorer.select_option("#gc-preset", "table1a")
    explorer.evaluate("() => { graspcompass.step(-1); graspcompass.fit(); }")
    errors = []
    for eps in (1e-3, 1e-6, 1e-9, 1e-11, 1e-13, 0.0):
        err = explorer.evaluate(
            "e => graspcompass.set({phi1: Math.PI / 2 - Math.atan(graspcompass.get('mu1')) + e})",
            eps,
        )
        errors.append(err)
        if err is None:
            _page_vs_python(explorer)
            assert len(explorer.evaluate("graspcompass.labels()")) >= 6
    assert errors[:3] == [None] * 3 and "condition (1)" in errors[-1]


# -- the port of scene.fit (the hard rules of the SVG, TikZ and PNG labels) -------------------
def _fit_problem(rnd: np.random.Generator, n: int) -> dict[str, Any]:
    """A crowded random problem: points in a small square of a 388 pt frame, a few on
    top of each other, polylines through them, break points among them."""
    centre = rnd.uniform(60, 320, 2)
    pts = centre + rnd.normal(0, rnd.choice([6.0, 15.0, 40.0]), (n, 2))
    if n > 2:
        pts[1] = pts[0] + rnd.normal(0, 1.5, 2)
    names = ["O", "P1", "P2x", "X1", "Y3", "V4", "O_M", "B12", "X4", "Y2"]
    texts = ["$" + label_tex(names[i % len(names)]) + "$" for i in range(n)]
    curves = [rnd.uniform(0, 388, (int(rnd.integers(2, 6)), 2)).tolist() for _ in range(3)]
    return {
        "anchors": pts.tolist(),
        "texts": texts,
        "opts": {
            "curves": curves,
            "frame": [0.0, 0.0, 388.0, 388.0],
            "obstacles": (centre + rnd.normal(0, 10, (3, 2))).tolist(),
            "optional": [bool(b) for b in rnd.integers(0, 2, n)],
        },
    }


def test_port_of_fit_gives_the_python_placement(port: Any) -> None:
    """GCLabelling.fit against scene.fit.fit on seeded random crowded problems: the same
    labels left out, the same sides, leaders and verdicts, the same boxes."""
    from graspcompass.scene import fit as fitting

    rnd = np.random.default_rng(23)
    problems = [_fit_problem(rnd, int(rnd.integers(1, 12))) for _ in range(40)]
    got = port.evaluate(
        "([ps, sp]) => ps.map(p => GCLabelling.fit(p.anchors, p.texts, "
        "Object.assign({fitSpec: sp}, p.opts)))",
        [problems, fitting.spec()],
    )
    compared = 0
    for p, js in zip(problems, got):
        o = p["opts"]
        want = fitting.fit(
            p["anchors"],
            p["texts"],
            curves=[np.array(c) for c in o["curves"]],
            frame=tuple(o["frame"]),
            obstacles=o["obstacles"],
            optional=o["optional"],
        )
        assert len(js) == len(want)
        for a, b in zip(want, js):
            assert (a is None) == (b is None)
            if a is None:
                continue
            assert (tuple(b["direction"]), b["leader"], b["ok"]) == (a.direction, a.leader, a.ok)
            assert b["box"] == pytest.approx(list(a.box), abs=1e-9)
            compared += 1
    assert compared > 100


def test_extent_port_is_the_metrics_of_the_font(port: Any) -> None:
    from graspcompass.scene import fit as fitting
    from graspcompass.scene import metrics

    texts = ["$O = O_M = Y_4$", "$P_{1x}, V_4$", "$X_2$", "$B_{12}$"]
    got = port.evaluate(
        "([ts, sp]) => ts.map(t => GCLabelling.extent(t, 10, sp.metrics))", [texts, fitting.spec()]
    )
    for t, g in zip(texts, got):
        assert g == pytest.approx(list(metrics.extent(t, 10.0)), abs=1e-12)


def test_page_labels_name_their_points_in_chromium(explorer: Any) -> None:
    """The rules of the SVG's labels (tests/test_svg_labels_browser.py) on the page, placed
    by the port of scene.fit: no label over a label or a marker, each nearer its own point
    than any other, measured from the browser's layout, for the presets and random grasps
    (every step a labelled point appears and the whole construction)."""
    from test_svg_labels_browser import faults, random_grasps

    report = {}
    for preset in PRESETS:
        explorer.evaluate(
            "p => { const box = document.getElementById('gc-preset'); box.value = p; "
            "box.dispatchEvent(new Event('change')); graspcompass.fit(); }",
            preset,
        )
        c = internal_force_diagram(Grasp.preset(preset))
        steps = [s.index for s in c.steps if s.kind == "point" and s.role != "break_point"]
        for i in [*steps[2::4], len(c.steps) - 1]:
            pts = explorer.evaluate(
                "s => { graspcompass.step(s); return graspcompass.labelRects(); }", i
            )
            found = faults([{"panel": f"{preset}@{i}", "pts": pts}])
            if found:
                report[f"{preset}@{i}"] = found
    explorer.evaluate("() => { graspcompass.step(-1); }")
    shown = 0
    for g in random_grasps(6, seed=2323):
        p = {k: float(v) for k, v in g.params.items()}
        err = explorer.evaluate(
            "p => { const e = graspcompass.set(p); graspcompass.fit(); return e; }",
            {
                "x1": p["x1"],
                "x2": p["x2"],
                "y": p["y"],
                "phi1": p["phi1"],
                "phi2": p["phi2"],
                "mu1": p["mu1"],
                "mu2": p["mu2"],
            },
        )
        if err:
            continue
        pts = explorer.evaluate("graspcompass.labelRects()")
        shown += sum(q["t"] is not None for q in pts)
        found = faults([{"panel": str(p), "pts": pts}])
        if found:
            report[str(p)] = found
    assert shown >= 6 * 6
    assert not report, report


def test_page_leaves_out_few_labels(explorer: Any) -> None:
    """A label with no place that keeps the rules is left out (zoom in to read it): of the
    final picture's labels of each preset, at most two."""
    for preset in PRESETS:
        labels = explorer.evaluate(
            "p => { const box = document.getElementById('gc-preset'); box.value = p; "
            "box.dispatchEvent(new Event('change')); graspcompass.step(-1); graspcompass.fit(); "
            "return graspcompass.labels(); }",
            preset,
        )
        paper = [lab for lab in labels if lab["names"][0] not in ("H", "worst", "best")]
        assert len(paper) >= 8
        assert sum(not lab["shown"] for lab in paper) <= 2, (preset, paper)
