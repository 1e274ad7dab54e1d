"""Headless Chromium for the tests of web pages (Debian's ``/usr/bin/chromium``, Playwright).

The tests that need it skip, saying why, when Playwright or Chromium is missing
(``pip install playwright``; ``apt-get install chromium``: no ``playwright
install``, which downloads a browser).
"""

from __future__ import annotations

import contextlib
import shutil
from collections.abc import Iterator
from typing import Any

import pytest


@contextlib.contextmanager
def chromium(what: str, env: dict[str, str] | None = None) -> Iterator[Any]:
    """A launched headless Chromium; ``what`` says what goes untested without one; ``env``:
    its environment (a ``FONTCONFIG_FILE`` giving it other fonts)."""
    sync_api = pytest.importorskip(
        "playwright.sync_api",
        reason=f"Playwright for Python is not installed (pip install playwright, in the test "
        f"extra): {what} is not tested in a browser",
    )
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        pytest.skip(
            f"Chromium is not installed (Debian: apt-get install chromium): {what} "
            "is not tested in a browser"
        )
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=exe, args=["--no-sandbox"], env=env)
        try:
            yield browser
        finally:
            browser.close()


def fig6_explorer(tmp_path_factory: Any) -> Any:
    """The web explorer of Fig. 6 written to a fresh folder (a module's ``page_path``)."""
    from graspcompass import Grasp, internal_force_diagram
    from graspcompass.export.html import write_html

    path = tmp_path_factory.mktemp("web") / "explorer.html"
    return write_html(internal_force_diagram(Grasp.preset("fig6")), path)


def open_explorer(browser: Any, path: Any, width: int, height: int) -> Any:
    """A page of ``browser`` at ``width`` × ``height`` with the explorer at ``path`` loaded
    and ready; ``page.errors`` collects the page's uncaught errors."""
    page = browser.new_page(viewport={"width": width, "height": height})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.wait_for_selector("body[data-ready='1']", timeout=20_000)
    page.errors = errors
    return page


def client_rects(page: Any, selectors: list[str]) -> list[dict[str, Any]]:
    """Per CSS selector, its element's client rectangle (``s``, left, right, top, bottom,
    height), the browser's own layout."""
    return page.evaluate(
        "ss => ss.map(s => { const r = document.querySelector(s)"
        ".getBoundingClientRect(); return {s, left: r.left, right: r.right, "
        "top: r.top, bottom: r.bottom, height: r.height}; })",
        selectors,
    )


def drag_point(page: Any, name: str, dx: float, dy: float) -> None:
    """Drag the explorer's point ``name`` by (dx, dy) pixels with the mouse, in 8 moves."""
    x0, y0 = page.evaluate(f"graspcompass.toScreen('{name}')")
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move(x0 + dx, y0 + dy, steps=8)
    page.mouse.up()
    page.wait_for_timeout(150)
