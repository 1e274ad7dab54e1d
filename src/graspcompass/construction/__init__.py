"""Construction protocol (replayable steps) and the paper's drawing recipe (§3.3)."""

from .describe import describe, step_record, to_records
from .envelope import Arc, Envelope, EnvelopeError, outer_envelope
from .protocol import INSTRUMENTS, OPS, Construction, Step, StepSpec, replay
from .recipe import diagram_specs, internal_force_diagram

__all__ = [
    "INSTRUMENTS",
    "OPS",
    "Arc",
    "Construction",
    "Envelope",
    "EnvelopeError",
    "Step",
    "StepSpec",
    "describe",
    "diagram_specs",
    "internal_force_diagram",
    "outer_envelope",
    "replay",
    "step_record",
    "to_records",
]
