"""The geometry-class corpus (issue 24): 48 classic constructions and their textbook claims.

Each claim of ``tests/corpus_geometry/*.gc`` carries its truth from geometry
(``# expect true|false``), written before the checker ran.  For every file:

* the checker raises nothing (no internal error discards a file) and the language reads it;
* a false claim is never PROVED and is REFUTED; a true claim is never REFUTED;
* every PROVED claim holds at random points where its objects exist (the evaluator);
* every counterexample is replayed by ``tests/_evaluator.py`` (no code shared with
  graspcompass): the objects exist there, the claim is false there and the file's
  inequality hypotheses (``hypothesis NAME: A > B``) hold there.

The rates (true claims PROVED, median time) are measured by ``bench/bench_corpus.py``.
"""

from __future__ import annotations

import random

import pytest

import _corpus
from _evaluator import evaluate, hypotheses_hold, params_of, random_point

FILES = _corpus.files()


def test_the_corpus_is_a_class_worth():
    expected = [e for f in FILES for e in _corpus.expectations(f.read_text("utf-8"))]
    wrong = [f for f in FILES if not all(_corpus.expectations(f.read_text("utf-8")))]
    assert len(FILES) >= 40 and len(wrong) >= 5 and len(expected) >= 100


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_corpus_file(path):
    record = _corpus.run(path)
    assert record["error"] is None, record["error"]
    text = path.read_text("utf-8")
    for i, (truth, status, cx) in enumerate(record["claims"]):
        if truth:
            assert status != "REFUTED", f"claim {i + 1} is true, refuted at {cx}"
            continue
        assert status == "REFUTED", f"claim {i + 1} is false, got {status}"
        if cx is not None:  # replayed independently: the claim is false there
            assert evaluate(text, cx)[i] is False, (i, cx)
            assert hypotheses_hold(text, cx), ("the counterexample breaks a hypothesis", cx)
    rng = random.Random(path.name)
    proved = [i for i, (_, status, _) in enumerate(record["claims"]) if status == "PROVED"]
    for _ in range(4):  # every PROVED claim holds wherever its objects exist
        pt = random_point(params_of(text), rng)
        while not hypotheses_hold(text, pt):  # a point of the file's hypotheses
            pt = random_point(params_of(text), rng)
        truth = evaluate(text, pt)
        assert all(truth[i] is not False for i in proved), (pt, truth)
