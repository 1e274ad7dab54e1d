"""Every example of docs/language-reference.md and docs/geometry-gallery.md is checked:
it parses, and every claim in it is PROVED (the examples are true statements)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graspcompass.construction.language import parse
from graspcompass.construction.operations import OPERATIONS
from graspcompass.proof.program_check import check_program

DOCS = Path(__file__).resolve().parent.parent / "docs"
PAGES = ("language-reference.md", "geometry-gallery.md")


def _examples(page: str) -> list[tuple[int, str]]:
    text = (DOCS / page).read_text("utf-8")
    return [
        (text.count("\n", 0, m.start()) + 2, m.group(1))
        for m in re.finditer(r"^```text\n(.*?)^```", text, re.S | re.M)
        if "claim" in m.group(1)
    ]


EXAMPLES = [(page, line, body) for page in PAGES for line, body in _examples(page)]


def test_every_operation_has_a_reference_entry_with_an_example():
    text = (DOCS / "language-reference.md").read_text("utf-8")
    for name in OPERATIONS:
        head = text.index(f"### `{name}`")
        assert "```text" in text[head : text.find("### ", head + 4)], name
    assert len(_examples("geometry-gallery.md")) >= 10


@pytest.mark.parametrize(
    ("page", "line", "body"), EXAMPLES, ids=[f"{p}:{n}" for p, n, _ in EXAMPLES]
)
def test_example_is_proved(page, line, body):
    report = check_program(parse(body, f"{page}:{line}"), timeout=60)
    assert [r.result.status.value for r in report.claims] == ["PROVED"] * len(report.claims)


def test_the_first_example_of_language_md_builds_and_proves_what_its_title_says():
    text = (DOCS / "language.md").read_text("utf-8")
    body = re.search(r"^```text\n(.*?)^```", text, re.S | re.M).group(1)
    assert body.startswith("# Thales") and "circle_on_diameter O V" in body
    report = check_program(parse(body, "language.md"))
    assert [r.result.status.value for r in report.claims] == ["PROVED", "PROVED"]
