"""certify proves that a construction IS the paper's drawing, and refutes wrong ones.

Mutations change one StepSpec of the recipe; the first step whose object differs
from the correct construction's (compared here numerically, without certify) must
be the first step certify does not accept, and it must be REFUTED; symbolic
refutations carry a counterexample that is checked here by hand to be a point of
the model (domains, condition (1), μ = tan ξ).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings

from conftest import float_params
from graspcompass import Grasp, internal_force_diagram
from graspcompass.construction import Construction
from graspcompass.construction.protocol import run_step
from graspcompass.construction.recipe import diagram_specs
from graspcompass.geometry import Circle, GeometryError, Line, Point
from graspcompass.proof.certify import certify, certify_records, step_facts
from graspcompass.proof.prove import Status

GIVEN_NAMES = {"O", "x-axis", "y-axis", "P1", "P2", "side1", "side2", "side3", "side4"}
#: an exact grasp that is no preset: x1 ≠ x2, y > 0, φ1 ≠ φ2, rational μ
OTHER = dict(x1="3/2", x2="1", y="1/2", phi1="pi/2", phi2="2*pi/3", mu1="1", mu2="2")


# -- building (mutated) constructions ------------------------------------------
def _mutate(specs: list, name: str, **changes: Any) -> list:
    out = []
    for s in specs:
        if s.name == name:
            if "params_from" in changes:
                src = changes.pop("params_from")
                changes["params"] = next(t.params for t in specs if t.name == src)
            s = replace(s, **changes)
        out.append(s)
    return out


def _build(grasp: Grasp, specs: list, upto: str | None = None) -> Construction:
    """Replay ``specs`` like internal_force_diagram (second intersections may be skipped)."""
    env: dict[str, Any] = {}
    steps = []
    for spec in specs:
        try:
            step = run_step(spec, env, len(steps))
        except GeometryError:
            if spec.op != "second_intersection":
                raise
            continue
        env[spec.name] = step.obj
        steps.append(step)
        if spec.name == upto:
            break
    return Construction(tuple(steps), grasp)


MUTATIONS: dict[str, tuple[str, dict]] = {
    "wrong foot (perp1 from P1x)": ("perp1", dict(inputs=("side1", "P1x"))),
    "wrong foot (perp2 from P2x)": ("perp2", dict(inputs=("side2", "P2x"))),
    "wrong cone side (X1 on side3)": ("X1", dict(inputs=("side3", "x-axis"))),
    "wrong cone side (X1 on side2)": ("X1", dict(inputs=("side2", "x-axis"))),
    "wrong sign (V1 with (1, -1))": ("V1", dict(params=(1, -1))),
    "wrong midpoint (O_M of P1x and O)": ("O_M", dict(inputs=("P1x", "O"))),
    "wrong axis (X1 on the y-axis)": ("X1", dict(inputs=("side1", "y-axis"))),
    "wrong axis (Y1 on the x-axis)": ("Y1", dict(inputs=("perp1", "x-axis"))),
    "wrong diameter (circle1 on O X1)": ("circle1", dict(inputs=("O", "X1"))),
    "wrong diameter (circle1 on V1 P1)": ("circle1", dict(inputs=("V1", "P1"))),
    "wrong contact (side1 at P2)": ("side1", dict(inputs=("P2",))),
    "wrong base point (O X1 for O_M X1)": ("OMX1", dict(inputs=("O", "X1", "x-axis"))),
    "swapped signed length (X1 O_M)": ("OMX1", dict(inputs=("X1", "O_M", "x-axis"))),
    "φ − ξ for φ + ξ (side1 along side3)": ("side1", dict(params_from="side3")),
    "tampered given point P1 = (x1, 2y)": ("P1", dict(params="double-y")),
}


def _specs(grasp: Grasp, label: str) -> tuple[list, str]:
    name, change = MUTATIONS[label]
    change = dict(change)
    if change.get("params") == "double-y":
        change["params"] = (grasp.x1, 2 * grasp.y)
    return _mutate(diagram_specs(grasp), name, **change), name


# -- independent comparison of objects (floats, no certify) -------------------------
def _num(e: Any, at: dict | None = None) -> float:
    return float(sp.N(sp.sympify(e).subs(at) if at else e, 30))


def _same(a: Any, b: Any, at: dict | None = None) -> bool:
    close = lambda u, v: abs(_num(u, at) - _num(v, at)) < 1e-9 * (1 + abs(_num(v, at)))  # noqa
    if isinstance(a, Point):
        return close(a.x, b.x) and close(a.y, b.y)
    if isinstance(a, Line):
        d, e = a.direction, b.direction
        q = b.point - a.point
        return close(d.x * e.y, d.y * e.x) and close(q.x * d.y, q.y * d.x)
    if isinstance(a, Circle):
        return _same(a.center, b.center, at) and close(a.radius2, b.radius2)
    if isinstance(a, sp.Expr):
        return close(a, b)
    return True  # the envelope: compared through its circles


def _first_difference(good: Construction, bad: Construction, at: dict | None = None):
    for s in bad.steps:
        if s.name in good and not _same(s.obj, good[s.name], at):
            return s.name
    return None


def _first_rejected(certs) -> Any:
    return next((c for c in certs if not c.result.holds), None)


def _assert_model_point(cx: dict[str, str]) -> None:
    """Domains, condition (1) and μ = tan ξ, checked by hand in floats."""
    v = {k: float(sp.N(sp.sympify(val), 30)) for k, val in cx.items()}
    assert v["x1"] > 0 and v["x2"] > 0 and v["y"] >= 0
    for i in (1, 2):
        phi = v[f"phi{i}"]
        xi = v[f"xi{i}"] if f"xi{i}" in v else math.atan(v[f"mu{i}"])
        if f"mu{i}" in v and f"xi{i}" in v:
            assert math.isclose(math.tan(v[f"xi{i}"]), v[f"mu{i}"], rel_tol=1e-12)
        assert 0 < phi <= math.pi and 0 < xi < math.pi / 2
        assert math.pi / 2 < phi + xi < 3 * math.pi / 2
        assert -math.pi / 2 < phi - xi < math.pi / 2


# -- the correct recipe ----------------------------------------------------------
@pytest.mark.parametrize("preset", ["fig6", "table1a", "table1b", "table1c"])
def test_presets_proved_and_given(preset):
    certs = certify(internal_force_diagram(Grasp.preset(preset)))
    for c in certs:
        want = Status.GIVEN if c.step in GIVEN_NAMES else Status.PROVED
        assert c.result.status is want, (c.step, c.result.detail)
        assert c.facts, c.step  # every step has facts
    facts = {f for c in certs for f in c.facts}
    assert "(A7) O_M X1 = −S1" in facts and "(A8) O Y4 = −C4" in facts
    assert any(f.startswith("arc") and "≥" in f for f in facts)  # the envelope's winners


def test_other_exact_grasp_proved():
    certs = certify(internal_force_diagram(Grasp(**OTHER)))
    assert all(c.result.status in (Status.GIVEN, Status.PROVED) for c in certs)


def test_given_steps_are_given_not_proved():
    certs = {c.step: c for c in certify(internal_force_diagram(Grasp.preset("fig6")))}
    for name in GIVEN_NAMES:
        assert certs[name].result.status is Status.GIVEN
        assert certs[name].facts
    assert any("P1" in f and "through" in f for f in certs["side1"].facts)


def test_float_grasp_is_numeric():
    g = Grasp(2.0, 2.0, 1.0, 1.5707963267948966, 1.5707963267948966, mu1=1.0, mu2=1.2)
    certs = certify(internal_force_diagram(g))
    assert {c.result.status for c in certs} == {Status.GIVEN, Status.NUMERIC}


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(float_params())
def test_random_float_grasps_are_numeric(p):
    certs = certify(internal_force_diagram(p.grasp()))
    for c in certs:
        assert c.result.status in (Status.GIVEN, Status.NUMERIC), (c.step, c.result.detail)


def test_float_grasp_tampered_beyond_tolerance_is_refuted():
    g = Grasp(2.0, 1.5, 1.0, 1.4, 1.9, mu1=1.0, mu2=1.2)
    specs = _mutate(diagram_specs(g), "P1", params=(g.x1, g.y * (1 + 1e-6)))
    certs = certify(_build(g, specs))
    assert _first_rejected(certs).step == "P1"
    assert _first_rejected(certs).result.status is Status.REFUTED


def test_records_and_step_facts():
    c = internal_force_diagram(Grasp.preset("table1a"))
    rows = certify_records(certify(c))
    assert rows[0]["step"] == "O" and rows[0]["status"] == "GIVEN"
    env = {s.name: s.obj for s in c.steps}
    facts = step_facts(c.step("V1"), env, grasp=c.grasp)
    assert [t for t, _ in facts] == [
        "V1.x = (S1, C1) of eqs. (28)-(39)",
        "V1.y = (S1, C1) of eqs. (28)-(39)",
    ]
    assert all(sp.simplify(e) == 0 for _, e in facts)


# -- mutations, numbers -------------------------------------------------------------
@pytest.mark.parametrize("label", sorted(MUTATIONS))
@pytest.mark.parametrize("where", ["fig6", "table1a", "other"])
def test_mutation_refuted_exact(label, where):
    g = Grasp(**OTHER) if where == "other" else Grasp.preset(where)
    specs, name = _specs(g, label)
    bad = _build(g, specs)
    first = _first_difference(internal_force_diagram(g), bad)
    rejected = _first_rejected(certify(bad))
    if first is None:  # e.g. O = O_M when x1 = x2: the drawing is the paper's here
        assert rejected is None
        assert where != "other", "each mutation must change the non-preset grasp"
        return
    assert first == name
    assert rejected is not None and rejected.step == first
    assert rejected.result.status is Status.REFUTED


# -- symbolic ----------------------------------------------------------------------
@pytest.fixture(scope="module")
def symbolic_mu():
    return Grasp.symbolic("mu")


def _upto(specs: list, name: str) -> str:
    """The step after which a truncated symbolic replay stops (before the break points)."""
    names = [s.name for s in specs]
    i = names.index(name)
    stop = min(i + 2, names.index("B12") - 1)
    return names[stop]


@pytest.mark.parametrize("label", sorted(MUTATIONS))
def test_mutation_refuted_symbolic(label, symbolic_mu):
    g = symbolic_mu
    specs, name = _specs(g, label)
    bad = _build(g, specs, upto=_upto(specs, name))
    certs = certify(bad)
    rejected = _first_rejected(certs)
    assert rejected is not None and rejected.step == name, [
        (c.step, c.result.status) for c in certs
    ]
    assert rejected.result.status is Status.REFUTED
    cx = rejected.result.counterexample
    assert cx
    _assert_model_point(cx)
    # at the counterexample the mutated object differs from the correct one
    at = {sp.Symbol(k, **_assumptions(k)): sp.sympify(v) for k, v in cx.items()}
    good = _build(g, diagram_specs(g), upto=name)
    assert not _same(bad[name], good[name], {s: at[s] for s in at if s.name in _NAMES}), label


_NAMES = {"x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"}


def _assumptions(name: str) -> dict:
    from graspcompass import symbols as S

    return dict(getattr(S, name).assumptions0) if hasattr(S, name) else {}


_SYMBOLIC_CERTS: dict[str, list] = {}


def _symbolic_certs(friction: str) -> list:
    if friction not in _SYMBOLIC_CERTS:
        _SYMBOLIC_CERTS[friction] = certify(internal_force_diagram(Grasp.symbolic(friction)))
    return _SYMBOLIC_CERTS[friction]


@pytest.mark.parametrize("friction", ["mu", "xi"])
def test_symbolic_recipe_proved(friction):
    certs = _symbolic_certs(friction)
    for c in certs:
        want = Status.GIVEN if c.step in GIVEN_NAMES else Status.PROVED
        assert c.result.status is want, (c.step, c.result.detail)
    by = {c.step: c for c in certs}
    # cos(φ1 + ξ1) ≠ 0 is implied by condition (1), not an extra hypothesis
    assert any("φ1+ξ1" in s for s in by["X1"].result.implied)
    assert not by["X1"].result.conditions
    assert "condition (1)" in by["V1"].result.hypotheses


@pytest.mark.parametrize(
    "angles",
    [
        {"phi1": "3*pi/5"},  # 108°: sin 108° = cos 18°, not nested radicals
        {"phi1": "3*pi/7"},  # no radicals: generators sin(π/7), cos(π/7)
        {"phi1": "6/5"},  # radians, with ξ1 = π/4
        {"phi1": "6/5", "xi1": "1/2"},  # φ1 ± ξ1 = 17/10, 7/10 rad: by the addition formula
        {"phi1": "6/5", "mu1": "1/2", "xi1": None},
    ],
)
def test_typed_angles_proved(angles):
    """Issue 19 item 7: certify at φ = 108° ran past 200 s; on the new kernel it was fast
    but UNDECIDED, the paper's model writing sin 108° with nested radicals (and sin(φ + ξ)
    as a new generator) where the grasp uses trig.sincos.  Every step holds there: the
    construction is the paper's, checked independently by the catalogue."""
    from graspcompass import PRESETS

    params = dict(PRESETS["fig6"]["params"])
    params.update(angles)
    params = {k: v for k, v in params.items() if v is not None}
    certs = certify(internal_force_diagram(Grasp(**params)))
    bad = [
        (c.step, c.result.status.value)
        for c in certs
        if c.result.status not in (Status.PROVED, Status.GIVEN)
    ]
    assert not bad
