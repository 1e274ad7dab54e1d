"""The steps of a JSON document: their records, and the replay that checks them.

A document is never computed with: :func:`_rebuild` replays the paper's recipe on
the document's grasp and compares every stored step with the one the grasp gives,
field by field (step 5 of "Reading JSON files" in :mod:`graspcompass.export.json`).
Private to :mod:`graspcompass.export.json`, which re-exports these names.
"""

from __future__ import annotations

from typing import Any

from ..construction.describe import step_record
from ..construction.envelope import outer_envelope
from ..construction.protocol import Construction, Step, run_step
from ..construction.recipe import diagram_specs
from ..geometry import GeometryError
from ..grasp import Grasp
from ._json_grasp import _number
from ._json_limits import InconsistentDocumentError
from ._json_schema import _difference, _fail, _show


def _record(step: Step) -> dict[str, Any]:
    rec = step_record(step)
    rec["params"] = [_number(p) for p in step.params]
    return rec


def _compare(stored: dict[str, Any], step: Step, i: int) -> None:
    given = _record(step)
    for field in (
        "name",
        "kind",
        "op",
        "inputs",
        "params",
        "instrument",
        "key",
        "caption",
        "ref",
        "index",
        "conditions",
        "value",
    ):
        found = _difference(stored[field], given[field], field)
        if found:
            where, a, b = found
            how = "does not match its replay" if field == "value" else "disagrees with the grasp"
            raise InconsistentDocumentError(
                f"steps[{i}] ({stored['name']}) {how}: {where} is {_show(a)} in the file, "
                f"but the grasp gives {_show(b)}"
            )


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
                raise _fail(
                    f"steps[{len(steps)}]",
                    f"the grasp's construction fails at {spec.name} ({exc})",
                    spec.name,
                    InconsistentDocumentError,
                ) from None
            skipped.append((spec.name, str(exc)))
            pending.discard(spec.name)
            continue
        if spec.name in pending:
            raise _fail(
                f"skipped[{names.index(spec.name)}]",
                f"the grasp makes {spec.name} (it is not left out)",
                listed[names.index(spec.name)],
                InconsistentDocumentError,
            )
        if len(steps) < len(records):
            _compare(records[len(steps)], step, len(steps))
        env[spec.name] = step.obj
        steps.append(step)
    if len(steps) < len(records):
        total = len(steps) + (not any(v.free_symbols for v in g.params.values()))
        if len(records) > total:
            raise _fail(
                f"steps[{total}]",
                f"the recipe of this grasp has {total} steps, the file {len(records)}",
                records[total]["name"],
                InconsistentDocumentError,
            )
        circles = [s.name for s in steps if s.op in ("circle_on_diameter", "second_intersection")]
        step = Step(
            len(steps),
            "envelope",
            "envelope",
            "compass",
            tuple(circles),
            outer_envelope(env),
            (),
            "Outer envelope of the four circles: the polar graph of k_grasp(θ)",
            "§3.3 outside extraction, eq. (25), Fig. 5",
            key=True,
            role="envelope",
        )
        _compare(records[len(steps)], step, len(steps))
        steps.append(step)
    if listed != skipped:
        found = _difference([list(x) for x in listed], [list(x) for x in skipped], "skipped")
        where, a, b = found or ("skipped", listed, skipped)
        raise InconsistentDocumentError(
            f"{where} is {_show(a)} in the file, but the grasp gives {_show(b)}"
        )
    return Construction(tuple(steps), g, tuple(skipped))
