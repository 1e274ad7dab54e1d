"""The geometry-class corpus (``tests/corpus_geometry/*.gc``, issue 24): files and verdicts.

Each claim line of a corpus file ends with ``# expect true`` or ``# expect false``: the
textbook's truth of the claim, written from geometry before the checker ran.  :func:`run`
checks one file with :func:`graspcompass.proof.program_check.check_program` under a small
time budget and returns one record per claim; any exception but a parse error of a
construction the language cannot yet express (``BLOCKED``) is an internal error.
"""

from __future__ import annotations

import re
import time
import traceback
from pathlib import Path

CORPUS = Path(__file__).parent / "corpus_geometry"
#: Seconds per file (the check's own ``timeout``: rows left are UNDECIDED).
BUDGET = 20.0
_EXPECT = re.compile(r"#\s*expect\s+(true|false)\s*$")


def files() -> list[Path]:
    """The corpus files, sorted."""
    return sorted(CORPUS.glob("*.gc"))


def expectations(text: str) -> list[bool]:
    """The textbook truth of each claim, in order."""
    out = []
    for raw in text.splitlines():
        if raw.lstrip().startswith("claim"):
            m = _EXPECT.search(raw)
            if m is None:
                raise ValueError(f"a corpus claim without '# expect true|false': {raw!r}")
            out.append(m.group(1) == "true")
    return out


def run(path: Path, budget: float = BUDGET) -> dict:
    """Check one file: ``{"file", "seconds", "error", "claims": [(expected, status,
    counterexample), ...]}``; ``error`` is ``"BLOCKED: ..."`` for a file the language
    cannot read, a traceback for an internal error, else None."""
    from graspcompass.construction.language import parse
    from graspcompass.construction.program import ConstructionSyntaxError
    from graspcompass.proof.program_check import check_program

    text = path.read_text("utf-8")
    expected = expectations(text)
    t0 = time.perf_counter()
    out = {"file": path.name, "error": None, "claims": [], "seconds": 0.0}
    try:
        program = parse(text, path.name)
    except ConstructionSyntaxError as exc:
        out["error"] = f"BLOCKED: {exc}"
        out["claims"] = [(e, "BLOCKED", None) for e in expected]
        return out
    try:
        report = check_program(program, timeout=budget)
    except Exception:
        out["error"] = traceback.format_exc(limit=4)
        out["claims"] = [(e, "ERROR", None) for e in expected]
        out["seconds"] = time.perf_counter() - t0
        return out
    out["seconds"] = time.perf_counter() - t0
    out["claims"] = [(e, row.result.status.value, row.result.counterexample)
                     for e, row in zip(expected, report.claims)]
    return out


def summary(records: list[dict]) -> dict:
    """Counts over the corpus: true claims PROVED, false ones REFUTED, errors, blocked."""
    true = [c for r in records for c in r["claims"] if c[0]]
    false = [c for r in records for c in r["claims"] if not c[0]]
    secs = sorted(r["seconds"] for r in records if not (r["error"] or "").startswith("BLOCKED"))
    return {
        "files": len(records),
        "blocked_files": sum(1 for r in records if (r["error"] or "").startswith("BLOCKED")),
        "internal_errors": sum(1 for r in records if r["error"] and not
                               r["error"].startswith("BLOCKED")),
        "true": len(true), "true_proved": sum(1 for c in true if c[1] == "PROVED"),
        "true_refuted": sum(1 for c in true if c[1] == "REFUTED"),
        "false": len(false), "false_refuted": sum(1 for c in false if c[1] == "REFUTED"),
        "false_proved": sum(1 for c in false if c[1] == "PROVED"),
        "median_s": secs[len(secs) // 2] if secs else 0.0,
    }
