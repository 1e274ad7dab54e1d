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
