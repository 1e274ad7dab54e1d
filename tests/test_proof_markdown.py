"""The proof reports as Markdown (issue 23): escaped, readable, with MathJax math.

The pages are rendered by markdown-it (the parser of MyST, which builds the docs) with
the docs' extensions (dollar math, definition lists, tables), and the HTML is read back:
no text of a statement, a counterexample or a condition turns into italics, bold, code,
raw HTML or a table split; exact values and conditions are math; the claims table has
five narrow columns; the errata are one section.
"""

from __future__ import annotations

import dataclasses
import re
from html import unescape

import pytest

from graspcompass.construction.language import parse
from graspcompass.proof import CLAIMS
from graspcompass.proof.program_check import check_program
from graspcompass.proof.program_report import to_markdown as check_markdown
from graspcompass.proof.report import run_catalogue, to_markdown

markdown_it = pytest.importorskip("markdown_it", reason="markdown-it-py (with myst-parser)")
plugins = pytest.importorskip("mdit_py_plugins", reason="mdit-py-plugins (with myst-parser)")

HOSTILE = "a*b*c and x_1_ | <script>alert(1)</script> `code` $5 [link](x) ~~no~~"


def render(md: str) -> str:
    from mdit_py_plugins.deflist import deflist_plugin
    from mdit_py_plugins.dollarmath import dollarmath_plugin

    return (
        markdown_it.MarkdownIt("commonmark")
        .enable("table")
        .use(dollarmath_plugin)
        .use(deflist_plugin)
        .render(md)
    )


def text_of(html: str) -> str:
    return unescape(re.sub(r"<[^>]+>", "", html))


@pytest.fixture(scope="module")
def reports() -> list:
    ids = ("s5-V1V2-printed", "s5-V1V2-corrected", "s5-collinear-12", "eq5")
    rs = run_catalogue([c for c in CLAIMS if c.id in ids], quiet=True)
    # a statement with every Markdown special character
    return [
        *rs,
        dataclasses.replace(
            rs[-1], claim=dataclasses.replace(rs[-1].claim, id="hostile", statement=HOSTILE)
        ),
    ]


def test_verify_report_is_escaped_with_math(reports: list) -> None:
    md = to_markdown(reports)
    html = render(md)
    assert "<script>" not in html and "<em>" not in html and "<strong>" not in html
    assert "<del>" not in html and "<s>" not in html
    assert HOSTILE in text_of(html)  # as written, characters and all
    # the §5 counterexample xi1 = 5*pi/12, phi1 = 17*pi/24 (once italics) is math
    math = re.findall(r'<span class="math inline">(.*?)</span>', html)
    assert r"\xi_{1} = \frac{5 \pi}{12}" in math and r"\phi_{1} = \frac{17 \pi}{24}" in math
    # the condition a1**2 - 2*a1*b1 + ... != 0 (once bold) is math, and ≠
    assert any(m.startswith("a_{1}^{2} - 2 a_{1} b_{1}") and m.endswith(r"\ne 0") for m in math)
    # a condition too long to read at once is math too, one piece per term
    assert sum(m.startswith(("+ \\sin", "- \\sin")) for m in math) >= 7


def test_verify_report_tables_are_narrow_and_errata_one_section(reports: list) -> None:
    html = render(to_markdown(reports))
    heads = re.findall(r"<thead>(.*?)</thead>", html, re.S)
    assert len(heads) == 1 and heads[0].count("<th") == 5  # id, paper, status, method, s
    assert len(re.findall(r"<h2>[^<]*[Ee]rrata", html)) == 1
    for row in re.findall(r"<tr>(.*?)</tr>", html, re.S)[1:]:
        assert row.count("<td") == 5 and len(text_of(row)) < 120, row
    # every claim's statement, hypotheses and conditions follow, as a definition list
    assert html.count("<dt>") == len(reports)


def test_docs_have_one_errata_section() -> None:
    from pathlib import Path

    page = (Path(__file__).parent.parent / "docs" / "proof.md").read_text("utf-8")
    assert not re.search(r"^#+ .*[Ee]rrata", page, re.M)  # the report's is the one


def test_check_report_is_escaped_with_math() -> None:
    src = (
        "param a > 0\nparam b > 0\nA = point (a, 0)\nB = point (b*b, 0)\n"
        "claim A == point (a*a, 0)\nclaim sign a*b > 0\n"
    )
    report = dataclasses.replace(check_program(parse(src)), file="my_*file*_.gc")
    md = check_markdown(report)
    html = render(md)
    assert "<em>" not in html and "<strong>" not in html
    assert "Check of my_*file*_.gc" in text_of(html)
    math = re.findall(r'<span class="math inline">(.*?)</span>', html)
    assert any(re.fullmatch(r"a = \S+", m) for m in math), math  # the counterexample
    assert html.count("<dt>") >= 3
