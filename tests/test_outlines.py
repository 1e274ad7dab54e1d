"""Outlines from SVG and DXF drawings (issue 13 §1): units, frames, curves, hostile files.

Expected values are worked out in the tests from the drawings written here: the
polygons' vertices in millimetres, the circle's radius, the transform's matrix.
"""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graspcompass import cli
from graspcompass.errors import InputError, InputTooLargeError
from graspcompass.world import OutlineError, place_grasp

outlines = pytest.importorskip("graspcompass.outlines")
pytest.importorskip("svgelements", reason="the optional extra graspcompass[outlines]")
ezdxf = pytest.importorskip("ezdxf", reason="the optional extra graspcompass[outlines]")
read_outline = outlines.read_outline
DOCS = Path(__file__).resolve().parents[1] / "docs" / "_static" / "outlines"


def svg(
    tmp_path: Path,
    body: str,
    size: str = 'width="200mm" height="200mm" viewBox="0 0 200 200"',
    name: str = "part.svg",
) -> Path:
    p = tmp_path / name
    p.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" {size}>{body}</svg>')
    return p


def vertices_mm(poly) -> set[tuple[float, float]]:
    return {(round(x * 1000, 6), round(y * 1000, 6)) for x, y in poly.exterior.coords}


def test_millimetre_polygon_reads_exactly_with_y_up(tmp_path: Path) -> None:
    poly = read_outline(svg(tmp_path, '<polygon points="10,10 50,10 30,40"/>'))
    # SVG y down -> y up: the apex at SVG y = 40 is the lowest point
    assert vertices_mm(poly) == {(10.0, -10.0), (50.0, -10.0), (30.0, -40.0)}
    assert poly.exterior.is_ccw


def test_transforms_are_applied(tmp_path: Path) -> None:
    body = '<g transform="translate(100,20) scale(2)"><rect x="0" y="0" width="10" height="5"/></g>'
    poly = read_outline(svg(tmp_path, body))
    # x' = 100 + 2x, y' = 20 + 2y, then y up
    assert vertices_mm(poly) == {(100.0, -20.0), (120.0, -20.0), (120.0, -30.0), (100.0, -30.0)}


def test_circle_is_flattened_within_the_tolerance(tmp_path: Path) -> None:
    r, tol = 30.0, 1e-4
    poly = read_outline(svg(tmp_path, f'<circle cx="100" cy="100" r="{r}"/>'), tolerance=tol)
    size = 2 * r
    for x, y in poly.exterior.coords:  # vertices on the circle
        assert abs(math.hypot(x * 1000 - 100, y * 1000 + 100) - r) < 1e-6
    coords = list(poly.exterior.coords)
    for (x0, y0), (x1, y1) in itertools.pairwise(coords):  # chords' sagitta within tolerance
        mx, my = (x0 + x1) / 2 * 1000 - 100, (y0 + y1) / 2 * 1000 + 100
        assert r - math.hypot(mx, my) <= tol * size * 1.001
    assert abs(poly.area * 1e6 - math.pi * r * r) < math.pi * r * r * 1e-3


def test_units_and_the_unit_option(tmp_path: Path) -> None:
    rect = '<rect x="0" y="0" width="10" height="10"/>'
    inch = read_outline(svg(tmp_path, rect, 'width="1in" height="1in" viewBox="0 0 10 10"'))
    assert abs(inch.area - (0.0254**2)) < 1e-12  # 10 user units = 1 inch
    plain = svg(tmp_path, rect, 'width="100" height="100"', name="plain.svg")
    assert abs(read_outline(plain).area - (10 * 0.0254 / 96) ** 2) < 1e-12  # CSS px
    assert abs(read_outline(plain, unit="1mm").area - 1e-4) < 1e-12
    with pytest.raises(InputError, match="unit"):
        read_outline(plain, unit="3 furlongs")


def test_largest_shape_or_the_named_one(tmp_path: Path) -> None:
    body = (
        '<rect id="small" x="0" y="0" width="5" height="5"/>'
        '<rect id="big" x="50" y="50" width="40" height="30"/>'
    )
    p = svg(tmp_path, body)
    assert abs(read_outline(p).area * 1e6 - 1200) < 1e-6
    assert abs(read_outline(p, element="small").area * 1e6 - 25) < 1e-6
    with pytest.raises(OutlineError, match="nope"):
        read_outline(p, element="nope")


@pytest.mark.parametrize(
    "body, match",
    [
        ('<path d="M 0 0 L 10 0 L 10 10"/>', "no closed shape"),
        ('<polygon points="0,0 10,10 10,0 0,10"/>', "crosses itself"),
        ('<polygon points="0,0 10,0 20,0"/>', "crosses itself|no closed shape"),
        ("", "no closed shape"),
    ],
)
def test_bad_outlines_are_refused(tmp_path: Path, body: str, match: str) -> None:
    with pytest.raises(OutlineError, match=match):
        read_outline(svg(tmp_path, body))


def test_hostile_files_are_refused(tmp_path: Path) -> None:
    bomb = tmp_path / "bomb.svg"
    bomb.write_text(
        '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa">'
        '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]><svg xmlns="http://www.w3.org/'
        '2000/svg"><text>&b;</text></svg>'
    )
    with pytest.raises(InputError, match="entities"):
        read_outline(bomb)
    junk = tmp_path / "junk.svg"
    junk.write_bytes(b"\x00\xff not xml at all <<<")
    with pytest.raises(InputError):
        read_outline(junk)
    big = tmp_path / "big.svg"
    big.write_bytes(b" " * (outlines.MAX_OUTLINE_BYTES + 1))
    with pytest.raises(InputTooLargeError):
        read_outline(big)
    with pytest.raises(InputError, match=r"\.svg or \.dxf"):
        read_outline(tmp_path / "part.png")
    with pytest.raises(InputError, match="cannot read"):
        read_outline(tmp_path / "missing.svg")
    with pytest.raises(InputError, match="tolerance"):
        read_outline(junk, tolerance=0.0)


# -- DXF ------------------------------------------------------------------------------------
def dxf(tmp_path: Path, insunits: int, add, name: str = "part.dxf") -> Path:
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = insunits
    add(doc.modelspace())
    p = tmp_path / name
    doc.saveas(p)
    return p


def test_dxf_units_and_bulges(tmp_path: Path) -> None:
    square = [(0, 0), (40, 0), (40, 30), (0, 30)]
    mm = dxf(tmp_path, 4, lambda m: m.add_lwpolyline(square, close=True))
    assert vertices_mm(read_outline(mm)) == {(0.0, 0.0), (40.0, 0.0), (40.0, 30.0), (0.0, 30.0)}
    metres = dxf(tmp_path, 6, lambda m: m.add_lwpolyline(square, close=True), "m.dxf")
    assert abs(read_outline(metres).area - 1200.0) < 1e-9  # 40 m × 30 m
    plain = dxf(tmp_path, 0, lambda m: m.add_lwpolyline(square, close=True), "plain.dxf")
    assert abs(read_outline(plain, unit="1in").area - 1200 * 0.0254**2) < 1e-12
    # a half disc: the bulge 1 is a half circle of radius 20 over the chord (0,0)-(40,0)
    half = dxf(
        tmp_path,
        4,
        lambda m: m.add_lwpolyline([(0, 0, 0, 0, 1), (40, 0, 0, 0, 0)], format="xyseb", close=True),
        "half.dxf",
    )
    assert abs(read_outline(half).area * 1e6 - math.pi * 400 / 2) < 0.5


def test_dxf_open_polyline_and_circle(tmp_path: Path) -> None:
    open_ = dxf(tmp_path, 4, lambda m: m.add_lwpolyline([(0, 0), (1, 0), (1, 1)]))
    with pytest.raises(OutlineError, match="no closed shape"):
        read_outline(open_)
    circle = dxf(tmp_path, 4, lambda m: m.add_circle((10, 10), 5), "c.dxf")
    assert abs(read_outline(circle).area * 1e6 - math.pi * 25) < math.pi * 25 * 1e-3


def test_shipped_bracket_reads_the_same_from_svg_and_dxf() -> None:
    a, b = read_outline(DOCS / "bracket.svg"), read_outline(DOCS / "bracket.dxf")
    # 100 × 60 mm, a 20 × 15 mm notch, the corner rounded with R 20 mm
    want = 100 * 60 - 20 * 15 - (20 * 20 - math.pi * 20 * 20 / 4)
    for poly in (a, b):
        assert abs(poly.area * 1e6 - want) < want * 1e-4
    assert a.symmetric_difference(b).area * 1e6 < 0.5


@settings(max_examples=25, deadline=None)
@given(
    st.lists(
        st.tuples(st.integers(0, 199), st.integers(0, 199)), min_size=3, max_size=8, unique=True
    )
)
def test_random_polygons_round_trip(tmp_path_factory, pts: list[tuple[int, int]]) -> None:
    from shapely.geometry import MultiPoint

    hull = MultiPoint(pts).convex_hull
    if hull.geom_type != "Polygon" or hull.area == 0:
        return
    ring = list(hull.exterior.coords)[:-1]
    body = '<polygon points="' + " ".join(f"{x},{y}" for x, y in ring) + '"/>'
    poly = read_outline(svg(tmp_path_factory.mktemp("p"), body))
    assert vertices_mm(poly) == {(float(x), float(-y)) for x, y in ring}


# -- in a grasp and on the command line ------------------------------------------------------
def test_outline_feeds_place_grasp() -> None:
    poly = read_outline(DOCS / "bracket.svg")
    wg = place_grasp([(0.110, -0.050), (0.010, -0.050)], mu=(0.4, 0.4), outline=poly)
    cx, cy = poly.centroid.x, poly.centroid.y
    # the paper frame's origin is the centroid: x1 + x2 is the jaws' distance
    g = wg.grasp  # which contact is P1 follows the frame's rule (world.py)
    assert abs(float(g.x1 + g.x2) - 0.100) < 1e-12
    assert sorted([float(g.x1), float(g.x2)]) == pytest.approx(
        sorted([0.110 - cx, cx - 0.010]), abs=1e-12
    )
    assert abs(float(g.y) - abs(-0.050 - cy)) < 1e-12


def test_size_shape_equals_size_outline(capsys) -> None:
    common = [
        "--p1",
        "110mm,-50mm",
        "--p2",
        "10mm,-50mm",
        "--mass",
        "0.5kg",
        "--mu",
        "0.4",
        "--json",
    ]
    assert cli.main(["size", "--shape", str(DOCS / "bracket.dxf"), *common]) == 0
    from_file = json.loads(capsys.readouterr().out)
    verts = ";".join(
        f"{x * 1000}mm,{y * 1000}mm"
        for x, y in list(read_outline(DOCS / "bracket.dxf").exterior.coords)[:-1]
    )
    assert cli.main(["size", f"--outline={verts}", *common]) == 0
    typed = json.loads(capsys.readouterr().out)
    assert abs(from_file["worst_squeeze_N"] - typed["worst_squeeze_N"]) < 1e-9


@pytest.mark.parametrize(
    "extra, needle",
    [
        (["--shape", "/no/such.svg"], "cannot read"),
        (["--shape", "part.png"], ".svg or .dxf"),
        (["--shape", str(DOCS / "bracket.svg"), "--outline", "0,0;1,0;0,1"], "not both"),
        (["--shape-unit", "1mm", "--n1=-1,0", "--n2", "1,0", "--com", "0,0"], "--shape"),
    ],
)
def test_size_shape_errors_are_one_line(extra: list[str], needle: str, capsys) -> None:
    argv = [
        "size",
        "--p1",
        "110mm,-50mm",
        "--p2",
        "10mm,-50mm",
        "--mass",
        "1",
        "--mu",
        "0.4",
        *extra,
    ]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0], err
