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

1. **Size**: at most :data:`MAX_BYTES` (1 MiB) of text (:class:`JSONTooLargeError`).
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
   φ1, φ2) may hold at most :data:`MAX_NUMBER_GENERATORS` distinct irrational
   numbers: square roots of rationals of at most :data:`MAX_RADICAND_BITS` bits
   (no nested or higher roots, no ``pi`` or ``atan`` in a length), or the
   ``sin``/``cos`` that the kernel keeps for an angle such as 1 rad or 3π/5,
   which then go with rational numbers only.  Next to symbols at most 2 square
   roots, and at most :data:`MAX_GENERATORS` generators in all (the fully
   symbolic grasp has 9: x1, x2, y, μ1 or tan ξ1, μ2 or tan ξ2 and the sines
   and cosines of φ1, φ2).
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
"""

from __future__ import annotations

import json as _json
import math
import re
from typing import Any

import sympy as sp
from sympy.polys.polyerrors import BasePolynomialError

from .. import __version__, symbols
from ..construction.describe import step_record
from ..construction.envelope import outer_envelope
from ..construction.protocol import INSTRUMENTS, OPS, Construction, Step, run_step
from ..construction.recipe import diagram_specs
from ..errors import GraspCompassError, InputError, InputTooLargeError
from ..expr import parse_exact
from ..geometry import GeometryError
from ..grasp import Grasp

__all__ = ["DOCUMENT_SCHEMA", "MAX_BYTES", "MAX_FLOAT_BITS", "MAX_GENERATORS", "MAX_INT_DIGITS",
           "MAX_MAGNITUDE", "MAX_NUMBER_GENERATORS", "MAX_RADICAND_BITS", "MAX_STEPS",
           "MAX_TEXT", "MAX_TITLE", "SCHEMA", "VALUE_SCHEMAS", "InconsistentDocumentError",
           "JSONDocumentError", "JSONTooLargeError", "dumps", "from_document", "loads",
           "to_document"]

#: The schema identifier written to and required in every document.
SCHEMA = "graspcompass.construction/1"

#: Most characters (or bytes) of a JSON text :func:`loads` reads.
MAX_BYTES = 1 << 20
#: Most steps in a document (the paper's recipe has at most 47).
MAX_STEPS = 64
#: Longest string in a document (exact values of symbolic grasps are the longest).
MAX_TEXT = 100_000
#: Longest title of a grasp.
MAX_TITLE = 1000
#: Most digits of a JSON integer literal.
MAX_INT_DIGITS = 30
#: Largest absolute value of a JSON number (or integer) in the grasp.
MAX_MAGNITUDE = 1e15
#: Largest ``bits`` of a ``{"float": "p/q", "bits": n}`` number.
MAX_FLOAT_BITS = 1024
#: Most distinct irrational numbers (square roots, sin/cos atoms) in an exact grasp.
MAX_NUMBER_GENERATORS = 3
#: Most generators (symbols, and sin/cos of symbols, plus the above) of a grasp.
MAX_GENERATORS = 9
#: Most bits of the numerator and of the denominator under a square root.
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


# ---------------------------------------------------------------------------
# the schema, as data (a subset of JSON Schema; "description" is what the
# error message says was expected)
# ---------------------------------------------------------------------------
def _obj(props: dict[str, Any], description: str, optional: tuple[str, ...] = ()) -> dict:
    return {"type": "object", "properties": props, "additionalProperties": False,
            "required": [k for k in props if k not in optional], "description": description}


def _text(max_length: int = MAX_TEXT, **extra: Any) -> dict[str, Any]:
    return {"type": "string", "maxLength": max_length, **extra}


_NAME = _text(32, pattern=r"[A-Za-z0-9_-]+", description="a step name (letters, digits, _ -)")
_FLOAT_READOUT = {"type": ["number", "null"], "description": "a JSON number or null"}
_POINT = _obj({"x": _text(), "y": _text(),
               "float": {"type": "array", "prefixItems": [_FLOAT_READOUT, _FLOAT_READOUT],
                         "minItems": 2, "maxItems": 2, "description": "a pair [x, y]"}},
              "a point record {x, y, float}")
#: The ``value`` record of each step kind.
VALUE_SCHEMAS: dict[str, dict[str, Any]] = {
    "point": _POINT,
    "line": _obj({"point": _POINT, "direction": _POINT}, "a line record {point, direction}"),
    "circle": _obj({"center": _POINT, "radius2": _text(), "radius": _FLOAT_READOUT},
                   "a circle record {center, radius2, radius}"),
    "length": _obj({"exact": _text(), "float": _FLOAT_READOUT}, "a length record {exact, float}"),
    "envelope": _obj({"arcs": {"type": "array", "maxItems": 16, "description": "a list of arcs",
                               "items": _obj({
                                   "circle": {"type": "integer", "minimum": 0, "maximum": 4},
                                   "theta_start": _text(), "theta_end": _text(),
                                   "theta_start_deg": _FLOAT_READOUT,
                                   "theta_end_deg": _FLOAT_READOUT,
                                   "start": _POINT, "end": _POINT}, "an arc record")}},
                     "an envelope record {arcs}"),
}
_FINITE = {"type": "number", "minimum": -MAX_MAGNITUDE, "maximum": MAX_MAGNITUDE}
_NUMBER = {"anyOf": [
    _text(1000),
    _FINITE,
    _obj({"float": _text(1000, pattern=r"-?[0-9]+(/[0-9]+)?", description="a fraction 'p/q'"),
          "bits": {"type": "integer", "minimum": 1, "maximum": MAX_FLOAT_BITS}},
         'a float record {"float": "p/q", "bits": n}'),
], "description": 'a number (exact text, a JSON number or {"float": "p/q", "bits": n})'}
_SIZE = {"type": "number", "exclusiveMinimum": 0, "maximum": MAX_MAGNITUDE,
         "description": "a positive JSON number"}
_GRASP = _obj({
    **{k: _NUMBER for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")},
    "friction": _obj({i: {"enum": ["mu", "xi"]} for i in ("1", "2")},
                     'the friction record {"1": "mu" or "xi", "2": ...}'),
    "title": {"anyOf": [_text(MAX_TITLE), {"type": "null"}], "description": "a text or null"},
    "shape": {"anyOf": [
        {"type": "null"},
        {"type": "array", "prefixItems": [{"const": "circle"}, _SIZE], "minItems": 2,
         "maxItems": 2},
        {"type": "array", "prefixItems": [{"const": "rectangle"}, _SIZE, _SIZE], "minItems": 3,
         "maxItems": 3},
    ], "description": 'null, ["circle", r] or ["rectangle", w, h]'},
}, "the grasp record (an object)")
_STEP = _obj({
    "index": {"type": "integer", "minimum": 0, "maximum": MAX_STEPS},
    "name": _NAME,
    "kind": {"enum": list(VALUE_SCHEMAS)},
    "op": {"enum": [*OPS, "envelope"], "description": "a known operation",
           "x-error": "unknown operation"},
    "instrument": {"enum": list(INSTRUMENTS)},
    "inputs": {"type": "array", "items": _NAME, "maxItems": 16},
    "params": {"type": "array", "items": _NUMBER, "maxItems": 8},
    "key": {"type": "boolean"},
    "caption": _text(500),
    "ref": _text(200),
    "conditions": {"type": "array", "items": _text(), "maxItems": 64},
    "value": {"type": "object", "description": "a value record (an object)"},
}, "a step record (an object)")
#: The whole document (see the module docstring); ``value`` follows :data:`VALUE_SCHEMAS`.
DOCUMENT_SCHEMA: dict[str, Any] = _obj({
    "schema": {"const": SCHEMA},
    "generator": _text(200),
    "grasp": {"anyOf": [_GRASP, {"type": "null"}],
              "description": "the grasp record (an object) or null"},
    "skipped": {"type": "array", "maxItems": 6, "items": {
        "type": "array", "prefixItems": [_NAME, _text(1000)], "minItems": 2, "maxItems": 2,
        "description": "a pair [name, reason]"}},
    "steps": {"type": "array", "items": _STEP, "maxItems": MAX_STEPS},
}, "a JSON object", optional=("generator",))

_SYMBOLS = {str(s): s for s in (symbols.x1, symbols.x2, symbols.y, symbols.phi1, symbols.phi2,
                                symbols.xi1, symbols.xi2, symbols.mu1, symbols.mu2,
                                symbols.theta, symbols.F_e)}
_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")
_JUNK = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f\ud800-\udfff\ufffe\uffff]")
_JSON_TYPES = {"string": str, "array": list, "object": dict, "boolean": bool,
               "null": type(None)}


# ---------------------------------------------------------------------------
# the validator of that subset
# ---------------------------------------------------------------------------
def _show(v: Any) -> str:
    try:
        text = repr(v)
    except (ValueError, RecursionError):  # an int of more than 4300 digits, say
        text = f"<{type(v).__name__}>"
    return text if len(text) <= _MAX_SHOWN else text[: _MAX_SHOWN - 5] + "…" + text[-4:]


def _join(path: str, key: str) -> str:
    """``path.key``, or ``path['key']`` for a key that is not a plain word."""
    if re.fullmatch(r"[A-Za-z0-9_]{1,40}", key):
        return f"{path}.{key}" if path else key
    return f"{path}[{_show(key)}]"


def _where(path: str) -> str:
    return path or "the document"


def _fail(path: str, what: str, v: Any, cls: type[JSONDocumentError] = JSONDocumentError
          ) -> JSONDocumentError:
    return cls(f"{_where(path)}: {what}, got {_show(v)}")


def _is_type(v: Any, t: str) -> bool:
    if t == "integer":
        return isinstance(v, int) and not isinstance(v, bool)
    if t == "number":
        return isinstance(v, (int, float)) and not isinstance(v, bool)
    return isinstance(v, _JSON_TYPES[t])


def _expected(schema: dict[str, Any]) -> str:
    if "description" in schema:
        return schema["description"]
    if "const" in schema:
        return repr(schema["const"])
    if "enum" in schema:
        return "one of " + ", ".join(map(repr, schema["enum"]))
    types = schema.get("type", "a value")
    types = types if isinstance(types, list) else [types]
    words = {"string": "a text", "integer": "an integer", "number": "a JSON number",
             "array": "a list", "object": "an object", "boolean": "true or false",
             "null": "null"}
    return " or ".join(words.get(t, t) for t in types)


def _check(v: Any, schema: dict[str, Any], path: str) -> None:
    """Refuse ``v`` at ``path`` unless it follows ``schema`` (never deeper than the schema)."""
    if "anyOf" in schema:
        options = schema["anyOf"]
        for option in options:
            try:
                _check(v, option, path)
                return
            except JSONDocumentError:
                pass
        # one alternative of the value's own type: its error is the more precise one
        same = [o for o in options if "type" in o and any(
            _is_type(v, t) for t in (o["type"] if isinstance(o["type"], list) else [o["type"]]))]
        if len(same) == 1:
            _check(v, same[0], path)
        raise _fail(path, f"expected {_expected(schema)}", v)
    if "const" in schema and (type(v) is not type(schema["const"]) or v != schema["const"]):
        raise _fail(path, f"expected {_expected(schema)}", v)
    if "enum" in schema and not (isinstance(v, str) and v in schema["enum"]):
        raise _fail(path, schema.get("x-error") or f"expected {_expected(schema)}", v)
    types = schema.get("type")
    if types is not None:
        types = types if isinstance(types, list) else [types]
        if not any(_is_type(v, t) for t in types):
            raise _fail(path, f"expected {_expected(schema)}", v)
    if isinstance(v, str):
        _check_text(v, schema, path)
    elif isinstance(v, (int, float)) and not isinstance(v, bool):
        _check_number(v, schema, path)
    elif isinstance(v, list):
        _check_list(v, schema, path)
    elif isinstance(v, dict):
        _check_object(v, schema, path)


def _check_text(v: str, schema: dict[str, Any], path: str) -> None:
    limit = schema.get("maxLength", MAX_TEXT)
    if len(v) > limit:
        raise _fail(path, f"a text of {len(v)} characters is longer than {limit}", v,
                    JSONTooLargeError)
    junk = _JUNK.search(v)
    if junk:
        raise _fail(path, f"control character or lone surrogate {junk.group()!r} in a text", v)
    if "pattern" in schema and not re.fullmatch(schema["pattern"], v):
        raise _fail(path, f"expected {_expected(schema)}", v)


def _check_number(v: float, schema: dict[str, Any], path: str) -> None:
    if isinstance(v, float) and not math.isfinite(v):
        raise _fail(path, "expected a finite number", v)
    low, high = schema.get("minimum"), schema.get("maximum")
    if high is not None and v > high or low is not None and v < low:  # noqa: RUF021
        big = high is not None and abs(v) > high
        span = f"at least {low:g}" if high is None else f"at most {high:g}"
        span = f"from {low:g} to {high:g}" if None not in (low, high) else span
        kind = "an integer" if isinstance(v, int) else "a number"
        raise _fail(path, f"expected {kind} {span}", v,
                    JSONTooLargeError if big else JSONDocumentError)
    if "exclusiveMinimum" in schema and not v > schema["exclusiveMinimum"]:
        raise _fail(path, f"expected a number > {schema['exclusiveMinimum']}", v)


def _check_list(v: list, schema: dict[str, Any], path: str) -> None:
    if len(v) > schema.get("maxItems", MAX_STEPS):
        raise _fail(path, f"a list of {len(v)} items is longer than {schema.get('maxItems')}",
                    v, JSONTooLargeError)
    if len(v) < schema.get("minItems", 0):
        raise _fail(path, f"expected {_expected(schema)}", v)
    prefix = schema.get("prefixItems", [])
    for i, item in enumerate(v):
        sub = prefix[i] if i < len(prefix) else schema.get("items", {})
        _check(item, sub, f"{path}[{i}]")


def _check_object(v: dict, schema: dict[str, Any], path: str) -> None:
    duplicate = getattr(v, "duplicate", None)
    if duplicate is not None:
        raise _fail(path, f"the key {duplicate!r} appears twice", v)
    props = schema.get("properties", {})
    for key in v:
        if not isinstance(key, str):
            raise _fail(path, "keys must be texts", key)
        if schema.get("additionalProperties", True) is False and key not in props:
            raise _fail(_join(path, key),
                        f"unknown key (expected {', '.join(props)})", key)
    for key in schema.get("required", []):
        if key not in v:
            raise JSONDocumentError(f"{_where(path)}: the key {key!r} is missing from "
                                    f"{_expected(schema)} (it has {_show(sorted(v))})")
    for key, sub in props.items():
        if key in v:
            _check(v[key], sub, _join(path, key))


# ---------------------------------------------------------------------------
# numbers
# ---------------------------------------------------------------------------
def _number(v: Any) -> str | float | dict[str, Any]:
    v = sp.sympify(v)  # internal: a grasp's value or a step's parameter (sympy, or an int)
    if v.atoms(sp.Float):
        if not v.is_Float:
            v = v.evalf(17)
        if v.free_symbols or not v.is_Float:
            raise ValueError(f"cannot store {v} exactly: it mixes floats and symbols")
        if v._prec == 53:
            return float(v)
        return {"float": str(sp.Rational(v)), "bits": int(v._prec)}  # exact binary value
    return str(v)


def _read_float(v: dict[str, Any], where: str) -> sp.Float:
    p, _, q = v["float"].partition("/")
    num, den = int(p), int(q or 1)
    bits = v["bits"]
    if den == 0 or den & (den - 1):
        raise _fail(f"{where}.float", "expected the exact binary value of a float "
                    "(a denominator that is a power of 2)", v["float"])
    odd = abs(num) >> ((abs(num) & -abs(num)).bit_length() - 1) if num else 0
    if odd.bit_length() > bits:
        raise _fail(f"{where}.float", f"this value needs {odd.bit_length()} bits, not {bits}",
                    v["float"])
    value = sp.Rational(num, den)
    if value != 0 and abs(value) > MAX_MAGNITUDE:
        raise _fail(f"{where}.float", f"expected a number at most {MAX_MAGNITUDE:g}",
                    v["float"], JSONTooLargeError)
    return sp.Float(value, precision=bits)


def _read(v: Any, where: str) -> sp.Expr:
    """A validated ``<number>`` as a sympy value (text through the safe parser only)."""
    if isinstance(v, dict):
        return _read_float(v, where)
    if isinstance(v, float):
        return sp.Float(v)
    if isinstance(v, int):
        return sp.Integer(v)
    try:
        return parse_exact(v, symbols=_SYMBOLS)
    except InputError as exc:
        raise JSONDocumentError(f"{where}: {exc}") from None


# ---------------------------------------------------------------------------
# writing
# ---------------------------------------------------------------------------
def _grasp_record(g: Grasp) -> dict[str, Any]:
    p = g.params
    friction = {str(i): ("mu" if sp.atan(p[f"mu{i}"]) == p[f"xi{i}"] else "xi") for i in (1, 2)}
    rec: dict[str, Any] = {k: _number(p[k]) for k in _PARAMS}
    rec["friction"] = friction
    rec["title"] = g.title
    rec["shape"] = list(g.shape) if g.shape else None
    return rec


def _record(step: Step) -> dict[str, Any]:
    rec = step_record(step)
    rec["params"] = [_number(p) for p in step.params]
    return rec


def _check_grasp_limits(g: Grasp, rec: dict[str, Any]) -> None:
    """Refuse, as :func:`loads` would, a grasp beyond the loader's limits.

    The same checks, in the same order and with the same messages, as step 3
    (the grasp record's schema: title length, number texts, ``bits``, magnitudes)
    and step 4 (sizes, square roots, generators) of "Reading JSON files".
    """
    _check(rec, _GRASP, "grasp")
    _check_magnitudes({k: g.params[k] for k in _PARAMS}, rec)
    _check_generators(g)


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
    grasp = None if g is None else _grasp_record(g)
    if g is not None:
        _check_grasp_limits(g, grasp)
    doc = {"schema": SCHEMA, "generator": f"graspcompass {__version__}", "grasp": grasp,
           "skipped": [list(x) for x in construction.skipped],
           "steps": [_record(s) for s in construction.steps]}
    _check(doc, DOCUMENT_SCHEMA, "")
    for i, rec in enumerate(doc["steps"]):
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


# ---------------------------------------------------------------------------
# reading
# ---------------------------------------------------------------------------
def _grasp(rec: dict[str, Any]) -> Grasp:
    vals = {k: _read(rec[k], f"grasp.{k}") for k in _PARAMS}
    floats = [k for k, v in vals.items() if v.atoms(sp.Float)]
    syms = [k for k, v in vals.items() if v.free_symbols]
    if floats and syms:
        raise JSONDocumentError(f"grasp: floats ({', '.join(floats)}) and symbols "
                                f"({', '.join(syms)}) cannot be mixed in one grasp")
    _check_magnitudes(vals, rec)
    fr = rec["friction"]
    kw = {f"{fr[str(i)]}{i}": vals[f"{fr[str(i)]}{i}"] for i in (1, 2)}
    shape = tuple(rec["shape"]) if rec["shape"] else None
    try:
        g = Grasp(vals["x1"], vals["x2"], vals["y"], vals["phi1"], vals["phi2"], **kw,
                  shape=shape, title=rec["title"])
    except GraspCompassError as exc:
        raise JSONDocumentError(f"grasp: {exc}") from None
    except (ArithmeticError, TypeError, ValueError, NotImplementedError, RecursionError,
            BasePolynomialError) as exc:
        raise JSONDocumentError(f"grasp: the exact kernel cannot use these values "
                                f"({type(exc).__name__}: {str(exc)[:80]})") from None
    _check_generators(g)
    again = _grasp_record(g)
    for k in _PARAMS:
        if _difference(rec[k], again[k], k) is None:
            continue
        if _read(rec[k], f"grasp.{k}") == g.params[k]:  # the same value, written otherwise
            raise _fail(f"grasp.{k}", f"expected {_show(again[k])}, the way dumps writes this "
                        "value", rec[k], InconsistentDocumentError)
        src = f"{fr[k[-1]]}{k[-1]}"
        raise _fail(f"grasp.{k}", f"the grasp gives {_show(again[k])} from {src} = "
                    f"{_show(again[src])}", rec[k], InconsistentDocumentError)
    if again["friction"] != fr:
        raise _fail("grasp.friction", f"the grasp is written {again['friction']}", fr,
                    InconsistentDocumentError)
    return g


def _check_magnitudes(vals: dict[str, sp.Expr], rec: dict[str, Any]) -> None:
    """Refuse a grasp value of size above :data:`MAX_MAGNITUDE` (``rec`` is shown)."""
    for k, v in vals.items():
        size = sp.N(abs(v), 15) if not v.free_symbols else sp.S.Zero
        if not (size.is_Number and size <= MAX_MAGNITUDE):
            raise _fail(f"grasp.{k}", f"expected a number at most {MAX_MAGNITUDE:g}", rec[k],
                        JSONTooLargeError)


def _check_generators(g: Grasp) -> None:
    """Bound the number of irrationals and symbols the exact construction works with."""
    numbers: set[sp.Expr] = set()
    symbolic: set[sp.Expr] = set()
    for name, v in (("x1", g.x1), ("x2", g.x2), ("y", g.y), ("mu1", g.mu1), ("mu2", g.mu2),
                    ("sin(phi1)", g.s1), ("cos(phi1)", g.c1), ("sin(phi2)", g.s2),
                    ("cos(phi2)", g.c2)):
        if v.atoms(sp.Float):
            continue  # the numeric path: evaluated to floats at once
        walk = sp.preorder_traversal(v)
        for atom in walk:
            if isinstance(atom, sp.Symbol):
                symbolic.add(atom)
            elif isinstance(atom, (sp.Function, sp.NumberSymbol)):
                walk.skip()
                if atom.free_symbols:
                    symbolic.add(atom)
                elif isinstance(atom, (sp.sin, sp.cos)):
                    numbers.add(atom)
                else:
                    raise JSONDocumentError(
                        f"grasp: {name} = {_show(str(v))} uses {str(atom)[:_MAX_SHOWN]}: lengths "
                        "and friction coefficients of exact grasps are rational numbers or square "
                        "roots of them (give floats for the numeric path)")
            elif isinstance(atom, sp.Pow) and not atom.exp.is_Integer:
                walk.skip()
                if atom.free_symbols:
                    symbolic.add(atom)
                    continue
                base = atom.base
                if atom.exp not in (sp.S.Half, -sp.S.Half) or not base.is_Rational:
                    raise JSONDocumentError(
                        f"grasp: {name} = {_show(str(v))} uses {atom}: only square roots of "
                        "rational numbers are supported in exact grasps")
                if max(abs(base.p).bit_length(), base.q.bit_length()) > MAX_RADICAND_BITS:
                    raise JSONTooLargeError(
                        f"grasp: {name} uses {_show(str(atom))}, a square root of a number of "
                        f"more than {MAX_RADICAND_BITS} bits")
                numbers.add(sp.sqrt(base))
    trig = {n for n in numbers if isinstance(n, (sp.sin, sp.cos))}
    shown = _show(", ".join(sorted(str(n) for n in numbers)))
    limit = _MAX_NUMBER_GENERATORS_WITH_SYMBOLS if symbolic else MAX_NUMBER_GENERATORS
    if len(numbers) > limit:
        raise JSONTooLargeError(
            f"grasp: its values use {len(numbers)} distinct irrational numbers ({shown}); at "
            f"most {limit} are allowed" + (" next to symbols" if symbolic else ""))
    if trig and (symbolic or numbers - trig):
        raise JSONTooLargeError(
            f"grasp: its values use sin/cos of an angle that is no multiple of pi/12 next to "
            f"{'symbols' if symbolic else 'other irrational numbers'} ({shown}); this is not "
            "allowed (it could take minutes to construct)")
    if len(numbers) + len(symbolic) > MAX_GENERATORS:
        shown = ", ".join(sorted(str(n) for n in numbers | symbolic))
        raise JSONTooLargeError(f"grasp: its values use {len(numbers) + len(symbolic)} "
                                f"generators ({_show(shown)}); at most {MAX_GENERATORS} "
                                "are allowed")


def _difference(stored: Any, given: Any, path: str) -> tuple[str, Any, Any] | None:
    """The first place where ``stored`` and ``given`` differ (JSON values), or None."""
    if isinstance(stored, dict) and isinstance(given, dict):
        for key in list(given) + [k for k in stored if k not in given]:
            if key not in stored or key not in given:
                return _join(path, key), stored.get(key, "(missing)"), given.get(key, "(none)")
            found = _difference(stored[key], given[key], _join(path, key))
            if found:
                return found
        return None
    if isinstance(stored, list) and isinstance(given, list):
        for i, (a, b) in enumerate(zip(stored, given)):
            found = _difference(a, b, f"{path}[{i}]")
            if found:
                return found
        if len(stored) != len(given):
            return f"{path} (length)", len(stored), len(given)
        return None
    same = type(stored) is type(given) or {type(stored), type(given)} <= {int, float}
    return None if same and stored == given else (path, stored, given)


def _compare(stored: dict[str, Any], step: Step, i: int) -> None:
    given = _record(step)
    for field in ("name", "kind", "op", "inputs", "params", "instrument", "key", "caption",
                  "ref", "index", "conditions", "value"):
        found = _difference(stored[field], given[field], field)
        if found:
            where, a, b = found
            how = "does not match its replay" if field == "value" else "disagrees with the grasp"
            raise InconsistentDocumentError(
                f"steps[{i}] ({stored['name']}) {how}: {where} is {_show(a)} in the file, "
                f"but the grasp gives {_show(b)}")


def _rebuild(doc: dict[str, Any], g: Grasp) -> Construction:
    """Replay the recipe on ``g`` as far as the document goes, comparing every step."""
    records, listed = doc["steps"], [tuple(x) for x in doc["skipped"]]
    names = [n for n, _ in listed]
    specs = diagram_specs(g)
    known = {s.name for s in specs if s.op == "second_intersection"}
    for i, (n, _) in enumerate(listed):
        if n not in known or names.index(n) != i:
            why = "a repeated name" if n in known else "not a step the recipe may leave out"
            raise _fail(f"skipped[{i}][0]", why, n)
    env: dict[str, Any] = {}
    steps: list[Step] = []
    skipped: list[tuple[str, str]] = []
    pending = set(names)

    def done() -> bool:
        return len(steps) >= len(records) and not pending

    for spec in specs:
        if done():
            break
        try:
            step = run_step(spec, env, len(steps))
        except GeometryError as exc:
            if spec.op != "second_intersection":
                raise _fail(f"steps[{len(steps)}]", f"the grasp's construction fails at "
                            f"{spec.name} ({exc})", spec.name, InconsistentDocumentError) from None
            skipped.append((spec.name, str(exc)))
            pending.discard(spec.name)
            continue
        if spec.name in pending:
            raise _fail(f"skipped[{names.index(spec.name)}]", f"the grasp makes {spec.name} "
                        "(it is not left out)", listed[names.index(spec.name)],
                        InconsistentDocumentError)
        if len(steps) < len(records):
            _compare(records[len(steps)], step, len(steps))
        env[spec.name] = step.obj
        steps.append(step)
    if len(steps) < len(records):
        total = len(steps) + (not any(v.free_symbols for v in g.params.values()))
        if len(records) > total:
            raise _fail(f"steps[{total}]", f"the recipe of this grasp has {total} steps, the "
                        f"file {len(records)}", records[total]["name"],
                        InconsistentDocumentError)
        circles = [s.name for s in steps if s.op in ("circle_on_diameter", "second_intersection")]
        step = Step(len(steps), "envelope", "envelope", "compass", tuple(circles),
                    outer_envelope(env), (),
                    "Outer envelope of the four circles: the polar graph of k_grasp(θ)",
                    "§3.3 outside extraction, eq. (25), Fig. 5", key=True, role="envelope")
        _compare(records[len(steps)], step, len(steps))
        steps.append(step)
    if listed != skipped:
        found = _difference([list(x) for x in listed], [list(x) for x in skipped], "skipped")
        where, a, b = found or ("skipped", listed, skipped)
        raise InconsistentDocumentError(f"{where} is {_show(a)} in the file, but the grasp "
                                        f"gives {_show(b)}")
    return Construction(tuple(steps), g, tuple(skipped))


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
        raise JSONDocumentError("grasp: a document without a grasp cannot be checked against "
                                "the paper's recipe, so it is not read")
    g = _grasp(doc["grasp"])
    try:
        return _rebuild(doc, g)
    except GraspCompassError as exc:
        if isinstance(exc, JSONDocumentError):
            raise
        raise JSONDocumentError(f"steps: the grasp's construction fails: {exc}") from None
    except (ArithmeticError, TypeError, ValueError, NotImplementedError, RecursionError,
            BasePolynomialError) as exc:
        raise JSONDocumentError(f"steps: the exact kernel cannot build this grasp's "
                                f"construction ({type(exc).__name__}: {str(exc)[:80]})") from None


class _Object(dict):
    """A JSON object; ``duplicate`` is a key that appeared twice (reported with its path)."""

    duplicate: str | None = None


def _pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    obj = _Object(pairs)
    if len(obj) != len(pairs):
        seen: set[str] = set()
        obj.duplicate = next(k for k, _ in pairs if k in seen or seen.add(k))  # type: ignore
    return obj


def _constant(name: str) -> float:
    raise JSONDocumentError(f"not JSON: {name} is not a JSON number (only finite numbers are)")


def _float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise JSONTooLargeError(f"not JSON: the number {_show(text)} does not fit a double")
    return value


def _int(text: str) -> int:
    if len(text.lstrip("-")) > MAX_INT_DIGITS:
        raise JSONTooLargeError(f"the integer {_show(text)} has more than {MAX_INT_DIGITS} "
                                "digits")
    return int(text)


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
        raise JSONTooLargeError(f"the JSON text has {len(text)} characters, more than "
                                f"{MAX_BYTES}")
    try:
        doc = _json.loads(text, object_pairs_hook=_pairs, parse_constant=_constant,
                          parse_float=_float, parse_int=_int)
    except _json.JSONDecodeError as exc:
        raise JSONDocumentError(f"not JSON: {exc}") from None
    except RecursionError:
        raise JSONTooLargeError("not read: the JSON text is nested too deeply") from None
    return from_document(doc)
