"""The limits of the JSON files and the errors that refuse a file.

The values of the limits are set here and documented in
:mod:`graspcompass.export.json` ("Reading JSON files"), which re-exports them with
the errors; the errors are shown as ``graspcompass.export.json.*`` (their
``__module__``).  Private to :mod:`graspcompass.export.json`.
"""

from __future__ import annotations

from ..boundary.errors import InputError, InputTooLargeError

# documented in graspcompass.export.json, which binds them again with their descriptions
SCHEMA = "graspcompass.construction/1"
MAX_BYTES = 16 << 20
MAX_STEPS = 64
MAX_TEXT = 4_000_000
MAX_TITLE = 1000
MAX_INT_DIGITS = 30
MAX_MAGNITUDE = 1e15
MAX_FLOAT_BITS = 1024
MAX_NUMBER_GENERATORS = 3
MAX_ANGLE_GENERATORS = 8
MAX_GENERATORS = 14
MAX_RADICAND_BITS = 64
_MAX_NUMBER_GENERATORS_WITH_SYMBOLS = 2
_MAX_SHOWN = 60


class JSONDocumentError(InputError):
    """A JSON text or document that is not a valid ``graspcompass.construction/1`` file.

    The message names the place (``steps[3].params[1]``), what is wrong and the value.

    Examples
    --------
    >>> try:
    ...     loads('{"schema": "graspcompass.construction/1", "grasp": null, "skipped": [], '
    ...           '"steps": [1]}')
    ... except JSONDocumentError as err:
    ...     print(err)
    steps[0]: expected a step record (an object), got 1
    """


class JSONTooLargeError(JSONDocumentError, InputTooLargeError):
    """A JSON text beyond :data:`MAX_BYTES`, or a value beyond the documented limits."""


class InconsistentDocumentError(JSONDocumentError):
    """A document whose steps are not those its grasp gives (edited by hand, or tampered)."""


# documented and shown in tracebacks as graspcompass.export.json.*, where they belong
for _error in (JSONDocumentError, JSONTooLargeError, InconsistentDocumentError):
    _error.__module__ = "graspcompass.export.json"
del _error
