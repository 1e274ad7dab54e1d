"""Every corpus file exports to .ggb; the real GeoGebra puts its points where the kernel does.

Each file of ``tests/corpus_geometry`` is replayed at exact values in its domains and
written with :func:`graspcompass.export.to_ggb` (every operation has a GeoGebra
definition).  A few files that together use every operation are opened in GeoGebra
under Xvfb (``--regressionFile``, as ``tests/test_export.py`` does): each point GeoGebra
computes from the commands (intersections on the kernel's branch, rotations,
homotheties, the radical axis, tangents, free points on paths) is the kernel's point.
The file's parameters are GeoGebra sliders on which its given points depend, and each
claim GeoGebra's prover states is a ``Prove``/``ProveDetails`` pair.
``bench/bench_corpus_ggb.py`` opens all of them.
"""

from __future__ import annotations

import shutil

import pytest

import _corpus
from graspcompass.construction.language import parse, replay
from graspcompass.export.geogebra import read_ggb_xml, to_ggb

FILES = _corpus.files()


def _export(path):
    program = parse(path.read_text("utf-8"), path.name)
    values = _corpus.sample_values(program, path.name)
    c = replay(program, values)
    return c, to_ggb(c, program=program, values=values)


def test_a_files_parameters_are_sliders_and_its_claims_prove_commands():
    path = _corpus.CORPUS / "06_simson.gc"
    program = parse(path.read_text("utf-8"), path.name)
    xml = read_ggb_xml(_export(path)[1])
    for p in program.params:
        assert f'<element type="numeric" label="{p.name}">' in xml
    assert '<expression label="C" exp="((p), (q))" type="point"/>' in xml  # on the sliders
    assert xml.count('<command name="Prove">') == 2  # both collinear claims
    assert '<input a0="AreCollinear[D, E, F]"/>' in xml and "ProveDetails" in xml


def test_every_corpus_file_exports_to_ggb():
    for path in FILES:
        c, data = _export(path)
        xml = read_ggb_xml(data)
        for s in c.steps:
            assert f'label="{s.name}"' in xml, (path.name, s.name)


@pytest.mark.skipif(
    shutil.which("geogebra") is None or shutil.which("xvfb-run") is None,
    reason="GeoGebra or xvfb-run not installed (.ci/apt-packages.txt)",
)
@pytest.mark.parametrize(
    "path",
    sorted(
        {
            *_corpus.covering_files(),  # and a point on a
            _corpus.CORPUS / "41_radical_axis_tangents.gc",
        }
    ),
    ids=lambda p: p.stem,
)  # line GeoGebra defines by its equation
def test_geogebra_puts_the_points_where_the_kernel_does(path, tmp_path):
    c, data = _export(path)
    pts = _corpus.geogebra_points(data, tmp_path)
    for s in c.steps:
        if s.kind == "point":
            assert s.name in pts, s.name
            assert pts[s.name] == pytest.approx((float(s.obj.x), float(s.obj.y)), abs=2e-5), s.name


@pytest.mark.skipif(
    shutil.which("geogebra") is None or shutil.which("xvfb-run") is None,
    reason="GeoGebra or xvfb-run not installed (.ci/apt-packages.txt)",
)
@pytest.mark.parametrize("name", ["06_simson.gc", "07_pappus.gc", "01_circumcentre.gc"])
def test_geogebra_as_a_second_prover(name, tmp_path):
    """GeoGebra's ``Prove`` agrees with the checker on every claim both state: a PROVED
    claim is true for GeoGebra, a REFUTED one false.  Skipped where GeoGebra has no
    prover: Debian's GeoGebra 4.0.34 (2012) predates ``Prove`` (GeoGebra 4.2+) and logs
    ``Unknown command : Prove``; the .ggb still opens there, without the claims."""
    from graspcompass.proof.program_check import check_program

    path = _corpus.CORPUS / name
    program = parse(path.read_text("utf-8"), path.name)
    verdicts = _corpus.geogebra_verdicts(_export(path)[1], tmp_path)
    if verdicts is None:
        pytest.skip("this GeoGebra has no Prove command (4.0.34: 'Unknown command : Prove')")
    ours = {i: row.status.value for i, row in enumerate(check_program(program).claims, 1)}
    for i, true in verdicts.items():
        if ours[i] in ("PROVED", "REFUTED"):
            assert true == (ours[i] == "PROVED"), (name, i, true, ours[i])
