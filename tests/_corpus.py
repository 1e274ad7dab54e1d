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
    out["claims"] = [
        (e, row.result.status.value, row.result.counterexample)
        for e, row in zip(expected, report.claims)
    ]
    return out


def summary(records: list[dict]) -> dict:
    """Counts over the corpus: true claims PROVED, false ones REFUTED, errors, blocked."""
    true = [c for r in records for c in r["claims"] if c[0]]
    false = [c for r in records for c in r["claims"] if not c[0]]
    secs = sorted(r["seconds"] for r in records if not (r["error"] or "").startswith("BLOCKED"))
    return {
        "files": len(records),
        "blocked_files": sum(1 for r in records if (r["error"] or "").startswith("BLOCKED")),
        "internal_errors": sum(
            1 for r in records if r["error"] and not r["error"].startswith("BLOCKED")
        ),
        "true": len(true),
        "true_proved": sum(1 for c in true if c[1] == "PROVED"),
        "true_refuted": sum(1 for c in true if c[1] == "REFUTED"),
        "false": len(false),
        "false_refuted": sum(1 for c in false if c[1] == "REFUTED"),
        "false_proved": sum(1 for c in false if c[1] == "PROVED"),
        "median_s": secs[len(secs) // 2] if secs else 0.0,
    }


def sample_values(program, seed: str) -> dict:
    """Exact values of the parameters at which every step of ``program`` is made
    (random small fractions in the declared domains, tried until the replay succeeds)."""
    import random
    from fractions import Fraction

    from graspcompass.construction.language import replay
    from graspcompass.geometry import GeometryError

    rng = random.Random(seed)
    for _ in range(200):
        vals = {}
        for q in program.params:
            v = Fraction(rng.randint(1, 12), rng.choice((3, 4, 5)))
            if q.domain == "real":
                v *= rng.choice((-1, 1))
            if q.domain == "angle":
                v = min(v, Fraction(3))
            vals[q.name] = str(v)
        try:
            replay(program, vals)
        except (GeometryError, ValueError, ArithmeticError):
            continue
        return vals
    raise RuntimeError(f"{program.file}: no values found at which every step is made")


def geogebra_points(data: bytes, workdir: Path) -> dict[str, tuple[float, float]] | None:
    """Open a ``.ggb`` in the real GeoGebra under Xvfb (``--regressionFile``) and return
    every point's coordinates as its kernel computed them; None without GeoGebra."""
    import re
    import shutil
    import subprocess

    geogebra, xvfb = shutil.which("geogebra"), shutil.which("xvfb-run")
    if geogebra is None or xvfb is None:
        return None
    src, out = workdir / "file.ggb", workdir / "values.txt"
    src.write_bytes(data)
    subprocess.run(
        [xvfb, "-a", geogebra, "--showSplash=false", f"--regressionFile={out}", str(src)],
        check=False,
        timeout=240,
        capture_output=True,
        text=True,
        env={"HOME": str(workdir), "PATH": "/usr/bin:/bin"},
    )
    if not out.exists():
        raise RuntimeError("GeoGebra wrote no values")
    pts = {}
    for m in re.finditer(r"^Point (\S+) = (.*)$", out.read_text("utf-8"), re.M):
        nums = (m[2].split(" == ")[-1] if " == " in m[2] else m[2]).split()
        try:
            x, y, *z = (float(v) for v in nums)
        except ValueError:
            continue
        w = z[0] if z else 1.0
        pts[m[1]] = (x / w, y / w) if w else (float("nan"), float("nan"))
    return pts


def geogebra_verdicts(data: bytes, workdir: Path) -> dict[int, bool] | None:
    """GeoGebra's own ``Prove`` verdicts of a ``.ggb`` (claim number -> true/false), read
    from its ``--regressionFile``; None without GeoGebra, or with a GeoGebra that has no
    prover (4.0.34, Debian's, logs ``Unknown command : Prove`` and drops the claims)."""
    import re
    import shutil
    import subprocess

    geogebra, xvfb = shutil.which("geogebra"), shutil.which("xvfb-run")
    if geogebra is None or xvfb is None:
        return None
    src, out = workdir / "file.ggb", workdir / "values.txt"
    src.write_bytes(data)
    run = subprocess.run(
        [xvfb, "-a", geogebra, "--showSplash=false", f"--regressionFile={out}", str(src)],
        check=False,
        timeout=240,
        capture_output=True,
        text=True,
        env={"HOME": str(workdir), "PATH": "/usr/bin:/bin"},
    )
    if not out.exists() or "Unknown command : Prove" in run.stdout + run.stderr:
        return None
    found = {
        int(m[1]): m[2] == "true"
        for m in re.finditer(
            r"^\S+ claim(\d+) = (?:.* == )?(true|false)\s*$", out.read_text("utf-8"), re.M
        )
    }
    return found or None


def covering_files() -> list[Path]:
    """A few corpus files that together use every operation of the language (greedy)."""
    from graspcompass.construction.language import parse

    ops = {f: {s.op for s in parse(f.read_text("utf-8"), f.name).steps} for f in files()}
    need, out = set().union(*ops.values()), []
    while need:
        best = max(ops, key=lambda f: len(ops[f] & need))
        out.append(best)
        need -= ops[best]
    return sorted(out)
