"""Construction protocol (replayable steps), the operation records, the construction
language and the paper's drawing recipe (§3.3).

``replay`` here is the protocol's (a list of :class:`StepSpec`); the language's
is :func:`graspcompass.construction.language.replay` (a :class:`Program`).
"""

from .describe import describe, step_record, to_records
from .envelope import Arc, Envelope, EnvelopeError, outer_envelope
from .language import (
    ConstructionBuilder,
    ConstructionSyntaxError,
    DegenerateStepError,
    Program,
    paper_program,
    paper_text,
    parse,
)
from .operations import OPERATIONS, ROLES, Operation
from .protocol import INSTRUMENTS, OPS, Construction, Step, StepSpec, replay
from .recipe import diagram_specs, internal_force_diagram

__all__ = [
    "INSTRUMENTS",
    "OPERATIONS",
    "OPS",
    "ROLES",
    "Arc",
    "Construction",
    "ConstructionBuilder",
    "ConstructionSyntaxError",
    "DegenerateStepError",
    "Envelope",
    "EnvelopeError",
    "Operation",
    "Program",
    "Step",
    "StepSpec",
    "describe",
    "diagram_specs",
    "internal_force_diagram",
    "outer_envelope",
    "paper_program",
    "paper_text",
    "parse",
    "replay",
    "step_record",
    "to_records",
]
