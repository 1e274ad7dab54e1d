"""Hostile and careless JSON files for graspcompass.export.json.loads (issue 10, item 4).

Every document here is refused with :class:`JSONDocumentError` (an ``InputError``,
so a ``ValueError``) and a one-line message naming the place, or loaded into the
construction its grasp gives.  Nothing may hang: each call runs under an alarm
(a generous hang detector, not a speed assertion).
"""

from __future__ import annotations

import contextlib
import copy
import json
import os
import time
from typing import Any

import pytest
import sympy as sp
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from _hang import no_hang
from graspcompass import Grasp, internal_force_diagram
from graspcompass.construction import diagram_specs, replay
from graspcompass.errors import InputError, InputTooLargeError
from graspcompass.export.json import (
    DOCUMENT_SCHEMA,
    MAX_BYTES,
    InconsistentDocumentError,
    JSONDocumentError,
    JSONTooLargeError,
    dumps,
    from_document,
    loads,
    to_document,
)

HANG = 20.0  # seconds: far above the second allowed, only to catch a hang


def _no_hang(seconds: float = HANG) -> contextlib.AbstractContextManager[None]:
    return no_hang("loads", seconds)


def refused(text: str | bytes, cls: type[Exception] = JSONDocumentError) -> str:
    """The one-line message of ``loads(text)``, which must raise ``cls``."""
    with _no_hang(), pytest.raises(cls) as err:
        loads(text)
    message = str(err.value)
    assert isinstance(err.value, InputError) and "\n" not in message and message
    assert len(message) < 400
    return message


@pytest.fixture(scope="module")
def table1a() -> dict[str, Any]:
    return to_document(internal_force_diagram(Grasp.preset("table1a")))


@pytest.fixture(scope="module")
def fig6_text() -> str:
    return dumps(internal_force_diagram(Grasp.preset("fig6")))


def edited(doc: dict[str, Any], path: tuple, value: Any = ..., delete: bool = False) -> str:
    doc = copy.deepcopy(doc)
    *head, last = path
    target = doc
    for key in head:
        target = target[key]
    if delete:
        del target[last]
    else:
        target[last] = value
    return json.dumps(doc, ensure_ascii=False)


# ---------------------------------------------------------------------------
# the defects found (issue 10, item 4): each failed before the fix
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("bits", [0, -1, -3, 10**10, 2**64])
def test_float_bits_zero_negative_or_huge_is_refused_at_once(table1a, bits):
    # before: bits 0 or negative looped forever; 10**10 took 25 s and 5.3 GB
    text = edited(table1a, ("grasp", "x1"), {"float": "1/3", "bits": bits})
    t0 = time.perf_counter()
    msg = refused(text)
    assert time.perf_counter() - t0 < HANG
    assert msg.startswith("grasp.x1.bits:") and str(bits)[:20] in msg


def test_float_record_must_be_an_exact_binary_value(table1a):
    assert "power of 2" in refused(edited(table1a, ("grasp", "x1"), {"float": "1/3", "bits": 60}))
    msg = refused(edited(table1a, ("grasp", "x1"), {"float": str(2**70 + 1), "bits": 60}))
    assert "needs 71 bits" in msg
    msg = refused(edited(table1a, ("grasp", "x1"), {"float": "sqrt(2)", "bits": 60}))
    assert "grasp.x1.float" in msg


def test_a_dozen_square_roots_is_refused_at_once(table1a):
    # before: a 760-byte file with a dozen different square roots took over 40 s
    doc = copy.deepcopy(table1a)
    roots = [f"sqrt({p})" for p in (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37)]
    doc["grasp"].update(
        x1="+".join(roots[:3]),
        x2="+".join(roots[3:6]),
        y="+".join(roots[6:9]),
        mu1="+".join(roots[9:]),
    )
    short = dict(doc, steps=[], generator="x")
    assert len(json.dumps(short)) < 1000
    for d in (short, doc):
        msg = refused(json.dumps(d), JSONTooLargeError)
        assert msg.startswith("grasp:") and "distinct irrational numbers" in msg


def test_free_replay_of_a_dozen_square_roots_is_refused_at_once(table1a):
    # before: a grasp-less file of six steps (points with sums of square roots, two
    # circles and their intersection) was replayed as written and ran for minutes
    r = [f"sqrt({p})" for p in (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37)]
    step = copy.deepcopy(table1a["steps"][0])
    steps = []
    for i, (name, op, inputs, params) in enumerate(
        [
            ("O", "point", [], ["0", "0"]),
            ("A", "point", [], ["+".join(r[0:3]), "+".join(r[3:6])]),
            ("B", "point", [], ["+".join(r[6:9]), "+".join(r[9:12])]),
            ("c1", "circle_on_diameter", ["O", "A"], []),
            ("c2", "circle_on_diameter", ["O", "B"], []),
            ("X", "second_intersection", ["c1", "c2", "O"], []),
        ]
    ):
        steps.append(dict(step, index=i, name=name, op=op, inputs=inputs, params=params))
    doc = dict(table1a, steps=steps, grasp=None)
    assert "without a grasp" in refused(json.dumps(doc))
    doc["grasp"] = table1a["grasp"]  # with a grasp: the first step not the recipe's is named
    assert refused(json.dumps(doc), InconsistentDocumentError).startswith("steps[1] (A)")


def test_irrational_numbers_the_kernel_is_slow_with_are_refused(table1a):
    # sin/cos of 1 rad next to square roots took 8 s and more to construct before the
    # kernel's flint algebra (issue 20); now such a grasp is written and read back
    g = Grasp(x1="sqrt(2)", x2="0.3", y="0.4", phi1="1", phi2="118deg", xi1="67deg", xi2="49deg")
    assert loads(dumps(internal_force_diagram(g))).grasp == g
    text = edited(table1a, ("grasp", "phi1"), "1")
    doc = json.loads(text)
    doc["grasp"]["x1"] = "2"
    doc["grasp"]["mu1"] = "pi/4"
    assert "uses pi" in refused(json.dumps(doc))
    msg = refused(
        edited(table1a, ("grasp", "mu1"), "sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7)"), JSONTooLargeError
    )
    assert "4 distinct irrational numbers" in msg and "at most 3" in msg


def test_tampered_grasp_is_refused_naming_the_step(fig6_text):
    # before: accepted; re-exported it gave a .ggb and an .svg of different grasps
    doc = json.loads(fig6_text)
    doc["grasp"]["x1"] = "1"
    msg = refused(json.dumps(doc), InconsistentDocumentError)
    assert msg.startswith("steps[3] (P1)")
    assert "params[0] is 'sqrt(3)/2' in the file, but the grasp gives '1'" in msg


def test_tampered_step_value_is_refused_with_both_values(fig6_text):
    doc = json.loads(fig6_text)
    v2 = next(i for i, s in enumerate(doc["steps"]) if s["name"] == "V2")
    doc["steps"][v2]["value"]["x"] = "2"
    msg = refused(json.dumps(doc), InconsistentDocumentError)
    assert f"steps[{v2}] (V2)" in msg and "value.x is '2' in the file" in msg
    assert "the grasp gives 'sqrt(3)'" in msg  # §4.1: V2 = (√3, −3/2)


def test_derived_friction_and_friction_choice_must_match(fig6_text):
    doc = json.loads(fig6_text)
    doc["grasp"]["xi1"] = "pi/5"  # fig6 gives μ1 = 1, so ξ1 = π/4
    msg = refused(json.dumps(doc), InconsistentDocumentError)
    assert msg.startswith("grasp.xi1:") and "pi/4" in msg and "mu1" in msg
    doc = json.loads(fig6_text)
    doc["grasp"]["friction"]["2"] = "xi"  # the same grasp, but not how dumps writes it
    assert refused(json.dumps(doc), InconsistentDocumentError).startswith("grasp.friction")


def test_grasp_numbers_must_be_written_as_dumps_writes_them(table1a):
    # the same grasp, written otherwise, would re-export differently: refused
    msg = refused(edited(table1a, ("grasp", "x1"), 2), InconsistentDocumentError)
    assert msg.startswith("grasp.x1: expected '2', the way dumps writes this value, got 2")
    assert "grasp.mu2" in refused(edited(table1a, ("grasp", "mu2"), "1.2"))


def test_steps_beyond_the_recipe_and_false_skips_are_refused(table1a):
    doc = copy.deepcopy(table1a)
    doc["steps"].append(copy.deepcopy(doc["steps"][-1]))
    assert "the recipe of this grasp has 47 steps" in refused(json.dumps(doc))
    assert "the grasp makes B12" in refused(edited(table1a, ("skipped",), [["B12", "tangent"]]))
    assert "not a step the recipe may leave out" in refused(
        edited(table1a, ("skipped",), [["P1", "x"]])
    )
    # steps out of order: the first one that is not the recipe's is named
    doc = copy.deepcopy(table1a)
    doc["steps"][3], doc["steps"][4] = doc["steps"][4], doc["steps"][3]
    assert refused(json.dumps(doc)).startswith("steps[3] (P2)")


def test_no_grasp_cannot_be_checked(table1a):
    assert "without a grasp" in refused(edited(table1a, ("grasp",), None))


def test_expression_text_goes_through_the_safe_parser(table1a, tmp_path):
    marker = tmp_path / "x"
    attack = f"__import__('os').system('touch {marker}') or 2"
    msg = refused(edited(table1a, ("grasp", "x1"), attack))
    assert msg.startswith("grasp.x1:") and not marker.exists()
    assert refused(edited(table1a, ("grasp", "y"), "2**(1/3)")).startswith("grasp:")
    assert "sqrt(12345678901234567890123)" in refused(
        edited(table1a, ("grasp", "mu1"), "sqrt(12345678901234567890123)"), JSONTooLargeError
    )


# ---------------------------------------------------------------------------
# malformed documents: all refused with the documented error, saying where
# ---------------------------------------------------------------------------
MALFORMED: list[tuple[str, Any, str]] = [
    # (id, how to make the text from the table1a document, start of the message)
    ("not json", lambda d: "{", "not JSON"),
    ("empty", lambda d: "", "not JSON"),
    ("top level list", lambda d: "[1, 2]", "not a graspcompass.construction/1 document"),
    ("top level string", lambda d: '"graspcompass.construction/1"', "not a graspcompass"),
    ("wrong schema name", lambda d: edited(d, ("schema",), "other/1"), "not a graspcompass"),
    (
        "wrong schema version",
        lambda d: edited(d, ("schema",), "graspcompass.construction/2"),
        "not a graspcompass",
    ),
    ("schema not a string", lambda d: edited(d, ("schema",), 1), "not a graspcompass"),
    ("unknown top key", lambda d: edited(d, ("extra",), 1), "extra: unknown key"),
    (
        "missing steps",
        lambda d: edited(d, ("steps",), delete=True),
        "the document: the key 'steps' is missing",
    ),
    (
        "missing grasp key",
        lambda d: edited(d, ("grasp", "phi2"), delete=True),
        "grasp: the key 'phi2' is missing",
    ),
    (
        "missing step key",
        lambda d: edited(d, ("steps", 4, "op"), delete=True),
        "steps[4]: the key 'op' is missing",
    ),
    ("grasp a list", lambda d: edited(d, ("grasp",), [1, 2]), "grasp: expected"),
    ("steps an object", lambda d: edited(d, ("steps",), {"0": 1}), "steps: expected a list"),
    ("step a string", lambda d: edited(d, ("steps", 2), "O"), "steps[2]: expected a step"),
    ("name an int", lambda d: edited(d, ("steps", 0, "name"), 0), "steps[0].name: expected"),
    (
        "inputs a string",
        lambda d: edited(d, ("steps", 8, "inputs"), "P1"),
        "steps[8].inputs: expected a list",
    ),
    ("input an int", lambda d: edited(d, ("steps", 8, "inputs", 0), 3), "steps[8].inputs[0]"),
    (
        "params a number",
        lambda d: edited(d, ("steps", 3, "params"), 2),
        "steps[3].params: expected a list",
    ),
    (
        "param a list",
        lambda d: edited(d, ("steps", 3, "params", 1), [1]),
        "steps[3].params[1]: expected a number",
    ),
    (
        "param a bool",
        lambda d: edited(d, ("steps", 3, "params", 1), True),
        "steps[3].params[1]: expected a number",
    ),
    ("key a string", lambda d: edited(d, ("steps", 3, "key"), "yes"), "steps[3].key: expected"),
    (
        "index a float",
        lambda d: edited(d, ("steps", 3, "index"), 3.0),
        "steps[3].index: expected an integer",
    ),
    (
        "unknown op",
        lambda d: edited(d, ("steps", 5, "op"), "eval"),
        "steps[5].op: unknown operation",
    ),
    ("unknown kind", lambda d: edited(d, ("steps", 5, "kind"), "spline"), "steps[5].kind"),
    (
        "value of the wrong kind",
        lambda d: edited(d, ("steps", 3, "value"), {"exact": "1"}),
        "steps[3].value.exact: unknown key",
    ),
    (
        "value point float a string",
        lambda d: edited(d, ("steps", 3, "value", "float"), "1,2"),
        "steps[3].value.float: expected a pair",
    ),
    (
        "deep value",
        lambda d: edited(d, ("steps", 3, "value", "x"), [[[[[[[[[[[["1"]]]]]]]]]]]]),
        "steps[3].value.x: expected a text",
    ),
    ("extra deep nesting", lambda d: "[" * 100_000 + "]" * 100_000, "not read: the JSON text"),
    (
        "deep inside the grasp",
        lambda d: edited(d, ("grasp", "title"), json.loads("[" * 500 + "]" * 500)),
        "grasp.title: expected a text or null",
    ),
    ("NaN", lambda d: edited(d, ("grasp", "x1"), float("nan")), "not JSON: NaN"),
    ("Infinity", lambda d: edited(d, ("grasp", "x1"), float("inf")), "not JSON: Infinity"),
    ("-Infinity", lambda d: edited(d, ("grasp", "x1"), float("-inf")), "not JSON: -Infinity"),
    (
        "overflowing float",
        lambda d: edited(d, ("grasp", "x1"), 1.0).replace('"x1": 1.0', '"x1": 1e999'),
        "not JSON: the number '1e999'",
    ),
    (
        "huge integer",
        lambda d: edited(d, ("grasp", "x1"), 1.0).replace('"x1": 1.0', '"x1": ' + "9" * 5000),
        "the integer '99",
    ),
    (
        "huge JSON number",
        lambda d: edited(d, ("grasp", "x1"), 1e300),
        "grasp.x1: expected a number from",
    ),
    (
        "huge exact number",
        lambda d: edited(d, ("grasp", "x1"), "1e300"),
        "grasp.x1: expected a number at most 1e+15",
    ),
    (
        "duplicate key",
        lambda d: edited(d, ("grasp", "x1"), "2").replace('"x1": "2"', '"x1": "2", "x1": "3"'),
        "grasp: the key 'x1' appears twice",
    ),
    (
        "bits a string",
        lambda d: edited(d, ("grasp", "x1"), {"float": "1", "bits": "53"}),
        "grasp.x1.bits: expected an integer",
    ),
    (
        "float record extra key",
        lambda d: edited(d, ("grasp", "x1"), {"float": "1", "bits": 53, "eval": 1}),
        "grasp.x1.eval: unknown key",
    ),
    (
        "expression a list",
        lambda d: edited(d, ("grasp", "x1"), ["sqrt", 2]),
        "grasp.x1: expected a number",
    ),
    ("expression null", lambda d: edited(d, ("grasp", "mu1"), None), "grasp.mu1: expected"),
    ("expression an object", lambda d: edited(d, ("grasp", "y"), {"a": 1}), "grasp.y"),
    ("expression junk", lambda d: edited(d, ("grasp", "y"), "1 +* 2"), "grasp.y: cannot read"),
    (
        "friction junk",
        lambda d: edited(d, ("grasp", "friction"), {"1": "mu"}),
        "grasp.friction: the key '2' is missing",
    ),
    ("shape junk", lambda d: edited(d, ("grasp", "shape"), ["circle", -1]), "grasp.shape"),
    ("invalid grasp", lambda d: edited(d, ("grasp", "x1"), "-3"), "grasp: x1 + x2 = -1 must be"),
    (
        "lone surrogate",
        lambda d: edited(d, ("grasp", "title"), "a\ud800b"),
        "grasp.title: control character or lone surrogate",
    ),
    ("NUL in a text", lambda d: edited(d, ("grasp", "title"), "a\x00b"), "grasp.title: control"),
    (
        "unicode junk name",
        lambda d: edited(d, ("steps", 0, "name"), "O\u202e"),
        "steps[0].name: expected a step name",
    ),
    ("newline in a key", lambda d: edited(d, ("grasp", "\n"), None), "grasp['\\n']: unknown key"),
    (
        "newline after a name",
        lambda d: edited(d, ("steps", 0, "name"), "O\n"),
        "steps[0].name: expected a step name",
    ),
    (
        "unicode digits in a float",
        lambda d: edited(d, ("grasp", "x1"), {"float": "\u0663", "bits": 53}),
        "grasp.x1.float: expected a fraction",
    ),
    (
        "long title",
        lambda d: edited(d, ("grasp", "title"), "t" * 5000),
        "grasp.title: a text of 5000 characters",
    ),
    (
        "many steps",
        lambda d: edited(d, ("steps",), [d["steps"][0]] * 1000),
        "steps: a list of 1000 items is longer than 64",
    ),
    ("skipped junk", lambda d: edited(d, ("skipped",), [["B12"]]), "skipped[0]: expected a pair"),
    ("twenty megabytes", lambda d: " " * (20 * 2**20), "the JSON text has"),
]


@pytest.mark.parametrize("make, start", [m[1:] for m in MALFORMED], ids=[m[0] for m in MALFORMED])
def test_malformed_documents_are_refused_saying_where(table1a, make, start):
    assert refused(make(table1a)).startswith(start)


def test_malformed_bytes_and_types():
    assert refused(b"\xff\xfe{").startswith("not UTF-8")
    assert refused(b" " * (MAX_BYTES + 1), JSONTooLargeError).startswith("the JSON text has")
    with pytest.raises(JSONDocumentError, match="expected a JSON text"):
        loads(None)  # type: ignore[arg-type]
    with pytest.raises(JSONDocumentError, match="not a graspcompass"):
        from_document([])


def test_size_errors_are_also_input_too_large(table1a):
    with pytest.raises(InputTooLargeError):
        loads(" " * (MAX_BYTES + 1))
    with pytest.raises(InputTooLargeError):
        loads(edited(table1a, ("steps",), [table1a["steps"][0]] * 100))


def test_huge_python_ints_in_a_document_are_refused(table1a):
    doc = copy.deepcopy(table1a)
    doc["steps"][0]["index"] = 10**5000
    with _no_hang(), pytest.raises(JSONTooLargeError, match=r"steps\[0\]\.index"):
        from_document(doc)


def test_a_cyclic_python_document_is_refused(table1a):
    doc = copy.deepcopy(table1a)
    doc["steps"][3]["value"]["x"] = doc["steps"][3]["value"]
    with _no_hang(), pytest.raises(JSONDocumentError, match=r"steps\[3\]\.value\.x"):
        from_document(doc)


def test_the_schema_is_data():
    assert DOCUMENT_SCHEMA["additionalProperties"] is False
    assert set(DOCUMENT_SCHEMA["required"]) == {"schema", "grasp", "skipped", "steps"}
    json.dumps(DOCUMENT_SCHEMA)  # plain JSON-ready data


# ---------------------------------------------------------------------------
# what must keep working
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1b", "table1c"])
def test_presets_re_export_identically(preset):
    c = internal_force_diagram(Grasp.preset(preset))
    text = dumps(c)
    with _no_hang():
        assert dumps(loads(text)) == text
        assert dumps(loads(text.encode())) == text
        part = dumps(c.upto(8))
        assert dumps(loads(part)) == part


def test_float_and_symbolic_prefix_re_export_identically():
    g = Grasp(1.0, 1.3, 0.5, 1.2, 1.4, mu1=0.7, mu2=0.8)
    text = dumps(internal_force_diagram(g))
    assert dumps(loads(text)) == text
    g = Grasp(1, 2, "1/3", sp.Float(1.2, 30), "pi/2", mu1="1/2", mu2=sp.Float(0.25, 40))
    text = dumps(internal_force_diagram(g))
    assert '"bits": ' in text and dumps(loads(text)) == text
    s = Grasp.symbolic("mu")
    text = dumps(replay(diagram_specs(s)[:14], s))
    with _no_hang(60):
        assert dumps(loads(text)) == text


# ---------------------------------------------------------------------------
# mutations of a valid document: the named error, or a load that re-exports it
# ---------------------------------------------------------------------------
def _paths(value: Any, path: tuple = ()) -> list[tuple]:
    out = [path] if path else []
    if isinstance(value, dict):
        for k, v in value.items():
            out += _paths(v, (*path, k))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            out += _paths(v, (*path, i))
    return out


_JSON_LEAF = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(10**40), max_value=10**40),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=30),
    st.sampled_from(
        [
            "1",
            "0",
            "-1",
            "1/2",
            "sqrt(2)",
            "pi/2",
            "x1",
            "1e400",
            "2**(1/3)",
            "O",
            "P1",
            "B12",
            "mu",
            "xi",
            "point",
            "meet",
            "circle",
            "envelope",
            "graspcompass.construction/1",
        ]
    ),
    st.fixed_dictionaries(
        {"float": st.sampled_from(["1/3", "1", "-3/4", "x"]), "bits": st.integers(-5, 2000)}
    ),
)
_JSON = st.recursive(
    _JSON_LEAF,
    lambda inner: st.one_of(
        st.lists(inner, max_size=3), st.dictionaries(st.text(max_size=5), inner, max_size=3)
    ),
    max_leaves=6,
)


def _swap(value: Any) -> Any:
    """The same content with another JSON type."""
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, str):
        try:
            return json.loads(value)
        except ValueError:
            return [value]
    if isinstance(value, list):
        return {str(i): v for i, v in enumerate(value)}
    if isinstance(value, dict):
        return list(value.values())
    return False


@st.composite
def mutated(draw: st.DrawFn, doc: dict[str, Any]) -> dict[str, Any]:
    doc = copy.deepcopy(doc)
    for _ in range(draw(st.integers(1, 3))):
        paths = _paths(doc)
        if not paths:
            break
        *head, last = draw(st.sampled_from(paths))
        parent = doc
        for key in head:
            parent = parent[key]
        how = draw(st.sampled_from(["delete", "replace", "swap", "borrow"]))
        if how == "delete":
            del parent[last]
        elif how == "borrow":  # a value of the same document, from another place
            *head2, last2 = draw(st.sampled_from(paths))
            source = doc
            for key in head2:
                source = source[key]
            parent[last] = copy.deepcopy(source[last2])
        elif how == "replace":
            parent[last] = draw(_JSON)
        else:
            parent[last] = _swap(parent[last])
    return doc


_DOC = to_document(internal_force_diagram(Grasp.preset("table1a")))
_FLOAT_DOC = to_document(
    internal_force_diagram(Grasp(1.0, 1.3, 0.5, 1.2, 1.4, mu1=0.7, mu2=sp.Float(0.8, 30)))
)
_EXAMPLES = int(os.environ.get("GRASPCOMPASS_FUZZ_EXAMPLES", "120"))


@settings(
    max_examples=_EXAMPLES,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(mutated(_DOC))
def test_mutated_documents_are_refused_or_re_export_identically(doc):
    _refused_or_the_same(doc)


@settings(
    max_examples=max(_EXAMPLES // 2, 10),
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(mutated(_FLOAT_DOC))
def test_mutated_float_documents_are_refused_or_re_export_identically(doc):
    _refused_or_the_same(doc)


def _refused_or_the_same(doc: dict[str, Any]) -> None:
    text = json.dumps(doc, ensure_ascii=False)
    with _no_hang():
        try:
            c = loads(text)
        except JSONDocumentError as exc:
            assert "\n" not in str(exc)
            event(f"refused: {type(exc).__name__}")
            return
    event("accepted")
    again = to_document(c)
    again.pop("generator")
    doc.pop("generator", None)
    assert again == doc
