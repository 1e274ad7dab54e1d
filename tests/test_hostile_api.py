"""Hostile and careless input through the public API (issue 10, items 1-3, API side).

Every entry point that takes a value from outside (``Grasp(...)``, ``k``,
``k_grasp``, ``internal_force``, ``F_T``, ``F_N``, ``contact_forces``,
``external_wrench``, ``subs``, ``geometry.evaluate``, ``Point``) must:

* never run text (no ``eval``/``sympify``: a payload that would create a file
  creates none);
* accept or refuse within a bound (hang detection at 5 s per call, not a speed test);
* refuse with a named error only: a subclass of
  :class:`graspcompass.errors.GraspCompassError`, never ``TypeError``,
  ``AttributeError``, ``OverflowError`` or a silent ``nan``;
* never return a number for an invalid grasp.

Expected values come from first principles (condition (1) of the paper written
out again here, exact rationals by hand), never from the code under test.
"""

from __future__ import annotations

import math
import os
import tempfile
import warnings
from contextlib import contextmanager
from decimal import Decimal
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _hang import no_hang
from graspcompass import Grasp, Point
from graspcompass.errors import (
    ComplexValueError,
    GraspCompassError,
    InputError,
    InputTooLargeError,
    NonFiniteValueError,
    WrongTypeError,
)
from graspcompass.expr import ExpressionError
from graspcompass.geometry import evaluate
from graspcompass.grasp import InvalidGraspError
from graspcompass.inputs import (
    MAX_ARRAY_SIZE,
    angle_values,
    float_array,
    force_value,
    real_value,
    substitutions,
)

pi, R = sp.pi, sp.Rational
HANG_SECONDS = 5.0
FIG6 = dict(
    x1="sqrt(3)/2", x2="sqrt(3)/2", y="1/2", phi1="pi/3", phi2="pi/3", xi1="pi/4", xi2="pi/3"
)
FLOAT = dict(x1=2.0, x2=2.0, y=1.0, phi1=math.pi / 2, phi2=math.pi / 2, mu1=1.0, mu2=1.2)
PROPERTY = settings(
    max_examples=150, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow]
)


def bounded(what: str, seconds: float = HANG_SECONDS):
    """Fail a call still running after ``seconds`` (hang detection, not a speed test)."""
    return no_hang(what, seconds)


@contextmanager
def empty_cwd():
    """Run in a fresh empty folder; fail if anything was created in it."""
    before = os.getcwd()
    with tempfile.TemporaryDirectory() as folder:
        os.chdir(folder)
        try:
            yield Path(folder)
        finally:
            os.chdir(before)
        assert os.listdir(folder) == [], f"files created: {os.listdir(folder)}"


def named_or_value(call, what: str) -> Any:
    """Run ``call``: return its value, or None when it raised a named error; else fail."""
    with bounded(what), warnings.catch_warnings():
        warnings.simplefilter("error")  # a RuntimeWarning (overflow, invalid) is a defect too
        try:
            return call()
        except GraspCompassError:
            return None


# ----------------------------------------------------------------------- 1. no code runs


def payload(marker: Path) -> str:
    return f"__import__('os').system('touch {marker}') or 0.3"


def entry_points(text: str) -> dict[str, Any]:
    g = Grasp.preset("fig6")
    x = sp.Symbol("x")
    return {
        "Grasp(x1=...)": lambda: Grasp(**{**FIG6, "x1": text}),
        "Grasp(mu1=...)": lambda: Grasp(**{**FIG6, "xi1": None, "mu1": text}),
        "k": lambda: g.k(text),
        "k_grasp": lambda: g.k_grasp(text),
        "internal_force(theta)": lambda: g.internal_force(text),
        "internal_force(external_force)": lambda: g.internal_force(0.3, text),
        "internal_force(exact, external_force)": lambda: g.internal_force(0, text),
        "F_T": lambda: g.F_T(text),
        "F_T(external_force)": lambda: g.F_T(0.3, text),
        "F_N": lambda: g.F_N(text),
        "contact_forces(theta)": lambda: g.contact_forces(text, 1),
        "contact_forces(k)": lambda: g.contact_forces(0.3, text),
        "contact_forces(k, exact)": lambda: g.contact_forces(0, text),
        "contact_forces(external_force)": lambda: g.contact_forces(0.3, 1.0, text),
        "external_wrench": lambda: g.external_wrench(text),
        "subs": lambda: Grasp.symbolic("mu").subs({"x1": text}),
        "evaluate": lambda: evaluate(text),
        "evaluate(subs)": lambda: evaluate(Point(x, 1), {x: text}),
        "Point": lambda: Point(text, 0),
    }


@pytest.mark.parametrize("entry", sorted(entry_points("0")))
def test_text_never_runs(entry: str, tmp_path: Path) -> None:
    """Issue 10, item 1: sympify ran this text; the file was created and a number returned."""
    marker = tmp_path / "pwned"
    call = entry_points(payload(marker))[entry]
    with pytest.raises(ExpressionError) as info:
        call()
    assert "__import__" in str(info.value)
    assert not marker.exists()


def test_subs_keys_are_never_parsed(tmp_path: Path) -> None:
    marker = tmp_path / "pwned"
    g = Grasp.symbolic("mu")
    with pytest.raises(InputError, match="not a symbol"):
        g.subs({payload(marker): 1})
    assert not marker.exists()
    with pytest.raises(WrongTypeError):
        g.subs([("x1", 1)])  # not a mapping
    with pytest.raises(WrongTypeError):
        g.subs({sp.cos(sp.Symbol("x1")): 1})  # keys are symbols or names


def test_subs_by_name_and_symbol_agree() -> None:
    from graspcompass import symbols as gs

    by_name = Grasp.symbolic("mu").subs(
        {"x1": 2, "x2": 2, "y": 1, "phi1": "pi/2", "phi2": "pi/2", "mu1": "1.0", "mu2": "1.2"}
    )
    by_symbol = Grasp.symbolic("mu").subs(
        {gs.x1: 2, gs.x2: 2, gs.y: 1, gs.phi1: pi / 2, gs.phi2: pi / 2, gs.mu1: 1, gs.mu2: R(6, 5)}
    )
    assert by_name == by_symbol
    assert by_name.mu2 == R(6, 5)  # "1.2" read exactly, by hand: 12/10


# ------------------------------------------------------- 2. complex and non-finite values


def test_complex_text_parameter_is_refused() -> None:
    """Issue 10, item 2: mu1='asin(2)' was accepted and k_grasp(0) gave 3/2."""
    with pytest.raises(ComplexValueError) as info:
        Grasp(**{**FIG6, "xi1": None, "mu1": "asin(2)"})
    message = str(info.value)
    assert message.startswith("mu1: ")
    assert "asin(2) = 1.57 - 1.32*I" in message  # asin 2 = π/2 - i·ln(2 + √3), by hand


@pytest.mark.parametrize(
    ("value", "error"),
    [
        (sp.I, ComplexValueError),
        (1j, ComplexValueError),
        (np.complex128(1), ComplexValueError),
        ("sqrt(-1)", ComplexValueError),
        ("asin(2)", ComplexValueError),
        (sp.oo, NonFiniteValueError),
        (-sp.oo, NonFiniteValueError),
        (sp.zoo, NonFiniteValueError),
        (sp.nan, NonFiniteValueError),
        (float("nan"), NonFiniteValueError),
        (float("inf"), NonFiniteValueError),
        (np.float32("-inf"), NonFiniteValueError),
        (Decimal("NaN"), NonFiniteValueError),
        (None, WrongTypeError),
        (True, WrongTypeError),
        (np.bool_(False), WrongTypeError),
        ({}, WrongTypeError),
        (set(), WrongTypeError),
        (b"1", WrongTypeError),
        (object(), WrongTypeError),
        (sp.Eq(sp.Symbol("t"), 1), WrongTypeError),
        (sp.Matrix([1]), WrongTypeError),
        ("1/0", ExpressionError),
        ("tan(pi/2)", ExpressionError),
    ],
    ids=lambda v: "object()" if type(v) is object else repr(v),  # stable across processes
)
def test_k_grasp_refuses_with_a_named_error(value: Any, error: type) -> None:
    """Issue 10, item 2: these returned 0 or 0.0, or raised AttributeError / TypeError."""
    g = Grasp.preset("fig6")
    with pytest.raises(error) as info:
        g.k_grasp(value)
    assert isinstance(info.value, InputError)
    assert str(info.value).startswith("theta: ")


def test_nan_scalar_and_array_agree() -> None:
    """Issue 10, item 2: k_grasp(nan) was 0.0 while the array path gave nan; now both refuse."""
    g = Grasp.preset("table1a")
    with pytest.raises(NonFiniteValueError, match="nan"):
        g.k_grasp(float("nan"))
    with pytest.raises(NonFiniteValueError, match=r"theta\[2\] = nan"):
        g.k_grasp(np.array([0.0, 1.0, np.nan, np.nan]))
    with pytest.raises(NonFiniteValueError, match=r"theta\[0, 1\] = inf"):
        g.k(np.array([[0.0, np.inf]]))
    with pytest.raises(NonFiniteValueError):
        g.k_grasp([0.0, float("-inf")])


@pytest.mark.parametrize(
    ("theta", "error"),
    [
        (np.array([1j]), ComplexValueError),
        (np.array(["0.5"]), WrongTypeError),
        (np.array([None, 1.0], dtype=object), WrongTypeError),
        (np.array([True]), WrongTypeError),
        ([[0.0], [0.0, 1.0]], WrongTypeError),
        (["pi/2"], WrongTypeError),
        (np.array(["2000-01-01"], dtype="datetime64[D]"), WrongTypeError),
        (np.broadcast_to(np.float64(0), (MAX_ARRAY_SIZE + 1,)), InputTooLargeError),
    ],
    ids=["complex", "text", "objects", "bools", "ragged", "list-of-text", "dates", "too-large"],
)
def test_arrays_are_checked(theta: Any, error: type) -> None:
    g = Grasp.preset("table1a")
    for call in (g.k, g.k_grasp, g.internal_force, g.F_T):
        with pytest.raises(error):
            call(theta)


def test_huge_values_exact_as_text_refused_as_floats() -> None:
    """Issue 10, item 2: values of size 1e309 printed nan/inf; as text they are exact."""
    assert real_value("1e309", "x1") == sp.Integer(10) ** 309
    g = Grasp(**{**FIG6, "x1": "1e309"})
    assert g.x1 == sp.Integer(10) ** 309
    # exact θ: k_n(0) = -C_n; C_1 = x2 tan(φ1 + ξ1) is unchanged, so k_1(0) = (2 + √3)·√3/2
    assert sp.simplify(g.k(0)[0] - (2 + sp.sqrt(3)) * sp.sqrt(3) / 2) == 0
    # a float θ needs S_n = -(x1 + x2)/2 + ... as a double: 5e308 is beyond double precision
    with pytest.raises(NonFiniteValueError, match="double precision"):
        g.k_grasp(0.5)
    with pytest.raises(NonFiniteValueError, match="double precision"):
        g.F_T(0.5)
    with pytest.raises(NonFiniteValueError):
        Grasp(**{**FIG6, "x1": 1e309})  # the float 1e309 is inf
    with pytest.raises(NonFiniteValueError, match="double precision"):
        Grasp.preset("fig6").internal_force(0.5, "1e309")
    with pytest.raises(NonFiniteValueError, match="overflows"):
        Grasp.preset("fig6").internal_force(0.5, 1.7e308)  # k·F_e/D > 1.8e308


def test_exact_inputs_stay_exact() -> None:
    g = Grasp.preset("fig6")
    assert g.k_grasp("1.2") == g.k_grasp(R(6, 5))
    assert g.k_grasp("108deg") == g.k_grasp(3 * pi / 5)
    assert g.k_grasp("0") == R(3, 2) + sp.sqrt(3)  # §4.1: k_1(0) = C... = 3/2 + √3
    h = Grasp(**{**FIG6, "phi1": "108deg", "xi1": "45deg"})
    assert h.phi1 == 3 * pi / 5 and h.xi1 == pi / 4
    assert real_value("1.2", "mu1") == R(6, 5)
    assert force_value("5/2") == R(5, 2)
    assert angle_values("30deg") == pi / 6


def test_external_force_is_a_magnitude() -> None:
    g = Grasp.preset("fig6")
    with pytest.raises(InputError, match="negative"):
        g.internal_force(0, -1)
    with pytest.raises(InputError, match="negative"):
        g.F_N(-0.5)
    with pytest.raises(WrongTypeError):
        g.internal_force(0.3, [1.0, 2.0])
    with pytest.raises(NonFiniteValueError):
        g.contact_forces(0.3, 1.0, float("nan"))


def test_contact_forces_k_must_broadcast() -> None:
    g = Grasp.preset("table1a")
    with pytest.raises(InputError, match="broadcast"):
        g.contact_forces(np.zeros(3), np.zeros(4))
    with pytest.raises(NonFiniteValueError):
        g.contact_forces(np.zeros(2), [0.0, np.nan])
    with pytest.raises(WrongTypeError):
        g.contact_forces(0, None)


def test_parameter_errors_are_also_invalid_grasp_errors() -> None:
    for bad, error in (
        (None, WrongTypeError),
        (sp.I, ComplexValueError),
        (float("nan"), NonFiniteValueError),
        ([1], WrongTypeError),
    ):
        with pytest.raises(error) as info:
            Grasp(**{**FIG6, "y": bad})
        assert isinstance(info.value, InvalidGraspError)
        assert str(info.value).startswith("y: ")


def test_float_grasp_defects_found_by_the_property_tests() -> None:
    """Found by test_constructor_raises_only_named_errors / test_api_raises_only_named_errors:
    each raised TypeError (or gave inf/nan) before."""
    t = sp.Symbol("t")
    with pytest.raises(InvalidGraspError, match="symbolic"):
        Grasp(**{**FLOAT, "phi1": t})  # floats and a symbol: accepted, then TypeError in k
    with pytest.raises(NonFiniteValueError, match="double precision") as info:
        Grasp(**{**FLOAT, "mu1": 10**330})  # exact θ then compared nan: TypeError
    assert isinstance(info.value, InvalidGraspError)
    with pytest.raises(InvalidGraspError, match="1329 bits"):  # issue 22: ints as text are
        Grasp(**{**FLOAT, "mu1": 10**400})  # bounded (MAX_INT_BITS), before any work
    with pytest.raises(InputError, match="not a number"):
        Grasp.preset("table1a").contact_forces(0.3, t)  # TypeError from float(t)
    with pytest.raises(TypeError):  # still a TypeError, as documented before
        Grasp.symbolic().k(0.3)
    with pytest.raises(InputError):
        Grasp.symbolic().k(0.3)
    with pytest.raises(NonFiniteValueError):
        evaluate(sp.Integer(10) ** 309)  # was inf


def test_points_from_text_and_floats() -> None:
    assert Point("1.2", "108deg") == Point(R(6, 5), 3 * pi / 5)
    with pytest.raises(ComplexValueError):
        Point("sqrt(-1)", 0)
    with pytest.raises(NonFiniteValueError):
        Point(0, float("nan"))
    assert evaluate(Point(sp.Symbol("a"), 1), {"a": "1/4"}) == (0.25, 1.0)


def test_boundary_functions_directly() -> None:
    assert real_value(Fraction(2, 4), "a") == R(1, 2)
    assert real_value(Decimal("1.25"), "a") == R(5, 4)
    assert real_value(np.int64(7), "a") == 7
    assert real_value(np.array(3), "a") == 3
    assert float_array((1, 2), "a").dtype == np.float64
    x = sp.Symbol("x", positive=True)
    assert substitutions({"x": "pi"}, [x]) == {x: pi}
    assert substitutions({"y": 1}, [x], strict=False) == {}
    with pytest.raises(InputError):
        substitutions({"y": 1}, [x])
    with pytest.raises(WrongTypeError, match="one number"):
        real_value([1], "a")


# -------------------------------------------------------------- 4. properties (hypothesis)

GRAMMAR = [
    "1",
    "2",
    "0",
    "0.5",
    "1e309",
    "1e-309",
    "9" * 40,
    "pi",
    "deg",
    "30deg",
    "sqrt(",
    "sin(",
    "cos(",
    "tan(",
    "asin(",
    "acos(",
    "atan(",
    "atan2(",
    "(",
    ")",
    ",",
    "+",
    "-",
    "*",
    "/",
    "**",
    " ",
    "°",
    "1j",
    "x1",
    "__import__('os')",
    ".system('touch f')",
    "lambda:",
    "[",
    "]",
    "{",
    "}",
    ":",
    "'",
    '"',
    "\\",
    "\x00",
    "if",
    "else",
    "or",
]
texts = st.one_of(
    st.lists(st.sampled_from(GRAMMAR), min_size=1, max_size=25).map("".join),
    st.text(max_size=40),
)
numbers = st.one_of(
    st.integers(min_value=-(10**400), max_value=10**400),
    st.floats(allow_nan=True, allow_infinity=True),
    st.fractions(),
    st.decimals(allow_nan=True, allow_infinity=True),
    st.complex_numbers(),
)
arrays = st.one_of(
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=5).map(np.array),
    st.lists(st.integers(-5, 5), max_size=5).map(np.array),
    st.lists(st.complex_numbers(), max_size=3).map(np.array),
    st.lists(st.text(max_size=3), max_size=3).map(np.array),
    st.lists(st.booleans(), max_size=3).map(np.array),
    st.lists(st.one_of(st.none(), st.floats(), st.text(max_size=3)), max_size=3),
    st.just(np.zeros((2, 0))),
)
objects = st.sampled_from(
    [
        None,
        True,
        False,
        {},
        {"a": 1},
        set(),
        b"1",
        object(),
        sp.I,
        sp.oo,
        -sp.oo,
        sp.zoo,
        sp.nan,
        sp.Symbol("t"),
        sp.Symbol("z", complex=True),
        sp.Eq(sp.Symbol("t"), 1),
        sp.Matrix([1, 2]),
        sp.Tuple(1, 2),
        Grasp,
        np.float64("nan"),
        np.int8(-3),
        np.array(0.5),
        np.array("a"),
    ]
)
anything = st.one_of(texts, numbers, arrays, objects)


def _check_output(value: Any) -> None:
    """A returned number is finite (no silent nan or inf); arrays too."""
    if isinstance(value, (float, np.ndarray)):
        assert np.isfinite(value).all(), value
    if isinstance(value, sp.Basic):
        assert not value.has(sp.nan, sp.zoo, sp.oo, -sp.oo), value


METHODS = {
    "k": lambda g, v: g.k(v),
    "k_grasp": lambda g, v: g.k_grasp(v),
    "internal_force(theta)": lambda g, v: g.internal_force(v),
    "internal_force(force)": lambda g, v: g.internal_force(0.25, v),
    "F_T": lambda g, v: g.F_T(v),
    "F_N": lambda g, v: g.F_N(v),
    "contact_forces(theta)": lambda g, v: g.contact_forces(v, 1.5),
    "contact_forces(k)": lambda g, v: g.contact_forces(np.zeros(3), v),
    "external_wrench": lambda g, v: g.external_wrench(v),
}


@pytest.mark.parametrize("method", sorted(METHODS))
@PROPERTY
@given(value=anything)
def test_api_raises_only_named_errors(method: str, value: Any) -> None:
    g = Grasp.preset("table1a") if "contact" in method else Grasp(**FLOAT)
    with empty_cwd():
        out = named_or_value(lambda: METHODS[method](g, value), f"{method}({value!r:.60})")
    _check_output(out)


PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")


@PROPERTY
@given(name=st.sampled_from(PARAMS), value=anything)
def test_constructor_raises_only_named_errors(name: str, value: Any) -> None:
    with empty_cwd():
        g = named_or_value(lambda: Grasp(**{**FLOAT, name: value}), f"Grasp({name}={value!r:.60})")
        if g is not None:
            _check_output(named_or_value(lambda: g.k_grasp(0.3), "k_grasp(0.3)"))
            _check_output(named_or_value(lambda: g.k_grasp("1/3"), "k_grasp('1/3')"))


@PROPERTY
@given(name=st.sampled_from(PARAMS), value=anything)
def test_subs_raises_only_named_errors(name: str, value: Any) -> None:
    from graspcompass import symbols as gs

    base = {
        gs.x1: 2,
        gs.x2: 2,
        gs.y: 1,
        gs.phi1: pi / 2,
        gs.phi2: pi / 2,
        gs.mu1: 1,
        gs.mu2: R(6, 5),
    }
    given_values = {**{s: v for s, v in base.items() if s.name != name}, name: value}
    with empty_cwd():
        named_or_value(
            lambda: Grasp.symbolic("mu").subs(given_values), f"subs({name}={value!r:.60})"
        )


# condition (1) and the ranges of §2.2.1, written out again (not the code under test)
def paper_valid(p: dict[str, float]) -> bool:
    """The model's domain: x1 + x2 > 0 (a centre of mass beyond a contact is allowed,
    issue 13 §1), y >= 0, condition (1)."""
    if not (p["x1"] + p["x2"] > 0 and p["y"] >= 0):
        return False
    for i in (1, 2):
        phi, mu = p[f"phi{i}"], p[f"mu{i}"]
        if not (0 < phi <= math.pi and mu > 0):
            return False
        xi = math.atan(mu)
        if not (-math.pi / 2 < phi - xi < math.pi / 2 < phi + xi < 3 * math.pi / 2):
            return False
    return True


def _margin(p: dict[str, float]) -> float:
    """Distance of the friction data from the bounds of (1): tiny ones are left out."""
    gaps = [1.0]
    for i in (1, 2):
        phi, xi = p[f"phi{i}"], math.atan(p[f"mu{i}"]) if p[f"mu{i}"] > 0 else 0.0
        gaps += [abs(phi), abs(math.pi - phi), abs(abs(phi - math.pi / 2) - xi)]
    return min(gaps)


@PROPERTY
@given(
    x1=st.floats(-2, 3),
    x2=st.floats(-2, 3),
    y=st.floats(-1, 3),
    phi1=st.floats(-1, 4),
    phi2=st.floats(-1, 4),
    mu1=st.floats(-1, 5),
    mu2=st.floats(-1, 5),
)
def test_no_number_for_an_invalid_grasp(**p: float) -> None:
    """A grasp accepted by the constructor satisfies (1); a refused one violates it."""
    from hypothesis import assume

    assume(_margin(p) > 1e-6)
    valid = paper_valid(p)
    try:
        g = Grasp(**p)
    except InvalidGraspError:
        assert not valid, p
        return
    assert valid, p
    k = g.k_grasp(np.linspace(0, 2 * math.pi, 7))
    assert np.isfinite(k).all() and (k >= 0).all()


def test_property_folders_stay_empty(tmp_path: Path) -> None:
    """The helper itself: a created file is reported."""
    with pytest.raises(AssertionError, match="files created"), empty_cwd():
        Path("stray").write_text("x")


EXACT_TEXTS = st.lists(
    st.sampled_from(
        [
            "1",
            "2",
            "3",
            "1/3",
            "0.5",
            "pi",
            "pi/3",
            "30deg",
            "sqrt(2)",
            "sqrt(",
            "sin(",
            "cos(",
            "tan(",
            "atan(",
            "asin(",
            "acos(",
            "(",
            ")",
            "+",
            "-",
            "*",
            "/",
            "**2",
            "**(1/3)",
            "1e309",
            "1e-300",
            "9" * 30,
        ]
    ),
    min_size=1,
    max_size=12,
).map("".join)


# derandomized: the exact kernel is reached here, and its known unbounded cases (below) must
# not make CI flaky; the examples are the same on every run
@settings(PROPERTY, derandomize=True)
@given(
    name=st.sampled_from(("x1", "x2", "y", "phi1", "phi2", "xi1", "xi2")),
    text=EXACT_TEXTS,
    theta=st.sampled_from(["0", "1/3", "pi/5", "2"]),
)
def test_exact_grasp_from_text(name: str, text: str, theta: str) -> None:
    """An exact grasp with one parameter given as random text: a value or a named refusal."""
    with empty_cwd():
        g = named_or_value(lambda: Grasp(**{**FIG6, name: text}), f"Grasp({name}={text!r})")
        if g is not None:
            _check_output(named_or_value(lambda: g.k_grasp(theta), f"k_grasp({theta!r})"))
            _check_output(named_or_value(lambda: g.k_grasp(0.5), "k_grasp(0.5)"))


# Defects of the exact kernel found by the grasp fuzz of issue 10: the parser read these
# values in milliseconds, then canon() factored a radicand with an unbounded
# sympy.factorint (minutes), or cube and nested roots blew every canonical form up (hang
# or sympy's GeneratorsError).  Radicands are now split by trial division only, and
# other roots than square roots of rationals are refused in lengths and friction.
KERNEL_SLOW = [
    ("x1", "sqrt(1e300+1)"),  # was > 20 s
    ("phi2", "atan(2e30)"),  # sin, cos of atan(2e30) have the radicand 4e60 + 1: was > 10 s
    ("x1", "sqrt(18446744073709551557*18446744073709551533)"),  # two 64-bit primes: ~10 s
    ("xi1", "acos(((pi/120)/(pi/7))*((1e-30)+(2)))"),  # hung in the constructor
]
KERNEL_REFUSED = [
    ("y", "((1e-30)-(pi/120))+((2/3)**(1/3)*(sqrt(2)))"),  # hung in the envelope
    ("x2", "(acos(0.5))**(1/3)*((7/11)+(pi/3))"),  # GeneratorsError
    ("mu1", "sqrt(2+sqrt(3))"),  # GeneratorsError in internal_force_diagram
    ("mu2", "2**(1/3)"),
]


def _with(name: str, text: str) -> dict:
    params = {**FIG6, name: text}
    if name.startswith("xi"):
        params.pop("mu" + name[-1], None)
    if name.startswith("mu"):
        params.pop("xi" + name[-1], None)
    return params


@pytest.mark.parametrize(("name", "text"), KERNEL_SLOW)
def test_exact_kernel_is_bounded(name: str, text: str) -> None:
    """Huge radicands: the grasp, k_grasp and the whole exact diagram come back (hang
    detection with a generous bound, not a speed test), V_n equal to the closed form."""
    import graspcompass as gc

    with bounded(f"Grasp({name}={text!r}) and its diagram", seconds=60.0):
        g = Grasp(**_with(name, text))
        g.k_grasp("1/3")
        c = gc.internal_force_diagram(g)
        for n, v in enumerate(g.V, 1):
            assert c[f"V{n}"] == v


@pytest.mark.parametrize(("name", "text"), KERNEL_REFUSED)
def test_other_roots_are_refused_with_a_reason(name: str, text: str) -> None:
    from graspcompass.grasp import UnsupportedParameterError

    with bounded(f"Grasp({name}={text!r})", seconds=10.0):
        with pytest.raises(UnsupportedParameterError, match="square roots of rational numbers"):
            Grasp(**_with(name, text))
