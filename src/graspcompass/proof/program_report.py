"""The report of ``graspcompass check``: a text table, JSON and a Markdown page.

The JSON shape is stable, for other tools::

    {"file": ..., "against": "paper" | null, "status": 0 | 1 | 3, "seconds": ...,
     "targets": [{"name", "status", "hypotheses", "conditions", "implied",
                  "counterexample": {param: exact text} | null, "seconds", "line",
                  "method", "detail"}, ...],
     "claims": [...same keys...], "steps": [...same keys...]}

Examples
--------
>>> from graspcompass.construction.language import parse
>>> from graspcompass.proof.program_check import check_program
>>> r = check_program(parse("param a > 0\\nA = point (a, 0)\\nclaim sign a > 0\\n"))
>>> print(to_table(r).splitlines()[-1])  # doctest: +ELLIPSIS
1 proved, 0 refuted, 0 undecided (1 given); 0 targets, 1 claims, 1 steps; ... s
"""

from __future__ import annotations

import json
from typing import Any

from .program_check import CheckRow, ProgramReport
from .prove import Status

__all__ = ["to_json", "to_markdown", "to_table"]


def to_json(report: ProgramReport) -> str:
    """The report as one JSON object (see the module's docstring for its shape)."""
    doc: dict[str, Any] = {
        "file": report.file,
        "against": report.against,
        "status": report.exit_status,
        "seconds": round(report.seconds, 3),
        "targets": [r.record() for r in report.targets],
        "claims": [r.record() for r in report.claims],
        "steps": [r.record() for r in report.steps],
    }
    return json.dumps(doc, indent=1, ensure_ascii=False)


def _cx(row: CheckRow) -> str:
    if row.reason is not None:
        return "none: " + row.reason
    if row.counterexample == {}:
        return "false as the file stands (it has no parameters)"
    return ", ".join(f"{k} = {v}" for k, v in (row.counterexample or {}).items())


def _short(text: str, width: int = 60) -> str:
    return text if len(text) <= width else text[: width - 1] + "…"


def _extra(row: CheckRow, domains: str, common: tuple[str, ...] = ()) -> str:
    """What a row assumes beyond the parameters' domains and the file's inequality
    hypotheses (printed once above the table)."""
    r = row.result
    parts = [h for h in r.hypotheses if h != domains and h not in common]
    if r.conditions:
        parts.append("if " + "; ".join(r.conditions))
    return "; ".join(parts)


def _counts(report: ProgramReport) -> str:
    n = {s: sum(r.status is s for r in report.rows) for s in Status}
    return (
        f"{n[Status.PROVED]} proved, {n[Status.REFUTED]} refuted, "
        f"{n[Status.UNDECIDED]} undecided ({n[Status.GIVEN]} given); "
        f"{len(report.targets)} targets, {len(report.claims)} claims, "
        f"{len(report.steps)} steps"
    )


def to_table(report: ProgramReport, steps: bool = False) -> str:
    """A text table of the targets and claims (and the steps with ``steps=True``).

    Each row: kind, line, name (cut at 60 characters), status, seconds and what
    it assumes beyond the parameters' domains (printed once above the table):
    condition (1) where the claim says ``under condition1`` (targets always),
    and the non-degeneracy conditions that remain (``if ... ≠ 0``).  The
    counterexamples of refuted rows follow the table.
    """
    shown = [
        *report.targets,
        *report.claims,
        *(
            report.steps
            if steps
            else [r for r in report.steps if r.status not in (Status.PROVED, Status.GIVEN)]
        ),
    ]
    domains = next(
        (h for r in report.rows for h in r.result.hypotheses if h.startswith("domains")), ""
    )
    common = tuple(
        h
        for h in (report.rows[0].result.hypotheses if report.rows else ())
        if h.startswith("hypothesis ") and all(h in r.result.hypotheses for r in report.rows)
    )
    head = ("kind", "line", "name", "status", "s", "assumes")
    rows = [
        (
            r.kind,
            str(r.line),
            _short(r.name),
            r.status.value,
            f"{r.result.seconds:.2f}",
            _extra(r, domains, common),
        )
        for r in shown
    ]
    widths = [max(len(x[i]) for x in [head, *rows]) for i in range(5)]
    lines = [
        f"{report.file}: every row assumes the {'; '.join((domains, *common))}"
        if domains
        else f"{report.file}: no parameters (the file's numbers are exact)",
        "",
        "  ".join(h.ljust(widths[i]) if i < 5 else h for i, h in enumerate(head)),
    ]
    lines += [
        "  ".join(x.ljust(widths[i]) if i < 5 else x for i, x in enumerate(row)).rstrip()
        for row in rows
    ]
    refuted = [r for r in shown if r.status is Status.REFUTED and r.counterexample is not None]
    if refuted:
        lines.append("\ncounterexamples (points of the model; the file replayed exactly there)")
        lines += [f"  {_short(r.name)}: {_cx(r)}" for r in refuted]
    other = [r for r in shown if r.status is Status.REFUTED and r.counterexample is None]
    if other:
        lines.append(
            "\nrefuted without a counterexample (false or undefined at every point of the model)"
        )
        lines += [f"  {_short(r.name)}: {r.reason}" for r in other]
    lines.append(f"\n{_counts(report)}; {report.seconds:.1f} s")
    return "\n".join(lines)


def to_markdown(report: ProgramReport) -> str:
    """A Markdown page: the verdicts in a table, then each row's hypotheses, conditions and
    counterexample as a definition list; text escaped, formulas as MathJax math."""
    from ._markdown import md_counterexample, md_items, md_text

    out = [
        f"# Check of {md_text(report.file)}",
        "",
        f"{_counts(report)}; {report.seconds:.1f} s"
        + (", graded against the paper" if report.against else "")
        + ".",
        "",
        "PROVED: an exact argument for every admissible parameter (hypotheses and "
        "non-degeneracy conditions below); REFUTED: a point of the model where the file, "
        "replayed exactly, contradicts the statement.",
        "",
        "| kind | line | name | status | s |",
        "| --- | ---: | --- | --- | ---: |",
    ]
    for r in report.rows:
        out.append(
            f"| {md_text(r.kind)} | {r.line} | {md_text(r.name)} | {r.status.value} | "
            f"{r.result.seconds:.2f} |"
        )
    out += ["", "## Hypotheses, conditions and counterexamples", ""]
    for r in report.rows:
        cx = (
            md_text(_cx(r))
            if r.reason is not None or r.counterexample == {}
            else md_counterexample(r.counterexample)
        )
        out += [
            f"{md_text(r.name)} (line {r.line}), {r.status.value}",
            ": hypotheses: " + ("; ".join(md_items(r.result.hypotheses)) or "none"),
            ": conditions: " + ("; ".join(md_items(r.result.conditions)) or "none"),
        ]
        if cx:
            out.append(": counterexample: " + cx)
        out.append("")
    return "\n".join(out) + "\n"
