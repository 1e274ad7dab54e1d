"""Every file of the geometry-class corpus opened in the real GeoGebra under Xvfb.

For each file of ``tests/corpus_geometry``: replay at exact values in its domains, write
the .ggb, open it in GeoGebra (``--regressionFile``) and compare every point GeoGebra
computes with the kernel's.  Prints one line per file and the count of files whose
points all agree (to 2e-5).  Nothing is asserted (``tests/test_corpus_geogebra.py``
asserts it on the files that together use every operation).

Run:  PYTHONPATH=src python bench/bench_corpus_ggb.py
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
import _corpus
from graspcompass.construction.language import parse, replay
from graspcompass.export.geogebra import to_ggb


def main() -> None:
    good = 0
    for path in _corpus.files():
        program = parse(path.read_text("utf-8"), path.name)
        values = _corpus.sample_values(program, path.name)
        c = replay(program, values)
        with tempfile.TemporaryDirectory() as tmp:  # sliders for its parameters, Prove
            pts = _corpus.geogebra_points(to_ggb(c, program=program, values=values), Path(tmp))
        if pts is None:
            print("GeoGebra or xvfb-run is not installed")
            return
        bad = [
            s.name
            for s in c.steps
            if s.kind == "point"
            and (
                s.name not in pts
                or max(abs(pts[s.name][0] - float(s.obj.x)), abs(pts[s.name][1] - float(s.obj.y)))
                > 2e-5
            )
        ]
        good += not bad
        print(f"{path.name:34s} {'ok' if not bad else 'differs: ' + ', '.join(bad)}")
    print(f"\n{good}/{len(_corpus.files())} files: GeoGebra's points are the kernel's")


if __name__ == "__main__":
    main()
