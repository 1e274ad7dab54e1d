"""Checks of the documentation (docs/) and the gallery (gallery/).

- every Python session shown in a page (```` ```pycon ```` blocks) runs as a doctest;
- every ``graspcompass`` command shown in a page parses, with valid grasp parameters;
- the gallery has a script for each figure of the paper, the animations and the pages
  beyond the paper;
- the built site (``docs/_build/html``, made by ``.ci/build-docs.sh``) opens in headless
  Chromium: every image of the gallery index, the Fig. 6 page, the front page and the
  tutorial loads, no request gets a 404, the console reports no failed resource, and a
  screenshot of each page is saved in ``docs/_build/screenshots/``.  These tests are
  skipped, saying why, when the site is not built or Chromium is not installed;
- the built site works offline: every page opened from ``file://`` in Chromium (driven by
  Playwright) with every non-file request aborted makes no such request and no request
  fails, MathJax typesets every formula (no raw TeX left in the text, no MathJax error),
  and the animation players of the gallery show their nine buttons with their icons;
- the docs' own rules: the API has one page per module, the glossary defines its terms,
  ``CITATION.cff`` cites the paper, ``pyproject.toml`` declares what the docs need.
"""

from __future__ import annotations

import doctest
import functools
import http.server
import json
import os
import re
import shlex
import shutil
import subprocess
import tempfile
import textwrap
import threading
import urllib.parse
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
GALLERY = ROOT / "gallery"
HTML = DOCS / "_build" / "html"
SCREENSHOTS = DOCS / "_build" / "screenshots"
SKIP_DIRS = ("_build", "_generated", "auto_examples", "_intersphinx")

PAGES = sorted(p for p in DOCS.rglob("*.md") if not set(p.relative_to(DOCS).parts) & set(SKIP_DIRS))


def _blocks(page: Path, language: str) -> list[tuple[int, str]]:
    """``(line, text)`` of the fenced code blocks of ``language`` in a Markdown page."""
    text = page.read_text(encoding="utf-8")
    out = []
    for m in re.finditer(rf"^([ \t]*)```{language}\n(.*?)^\1```", text, re.S | re.M):
        out.append((text.count("\n", 0, m.start()) + 2, textwrap.dedent(m.group(2))))
    return out


# -- the Python sessions ------------------------------------------------------------------------
@pytest.mark.parametrize(
    "page", [p for p in PAGES if _blocks(p, "pycon")], ids=lambda p: str(p.relative_to(DOCS))
)
def test_python_sessions_run(page: Path, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    monkeypatch.setenv("MPLBACKEND", "agg")
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # files the sessions write
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, verbose=False
    )
    globs: dict = {}
    report: list[str] = []
    for line, block in _blocks(page, "pycon"):
        test = parser.get_doctest(block, globs, f"{page.name}:{line}", str(page), line - 1)
        runner.run(test, out=report.append, clear_globs=False)
        globs = test.globs  # the blocks of a page are one session
    results = runner.summarize(verbose=False)
    assert results.failed == 0, "".join(report)
    assert results.attempted > 0


# -- the commands ------------------------------------------------------------------------------
def _commands() -> list[tuple[str, str, bool]]:
    """``(where, command, fails)`` for each ``$ graspcompass ...`` line of a console block;
    ``fails`` when the next line shows an error message."""
    out = []
    for page in PAGES:
        for line, block in _blocks(page, "console"):
            rows = block.splitlines()
            for i, row in enumerate(rows):
                if row.startswith("$ graspcompass"):
                    nxt = rows[i + 1] if i + 1 < len(rows) else ""
                    cmd = re.split(r"\s(?:\||>|&&)\s", row[2:])[0]
                    out.append((f"{page.relative_to(DOCS)}:{line + i}", cmd, "error:" in nxt))
    return out


COMMANDS = _commands()


def test_pages_show_commands() -> None:
    assert len(COMMANDS) >= 20
    assert {c.split()[1] for _, c, _ in COMMANDS if len(c.split()) > 1} >= {
        "draw",
        "steps",
        "k",
        "presets",
        "animate",
        "export",
        "verify",
    }


@pytest.mark.parametrize(("where", "command", "fails"), COMMANDS, ids=[w for w, _, _ in COMMANDS])
def test_commands_parse(where: str, command: str, fails: bool) -> None:
    from graspcompass.cli import build_parser, grasp_from_args

    args = build_parser().parse_args(shlex.split(command)[1:])
    if not hasattr(args, "preset"):
        return
    if fails:
        with pytest.raises(ValueError):
            grasp_from_args(args)
    else:
        grasp_from_args(args)  # the grasp parameters are valid


def test_getting_started_shows_the_readme_commands() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme.split("## Two commands", 1)[-1].split("\n## ", 1)[0]
    commands = re.findall(r"```(?:bash|sh|console)\n(.*?)```", section, re.S)
    assert commands, "README.md has no '## Two commands' section with code blocks"
    page = (DOCS / "getting-started.md").read_text(encoding="utf-8")
    for block in commands:
        for line in block.strip().splitlines():
            assert f"$ {line.removeprefix('$ ')}" in page, (
                f"docs/getting-started.md does not show the README's command {line!r}"
            )


# -- the gallery -------------------------------------------------------------------------------
def _scripts(folder: Path) -> list[Path]:
    return sorted(folder.glob("plot_*.py"))


def test_gallery_has_every_figure() -> None:
    names = " ".join(p.name for p in _scripts(GALLERY))
    for fig in ("fig2", "fig3", "fig4", "fig5", "fig6", "fig7", "fig8"):
        assert f"_{fig}_" in names, f"no gallery script for {fig}"
    animations = " ".join(p.name for p in _scripts(GALLERY / "animations"))
    assert "construction" in animations and "sweep" in animations
    beyond = " ".join(p.name for p in _scripts(GALLERY / "beyond"))
    for topic in ("worst", "friction", "slips"):
        assert topic in beyond
    language = " ".join(p.name for p in _scripts(GALLERY / "language"))
    assert "thales" in language and "exercise" in language
    for folder in (GALLERY, GALLERY / "animations", GALLERY / "beyond", GALLERY / "language"):
        assert (folder / "GALLERY_HEADER.rst").is_file()


def test_gallery_numbers_are_unique() -> None:
    """One number per example across every section (issue 23: two plot_13, two plot_14)."""
    numbers = [p.name.split("_")[1] for p in GALLERY.rglob("plot_*.py")]
    assert len(numbers) > 10
    assert sorted(numbers) == sorted(set(numbers)), sorted(numbers)


@pytest.mark.parametrize(
    "script",
    _scripts(GALLERY)
    + _scripts(GALLERY / "animations")
    + _scripts(GALLERY / "beyond")
    + _scripts(GALLERY / "language"),
    ids=lambda p: p.name,
)
def test_gallery_script_has_a_titled_docstring(script: Path) -> None:
    import ast

    doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8")), clean=False)
    assert doc, f"{script.name}: sphinx-gallery needs a docstring"
    lines = doc.strip("\n").splitlines()
    assert len(lines) > 3 and set(lines[1]) == {"="} and len(lines[1]) >= len(lines[0]), (
        f"{script.name}: the docstring must start with a title underlined with '='"
    )


# -- the built site in a browser ---------------------------------------------------------------
BROWSER_PAGES = {
    "gallery-index": "auto_examples/index.html",
    "fig6": "auto_examples/plot_05_fig6_construction_vs_computer.html",
    "front-page": "index.html",
    "tutorial": "tutorial.html",
}
CHECKER = "/__graspcompass_image_check__.html"

# a same-origin page that loads one page in a frame and reports its images as JSON
CHECKER_HTML = """<!doctype html><meta charset="utf-8"><title>image check</title>
<link rel="icon" href="data:,">
<pre id="result">pending</pre>
<iframe id="page" src="{page}" style="width:1280px;height:4000px"></iframe>
<script>
const frame = document.getElementById("page");
frame.addEventListener("load", () => {{
  const images = Array.from(frame.contentDocument.images);
  images.forEach(img => {{ img.loading = "eager"; }});
  const report = () => {{
    if (images.some(img => !img.complete)) {{ setTimeout(report, 50); return; }}
    const broken = images.filter(img => img.naturalWidth === 0)
                         .map(img => img.getAttribute("src"));
    document.getElementById("result").textContent =
      JSON.stringify({{count: images.length, broken: broken}});
  }};
  report();
}});
</script>"""


def _chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        path = shutil.which(name)
        if path:
            return path
    return None


class _Server:
    """The built site on 127.0.0.1 (a free port), recording the status of every request."""

    def __init__(self, root: Path) -> None:
        self.requests: list[tuple[str, int]] = []
        server = self

        class Handler(http.server.SimpleHTTPRequestHandler):
            def do_GET(self) -> None:
                url = urllib.parse.urlsplit(self.path)
                if url.path == CHECKER:
                    page = urllib.parse.parse_qs(url.query)["page"][0]
                    body = CHECKER_HTML.format(page="/" + page).encode()
                    self.send_response(200)
                    self.send_header("Content-Type", "text/html; charset=utf-8")
                    self.send_header("Content-Length", str(len(body)))
                    self.end_headers()
                    self.wfile.write(body)
                    return
                super().do_GET()

            def log_request(self, code: object = "-", size: object = "-") -> None:
                server.requests.append((self.path, int(getattr(code, "value", code))))

            def log_message(self, format: str, *args: object) -> None:
                pass

        handler = functools.partial(Handler, directory=str(root))
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.url = f"http://127.0.0.1:{self.httpd.server_address[1]}/"
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)

    def __enter__(self) -> _Server:
        self.thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.httpd.shutdown()
        self.httpd.server_close()


@pytest.fixture(scope="module")
def browser() -> tuple[str, Path]:
    if not (HTML / "index.html").is_file() or not (HTML / "auto_examples").is_dir():
        pytest.skip(
            "the documentation is not built (docs/_build/html is missing): "
            "run .ci/build-docs.sh, or sphinx-build -b html docs docs/_build/html, "
            "before this test"
        )
    chromium = _chromium()
    if chromium is None:
        pytest.skip(
            "Chromium is not installed (Debian: apt-get install chromium), so the "
            "built documentation cannot be checked in a browser"
        )
    with tempfile.TemporaryDirectory(prefix="graspcompass-chromium-") as profile:
        yield chromium, Path(profile)


def _run_chromium(chromium: str, profile: Path, *args: str) -> subprocess.CompletedProcess:
    flags = [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-default-apps",
        "--disable-extensions",
        "--mute-audio",
        "--hide-scrollbars",
        f"--user-data-dir={profile}",
        "--enable-logging=stderr",
        "--v=0",
        "--virtual-time-budget=15000",
    ]
    return subprocess.run(
        [chromium, *flags, *args],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "LANG": "C.UTF-8"},
    )


def _console_failures(stderr: str) -> list[str]:
    """Console lines about a resource that failed with a 4xx/5xx status."""
    return [
        ln
        for ln in stderr.splitlines()
        if "CONSOLE" in ln and re.search(r"status of [45]\d\d|\b404\b", ln)
    ]


@pytest.mark.parametrize("name", list(BROWSER_PAGES))
def test_built_page_renders_in_chromium(browser: tuple[str, Path], name: str) -> None:
    chromium, profile = browser
    page = BROWSER_PAGES[name]
    if not (HTML / page).is_file():
        pytest.fail(f"{page} is not in the built site")
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    shot = SCREENSHOTS / f"{name}.png"
    shot.unlink(missing_ok=True)
    with _Server(HTML) as server:
        # 1. every <img> of the page loads (checked by the browser itself)
        run = _run_chromium(
            chromium,
            profile,
            "--dump-dom",
            f"{server.url}{CHECKER[1:]}?page={urllib.parse.quote(page)}",
        )
        m = re.search(r'<pre id="result">(.*?)</pre>', run.stdout, re.S)
        assert m and m.group(1) != "pending", (
            f"the image check of {page} did not finish:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}"
        )
        result = json.loads(m.group(1).replace("&quot;", '"'))
        assert result["count"] > 0, f"{page} shows no image"
        assert result["broken"] == [], f"broken images on {page}: {result['broken']}"
        console = _console_failures(run.stderr)
        # 2. a screenshot of the page on its own
        run = _run_chromium(
            chromium,
            profile,
            f"--screenshot={shot}",
            "--window-size=1280,3200",
            f"{server.url}{page}",
        )
        console += _console_failures(run.stderr)
        failed = [(path, code) for path, code in server.requests if code >= 400]
    assert not failed, f"requests that failed while loading {page}: {failed}"
    assert not console, "console errors:\n" + "\n".join(console)
    assert shot.is_file(), f"no screenshot of {page}:\n{run.stderr[-2000:]}"
    from PIL import Image

    with Image.open(shot) as im:
        assert im.size[0] >= 1000
        lo, hi = im.convert("L").getextrema()
        assert hi - lo > 100, f"the screenshot of {page} is blank"


# -- the built site, offline -------------------------------------------------------------------
# Raw TeX that MathJax should have replaced (text outside code blocks).
RAW_TEX = re.compile(
    r"\\[()\[\]]|\$\$|\\(?:frac|sqrt|varphi|phi|xi|mu|theta|text|mathrm|"
    r"overline|begin|end|left|right|cdot|tan|sin|cos|max|tfrac|qquad)\b"
)
# the page's text without code, with MathJax done (or no MathJax on the page)
PAGE_STATE_JS = """async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  await document.fonts.ready;
  const body = document.body.cloneNode(true);
  body.querySelectorAll("pre, code, script, style, mjx-container, .highlight, textarea")
      .forEach(e => e.remove());
  const players = Array.from(document.querySelectorAll(".animation")).map(a => {
    const buttons = Array.from(a.querySelectorAll(".anim-buttons button"));
    return {
      buttons: buttons.length,
      icons: buttons.filter(b => {
        const i = b.querySelector("i.fa");
        if (!i) return false;
        const before = getComputedStyle(i, "::before");
        return getComputedStyle(i).fontFamily.includes("FontAwesome") &&
               before.content.length === 3 && i.getBoundingClientRect().width > 4;
      }).length,
      frame: (a.querySelector("img") || {}).src || "",
    };
  });
  return {
    text: body.innerText,
    math: document.querySelectorAll("mjx-container").length,
    mathErrors: document.querySelectorAll("mjx-merror, [data-mjx-error]").length,
    hasMath: !!document.querySelector(".math, div.math, span.math"),
    players: players,
    fontAwesome: document.fonts.check("14px FontAwesome", "\\uf04b"),
  };
}"""


def _site_pages() -> list[Path]:
    """Every page of the built site except the highlighted sources (``_modules``)."""
    return sorted(
        p
        for p in HTML.rglob("*.html")
        if not {"_modules", "_static", "_sources", "_downloads"} & set(p.relative_to(HTML).parts)
    )


@pytest.fixture(scope="module")
def offline_browser():
    if not (HTML / "index.html").is_file() or not (HTML / "auto_examples").is_dir():
        pytest.skip(
            "the documentation is not built (docs/_build/html is missing): run "
            ".ci/build-docs.sh before this test"
        )
    chromium = _chromium()
    if chromium is None:
        pytest.skip(
            "Chromium is not installed (Debian: apt-get install chromium), so the "
            "built documentation cannot be checked offline in a browser"
        )
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.skip(
            "Playwright for Python is not installed (pip install -e '.[test]'), so "
            "the built documentation cannot be checked offline in a browser"
        )
    with sync_playwright() as pw:
        browser = pw.chromium.launch(
            executable_path=chromium, args=["--no-sandbox", "--disable-gpu"]
        )
        try:
            yield browser
        finally:
            browser.close()


SHARDS = 2  # the site's pages in two tests, which the two test workers share out


def _static_counts(pages: list[Path]) -> tuple[int, int]:
    """Pages with formulas and animation players, read from the HTML files themselves."""
    texts = [p.read_text(encoding="utf-8", errors="replace") for p in pages]
    math = sum(1 for t in texts if re.search(r'class="[^"]*\bmath\b', t))
    players = sum(len(re.findall(r'<div class="animation"', t)) for t in texts)
    return math, players


@pytest.mark.parametrize("shard", range(SHARDS))
def test_built_site_works_offline(offline_browser, shard: int) -> None:
    every = _site_pages()
    assert len(every) >= 30, f"only {len(every)} pages in the built site"
    math_all, players_all = _static_counts(every)
    assert math_all >= 10 and players_all >= 2, (math_all, players_all)
    pages = every[shard::SHARDS]
    want_math, want_players = _static_counts(pages)
    context = offline_browser.new_context(viewport={"width": 1280, "height": 900})
    outside: list[str] = []  # requests that would have needed the network
    failed: list[str] = []  # requests that failed (a missing file, an aborted request)

    def route(r) -> None:
        if r.request.url.startswith(("file:", "data:", "blob:", "about:")):
            r.continue_()
        else:
            outside.append(r.request.url)
            r.abort("internetdisconnected")

    context.route("**/*", route)
    problems: list[str] = []
    typeset = players = 0
    try:
        page = context.new_page()

        def request_failed(req) -> None:
            # a file request cancelled because the test moved on to the next page (the
            # favicon, typically) is no failure when the file is there
            if req.failure == "net::ERR_ABORTED" and req.url.startswith("file:"):
                local = Path(urllib.parse.unquote(urllib.parse.urlsplit(req.url).path))
                if local.is_file() and req.url not in outside:
                    return
            failed.append(f"{req.url[:200]} ({req.failure})")

        page.on("requestfailed", request_failed)
        for path in pages:
            name = str(path.relative_to(HTML))
            before = len(outside), len(failed)
            page.goto(path.as_uri(), wait_until="load", timeout=60_000)
            state = page.evaluate(PAGE_STATE_JS)
            if state["hasMath"]:
                typeset += 1
                if state["math"] == 0:
                    problems.append(f"{name}: MathJax typeset no formula")
            if state["mathErrors"]:
                problems.append(f"{name}: {state['mathErrors']} MathJax errors")
            raw = sorted({m.group(0) for m in RAW_TEX.finditer(state["text"])})
            if raw:
                i = RAW_TEX.search(state["text"]).start()
                problems.append(
                    f"{name}: raw TeX {raw} in the text, e.g. "
                    f"{state['text'][max(0, i - 60) : i + 60]!r}"
                )
            for k, player in enumerate(state["players"]):
                players += 1
                if player["buttons"] != 9 or player["icons"] != 9:
                    problems.append(
                        f"{name}: animation {k} has {player['buttons']} buttons, "
                        f"{player['icons']} with their icon (9 expected)"
                    )
            if state["players"]:
                # the player works: "next frame" shows another frame
                page.locator(".animation button[title='Next frame']").first.click()
                frame = page.evaluate("() => document.querySelector('.animation img').src")
                if frame == state["players"][0]["frame"]:
                    problems.append(f"{name}: 'Next frame' did not change the frame")
                if not state["fontAwesome"]:
                    problems.append(f"{name}: the icon font of the player did not load")
            if name == "explore.html":
                # the web explorer, generated at build time, runs in its frame
                explorer = [f for f in page.frames if f.url.endswith("_static/explorer.html")]
                if not explorer:
                    problems.append("explore.html: no frame shows _static/explorer.html")
                else:
                    explorer[0].wait_for_function("() => window.graspcompass", timeout=30_000)
                    # the Fig. 6 grasp: V1 = (-1 - sqrt(3), -3/2 - sqrt(3))
                    v1 = explorer[0].evaluate("() => window.graspcompass.get('V1')")
                    if (
                        v1 is None
                        or abs(v1[0] + 1 + 3**0.5) > 1e-9
                        or (abs(v1[1] + 1.5 + 3**0.5) > 1e-9)
                    ):
                        problems.append(f"explore.html: the explorer's V1 is {v1}")
            if len(outside) > before[0] or len(failed) > before[1]:
                problems.append(
                    f"{name}: requests outside the site {outside[before[0] :]}, "
                    f"failed {failed[before[1] :]}"
                )
    finally:
        context.close()
    print(
        f"offline: {len(pages)} pages, {typeset} with formulas, {players} animation "
        f"players, {len(outside)} requests outside the site, {len(failed)} failed"
    )
    assert not outside, f"requests that need the network: {sorted(set(outside))[:20]}"
    assert not failed, f"failed requests: {failed[:20]}"
    assert not problems, "\n".join(problems)
    # every page that has formulas in its HTML typeset them, every player was checked
    assert typeset == want_math and players == want_players, (
        typeset,
        want_math,
        players,
        want_players,
    )


# -- the docs' own rules ----------------------------------------------------------------------
def test_api_has_one_page_per_module() -> None:
    index = (DOCS / "api" / "index.md").read_text(encoding="utf-8")
    for module in (
        "graspcompass",
        "grasp",
        "construction",
        "geometry",
        "expr",
        "render",
        "export",
        "proof",
        "cli",
        "symbols",
    ):
        page = DOCS / "api" / f"{module}.md"
        assert page.is_file(), f"no API page for {module}"
        name = "graspcompass" if module == "graspcompass" else f"graspcompass.{module}"
        assert f".. automodule:: {name}\n" in page.read_text(encoding="utf-8")
        assert f"\n{module}\n" in index, f"api/index.md does not list {module}"


def test_glossary_defines_the_terms() -> None:
    text = (DOCS / "glossary.md").read_text(encoding="utf-8")
    terms = re.findall(r"^([a-zA-Z_ ]+)\n  \S", text.split("```{glossary}", 1)[1], re.M)
    for term in (
        "internal force",
        "friction cone",
        "signed length",
        "outer envelope",
        "break point",
        "protocol",
    ):
        assert term in terms, f"the glossary does not define {term!r}"
    tutorial = (DOCS / "tutorial.md").read_text(encoding="utf-8")
    assert len(re.findall(r"\{term\}`", tutorial)) >= 3


def test_citation_file_cites_the_paper() -> None:
    cff = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert cff.startswith("#") and "\ncff-version: 1.2.0\n" in cff
    for needle in (
        "doi: 10.1017/S0263574711001135",
        "journal: Robotica",
        "volume: 30",
        'issue: "5"',
        "family-names: Ito",
        "family-names: Tanaka",
        "family-names: Sasaki",
        "year: 2012",
        'title: "graspcompass',
    ):
        assert needle in cff, f"CITATION.cff lacks {needle!r}"
    assert "10.1017/S0263574711001135" in (DOCS / "cite.md").read_text(encoding="utf-8")


def test_pyproject_declares_what_the_docs_need() -> None:
    tomllib = pytest.importorskip("tomllib")

    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    deps = " ".join(project["dependencies"])
    # plt.figure(fig) adopting a standalone Figure, as the gallery and how-tos do: 3.11
    assert re.search(r"matplotlib>=3\.(1[1-9]|[2-9]\d)", deps), deps
    assert any(d.startswith("sphinx-copybutton") for d in project["optional-dependencies"]["docs"])
    urls = project.get("urls", {})
    assert urls and all(u.startswith("https://") for u in urls.values()), urls


def test_mathjax_and_player_icons_are_vendored() -> None:
    static = DOCS / "_static"
    assert (static / "mathjax" / "tex-chtml-full.js").stat().st_size > 1_000_000
    assert (
        len(list((static / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").glob("*.woff")))
        >= 20
    )
    assert (static / "fontawesome" / "fontawesome-webfont.woff2").is_file()
    conf = (DOCS / "conf.py").read_text(encoding="utf-8")
    assert 'mathjax_path = "mathjax/tex-chtml-full.js"' in conf
    assert not (static / "explorer.html").exists(), (
        "docs/_static/explorer.html is generated at build time (docs/conf.py), not committed"
    )


def test_grouped_numpydoc_entries_render_together() -> None:
    """``x1, x2, y : number or str`` is one entry naming all three (not three copies of
    one text, nor ``y`` typed as ``x1, x2,``)."""
    page = HTML / "api" / "graspcompass.html"
    if not page.is_file():
        pytest.skip("the documentation is not built: run .ci/build-docs.sh first")
    text = re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", page.read_text(encoding="utf-8")))
    assert "x1, x2, y (number or str) – Contacts" in text
    assert text.count("– Contacts P1 = (x1, y)") == 1
    render = re.sub(
        r"\s+",
        " ",
        re.sub(r"<[^>]+>", "", (HTML / "api" / "render.html").read_text(encoding="utf-8")),
    )
    assert "object_face, object_edge (str) – Fill and outline" in render
    assert "cone_face, cone_alpha (str, float)" in render


def test_pages_state_the_paper_correctly() -> None:
    construction = (DOCS / "construction.md").read_text(encoding="utf-8")
    # §5's collinearity is for sides of different cones; B13 is on O P2, B24 on O P1
    assert "s5-same-contact-13" in construction and "$B_{13}$ lies on the\nline $OP_2$" in (
        construction
    )
    tutorial = (DOCS / "tutorial.md").read_text(encoding="utf-8")
    assert "{ref}`(8)–(11) <eq-8>`" in tutorial
    assert "(eq-8)=\n**(8)–(11)**" in (DOCS / "paper.md").read_text(encoding="utf-8")


def _ids(page: Path, cache: dict[Path, set[str]]) -> set[str]:
    if page not in cache:
        cache[page] = set(
            re.findall(r'\bid="([^"]+)"', page.read_text(encoding="utf-8", errors="replace"))
        )
    return cache[page]


def test_source_pages_link_to_ids_that_exist() -> None:
    """Every "[docs]" link of the highlighted sources (``_modules``, sphinx.ext.viewcode)
    and every fragment link there points at an id of its page (issue 23: 33 did not, the
    module of a re-exported object's id was that of another page; docs/conf.py)."""
    sources = sorted(HTML.glob("_modules/**/*.html"))
    if not sources:
        pytest.skip("the documentation is not built: run .ci/build-docs.sh first")
    broken, links = _broken_fragments(sources)
    assert links > 100
    assert not broken, broken[:10]


def test_every_page_links_to_ids_that_exist() -> None:
    """Every fragment link of every built page, to its own page or another of the site,
    points at an id there: the "[source]" links of the API pages too (9 pointed at
    source blocks that the backlink fix of docs/conf.py had dropped, issue 23)."""
    pages = sorted(HTML.rglob("*.html"))
    if not (HTML / "_modules").is_dir():
        pytest.skip("the documentation is not built: run .ci/build-docs.sh first")
    broken, links = _broken_fragments(pages)
    assert links > 1000
    assert not broken, broken[:10]


def _broken_fragments(pages: list[Path]) -> tuple[list[str], int]:
    """The fragment links of ``pages`` (to a page of the site) whose id is not there."""
    cache: dict[Path, set[str]] = {}
    broken, links = [], 0
    for page in pages:
        text = page.read_text(encoding="utf-8", errors="replace")
        for href, frag in re.findall(r'href="([^"#:]*)#([^"]+)"', text):
            target = (page.parent / href).resolve() if href else page
            if href and not href.endswith(".html"):
                continue
            links += 1
            if not target.is_file() or urllib.parse.unquote(frag) not in _ids(target, cache):
                broken.append(f"{page.relative_to(HTML)} -> {href}#{frag}")
    return broken, links
