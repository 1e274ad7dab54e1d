"""Tests of the construction language (issue 11 §1): parser, replay, builder, records.

Expected objects are worked out by hand in the comments (small integer
constructions), never read from the implementation; the shipped recipe is
compared with today's Python recipe, :func:`internal_force_diagram`, step by
step and field by field.
"""

from __future__ import annotations

import argparse
import math
import re
import signal
import time
from contextlib import contextmanager

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graspcompass import Circle, Grasp, InvalidGraspError, Line, Point, internal_force_diagram
from graspcompass.construction import OPERATIONS, OPS, ROLES
from graspcompass.construction.language import (
    ConstructionBuilder,
    ConstructionSyntaxError,
    DegenerateStepError,
    PointValue,
    Program,
    Ref,
    Value,
    paper_program,
    paper_text,
    parse,
    replay,
)
from graspcompass.construction.recipe import _internal_force_diagram_from_specs
from graspcompass.errors import InputError

sqrt = sp.sqrt

# Every operation once, on small integers; the expected objects are worked out by hand.
EVERY_OP = """\
param a > 0
A = point (0, 0)
B = point (2, 0)
C = point (0, 2)
l = line_through A B
m = line_with_direction C (1, 1)
h = line_at_angle A (pi/2)         # e(pi/2) = (sin, -cos) = (1, 0)
p = perpendicular l C              # direction (2, 0) turned: (0, 2)
q = parallel l C
F = foot C l
M = midpoint B C
X = meet m l                       # (0, 2) + t (1, 1) on y = 0: t = -2
R = reflect C l
c1 = circle_through A B            # centre A, radius 2
c2 = circle_on_diameter A B        # centre (1, 0), radius 1
c3 = circle_through B A            # centre B, radius 2
I0 = intersect_line_circle l c1 (0)   # further along l (+x) first
I1 = intersect_line_circle l c1 (1)
J = intersect_circles c1 c3 (0)    # x = 1, left of A->B: y = +sqrt(3)
K = second_intersection c1 c3 J
s = signed_length A B l
V = point_from_lengths s s (-1, a)
D = point (4, 0)
P1 = point_on_line m (2)          # (0, 2) + 2 (1, 1)
P2 = point_on_circle c1 B (1)     # B turned by 2 atan 1 = pi/2
cc = circumcircle A B C           # centre (1, 1), r^2 = 2
cr = circle_radius C (3)
cs = circle_compass C A B         # radius |AB| = 2
bs = bisector B A C               # u |v| + v |u| = (4, 4)
ta = tangent_at c1 B              # the radius (2, 0) turned: (0, 2)
Tp = tangent_point D c1 (0)        # polar x = 1, left of the ray A->D: y = +sqrt(3)
rt = rotate B A (pi/2)
ho = homothety B C (1/2)          # C + (B - C)/2
pr = point_reflect B C            # 2C - B
ra = radical_axis c1 c3           # x = 1
Pq = parallel_to_points A B C      # through C along B - A = (2, 0)
T = quarter_turn B C               # B - C = (2, -2) turned clockwise: (-2, -2), plus C
"""
EXPECTED = {
    "A": Point(0, 0),
    "B": Point(2, 0),
    "C": Point(0, 2),
    "l": Line(Point(0, 0), Point(2, 0)),
    "m": Line(Point(0, 2), Point(1, 1)),
    "h": Line(Point(0, 0), Point(1, 0)),
    "p": Line(Point(0, 2), Point(0, 2)),
    "q": Line(Point(0, 2), Point(2, 0)),
    "F": Point(0, 0),
    "M": Point(1, 1),
    "X": Point(-2, 0),
    "R": Point(0, -2),
    "c1": Circle(Point(0, 0), 4),
    "c2": Circle(Point(1, 0), 1),
    "c3": Circle(Point(2, 0), 4),
    "I0": Point(2, 0),
    "I1": Point(-2, 0),
    "J": Point(1, sqrt(3)),
    "K": Point(1, -sqrt(3)),
    "s": sp.Integer(2),
    "V": Point(-2, 6),
    "P1": Point(2, 4),
    "P2": Point(0, 2),
    "cc": Circle(Point(1, 1), 2),
    "cr": Circle(Point(0, 2), 9),
    "cs": Circle(Point(0, 2), 4),
    "bs": Line(Point(0, 0), Point(4, 4)),
    "ta": Line(Point(2, 0), Point(0, 2)),
    "Tp": Point(1, sqrt(3)),
    "rt": Point(0, 2),
    "ho": Point(1, 1),
    "pr": Point(-2, 4),
    "ra": Line(Point(1, 0), Point(0, 2)),
    "Pq": Line(Point(0, 2), Point(2, 0)),
    "T": Point(-2, 0),
}
PRESETS = ("fig6", "table1a", "table1b", "table1c")


@contextmanager
def hang_bound(seconds: int):
    """Fail instead of hanging: SIGALRM after ``seconds``."""

    def stop(signum, frame):
        raise TimeoutError(f"parse took more than {seconds} s")

    old = signal.signal(signal.SIGALRM, stop)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


# -- the operation records -------------------------------------------------------------
def test_every_operation_of_the_kernel_has_a_record():
    expected = {
        "point",
        "line_through",
        "line_with_direction",
        "line_at_angle",
        "perpendicular",
        "parallel",
        "foot",
        "midpoint",
        "meet",
        "reflect",
        "circle_through",
        "circle_on_diameter",
        "intersect_line_circle",
        "intersect_circles",
        "second_intersection",
        "signed_length",
        "point_from_lengths",
        "point_on_line",
        "point_on_circle",
        "circumcircle",
        "circle_radius",
        "circle_compass",
        "bisector",
        "tangent_at",
        "tangent_point",
        "rotate",
        "homothety",
        "point_reflect",
        "radical_axis",
    }
    expected |= {"parallel_to_points", "quarter_turn"}  # issue 25: the n-contact recipe
    assert set(OPERATIONS) == expected
    assert all(OPS[k] is op.function for k, op in OPERATIONS.items())
    for op in OPERATIONS.values():
        assert op.makes in ("point", "line", "circle", "number")
        assert set(op.inputs) <= {"point", "line", "circle", "number"}
        assert op.draws in ("point", "line", "circle", "length", "curve")
        assert op.caption_for("Z", tuple("abc"[: len(op.inputs)]))


def test_ggb_templates_agree_with_the_geogebra_export():
    from graspcompass.export._ggb_defs import definition, ggb_label

    c = internal_force_diagram()
    steps = {s.name: s for s in c.steps}
    seen = set()
    for s in c.steps:
        op = OPERATIONS.get(s.op)
        if (
            op is None
            or op.ggb is None
            or s.op in ("point", "line_with_direction", "signed_length", "point_from_lengths")
        ):
            continue
        d = definition(s, steps, with_grasp=False)
        ours = op.ggb_for(tuple(ggb_label(n) for n in s.inputs), s.params)
        assert ours == f"{d.command}[{', '.join(d.inputs)}]", s.name
        seen.add(s.op)
    assert seen == {
        "foot",
        "midpoint",
        "meet",
        "perpendicular",
        "circle_on_diameter",
        "second_intersection",
    }


def test_every_step_of_the_recipe_has_a_role():
    c = internal_force_diagram(Grasp.preset("table1c"))
    assert all(s.role in ROLES and s.role for s in c.steps)
    assert c.step("V3").role == "V" and c.step("V3").n == (3,)
    assert c.step("B24").role == "break_point" and c.step("B24").n == (2, 4)
    assert c.step("side4").role == "cone_side" and c.step("envelope").role == "envelope"


# -- replay of every operation -----------------------------------------------------------
def test_every_operation_replays_to_the_hand_computed_object():
    prog = parse(EVERY_OP, "ops.gc")
    assert {s.op for s in prog.steps} == set(OPERATIONS)
    c = replay(prog, {"a": 3})
    for name, obj in EXPECTED.items():
        assert c[name] == obj, name
    assert c.step("J").instrument == "mark" and c.step("F").instrument == "perpendicular"
    assert c.step("X").caption == "X: where m meets l"


def test_symbolic_replay_keeps_the_parameter():
    c = replay(parse(EVERY_OP))
    (a,) = [p.symbol for p in parse(EVERY_OP).params]
    assert c["V"] == Point(-2, 2 * a)


def test_degenerate_step_names_step_line_and_objects():
    text = (
        "A = point (0, 0)\nl = line_with_direction A (1, 0)\n"
        "m = line_with_direction A (2, 0)\nX = meet l m\n"
    )
    with pytest.raises(DegenerateStepError) as info:
        replay(parse(text, "par.gc"))
    err = info.value
    assert (err.step, err.line) == ("X", 4)
    assert str(err).startswith("par.gc:4:1: step X = meet l m is degenerate: lines are parallel")
    assert err.objects == (Line(Point(0, 0), Point(1, 0)), Line(Point(0, 0), Point(2, 0)))


def test_optional_step_is_left_out_when_degenerate():
    text = (
        "A = point (0, 0)\nB = point (2, 0)\nC = point (4, 0)\nc1 = circle_on_diameter A B\n"
        "c2 = circle_on_diameter A C\nT = second_intersection c1 c2 A optional\n"
    )
    c = replay(parse(text))
    assert "T" not in c and c.skipped[0][0] == "T" and "tangent" in c.skipped[0][1]
    with pytest.raises(DegenerateStepError, match=":6:1: step T"):
        replay(parse(text.replace(" optional", "")))
    with pytest.raises(DegenerateStepError, match="no branch 1"):
        replay(
            parse(
                "A = point (0, 0)\nB = point (1, 0)\nc = circle_through A B\n"
                "d = circle_through B A\nl = line_through A B\n"
                "T = intersect_line_circle l c (1)\nc2 = circle_on_diameter A B\n"
                "U = intersect_circles c c2 (1)\n"
            )
        )


def test_replay_on_float_values_of_a_mapping():
    vals = {
        "x1": 2.0,
        "x2": 2.0,
        "y": 1.0,
        "phi1": math.pi / 2,
        "phi2": math.pi / 2,
        "mu1": 1.0,
        "mu2": 1.2,
    }
    a = replay(paper_program(), vals)
    b = internal_force_diagram(Grasp(**vals))
    assert a.steps == b.steps


@pytest.mark.parametrize(
    "text, values, what",
    [
        (
            "param a real\nA = point (1/a, 0)",
            {"a": 0},
            "t.gc:2:1: step A: the value 1/a is not finite",
        ),
        (
            "param a real\nA = point (1/a, 0)",
            {"a": 0.0},
            "t.gc:2:1: step A: the value 1/a is not a finite real",
        ),
        ("param a real\nA = point (sqrt(a), 0)", {"a": -1}, "sqrt(a) is not a real number"),
        ("param a real\nA = point (sqrt(a), 0)", {"a": -1.0}, "sqrt(a) is not a finite real"),
        ("param a > 0\nA = point (a, 0)", {"a": -1}, "t.gc:1:1: a = -1 is outside its domain"),
        ("param a angle\nA = point (a, 0)", {"a": "4"}, "a = 4 is outside its domain (angle"),
        ("param a half_angle\nA = point (a, 0)", {"a": "pi/2"}, "outside its domain (half_angle"),
    ],
)
def test_replay_refuses_bad_values(text, values, what):
    with pytest.raises(InputError, match=re.escape(what)):
        replay(parse(text, "t.gc"), values)


def test_replay_needs_every_parameter():
    with pytest.raises(InputError, match="no value for the parameter 'a'"):
        replay(parse(EVERY_OP), {"b": 1})


# -- the shipped recipe ---------------------------------------------------------------------
def _same_protocol(a, b):
    assert a.names == b.names
    assert a.skipped == b.skipped
    for x, y in zip(a.steps, b.steps):
        for f in (
            "index",
            "name",
            "op",
            "instrument",
            "inputs",
            "obj",
            "conditions",
            "caption",
            "ref",
            "params",
            "key",
            "role",
            "n",
        ):
            assert getattr(x, f) == getattr(y, f), (x.name, f)
    assert a.steps == b.steps


@pytest.mark.parametrize("preset", PRESETS)
def test_shipped_recipe_is_todays_protocol(preset):
    g = Grasp.preset(preset)
    _same_protocol(replay(paper_program(), g), _internal_force_diagram_from_specs(g))


def test_shipped_recipe_is_todays_protocol_symbolic():
    g = Grasp.symbolic("mu")
    c = replay(paper_program(), g)
    _same_protocol(c, _internal_force_diagram_from_specs(g))
    assert "envelope" not in c and c.conditions


GRASP_VALUES = st.fixed_dictionaries(
    dict(
        x1=st.integers(1, 40),
        x2=st.integers(1, 40),
        y=st.integers(0, 40),
        phi1=st.integers(1, 24),
        phi2=st.integers(1, 24),
        mu1=st.integers(1, 30),
        mu2=st.integers(1, 30),
    )
)


def _grasp(v, floats):
    """A grasp from small integers: lengths in tenths, φ in multiples of π/24, μ in tenths."""
    if floats:
        return Grasp(
            v["x1"] / 10,
            v["x2"] / 10,
            v["y"] / 10,
            v["phi1"] * math.pi / 24,
            v["phi2"] * math.pi / 24,
            mu1=v["mu1"] / 10,
            mu2=v["mu2"] / 10,
        )
    return Grasp(
        f"{v['x1']}/10",
        f"{v['x2']}/10",
        f"{v['y']}/10",
        f"{v['phi1']}*pi/24",
        f"{v['phi2']}*pi/24",
        mu1=f"{v['mu1']}/10",
        mu2=f"{v['mu2']}/10",
    )


@pytest.mark.parametrize("floats", [False, True], ids=["exact", "float"])
# two grasps in three break condition (1) and are skipped: not a sign of a bad strategy
@settings(
    max_examples=12,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(values=GRASP_VALUES)
def test_shipped_recipe_is_todays_protocol_on_random_grasps(floats, values):
    try:
        g = _grasp(values, floats)
    except InvalidGraspError:
        assume(False)
    _same_protocol(replay(paper_program(), g), _internal_force_diagram_from_specs(g))


def test_shipped_recipe_text_and_claims():
    text = paper_text()
    assert text.startswith("# The internal force diagram")
    p = paper_program()
    assert [q.name for q in p.params] == ["x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"]
    assert p.hypotheses == ("condition1",)
    kinds = {c.kind for c in p.claims}
    assert kinds == {"equal", "on", "perpendicular", "collinear", "sign"}
    v1 = p.claims[0]
    assert v1.terms[0] == Ref("V1") and isinstance(v1.terms[1], PointValue)


def test_recipe_replays_with_a_mapping():
    vals = {"x1": 2, "x2": 2, "y": 1, "phi1": "pi/2", "phi2": "pi/2", "mu1": "1.0", "mu2": "1.2"}
    a = replay(paper_program(), vals)
    b = internal_force_diagram(Grasp.preset("table1a"))
    assert all(a[n] == b[n] for n in a.names if n != "envelope")


# -- round trip and builder -----------------------------------------------------------------
@pytest.mark.parametrize("text", [EVERY_OP, None])
def test_round_trip(text):
    p = paper_program() if text is None else parse(text)
    again = parse(p.to_text())
    assert again == p
    assert again.to_text() == p.to_text()


def test_builder_gives_the_same_program_and_construction():
    b = ConstructionBuilder()
    b.param("a", "positive")
    for line in EVERY_OP.splitlines()[1:]:
        m = re.match(r"(\S+) = (\S+)([^(#]*)(?:\((.*?)\))?", line)
        values = [v.strip() for v in m.group(4).split(",")] if m.group(4) else []
        b.step(m.group(1), m.group(2), *m.group(3).split(), values=values)
    b.claim("equal", "V", ("-2", "a"))
    b.claim("collinear", "A", "B", "X")
    b.claim("sign", "s - a", "0", relation=">")
    prog = b.build()
    text = EVERY_OP + "claim V == point(-2, a)\nclaim collinear A B X\nclaim sign s - a > 0\n"
    assert prog == parse(text)
    assert replay(prog, {"a": 3}).steps == replay(parse(text), {"a": 3}).steps


def test_builder_refuses_like_the_parser():
    b = ConstructionBuilder()
    b.step("A", "point", values=(0, 0))
    with pytest.raises(ConstructionSyntaxError, match="<builder>:2:0: wrong kind of input"):
        b.step("m", "meet", "A", "A")
    with pytest.raises(ConstructionSyntaxError, match="duplicate name 'A'"):
        b.step("A", "point", values=(1, 0))
    with pytest.raises(ConstructionSyntaxError, match="bad value"):
        b.step("B", "point", values=("__import__('os')", 0))
    with pytest.raises(ConstructionSyntaxError, match="unknown name 'q' in a value"):
        b.step("B", "point", values=(sp.Symbol("q"), 0))
    with pytest.raises(ConstructionSyntaxError, match="unknown operation"):
        b.step("B", "circle", "A")


def test_claims_are_data():
    p = parse(
        "param a > 0\nhypothesis condition1\nA = point (a, 0)\nB = point (0, a)\n"
        "l = line_through A B\ns = signed_length A B l\n"
        "claim A == point(a, 0)\nclaim s == sqrt(2)*a\nclaim on A l\n"
        "claim sign s - a >= 0 under condition1\nclaim parallel l l\n"
    )
    kinds = [(c.kind, c.relation, c.under) for c in p.claims]
    assert kinds == [
        ("equal", "==", ()),
        ("equal", "==", ()),
        ("on", "", ()),
        ("sign", ">=", ("condition1",)),
        ("parallel", "", ()),
    ]
    s = sp.Symbol("s", real=True)
    assert p.claims[1].terms[1] == Value(sqrt(2) * p.params[0].symbol)
    assert p.claims[3].terms[0] == Value(s - p.params[0].symbol)


# -- parse errors: each kind, with line and column ----------------------------------------
BASE = "A = point (0, 0)\nl = line_with_direction A (1, 0)\n"
ERRORS = [
    # line 4 of the file, with ^ before the column the error must name; part of the message
    ("X = meet l ^m", "unknown name 'm'"),
    ("X = meet l ^A", "wrong kind of input: meet takes a line as input 2, got the point"),
    ("X = ^meat l l", "unknown operation 'meat' (did you mean 'meet'?)"),
    ("^A = point (1, 1)", "duplicate name 'A' (first defined on line 1)"),
    ("B = point (1, ^foo)", "bad value: cannot read 'foo'"),
    ("B = point ^(1)", "point takes 2 value(s)"),
    ("X = meet ^l", "meet takes 2 input(s) (line, line), got 1"),
    ("X = meet l l ^l", "too many inputs"),
    ("B = point (1, 2) role ^hero", "unknown role 'hero'"),
    ('B = point (1, 2) ^"cap', "unterminated string"),
    ("B = point ^(1, 2", "unbalanced parenthesis"),
    ("B = point (1, 2) ^$", "unexpected character '$'"),
    ("^key = point (1, 2)", "'key' is a reserved word"),
    ("param q ^between", "unknown domain 'between'"),
    ("hypothesis ^lucky", "unknown hypothesis 'lucky'"),
    ("B = intersect_line_circle l ^l (0)", "wrong kind of input"),
    ("B = point (1, 2) ^extra", "unexpected 'extra'"),
    ("claim collinear A ^l A", "wrong kind of input: claim collinear takes a point"),
    ("claim A == ^l", "wrong kinds: cannot compare a point with a line"),
    ("claim ^Q == A", "unknown name 'Q'"),
    ("claim sign 1 > 0 under ^lucky", "unknown hypothesis 'lucky'"),
    ("claim ^whatever", "a claim is NAME == TERM"),
    ("just ^words", "expected NAME = OPERATION"),
    ("let k = ^1 +", "bad value"),
    ("B = point (1, 2) ^(3)", "the values go in one pair of parentheses"),
    ("B = point (1, 2) ^ref", "write ref"),
]


@pytest.mark.parametrize("marked, what", ERRORS)
def test_parse_error_names_file_line_and_column(marked, what):
    line4 = marked.replace("^", "")
    with pytest.raises(ConstructionSyntaxError) as info:
        parse(BASE + "# a comment\n" + line4 + "  # trailing\n", file="bad.gc")
    err = info.value
    col = marked.index("^") + 1
    assert (err.file, err.line, err.column) == ("bad.gc", 4, col), str(err)
    assert what in err.what
    assert str(err) == f"bad.gc:4:{col}: {err.what}"
    assert isinstance(err, InputError) and "\n" not in str(err)


def test_branch_value_checked():
    text = (
        "A = point (0, 0)\nB = point (1, 0)\nc = circle_through A B\n"
        "X = intersect_circles c c (2)\n"
    )
    with pytest.raises(ConstructionSyntaxError) as info:
        parse(text)
    assert (info.value.line, info.value.column) == (4, 28)
    assert "a branch is 0 or 1, got 2" in info.value.what


def test_limits():
    with pytest.raises(ConstructionSyntaxError, match=":1:1001: the line is longer"):
        parse("# " + "x" * 1200)
    with pytest.raises(ConstructionSyntaxError, match="more than 10000 lines"):
        parse("\n" * 10_001)
    with pytest.raises(TypeError):
        parse(b"A = point (0, 0)")  # type: ignore[arg-type]


# -- fuzz: only ConstructionSyntaxError or a Program -------------------------------------------
WORDS = [
    "A",
    "B",
    "l",
    "c",
    "X",
    "=",
    "==",
    "point",
    "meet",
    "foot",
    "line_through",
    "circle_through",
    "intersect_circles",
    "(0, 0)",
    "(1, 2)",
    "(0)",
    "(1",
    ")",
    "(",
    '"cap"',
    '"',
    "ref",
    "role",
    "V",
    "1",
    "key",
    "optional",
    "param",
    "> 0",
    "angle",
    "hypothesis",
    "condition1",
    "let",
    "claim",
    "collinear",
    "on",
    "sign",
    "under",
    "#",
    "x-axis",
    "-",
    "sqrt(2)",
    "(pi/3, 10**99999)",
    "(x, )",
    "\\",
    "envelope",
    "é",
    "\t",
    "(sin(a), cos(a))",
    ">",
    "<=",
    "point(1, 2)",
    "9" * 30,
]
PREFIX = (
    "param a angle\nhypothesis condition1\nA = point (0, 0)\nB = point (1, 0)\n"
    "l = line_through A B\nc = circle_through A B\n"
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.lists(st.sampled_from(WORDS), max_size=9).map(" ".join), max_size=4))
def test_fuzz_parser_only_refuses_with_its_error(lines):
    text = PREFIX + "\n".join(lines)
    t0 = time.perf_counter()
    with hang_bound(20):
        try:
            prog = parse(text, "fuzz.gc")
        except ConstructionSyntaxError as err:
            assert str(err).startswith("fuzz.gc:") and "\n" not in str(err)
        else:
            assert isinstance(prog, Program)
            assert parse(prog.to_text()) == prog
    assert time.perf_counter() - t0 < 20


# -- the command line module ------------------------------------------------------------------
def _args(*argv):
    from graspcompass.cli import _recipe as _cli_recipe

    parser = argparse.ArgumentParser(prog="graspcompass")
    sub = parser.add_subparsers(dest="command")
    _cli_recipe.register(sub, lambda p: None)
    return _cli_recipe, parser.parse_args(["recipe", *argv])


def test_cli_recipe_prints_the_shipped_file(capsys):
    mod, args = _args()
    assert mod.run(args) == 0
    assert capsys.readouterr().out == paper_text()


def test_cli_recipe_writes_a_file(tmp_path, capsys):
    mod, args = _args("-o", str(tmp_path / "mine.gc"))
    assert mod.run(args) == 0
    assert (tmp_path / "mine.gc").read_text("utf-8") == paper_text()
    assert "wrote" in capsys.readouterr().out
    mod, args = _args("-o", str(tmp_path / "missing" / "x.gc"))
    with pytest.raises(InputError.__mro__[1]):  # OutputError: a GraspCompassError
        mod.run(args)


def test_paper_steps_are_the_programs_steps():
    """The replay's quick parse (claims and let values left out) reads every step, its
    values and their conditions as the whole program does (a fresh parse of each)."""
    from graspcompass.construction import language

    language._paper_steps.cache_clear()
    quick, whole = language._paper_steps(), language.parse(language.paper_text(), "paper.gc")
    assert quick.steps == whole.steps and quick.params == whole.params
    assert quick.hypotheses == whole.hypotheses
    assert not quick.claims and not quick.lets and whole.claims and whole.lets
