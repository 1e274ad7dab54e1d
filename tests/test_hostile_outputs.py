"""Leftovers of issue 10: no ``sympify`` on outside values, writers refuse missing folders.

Each test here failed before its fix (see the issue's "Found" list).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from graspcompass.errors import InputError, OutputError, WrongTypeError
from graspcompass.symbols import mu1, phi1


def _payload(tmp_path: Path) -> tuple[str, Path]:
    marker = tmp_path / "ran"
    return f"__import__('os').system('touch {marker}') or 0", marker


# -- 1. the proof checker's boundary ------------------------------------------------
@pytest.mark.parametrize(
    "wrap", [np.array, lambda s: [s], lambda s: (s,)], ids=["ndarray", "list", "tuple"]
)
def test_violations_never_runs_text_in_containers(tmp_path: Path, wrap) -> None:
    from graspcompass.proof import violations

    code, marker = _payload(tmp_path)
    with pytest.raises(InputError):
        violations({"x1": wrap(code)})
    assert not marker.exists()


def test_violations_reads_text_with_the_safe_parser(tmp_path: Path) -> None:
    from graspcompass.proof import violations

    code, marker = _payload(tmp_path)
    with pytest.raises(InputError):
        violations({"x1": code})
    assert not marker.exists()
    assert violations({"phi1": "pi/2", "mu1": "1"}) == []


class _Sneaky:
    """An unknown object whose ``str`` is code (``sympify`` falls back to ``str``)."""

    def __init__(self, code: str) -> None:
        self.code = code

    def __str__(self) -> str:
        return self.code


@pytest.mark.parametrize(
    "call",
    [
        "prove_identity",
        "prove_sign",
        "reduce_expr",
        "trig_to_poly",
        "is_identically_zero",
        "assumption",
        "domain",
    ],
)
def test_proof_functions_never_sympify_outside_values(tmp_path: Path, call: str) -> None:
    import random

    from graspcompass import proof
    from graspcompass.proof.model import sample

    code, marker = _payload(tmp_path)
    for bad in (np.array([code]), _Sneaky(code)):
        with pytest.raises(WrongTypeError):
            if call == "prove_identity":
                proof.prove_identity(bad, 0)
            elif call == "prove_sign":
                proof.prove_sign(bad, 1)
            elif call == "assumption":
                proof.violations({phi1: sp.pi / 2}, [bad])
            elif call == "domain":
                sample([sp.Symbol("r")], random.Random(1), {sp.Symbol("r"): (bad, None)})
            else:
                getattr(proof, call)(bad)
    assert not marker.exists()


def test_proof_text_is_parsed_with_the_models_symbols() -> None:
    from graspcompass.proof import prove_identity

    r = prove_identity("sin(2*phi1)", 2 * sp.sin(phi1) * sp.cos(phi1))
    assert r.proved
    assert prove_identity(mu1 * 2, "2*mu1").proved


@pytest.mark.parametrize("where", ["params", "subs"])
def test_replay_with_subs_never_runs_text(tmp_path: Path, where: str) -> None:
    from graspcompass.construction.protocol import StepSpec, replay

    code, marker = _payload(tmp_path)
    q = sp.Symbol("q")
    params, subs = ((code, 0), {q: 1}) if where == "params" else ((q, 0), {q: code})
    with pytest.raises(InputError):
        replay([StepSpec("A", "point", (), "mark", "A", "-", params)], subs=subs)
    assert not marker.exists()
    spec = StepSpec("A", "point", (), "mark", "A", "-", (q, "1/3"))
    assert replay([spec], subs={"q": "1/2"})["A"].x == sp.Rational(1, 2)


@pytest.mark.parametrize("bad", ["code", "list", "array"])
def test_replay_reads_angles_at_the_boundary(tmp_path: Path, bad: str) -> None:
    from graspcompass.construction.protocol import StepSpec, replay

    code, marker = _payload(tmp_path)
    value = {"code": code, "list": [code], "array": np.array([code])}[bad]
    specs = [
        StepSpec("A", "point", (), "mark", "A", "-", (0, 0)),
        StepSpec("L", "line_at_angle", ("A",), "ruler", "L", "-", (value,)),
    ]
    with pytest.raises(InputError, match=r"L\.params\[0\]"):
        replay(specs)
    assert not marker.exists()
    specs[1] = StepSpec("L", "line_at_angle", ("A",), "ruler", "L", "-", ("60deg",))
    assert replay(specs)["L"].direction.y != 0


def test_sincos_refuses_text(tmp_path: Path) -> None:
    from graspcompass.geometry.trig import sincos

    code, marker = _payload(tmp_path)
    with pytest.raises(ValueError):
        sincos(code)
    assert not marker.exists()
    assert sincos(sp.pi / 3) == (sp.sqrt(3) / 2, sp.Rational(1, 2))


# -- 2. writers: an output's folder must exist -------------------------------------
@pytest.fixture(scope="module")
def c1a():
    from graspcompass import Grasp, internal_force_diagram

    return internal_force_diagram(Grasp.preset("table1a"))


def _writers():
    from graspcompass.export.geogebra import write_ggb
    from graspcompass.export.html import write_html
    from graspcompass.export.svg import write_svg
    from graspcompass.export.tikz import write_tikz

    return {"svg": write_svg, "ggb": write_ggb, "tex": write_tikz, "html": write_html}


@pytest.mark.parametrize("ext", ["svg", "ggb", "tex", "html"])
def test_export_writers_refuse_a_missing_folder(c1a, tmp_path: Path, ext: str) -> None:
    write = _writers()[ext]
    target = tmp_path / "missing" / "deeper" / f"d.{ext}"
    with pytest.raises(OutputError, match=r"the folder '.*missing/deeper' does not exist"):
        write(c1a, target)
    assert not (tmp_path / "missing").exists()
    assert write(c1a, tmp_path / f"d.{ext}").stat().st_size > 0


@pytest.mark.parametrize("ext", ["svg", "ggb", "tex", "html"])
def test_export_writers_turn_write_errors_into_output_errors(c1a, tmp_path: Path, ext: str) -> None:
    write = _writers()[ext]
    with pytest.raises(OutputError, match="that is a folder"):
        write(c1a, tmp_path)
    if os.path.exists("/dev/full"):
        with pytest.raises(OutputError, match="no space left"):
            write(c1a, "/dev/full")


def test_export_writer_removes_a_half_written_file(c1a, tmp_path: Path, monkeypatch) -> None:
    from graspcompass.export.svg import write_svg

    target = tmp_path / "d.svg"

    def full(self: Path, text: str, encoding: str | None = None) -> int:
        with open(self, "w", encoding=encoding) as f:
            f.write(text[:10])
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_text", full)
    with pytest.raises(OutputError, match="no space left"):
        write_svg(c1a, target)
    assert not target.exists()


@pytest.fixture(scope="module")
def small_anim(c1a):
    from graspcompass.render.animate import animate_construction

    return animate_construction(
        c1a, frames_per_step=1, pause_frames=1, hold_frames=1, figsize=(1.5, 1.5), dpi=20
    )


@pytest.mark.parametrize("ext", ["gif", "html"])
def test_write_animation_refuses_a_missing_folder(small_anim, tmp_path: Path, ext: str) -> None:
    from graspcompass.render.timeline import write_animation

    with pytest.raises(OutputError, match="does not exist"):
        write_animation(small_anim, tmp_path / "missing" / f"a.{ext}", quiet=True)
    assert not (tmp_path / "missing").exists()
    (tmp_path / f"dir.{ext}").mkdir()
    with pytest.raises(OutputError, match="that is a folder"):
        write_animation(small_anim, tmp_path / f"dir.{ext}", quiet=True)


def test_write_animation_removes_a_half_written_file(
    small_anim, tmp_path: Path, monkeypatch
) -> None:
    from graspcompass.render import timeline

    def full(frames, path, fps, palette_sample=None) -> int:
        Path(path).write_bytes(b"GIF89a")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(timeline, "write_gif", full)
    with pytest.raises(OutputError, match="no space left"):
        timeline.write_animation(small_anim, tmp_path / "a.gif", quiet=True)
    assert not (tmp_path / "a.gif").exists()


def test_write_animation_removes_the_file_of_a_failed_or_interrupted_write(
    small_anim, tmp_path: Path, monkeypatch
) -> None:
    from graspcompass.render import timeline

    def interrupted(frames, path, fps, palette_sample=None) -> int:
        Path(path).write_bytes(b"GIF89a")
        raise KeyboardInterrupt

    monkeypatch.setattr(timeline, "write_gif", interrupted)
    with pytest.raises(KeyboardInterrupt):
        timeline.write_animation(small_anim, tmp_path / "a.gif", quiet=True)
    assert not (tmp_path / "a.gif").exists()
    (tmp_path / "b.gif").write_bytes(b"old")  # a file that was there before is left alone
    with pytest.raises(KeyboardInterrupt):
        timeline.write_animation(small_anim, tmp_path / "b.gif", quiet=True)
    assert (tmp_path / "b.gif").exists()


def test_save_frames_refuses_a_missing_folder(small_anim, tmp_path: Path) -> None:
    from graspcompass.render.animate import save_frames

    with pytest.raises(OutputError, match="does not exist"):
        save_frames(small_anim, tmp_path / "png", frames=[0])
    assert not (tmp_path / "png").exists()
    (tmp_path / "file").write_text("")
    with pytest.raises(OutputError, match="is not a folder"):
        save_frames(small_anim, tmp_path / "file", frames=[0])
    assert [p.name for p in save_frames(small_anim, tmp_path, frames=[0])] == ["frame-0000.png"]
