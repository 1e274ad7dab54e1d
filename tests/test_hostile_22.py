"""Issue 22, item 8: hostile input tried as an attacker would, class by class.

Each test names the sample that broke docs/security.md's promise before the fix.
"""

from __future__ import annotations

import os
import warnings
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from _hang import no_hang
from graspcompass import Grasp
from graspcompass.cli import TIMED, build_parser, main
from graspcompass.errors import GraspCompassError, InputError, InputTooLargeError, WrongTypeError
from graspcompass.inputs import float_value, real_value

#: A small file whose exact replay grows without bound: each let squares ... 64 times.
SLOW = "param t > 0\n" + "".join(
    f"let {b} = ({a}+1)**64\n" for a, b in zip("tabcd", "abcde")) + "O = point (e, 0)\n"


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
    for name in (*TIMED, "check"):
        assert "--timeout" in sub.choices[name]._option_string_actions, name


@pytest.mark.parametrize("command", ["steps", "draw", "export"])
def test_a_slow_file_stops_at_timeout(command, tmp_path, monkeypatch, capsys):
    """A 200-byte ``let`` chain replayed for over 60 s (only ``check`` had a timeout)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "slow.gc").write_text(SLOW)
    with no_hang(command, 60):
        err = _one_line_refusal(capsys, [command, "slow.gc", "--set", "t=1/3", "--timeout",
                                         "1"], "--timeout")
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


@pytest.mark.parametrize("value", [2**(10**6), -(2**5000), Fraction(1, 2**2000),
                                   Decimal("1e999999"), Decimal("-1e-999999"),
                                   sp.Integer(2) ** 4000, sp.Rational(1, 3**2000)],
                         ids=["2**10**6", "-2**5000", "Fraction", "Decimal", "-Decimal",
                              "Integer", "Rational"])
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
    from graspcompass._infiles import read_bounded

    with pytest.raises(WrongTypeError, match="file name"):
        read_bounded(path, 100)


def test_a_far_centre_of_mass_is_sized_in_floats_not_factored(capsys):
    """``size --com 1e300,0`` spent minutes in factorint (square roots of 2000-bit numbers).

    The squeeze is m·g·max|V_n|/D (eq. (17)) and V_n is linear in x1, x2 (eqs. (28)-(39)):
    with the centre of mass at a distance c ≫ D it grows as c (up to terms of relative size
    D/c).  So the float answer at c = 1e300 is 1e260 times the exact one at c = 1e40.
    """
    import json

    base = ["size", "--p1", "50mm,0", "--p2", "-50mm,0", "--n1", "-1,0", "--n2", "1,0",
            "--mass", "1", "--mu", "0.3", "--json"]
    with no_hang("size --com 1e300", 30):
        assert main([*base, "--com", "1e300,0"]) == 0
    far = json.loads(capsys.readouterr().out)["worst_squeeze_N"]
    assert main([*base, "--com", "1e40,0"]) == 0  # 133 bits: the exact path
    near = json.loads(capsys.readouterr().out)["worst_squeeze_N"]
    assert far / near == pytest.approx(1e260, rel=1e-9)


def test_non_finite_results_are_refused_before_printing(capsys):
    """``size --mass 1e308`` printed "inf N per jaw … nan×"; --json wrote Infinity and NaN."""
    base = ["size", "--p1", "50mm,0", "--p2", "-50mm,0", "--n1", "-1,0", "--n2", "1,0",
            "--com", "25mm,0", "--mass", "1e308", "--mu", "0.3"]
    _one_line_refusal(capsys, base, "beyond double precision")
    _one_line_refusal(capsys, [*base, "--json"], "beyond double precision")
    _one_line_refusal(capsys, ["k", "--theta=1e308"], "beyond double precision")


def test_draw_step_minus_one_is_out_of_range(capsys):
    """``draw --step=-1`` was accepted while 47 was refused as out of 0-46."""
    _one_line_refusal(capsys, ["draw", "--step=-1", "-o", os.devnull, "--format", "png"],
                      "0 to 46")
