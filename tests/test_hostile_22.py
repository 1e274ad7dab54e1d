"""Issue 22, item 8: hostile input tried as an attacker would, class by class.

Each test names the sample that broke docs/security.md's promise before the fix.
"""

from __future__ import annotations

import math
import os
import warnings
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from _hang import no_hang
from graspcompass import Grasp
from graspcompass.cli import TIMED, build_parser, main
from graspcompass.errors import GraspCompassError, InputError, InputTooLargeError, WrongTypeError
from graspcompass.inputs import float_value, real_value

# 1.3 KB within every size budget: eleven nested line-circle intersections, each of them
# a square root of the last (a let chain such as (t+1)**64 five deep is refused by degree)
SLOW = "param t > 0\nA = point (0, 0)\nB = point (1, t)\n" + "".join(
    f"c{i} = circle_through {p} {q}\nC{i} = point ({i}/(t+{i}), -{i + 2})\n"
    f"l{i} = line_through {p} C{i}\nR{i} = intersect_line_circle l{i} c{i} (1)\n"
    for i, p, q in zip(
        range(1, 12),
        ["A", "B", *(f"R{j}" for j in range(1, 10))],
        ["B", *(f"R{j}" for j in range(1, 11))],
    )
)


def _one_line_refusal(capsys, argv, fragment=""):
    code = main(argv)
    out, err = capsys.readouterr()
    assert out == ""
    assert code == 2, (code, err)
    assert len(err.strip().splitlines()) == 1 and "internal error" not in err, err
    assert fragment in err, err
    return err


# -- hangs and memory from small inputs -----------------------------------------------------
def test_every_command_that_replays_or_checks_takes_timeout():
    p = build_parser()
    sub = next(a for a in p._actions if a.dest == "command")
    for name in (*TIMED, "check", "verify", "explore"):
        assert "--timeout" in sub.choices[name]._option_string_actions, name


@pytest.mark.parametrize("command", ["steps", "draw", "export", "explore"])
def test_a_slow_file_stops_at_timeout(command, tmp_path, monkeypatch, capsys):
    """A 200-byte ``let`` chain replayed for over 60 s (only ``check`` had a timeout)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "slow.gc").write_text(SLOW)
    with no_hang(command, 60):
        err = _one_line_refusal(
            capsys, [command, "slow.gc", "--set", "t=1/3", "--timeout", "1"], "--timeout"
        )
    assert "longer than 1 s" in err
    assert sorted(os.listdir(tmp_path)) == ["slow.gc"]  # no half-written output


def test_a_fifo_is_refused_not_waited_for(tmp_path, capsys):
    """A FIFO given as a construction file blocked forever."""
    fifo = tmp_path / "f.gc"
    os.mkfifo(fifo)
    for argv in (["steps", str(fifo)], ["check", str(fifo)], ["draw", "--file", str(fifo)]):
        with no_hang("fifo", 30):
            _one_line_refusal(capsys, argv, "FIFO")
    _one_line_refusal(capsys, ["steps", str(tmp_path)], "")
    _one_line_refusal(capsys, ["steps", "/dev/zero"], "not a regular file")


@pytest.mark.parametrize(
    "value",
    [
        2 ** (10**6),
        -(2**5000),
        Fraction(1, 2**2000),
        Decimal("1e999999"),
        Decimal("-1e-999999"),
        sp.Integer(2) ** 4000,
        sp.Rational(1, 3**2000),
    ],
    ids=["2**10**6", "-2**5000", "Fraction", "Decimal", "-Decimal", "Integer", "Rational"],
)
def test_python_numbers_are_bounded_before_any_work(value):
    """``Grasp(x1=2**(10**6))`` and ``Decimal('1e999999')`` were accepted."""
    with no_hang("big number", 10):
        with pytest.raises(InputTooLargeError, match="bits"):
            real_value(value, "x1")
        g = Grasp.preset("table1a").params
        with pytest.raises(GraspCompassError, match="bits"):
            Grasp(**{**g, "x1": value})


def test_a_nested_list_is_sized_before_it_is_copied():
    """``k_grasp([[0.1]*10**5]*10**5)`` built the 80 GB array before the size check."""
    row = [0.1] * 10**5
    with no_hang("nested list", 10), pytest.raises(InputTooLargeError, match="before"):
        Grasp.preset("fig6").k_grasp([row] * 10**5)


def test_accumbounds_is_not_a_number():
    """``sympy.AccumBounds`` was taken as a number (k_grasp 0)."""
    with pytest.raises(WrongTypeError):
        Grasp.preset("fig6").k_grasp(sp.AccumBounds(0, 1))
    with pytest.raises(WrongTypeError):
        real_value(sp.AccumBounds(-1, 1) + 1, "x1")


def test_a_huge_long_double_leaks_no_warning():
    """``k_grasp`` of a long double 1e4000 leaked a RuntimeWarning beside its error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(InputError, match="finite"):
            float_value(np.longdouble("1e4000"), "theta")


@pytest.mark.parametrize("path", [None, b"x.gc", 3])
def test_read_file_of_a_non_name(path):
    from graspcompass.boundary._infiles import read_bounded

    with pytest.raises(WrongTypeError, match="file name"):
        read_bounded(path, 100)


def test_a_far_centre_of_mass_is_sized_in_floats_not_factored(capsys):
    """``size --com 1e300,0`` spent minutes in factorint (square roots of 2000-bit numbers).

    The squeeze is m·g·max|V_n|/D (eq. (17)) and V_n is linear in x1, x2 (eqs. (28)-(39)):
    with the centre of mass at a distance c ≫ D it grows as c (up to terms of relative size
    D/c).  So the float answer at c = 1e300 is 1e260 times the exact one at c = 1e40.
    """
    import json

    base = [
        "size",
        "--p1",
        "50mm,0",
        "--p2",
        "-50mm,0",
        "--n1",
        "-1,0",
        "--n2",
        "1,0",
        "--mass",
        "1",
        "--mu",
        "0.3",
        "--json",
    ]
    with no_hang("size --com 1e300", 30):
        assert main([*base, "--com", "1e300,0"]) == 0
    far = json.loads(capsys.readouterr().out)["worst_squeeze_N"]
    assert main([*base, "--com", "1e40,0"]) == 0  # 133 bits: the exact path
    near = json.loads(capsys.readouterr().out)["worst_squeeze_N"]
    assert far / near == pytest.approx(1e260, rel=1e-9)


def test_non_finite_results_are_refused_before_printing(capsys):
    """``size --mass 1e308`` printed "inf N per jaw … nan×"; --json wrote Infinity and NaN."""
    base = [
        "size",
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
        "1e308",
        "--mu",
        "0.3",
    ]
    _one_line_refusal(capsys, base, "beyond double precision")
    _one_line_refusal(capsys, [*base, "--json"], "beyond double precision")
    _one_line_refusal(capsys, ["k", "--theta=1e308"], "beyond double precision")


def test_draw_step_minus_one_is_out_of_range(capsys):
    """``draw --step=-1`` was accepted while 47 was refused as out of 0-46."""
    _one_line_refusal(capsys, ["draw", "--step=-1", "-o", os.devnull, "--format", "png"], "0 to 46")


# -- drawings: SVG and DXF ------------------------------------------------------------------
_PLAIN = (
    '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" '
    'viewBox="0 0 100 60"><rect x="10" y="10" width="80" height="40"/></svg>'
)


def _nested_use(levels: int) -> str:
    defs = ['<rect id="u0" x="0" y="0" width="10" height="10"/>']
    defs += [
        f'<g id="u{i}"><use href="#u{i - 1}"/><use href="#u{i - 1}"/></g>' for i in range(1, levels)
    ]
    return (
        '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" '
        f'viewBox="0 0 100 100"><defs>{"".join(defs)}</defs><use href="#u{levels - 1}"/>'
        "</svg>"
    )


def _read(path, **kw):
    from graspcompass.outlines import read_outline

    with no_hang(str(path), 30):
        return read_outline(path, **kw)


def test_nested_use_is_counted_before_it_is_expanded(tmp_path):
    """1.3 KB of 17 nested ``<use>`` ran past 90 s and 3 GB in ``plan --shape``."""
    p = tmp_path / "nested.svg"
    p.write_text(_nested_use(17))
    assert len(p.read_bytes()) < 1500
    with pytest.raises(InputTooLargeError, match="<use>"):
        _read(p)
    p.write_text(_nested_use(4))  # 8 copies of the square, all at one place: still read
    assert _read(p).area == pytest.approx(1e-4)  # 10 mm × 10 mm
    p.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg"><g id="a"><use href="#a"/></g>'
        '<rect width="1" height="1"/></svg>'
    )
    with pytest.raises(InputError, match="itself"):
        _read(p)


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-be", "utf-16-le", "utf-8-sig", "utf-32"])
def test_entities_are_refused_in_any_encoding(encoding, tmp_path):
    """A UTF-16 SVG with an internal ``<!ENTITY>`` passed the byte test."""
    body = _PLAIN.replace('height="40"', 'height="&a;"')
    for dtd in (
        '<!DOCTYPE svg [<!ENTITY a "40">]>',
        "<!DOCTYPE svg [<!ENTITY % p \"<!ENTITY a '40'>\"> %p;]>",
    ):
        text = f'<?xml version="1.0" encoding="{encoding.upper()}"?>{dtd}{body}'
        p = tmp_path / "e.svg"
        p.write_bytes(text.encode(encoding))
        with pytest.raises(InputError, match="entities"):
            _read(p)


@pytest.mark.parametrize("encoding", ["utf-8", "utf-16", "utf-16-be", "utf-32"])
def test_an_svg_reads_the_same_in_every_encoding(encoding, tmp_path):
    """The UTF-16 file was read 0.54 ppm larger (``width="…mm"`` read from raw bytes)."""
    p = tmp_path / "p.svg"
    p.write_bytes(
        (
            f'<?xml version="1.0" encoding="{encoding.upper()}"?>'
            '<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
            '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">' + _PLAIN
        ).encode(encoding)
    )
    poly = _read(p)
    assert poly.area == 0.08 * 0.04 and poly.bounds == (0.01, -0.05, 0.09, -0.01)


@pytest.mark.parametrize(
    "shape",
    [
        '<circle cx="0" cy="0" r="1e300"/>',
        '<rect width="1" height="1" transform="scale(1e300)"/>',
        '<rect width="1e400" height="1"/>',
    ],
)
def test_svg_coordinates_beyond_the_budget(shape, tmp_path):
    """A circle of radius 1e300: ``cannot convert float NaN to integer`` (a ValueError)."""
    p = tmp_path / "big.svg"
    p.write_text(f'<svg xmlns="http://www.w3.org/2000/svg">{shape}</svg>')
    with pytest.raises(InputError, match=r"drawing units|not finite|no closed shape"):
        _read(p)


def test_chords_are_counted_before_they_are_made(tmp_path):
    """200 arcs in 4 KB with tolerance=1e-9 flattened for over 30 s (checked after)."""
    arcs = "M 0 0 " + " ".join(f"A 1 1 0 0 1 {i + 1} 0" for i in range(200)) + " L 200 -50 Z"
    p = tmp_path / "arcs.svg"
    p.write_text(f'<svg xmlns="http://www.w3.org/2000/svg"><path d="{arcs}"/></svg>')
    assert len(p.read_bytes()) < 4096
    with pytest.raises(InputTooLargeError, match="vertices"):
        _read(p, tolerance=1e-9)


def _dxf(tmp_path, units=None, radius=10.0, bulges=None):
    ezdxf = pytest.importorskip("ezdxf")
    doc = ezdxf.new()
    if units is not None:
        doc.header["$INSUNITS"] = units
    msp = doc.modelspace()
    if bulges is None:
        msp.add_circle((0, 0), radius)
    else:
        msp.add_lwpolyline(
            [(0, 0, 0, 0, bulges[0]), (10, 0, 0, 0, bulges[1]), (10, 10), (0, 10)],
            format="xyseb",
            close=True,
        )
    path = tmp_path / "part.dxf"
    doc.saveas(path)
    return path


@pytest.mark.parametrize("units", [-5, -1, 999, 25])
def test_dxf_units_that_are_no_length_are_refused(units, tmp_path):
    """$INSUNITS −5 gave contacts at 6e20 mm (negative indexing); −1 exit 3; 999 a ValueError."""
    with pytest.raises(InputError, match=r"\$INSUNITS"):
        _read(_dxf(tmp_path, units))


def test_dxf_units_that_are_lengths_are_read(tmp_path):
    area = {4: 1e-6, 5: 1e-4, 6: 1.0, 1: 0.0254**2}  # mm, cm, m, in: a circle of radius 10
    for units, unit2 in area.items():
        got = _read(_dxf(tmp_path, units)).area
        assert got == pytest.approx(math.pi * 100 * unit2, rel=1e-3)


@pytest.mark.parametrize("radius", [1e308, 1e300, 1e13])
def test_dxf_huge_circle_is_refused_not_flattened(radius, tmp_path):
    """A DXF circle of radius 1e308 (83 bytes of entity) hung."""
    with pytest.raises(InputError, match=r"drawing units|not finite"):
        _read(_dxf(tmp_path, 4, radius))


@pytest.mark.parametrize("bulges", [(math.nan, 0.0), (1e300, 0.0), (math.inf, math.nan)])
def test_dxf_bad_bulges_are_one_named_error(bulges, tmp_path, capfd):
    """NaN or 1e300 bulges printed ezdxf's warnings: more than one stderr line."""
    from graspcompass.errors import GraspCompassError

    with pytest.raises(GraspCompassError):
        _read(_dxf(tmp_path, 4, bulges=bulges))
    assert capfd.readouterr().err == ""


@pytest.mark.parametrize("unit", ["1e300m", "1e-300m"])
def test_outline_of_infinite_or_zero_area_is_refused(unit, tmp_path):
    """``unit="1e300m"`` gave an outline of infinite area, ``"1e-300m"`` one of none."""
    p = tmp_path / "p.svg"
    p.write_text(_PLAIN.replace(' width="100mm" height="60mm"', ""))
    with pytest.raises(InputError, match="across"):
        _read(p, unit=unit)


@pytest.mark.parametrize("path", [None, b"x.svg", 3])
def test_read_outline_of_a_non_name(path):
    with pytest.raises(WrongTypeError):
        _read(path)


def test_animation_frames_are_bounded_before_drawing(tmp_path, capsys):
    """``animate --fps 120 --hold 60 --frames-per-step 120 --dpi 10`` was within the pixel
    budget with tens of thousands of frames, each kept until the file is written."""
    out = tmp_path / "x.gif"
    with no_hang("animate", 60):
        _one_line_refusal(
            capsys,
            [
                "animate",
                "--fps",
                "120",
                "--hold",
                "60",
                "--pause",
                "60",
                "--caption-seconds",
                "60",
                "--frames-per-step",
                "120",
                "--dpi",
                "10",
                "-o",
                str(out),
            ],
            "frames; at most 20000",
        )
    assert not out.exists()


# -- errors that are not the named ones: Point and batch through the one boundary -------------
@pytest.mark.parametrize(
    ("value", "error"),
    [
        (1j, "ComplexValueError"),
        (sp.I, "ComplexValueError"),
        (sp.oo, "NonFiniteValueError"),
        (sp.zoo, "NonFiniteValueError"),
        (sp.nan, "NonFiniteValueError"),
        (None, "WrongTypeError"),
        (True, "WrongTypeError"),
        (b"1", "WrongTypeError"),
        (2**5000, "InputTooLargeError"),
        ("1/0", "ExpressionError"),
    ],
)
def test_point_takes_coordinates_through_the_boundary(value, error):
    """``Point(1j, 0)``, ``I``, ``oo``, ``zoo``, ``nan`` passed; None, True, bytes: TypeError."""
    from graspcompass.geometry import Point

    with pytest.raises(GraspCompassError) as info:
        Point(value, 0)
    assert type(info.value).__name__ == error or error in {
        c.__name__ for c in type(info.value).__mro__
    }


_HALF = math.pi / 2
_GRASP = (1.0, 1.0, 0.5, _HALF, _HALF, 0.5, 0.5)


@pytest.mark.parametrize(
    ("x1", "error"),
    [
        ("1", WrongTypeError),
        (None, WrongTypeError),
        ([[1.0], [1.0, 2.0]], WrongTypeError),
        ([None], WrongTypeError),
        (["1"], WrongTypeError),
        (1j, "ComplexValueError"),
        ([1j], "ComplexValueError"),
        (sp.Symbol("a"), WrongTypeError),
        (object(), WrongTypeError),
    ],
)
def test_batch_refusals_are_named(x1, error):
    """``batch`` raised TypeError/ValueError for strings, None, ragged lists, complex values."""
    from graspcompass import batch

    with pytest.raises(GraspCompassError) as info:
        batch.worst_squeeze(x1, *_GRASP[1:], 1.0)
    names = {c.__name__ for c in type(info.value).__mro__}
    assert (error if isinstance(error, str) else error.__name__) in names


def test_batch_takes_exact_python_numbers_as_floats():
    from graspcompass import batch

    exact = batch.worst_squeeze(Fraction(1, 1), Decimal("1"), sp.Rational(1, 2), *_GRASP[3:], 1.0)
    assert exact == batch.worst_squeeze(*_GRASP, 1.0)


def test_batch_broadcast_is_sized_before_it_is_made():
    """A (100000, 1) × (1, 100000) broadcast allocated 74 GiB."""
    from graspcompass import batch

    col, row = np.ones((100_000, 1)), np.ones((1, 100_000))
    with no_hang("broadcast", 10), pytest.raises(InputTooLargeError, match="broadcast"):
        batch.worst_squeeze(col, row, *_GRASP[2:], 1.0)
    with pytest.raises(InputError, match="do not broadcast"):
        batch.k_grasp(np.zeros(3), np.ones(4), *_GRASP[1:])


def test_batch_mixed_array_libraries_are_named():
    xs = pytest.importorskip("array_api_strict")
    from graspcompass import batch

    with pytest.raises(WrongTypeError, match="mix array libraries"):
        batch.worst_squeeze(xs.asarray([1.0]), np.asarray([1.0]), *_GRASP[2:], 1.0)


# -- wrong answers accepted: an exactly-zero denominator in disguise ---------------------------
#: sqrt(5 + 2√6) = √2 + √3, so this divides by exactly 0.
DISGUISED = "1/(sqrt(2)+sqrt(3)-sqrt(5+2*sqrt(6)))"


def test_disguised_zero_denominator_is_refused_at_the_boundary(capsys):
    """Accepted by ``Point``, ``Grasp`` and ``k --theta`` (a row at 1.2e129 degrees)."""
    from graspcompass.errors import NonFiniteValueError
    from graspcompass.geometry import Point

    assert sp.sqrtdenest(sp.sqrt(5 + 2 * sp.sqrt(6))) == sp.sqrt(2) + sp.sqrt(3)  # the premise
    for make in (
        lambda: real_value(DISGUISED, "x1"),
        lambda: Point(DISGUISED, 0),
        lambda: Grasp(**{**Grasp.preset("table1a").params, "x1": DISGUISED}),
    ):
        with pytest.raises(GraspCompassError, match="exactly 0"):
            make()
    with pytest.raises(NonFiniteValueError):
        real_value(sp.Integer(1) / (sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6))), "y")
    _one_line_refusal(capsys, ["k", "--theta", DISGUISED], "exactly 0")
    assert real_value("1/(sqrt(2)+sqrt(3))", "x") == 1 / (sp.sqrt(2) + sp.sqrt(3))  # kept


def test_disguised_zero_is_not_negative(capsys):
    """``--external-force`` of a zero in disguise: "a magnitude cannot be negative"."""
    from graspcompass.inputs import force_value

    assert force_value("sqrt(2)+sqrt(3)-sqrt(5+2*sqrt(6))") == 0
    assert (
        main(
            ["k", "--theta", "0", "--external-force", "sqrt(2)+sqrt(3)-sqrt(5+2*sqrt(6))", "--json"]
        )
        == 0
    )
    assert '"F_int": 0.0' in capsys.readouterr().out


def test_parser_refuses_a_disguised_zero_denominator():
    from graspcompass.expr import parse_exact

    with pytest.raises(GraspCompassError, match="exactly 0"):
        parse_exact(DISGUISED)


def _disguised_zero(a: int, b: int) -> str:
    """sqrt(a) + sqrt(b) - sqrt(a + b + 2 sqrt(ab)): 0 by squaring (first principles)."""
    return f"(sqrt({a})+sqrt({b})-sqrt({a + b}+2*sqrt({a * b})))"


@settings(max_examples=40, deadline=None)
@given(
    a=st.integers(1, 10**6),
    b=st.integers(1, 10**6),
    form=st.sampled_from(
        [
            "1/{z}",
            "{z}**-1",
            "2/(3*{z})",
            "1 + 1/{z}",
            "{z}**(-3)",
            "sqrt(2)/({z}*5)",
            "1/({z}*sqrt(3))",
        ]
    ),
)
def test_every_disguised_zero_divisor_is_refused(a, b, form):
    """The class: a zero in disguise as a divisor or the base of a negative power, in any
    place of the text (squares are not zeros in disguise: the hypothesis keeps a*b non-square
    or square, both are zero)."""
    from graspcompass.expr import parse_exact

    text = form.format(z=_disguised_zero(a, b))
    with pytest.raises(GraspCompassError, match=r"exactly 0|division by zero"):
        parse_exact(text)


@settings(max_examples=30, deadline=None)
@given(a=st.integers(1, 10**4), b=st.integers(1, 10**4), c=st.integers(1, 50))
def test_a_near_zero_divisor_that_is_not_zero_is_kept(a, b, c):
    """Not every undecided-at-first divisor is zero: sqrt(a)+sqrt(b)-sqrt(a+b+2sqrt(ab)) + 1/c
    is 1/c, and the value is read, equal to c."""
    from graspcompass.expr import parse_exact

    value = parse_exact(f"1/({_disguised_zero(a, b)} + 1/{c})")
    assert abs(float(value.evalf(30)) - c) < 1e-9 * c


def test_a_file_refuses_a_disguised_zero_denominator(tmp_path, capsys):
    for text in (
        f"let z = {DISGUISED}\nO = point (z, 0)\n",
        f"param t > 0\nlet z = t/{_disguised_zero(2, 7)}\nO = point (z, 0)\n",
        f"O = point (1/{_disguised_zero(5, 11)}, 0)\n",
    ):
        (tmp_path / "z.gc").write_text(text)
        _one_line_refusal(capsys, ["steps", str(tmp_path / "z.gc")], "exactly 0")


def test_a_builder_refuses_a_disguised_zero_denominator():
    """The same value given from Python (a sympy expression) to the construction builder."""
    from graspcompass.construction.program import ConstructionBuilder

    zero = sp.sqrt(2) + sp.sqrt(3) - sp.sqrt(5 + 2 * sp.sqrt(6))
    b = ConstructionBuilder()
    with pytest.raises(GraspCompassError, match="exactly 0"):
        b.let("z", 1 / zero)
    b.let("w", 1 / (zero + sp.Rational(1, 7)))  # 7: kept


@pytest.mark.parametrize(
    "lets",
    [
        ["let a = (t+1)**64", "let b = (a+1)**64"],  # degree 4096
        ["let a = (t+1)**8", "let b = (a+1)**8", "let c = (b+1)**8"],  # 512
        ["let a = t**32", "let b = a*a*a"],  # 96 by products
        ["let a = (t+1)**16", "let b = 1/(a+1)**8"],  # 128 in a denominator
        ["param s > 0", "param u > 0", "param v > 0", "let a = (s+t+u+v+1)**40"],  # C(44,4) terms
    ],
)
def test_a_let_chain_is_refused_before_the_work(lets, tmp_path, capsys):
    """A ``let`` chain that would make a polynomial of huge degree (or too many terms) is
    refused while the file is read, in a fraction of a second, with the degree named."""
    f = tmp_path / "chain.gc"
    f.write_text(
        "\n".join(
            ["param t > 0", *lets, "O = point (0, 0)", f"A = point ({lets[-1].split()[1]}, 0)"]
        )
        + "\n"
    )
    with no_hang("a let chain", 10):
        err = _one_line_refusal(capsys, ["steps", str(f)], "degree")
    assert "too costly" in err


def test_a_let_chain_within_the_budget_is_read(tmp_path, capsys):
    """Degree 64 in one name (the largest allowed) still reads and replays."""
    f = tmp_path / "ok.gc"
    f.write_text("param t > 0\nlet a = t**8\nlet b = a**8\nO = point (0, 0)\nA = point (b, 1)\n")
    assert main(["steps", str(f), "--set", "t=1"]) == 0
    assert "(1, 1)" in capsys.readouterr().out


@pytest.mark.parametrize("text", [b"O = point (0, 0)", None, 3, ["O = point (0, 0)"]])
def test_language_parse_refuses_what_is_not_text_with_a_named_error(text):
    from graspcompass.construction.language import parse
    from graspcompass.errors import NotTextError

    with pytest.raises(NotTextError, match=type(text).__name__):
        parse(text)


# -- refusals that gave a false reason ---------------------------------------------------------
_BRACKET = os.path.join(
    os.path.dirname(__file__), "..", "docs", "_static", "outlines", "bracket.svg"
)


@pytest.mark.parametrize("extra", [["--mass", "1e308"], ["--mass", "1", "--g", "1e308"]])
def test_plan_overflow_is_not_called_no_force_closure(extra, capsys):
    """ "none of the 190 pairs is force-closure" for huge masses: they are, the squeeze
    overflows."""
    err = _one_line_refusal(
        capsys,
        ["plan", "--shape", _BRACKET, "--mu", "0.5", "--samples", "40", *extra],
        "beyond double precision",
    )
    assert "none of the" not in err


def test_a_huge_value_is_not_called_symbolic(tmp_path, capsys):
    """``--set a=1e300`` was refused as "the construction is symbolic"."""
    f = tmp_path / "t.gc"
    f.write_text("param a > 0\nO = point (0, 0)\nA = point (a, 0)\nc = circle_through O A\n")
    err = _one_line_refusal(
        capsys,
        ["draw", str(f), "--set", "a=1e300", "-o", str(tmp_path / "t.png")],
        "beyond double precision",
    )
    assert "symbolic" not in err
    from graspcompass import internal_force_diagram
    from graspcompass.layout import numeric_objects

    with pytest.raises(ValueError, match="symbolic"):  # a symbolic one still says so
        numeric_objects(internal_force_diagram(Grasp.symbolic("mu")))


def test_a_virtual_file_system_is_not_a_full_disk(capsys):
    """``-o /proc/x`` was refused as "no space left on the device"."""
    if not os.path.isdir("/proc") or os.statvfs("/proc").f_blocks:
        pytest.skip("no /proc without blocks here")
    err = _one_line_refusal(
        capsys, ["export", "--format", "svg", "-o", "/proc/x.svg"], "virtual file system"
    )
    assert "space" not in err
    if os.path.exists("/dev/full"):
        _one_line_refusal(capsys, ["draw", "-o", "/dev/full", "--format", "png"], "no space")
