"""JSON of the construction protocol, and loading it back (round trip).

Schema ``graspcompass.construction/1``
--------------------------------------
One JSON object::

    {
      "schema": "graspcompass.construction/1",
      "generator": "graspcompass 0.1.0",
      "grasp": null | {
          "x1", "x2", "y", "phi1", "phi2":  <number>,
          "friction": {"1": "mu" | "xi", "2": "mu" | "xi"},
          "mu1", "mu2", "xi1", "xi2":       <number>,
          "title": str | null,
          "shape": list | null              # ["circle", r] or ["rectangle", w, h]
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
for a float of ``n`` bits that a double cannot hold (its exact binary value).
``friction`` tells which of μ and ξ defined the contact (the other is derived:
ξ = atan μ or μ = tan ξ).

``value`` is :func:`graspcompass.construction.describe.step_record`'s: a point
``{"x", "y", "float": [x, y]}``, a line ``{"point", "direction"}``, a circle
``{"center", "radius2", "radius"}``, a length ``{"exact", "float"}``, the
envelope ``{"arcs": [{"circle", "theta_start", "theta_end", ..., "start",
"end"}]}``; exact values are ``str(expr)`` of sympy, floats are for reading only.

:func:`loads` rebuilds the grasp, replays the step declarations (``op``,
``inputs``, ``params``) with the exact kernel and checks every replayed value
against the stored exact text, so a file that was edited by hand into an
inconsistent state is refused rather than silently trusted.
"""

from __future__ import annotations

import json as _json
from typing import Any

import sympy as sp

from .. import __version__, symbols
from ..construction.describe import step_record
from ..construction.envelope import outer_envelope
from ..construction.protocol import OPS, Construction, StepSpec, run_step
from ..expr import parse_exact
from ..grasp import Grasp

__all__ = ["SCHEMA", "dumps", "from_document", "loads", "to_document"]

#: The schema identifier written to and required in every document.
SCHEMA = "graspcompass.construction/1"

_SYMBOLS = {str(s): s for s in (symbols.x1, symbols.x2, symbols.y, symbols.phi1, symbols.phi2,
                                symbols.xi1, symbols.xi2, symbols.mu1, symbols.mu2,
                                symbols.theta, symbols.F_e)}
_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")


def _number(v: Any) -> str | float | dict[str, Any]:
    v = sp.sympify(v)
    if v.atoms(sp.Float):
        if not v.is_Float:
            v = v.evalf(17)
        if v.free_symbols or not v.is_Float:
            raise ValueError(f"cannot store {v} exactly: it mixes floats and symbols")
        if v._prec == 53:
            return float(v)
        return {"float": str(sp.Rational(v)), "bits": int(v._prec)}  # exact binary value
    return str(v)


def _read(v: Any, where: str) -> sp.Expr:
    if isinstance(v, dict) and set(v) == {"float", "bits"} and isinstance(v["bits"], int):
        return sp.Float(parse_exact(str(v["float"])), precision=v["bits"])
    if isinstance(v, bool) or not isinstance(v, (str, int, float)):
        raise ValueError(f"{where}: expected a number or an exact expression, got {v!r}")
    if isinstance(v, float):
        return sp.Float(v)
    if isinstance(v, int):
        return sp.Integer(v)
    return parse_exact(v, symbols=_SYMBOLS)


def _grasp_record(g: Grasp) -> dict[str, Any]:
    p = g.params
    friction = {str(i): ("mu" if sp.atan(p[f"mu{i}"]) == p[f"xi{i}"] else "xi") for i in (1, 2)}
    rec: dict[str, Any] = {k: _number(p[k]) for k in _PARAMS}
    rec["friction"] = friction
    rec["title"] = g.title
    rec["shape"] = list(g.shape) if g.shape else None
    return rec


def to_document(construction: Construction) -> dict[str, Any]:
    """The JSON-ready document (schema :data:`SCHEMA`) of ``construction``."""
    steps = []
    for s in construction.steps:
        rec = step_record(s)
        rec["params"] = [_number(p) for p in s.params]
        steps.append(rec)
    g = construction.grasp
    return {"schema": SCHEMA, "generator": f"graspcompass {__version__}",
            "grasp": None if g is None else _grasp_record(g),
            "skipped": [list(x) for x in construction.skipped], "steps": steps}


def dumps(construction: Construction, indent: int | None = 1) -> str:
    """The construction as JSON text (schema ``graspcompass.construction/1``).

    Examples
    --------
    >>> from graspcompass import Grasp, internal_force_diagram
    >>> c = internal_force_diagram(Grasp.preset("table1a"))
    >>> text = dumps(c)
    >>> loads(text)["V1"] == c["V1"]
    True
    """
    return _json.dumps(to_document(construction), indent=indent, ensure_ascii=False)


def _grasp(rec: dict[str, Any]) -> Grasp:
    try:
        vals = {k: _read(rec[k], f"grasp.{k}") for k in _PARAMS}
        fr = rec.get("friction", {"1": "mu", "2": "mu"})
        kw = {f"{fr[str(i)]}{i}": vals[f"{fr[str(i)]}{i}"] for i in (1, 2)}
    except KeyError as exc:
        raise ValueError(f"the grasp record lacks {exc}") from None
    shape = tuple(rec["shape"]) if rec.get("shape") else None
    return Grasp(vals["x1"], vals["x2"], vals["y"], vals["phi1"], vals["phi2"], **kw,
                 shape=shape, title=rec.get("title"))


def _spec(rec: dict[str, Any]) -> StepSpec:
    try:
        return StepSpec(rec["name"], rec["op"], tuple(rec["inputs"]), rec["instrument"],
                        rec["caption"], rec["ref"],
                        tuple(_read(p, f"step {rec['name']}.params") for p in rec["params"]),
                        bool(rec.get("key", False)))
    except KeyError as exc:
        raise ValueError(f"step {rec.get('name', '?')!r} lacks {exc}") from None


def from_document(doc: dict[str, Any]) -> Construction:
    """Rebuild the construction of a document (see the module docstring).

    Raises
    ------
    ValueError
        For another schema, a malformed record, a step that cannot be replayed,
        or a stored exact value that differs from the replayed one.
    """
    if not isinstance(doc, dict) or doc.get("schema") != SCHEMA:
        found = doc.get("schema") if isinstance(doc, dict) else type(doc).__name__
        raise ValueError(f"not a {SCHEMA} document (schema: {found!r})")
    grasp = None if doc.get("grasp") is None else _grasp(doc["grasp"])
    env: dict[str, Any] = {}
    extra = {"envelope": lambda *_: outer_envelope(env)}
    steps = []
    for i, rec in enumerate(doc.get("steps", [])):
        spec = _spec(rec)
        if spec.op not in extra and spec.op not in OPS:
            raise ValueError(f"step {spec.name!r}: unknown operation {spec.op!r}")
        missing = [n for n in spec.inputs if n not in env]
        if missing:
            raise ValueError(f"step {spec.name!r} uses {', '.join(missing)} before it is made")
        step = run_step(spec, env, i, extra)
        stored = rec.get("value")
        if stored is not None and step_record(step)["value"] != stored:
            raise ValueError(f"step {spec.name!r}: the stored value does not match its replay")
        env[spec.name] = step.obj
        steps.append(step)
    skipped = tuple((str(a), str(b)) for a, b in doc.get("skipped", []))
    return Construction(tuple(steps), grasp, skipped)


def loads(text: str) -> Construction:
    """The construction of a JSON text written by :func:`dumps`."""
    try:
        doc = _json.loads(text)
    except _json.JSONDecodeError as exc:
        raise ValueError(f"not JSON: {exc}") from None
    return from_document(doc)
