"""The rows of :func:`graspcompass.proof.program_check.check_program`'s report (plain data).

Private (issue 21: the checker under 600 lines); :class:`CheckRow` and
:class:`ProgramReport` are documented and pickled as ``graspcompass.proof.program_check``'s.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from .prove import ProofResult, Status

if TYPE_CHECKING:
    from ..construction.protocol import Construction

__all__ = ["CheckRow", "ProgramReport"]


@dataclass(frozen=True)
class CheckRow:
    """The verdict on one step, claim or target (plain data).

    Attributes
    ----------
    name : str
        The step's or target's name, or the claim as written.
    kind : str
        ``"step"``, ``"claim"`` or ``"target"``.
    line : int
        Line of the file (0 for the builder).
    result : ProofResult
        Status, method, hypotheses, conditions (extra non-degeneracy conditions),
        implied (conditions shown to follow), counterexample (exact text by
        parameter name, re-checked by exact replay), seconds.
    """

    name: str
    kind: str
    line: int
    result: ProofResult

    @property
    def status(self) -> Status:
        """The verdict."""
        return self.result.status

    @property
    def counterexample(self) -> dict[str, str] | None:
        """Parameter name -> exact value where the file contradicts the statement."""
        return self.result.counterexample

    @property
    def reason(self) -> str | None:
        """Why a REFUTED row has no counterexample: the exact reason (``None`` otherwise)."""
        if self.status is not Status.REFUTED or self.counterexample is not None:
            return None
        return self.result.detail or None

    def __post_init__(self) -> None:
        """REFUTED comes with a counterexample or a stated exact reason, never bare: a bare
        one is UNDECIDED (an internal guard; every REFUTED row above states one)."""
        r = self.result
        if r.status is Status.REFUTED and r.counterexample is None and not r.detail:
            object.__setattr__(
                self,
                "result",
                ProofResult(
                    Status.UNDECIDED,
                    "refuted without a counterexample or a stated reason: not reported as refuted",
                    r.seconds,
                    hypotheses=r.hypotheses,
                    conditions=r.conditions,
                    implied=r.implied,
                ),
            )

    def record(self) -> dict[str, Any]:
        """JSON-ready: name, status, hypotheses, conditions, counterexample, seconds, ..."""
        r = self.result
        return {
            "name": self.name,
            "status": r.status.value,
            "line": self.line,
            "hypotheses": list(r.hypotheses),
            "conditions": list(r.conditions),
            "implied": list(r.implied),
            "counterexample": r.counterexample,
            "seconds": round(r.seconds, 4),
            "method": r.method,
            "detail": r.detail,
            "reason": self.reason,
        }


@dataclass(frozen=True)
class ProgramReport:
    """Every verdict on one file: ``steps``, ``claims`` and ``targets`` (tuples of rows)."""

    file: str
    steps: tuple[CheckRow, ...]
    claims: tuple[CheckRow, ...]
    targets: tuple[CheckRow, ...] = ()
    against: str | None = None
    seconds: float = 0.0
    construction: Construction | None = field(default=None, compare=False, repr=False)

    @property
    def rows(self) -> tuple[CheckRow, ...]:
        """Steps, claims and targets in that order."""
        return self.steps + self.claims + self.targets

    @property
    def exit_status(self) -> int:
        """0 all proved (or given), 1 something refuted, 3 something undecided."""
        statuses = {r.status for r in self.rows}
        if Status.REFUTED in statuses:
            return 1
        return 3 if Status.UNDECIDED in statuses else 0


CheckRow.__module__ = ProgramReport.__module__ = "graspcompass.proof.program_check"
