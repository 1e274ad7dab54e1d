"""The command line: the main job, sub-commands, and one-line errors with exit status 2."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import graspcompass
from graspcompass.cli import main


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture()
def stub_gif(monkeypatch):
    """The main job's GIF written by a stub (its own tests are in test_animate.py, on the
    same ``write_main_animation``: writing it again costs 15-30 s); records ``quiet``."""
    from graspcompass import cli

    written = []

    def stub(construction, out_dir, quiet=False):
        written.append(quiet)
        path = Path(out_dir) / cli.MAIN_ANIMATION
        path.write_bytes(b"GIF89a")
        return path

    monkeypatch.setattr(cli, "write_main_animation", stub)
    return written


def test_main_job_writes_fig6_and_prints_protocol(tmp_path, capsys, stub_gif):
    from graspcompass import cli

    code, out, err = run(capsys, "--out", str(tmp_path))
    assert code == 0 and err == "" and stub_gif == [False]
    png = tmp_path / "fig6-diagram.png"
    assert png.stat().st_size > 10_000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "fig6-diagram.svg").read_text().lstrip().startswith("<?xml")
    steps = json.loads((tmp_path / "fig6-steps.json").read_text())
    assert [s["name"] for s in steps][:3] == ["O", "x-axis", "y-axis"]
    # the printed protocol carries exact coordinates: V2 = (√3, −3/2) of §4.1 by hand,
    # S2 = (x1 + x2)/2 − y tan(φ2 + ξ2) = √3/2 + √3/2 and C2 = x1 tan(2π/3) = −3/2
    line_v2 = next(ln for ln in out.splitlines() if ln.split()[1:2] == ["V2"])
    assert "(sqrt(3), -3/2)" in line_v2
    assert cli.MAIN_ANIMATION in out  # the four files are named


def test_main_job_quiet(tmp_path, capsys, stub_gif):
    """-q prints nothing and asks the GIF writer for quiet."""
    from graspcompass import cli

    code, out, _ = run(capsys, "--quiet", "--out", str(tmp_path))
    assert code == 0 and out == "" and stub_gif == [True]
    assert {p.name for p in tmp_path.iterdir()} == {
        "fig6-diagram.png",
        "fig6-diagram.svg",
        "fig6-steps.json",
        cli.MAIN_ANIMATION,
    }


def test_steps_json_roundtrip_values(capsys):
    code, out, _ = run(capsys, "steps", "--preset", "table1a", "--json")
    assert code == 0
    steps = {s["name"]: s for s in json.loads(out)}
    # Table I(a): φ = π/2 so tan(φ + ξ) = −1/μ; V1 = (−2 − 1·1, 2·(−1)) = (−3, −2)
    assert steps["V1"]["value"]["x"] == "-3" and steps["V1"]["value"]["y"] == "-2"
    assert steps["X1"]["instrument"] == "ruler"
    assert all(s["caption"] and s["ref"] for s in steps.values())


def test_k_values_against_first_principles(capsys):
    code, out, _ = run(
        capsys,
        "k",
        "--preset",
        "table1a",
        "--theta",
        "0:360:90deg",
        "--external-force",
        "2",
        "--json",
    )
    assert code == 0
    recs = json.loads(out)
    assert [r["theta_deg"] for r in recs] == [0, 90, 180, 270]
    # Table I(a) by hand: V1 = (-3, -2), V2 = (17/6, -5/3), V3 = (-1, 2), V4 = (7/6, 5/3);
    # k_n(θ) = S_n sin θ − C_n cos θ; at θ = 0: k = (2, 5/3, −2, −5/3) → k_grasp = 2
    assert recs[0]["k"] == pytest.approx([2, 5 / 3, -2, -5 / 3], abs=1e-12)
    assert recs[0]["k_grasp"] == pytest.approx(2) and recs[0]["limiting"] == 1
    # eq. (17): F_int = k / (x1 + x2) · F_e = 2 / 4 · 2
    assert recs[0]["F_int"] == pytest.approx(1.0)
    # θ = π/2: k = S_n → max(−3, 17/6, −1, 7/6) = 17/6 by k2
    assert recs[1]["k_grasp"] == pytest.approx(17 / 6) and recs[1]["limiting"] == 2


def test_k_exact_output(capsys):
    code, out, _ = run(capsys, "k", "--preset", "table1a", "--theta", "pi/2", "--exact", "--json")
    assert code == 0
    assert json.loads(out)[0]["k_grasp_exact"] == "17/6"


def test_override_parameters(capsys):
    code, out, _ = run(capsys, "k", "--preset", "table1a", "--y", "3", "--theta", "pi/2", "--json")
    # that is Table I(b): V2.x = S2 = 2 − 3·(−1/1.2) = 9/2
    assert code == 0 and json.loads(out)[0]["k"][1] == pytest.approx(4.5)


def test_draw_formats(tmp_path, capsys):
    for ext in ("png", "svg", "pdf"):
        path = tmp_path / f"d.{ext}"
        code, _, _ = run(capsys, "draw", "--preset", "table1c", "-o", str(path), "--step", "20")
        assert code == 0 and path.stat().st_size > 1000
    assert (tmp_path / "d.pdf").read_bytes()[:4] == b"%PDF"


def test_presets_lists_all(capsys):
    code, out, _ = run(capsys, "presets")
    assert code == 0 and {ln.split()[0] for ln in out.splitlines()} == {
        "fig6",
        "table1a",
        "table1b",
        "table1c",
    }


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["k", "--mu1", "0.1"], "contact 1: φ1 + ξ1"),
        (["k", "--x1", "-1"], "x1 + x2 = -1"),
        (["k", "--phi2", "__import__('os').system('true')"], "cannot read"),
        (["k", "--phi2", "().__class__"], "cannot read"),
        (["k", "--y", "sqrt(3"], "malformed"),
        (["k", "--theta", "0:360:0deg"], "step must be positive"),
        (["k", "--external-force", "-1"], "external-force"),
        (["k", "--mu1", "0.5", "--xi1", "pi/8"], "exactly one"),
        (["draw", "-o", "out.gif"], "cannot tell the format"),
        (["draw", "--step", "999"], "out of range"),
        (["draw", "-o", "/nonexistent-dir/\0bad.png"], ""),
        (["steps", "--preset", "nope"], "invalid choice"),
        (["bogus"], "invalid choice"),
    ],
)
def test_user_errors_one_line_exit_2(argv, fragment, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse's own errors exit through SystemExit
        code = exc.code
    assert code == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert fragment in err


def test_console_script_subprocess_no_traceback(tmp_path):
    src = str(Path(graspcompass.__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": src + os.pathsep + os.environ.get("PYTHONPATH", "")}
    proc = subprocess.run(
        [sys.executable, "-m", "graspcompass", "k", "--phi1", "a.b"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        env=env,
        check=False,
    )
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr
    assert "cannot read 'a.b'" in proc.stderr


def test_draw_break_points_flag(tmp_path, capsys, monkeypatch):
    import graspcompass.render as render

    seen = []
    real = render.figure_diagram
    monkeypatch.setattr(
        render,
        "figure_diagram",
        lambda *a, **k: seen.append(k.get("break_points")) or real(*a, **k),
    )
    paths = []
    for flag in ([], ["--break-points"]):
        path = tmp_path / f"d{len(flag)}.png"
        code, _, _ = run(capsys, "draw", "--preset", "fig6", "-o", str(path), "-q", *flag)
        assert code == 0 and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        paths.append(path)
    assert seen == [False, True]
    assert paths[0].read_bytes() != paths[1].read_bytes()  # the labels are drawn
