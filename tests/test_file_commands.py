"""Construction files on steps, draw, animate, export and explore (issue 11 §3, §1).

(a) The shipped recipe as a file gives what the commands give without a file;
(b) a Thales file (its own parameters, ``--set``) and a student's exercise (the grasp's
parameters) work end to end, their objects checked against values computed here from
first principles; (c) every refusal is one line on stderr and exit status 2.  And
``internal_force_diagram`` (which replays the shipped file) gives the protocol the
Python step specs give.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
import sympy as sp

from graspcompass import Grasp, cli, internal_force_diagram
from graspcompass.construction.language import example_text, paper_text
from graspcompass.construction.recipe import _internal_force_diagram_from_specs

THALES = example_text("thales.gc")

#: A student's V3 (Fig. 4(c)) with one slip: the perpendicular through P1x, not P2x.
EXERCISE = example_text("exercise-v3.gc")

SETS = ("--set", "a=2", "--set", "b=1", "--set", "t=1/3")


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, Path]:
    d = tmp_path_factory.mktemp("gc")
    out = {"paper": d / "paper.gc", "thales": d / "thales.gc", "exercise": d / "v3.gc"}
    out["paper"].write_text(paper_text(), encoding="utf-8")
    out["thales"].write_text(THALES, encoding="utf-8")
    out["exercise"].write_text(EXERCISE, encoding="utf-8")
    return out


def _point(rec: dict) -> tuple[sp.Expr, sp.Expr]:
    return sp.sympify(rec["value"]["x"]), sp.sympify(rec["value"]["y"])


# -- §1: internal_force_diagram replays the shipped file -------------------------------------
@pytest.mark.parametrize(
    "grasp",
    [
        "fig6",
        "table1a",
        "table1b",
        "table1c",
        Grasp("7/10", "13/10", "3/10", "7*pi/12", "5*pi/12", mu1="1/2", mu2="9/10"),
        Grasp(0.7, 1.3, 0.3, 1.9, 1.3, mu1=0.5, mu2=0.9),
    ],
    ids=["fig6", "table1a", "table1b", "table1c", "exact", "float"],
)
def test_internal_force_diagram_is_the_python_specs_protocol(grasp):
    g = Grasp.preset(grasp) if isinstance(grasp, str) else grasp
    a, b = internal_force_diagram(g), _internal_force_diagram_from_specs(g)
    assert a.names == b.names and a.skipped == b.skipped and a.steps == b.steps
    assert a.grasp is g


# -- (a) the shipped recipe as a file: the same output -----------------------------------------
@pytest.mark.parametrize(
    "argv", [("steps",), ("steps", "--json"), ("steps", "--preset", "table1c", "--mu1", "0.7")]
)
def test_steps_of_the_paper_file_are_todays(capsys, files, argv):
    code, without, _ = run(capsys, *argv)
    assert code == 0
    assert run(capsys, *argv, files["paper"]) == (0, without, "")
    assert run(capsys, *argv, "--file", files["paper"]) == (0, without, "")


@pytest.mark.parametrize("fmt", ["svg", "tikz", "json", "ggb", "html"])
def test_export_of_the_paper_file_is_todays(capsys, files, tmp_path, fmt):
    a, b = tmp_path / f"a.{fmt}", tmp_path / f"b.{fmt}"
    assert run(capsys, "export", "--preset", "table1b", "-o", a, "-q")[0] == 0
    assert run(capsys, "export", files["paper"], "--preset", "table1b", "-o", b, "-q")[0] == 0
    if fmt == "ggb":  # a zip archive: its entries carry the time they were written
        a_xml, b_xml = (zipfile.ZipFile(p).read("geogebra.xml") for p in (a, b))
        assert a_xml == b_xml and b"x_1" in b_xml
    else:
        assert a.read_bytes() == b.read_bytes()


def test_draw_of_the_paper_file_is_todays(capsys, files, tmp_path):
    a, b = tmp_path / "a.png", tmp_path / "b.png"
    assert run(capsys, "draw", "--preset", "table1a", "-o", a, "-q")[0] == 0
    assert (
        run(capsys, "draw", "--file", files["paper"], "--preset", "table1a", "-o", b, "-q")[0] == 0
    )
    assert a.read_bytes() == b.read_bytes()


def test_animate_and_explore_of_the_paper_file_get_todays_construction(
    capsys, files, tmp_path, monkeypatch
):
    import graspcompass.render.animate as animate
    import graspcompass.render.explorer as explorer

    seen = []

    def fake_animate(c, **kw):
        seen.append(c)
        raise ValueError("stop here")

    monkeypatch.setattr(animate, "animate_construction", fake_animate)
    monkeypatch.setattr(explorer, "explore", lambda g, **kw: seen.append(g))
    for extra in ((), ("--file", files["paper"])):
        assert run(capsys, "animate", "table1c", *extra, "-o", tmp_path / "x.gif")[0] == 2
    assert seen[0].steps == seen[1].steps == internal_force_diagram(Grasp.preset("table1c")).steps
    assert run(capsys, "explore", files["paper"], "--preset", "table1a")[0] == 0
    assert seen[2].params == Grasp.preset("table1a").params


# -- (b) a Thales file and a student's exercise ---------------------------------------------
def test_thales_file_steps_exact(capsys, files):
    code, out, err = run(capsys, "steps", files["thales"], *SETS, "--json")
    assert code == 0 and err == ""
    recs = {r["name"]: r for r in json.loads(out)}
    assert list(recs) == ["O", "V", "dir", "H", "circle"]
    # first principles: H = (V·d / d·d) d with V = (a, b), d = (t, −1), a = 2, b = 1, t = 1/3
    a, b, t = sp.Integer(2), sp.Integer(1), sp.Rational(1, 3)
    lam = (a * t - b) / (t**2 + 1)
    assert _point(recs["H"]) == (lam * t, -lam)
    hx, hy = lam * t, -lam
    assert (hx - a / 2) ** 2 + (hy - b / 2) ** 2 == (a**2 + b**2) / 4  # H is on the circle
    code, table, _ = run(capsys, "steps", "--file", files["thales"], *SETS)
    assert code == 0 and "(-1/10, 3/10)" in table and "centre (1, 1/2)" in table


def test_thales_file_draw_export_animate(capsys, files, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert run(capsys, "draw", files["thales"], *SETS, "-q")[0] == 0
    assert (tmp_path / "thales.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    for fmt in ("svg", "tikz", "json", "ggb"):
        assert run(capsys, "export", files["thales"], *SETS, "--format", fmt, "-q")[0] == 0
    ext = {"svg": "svg", "tikz": "tex", "json": "json", "ggb": "ggb"}
    svg = (tmp_path / "thales.svg").read_text()
    assert 'id="H"' in svg and 'id="circle"' in svg
    assert "\\draw" in (tmp_path / "thales.tex").read_text()
    doc = json.loads((tmp_path / "thales.json").read_text())
    assert doc["grasp"] is None and [s["name"] for s in doc["steps"]][-1] == "circle"
    xml = zipfile.ZipFile(tmp_path / f"thales.{ext['ggb']}").read("geogebra.xml").decode()
    assert 'label="H"' in xml and "x_1" not in xml
    code, _, _ = run(
        capsys,
        "animate",
        "--file",
        files["thales"],
        *SETS,
        "--dpi",
        "20",
        "--frames-per-step",
        "1",
        "--pause",
        "0",
        "--hold",
        "0",
    )
    assert code == 0 and (tmp_path / "thales-construction.gif").stat().st_size > 0


def test_exercise_file_with_the_grasp(capsys, files, tmp_path, monkeypatch):
    code, out, _ = run(capsys, "steps", files["exercise"], "--preset", "table1c", "--json")
    assert code == 0
    recs = {r["name"]: r for r in json.loads(out)}
    # first principles, Table I(c): P1 = (2, 2), P2 = (−2, 2), φ1 = π/2, μ1 = 1/2: the lower
    # side at P1 runs along d = (−(sin φ1 − μ1 cos φ1), −(cos φ1 + μ1 sin φ1)) = (−1, −1/2)
    x1, x2, y, mu1, phi1 = 2, 2, 2, sp.Rational(1, 2), sp.pi / 2
    dx, dy = -(sp.sin(phi1) - sp.cos(phi1) * mu1), -(sp.cos(phi1) + sp.sin(phi1) * mu1)
    x3 = x1 - y * dx / dy  # X3: where P1 + s d meets y = 0
    y3 = x1 * dx / dy  # the perpendicular to d through P1x = (x1, 0) meets x = 0 there
    omx3 = x3 - sp.Rational(x1 - x2, 2)
    assert _point(recs["X3"]) == (x3, 0) and _point(recs["Y3"]) == (0, y3)
    assert _point(recs["V3"]) == (-omx3, -y3) == (2, -4)
    # the paper's V3 has the perpendicular through P2x: its C3 is x2 tan(φ1 − ξ1) = −x2 dx/dy
    assert internal_force_diagram(Grasp.preset("table1c"))["V3"].y != -y3
    drawn = []
    monkeypatch.setattr(
        cli,
        "_draw",
        lambda c, path, fmt, step, overlay, title=None, *_: drawn.append((c, overlay, title)),
    )
    assert (
        run(
            capsys,
            "draw",
            files["exercise"],
            "--preset",
            "table1c",
            "-o",
            tmp_path / "v3.png",
            "-q",
        )[0]
        == 0
    )
    c, overlay, title = drawn[0]
    assert c["V3"].x == 2 and not overlay  # no k_grasp of the paper over a student's file
    assert title == f"v3.gc: {Grasp.preset('table1c').title}"
    assert run(capsys, "draw", "--preset", "table1c", "-o", tmp_path / "p.png", "-q")[0] == 0
    assert drawn[1][1] and drawn[1][2] is None


def test_exercise_file_exports_without_sliders(capsys, files, tmp_path):
    out = tmp_path / "v3.ggb"
    assert run(capsys, "export", files["exercise"], "-o", out, "-q")[0] == 0
    xml = zipfile.ZipFile(out).read("geogebra.xml").decode()
    assert "x_1" not in xml and 'label="V3"' in xml
    assert Grasp.preset("fig6").title.split(":")[0] in xml  # the grasp's title is kept
    assert run(capsys, "export", files["exercise"], "-o", tmp_path / "v3.json", "-q")[0] == 0
    doc = json.loads((tmp_path / "v3.json").read_text())
    assert doc["grasp"] is not None and doc["steps"][-1]["name"] == "V3"


@pytest.mark.parametrize(
    "argv",
    [
        ("export", "{exercise}", "-o", "{tmp}/x.html"),
        ("explore", "{exercise}"),
        ("explore", "--file", "{thales}", "--set", "a=1", "--set", "b=1", "--set", "t=0"),
        ("animate", "--file", "{exercise}", "--kind", "sweep", "-o", "{tmp}/x.gif"),
        ("animate", "--file", "{exercise}", "--kind", "orientation", "-o", "{tmp}/x.gif"),
    ],
)
def test_paper_only_pictures_refuse_a_foreign_file(capsys, files, tmp_path, argv):
    names = {**{k: str(v) for k, v in files.items()}, "tmp": str(tmp_path)}
    code, out, err = run(capsys, *(a.format(**names) for a in argv))
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "shows the paper's recipe" in err and "has other steps" in err
    assert not list(tmp_path.iterdir())


# -- (c) refusals: one line, exit status 2 -------------------------------------------------------
@pytest.mark.parametrize(
    "argv, message",
    [
        (
            ("steps", "{thales}", "--set", "a=2"),
            "thales.gc:4:1: no value for the parameter 'b': give --set b=VALUE",
        ),
        (
            ("steps", "{thales}", *SETS, "--set", "c=1"),
            "thales.gc has no parameter 'c' (its parameters: a, b, t)",
        ),
        (("steps", "{thales}", *SETS, "--set", "x1=1"), "--set x1: x1 is a grasp parameter"),
        (("steps", "{thales}", *SETS, "--set", "a=3"), "--set a is given twice"),
        (("steps", "{thales}", *SETS, "--x1", "2"), "--x1 is not used: "),
        (
            ("steps", "{thales}", "--set", "a=-2", "--set", "b=1", "--set", "t=0"),
            "thales.gc:3:1: a = -2 is outside its domain",
        ),
        (
            ("steps", "{thales}", "--set", "a=__import__('os')", "--set", "b=1", "--set", "t=0"),
            "--set a: cannot read",
        ),
        (("steps", "--set", "a=1"), "--set gives values to the parameters of a construction file"),
        (("draw", "{thales}", "--file", "{thales}", "-o", "{tmp}/x.png"), "two construction files"),
        (("steps", "{tmp}/missing.gc"), "cannot read"),
        (("steps", "{tmp}"), "cannot read"),
        (("export", "{bad}", "-o", "{tmp}/x.svg"), "bad.gc:2:"),
        (("draw", "{latin1}", "-o", "{tmp}/x.png"), "is not UTF-8 text"),
        (
            ("animate", "--file", "{parallel}", "-o", "{tmp}/x.gif"),
            "parallel.gc:6:1: step X = meet",
        ),
        (("steps", "{thales}", "--set", "a"), "write NAME=VALUE"),
    ],
)
def test_refusals_are_one_line(capsys, files, tmp_path, argv, message):
    (tmp_path / "bad.gc").write_text("A = point (0, 0)\nB = meet A A\n")
    (tmp_path / "latin1.gc").write_bytes('A = point (0, 0) "é"\n'.encode("latin-1"))
    (tmp_path / "parallel.gc").write_text(
        "param a > 0\nO = point (0, 0)\nP = point (0, 1)\nl = line_with_direction O (1, a)\n"
        "m = line_with_direction P (1, a)\nX = meet l m\n"
    )
    names = {
        **{k: str(v) for k, v in files.items()},
        "tmp": str(tmp_path),
        **{k: str(tmp_path / f"{k}.gc") for k in ("bad", "latin1", "parallel")},
    }
    argv = tuple(a.format(**names) for a in argv)
    if any("parallel" in a for a in argv):
        argv += ("--set", "a=1")
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "", err
    assert err.count("\n") == 1 and message in err, err
    assert not {p.name for p in tmp_path.iterdir()} - {"bad.gc", "latin1.gc", "parallel.gc"}


def test_an_unreadable_file_is_refused_before_sympy_is_loaded(tmp_path):
    code = (
        "import sys\nfrom graspcompass.cli import main\n"
        f"assert main(['draw', {str(tmp_path / 'no.gc')!r}, '-o', "
        f"{str(tmp_path / 'x.png')!r}]) == 2\n"
        "print(' '.join(m for m in ('sympy', 'numpy', 'matplotlib') if m in sys.modules))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONWARNINGS": "ignore"},
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "" and "cannot read" in out.stderr
