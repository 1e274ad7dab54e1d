"""The web explorer (``graspcompass export --format html``) in a real browser (issue 12).

Headless Chromium (Debian's, ``/usr/bin/chromium``) driven by Playwright for
Python: the page loads with the network cut off and asks for nothing; dragging
P1 with the mouse and moving the sliders give V1..V4 (eqs. (28)-(39)), k_grasp
(eq. (25)) and the envelope's extreme points equal to the Python model's
closed form to 1e-9; the step navigator shows the protocol's captions,
numbered as ``graspcompass steps``; a grasp that breaks condition (1) shows
the inequality worded as :class:`graspcompass.InvalidGraspError` words it.

The browser tests skip, saying why, when Playwright or Chromium is missing
(``pip install playwright``; ``apt-get install chromium``: no ``playwright
install``, which downloads a browser).  Timings are reported by
``bench/bench_web.py``, not asserted here.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from typing import Any

import pytest

from _browser import chromium
from graspcompass import Grasp, internal_force_diagram
from graspcompass.construction import Construction
from graspcompass.construction.envelope import outer_envelope
from graspcompass.export import export
from graspcompass.export.html import WEB_FILES, to_html
from graspcompass.grasp import InvalidGraspError

TOL = 1e-9
PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")


# -- without a browser --------------------------------------------------------------------------
def test_installed_package_has_the_web_files() -> None:
    web = resources.files("graspcompass.export").joinpath("_web")
    for name in WEB_FILES:
        f = web.joinpath(name)
        assert f.is_file(), f"graspcompass/export/_web/{name} is not installed"
        assert f.read_bytes(), name
    assert "JSXGraph" in web.joinpath("jsxgraph.min.js").read_text("utf-8")[:2000]


def test_page_is_one_self_contained_file(fig6: Construction) -> None:
    page = to_html(fig6, title="Fig. 6 <explorer>")
    low = page.lower()
    assert "<script src" not in low and '<link rel="stylesheet"' not in low
    assert "@import" not in low and "sourcemappingurl" not in low
    assert "<title>Fig. 6 &lt;explorer&gt;</title>" in page
    assert page.count("</script>") == 4  # data, JSXGraph, the labels, the explorer


def test_symbolic_construction_is_refused() -> None:
    with pytest.raises(ValueError, match="numeric"):
        to_html(Construction((), Grasp.symbolic()))  # the page draws numbers


# -- the browser --------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def fig6() -> Construction:
    return internal_force_diagram(Grasp.preset("fig6"))


@pytest.fixture(scope="module")
def page_path(fig6: Construction, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return export(fig6, tmp_path_factory.mktemp("web") / "explorer.html", "html")


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    with chromium("the web explorer") as b:
        yield b


class Page:
    """One open explorer page, with the problems it reported."""

    def __init__(self, page: Any) -> None:
        self.page = page
        self.errors: list[str] = []
        self.requests: list[str] = []
        self.blocked: list[str] = []
        page.on("pageerror", lambda e: self.errors.append(f"page error: {e}"))
        page.on("console", lambda m: m.type == "error" and self.errors.append(m.text))
        page.on("request", lambda r: self.requests.append(r.url))

    def js(self, expr: str, arg: Any = None) -> Any:
        return self.page.evaluate(expr, arg)

    def get(self, name: str) -> Any:
        return self.js("n => graspcompass.get(n)", name)

    def params(self) -> dict[str, float]:
        return {k: self.get(k) for k in PARAMS}


@pytest.fixture(scope="module")
def opened(browser: Any, page_path: Path) -> Iterator[tuple[Page, dict[str, float]]]:
    """One page for the module (loading 1 MB of script takes a second or two), offline:
    every request but the page's own ``file:`` URL is aborted and kept in ``blocked``."""
    context = browser.new_context(viewport={"width": 1280, "height": 900}, offline=True)

    def route(r: Any) -> None:
        if r.request.url == page_path.as_uri():
            r.continue_()
        else:
            p.blocked.append(r.request.url)
            r.abort()

    context.route("**/*", route)
    p = Page(context.new_page())
    p.page.goto(page_path.as_uri())
    p.page.wait_for_selector("body[data-ready='1']", timeout=20_000)
    start = {k: p.get(k) for k in (*PARAMS, "theta")}
    yield p, start
    context.close()


@pytest.fixture()
def page(opened: tuple[Page, dict[str, float]]) -> Iterator[Page]:
    """The page back at its start: the Fig. 6 grasp, θ = 0, every step shown."""
    p, start = opened
    p.js(
        "s => { graspcompass.pause(); graspcompass.set(s); graspcompass.step(-1); "
        "graspcompass.fit(); }",
        start,
    )
    p.errors.clear()
    yield p
    assert not p.errors, p.errors


def python_grasp(params: dict[str, float]) -> Grasp:
    return Grasp(**{k: float(params[k]) for k in PARAMS})


def assert_matches_python(page: Page) -> Grasp:
    """V1..V4, X_n, Y_n, k_grasp and the envelope's extreme points against Python."""
    p = page.params()
    g = python_grasp(p)
    for n, v in enumerate(g.V, start=1):
        got = page.get(f"V{n}")
        want = (float(v.x), float(v.y))
        assert math.dist(got, want) <= TOL * max(1.0, math.hypot(*want)), (n, got, want)
        # X_n = (O_M.x − S_n, 0) and Y_n = (0, −C_n) (§3.3)
        assert abs(page.get(f"X{n}")[0] - ((p["x1"] - p["x2"]) / 2 - want[0])) <= TOL * 10
        assert abs(page.get(f"Y{n}")[1] + want[1]) <= TOL * 10
    norms = [math.hypot(float(v.x), float(v.y)) for v in g.V]
    env = page.js("graspcompass.envelope()")
    assert abs(env["worst"]["k"] - max(norms)) <= TOL * max(norms)
    for m in env["maxima"]:  # each extreme point of the envelope is a V_n, at k = |V_n|
        assert abs(m["k"] - norms[m["n"] - 1]) <= TOL * max(norms)
    # the arcs: the same circles in the same order, from the same angles, as the Python envelope
    arcs = internal_force_diagram(g)["envelope"].arcs
    assert [a["n"] for a in env["arcs"]] == [a.n for a in arcs]
    for a, b in zip(env["arcs"], arcs):
        assert abs(a["theta0"] - float(b.theta_start)) <= 1e-8
    for theta in (0.0, 1.0, 2.5, 4.0, p_theta := page.get("theta")):
        k = page.js("t => graspcompass.kGrasp(t)", theta)
        assert abs(k - g.k_grasp(float(theta))) <= TOL * max(1.0, max(norms))
    assert abs(page.get("kgrasp") - g.k_grasp(float(p_theta))) <= TOL * max(1.0, max(norms))
    return g


def test_loads_with_the_network_off(opened: tuple[Page, dict[str, float]], page_path: Path) -> None:
    """The page (opened offline, every other request aborted) asked for nothing but itself,
    whatever the other tests did with it before."""
    p, _ = opened
    assert p.js("typeof JXG") == "object" and p.js("typeof graspcompass.set") == "function"
    p.js("graspcompass.set({mu2: 1.1}); graspcompass.step(0); graspcompass.step(-1)")
    assert p.requests == [page_path.as_uri()], p.requests
    assert p.blocked == []


def test_start_values_are_the_closed_form(page: Page, fig6: Construction) -> None:
    assert page.get("step") == len(fig6) - 1
    assert page.js("graspcompass.error()") is None
    assert_matches_python(page)
    assert math.isfinite(page.js("graspcompass.lastUpdateMs"))


def user_at(page: Page, px: float, py: float) -> tuple[float, float, float]:
    """The user coordinates under the viewport pixel (px, py) in the view now, and the
    size of a pixel in user units."""
    return tuple(
        page.js(
            """([px, py]) => { const b = graspcompass.board;
        const r = b.containerObj.getBoundingClientRect();
        const c = new JXG.Coords(JXG.COORDS_BY_SCREEN, [px - r.left, py - r.top], b).usrCoords;
        return [c[1], c[2], 1 / b.unitX]; }""",
            [px, py],
        )
    )


def in_view(page: Page, name: str) -> bool:
    x, y = page.get(name)
    x0, y1, x1, y0 = page.js("graspcompass.board.getBoundingBox()")
    return x0 <= x <= x1 and y0 <= y <= y1


def test_drag_P1_with_the_mouse(page: Page) -> None:
    x0, y0 = page.js("graspcompass.toScreen('P1')")
    # where the mouse lets go, in the view of the drag (the view refits after it)
    ux, uy, px = user_at(page, x0 + 70, y0 - 45)
    mouse = page.page.mouse
    mouse.move(x0, y0)
    mouse.down()
    mouse.move(x0 + 70, y0 - 45, steps=8)
    mouse.up()
    # the page may still apply the last move in a later frame: read P1 once it is still
    # (two frames apart), within 2 s
    x1, y1 = page.get("P1")
    for _ in range(40):
        page.page.wait_for_timeout(50)
        x2, y2 = page.get("P1")
        if (x2, y2) == (x1, y1):
            break
        x1, y1 = x2, y2
    assert abs(x1 - ux) < 1.5 * px and abs(y1 - uy) < 1.5 * px  # P1 followed the mouse
    p = page.params()
    assert p["x1"] > math.sqrt(3) / 2 + 0.05 and p["y"] > 0.55
    assert page.get("P2") == [-p["x2"], p["y"]]  # P2 keeps the common y
    assert page.js("graspcompass.error()") is None
    assert_matches_python(page)
    # the drag is timed like a slider move
    assert len(page.js("graspcompass.timings()")) > 1
    # P2 = (−x2, y) drags x2 and y
    x0, y0 = page.js("graspcompass.toScreen('P2')")
    mouse.move(x0, y0)
    mouse.down()
    mouse.move(x0 - 30, y0 + 20, steps=4)
    mouse.up()
    q = page.params()
    assert q["x2"] > p["x2"] and q["y"] < p["y"] and q["x1"] == p["x1"]
    assert page.get("P1") == [q["x1"], q["y"]]
    assert_matches_python(page)


def test_sliders_move_the_diagram(page: Page) -> None:
    for name, value in (
        ("x2", "1.3"),
        ("phi1", "75"),
        ("mu2", "0.9"),
        ("mu1", "1.25"),
        ("y", "0.8"),
        ("theta", "123.5"),
        ("phi2", "100"),
    ):
        page.page.fill(f"#gc-slider-{name}", value)
    p = page.params()
    assert p["x2"] == 1.3 and p["mu2"] == 0.9 and p["y"] == 0.8
    assert abs(p["phi1"] - math.radians(75)) < 1e-15
    assert abs(page.get("theta") - math.radians(123.5)) < 1e-15
    assert page.page.input_value("#gc-num-mu1") == "1.25"
    assert_matches_python(page)
    # a preset of the paper from the menu
    page.page.select_option("#gc-preset", "table1a")
    want = Grasp.preset("table1a").params
    assert all(abs(page.get(k) - float(want[k])) < 1e-15 for k in PARAMS)
    assert_matches_python(page)
    # the set() API, as the sliders would
    assert page.js("graspcompass.set({x1: 1.7, phi2: 1.2, mu1: 0.6, theta: 3.0})") is None
    g = assert_matches_python(page)
    assert abs(page.get("Fint") - g.internal_force(3.0)) <= TOL


def test_step_navigator(page: Page, fig6: Construction) -> None:
    steps = fig6.steps

    def shown() -> tuple[str, str, str]:
        return tuple(
            page.page.inner_text(s)
            for s in ("#gc-stepno", "#gc-caption-text", "#gc-ref")  # type: ignore[return-value]
        )

    def expect(i: int) -> None:
        s = steps[i]
        # the caption with its subscripts set as subscripts (k_grasp -> k<sub>grasp</sub>)
        caption = re.sub(r"([A-Za-z])_\{?([A-Za-z0-9]+)\}?", r"\1\2", s.caption)
        assert shown() == (f"Step {s.index} / {len(steps) - 1}", caption, s.ref)
        assert page.get("step") == i

    expect(len(steps) - 1)
    page.page.click("#gc-first")
    expect(0)
    assert page.page.is_disabled("#gc-prev")
    for _ in range(3):
        page.page.click("#gc-next")
    expect(3)
    page.page.click("#gc-prev")
    expect(2)
    page.page.click("#gc-last")
    expect(len(steps) - 1)
    assert page.page.is_disabled("#gc-next")
    v1 = fig6.step("V1").index
    assert page.js(f"graspcompass.step({v1})") == v1
    expect(v1)
    assert steps[v1].name == "V1"
    # up to V1: V1 is drawn, V2 and the circles are not yet
    visible = "n => graspcompass.board.select(n).visProp.visible"
    assert page.js(visible, "V₁") and not page.js(visible, "V₂")
    with pytest.raises(Exception, match="out of range"):
        page.js("graspcompass.step(1000)")
    # play: the next step comes by itself, pause stops it
    page.page.click("#gc-first")
    page.page.click("#gc-play")
    page.page.wait_for_function("graspcompass.get('step') === 1", timeout=5000)
    page.page.click("#gc-play")
    expect(1)


def random_grasps(count: int, seed: int = 12) -> list[dict[str, float]]:
    """Float grasps inside condition (1) with a margin of 0.02 rad (|φ − π/2| < ξ < π/2)."""
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        p = dict(x1=rng.uniform(0.05, 3), x2=rng.uniform(0.05, 3), y=rng.uniform(0, 3))
        for i in (1, 2):
            phi = rng.uniform(0.05, math.pi)
            lo = abs(phi - math.pi / 2) + 0.02
            if lo >= math.pi / 2 - 0.02:
                break
            p[f"phi{i}"], p[f"mu{i}"] = phi, math.tan(rng.uniform(lo, math.pi / 2 - 0.02))
        else:
            out.append(p)
    return out


def test_random_grasps_match_the_closed_form(page: Page) -> None:
    """The page's model (no drawing) on 40 random grasps: V_n, k_grasp and the envelope."""
    grasps = random_grasps(40)
    got = page.js(
        """ps => ps.map(p => {
        const q = graspcompass.model.compute(Object.assign({theta: 0.7}, p));
        return {V: q.V, k: q.kgrasp, arcs: q.arcs.map(a => [a.n, a.theta0]), worst: q.worst.k};
      })""",
        grasps,
    )
    for p, q in zip(grasps, got):
        g = python_grasp(p)
        V = [(float(v.x), float(v.y)) for v in g.V]
        scale = max(1.0, *(math.hypot(*v) for v in V))
        for a, b in zip(q["V"], V):
            assert math.dist(a, b) <= TOL * scale, (p, a, b)
        assert abs(q["k"] - g.k_grasp(0.7)) <= TOL * scale
        assert abs(q["worst"] - max(math.hypot(*v) for v in V)) <= TOL * scale
        arcs = outer_envelope({f"V{n}": v for n, v in enumerate(g.V, start=1)}).arcs
        assert [n for n, _ in q["arcs"]] == [a.n for a in arcs], p
        for (_, t), a in zip(q["arcs"], arcs):
            assert abs(t - float(a.theta_start)) <= 1e-8, p


def python_message(params: dict[str, float]) -> str:
    with pytest.raises(InvalidGraspError) as exc:
        python_grasp(params)
    return str(exc.value)


def rounded(message: str) -> str:
    """Python's message as the page shows it: each exact value "v ≈ r" as r, longer
    decimals to 4 significant digits, >= and <= as ≥ and ≤."""
    out = re.sub(r"\S+ ≈ (\S+)", r"\1", message)
    out = re.sub(
        r"-?\d+\.\d{5,}(?:e[+-]?\d+)?", lambda m: f"{float(m.group()):.4g}", out, flags=re.I
    )
    return out.replace(">=", "≥").replace("<=", "≤")


def test_invalid_grasp_shows_the_inequality(page: Page) -> None:
    assert page.page.is_hidden("#gc-error")
    # condition (1): the cone at P1 no longer contains P2
    page.page.fill("#gc-slider-mu1", "0.2")
    page.page.fill("#gc-slider-phi1", "40")
    message = python_message(page.params())
    assert "condition (1)" in message
    assert page.page.is_visible("#gc-error")
    assert page.page.inner_text("#gc-error-text") == rounded(message)
    assert page.js("graspcompass.error()") == message
    assert page.get("V1") is None
    # the other contact, through set()
    page.js("graspcompass.set({phi1: 1.2, mu1: 1.0, phi2: 3.0, mu2: 0.3})")
    message = python_message(page.params())
    assert "contact 2" in message and page.page.inner_text("#gc-error-text") == rounded(message)
    # back to a valid grasp
    page.js("graspcompass.set({phi2: 1.2, mu2: 1.0})")
    assert page.page.is_hidden("#gc-error") and page.get("V1") is not None
    # drag P1 past P2: x1 + x2 < 0 is no grasp (x1 < 0 alone is: the centre of mass
    # then lies beyond a contact, issue 13 §1)
    x0, y0 = page.js("graspcompass.toScreen('P1')")
    x2s, _ = page.js("graspcompass.toScreen('P2')")
    page.page.mouse.move(x0, y0)
    page.page.mouse.down()
    page.page.mouse.move(x2s - 40, y0, steps=6)
    page.page.mouse.up()
    p = page.params()
    assert p["x1"] + p["x2"] < 0
    assert page.page.inner_text("#gc-error-text") == rounded(python_message(p))
    assert page.page.inner_text("#gc-error-text").startswith("x1 + x2 = -")


def test_messages_agree_with_python_on_many_values(page: Page) -> None:
    """The page's wording of every check, against Grasp for the same floats."""
    base = dict(x1=1.0, x2=1.5, y=0.5, phi1=1.2, phi2=1.4, mu1=0.8, mu2=0.9)
    cases = [
        dict(x1=-1.6),
        dict(x2=-1.5),
        dict(x1=-0.3, x2=0.2999),
        dict(y=-123456.7),
        dict(y=-2e15),
        dict(mu1=-0.0001),
        dict(mu2=0.0),
        dict(phi1=0.0),
        dict(phi2=3.3),
        dict(phi1=0.5),
        dict(phi1=0.3, mu1=3.0),
        dict(phi2=2.9, mu2=0.1),
        dict(phi2=4.5 - math.atan(9.0), mu2=9.0),
        dict(x1=math.nan),
        dict(mu2=math.inf),
        dict(y=-math.inf),
    ]
    for case in cases:
        p = {**base, **case}
        got = page.js("p => graspcompass.model.validate(Object.assign({theta: 0}, p))", p)
        assert got == python_message(p), case


def test_api_refuses_unknown_names(page: Page) -> None:
    with pytest.raises(Exception, match="unknown parameter"):
        page.js("graspcompass.set({z: 1})")
    with pytest.raises(Exception, match="unknown name"):
        page.js("graspcompass.get('Q7')")
    assert page.js("graspcompass.get('xi1')") == pytest.approx(math.atan(1.0))


@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1b", "table1c"])
def test_view_box_is_the_one_rule_of_every_picture(page: Page, preset: str) -> None:
    """The page frames the grasp as the PNG, SVG, TikZ and GeoGebra do (layout.view_box)."""
    from graspcompass import PRESETS
    from graspcompass.layout import numeric_objects, roles_of, view_box

    c = internal_force_diagram(Grasp.preset(preset))
    assert preset in PRESETS
    page.page.select_option("#gc-preset", preset)  # the preset's values and its object
    box = view_box(c.grasp, numeric_objects(c), roles=roles_of(c))
    assert page.js("graspcompass.viewBox()") == pytest.approx(box, rel=1e-9, abs=1e-9)
