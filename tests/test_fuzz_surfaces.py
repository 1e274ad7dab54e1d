"""Issue 22: a fuzz test per surface of outside input, each a few seconds.

Construction files, SVG and DXF drawings, command-line options, API values and batch
arrays are generated from small grammars of hostile pieces (huge, tiny, non-finite,
negative, wrong kinds, nested, encoded).  Each example must give a result or one named
error (a :class:`~graspcompass.errors.GraspCompassError`; on the command line exit status
0 or 2 with one line on stderr), within a hang bound that is not a speed assertion.
"""

from __future__ import annotations

import math
import os
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _hang import no_hang
from graspcompass.cli import main
from graspcompass.errors import GraspCompassError

FUZZ = settings(
    max_examples=int(os.environ.get("GRASPCOMPASS_FUZZ_EXAMPLES", "40")),
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)

NUMBERS = [
    "0",
    "1",
    "-1",
    "2",
    "1/3",
    "0.5",
    "-0.25",
    "sqrt(2)",
    "1e300",
    "-1e300",
    "1e-300",
    "1e308",
    "pi",
    "pi/3",
    "60deg",
    "1/(sqrt(2)+sqrt(3)-sqrt(5+2*sqrt(6)))",
    "t",
    "a",
    "(t+1)**64",
    "nan",
    "inf",
    "1j",
    "",
    "--",
    "-pi/4+pi",
    "2**64",
    "0,5",
    "x1",
]
NUMBER_TEXT = st.sampled_from(NUMBERS)


def _one_line_or_ok(code: int, err: str) -> None:
    assert code in (0, 2), (code, err)
    if code == 2:
        assert len(err.strip().splitlines()) == 1, err
    assert "internal error" not in err and "Traceback" not in err, err


# -- construction files ---------------------------------------------------------------------------
NAMES = st.sampled_from(["A", "B", "C", "O", "c", "d", "l", "E", "V1", "t"])


@st.composite
def statements(draw):
    name, a, b, c = (draw(NAMES) for _ in range(4))
    v1, v2 = draw(NUMBER_TEXT), draw(NUMBER_TEXT)
    return draw(
        st.sampled_from(
            [
                f"{name} = point ({v1}, {v2})",
                f"{name} = circle_through {a} {b}",
                f"{name} = circle_on_diameter {a} {b}",
                f"{name} = line_through {a} {b}",
                f"{name} = meet {a} {b}",
                f"{name} = second_intersection {a} {b} {c}",
                f"{name} = intersect_circles {a} {b} ({draw(st.sampled_from(['0', '1', '2']))})",
                f"{name} = foot {a} {b}",
                f"{name} = midpoint {a} {b}",
                f"let {name} = {v1}",
                f"param {name} > 0",
                f"{name} = envelope {a} {b}",
                f"claim on {a} {b}",
                f"claim sign {v1} > 0",
                f"{name} = {v1}",
                "#" + v1,
                "\x00",
                "A = point (0, 0)",
            ]
        )
    )


@FUZZ
@given(lines=st.lists(statements(), min_size=1, max_size=8))
def test_fuzz_construction_files(lines, tmp_path, capsys):
    f = tmp_path / "f.gc"
    f.write_text("\n".join(lines) + "\n", encoding="utf-8")
    with no_hang("construction file", 60):
        code = main(["steps", str(f), "--set", "t=1/3", "--timeout", "10"])
    _one_line_or_ok(code, capsys.readouterr().err)


# -- SVG and DXF drawings -------------------------------------------------------------------
SVG_NUMBERS = st.sampled_from(
    [
        "0",
        "1",
        "10",
        "-5",
        "1e300",
        "-1e300",
        "1e-300",
        "nan",
        "inf",
        "3.5",
        "1e12",
        "1e13",
        "",
        "x",
    ]
)


@st.composite
def svg_elements(draw, depth=0):
    n = [draw(SVG_NUMBERS) for _ in range(4)]
    leaf = st.sampled_from(
        [
            f'<rect id="r{depth}" x="{n[0]}" y="{n[1]}" width="{n[2]}" height="{n[3]}"/>',
            f'<circle id="c{depth}" cx="{n[0]}" cy="{n[1]}" r="{n[2]}"/>',
            f'<path d="M 0 0 A {n[0]} {n[0]} 0 0 1 {n[1]} 0 L {n[2]} {n[3]} Z"/>',
            f'<polygon points="0,0 {n[0]},0 {n[1]},{n[2]}"/>',
            f'<use href="#r{max(depth - 1, 0)}"/>',
            f'<use href="#g{depth}"/>',
        ]
    )
    if depth >= 3 or draw(st.booleans()):
        return draw(leaf)
    kids = "".join(draw(st.lists(svg_elements(depth + 1), max_size=3)))
    transform = draw(
        st.sampled_from(
            ["", f' transform="scale({n[0]})"', f' transform="translate({n[1]},{n[2]})"']
        )
    )
    return f'<g id="g{depth}"{transform}>{kids}</g>'


@FUZZ
@given(
    body=st.lists(svg_elements(), min_size=1, max_size=4),
    head=st.sampled_from(
        [
            "",
            '<!DOCTYPE svg [<!ENTITY a "1">]>',
            '<!DOCTYPE svg [<!ENTITY % p "x"> %p;]>',
            '<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "x.dtd">',
        ]
    ),
    encoding=st.sampled_from(["utf-8", "utf-16", "utf-16-be", "utf-32", "latin-1"]),
    unit=st.sampled_from([None, "1mm", "1e300m", "1e-300m"]),
    tolerance=st.sampled_from([1e-4, 1e-9, 0.1]),
)
def test_fuzz_svg_outlines(body, head, encoding, unit, tolerance, tmp_path):
    from graspcompass.outlines import read_outline

    text = (
        f'<?xml version="1.0" encoding="{encoding}"?>{head}'
        '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
        f'viewBox="0 0 100 100">{"".join(body)}</svg>'
    )
    p = tmp_path / "p.svg"
    p.write_bytes(text.encode(encoding))
    with no_hang("svg", 60):
        try:
            poly = read_outline(p, unit=unit, tolerance=tolerance)
        except GraspCompassError:
            return
    assert poly.is_valid and 0 < poly.area < math.inf
    assert "ENTITY" not in head or False  # an entity is never read


DXF_VALUES = st.sampled_from(
    [0.0, 1.0, 10.0, -3.0, 1e300, 1e308, -1e308, 1e-300, math.nan, math.inf, 1e12, 1e13]
)


@FUZZ
@given(
    kind=st.sampled_from(["circle", "polyline", "ellipse"]),
    values=st.lists(DXF_VALUES, min_size=8, max_size=8),
    insunits=st.sampled_from([None, 0, 1, 4, 6, -1, -5, 24, 25, 999]),
)
def test_fuzz_dxf_outlines(kind, values, insunits, tmp_path, capfd):
    ezdxf = pytest.importorskip("ezdxf")
    from graspcompass.outlines import read_outline

    doc = ezdxf.new()
    if insunits is not None:
        doc.header["$INSUNITS"] = insunits
    msp = doc.modelspace()
    try:
        if kind == "circle":
            msp.add_circle((values[0], values[1]), values[2])
        elif kind == "ellipse":
            msp.add_ellipse((values[0], values[1]), major_axis=(values[2], values[3]), ratio=0.5)
        else:
            msp.add_lwpolyline(
                [
                    (0, 0, 0, 0, values[4]),
                    (values[0], 0, 0, 0, values[5]),
                    (values[0], values[1]),
                    (0, values[1], 0, 0, values[6]),
                ],
                format="xyseb",
                close=True,
            )
        p = tmp_path / "p.dxf"
        doc.saveas(p)
    except Exception:  # ezdxf refuses to write some of these: nothing to read
        return
    with no_hang("dxf", 60):
        try:
            poly = read_outline(p)
        except GraspCompassError:
            poly = None
    assert capfd.readouterr().err == ""
    if poly is not None:
        assert poly.is_valid and 0 < poly.area < math.inf


# -- command-line options -------------------------------------------------------------------
OPTIONS = {
    "k": [
        "--x1",
        "--x2",
        "--y",
        "--phi1",
        "--phi2",
        "--mu1",
        "--mu2",
        "--xi1",
        "--theta",
        "--external-force",
        "--timeout",
    ],
    "size": [
        "--p1",
        "--p2",
        "--n1",
        "--n2",
        "--com",
        "--mass",
        "--mu",
        "--g",
        "--gravity",
        "--tilt",
        "--accel",
        "--safety",
        "--timeout",
    ],
    "steps": ["--x1", "--phi1", "--mu2", "--preset", "--timeout"],
}
PAIRS = st.sampled_from(
    [
        "0.05,0",
        "-0.05,0",
        "-1,0",
        "1,0",
        "0,0",
        "1e300,0",
        "-50mm,0",
        "25mm,0",
        "nan,0",
        "1,2,3",
        "0,5",
        "--",
        "-1e308,-1e308",
    ]
)


@FUZZ
@given(command=st.sampled_from(sorted(OPTIONS)), data=st.data())
def test_fuzz_cli_options(command, data, capsys):
    argv = [command]
    if command == "size":
        argv += [
            "--p1",
            "50mm,0",
            "--p2",
            "-50mm,0",
            "--n1",
            "-1,0",
            "--n2",
            "1,0",
            "--com",
            "25mm,0",
            "--mass",
            "1",
            "--mu",
            "0.3",
        ]
    for _ in range(data.draw(st.integers(1, 3))):
        option = data.draw(st.sampled_from(OPTIONS[command]))
        value = data.draw(
            PAIRS
            if option in ("--p1", "--p2", "--n1", "--n2", "--com", "--gravity")
            else NUMBER_TEXT
        )
        argv += data.draw(st.sampled_from([[option, value], [f"{option}={value}"]]))
    if command == "k" and "--theta" not in argv:
        argv += ["--theta", "0,pi/2"]
    with no_hang(" ".join(argv), 120):
        code = main(argv)
    out, err = capsys.readouterr()
    _one_line_or_ok(code, err)
    assert "inf" not in out.replace("info", "") and "nan" not in out.lower().replace(
        "nanosecond", ""
    ), out[-300:]


# -- API values --------------------------------------------------------------------------------
VALUES = st.one_of(
    st.sampled_from(
        [
            None,
            True,
            b"1",
            1j,
            sp.I,
            sp.oo,
            sp.zoo,
            sp.nan,
            sp.AccumBounds(0, 1),
            2**5000,
            Decimal("1e999999"),
            Decimal("nan"),
            Fraction(1, 3),
            np.longdouble("1e4000") if np.finfo(np.longdouble).max > 1e4000 else 1e308,
            [1.0, 2.0],
            {"a": 1},
            np.array([1.0]),
            object(),
            sp.Symbol("x"),
            sp.Integer(1) / (sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6))),
        ]
    ),
    NUMBER_TEXT,
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(10**400), 10**400),
)


@FUZZ
@given(value=VALUES, where=st.sampled_from(["x1", "phi1", "mu2", "point", "theta", "real"]))
def test_fuzz_api_values(value, where):
    import warnings

    from graspcompass import Grasp
    from graspcompass.geometry import Point
    from graspcompass.inputs import real_value

    base = dict(Grasp.preset("table1a").params)
    with warnings.catch_warnings(), no_hang(repr(where), 60):
        warnings.simplefilter("error")
        try:
            if where == "point":
                Point(value, 0)
            elif where == "theta":
                k = Grasp.preset("fig6").k_grasp(value)
                assert np.all(np.isfinite(np.asarray(k, dtype=float)))
            elif where == "real":
                real_value(value, "v")
            else:
                Grasp(**{**base, where: value})
        except GraspCompassError:
            pass
        except TypeError as exc:  # only a symbol where a number is needed (documented)
            assert isinstance(value, sp.Symbol) or "symbol" in str(exc).lower(), exc


# -- batch arrays ------------------------------------------------------------------------------
ARRAYS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=4),
    st.sampled_from(
        [
            None,
            "1",
            b"1",
            1j,
            [1j],
            [[1.0], [1.0, 2.0]],
            [None],
            Fraction(1, 2),
            Decimal("0.5"),
            sp.Rational(1, 2),
            sp.Symbol("a"),
            np.ones((3,)),
            np.ones((4,)),
            np.ones((2, 1)),
            np.array(["x"]),
            np.array([True]),
            np.ones((100_000, 1)),
            np.ones((1, 100_000)),
            object(),
        ]
    ),
)


@FUZZ
@given(x1=ARRAYS, x2=ARRAYS, fn=st.sampled_from(["worst_squeeze", "k_grasp", "closed_form"]))
def test_fuzz_batch_arrays(x1, x2, fn):
    import warnings

    from graspcompass import batch

    h = math.pi / 2
    with warnings.catch_warnings(), no_hang(fn, 60):
        warnings.simplefilter("error")
        try:
            if fn == "worst_squeeze":
                batch.worst_squeeze(x1, x2, 0.5, h, h, 0.5, 0.5, 1.0, on_invalid="nan")
            elif fn == "k_grasp":
                batch.k_grasp(x1, x2, 1.0, 0.5, h, h, 0.5, 0.5, on_invalid="nan")
            else:
                batch.closed_form(x1, x2, 0.5, h, h, 0.5, 0.5, on_invalid="nan")
        except GraspCompassError:
            pass
