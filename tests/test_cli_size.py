"""``graspcompass size``: the squeeze in newtons on the command line (issue 13 §2).

Expected numbers come from first principles here: the worked example by hand, and the
world-frame LP of ``tests/test_sizing.py`` (``lp_squeeze``) at the reported worst load.
"""

from __future__ import annotations

import json
import math
import shlex
import subprocess
import sys

import pytest

from graspcompass.cli import main
from test_sizing import e, lp_squeeze

WORKED = [
    "size",
    "--p1",
    "50mm,0",
    "--p2=-50mm,0",
    "--n1=-1,0",
    "--n2",
    "1,0",
    "--com",
    "25mm,0",
    "--mass",
    "1kg",
    "--mu",
    "0.3",
]


def run_json(argv: list[str], capsys) -> dict:
    assert main([*argv, "--json"]) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


def test_worked_example_json(capsys) -> None:
    d = run_json([*WORKED, "--g", "9.81"], capsys)
    hand = 9.81 * math.sqrt(0.05**2 + (0.075 / 0.3) ** 2) / 0.1  # m g |V_1| / D
    assert d["worst_squeeze_N"] == pytest.approx(hand, rel=1e-12)
    assert round(d["worst_squeeze_N"], 1) == 25.0 and d["per"] == "jaw"
    assert d["vendor_squeeze_N"] == pytest.approx(16.35, rel=1e-12)
    assert d["slipping_contact"] == "jaw1"  # jaw 1 is 25 mm from the centre of mass
    assert d["worst_direction_deg"] == pytest.approx(360 - math.degrees(math.atan(0.2)))
    assert d["ratio"] == pytest.approx(hand / 16.35)
    assert d["worst_squeeze_exact"] == "981*sqrt(26)/200"
    lp, _ = lp_squeeze(
        (0.05, 0),
        (-0.05, 0),
        (-1, 0),
        (1, 0),
        0.3,
        0.3,
        (0.025, 0),
        9.81 * e(math.radians(d["worst_direction_deg"])),
    )
    assert lp == pytest.approx(hand, rel=1e-7)


def test_units_accel_safety_and_total(capsys) -> None:
    """The same part in grams and centimetres, |a| <= 2 m/s², safety 1.5, total squeeze."""
    argv = [
        "size",
        "--p1",
        "5cm,0",
        "--p2=-5cm,0",
        "--n1=-1,0",
        "--n2",
        "1,0",
        "--com",
        "2.5cm,0",
        "--mass",
        "1000g",
        "--mu1",
        "0.3",
        "--mu2",
        "3/10",
        "--accel",
        "2",
        "--safety",
        "1.5",
        "--per",
        "total",
    ]
    d = run_json(argv, capsys)
    per_jaw = 1.5 * (9.80665 + 2) * math.sqrt(0.065) / 0.1
    assert d["per"] == "total" and d["worst_squeeze_N"] == pytest.approx(2 * per_jaw)
    assert d["worst_squeeze_per_jaw_N"] == pytest.approx(per_jaw)
    assert d["vendor_squeeze_N"] == pytest.approx(1.5 * (9.80665 + 2) / 0.3)  # m(g+a)S/μ
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "TOTAL (both jaws)" in out and out.count("total (both jaws)") >= 3


def test_given_gravity_tilt_accel_vector_and_least_mu(capsys) -> None:
    """Tilted jaws (normals 16° and 37° off the line), unequal friction, a tilt range."""
    part = [
        "size",
        "--p1",
        "40mm,0",
        "--p2=-40mm,0",
        "--n1=-0.96,0.28",
        "--n2",
        "0.8,0.6",
        "--com",
        "5mm,-10mm",
        "--mass",
        "750g",
    ]
    case = ["--gravity", "0,-1", "--tilt", "10deg", "--accel-vector", "0,2"]
    d = run_json([*part, "--mu1", "0.8", "--mu2", "1", *case, "--max-force", "4N"], capsys)
    w = d["load_direction_deg"]
    lp, _ = lp_squeeze(
        (0.04, 0),
        (-0.04, 0),
        (-0.96, 0.28),
        (0.8, 0.6),
        0.8,
        1.0,
        (0.005, -0.01),
        0.75 * 9.80665 * _rotated_load(w),
    )
    assert lp == pytest.approx(d["squeeze_N"], rel=1e-7)
    assert abs((d["gravity_direction_deg"] + 180) % 360 - 180) <= 10 + 1e-9
    lm = d["least_mu"]
    assert lm["mu_force_closure"] == pytest.approx(0.75) and lm["mu"] > 0.75
    # at the least μ (both pads) the worst of the case needs exactly 4 N per jaw
    d2 = run_json([*part, "--mu", repr(lm["mu"]), *case], capsys)
    assert d2["squeeze_N"] == pytest.approx(4, rel=1e-9)
    # a limit the case never reaches down to force closure: any force-closure μ suffices
    lm = run_json([*part, "--mu", "1", *case, "--max-force", "30N"], capsys)["least_mu"]
    assert lm["mu"] == lm["mu_force_closure"] and "any μ above" in lm["message"]


def _rotated_load(load_deg: float):
    """The load m(g ĝ − a)/m for ĝ = (0, −1) turned by ρ, a = (0, 2) turned too, whose
    direction is ``load_deg``: its length is |g ĝ − a| = g + 2."""
    return (9.80665 + 2) / 9.80665 * e(math.radians(load_deg))


def test_outline_part(capsys) -> None:
    """A 60 × 40 mm plate held on its short sides 10 mm above the centroid."""
    argv = [
        "size",
        "--p1",
        "30mm,10mm",
        "--p2=-30mm,10mm",
        "--outline=-30mm,-20mm;30mm,-20mm;30mm,20mm;-30mm,20mm",
        "--mass",
        "200g",
        "--mu",
        "0.5",
    ]
    d = run_json(argv, capsys)
    assert d["contacts"] == ["jaw1", "jaw2"]
    # by hand: x1 = x2 = 0.03, y = 0.01, tan(π/2 ± ξ) = ∓2: V_1 = (−0.03 − 0.02, −0.06)
    assert d["worst_squeeze_N"] == pytest.approx(0.2 * 9.80665 * math.hypot(0.05, 0.06) / 0.06)


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--mass", "-1"], "--mass must not be negative"),
        (["--mass", "3lb"], "unknown unit 'lb' in '3lb'"),
        (["--mass", "nan"], "nan"),
        (["--mass", "sqrt(-1)"], "not a real number"),
        (["--mass", "0"], "mass must be positive"),
        (["--mass", "1", "--gravity", "0,-1", "--tilt", "15"], "'15' needs a unit"),
        (["--mass", "1", "--safety", "0.5"], "at least 1"),
        (["--mass", "1", "--accel", "1", "--accel-vector", "0,1", "--gravity", "0,-1"], "not both"),
        (["--mass", "1", "--max-force", "10lbf"], "unknown unit 'lbf'"),
        (["--mass", "1", "--g", "__import__('os')"], "cannot read"),
    ],
)
def test_bad_values_one_line_exit_2(extra, message, capsys) -> None:
    argv = [a for a in WORKED if a not in ("--mass", "1kg")] + extra
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("graspcompass: error: ") and message in err


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            "--p1 0.04,0 --p2=-0.04,0 --n1=-0.8,0.6 --n2 1,0 --com 0,0 --mu 0.5",
            "not force-closure: squeezing harder cannot hold this part: contact jaw1",
        ),
        ("--p1 0.04,0 --p2=-0.04,0 --n1 1,0 --n2 1,0 --com 0,0 --mu 0.5", "no friction suffices"),
        ("--p1 0.04,0 --p2=-0.04,0 --n1=0,0 --n2 1,0 --com 0,0 --mu 2", "zero normal"),
        (
            "--p1 0.041,0 --p2=-0.04,0 --mu 0.5 "
            "'--outline=-0.04,-0.02;0.04,-0.02;0.04,0.02;-0.04,0.02'",
            "does not lie on the outline",
        ),
        (
            "--p1 0.04,0 --p2=-0.04,0 --n1=-1,0 --n2 1,0 --com 0,0 --mu 0.5 --outline '0,0;1,0'",
            "at least 3 vertices",
        ),
        ("--p1 0.04 --p2=-0.04,0 --n1=-1,0 --n2 1,0 --com 0,0 --mu 0.5", "expected X,Y"),
        ("--p1 4in,0 --p2=-0.04,0 --n1=-1,0 --n2 1,0 --com 0,0 --mu 0.5", "unknown unit 'in'"),
        ("--p1 0.04,0 --p2=-0.04,0 --com 0,0 --mu 0.5", "--n1 and --n2"),
        ("--p1 0.04,0 --p2=-0.04,0 --n1=-1,0 --n2 1,0 --com 0,0 --mu 0.5 --mu1 1", "not both"),
    ],
)
def test_bad_parts_one_line_exit_2(argv, message, capsys) -> None:
    assert main(["size", *shlex.split(argv), "--mass", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err, err


def test_force_closure_message_names_the_friction_needed(capsys) -> None:
    argv = [
        "size",
        "--p1",
        "0.04,0",
        "--p2=-0.04,0",
        "--n1=-0.8,0.6",
        "--n2",
        "1,0",
        "--com",
        "0,0",
        "--mu",
        "0.5",
        "--mass",
        "1",
    ]
    assert main(argv) == 2
    assert "force closure needs μ > 0.75 there" in capsys.readouterr().err


def test_missing_required_option_is_a_usage_error(capsys) -> None:
    assert main(["size", "--p1", "0,0"]) == 2
    assert "required" in capsys.readouterr().err


def test_as_a_process() -> None:
    p = subprocess.run(
        [sys.executable, "-m", "graspcompass", *WORKED, "--json"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert {
        "worst_squeeze_N",
        "worst_direction_deg",
        "slipping_contact",
        "vendor_squeeze_N",
    } <= set(d)
    assert round(d["worst_squeeze_N"], 2) == 25.0
