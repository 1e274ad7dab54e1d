"""The schema of a JSON document, as data, and the checker of that subset of JSON Schema.

:data:`~graspcompass.export.json.DOCUMENT_SCHEMA` and
:data:`~graspcompass.export.json.VALUE_SCHEMAS` are written as data in a subset of
JSON Schema ("description" is what the error message says was expected);
:func:`_check` walks a document along them (step 3 of "Reading JSON files" in
:mod:`graspcompass.export.json`) and refuses it at the first wrong place, named by
its JSON path (:func:`_join`).  :func:`_difference` finds the first place where two
JSON values differ (step 5).  Private to :mod:`graspcompass.export.json`, which
re-exports these names.
"""

from __future__ import annotations

import math
import re
from typing import Any

from ..construction.protocol import INSTRUMENTS, OPS
from ._json_limits import (
    _MAX_SHOWN,
    MAX_FLOAT_BITS,
    MAX_MAGNITUDE,
    MAX_STEPS,
    MAX_TEXT,
    MAX_TITLE,
    SCHEMA,
    JSONDocumentError,
    JSONTooLargeError,
)


def _obj(props: dict[str, Any], description: str, optional: tuple[str, ...] = ()) -> dict:
    return {
        "type": "object",
        "properties": props,
        "additionalProperties": False,
        "required": [k for k in props if k not in optional],
        "description": description,
    }


def _text(max_length: int = MAX_TEXT, **extra: Any) -> dict[str, Any]:
    return {"type": "string", "maxLength": max_length, **extra}


_NAME = _text(32, pattern=r"[A-Za-z0-9_-]+", description="a step name (letters, digits, _ -)")
_FLOAT_READOUT = {"type": ["number", "null"], "description": "a JSON number or null"}
_POINT = _obj(
    {
        "x": _text(),
        "y": _text(),
        "float": {
            "type": "array",
            "prefixItems": [_FLOAT_READOUT, _FLOAT_READOUT],
            "minItems": 2,
            "maxItems": 2,
            "description": "a pair [x, y]",
        },
    },
    "a point record {x, y, float}",
)
VALUE_SCHEMAS: dict[str, dict[str, Any]] = {
    "point": _POINT,
    "line": _obj({"point": _POINT, "direction": _POINT}, "a line record {point, direction}"),
    "circle": _obj(
        {"center": _POINT, "radius2": _text(), "radius": _FLOAT_READOUT},
        "a circle record {center, radius2, radius}",
    ),
    "length": _obj({"exact": _text(), "float": _FLOAT_READOUT}, "a length record {exact, float}"),
    "envelope": _obj(
        {
            "arcs": {
                "type": "array",
                "maxItems": 16,
                "description": "a list of arcs",
                "items": _obj(
                    {
                        "circle": {"type": "integer", "minimum": 0, "maximum": 4},
                        "theta_start": _text(),
                        "theta_end": _text(),
                        "theta_start_deg": _FLOAT_READOUT,
                        "theta_end_deg": _FLOAT_READOUT,
                        "start": _POINT,
                        "end": _POINT,
                    },
                    "an arc record",
                ),
            }
        },
        "an envelope record {arcs}",
    ),
}
_FINITE = {"type": "number", "minimum": -MAX_MAGNITUDE, "maximum": MAX_MAGNITUDE}
_NUMBER = {
    "anyOf": [
        _text(1000),
        _FINITE,
        _obj(
            {
                "float": _text(1000, pattern=r"-?[0-9]+(/[0-9]+)?", description="a fraction 'p/q'"),
                "bits": {"type": "integer", "minimum": 1, "maximum": MAX_FLOAT_BITS},
            },
            'a float record {"float": "p/q", "bits": n}',
        ),
    ],
    "description": 'a number (exact text, a JSON number or {"float": "p/q", "bits": n})',
}
_SIZE = {
    "type": "number",
    "exclusiveMinimum": 0,
    "maximum": MAX_MAGNITUDE,
    "description": "a positive JSON number",
}
_GRASP = _obj(
    {
        **{k: _NUMBER for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")},
        "friction": _obj(
            {i: {"enum": ["mu", "xi"]} for i in ("1", "2")},
            'the friction record {"1": "mu" or "xi", "2": ...}',
        ),
        "title": {"anyOf": [_text(MAX_TITLE), {"type": "null"}], "description": "a text or null"},
        "shape": {
            "anyOf": [
                {"type": "null"},
                {
                    "type": "array",
                    "prefixItems": [{"const": "circle"}, _SIZE],
                    "minItems": 2,
                    "maxItems": 2,
                },
                {
                    "type": "array",
                    "prefixItems": [{"const": "rectangle"}, _SIZE, _SIZE],
                    "minItems": 3,
                    "maxItems": 3,
                },
            ],
            "description": 'null, ["circle", r] or ["rectangle", w, h]',
        },
    },
    "the grasp record (an object)",
)
_STEP = _obj(
    {
        "index": {"type": "integer", "minimum": 0, "maximum": MAX_STEPS},
        "name": _NAME,
        "kind": {"enum": list(VALUE_SCHEMAS)},
        "op": {
            "enum": [*OPS, "envelope"],
            "description": "a known operation",
            "x-error": "unknown operation",
        },
        "instrument": {"enum": list(INSTRUMENTS)},
        "inputs": {"type": "array", "items": _NAME, "maxItems": 16},
        "params": {"type": "array", "items": _NUMBER, "maxItems": 8},
        "key": {"type": "boolean"},
        "caption": _text(500),
        "ref": _text(200),
        "conditions": {"type": "array", "items": _text(), "maxItems": 64},
        "value": {"type": "object", "description": "a value record (an object)"},
    },
    "a step record (an object)",
)
DOCUMENT_SCHEMA: dict[str, Any] = _obj(
    {
        "schema": {"const": SCHEMA},
        "generator": _text(200),
        "grasp": {
            "anyOf": [_GRASP, {"type": "null"}],
            "description": "the grasp record (an object) or null",
        },
        "skipped": {
            "type": "array",
            "maxItems": 6,
            "items": {
                "type": "array",
                "prefixItems": [_NAME, _text(1000)],
                "minItems": 2,
                "maxItems": 2,
                "description": "a pair [name, reason]",
            },
        },
        "steps": {"type": "array", "items": _STEP, "maxItems": MAX_STEPS},
    },
    "a JSON object",
    optional=("generator",),
)
_JUNK = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f\ud800-\udfff\ufffe\uffff]")
_JSON_TYPES = {"string": str, "array": list, "object": dict, "boolean": bool, "null": type(None)}


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


def _fail(
    path: str, what: str, v: Any, cls: type[JSONDocumentError] = JSONDocumentError
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
    words = {
        "string": "a text",
        "integer": "an integer",
        "number": "a JSON number",
        "array": "a list",
        "object": "an object",
        "boolean": "true or false",
        "null": "null",
    }
    return " or ".join(words[t] if t in words else t for t in types)


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
        same = [
            o
            for o in options
            if "type" in o
            and any(
                _is_type(v, t) for t in (o["type"] if isinstance(o["type"], list) else [o["type"]])
            )
        ]
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
        raise _fail(
            path, f"a text of {len(v)} characters is longer than {limit}", v, JSONTooLargeError
        )
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
        raise _fail(
            path, f"expected {kind} {span}", v, JSONTooLargeError if big else JSONDocumentError
        )
    if "exclusiveMinimum" in schema and not v > schema["exclusiveMinimum"]:
        raise _fail(path, f"expected a number > {schema['exclusiveMinimum']}", v)


def _check_list(v: list, schema: dict[str, Any], path: str) -> None:
    if len(v) > schema.get("maxItems", MAX_STEPS):
        raise _fail(
            path,
            f"a list of {len(v)} items is longer than {schema.get('maxItems')}",
            v,
            JSONTooLargeError,
        )
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
            raise _fail(_join(path, key), f"unknown key (expected {', '.join(props)})", key)
    for key in schema.get("required", []):
        if key not in v:
            raise JSONDocumentError(
                f"{_where(path)}: the key {key!r} is missing from "
                f"{_expected(schema)} (it has {_show(sorted(v))})"
            )
    for key, sub in props.items():
        if key in v:
            _check(v[key], sub, _join(path, key))


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
