"""Run the catalogue and write its report: a table, JSON records or a Markdown page."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..progress import Progress
from ._budget import TIMED_OUT, Budget
from .catalogue import CLAIMS, Claim, check, session
from .prove import ProofResult, Status

__all__ = ["ClaimReport", "exit_status", "run_catalogue", "to_json", "to_markdown", "to_table"]


@dataclass(frozen=True)
class ClaimReport:
    """A claim together with its result (plain data for writers)."""

    claim: Claim
    result: ProofResult

    def record(self) -> dict[str, Any]:
        """JSON-ready dict: id, ref, status, seconds, statement, method, ..."""
        c, r = self.claim, self.result
        rec: dict[str, Any] = {
            "id": c.id,
            "ref": c.ref,
            "status": r.status.value,
            "seconds": round(r.seconds, 4),
            "statement": c.statement,
            "method": r.method,
            "printed": c.printed,
            "hypotheses": list(r.hypotheses),
            "conditions": list(r.conditions),
            "implied": list(r.implied),
            "depends": [d.id for d in c.depends],
        }
        if r.certificate is not None:
            rec["certificate"] = r.certificate
        if r.counterexample is not None:
            rec["counterexample"] = r.counterexample
        if c.corrected_by:
            rec["corrected_by"] = c.corrected_by
        if c.note:
            rec["note"] = c.note
        if r.detail:
            rec["detail"] = r.detail
        return rec


def run_catalogue(
    claims: Sequence[Claim] = CLAIMS,
    quiet: bool = False,
    timeout: float | None = None,
    budget: Budget | None = None,
) -> list[ClaimReport]:
    """Check every claim, with a progress bar on a terminal unless ``quiet``.

    ``timeout`` (seconds, ``None``: no limit) bounds the whole run, or ``budget``
    shares one with the caller: the verdicts reached by then are kept, every
    later claim is UNDECIDED with the method
    :data:`~graspcompass.proof._budget.TIMED_OUT`.
    """
    out = []
    budget = budget if budget is not None else Budget(timeout)
    with session(), Progress(len(claims), "verify", quiet=quiet) as bar:
        for c in claims:
            out.append(
                ClaimReport(
                    c,
                    budget.run(
                        lambda c=c: check(c),
                        lambda: ProofResult(
                            Status.UNDECIDED,
                            TIMED_OUT,
                            0.0,
                            detail=f"--timeout {budget.seconds:g} s",
                        ),
                    ),
                )
            )
            bar.update(note=c.id)
    return out


def exit_status(reports: Sequence[ClaimReport]) -> int:
    """0 when nothing is UNDECIDED and every refuted claim has a proved correction, else 1."""
    by_id = {r.claim.id: r for r in reports}
    for r in reports:
        if r.result.status is Status.UNDECIDED:
            return 1
        if r.result.status is Status.REFUTED:
            fix = by_id.get(r.claim.corrected_by or "")
            if fix is None or not fix.result.proved:
                return 1
    return 0


def to_json(reports: Sequence[ClaimReport]) -> str:
    """The reports as a JSON list of records."""
    return json.dumps([r.record() for r in reports], indent=1, ensure_ascii=False, default=str)


def _assumes(r: ClaimReport) -> str:
    """Hypotheses, then extra non-degeneracy conditions, for one line of a report."""
    parts = list(r.result.hypotheses)
    if r.result.conditions:
        parts.append("extra: " + "; ".join(r.result.conditions))
    return "; ".join(parts) or "none"


def to_table(reports: Sequence[ClaimReport]) -> str:
    """A text table: id, reference, status, method, seconds."""
    rows = [
        (r.claim.id, r.claim.ref, r.result.status.value, r.result.method, f"{r.result.seconds:.2f}")
        for r in reports
    ]
    head = ("id", "paper", "status", "method", "s")
    w = [max(len(str(x[i])) for x in [head, *rows]) for i in range(4)]
    lines = ["  ".join(h.ljust(w[i]) if i < 4 else h for i, h in enumerate(head))]
    for row in rows:
        lines.append("  ".join(x.ljust(w[i]) if i < 4 else x for i, x in enumerate(row)))
    n = {s: sum(r.result.status is s for r in reports) for s in Status}
    lines.append(
        f"\n{n[Status.PROVED]} proved, {n[Status.REFUTED]} refuted, "
        f"{n[Status.UNDECIDED]} undecided; "
        f"{sum(r.result.seconds for r in reports):.1f} s in the checker"
    )
    for r in reports:
        if r.result.status is Status.REFUTED:
            cx = ", ".join(f"{k} = {v}" for k, v in (r.result.counterexample or {}).items())
            lines.append(f"  {r.claim.id}: REFUTED at {cx}; corrected by {r.claim.corrected_by}")
    lines.append("\nhypotheses (extra: non-degeneracy conditions not shown implied by them)")
    for r in reports:
        lines.append(f"  {r.claim.id}: {_assumes(r)}")
    return "\n".join(lines)


def to_markdown(reports: Sequence[ClaimReport]) -> str:
    """A Markdown page for the docs: the errata (the one section of them), a summary table
    of every claim (id, paper, status, method, seconds), then each claim's statement,
    hypotheses and conditions as a definition list.  Text is escaped and formulas are
    MathJax math (:mod:`graspcompass.proof._markdown`)."""
    from ._markdown import md_counterexample, md_items, md_text

    out = [
        "# Proof report",
        "",
        "Every claim of Ito, Tanaka and Sasaki (Robotica 30(5), 2012) checked by "
        "`graspcompass verify` for general symbolic parameters under the contact point "
        "conditions (1). PROVED means a symbolic proof (polynomial reduction modulo "
        "$\\sin^2 + \\cos^2 = 1$, or a sign witness); REFUTED comes with exact parameter "
        "values where the printed statement fails.",
        "",
        "## Errata: where the paper as printed is wrong",
        "",
    ]
    by_id = {r.claim.id: r for r in reports}
    for r in reports:
        if r.result.status is Status.REFUTED:
            fix = by_id.get(r.claim.corrected_by or "")
            out.append(
                f"- {md_text(r.claim.ref)}: {md_text(r.claim.statement)}. REFUTED, "
                f"counterexample {md_counterexample(r.result.counterexample)}. "
                f"{md_text(r.claim.note)}"
            )
            if fix is not None:
                out += [
                    "",
                    f"  Corrected (`{fix.claim.id}`, {fix.result.status.value}): "
                    f"{md_text(fix.claim.statement)}",
                    "",
                ]
    out += [
        "",
        "## All claims",
        "",
        "| id | paper | status | method | s |",
        "| --- | --- | --- | --- | ---: |",
    ]
    for r in reports:
        method = r.result.method if len(r.result.method) <= 40 else "see below"
        out.append(
            f"| `{r.claim.id}` | {md_text(r.claim.ref)} | "
            f"{r.result.status.value} | {md_text(method)} | "
            f"{r.result.seconds:.2f} |"
        )
    out += ["", "### Statements, hypotheses and conditions", ""]
    for r in reports:
        conds = [
            *md_items(r.result.conditions, "extra: "),
            *md_items(r.result.implied, "implied: "),
        ]
        out += [
            f"`{r.claim.id}` ({md_text(r.claim.ref)}), {r.result.status.value}",
            f": {md_text(r.claim.statement)}",
            ": hypotheses: " + ("; ".join(md_items(r.result.hypotheses)) or "none"),
            ": conditions: " + ("; ".join(conds) or "none"),
            *([": method: " + md_text(r.result.method)] if len(r.result.method) > 40 else []),
            "",
        ]
    return "\n".join(out) + "\n"
