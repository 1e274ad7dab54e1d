"""Claims of §4.2 and §5: Table I, where V1..V4 lie (Fig. 8), and the robust grasp.

Fig. 8: let α ∈ (0, π/2] be the angle of O_M − P1 clockwise from −y (equally of
O_M − P2 counter-clockwise), so (x1 + x2)/2 = r sin α, y = r cos α, r > 0.  Cone 1
is the set of directions at angles in (φ1 − ξ1, φ1 + ξ1) clockwise from −y; all
three angles lie in (−π/2, 3π/2), a window shorter than a turn, so O_M is
strictly inside cone 1 exactly when φ1 − ξ1 < α < φ1 + ξ1, on its lower side
when α = φ1 − ξ1, and strictly outside otherwise.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable

import sympy as sp

from ..symbols import phi1, phi2, theta, x1, x2, xi1, xi2, y
from . import paper as P
from .catalogue_core import Claim, conjunction, propositional, sign, sign_lemma
from .prove import ProofResult, Status, prove_identity

__all__ = ["FIG8_GOALS", "fig8_case", "rel1", "section5_claims", "table1_signs"]

pi = sp.pi


def rel1(*extra: sp.Basic) -> list[sp.Basic]:
    """Condition (1) and the angle domains as relations, plus ``extra`` (for samples)."""
    rels: list[sp.Basic] = []
    for phi, xi in ((phi1, xi1), (phi2, xi2)):
        rels += [
            phi + xi > pi / 2,
            phi + xi < 3 * pi / 2,
            phi - xi < pi / 2,
            phi - xi > -pi / 2,
            phi <= pi,
            xi < pi / 2,
        ]
    return rels + list(extra)


def _tan_sc(expr: sp.Expr) -> sp.Expr:
    return expr.replace(sp.tan, lambda u: sp.sin(u) / sp.cos(u))


def _v1v2(extra_iv: dict | None, hyp: str) -> list[ProofResult]:
    S1, S2 = (_tan_sc(s) for s in P.S_printed[:2])
    C1, C2 = (_tan_sc(c) for c in P.C_printed[:2])
    iv = extra_iv or {}
    out = []
    for e, sg in ((C1, -1), (C2, -1), (S1, -1), (S2, +1)):
        out.append(sign(e, sg, [e], iv, hypothesis=hyp))
        if out[-1].status is Status.REFUTED:  # a false conjunct: the rest is not needed
            break
    return out


def _v1v2_corrected() -> ProofResult:
    t0 = time.perf_counter()
    hyp = "φ_i + ξ_i < π"
    iv = {phi1 + xi1: (pi / 2, pi), phi2 + xi2: (pi / 2, pi)}
    parts = _v1v2(iv, hyp)
    # 0 < φ_i < π/2 (the §5 example) implies φ_i + ξ_i < π, since ξ_i < π/2
    ok = pi / 2 + pi / 2 <= pi  # sup φ_i + sup ξ_i, both intervals open
    parts.append(
        ProofResult(
            Status.PROVED if ok else Status.UNDECIDED,
            "interval endpoints: φ_i, ξ_i in (0, π/2) give φ_i + ξ_i < π",
            0.0,
            hypotheses=("0 < φ_i < π/2",),
        )
    )
    # and φ_i + ξ_i < π is needed: for φ_i + ξ_i in (π, 3π/2), C_i > 0
    for i, (phi, xi) in enumerate(((phi1, xi1), (phi2, xi2))):
        c = _tan_sc(P.C_printed[i])
        parts.append(
            sign(c, +1, [c], {phi + xi: (pi, 3 * pi / 2)}, hypothesis=f"π < φ{i + 1} + ξ{i + 1}")
        )
    return conjunction(
        [], "witness signs on the intervals (π/2, π) of φ_i + ξ_i; S1 < 0 < S2", t0, parts
    )


def _max_v(deps: list[Claim]) -> ProofResult:
    t0 = time.perf_counter()
    a, b = sp.symbols("a b", real=True)
    s, c = sp.sin(theta), sp.cos(theta)
    R, W, m = (sp.Symbol(n, nonnegative=True) for n in ("R", "W", "m"))
    t, g = sp.Symbol("t", positive=True), sp.Symbol("g", positive=True)
    own = [
        # Lagrange: |V|² − (V·e)² = (V × e)², with |e| = 1
        prove_identity(a**2 + b**2 - (a * s - b * c) ** 2, (a * c + b * s) ** 2),
        # t = V·e ≤ 0: R − t = R + |t| ≥ 0;  t > 0: R − t = (R² − t²)/(R + t) = W/(R + t) ≥ 0
        sign_lemma(R + m, (0, 1), "R − t ≥ 0 when t ≤ 0"),
        prove_identity((R - t) * (R + t), R**2 - t**2),
        sign_lemma(W / (R + t), (0, 1), "R − t ≥ 0 when t > 0"),
        # k − k_n = (k − R) + (R − t) > 0
        sign_lemma(g + R, (1, 1), "k − k_n = (k − |V_n|) + (|V_n| − k_n) > 0"),
    ]
    return conjunction(deps, "Cauchy–Schwarz via Lagrange's identity; then eq24-25", t0, own)


def fig8_side(n: int) -> ProofResult:
    """sign(V_n.x) = sign(α − (φ_i − ξ_i)) (n = 4) or its negative (n = 3), α < φ_i + ξ_i."""
    t0 = time.perf_counter()
    r, al = sp.Symbol("r", positive=True), sp.Symbol("alpha", positive=True)
    h = (x1 + x2) / 2
    if n == 3:
        u = phi1 - xi1
        lhs, rhs = P.S_printed[2] * sp.cos(u), y * sp.sin(u) - h * sp.cos(u)
        polar = prove_identity(
            rhs.subs({y: r * sp.cos(al), x2: 2 * r * sp.sin(al) - x1}), r * sp.sin(u - al)
        )
    else:
        u = phi2 - xi2
        lhs, rhs = P.S_printed[3] * sp.cos(u), h * sp.cos(u) - y * sp.sin(u)
        polar = prove_identity(
            rhs.subs({y: r * sp.cos(al), x2: 2 * r * sp.sin(al) - x1}), r * sp.sin(al - u)
        )
    v = (phi1 + xi1) if n == 3 else (phi2 + xi2)
    parts = [
        prove_identity(lhs, rhs),
        polar,
        sign(sp.cos(u), +1, [sp.cos(u)]),  # V_n.x has the sign of r sin(±(u − α))
        _interval_check(u, v),
    ]
    return conjunction(
        [],
        "V.x cos u = ±r sin(u − α) (polynomial reduction), cos u > 0 by "
        "(1); u − α ∈ (−π, π/2) so sin(u − α) has the sign of u − α; "
        "α ≤ π/2 < φ + ξ",
        t0,
        parts,
    )


def _interval_check(u: sp.Expr, v: sp.Expr) -> ProofResult:
    """u ∈ (−π/2, π/2), α ∈ (0, π/2], v ∈ (π/2, 3π/2) (condition (1)):
    u − α ∈ (−π, π/2) ⊂ (−π, π) and v − α ∈ (0, 3π/2), by endpoint arithmetic."""
    t0 = time.perf_counter()
    ulo, uhi, alo, ahi, vlo = -pi / 2, pi / 2, sp.Integer(0), pi / 2, pi / 2
    ok = (ulo - ahi >= -pi) and (uhi - alo <= pi) and (vlo - ahi >= 0)
    return ProofResult(
        Status.PROVED if ok else Status.UNDECIDED,
        "interval endpoints (open at u, v; α > 0)",
        time.perf_counter() - t0,
    )


#: Fig. 8 (a), (b), (c): premise ⇒ conclusion over the atoms below
FIG8_GOALS: dict[str, tuple[str, Callable[[dict], bool], Callable[[dict], bool]]] = {
    "a": (
        "O_M strictly inside both cones: V3 in x < 0, V4 in x > 0",
        lambda v: v["in1"] and v["in2"],
        lambda v: v["L3"] and v["R4"],
    ),
    "b": (
        "O_M strictly outside both cones: V3 in x > 0, V4 in x < 0",
        lambda v: v["out1"] and v["out2"],
        lambda v: v["R3"] and v["L4"],
    ),
    "c": (
        "O_M strictly inside one cone and strictly outside the other: V3, V4 both in "
        "x > 0 or both in x < 0",
        lambda v: (v["in1"] and v["out2"]) or (v["out1"] and v["in2"]),
        lambda v: (v["L3"] and v["L4"]) or (v["R3"] and v["R4"]),
    ),
}
_ATOMS = ("in1", "on1", "out1", "in2", "on2", "out2", "L3", "Z3", "R3", "L4", "Z4", "R4")


def _one(*xs: bool) -> bool:
    return sum(xs) == 1


def _fig8_facts(v: dict) -> bool:
    return (
        _one(v["in1"], v["on1"], v["out1"])
        and _one(v["in2"], v["on2"], v["out2"])
        and _one(v["L3"], v["Z3"], v["R3"])
        and _one(v["L4"], v["Z4"], v["R4"])
        # fig8-V3: V3.x < 0 ⇔ inside cone 1, = 0 ⇔ on it, > 0 ⇔ outside
        and v["L3"] == v["in1"]
        and v["Z3"] == v["on1"]
        and v["R3"] == v["out1"]
        # fig8-V4: V4.x > 0 ⇔ inside cone 2, = 0 ⇔ on it, < 0 ⇔ outside
        and v["R4"] == v["in2"]
        and v["Z4"] == v["on2"]
        and v["L4"] == v["out2"]
    )


def fig8_case(
    premise: Callable[[dict], bool], goal: Callable[[dict], bool], deps: list[Claim]
) -> ProofResult:
    """premise ⇒ goal from the two biconditionals (claims ``deps``), by truth tables."""
    t0 = time.perf_counter()
    own = propositional(
        _ATOMS,
        lambda v: _fig8_facts(v) and premise(v),
        goal,
        "the two biconditionals and trichotomy ⇒ the case",
    )
    return conjunction(deps, "follows from fig8-V3, fig8-V4 by a propositional check", t0, [own])


def table1_signs(case: str) -> tuple[int, int]:
    """sign(V3.x), sign(V4.x) for Table I case ``case``, exactly, from (36), (38)."""
    (p1x, p1y), f1, m1, (p2x, p2y), f2, m2 = P.TABLE_I[case]
    if p1y != p2y:
        raise ValueError("Table I: P1 and P2 at different heights")
    subs = {x1: p1x, x2: -p2x, y: p1y, phi1: f1, phi2: f2, xi1: sp.atan(m1), xi2: sp.atan(m2)}
    out = []
    for n in (3, 4):
        val = P.S_printed[n - 1].subs(subs)  # exact: tan(π/2 ∓ atan m) evaluates to ±1/m
        if not val.is_Rational:
            raise ValueError(f"Table I ({case}): S{n} = {val} is not an exact rational")
        out.append(int(sp.sign(val)))
    return out[0], out[1]


def _table1() -> ProofResult:
    t0 = time.perf_counter()
    from ..grasp import Grasp
    from ..symbols import mu1, mu2

    sg = {c: table1_signs(c) for c in "abc"}
    ok = sg["a"] == (-1, 1) and sg["b"] == (1, -1) and sg["c"] == (1, 1)
    for c in "abc":  # the presets are Table I
        (p1x, p1y), f1, m1, (p2x, _), f2, m2 = P.TABLE_I[c]
        g = Grasp.preset(f"table1{c}").params
        want = {x1: p1x, x2: -p2x, y: p1y, phi1: f1, phi2: f2, mu1: m1, mu2: m2}
        ok &= all(g[str(s)] == w or sp.simplify(g[str(s)] - w) == 0 for s, w in want.items())
    return ProofResult(
        Status.PROVED if ok else Status.REFUTED,
        "exact arithmetic on the printed Table I values; presets compared",
        time.perf_counter() - t0,
        detail="" if ok else f"signs {sg}",
    )


def section5_claims(eq27: list[Claim], eq24: Claim) -> list[Claim]:
    """The claims of §4.2 and §5."""
    C: list[Claim] = []
    add = C.append
    add(
        Claim(
            "s4-table1-V3V4",
            "§4.2, Table I, Fig. 7",
            "with Table I's values: in (a) V3 "
            "points left (x < 0) and V4 right; in (b) both directions are switched; in (c) "
            "both V3 and V4 face right (x > 0); the presets table1a-c are Table I",
            _table1,
            hypotheses=(),
        )
    )
    add(
        Claim(
            "s5-V1V2-printed",
            "§5 as printed",
            "under the contact point conditions as "
            "quoted there (φ_i + ξ_i > π/2 of (1)), V1, V2 lie in y < 0 and V1 left of V2",
            lambda: conjunction([], "witness signs", time.perf_counter(), _v1v2(None, "")),
            corrected_by="s5-V1V2-corrected",
            note="§5 quotes (1) as π/2 < φ_i + ξ_i < π, but (1) allows up to 3π/2; "
            "e.g. φ1 = 19π/24, ξ1 = 5π/12 gives C1 > 0 (V1 in y > 0)",
        )
    )
    add(
        Claim(
            "s5-V1V2-corrected",
            "§5, corrected",
            "under (1) and φ_i + ξ_i < π (implied by "
            "§5's 0 < φ_i < π/2), V1, V2 lie in y < 0 with S1 < 0 < S2 (V1 left of V2); "
            "φ_i + ξ_i < π is needed: for π < φ_i + ξ_i, C_i > 0",
            _v1v2_corrected,
            printed=False,
            hypotheses=("condition (1)", "φ_i + ξ_i < π"),
        )
    )
    eq27 = list(eq27)
    add(
        Claim(
            "s5-robust",
            "§5 (end)",
            "if k > max_n |V_n|, then k > k_n(θ) for every n and "
            "θ (|V_n·e| ≤ |V_n|, |e| = 1), so (8)-(11) hold and the object is held in every "
            "orientation",
            lambda: _max_v([*eq27, eq24]),
            depends=(*eq27, eq24),
            hypotheses=("condition (1)", "k > |V_n| (n = 1..4)"),
        )
    )
    fig = []
    for n, word in ((3, "P1"), (4, "P2")):
        lt, gt = ("<", ">") if n == 3 else (">", "<")
        c = Claim(
            f"fig8-V{n}",
            "§5, Fig. 8",
            (
                f"V{n} lies in x {lt} 0 exactly when O_M is strictly inside the friction cone at "
                f"{word}, in x {gt} 0 exactly when strictly outside, on the y-axis when O_M is on "
                f"its lower side; condition (1) suffices (0 < φ_i < π/2 is not needed)"
            ),
            functools.partial(fig8_side, n),
        )
        fig.append(c)
        add(c)
    for case, (text, premise, goal) in FIG8_GOALS.items():
        add(
            Claim(
                f"fig8{case}",
                f"§5, Fig. 8({case})",
                text,
                functools.partial(fig8_case, premise, goal, fig),
                depends=tuple(fig),
                note="'otherwise' in §5 read strictly: with O_M on a cone side one of V3, "
                "V4 is on the y-axis"
                if case == "c"
                else "",
            )
        )
    return C
