"""Issue 22: tried as a newcomer.  Every command answers, or explains in one line.

Each test names the input that failed before the fix (items 1-7 of the issue).
"""

from __future__ import annotations

import argparse

import pytest

from graspcompass.cli import build_parser, main

#: What each command needs besides the option under test (so that parsing reaches it).
_NEEDS = {
    "size": ["--p1=0,0", "--p2=1,0", "--mass=1"],
    "plan": ["--shape=x.svg"],
    "check": ["x.gc"],
}


def _value_options() -> list[tuple[str, str]]:
    """Every (command, option) that takes one value."""
    p = build_parser()
    sub = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))
    found = [
        (None, s)
        for a in p._actions
        for s in a.option_strings
        if a.nargs is None and s.startswith("--")
    ]
    for name, sp in sub.choices.items():
        found += [
            (name, a.option_strings[-1])
            for a in sp._actions
            if a.option_strings and a.nargs is None
        ]
    return found


def _parse(argv: list[str]) -> tuple[argparse.Namespace | None, str]:
    import contextlib
    import io

    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        try:
            return build_parser().parse_args(argv), ""
        except SystemExit:
            return None, err.getvalue()


@pytest.mark.parametrize(("command", "option"), _value_options())
@pytest.mark.parametrize("value", ["-0.05,0", "-pi/4+pi", "-1", "--", "-50mm,0;1,2"])
def test_item1_every_value_option_takes_a_leading_dash(command, option, value):
    """``--p2 -0.05,0`` is read as ``--p2=-0.05,0`` (argparse: "expected one argument")."""
    head = [] if command is None else [command, *_NEEDS.get(command, [])]
    spaced, err1 = _parse([*head, option, value])
    joined, err2 = _parse([*head, f"{option}={value}"])
    assert "expected one argument" not in err1, err1
    assert err1.replace(f"{option} {value}", "") == err2.replace(f"{option}={value}", ""), (
        err1,
        err2,
    )
    if joined is not None:
        assert vars(spaced) == vars(joined)


def test_item1_an_option_as_value_stays_an_option(capsys):
    assert main(["draw", "-o", "-q"]) == 2
    assert "expected one argument" in capsys.readouterr().err


@pytest.mark.parametrize("argv", [["k", "--x1=--"], ["k", "--x1", "--"], ["size", "--p1=--"]])
def test_item8_double_dash_value_is_a_user_error(argv, capsys):
    """``--x1=--`` was exit 3 (TypeError: expected a str, got list)."""
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1 and "internal error" not in err


def test_item1_readme_size_without_equals(capsys):
    argv = [
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
        "1kg",
        "--mu",
        "0.3",
        "--g",
        "9.81",
    ]
    assert main(argv) == 0
    assert "25.01 N per jaw" in capsys.readouterr().out


# -- item 2: a normal is a direction ----------------------------------------------------------
_C10, _S10 = "-0.98480775301", "-0.17364817767"  # cos 10°, sin 10° to 11 digits


@pytest.mark.parametrize(
    "normal",
    [(_C10, _S10), ("-3", "0"), ("-1/2", "1/7"), (float(_C10), float(_S10)), (-1e-30, 1e-31)],
)
def test_item2_any_nonzero_normal_is_scaled_to_one(normal):
    import sympy as sp

    from graspcompass.world import place_grasp

    wg = place_grasp(
        [("0.05", "0"), ("-0.05", "0")], [normal, ("1", "0")], mu=("0.5", "0.5"), com=("0.025", "0")
    )
    n = wg.normals[0]
    if isinstance(normal[0], float):
        length = (normal[0] ** 2 + normal[1] ** 2) ** 0.5
        assert n == pytest.approx((normal[0] / length, normal[1] / length), rel=1e-15)
    else:  # exact: the same direction, exactly of length one
        gx, gy = (sp.Rational(v) for v in normal)
        assert sp.simplify(n[0] ** 2 + n[1] ** 2 - 1) == 0
        assert sp.simplify(n[0] * gy - n[1] * gx) == 0 and sp.simplify(n[0] / gx) > 0


@pytest.mark.parametrize("normal", [("0", "0"), (0.0, 0.0), (0.0, -0.0)])
def test_item2_a_zero_normal_is_refused(normal):
    from graspcompass.world import NormalNotUnitError, place_grasp

    with pytest.raises(NormalNotUnitError, match="zero vector"):
        place_grasp(
            [("0.05", "0"), ("-0.05", "0")],
            [normal, ("1", "0")],
            mu=("0.5", "0.5"),
            com=("0.025", "0"),
        )


def test_item2_cli_rounded_normal(capsys):
    """``--n1=-0.98480775301,-0.17364817767`` was "not a unit vector (length 1)"."""
    import math

    argv = [
        "size",
        "--p1",
        "50mm,0",
        "--p2",
        "-50mm,0",
        "--n2",
        "1,0",
        "--com",
        "25mm,0",
        "--mass",
        "1kg",
        "--mu",
        "0.3",
        "--g",
        "9.81",
        "--json",
    ]
    assert main([*argv, f"--n1={_C10},{_S10}"]) == 0
    rounded = capsys.readouterr().out
    c, s = math.cos(math.radians(10)), math.sin(math.radians(10))
    assert main([*argv, f"--n1={-c!r},{-s!r}"]) == 0
    exact = capsys.readouterr().out
    import json

    a, b = json.loads(rounded), json.loads(exact)
    assert a["worst_squeeze_N"] == pytest.approx(b["worst_squeeze_N"], rel=1e-9)


# -- item 3: what each command needs comes with the install the README names ----------------
def _project() -> dict:
    from pathlib import Path

    tomllib = pytest.importorskip("tomllib")
    return tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())["project"]


def _names(requirements: list[str]) -> set[str]:
    import re

    return {re.split(r"[<>=!\[ ;]", r, maxsplit=1)[0].lower() for r in requirements}


def test_item3_outline_readers_come_with_the_main_install():
    """``plan --shape`` and ``size --shape`` failed after ``pip install .`` ([outlines])."""
    assert {"svgelements", "ezdxf", "shapely"} <= _names(_project()["dependencies"])


def test_item3_crosscheck_and_mp4_name_their_extra(monkeypatch, capsys):
    """crosscheck asked for the *test* extra; MP4 needed a system ffmpeg."""
    import importlib.util

    extras = _project()["optional-dependencies"]
    assert "scipy" in _names(extras["crosscheck"]) and "imageio-ffmpeg" in _names(extras["mp4"])
    assert {"scipy", "imageio-ffmpeg"} <= _names(extras["test"])  # tested in CI
    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util, "find_spec", lambda name, *a: None if name == "scipy" else real(name, *a)
    )
    assert main(["crosscheck", "--grasps", "1", "--thetas", "1"]) == 2
    assert "pip install 'graspcompass[crosscheck]'" in capsys.readouterr().err


def test_item3_readme_names_the_extra_of_each_command():
    from pathlib import Path

    readme = (Path(__file__).parents[1] / "README.md").read_text()
    for line in readme.splitlines():
        if line.startswith("$ graspcompass crosscheck"):
            assert "graspcompass[crosscheck]" in line
        if line.startswith("$ graspcompass") and ".mp4" in line:
            assert "graspcompass[mp4]" in line


def test_item3_cli_writes_an_mp4(tmp_path, capsys):
    """``animate … .mp4`` through the mp4 extra's ffmpeg; the file read back by ffmpeg."""
    imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg", reason="the test extra brings it")
    out = tmp_path / "s.mp4"
    assert (
        main(
            [
                "animate",
                "--kind",
                "sweep",
                "--frames",
                "5",
                "--dpi",
                "20",
                "--fps",
                "5",
                "-q",
                "-o",
                str(out),
            ]
        )
        == 0
    ), capsys.readouterr().err
    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(out))
    assert frames == 5 and seconds == pytest.approx(1.0, abs=0.05)


# -- item 4: animate takes a FILE where draw, steps and export do ---------------------------
def test_item4_animate_takes_a_file(tmp_path, monkeypatch, capsys):
    """``animate mine.gc`` answered "unknown preset 'mine.gc'"."""
    monkeypatch.chdir(tmp_path)
    assert main(["recipe", "-o", "mine.gc", "-q"]) == 0
    assert main(["animate", "mine.gc", "--frames-per-step", "1", "--dpi", "20", "-q"]) == 0
    assert (tmp_path / "mine-construction.gif").stat().st_size > 0
    assert (
        main(["animate", "table1a", "--kind", "sweep", "--frames", "2", "--dpi", "20", "-q"]) == 0
    )
    assert (tmp_path / "table1a-sweep.gif").exists()
    capsys.readouterr()
    assert main(["animate", "nosuch.gc"]) == 2
    err = capsys.readouterr().err
    assert "--file" in err and "neither a preset" in err and len(err.splitlines()) == 1
    assert main(["animate", "mine.gc", "--file", "mine.gc"]) == 2
    assert "two construction files" in capsys.readouterr().err


# -- item 5: each exit status has one meaning ------------------------------------------------
def test_item5_exit_status_3_is_undecided_everywhere(capsys):
    """3 was "undecided" in the README and check's docs and "a bug" in ``--help``."""
    import re
    from pathlib import Path

    from graspcompass.cli import EXIT_STATUSES

    assert "undecided" in EXIT_STATUSES[3] and "bug" not in EXIT_STATUSES[3]
    assert "bug" in EXIT_STATUSES[4]
    assert main(["--help"]) == 0
    top = capsys.readouterr().out
    assert re.search(r"^\s+3\s+undecided", top, re.M) and re.search(
        r"^\s+4\s+an internal", top, re.M
    )
    assert main(["check", "--help"]) == 0
    assert "3 something undecided" in capsys.readouterr().out
    root = Path(__file__).parents[1]
    for text in ((root / "README.md").read_text(), (root / "docs" / "security.md").read_text()):
        assert not re.search(r"\b3\b[^.|\n]{0,20}\bbug", text), "3 named a bug"


# -- item 6: exact inputs print the exact values, rounded once --------------------------------
def _table1a_k(theta, x1="2"):
    """k_n(θ) of Table I(a) from first principles: φ = π/2 makes tan(φ ± ξ) = ∓1/μ.

    S_n = ∓D/2 ± y tan(side n), C_n = x tan(side n) (eqs. (28)-(39)), k_n = S_n sin θ − C_n cos θ.
    """
    import sympy as sp

    x1, x2, y, mu1, mu2 = (
        sp.Rational(x1),
        sp.Integer(2),
        sp.Integer(1),
        sp.Integer(1),
        sp.Rational(6, 5),
    )
    tan = {1: -1 / mu1, 2: -1 / mu2, 3: 1 / mu1, 4: 1 / mu2}
    half = (x1 + x2) / 2
    S = {1: -half + y * tan[1], 3: -half + y * tan[3], 2: half - y * tan[2], 4: half - y * tan[4]}
    C = {1: x2 * tan[1], 3: x2 * tan[3], 2: x1 * tan[2], 4: x1 * tan[4]}
    return [S[n] * sp.sin(theta) - C[n] * sp.cos(theta) for n in (1, 2, 3, 4)]


@pytest.mark.parametrize("x1", ["2", "1e-30"])
def test_item6_k_json_is_the_exact_value_rounded(x1, capsys):
    """``--json`` gave 1.06e-16 and -1.4999999999999998 where the values are 0 and -3/2."""
    import json

    import sympy as sp

    thetas = "0,pi/2,pi,3*pi/2,30deg,1,7*pi/12,atan(2/3),atan2(-5,3)"
    assert main(["k", "--preset", "table1a", "--x1", x1, "--theta", thetas, "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    angles = [
        0,
        sp.pi / 2,
        sp.pi,
        3 * sp.pi / 2,
        sp.pi / 6,
        sp.Integer(1),
        7 * sp.pi / 12,
        sp.atan(sp.Rational(2, 3)),
        sp.atan2(-5, 3),
    ]
    for row, th in zip(rows, angles, strict=True):
        ks = [sp.nsimplify(v) if v.is_Rational else v for v in _table1a_k(th, x1)]
        expected = [float(sp.N(v, 50)) + 0.0 for v in ks]
        assert row["k"] == expected, (th, row["k"], expected)
        top = max([*ks, sp.Integer(0)], key=lambda v: sp.N(v, 50))
        assert row["k_grasp"] == float(sp.N(top, 50)) + 0.0
        assert row["F_int"] == float(sp.N(top / (sp.Rational(x1) + 2), 50)) + 0.0
        assert row["theta_deg"] == float(sp.N(th * 180 / sp.pi, 50))
    if x1 == "2":
        assert rows[7]["k"][0] == 0.0  # k1(atan(2/3)) = 0 exactly (tan θ = C1/S1)


def test_item6_k_table_prints_exact_zero(capsys):
    """The table printed k4 = -4.97074e-42 where the value is 0."""
    assert main(["k", "--preset", "table1a", "--theta", "atan(2/3)"]) == 0
    assert capsys.readouterr().out.splitlines()[2].split()[2] == "0"  # k1
    assert main(["k", "--preset", "table1a", "--theta", "pi/2", "--x1", "1e-30"]) == 0
    assert capsys.readouterr().out.splitlines()[2].split()[4] == "-5e-31"  # not -1.22e-16


# -- item 7: hints that save a user ----------------------------------------------------------
@pytest.mark.parametrize(
    ("argv", "hint"),
    [
        (
            ["k", "--phi1", "90"],
            "a number without a unit is in radians: for 90 degrees write 90deg",
        ),
        (["k", "--xi2", "30"], "for 30 degrees write 30deg"),
        (["k", "--mu1", "0,5"], "the decimal separator is a point"),
        (
            [
                "size",
                "--p1=0,0",
                "--p2=1,0",
                "--n1=1,0",
                "--n2=-1,0",
                "--com=0.5,0",
                "--mass",
                "1,5",
                "--mu",
                "0.3",
            ],
            "decimal separator",
        ),
    ],
)
def test_item7_refusals_say_what_to_type(argv, hint, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert hint in err and len(err.splitlines()) == 1, err


def test_item7_no_hint_where_it_would_mislead(capsys):
    assert main(["k", "--phi1", "200"]) == 2  # 200deg is refused too
    assert "deg" not in capsys.readouterr().err


def test_item7_explore_without_display_points_to_html(monkeypatch, capsys):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    import matplotlib

    monkeypatch.setattr(matplotlib, "get_backend", lambda: "agg")
    assert main(["explore"]) == 2
    assert "export --format html" in capsys.readouterr().err


def test_item7_every_command_has_a_description():
    p = build_parser()
    sub = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))
    assert all(sp.description for sp in sub.choices.values()), [
        n for n, sp in sub.choices.items() if not sp.description
    ]


@pytest.mark.parametrize("columns", [60, 80, 100, 160])
def test_item7_verify_table_fits_the_terminal(columns, monkeypatch, capsys):
    """The table was about 450 characters wide."""
    monkeypatch.setenv("COLUMNS", str(columns))
    assert main(["verify", "-q"]) == 0
    out = capsys.readouterr().out
    assert max(len(line) for line in out.splitlines()) <= columns
    for word in ("eq5", "PROVED", "REFUTED", "hypotheses", "polynomial reduction"):
        assert word in out


def test_item7_verify_table_keeps_every_word(monkeypatch, capsys):
    from graspcompass.cli._verify import table
    from graspcompass.proof import run_catalogue, to_table

    reports = run_catalogue(quiet=True)
    assert sorted(table(reports, 70).split()) == sorted(to_table(reports).split())
