"""JSON of the construction protocol, and loading it back (round trip).

Schema ``graspcompass.construction/1``
--------------------------------------
One JSON object (written out as data in :data:`DOCUMENT_SCHEMA`, a subset of
JSON Schema)::

    {
      "schema": "graspcompass.construction/1",
      "generator": "graspcompass 0.1.0",   # optional, free text
      "grasp": {
          "x1", "x2", "y", "phi1", "phi2":  <number>,
          "friction": {"1": "mu" | "xi", "2": "mu" | "xi"},
          "mu1", "mu2", "xi1", "xi2":       <number>,
          "title": str | null,
          "shape": null | ["circle", r] | ["rectangle", w, h]   # JSON numbers > 0
      },
      "skipped": [[name, reason], ...],     # steps left out (tangent circles)
      "steps": [ {                          # in protocol order
          "index": int, "name": str, "kind": "point"|"line"|"circle"|"length"|"envelope",
          "op": str,                        # graspcompass.construction.OPS key or "envelope"
          "instrument": "ruler"|"compass"|"perpendicular"|"mark",
          "inputs": [name, ...],            # names of earlier steps
          "params": [<number>, ...],        # exact values after the input objects
          "key": bool, "caption": str, "ref": str,   # ref: the paper's section / equation
          "conditions": ["expr != 0", ...], # non-degeneracy assumptions (symbolic grasps)
          "value": {...}                    # the exact object, see below
      }, ... ]
    }

A ``<number>`` is either a string, an exact sympy expression read back with
:func:`graspcompass.expr.parse_exact` (``"sqrt(3)/2"``, ``"pi/3"``; symbols of
:mod:`graspcompass.symbols` such as ``"mu1*cos(phi1)"`` for a symbolic grasp),
a JSON number for a float of the numeric path (a double, written with Python's
``repr``, so it reads back to the same float), or ``{"float": "p/q", "bits": n}``
for a float of ``n`` bits that a double cannot hold (its exact binary value:
``q`` is a power of two and ``p`` has at most ``n`` significant bits).
``friction`` tells which of μ and ξ defined the contact (the other is derived:
ξ = atan μ or μ = tan ξ).

``value`` is :func:`graspcompass.construction.describe.step_record`'s: a point
``{"x", "y", "float": [x, y]}``, a line ``{"point", "direction"}``, a circle
``{"center", "radius2", "radius"}``, a length ``{"exact", "float"}``, the
envelope ``{"arcs": [{"circle", "theta_start", "theta_end", ..., "start",
"end"}]}``; exact values are ``str(expr)`` of sympy, floats are for reading only.

Reading JSON files
------------------
A file is outside input: :func:`loads` trusts nothing in it and refuses, with a
:class:`JSONDocumentError` (an :class:`~graspcompass.errors.InputError`, so a
``ValueError``) whose one-line message names the place (a JSON path such as
``steps[3].params[1]``), what is wrong and the value (shortened).  In order:

1. **Size**: at most :data:`MAX_BYTES` (16 MiB) of text (:class:`JSONTooLargeError`).
2. **JSON**: strict JSON only: ``NaN``, ``Infinity``, numbers that overflow a
   double, integers of more than :data:`MAX_INT_DIGITS` digits, duplicate keys
   and nesting deeper than Python's JSON reader allows are refused.
3. **Schema** (:data:`DOCUMENT_SCHEMA`): every key, type and length, before
   anything is computed.  No unknown keys; at most :data:`MAX_STEPS` steps;
   strings at most :data:`MAX_TEXT` characters (titles :data:`MAX_TITLE`, names
   32), none with control characters or lone surrogates; ``bits`` of a number in
   1..:data:`MAX_FLOAT_BITS`; integers and JSON numbers of the grasp at most
   :data:`MAX_MAGNITUDE` in absolute value, and finite.
4. **The grasp**: its numbers are read by :func:`~graspcompass.expr.parse_exact`
   (never ``sympify`` or ``eval``; its own limits apply: 200 characters,
   bounded exponents and sizes), floats and symbols are not mixed, and the
   grasp must pass :class:`~graspcompass.Grasp`'s checks.  The exact numbers the
   construction computes with (x1, x2, y, μ1, μ2 and the sines and cosines of
   φ1, φ2) may hold at most :data:`MAX_NUMBER_GENERATORS` distinct square roots
   of rationals of at most :data:`MAX_RADICAND_BITS` bits (no nested or higher
   roots, no ``pi`` or ``atan`` in a length) and at most
   :data:`MAX_ANGLE_GENERATORS` of the ``sin``/``cos`` that the kernel keeps for
   angles such as 1 rad or 3π/5 (four typed angles: φ1, φ2, ξ1, ξ2).  Next to
   symbols at most 2 square roots and no such sin/cos, and at most
   :data:`MAX_GENERATORS` generators in all (the fully symbolic grasp has 9:
   x1, x2, y, μ1 or tan ξ1, μ2 or tan ξ2 and the sines and cosines of φ1, φ2).
   The derived friction value (ξ = atan μ or μ = tan ξ) must be the one the
   grasp gives.
5. **Consistency**: the construction is rebuilt from the grasp with the paper's
   recipe (:func:`~graspcompass.internal_force_diagram`) and every step of the
   file (a prefix of the recipe, as ``export --step`` writes) is compared with
   it, field by field: the first step that disagrees is named with its stored
   value and the value the grasp gives (:class:`InconsistentDocumentError`).
   The file's values are never computed with; what is returned is the rebuilt
   construction.  A document without a grasp (``"grasp": null``, which
   :func:`dumps` writes for a construction without one) cannot be checked and
   is refused.

Time: a document refused by steps 1-4 is refused in milliseconds, and one
refused at step 5 as soon as its first wrong step is rebuilt.  Accepting costs
what building the construction from the grasp and writing its records cost:
0.1-0.5 s for the paper's grasps, 0.3-1.5 s for random exact grasps at the
limits above on a loaded machine, under 0.2 s for float grasps (any ``bits``).
Symbolic grasps are the exception: their construction takes as long as
:func:`~graspcompass.internal_force_diagram` takes for them (seconds to
minutes for the fully symbolic grasp), which no limit on the file can shorten.

This module writes and reads documents (:func:`dumps`, :func:`loads`); the parts
are private modules, every name still importable from here: the limits and errors
(``_json_limits``), the schema and its checker (``_json_schema``), the bounded JSON
parser (``_json_parse``), the grasp record (``_json_grasp``) and the steps' records
and replay (``_json_steps``).
"""

from __future__ import annotations

import json as _json
from typing import Any

from sympy.polys.polyerrors import BasePolynomialError

from .._version import __version__
from ..boundary.errors import GraspCompassError
from ..construction.protocol import Construction
from . import _json_limits as _limits
from . import _json_schema as _schema
from ._json_grasp import (
    _PARAMS,  # noqa: F401
    _SYMBOLS,  # noqa: F401
    _check_generators,  # noqa: F401
    _check_grasp_limits,
    _check_magnitudes,  # noqa: F401
    _grasp,
    _grasp_record,
    _number,  # noqa: F401
    _read,  # noqa: F401
    _read_float,  # noqa: F401
)
from ._json_limits import (
    _MAX_NUMBER_GENERATORS_WITH_SYMBOLS,  # noqa: F401
    _MAX_SHOWN,  # noqa: F401
    InconsistentDocumentError,
    JSONDocumentError,
    JSONTooLargeError,
)
from ._json_parse import _constant, _float, _int, _Object, _pairs  # noqa: F401
from ._json_schema import (
    _FINITE,  # noqa: F401
    _FLOAT_READOUT,  # noqa: F401
    _GRASP,  # noqa: F401
    _JSON_TYPES,  # noqa: F401
    _JUNK,  # noqa: F401
    _NAME,  # noqa: F401
    _NUMBER,  # noqa: F401
    _POINT,  # noqa: F401
    _SIZE,  # noqa: F401
    _STEP,  # noqa: F401
    _check,
    _check_list,  # noqa: F401
    _check_number,  # noqa: F401
    _check_object,  # noqa: F401
    _check_text,  # noqa: F401
    _difference,  # noqa: F401
    _expected,  # noqa: F401
    _fail,  # noqa: F401
    _is_type,  # noqa: F401
    _join,  # noqa: F401
    _obj,  # noqa: F401
    _show,
    _text,  # noqa: F401
    _where,  # noqa: F401
)
from ._json_steps import _compare, _rebuild, _record  # noqa: F401

__all__ = [
    "DOCUMENT_SCHEMA",
    "MAX_ANGLE_GENERATORS",
    "MAX_BYTES",
    "MAX_FLOAT_BITS",
    "MAX_GENERATORS",
    "MAX_INT_DIGITS",
    "MAX_MAGNITUDE",
    "MAX_NUMBER_GENERATORS",
    "MAX_RADICAND_BITS",
    "MAX_STEPS",
    "MAX_TEXT",
    "MAX_TITLE",
    "SCHEMA",
    "VALUE_SCHEMAS",
    "InconsistentDocumentError",
    "JSONDocumentError",
    "JSONTooLargeError",
    "dumps",
    "from_document",
    "loads",
    "to_document",
]

#: The schema identifier written to and required in every document.
SCHEMA = _limits.SCHEMA
#: Most characters (or bytes) of a JSON text :func:`loads` reads.
MAX_BYTES = _limits.MAX_BYTES
#: Most steps in a document (the paper's recipe has at most 47).
MAX_STEPS = _limits.MAX_STEPS
#: Longest string in a document (exact values of symbolic grasps are the longest).
MAX_TEXT = _limits.MAX_TEXT
#: Longest title of a grasp.
MAX_TITLE = _limits.MAX_TITLE
#: Most digits of a JSON integer literal.
MAX_INT_DIGITS = _limits.MAX_INT_DIGITS
#: Largest absolute value of a JSON number (or integer) in the grasp.
MAX_MAGNITUDE = _limits.MAX_MAGNITUDE
#: Largest ``bits`` of a ``{"float": "p/q", "bits": n}`` number.
MAX_FLOAT_BITS = _limits.MAX_FLOAT_BITS
#: Most distinct square roots in an exact grasp (each doubles the number field's degree).
MAX_NUMBER_GENERATORS = _limits.MAX_NUMBER_GENERATORS
#: Most sines and cosines of angles that are no multiples of pi/12 (four typed angles).
MAX_ANGLE_GENERATORS = _limits.MAX_ANGLE_GENERATORS
#: Most generators (symbols, and sin/cos of symbols, plus the above) of a grasp.
MAX_GENERATORS = _limits.MAX_GENERATORS
#: Most bits of the numerator and of the denominator under a square root.
MAX_RADICAND_BITS = _limits.MAX_RADICAND_BITS
#: The ``value`` record of each step kind.
VALUE_SCHEMAS = _schema.VALUE_SCHEMAS
#: The whole document (see the module docstring); ``value`` follows :data:`VALUE_SCHEMAS`.
DOCUMENT_SCHEMA = _schema.DOCUMENT_SCHEMA


def to_document(construction: Construction) -> dict[str, Any]:
    """The JSON-ready document (schema :data:`SCHEMA`) of ``construction``.

    Raises
    ------
    JSONDocumentError
        :class:`JSONTooLargeError` (or another :class:`JSONDocumentError`) for a
        construction whose document :func:`loads` would refuse by its limits (see
        "Reading JSON files": a grasp with more square roots or larger numbers
        than the loader reads, a title too long, too many steps, a text too
        long), with the message :func:`loads` gives; checked on the grasp before
        any step is written.
    """
    g = construction.grasp
    grasp: dict[str, Any] | None = None
    if g is not None:
        grasp = _grasp_record(g)
        _check_grasp_limits(g, grasp)
    steps = [_record(s) for s in construction.steps]
    doc = {
        "schema": SCHEMA,
        "generator": f"graspcompass {__version__}",
        "grasp": grasp,
        "skipped": [list(x) for x in construction.skipped],
        "steps": steps,
    }
    _check(doc, DOCUMENT_SCHEMA, "")
    for i, rec in enumerate(steps):
        _check(rec["value"], VALUE_SCHEMAS[rec["kind"]], f"steps[{i}].value")
    return doc


def dumps(construction: Construction, indent: int | None = 1) -> str:
    """The construction as JSON text (schema ``graspcompass.construction/1``).

    Parameters
    ----------
    construction : Construction
        What to write; :func:`loads` reads it back when it is (a prefix of) the
        paper's recipe for its grasp, as :func:`~graspcompass.internal_force_diagram`
        and ``Construction.upto`` make it.
    indent : int or None, optional
        Indentation of the JSON text (``None``: one line).

    Returns
    -------
    str
        The JSON text.

    Raises
    ------
    JSONDocumentError
        For a construction :func:`loads` would refuse by its limits (a
        :class:`JSONTooLargeError`, with the loader's message): its grasp, its
        records (:func:`to_document`) or the length of the text (:data:`MAX_BYTES`).
        A construction without a grasp is written (``"grasp": null``), though
        :func:`loads` does not read it back.

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> c = internal_force_diagram(Grasp.preset("table1a"))
    >>> text = dumps(c)
    >>> loads(text)["V1"] == c["V1"]
    True
    """
    text = _json.dumps(to_document(construction), indent=indent, ensure_ascii=False)
    size = len(text.encode("utf-8"))  # a file is read as bytes: the stricter of the two limits
    if size > MAX_BYTES:
        raise JSONTooLargeError(f"the JSON text has {size} bytes, more than {MAX_BYTES}")
    return text


def from_document(doc: Any) -> Construction:
    """Rebuild the construction of a document (see "Reading JSON files" above).

    Parameters
    ----------
    doc : dict
        A document as :func:`to_document` makes it (any JSON-like value is checked).

    Returns
    -------
    Construction
        The construction rebuilt from the document's grasp, equal step for step
        to the document's.

    Raises
    ------
    JSONDocumentError
        For another schema, a record that does not follow the schema, a value
        beyond the limits (:class:`JSONTooLargeError`), or steps that are not
        those the grasp gives (:class:`InconsistentDocumentError`).
    """
    if not isinstance(doc, dict) or doc.get("schema") != SCHEMA:
        found = doc.get("schema") if isinstance(doc, dict) else type(doc).__name__
        raise JSONDocumentError(f"not a {SCHEMA} document (schema: {_show(found)})")
    _check(doc, DOCUMENT_SCHEMA, "")
    for i, rec in enumerate(doc["steps"]):
        _check(rec["value"], VALUE_SCHEMAS[rec["kind"]], f"steps[{i}].value")
    if doc["grasp"] is None:
        raise JSONDocumentError(
            "grasp: a document without a grasp cannot be checked against "
            "the paper's recipe, so it is not read"
        )
    g = _grasp(doc["grasp"])
    try:
        return _rebuild(doc, g)
    except GraspCompassError as exc:
        if isinstance(exc, JSONDocumentError):
            raise
        raise JSONDocumentError(f"steps: the grasp's construction fails: {exc}") from None
    except (
        ArithmeticError,
        TypeError,
        ValueError,
        NotImplementedError,
        RecursionError,
        BasePolynomialError,
    ) as exc:
        raise JSONDocumentError(
            f"steps: the exact kernel cannot build this grasp's "
            f"construction ({type(exc).__name__}: {str(exc)[:80]})"
        ) from None


def loads(text: str | bytes) -> Construction:
    """The construction of a JSON text written by :func:`dumps`, checked (see above).

    Parameters
    ----------
    text : str or bytes
        The JSON text (bytes are read as UTF-8).

    Returns
    -------
    Construction
        The construction rebuilt from the file's grasp.

    Raises
    ------
    JSONDocumentError
        If the text is not JSON, not of the schema, beyond a limit
        (:class:`JSONTooLargeError`) or inconsistent with its grasp
        (:class:`InconsistentDocumentError`); the message names the place.

    Examples
    --------
    >>> try:
    ...     loads('{"schema": "graspcompass.construction/1", "steps": NaN}')
    ... except JSONDocumentError as err:
    ...     print(err)
    not JSON: NaN is not a JSON number (only finite numbers are)
    """
    if isinstance(text, (bytes, bytearray)):
        if len(text) > MAX_BYTES:
            raise JSONTooLargeError(f"the JSON text has {len(text)} bytes, more than {MAX_BYTES}")
        try:
            text = bytes(text).decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            raise JSONDocumentError(f"not UTF-8 text: {exc}") from None
    if not isinstance(text, str):
        raise JSONDocumentError(f"expected a JSON text (str or bytes), got {type(text).__name__}")
    if len(text) > MAX_BYTES:
        raise JSONTooLargeError(f"the JSON text has {len(text)} characters, more than {MAX_BYTES}")
    try:
        doc = _json.loads(
            text,
            object_pairs_hook=_pairs,
            parse_constant=_constant,
            parse_float=_float,
            parse_int=_int,
        )
    except _json.JSONDecodeError as exc:
        raise JSONDocumentError(f"not JSON: {exc}") from None
    except RecursionError:
        raise JSONTooLargeError("not read: the JSON text is nested too deeply") from None
    return from_document(doc)
