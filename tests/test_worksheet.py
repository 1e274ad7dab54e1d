"""The hand-drawing worksheet (issue 12 §3): ``render.handdrawing`` and ``graspcompass worksheet``.

The PDF is read as bytes (pypdf when installed): its pages are counted and
the A4 MediaBox and the two bars (100 mm, and one unit at the stated scale)
are found in its content streams.  The scale is also computed from the
figure size, the axes position and the axis limits.  The solution page is
checked against the closed form V_n = (S_n, C_n) of eqs. (28)-(30),
(33)-(39), written out here again from the paper, not taken from the package.
"""

from __future__ import annotations

import argparse
import math
import re
import zlib
from pathlib import Path

import pytest

pytest.importorskip("matplotlib")

from graspcompass import Grasp, cli, internal_force_diagram
from graspcompass.cli import _worksheet as cw
from graspcompass.render.handdrawing import (
    Worksheet,
    given_names,
    selected_names,
    worksheet_pages,
)

A4_PT = (210 / 25.4 * 72, 297 / 25.4 * 72)
#: Protocol steps that make V_n (§3.3 steps (1)-(3)), in the order of the paper.
V_STEPS = ("X{n}", "perp{n}", "Y{n}", "OMX{n}", "OY{n}", "V{n}")

#: An asymmetric grasp (x1 ≠ x2), so that O_M ≠ O and the transfer to O matters.
ASYM = dict(x1=2.0, x2=1.0, y=0.5, phi1=math.pi / 3, phi2=math.pi / 2, mu1=1.0, mu2=0.8)


def closed_form_V(
    x1: float, x2: float, y: float, phi1: float, phi2: float, mu1: float, mu2: float
) -> list[tuple[float, float]]:
    """V_n = (S_n, C_n), eqs. (28)-(30), (33)-(39), with tan ξ_i = μ_i (eq. (22))."""
    xi1, xi2 = math.atan(mu1), math.atan(mu2)
    h = (x1 + x2) / 2
    t1p, t1m = math.tan(phi1 + xi1), math.tan(phi1 - xi1)
    t2p, t2m = math.tan(phi2 + xi2), math.tan(phi2 - xi2)
    S = (-h + y * t1p, h - y * t2p, -h + y * t1m, h - y * t2m)
    C = (x2 * t1p, x1 * t2p, x2 * t1m, x1 * t2m)
    return list(zip(S, C))


FIG6 = dict(
    x1=math.sqrt(3) / 2,
    x2=math.sqrt(3) / 2,
    y=0.5,
    phi1=math.pi / 3,
    phi2=math.pi / 3,
    mu1=1.0,
    mu2=math.sqrt(3),
)


# -- reading the PDF ---------------------------------------------------------------------------
def pdf_pages(data: bytes) -> int:
    try:
        import io

        from pypdf import PdfReader
    except ImportError:
        return len(re.findall(rb"/Type\s*/Page(?![a-z])", data))
    return len(PdfReader(io.BytesIO(data)).pages)


def pdf_segments(data: bytes) -> list[tuple[float, float, float, float]]:
    """Straight segments ``x0 y0 m x1 y1 l`` of the content streams, in points."""
    out = []
    for raw in re.findall(rb"stream\r?\n(.*?)\r?\nendstream", data, re.S):
        try:
            text = zlib.decompress(raw).decode("latin-1")
        except zlib.error:
            text = raw.decode("latin-1")
        for m in re.finditer(r"(-?[\d.]+) (-?[\d.]+) m\s+(-?[\d.]+) (-?[\d.]+) l\s", text):
            out.append(tuple(float(v) for v in m.groups()))
    return out


def horizontal_bars(data: bytes, length_mm: float) -> list[tuple[float, ...]]:
    want = length_mm / 25.4 * 72
    return [
        s
        for s in pdf_segments(data)
        if abs(s[1] - s[3]) < 1e-6 and abs(abs(s[2] - s[0]) - want) < 1e-3
    ]


def mm_per_unit(ws: Worksheet, page: int) -> tuple[float, float]:
    """Millimetres per unit along x and y, from the figure size, axes box and limits."""
    fig, ax = ws.figures[page], ws.axes[page]
    pos = ax.get_position()
    w_mm, h_mm = pos.width * fig.get_figwidth() * 25.4, pos.height * fig.get_figheight() * 25.4
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return w_mm / (x1 - x0), h_mm / (y1 - y0)


def marker_mm(ws: Worksheet, page: int, name: str) -> tuple[float, float]:
    """Where the marker of point ``name`` is drawn on ``page``, mm from the lower left."""
    fig, ax = ws.figures[page], ws.axes[page]
    line = ws.artists[page][name][0]
    ((x, y),) = line.get_xydata()
    px, py = ax.transData.transform((x, y))
    return px / fig.dpi * 25.4, py / fig.dpi * 25.4


# -- fixtures ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def fig6_all(tmp_path_factory: pytest.TempPathFactory) -> tuple[Worksheet, bytes]:
    ws = worksheet_pages(Grasp.preset("fig6"), steps="all")
    path = ws.save(tmp_path_factory.mktemp("ws") / "fig6.pdf")
    return ws, path.read_bytes()


@pytest.fixture(scope="module")
def asym_v3(tmp_path_factory: pytest.TempPathFactory) -> Worksheet:
    ws = worksheet_pages(Grasp(**ASYM), steps="V3", given="feet", scale=20)
    ws.save(tmp_path_factory.mktemp("ws") / "asym.pdf")  # positions as the PDF draws them
    return ws


# -- the PDF -----------------------------------------------------------------------------------
def test_pdf_has_two_a4_pages(fig6_all: tuple[Worksheet, bytes]) -> None:
    _, data = fig6_all
    assert data.startswith(b"%PDF")
    assert pdf_pages(data) == 2
    boxes = re.findall(rb"/MediaBox\s*\[\s*([\d.\s]+)\]", data)
    assert len(boxes) == 2
    for box in boxes:
        x0, y0, w, h = (float(v) for v in box.split())
        assert (x0, y0) == (0, 0)
        assert w == pytest.approx(A4_PT[0], abs=1e-6) and h == pytest.approx(A4_PT[1], abs=1e-6)


def test_pdf_draws_the_stated_scale(fig6_all: tuple[Worksheet, bytes]) -> None:
    ws, data = fig6_all
    assert ws.scale == int(ws.scale) >= 10  # a whole number of mm per unit by default
    assert any(f"1 unit = {ws.scale:g} mm" in t.get_text() for t in ws.figures[0].texts)
    check = horizontal_bars(data, 100.0)  # the print check bar, on both pages
    unit = horizontal_bars(data, ws.scale)  # one unit in the drawing, on both pages
    assert len(check) >= 2 and len(unit) >= 2, (check, unit)


@pytest.mark.parametrize("page", [0, 1])
def test_scale_is_exact_in_the_figure(fig6_all: tuple[Worksheet, bytes], page: int) -> None:
    ws, _ = fig6_all
    fig = ws.figures[page]
    assert fig.get_figwidth() * 25.4 == pytest.approx(210, abs=1e-9)
    assert fig.get_figheight() * 25.4 == pytest.approx(297, abs=1e-9)
    sx, sy = mm_per_unit(ws, page)
    assert sx == pytest.approx(ws.scale, rel=1e-12)
    assert sy == pytest.approx(ws.scale, rel=1e-12)
    # the unit bar is one unit long in data coordinates, so ws.scale mm on paper
    (x0, _), (x1, _) = ws.scale_bar.get_xydata()
    assert (x1 - x0) * sx == pytest.approx(ws.scale, rel=1e-12)
    # the check bar is 100 mm in figure coordinates
    (f0, _), (f1, _) = ws.check_bar.get_xydata()
    assert (f1 - f0) * 210 == pytest.approx(100, abs=1e-9)


def test_both_pages_put_the_drawing_in_the_same_place(fig6_all: tuple[Worksheet, bytes]) -> None:
    ws, _ = fig6_all
    a, b = (ax.get_position().bounds for ax in ws.axes)
    assert a == pytest.approx(b, abs=1e-12)
    assert marker_mm(ws, 0, "O") == pytest.approx(marker_mm(ws, 1, "O"), abs=1e-9)
    assert marker_mm(ws, 0, "P1") == pytest.approx(marker_mm(ws, 1, "P1"), abs=1e-9)


# -- the solution against the closed form -----------------------------------------------------
@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_solution_page_puts_V_n_at_the_closed_form(
    fig6_all: tuple[Worksheet, bytes], n: int
) -> None:
    ws, _ = fig6_all
    S, C = closed_form_V(**FIG6)[n - 1]
    ox, oy = marker_mm(ws, 1, "O")
    vx, vy = marker_mm(ws, 1, f"V{n}")
    assert (vx - ox, vy - oy) == pytest.approx((S * ws.scale, C * ws.scale), abs=1e-6)


def test_asymmetric_grasp_V3_with_the_transfer_to_O(asym_v3: Worksheet) -> None:
    ws = asym_v3
    assert ws.scale == 20
    S3, C3 = closed_form_V(**ASYM)[2]
    o = marker_mm(ws, 1, "O")
    v = marker_mm(ws, 1, "V3")
    assert (v[0] - o[0], v[1] - o[1]) == pytest.approx((20 * S3, 20 * C3), abs=1e-6)
    # O_M is not O here: V3.x is −O_M X3 measured from O (eq. (36), Appendix (A7))
    om = marker_mm(ws, 1, "O_M")
    x3 = marker_mm(ws, 1, "X3")
    assert om[0] - o[0] == pytest.approx(20 * (ASYM["x1"] - ASYM["x2"]) / 2, abs=1e-6)
    assert v[0] - o[0] == pytest.approx(-(x3[0] - om[0]), abs=1e-6)
    assert abs(v[0] - o[0] + (x3[0] - o[0])) > 1.0  # not the mirror image of X3 through O
    # the feet and O_M are given: drawn on page 1, not among the instructions
    assert {"P1x", "P2x", "O_M"} <= set(ws.given)
    assert "O_M" in ws.artists[0] and "X3" not in ws.artists[0]
    made = [n for i in ws.instructions for n in i.names]
    assert not {"P1x", "P2x", "O_M"} & set(made)
    assert made == ["side3", "X3", "perp3", "Y3", "OMX3", "OY3", "V3", "circle3"]


# -- the instructions --------------------------------------------------------------------------
def _in_order(numbers: list[int]) -> bool:
    return numbers == sorted(numbers) and len(set(numbers)) == len(numbers)


@pytest.mark.parametrize("which", ["V1", "V2", "V4"])
def test_instructions_of_one_V_n_in_protocol_order(which: str) -> None:
    c = internal_force_diagram(Grasp.preset("table1b"))
    from graspcompass.render.handdrawing import instructions_for

    sel = selected_names(c, which)
    ins = instructions_for(c, sel, given_names(sel, "grasp"))
    n = int(which[1])
    steps = [k for i in ins for k in i.steps]
    assert _in_order(steps)
    want = [c.step(s.format(n=n)).index for s in V_STEPS]
    assert [k for k in steps if k in want] == want
    assert {c.step(s).index for s in ("P1x", "P2x", "O_M", f"side{n}", f"circle{n}")} <= set(steps)
    for i in ins:  # each carries the paper's reference of its step
        assert c.step(i.names[-1]).ref in i.text


def test_instructions_of_all_mention_every_step_in_order(fig6_all: tuple[Worksheet, bytes]) -> None:
    ws, _ = fig6_all
    c = internal_force_diagram(Grasp.preset("fig6"))
    steps = [k for i in ws.instructions for k in i.steps]
    assert _in_order(steps)
    assert steps == list(range(5, len(c)))  # everything after O, the axes and the contacts
    text = "\n".join(ws.texts)
    # each step number is printed, in order, as a label or in bold inside a line
    for i in ws.instructions:
        assert i.number in text
    for n in (1, 2, 3, 4):
        assert f"$V_{{{n}}}$" in text or f"$V_{n}$" in text
    assert "(-\\overline{O_MX_1}, -\\overline{OY_1})" in text  # the transfer, spelled out
    # the sign convention is stated on the page
    assert "is positive when $X_n$ lies to the right of $O_M$" in " ".join(ws.texts)


def _check_text(ws: Worksheet, page: int) -> None:
    """Every text inside the page margins (5 mm) and off the drawing, measured without font
    hinting as in the PDF (hinting widens text at 72 dpi by several per cent)."""
    import matplotlib

    fig, ax = ws.figures[page], ws.axes[page]
    with matplotlib.rc_context({"text.hinting": "no_hinting"}):
        renderer = fig.canvas.get_renderer()
        boxes = [(t, t.get_window_extent(renderer)) for t in fig.texts]
    sheet = fig.bbox
    drawing = ax.get_window_extent(renderer)
    for t, bb in boxes:
        assert sheet.x0 <= bb.x0 and bb.x1 <= sheet.x1 - 5 * 72 / 25.4, t.get_text()
        assert sheet.y0 + 5 * 72 / 25.4 <= bb.y0 and bb.y1 <= sheet.y1, t.get_text()
        assert not bb.overlaps(drawing), t.get_text()


def test_text_stays_on_the_page_and_off_the_drawing(
    fig6_all: tuple[Worksheet, bytes], asym_v3: Worksheet
) -> None:
    ws, _ = fig6_all
    _check_text(ws, 0)
    _check_text(ws, 1)
    _check_text(asym_v3, 0)


def test_page_1_shows_the_givens_only(fig6_all: tuple[Worksheet, bytes]) -> None:
    ws, _ = fig6_all
    assert set(ws.given) == {"O", "x-axis", "y-axis", "P1", "P2"}
    drawn = {k for k in ws.artists[0] if not k.startswith("cone")} - {"object"}
    assert drawn == set(ws.given)
    assert ws.artists[0]["cones"]  # both friction cones with their sides, to be extended
    assert {f"V{n}" for n in (1, 2, 3, 4)} <= set(ws.artists[1])
    assert "envelope" in ws.artists[1]


# -- options -----------------------------------------------------------------------------------
def test_given_levels_and_names() -> None:
    c = internal_force_diagram(Grasp.preset("fig6"))
    sel = selected_names(c, "V2")
    assert given_names(sel, "perpendiculars")[5:] == (
        "side2",
        "P1x",
        "P2x",
        "O_M",
        "X2",
        "perp2",
        "Y2",
    )
    assert given_names(sel, "grasp") == ("O", "x-axis", "y-axis", "P1", "P2")
    assert given_names(sel, ["O_M", "X2"])[-2:] == ("O_M", "X2")
    with pytest.raises(ValueError, match="not a step of this worksheet"):
        given_names(sel, "X1")
    with pytest.raises(ValueError, match="steps must be one of"):
        selected_names(c, "V5")


def test_scale_too_large_is_refused_with_the_largest_that_fits() -> None:
    with pytest.raises(ValueError, match=r"at most [\d.]+ mm per unit fits"):
        worksheet_pages(Grasp.preset("table1c"), steps="all", scale=400)
    with pytest.raises(ValueError, match="scale must be"):
        worksheet_pages(Grasp.preset("fig6"), scale=float("nan"))
    with pytest.raises(ValueError, match="too small to draw in"):
        worksheet_pages(Grasp.preset("fig6"), steps="V4", scale=0.5)


def test_any_size_of_grasp_gets_a_round_scale() -> None:
    from graspcompass.render.handdrawing import round_scale

    assert [round_scale(f) for f in (12.9, 10.0, 9.99, 0.0437, 2345.6)] == [
        12.0,
        10.0,
        9.9,
        0.043,
        2340.0,
    ]
    big = Grasp(x1=100, x2=200, y=50, phi1="pi/2", phi2="pi/2", mu1="1/2", mu2="1/2")
    ws = worksheet_pages(big, steps="V4")
    assert 0.1 < ws.scale < 1 and mm_per_unit(ws, 0)[0] == pytest.approx(ws.scale, rel=1e-12)


# -- the command -------------------------------------------------------------------------------
def _parser() -> argparse.ArgumentParser:
    p = cli._Parser(prog="graspcompass")
    sub = p.add_subparsers(dest="command", parser_class=cli._Parser)
    cw.register(sub, cli._add_grasp_options)
    return p


def test_command_writes_the_worksheet(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "t.pdf"
    args = _parser().parse_args(
        [
            "worksheet",
            "--preset",
            "table1a",
            "--steps",
            "V2",
            "--given",
            "sides",
            "--scale",
            "12",
            "-q",
            "-o",
            str(out),
        ]
    )
    assert cw.run(args) == 0
    data = out.read_bytes()
    assert pdf_pages(data) == 2
    assert len(horizontal_bars(data, 12.0)) >= 2
    assert capsys.readouterr().out == ""  # -q
    # the global -q of graspcompass is not overridden by the sub-command's default
    p = cli.build_parser()
    sub = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))
    if "worksheet" not in sub.choices:  # until cli.py registers it
        cw.register(sub, cli._add_grasp_options)
    assert p.parse_args(["-q", "worksheet"]).quiet is True
    assert p.parse_args(["worksheet"]).quiet is False


@pytest.mark.parametrize(
    "argv",
    [
        ["--scale", "0"],
        ["--scale", "inf"],
        ["--steps", "V5"],
        ["--given", "P1x;rm"],
        ["--scale", "x"],
        ["--scale", "-3"],
    ],
)
def test_command_refuses_bad_options(argv: list[str]) -> None:
    with pytest.raises(SystemExit) as err:
        _parser().parse_args(["worksheet", *argv])
    assert err.value.code == 2


def test_command_checks_the_output_before_any_work(tmp_path: Path) -> None:
    from graspcompass.errors import OutputError

    with pytest.raises(ValueError, match="a worksheet is a PDF"):
        cw.run(_parser().parse_args(["worksheet", "-o", str(tmp_path / "w.png")]))
    with pytest.raises(OutputError, match="does not exist"):
        cw.run(_parser().parse_args(["worksheet", "-o", str(tmp_path / "no" / "w.pdf")]))
    with pytest.raises(ValueError, match="not a step"):
        cw.run(
            _parser().parse_args(["worksheet", "--given", "nothing", "-o", str(tmp_path / "w.pdf")])
        )
    assert not (tmp_path / "w.pdf").exists()
