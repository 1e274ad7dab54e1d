"""The command line refuses fast (issue 10: under a second per refusal, as a process).

What makes a refusal fast is tested here as behaviour, not as time (times live
in ``bench/bench_cli.py``): option errors are found before sympy or numpy are
loaded, an output that cannot be written is refused before any work, and the
program exits with ``main``'s status.
"""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import graspcompass
from graspcompass import cli
from graspcompass.boundary import _output
from graspcompass.errors import OutputError

HEAVY = ("sympy", "numpy", "mpmath", "matplotlib", "scipy", "shapely")


def _loaded_after(code: str) -> dict[str, bool]:
    """Which heavy modules a fresh interpreter has loaded after running ``code``."""
    probe = f"{code}\nimport sys\nprint(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
    out = subprocess.run(
        [sys.executable, "-c", probe],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONWARNINGS": "ignore"},
    )
    assert out.returncode == 0, out.stderr
    loaded = out.stdout.split()
    return {m: m in loaded for m in HEAVY}


def test_import_graspcompass_loads_no_heavy_module() -> None:
    assert not any(_loaded_after("import graspcompass, graspcompass.cli").values())


@pytest.mark.parametrize(
    "argv",
    [
        ["--version"],
        ["--help"],
        ["k", "--help"],
        ["presets"],
        ["animate", "--fps", "1e-300"],
        ["animate", "--dpi", "inf"],
        ["animate", "--fps", "nan"],
        ["steps", "--preset", "nope"],
        ["crosscheck", "--grasps", "0"],
        ["draw", "-o", "/no/such/folder/x.png"],
        ["draw", "--format", "pdf", "-o", "/dev/full"],
        ["export", "--format", "svg", "-o", "/no/such/folder/x.svg"],
        ["export", "-o", "x.zzz"],
        ["export", "--fragment", "-o", "/no/x.svg"],
        ["recipe", "-o", "/no/x.gc"],
        ["verify", "--markdown", "/no/x.md"],
        ["worksheet", "-o", "/no/x.pdf"],
        ["worksheet", "-o", "x.png"],
        ["draw", "-o", "x.gif"],
        ["--out", "/no/such/folder"],
        [
            "size",
            "--p1",
            "1,0",
            "--p2=-1,0",
            "--n1=-1,0",
            "--n2",
            "1,0",
            "--com",
            "0,0",
            "--mu",
            "0.3",
            "--mass",
            "-1",
        ],
        ["size", "--p1", "1,0", "--p2", "1", "--mass", "5lb"],
        ["check", "/no/such/file.gc"],
        ["check", "x.gc", "--markdown", "/no/such/folder/r.md"],
        ["check", "x.gc", "--draw", "cx.png"],
    ],
)
def test_usage_errors_and_cheap_commands_load_no_heavy_module(argv: list[str]) -> None:
    code = f"from graspcompass.cli import main\nmain({argv!r})"
    quiet = "contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO())"
    loaded = _loaded_after(
        f"import contextlib, io\nwith {quiet}:\n    {code.replace(chr(10), chr(10) + '    ')}"
    )
    assert not any(loaded.values()), loaded


@pytest.mark.parametrize(
    "argv",
    [
        ["animate", "-o", "/no/such/folder/x.gif"],
        ["animate", "-o", "x.avi"],
        ["animate", "-o", "/dev/full"],
    ],
)
def test_animation_output_errors_load_neither_sympy_nor_matplotlib(argv: list[str]) -> None:
    loaded = _loaded_after(
        "import contextlib, io\nfrom graspcompass.cli import main\n"
        "with contextlib.redirect_stderr(io.StringIO()):\n"
        f"    assert main({argv!r}) == 2"
    )
    assert not loaded["sympy"] and not loaded["matplotlib"], loaded


def test_value_errors_load_sympy_but_not_numpy_matplotlib() -> None:
    loaded = _loaded_after(
        "import contextlib, io\nfrom graspcompass.cli import main\n"
        "with contextlib.redirect_stderr(io.StringIO()):\n"
        "    assert main(['k', '--mu1', 'asin(2)']) == 2"
    )
    assert loaded["sympy"] and not loaded["matplotlib"] and not loaded["scipy"]


@pytest.mark.parametrize(
    "name, text",
    [
        ("mu1", "asin(2)"),
        ("x1", "sqrt(-1)"),
        ("y", "I"),
        ("x2", "oo"),
        ("mu2", "nan"),
        ("phi1", "10**10**10"),
        ("phi2", "sqrt(" * 20 + "2" + ")" * 20),
        ("xi1", "1e400"),
        ("x1", "__import__('os')"),
        ("y", "(1"),
        ("x2", "1+" * 150 + "1"),
        ("mu1", "1/0"),
    ],
)
def test_cli_refuses_text_with_the_models_message(name: str, text: str, capsys) -> None:
    """The early reading of the options says what the grasp itself says."""
    params = dict(graspcompass.PRESETS["table1a"]["params"])
    if name.startswith("xi"):  # friction as a cone angle replaces the coefficient
        params.pop(f"mu{name[2:]}")
    with pytest.raises(ValueError) as info:
        graspcompass.Grasp(**{**params, name: text})
    assert cli.main(["k", "--preset", "table1a", f"--{name}", text]) == 2
    assert capsys.readouterr().err == f"graspcompass: error: {cli.one_line(str(info.value))}\n"


def test_lazy_package_attributes_resolve_and_are_listed() -> None:
    for name in graspcompass.__all__:
        assert getattr(graspcompass, name) is not None, name
    assert set(graspcompass.__all__) <= set(dir(graspcompass))
    assert graspcompass.Grasp.__module__ == "graspcompass.grasp"
    assert graspcompass.PRESETS is __import__("graspcompass.grasp").grasp.PRESETS
    with pytest.raises(AttributeError, match="no_such_name"):
        graspcompass.no_such_name  # noqa: B018


def test_presets_data_builds_the_papers_grasps() -> None:
    """The data module and the model agree: Fig. 6's contact P1 = (√3/2, 1/2), μ1 = tan(π/4)."""
    import sympy as sp

    from graspcompass.presets import PRESETS

    assert sorted(PRESETS) == ["fig6", "table1a", "table1b", "table1c"]
    g = graspcompass.Grasp.preset("fig6")
    assert (g.x1, g.y) == (sp.sqrt(3) / 2, sp.Rational(1, 2))
    assert sp.simplify(g.mu1 - 1) == 0


# -- outputs that cannot be written: refused before the work -------------------------------
@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full on this system")
def test_dev_full_is_refused_before_any_work(monkeypatch, capsys) -> None:
    import graspcompass.construction as construction

    def boom(*args, **kwargs):
        raise AssertionError("the diagram was computed before the output was checked")

    monkeypatch.setattr(construction, "internal_force_diagram", boom)
    assert cli.main(["draw", "--format", "pdf", "-o", "/dev/full"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["graspcompass: error: cannot write '/dev/full': no space left on the device"]


@pytest.mark.skipif(not os.path.exists("/dev/null"), reason="no /dev/null on this system")
def test_dev_null_is_still_a_target() -> None:
    assert _output.check_target("/dev/null") == Path("/dev/null")


def test_a_full_file_system_is_refused_before_any_work(tmp_path: Path, monkeypatch) -> None:
    real = os.statvfs

    def statvfs(path):
        if Path(path) == tmp_path:
            return SimpleNamespace(f_bavail=0)
        return real(path)

    monkeypatch.setattr(os, "statvfs", statvfs)
    with pytest.raises(OutputError, match="no space left"):
        _output.check_target(tmp_path / "d.svg")
    with pytest.raises(OutputError, match="no space left"):
        _output.check_folder(tmp_path)


def test_a_broken_pipe_passes_through_writing(tmp_path: Path) -> None:
    """``-o /dev/stdout | head``: the reader stopped; not an output error."""
    with pytest.raises(BrokenPipeError):
        with _output.writing(tmp_path / "x"):
            raise BrokenPipeError(errno.EPIPE, "Broken pipe")


def test_svg_to_a_pipe_closed_early_ends_quietly() -> None:
    p = subprocess.Popen(
        [sys.executable, "-m", "graspcompass", "draw", "--format", "svg", "-o", "/dev/stdout"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert p.stdout is not None
    assert p.stdout.read(5) == b"<?xml"
    p.stdout.close()
    _, err = p.communicate(timeout=120)
    assert p.returncode == 0 and err == b"", err


# -- the program ---------------------------------------------------------------------------
def test_console_exits_with_mains_status(monkeypatch) -> None:
    monkeypatch.setattr(sys, "argv", ["graspcompass", "k", "--mu1", "asin(2)"])
    with pytest.raises(SystemExit) as info:
        cli.console()
    assert info.value.code == 2


def test_python_m_graspcompass_refuses_with_one_line() -> None:
    p = subprocess.run(
        [sys.executable, "-m", "graspcompass", "k", "--x1", "sqrt(-1)"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 2
    assert len(p.stderr.strip().splitlines()) == 1 and "not a real number" in p.stderr


@pytest.mark.parametrize(
    "argv",
    [
        [
            "check",
            str(Path(graspcompass.__file__).parent / "construction" / "recipes" / "paper.gc"),
            "--against",
            "paper",
        ],
        ["verify", "--quiet"],
    ],
)
def test_exact_commands_do_not_import_numpy(argv: list[str]) -> None:
    """The exact paths never compute with numpy; importing it costs 80 ms (issue 20)."""
    loaded = _loaded_after(
        "import contextlib, io\nfrom graspcompass.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    assert main({argv!r}) == 0"
    )
    assert loaded["sympy"] and not loaded["numpy"] and not loaded["matplotlib"], loaded
