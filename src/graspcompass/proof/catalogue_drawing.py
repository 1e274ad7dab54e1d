"""Claims of §3.2-§3.3 (the diagram and its drawing) and of the Appendix.

The drawing steps (§3.3, (A4)-(A5)) are checked on the objects that the recipe
constructs with every parameter a symbol; the circles and their intersections
(§3.2, §5) on the closed form V_n of (28)-(39), with each second intersection
B_ab built here as the foot of the perpendicular from O to V_a V_b and shown to
lie on both circles.
"""

from __future__ import annotations

import functools
import itertools
import time

import sympy as sp

from ..symbols import F_e, phi1, phi2, theta, x1, x2, xi1, xi2, y
from . import paper as P
from .catalogue_core import Claim, conjunction, early_construction, identity, sign_lemma
from .prove import ProofResult, Status, prove_identity

__all__ = ["V", "appendix_claims", "diagram_claims", "side_meet", "thales"]

_SC_EQ = {1: "(28)-(29)", 2: "(34)-(35)", 3: "(36)-(37)", 4: "(38)-(39)"}
_S_EQ = {1: "(28)", 2: "(34)", 3: "(36)", 4: "(38)"}  # O_M X_n = −S_n
_C_EQ = {1: "(29)", 2: "(35)", 3: "(37)", 4: "(39)"}  # O Y_n = −C_n
a_, b_ = sp.symbols("a b", real=True)


def V(n: int) -> sp.Matrix:
    """V_n = (S_n, C_n) of (28)-(39)."""
    return sp.Matrix([P.S_printed[n - 1], P.C_printed[n - 1]])


def _dir(n: int) -> tuple[sp.Matrix, sp.Matrix]:
    """Point and direction of cone side n (1, 3 at P1 clockwise; 2, 4 at P2 counter-cw)."""
    if n in (1, 3):
        u = phi1 + xi1 if n == 1 else phi1 - xi1
        return sp.Matrix([x1, y]), sp.Matrix([-sp.sin(u), -sp.cos(u)])
    u = phi2 + xi2 if n == 2 else phi2 - xi2
    return sp.Matrix([-x2, y]), sp.Matrix([sp.sin(u), -sp.cos(u)])


def side_meet(n: int, m: int) -> sp.Matrix:
    """Where the lines of cone sides n and m meet (Cramer's rule)."""
    (p, d), (q, e) = _dir(n), _dir(m)
    cross = d[0] * e[1] - d[1] * e[0]
    w = q - p
    t = (w[0] * e[1] - w[1] * e[0]) / cross
    return p + t * d


def thales(v: sp.Matrix) -> tuple[ProofResult, ...]:
    """For V = v and H = (V·e)e: H is the foot (on the line of e, (V − H)·e = 0), on the
    circle with diameter OV, and OH = V·e signed along e (|e| = 1)."""
    e = P.e_printed
    t = v.dot(e)
    H = t * e
    return (
        prove_identity(e.dot(e), 1),
        prove_identity((v - H).dot(e), 0),
        prove_identity(H[0] * e[1] - H[1] * e[0], 0),
        prove_identity((H - v / 2).dot(H - v / 2), v.dot(v) / 4),
        prove_identity(H.dot(e), t),
    )


def _order_types_max() -> ProofResult:
    """max({0} ∪ {k_n : k_n > 0}) = max(k1, k2, k3, k4, 0) on every order type."""
    t0 = time.perf_counter()
    n = 0
    for ks in itertools.product(range(-4, 5), repeat=4):
        n += 1
        radial = max([0, *(v for v in ks if v > 0)])
        if radial != max(*ks, 0):
            return ProofResult(
                Status.UNDECIDED, "order types", time.perf_counter() - t0, detail=f"fails at {ks}"
            )
    return ProofResult(
        Status.PROVED,
        f"all order types of (k1..k4, 0) (values in -4..4, {n} tuples)",
        time.perf_counter() - t0,
    )


def _envelope(eq27: list[Claim]) -> ProofResult:
    t0 = time.perf_counter()
    v = sp.Matrix([a_, b_])
    rho = sp.Symbol("rho", positive=True)
    e = P.e_printed
    q = rho * e - v / 2
    own = [
        *thales(v),
        # ρ e on the circle ⇔ ρ (ρ − V·e) = 0 ⇔ ρ = V·e (ρ > 0)
        prove_identity(q.dot(q) - v.dot(v) / 4, rho * (rho - v.dot(e))),
        _order_types_max(),
    ]
    return conjunction(
        eq27,
        "k_n e(θ) is on circle n; a point ρ e(θ), ρ > 0, of circle n has "
        "ρ = k_n(θ); so the farthest point of the circles (and O) in direction "
        "θ is at max(k1..k4, 0)",
        t0,
        own,
    )


def _foot_lemmas() -> list[ProofResult]:
    """For any A ≠ B (d = B − A) and Q, the foot F = A − (A·d / d·d) d of O on line AB
    lies on the circles on OA and OB, and F × Q = −(d × A)(d·Q)/(d·d)."""
    a1, a2, b1, b2, q1, q2 = sp.symbols("a1 a2 b1 b2 q1 q2", real=True)
    A, Bv, Q = sp.Matrix([a1, a2]), sp.Matrix([b1, b2]), sp.Matrix([q1, q2])
    d = Bv - A
    F = A - (A.dot(d) / d.dot(d)) * d
    return [
        prove_identity(F.dot(F - A), 0),
        prove_identity(F.dot(F - Bv), 0),
        prove_identity(
            F[0] * Q[1] - F[1] * Q[0], -(d[0] * A[1] - d[1] * A[0]) * d.dot(Q) / d.dot(d)
        ),
    ]


def _collinear(n: int, m: int) -> ProofResult:
    t0 = time.perf_counter()
    a, b = min(n, m), max(n, m)
    Q = side_meet(n, m)
    parts = [*_foot_lemmas(), prove_identity((V(b) - V(a)).dot(Q), 0)]
    r = conjunction(
        [],
        f"B{a}{b} = foot of O on V{a}V{b} is on both circles; B × Q = "
        f"−(d × V{a})(d·Q)/|d|² with d = V{b} − V{a}, and d·Q = 0",
        t0,
        parts,
    )
    return _with_conditions(r, (f"V{a} != V{b}", f"sides {n}, {m} not parallel"))


def _with_conditions(r: ProofResult, cond: tuple[str, ...]) -> ProofResult:
    return ProofResult(
        r.status,
        r.method,
        r.seconds,
        r.counterexample,
        r.detail,
        r.values,
        r.hypotheses,
        tuple(dict.fromkeys((*r.conditions, *cond))),
        r.implied,
        r.certificate,
    )


def _same_contact(a: int, b: int) -> ProofResult:
    t0 = time.perf_counter()
    Pt = sp.Matrix([-x2, y]) if a == 1 else sp.Matrix([x1, y])  # B13 on O P2, B24 on O P1
    parts = [*_foot_lemmas(), prove_identity((V(b) - V(a)).dot(Pt), 0)]
    r = conjunction([], f"as for the collinear claims, with P{2 if a == 1 else 1} for Q", t0, parts)
    return _with_conditions(r, (f"V{a} != V{b}",))


def diagram_claims(eq27_out: list[Claim]) -> list[Claim]:
    """The claims of §3.2, §3.3 and §5 about V_n, the circles and the drawing steps."""
    C: list[Claim] = []
    add = C.append
    e = P.e_printed
    for n in (1, 2, 3, 4):
        c = Claim(
            f"eq27-V{n}",
            f"eqs. (27), (32), {_SC_EQ[n]}",
            f"k{n}(θ) = V{n}·e(θ) with V{n} = (S{n}, C{n}), e(θ) = (sin θ, −cos θ)",
            identity(lambda n=n: P.k_tan_printed[n - 1], lambda n=n: V(n).dot(e)),
            hypotheses=(),
        )
        eq27_out.append(c)
        add(c)
    add(
        Claim(
            "eq31",
            "eq. (31), Fig. 3",
            "H = (V·e)e is the foot of the perpendicular from V "
            "to the line of e(θ) through O, OH = V·e = k (signed, |e| = 1), and H lies on "
            "the circle with diameter OV (Thales)",
            lambda: conjunction(
                [], "polynomial reduction", time.perf_counter(), thales(sp.Matrix([a_, b_]))
            ),
            hypotheses=(),
        )
    )
    deps = tuple(eq27_out)
    add(
        Claim(
            "s3.2-envelope",
            "§3.2 (end), (25)",
            "the polar graph of k_grasp = max(k1..k4, 0) "
            "is the outer envelope of the four circles on O V_n: in every direction θ, the "
            "farthest point of the circles (or O) is at distance k_grasp(θ)",
            lambda: _envelope(list(deps)),
            depends=deps,
            hypotheses=(),
        )
    )
    for n in (1, 2, 3, 4):
        add(
            Claim(
                f"s3.3-V{n}-OMX",
                f"§3.3 V{n} step (1), eq. {_S_EQ[n]}",
                f"On the constructed X{n} and O_M: the signed length O_M X{n} = −S{n}",
                identity(
                    lambda n=n: early_construction()[f"OMX{n}"], lambda n=n: -P.S_printed[n - 1]
                ),
            )
        )
        add(
            Claim(
                f"s3.3-V{n}-OY",
                f"§3.3 V{n} step (2), eq. {_C_EQ[n]}",
                f"On the constructed Y{n}: the signed length O Y{n} = −C{n}",
                identity(
                    lambda n=n: early_construction()[f"OY{n}"], lambda n=n: -P.C_printed[n - 1]
                ),
            )
        )
    for n, m in ((1, 2), (1, 4), (3, 2), (3, 4)):
        a, b = min(n, m), max(n, m)
        add(
            Claim(
                f"s5-collinear-{a}{b}",
                "§5, ref. 15",
                f"The second intersection B{a}{b} of circles {a} and {b} and the intersection "
                f"of cone sides {n} and {m} lie on one line through O",
                functools.partial(_collinear, n, m),
                note="statics: with both contact forces on those cone sides the three forces "
                "are concurrent, so F_e points along that line",
            )
        )
    for a, b, w in ((1, 3, "P2"), (2, 4, "P1")):
        side = "P1" if a == 1 else "P2"
        add(
            Claim(
                f"s5-same-contact-{a}{b}",
                "§5 (complement)",
                f"For two sides of the same cone (n = {a}, {b} at {side}) the second "
                f"intersection B{a}{b} of the circles lies on the line O {w}, not on a line "
                f"through the sides' meeting point {side}",
                functools.partial(_same_contact, a, b),
                printed=False,
            )
        )
    return C


def appendix_claims() -> list[Claim]:
    """(A1)-(A8)."""
    C: list[Claim] = []
    add = C.append
    T1, gam = sp.tan(phi1 + xi1), sp.pi - (phi1 + xi1)
    add(
        Claim(
            "A4",
            "eq. (A4)",
            "P1x X1 = P1 P1x · tan γ, γ = π − (φ1 + ξ1) (signed along x)",
            identity(lambda: early_construction()["X1"].x - x1, lambda: y * sp.tan(gam)),
        )
    )
    add(
        Claim(
            "A5",
            "eq. (A5)",
            "O Y1 = O P2x · tan γ",
            identity(lambda: early_construction()["Y1"].y, lambda: x2 * sp.tan(gam)),
        )
    )
    add(
        Claim(
            "A6",
            "eq. (A6)",
            "tan γ = tan(π − (φ1 + ξ1)) = −tan(φ1 + ξ1)",
            identity(lambda: sp.tan(gam), lambda: -T1),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "A7",
            "eq. (A7)",
            "O_M X1 = (x1 + x2)/2 + y·(−tan(φ1 + ξ1)) = −S1",
            identity(lambda: P.D / 2 + y * (-T1), lambda: -P.S_printed[0]),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "A8",
            "eq. (A8)",
            "O Y1 = x2·(−tan(φ1 + ξ1)) = −C1",
            identity(lambda: x2 * (-T1), lambda: -P.C_printed[0]),
            hypotheses=(),
        )
    )
    f = P.f_N_printed
    add(
        Claim(
            "A1-printed",
            "eq. (A1) as printed",
            "F_N of (15) = [f_N1 f_N2 f_N3 f_N3]ᵀ (the fourth entry printed as f_N3)",
            identity(lambda: P.F_N_printed, lambda: sp.Matrix([f[0], f[1], f[2], f[2]])),
            corrected_by="A1-corrected",
            note="an index slip, repeated in k F_N below (A1)",
            hypotheses=(),
        )
    )
    add(
        Claim(
            "A1-corrected",
            "eq. (A1), corrected",
            "F_N of (15) = [f_N1 f_N2 f_N3 f_N4]ᵀ, with f_N1..f_N4 typed from (15) entry by entry",
            identity(lambda: P.F_N_printed, lambda: sp.Matrix(f)),
            printed=False,
            hypotheses=(),
        )
    )
    add(
        Claim(
            "A2",
            "eq. (A2)",
            "F_int = k √(f_N1² + f_N2²) = k √(f_N3² + f_N4²): both "
            "contacts carry the same internal force (equal radicands)",
            identity(lambda: f[0] ** 2 + f[1] ** 2, lambda: f[2] ** 2 + f[3] ** 2),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "A3-17",
            "eqs. (A3), (17)",
            "k √(f_N1² + f_N2²) = k F_e/(x1 + x2) √(s² + c²) "
            "= k F_e/(x1 + x2): √(f_N1² + f_N2²) = F_e/(x1 + x2) since the radicand is "
            "(F_e/(x1 + x2))² and F_e/(x1 + x2) > 0; √(s² + c²) = 1",
            lambda: conjunction(
                [],
                "squares by polynomial reduction; signs",
                time.perf_counter(),
                [
                    prove_identity(f[0] ** 2 + f[1] ** 2, (F_e / P.D) ** 2),
                    sign_lemma(F_e / (x1 + x2), (1, 1), "F_e/(x1 + x2) > 0"),
                    prove_identity(sp.sin(theta) ** 2 + sp.cos(theta) ** 2, 1),
                    prove_identity(sp.sin(phi1) ** 2 + sp.cos(phi1) ** 2, 1),
                ],
            ),
            hypotheses=("k ≥ 0",),
            note="(A3) writes √(s² + c²) where √(s1² + c1²) is meant — equal to 1 either "
            "way; k ≥ 0 (§2.3) makes k |F_N part| the magnitude",
        )
    )
    return C
