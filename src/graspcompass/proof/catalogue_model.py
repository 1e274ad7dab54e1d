"""Claims of §2 (the model): eqs. (2)-(25), each checked as a whole statement.

Claims that mix the μ form and the ξ form are checked with μ_i = tan ξ_i
substituted (eq. (22)), so that a counterexample is a point of the model in
the ξ variables.
"""

from __future__ import annotations

import functools
import itertools
import time
from fractions import Fraction

import sympy as sp

from ..symbols import F_e, mu1, mu2, phi1, phi2, x1, x2, xi1, xi2, y
from . import paper as P
from .catalogue_core import (
    H22,
    Claim,
    conjunction,
    identity,
    sign,
    sign_lemma,
    with_xi,
)
from .prove import ProofResult, Status, prove_identity

__all__ = ["DIVISOR", "DIV_WITNESS", "ineq", "model_claims"]

k = P.k_symbol
_NF = sp.symbols("N1 F1 N2 F2", real=True)


def ineq(n: int) -> sp.Expr:
    """The left side of inequality (8), (9), (10) or (11) with F = F_T + k F_N (16)."""
    N1, F1, N2, F2 = P.F_T_printed + k * P.F_N_printed
    return (mu1 * N1 - F1, mu2 * N2 - F2, mu1 * N1 + F1, mu2 * N2 + F2)[n - 1]


#: the divisor of k_n in (18)-(21)
DIVISOR = {1: mu1 * P.s1 - P.c1, 2: mu2 * P.s2 - P.c2, 3: mu1 * P.s1 + P.c1, 4: mu2 * P.s2 + P.c2}
#: factors of the divisor (with μ = tan ξ) whose signs follow from (1)
DIV_WITNESS = {
    1: [-1, sp.cos(phi1 + xi1), 1 / sp.cos(xi1)],
    2: [-1, sp.cos(phi2 + xi2), 1 / sp.cos(xi2)],
    3: [sp.cos(phi1 - xi1), 1 / sp.cos(xi1)],
    4: [sp.cos(phi2 - xi2), 1 / sp.cos(xi2)],
}
_INEQ = {1: "(8)", 2: "(9)", 3: "(10)", 4: "(11)"}
_K = {1: "(18)", 2: "(19)", 3: "(20)", 4: "(21)"}


def _rot_cw(a: sp.Expr) -> sp.Matrix:
    return sp.Matrix([[sp.cos(a), sp.sin(a)], [-sp.sin(a), sp.cos(a)]])


def first_principles_L() -> sp.Matrix:
    """L from the frame of §2.2.1: (0, −1) turned by φ1 clockwise / φ2 counter-clockwise
    is the normal, a quarter turn further (towards the other contact's side) the tangent;
    row 3 is the moment p × f about O."""
    down = sp.Matrix([0, -1])
    n1, n2 = _rot_cw(phi1) * down, _rot_cw(-phi2) * down
    t1, t2 = _rot_cw(sp.pi / 2) * n1, _rot_cw(-sp.pi / 2) * n2
    cols = []
    for p, f in (((x1, y), n1), ((x1, y), t1), ((-x2, y), n2), ((-x2, y), t2)):
        cols.append([f[0], f[1], p[0] * f[1] - p[1] * f[0]])
    return sp.Matrix(cols).T


def _LLt() -> sp.Matrix:
    return sp.Matrix([[2, 0, -2 * y], [0, 2, x1 - x2], [-2 * y, x1 - x2, x1**2 + x2**2 + 2 * y**2]])


def _eq24_25(factors: list[Claim], signs: list[Claim]) -> ProofResult:
    """Own logic of (24)-(25): sign transfer through a positive factor, and the least k."""
    t0 = time.perf_counter()
    d, t = sp.Symbol("d", positive=True), sp.Symbol("t", positive=True)
    pre = sp.Symbol("pre", positive=True)
    own = [
        sign_lemma(F_e / (x1 + x2), (1, 1), "F_e/(x1 + x2) > 0"),
        sign_lemma(pre * d * t, (1, 1), "positive factor × (k − k_n) > 0 when k > k_n"),
        sign_lemma(pre * d * -t, (-1, -1), "… < 0 when k < k_n"),
        _least_k(),
    ]
    return conjunction(
        [*factors, *signs],
        "each of (8)-(11) is F_e/(x1 + x2) · d_n · (k − k_n) "
        "with d_n > 0 (lemmas), so (8)-(11) ⇔ k > k_n for all n; the set "
        "{k ≥ 0 : k > k_n ∀n} has infimum max(k1..k4, 0) (all order types)",
        t0,
        own,
    )


def _least_k() -> ProofResult:
    """inf{k ≥ 0 : k > k_n, n = 1..4} = max(k1, k2, k3, k4, 0), on every order type.

    Both sides depend on the order type of (k1, k2, k3, k4, 0) only; each order type
    (ties included) is realised by integer values in [-4, 4].  For each, the set is
    computed exactly by cells: the breakpoints {0, k_n} cut the line into points and
    open gaps on each of which every constraint has one truth value, decided at the
    cell's representative (the point, a midpoint, or a point beyond the ends); the
    infimum is the left end of the first cell in the set.
    """
    t0 = time.perf_counter()
    seen: set[tuple[int, ...]] = set()
    for ks in itertools.product(range(-4, 5), repeat=4):
        order = tuple(sorted(set(ks) | {0}))
        key = tuple(order.index(v) for v in (*ks, 0))
        if key in seen:
            continue
        seen.add(key)
        inf = _least_in_set(ks, order)
        if inf != max(*ks, 0):
            return ProofResult(
                Status.UNDECIDED,
                "order types",
                time.perf_counter() - t0,
                detail=f"fails at {ks}: infimum {inf}",
            )
    return ProofResult(
        Status.PROVED,
        f"all {len(seen)} order types of (k1..k4, 0), each set decided cell by cell",
        time.perf_counter() - t0,
    )


def _least_in_set(ks: tuple[int, ...], cuts: tuple[int, ...]) -> Fraction | None:
    """inf{k : k ≥ 0, k > k_n ∀n} from the cells of the sorted breakpoints ``cuts``;
    None when the set is empty or unbounded below."""

    def member(k: Fraction) -> bool:
        return k >= 0 and all(k > v for v in ks)

    if member(Fraction(cuts[0] - 1)):  # the cell (-oo, cuts[0])
        return None
    for i, b in enumerate(cuts):  # the point {b}, then the gap (b, next cut) or (b, oo)
        nxt = cuts[i + 1] if i + 1 < len(cuts) else b + 2
        if member(Fraction(b)) or member(Fraction(b + nxt, 2)):
            return Fraction(b)
    return None


def _abs_decomposition(i: int) -> ProofResult:
    """|F_i| < μ_i N_i ⇔ (8)/(10) (i = 1) or (9)/(11) (i = 2), and then N_i > 0.

    Case F ≥ 0 (|F| = F): the pair is μN − F > 0, since it implies μN + F > 0.
    Case F ≤ 0 (|F| = −F): the pair is μN + F > 0, since it implies μN − F > 0.
    """
    t0 = time.perf_counter()
    N, F = _NF[2 * i - 2], _NF[2 * i - 1]
    mu = (mu1, mu2)[i - 1]
    p, q = sp.Symbol("p", positive=True), sp.Symbol("q", positive=True)
    f0, f1 = sp.Symbol("f0", nonnegative=True), sp.Symbol("f1", nonpositive=True)
    parts = [
        # N = ((μN − F) + (μN + F)) / (2μ): the identity, then the sign with p, q > 0
        prove_identity(N, ((mu * N - F) + (mu * N + F)) / (2 * mu)),
        sign_lemma((p + q) / (2 * mu), (1, 1), "(p + q)/(2μ) > 0"),
        # F ≥ 0: |F| = F, μN + F = (μN − F) + 2F; F ≤ 0: |F| = −F, μN − F = (μN + F) − 2F
        prove_identity(mu * N + F, (mu * N - F) + 2 * F),
        sign_lemma(p + 2 * f0, (1, 1), "F ≥ 0: μN − F > 0 ⇒ μN + F > 0"),
        prove_identity(mu * N - F, (mu * N + F) - 2 * F),
        sign_lemma(q - 2 * f1, (1, 1), "F ≤ 0: μN + F > 0 ⇒ μN − F > 0"),
    ]
    return conjunction([], "(8)+(10) = 2 μ N; case split on the sign of F", t0, parts)


def model_claims() -> list[Claim]:
    """The claims of §2."""
    C: list[Claim] = []
    add = C.append
    NF = sp.Matrix(_NF)
    add(
        Claim(
            "eq5",
            "eq. (5)",
            "L is the grasp matrix: its columns are the unit normal (φ1 "
            "clockwise, φ2 counter-clockwise from −y) and unit tangential forces at P1 = "
            "(x1, y), P2 = (−x2, y) with their moments about O; L31..L34 as printed",
            identity(lambda: P.L_printed, first_principles_L),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq2-4",
            "eqs. (2)-(4)",
            "L F = M (all three rows) says: the contact forces "
            "plus F_e e(θ) at O sum to zero, and their moments about O sum to zero",
            identity(
                lambda: P.L_printed * NF - P.M_printed,
                lambda: first_principles_L() * NF + sp.Matrix([*(F_e * P.e_printed), 0]),
            ),
            hypotheses=(),
        )
    )
    rank = [
        Claim(
            "rank-LLt",
            "§2.3",
            "L Lᵀ is the matrix used for L†",
            identity(lambda: P.L_printed * P.L_printed.T, _LLt),
            printed=False,
            hypotheses=(),
        ),
        Claim(
            "rank-det",
            "§2.3",
            "det(L Lᵀ) = 2 (x1 + x2)²",
            identity(lambda: _LLt().det(), lambda: 2 * P.D**2),
            printed=False,
            hypotheses=(),
        ),
    ]
    add(
        Claim(
            "rank-L",
            "§2.3",
            "L Lᵀ has det 2 (x1 + x2)² > 0, so L has rank 3 and L† = Lᵀ(L Lᵀ)⁻¹",
            lambda: conjunction(
                rank,
                "lemmas + sign",
                time.perf_counter(),
                [sign_lemma(2 * (x1 + x2) ** 2, (1, 1), "2 (x1 + x2)² > 0")],
            ),
            printed=False,
            depends=tuple(rank),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq12-13",
            "eqs. (12)-(13)",
            "F_T = Lᵀ(L Lᵀ)⁻¹ M is the printed vector (13)",
            identity(lambda: P.L_printed.T * _LLt().inv() * P.M_printed, lambda: P.F_T_printed),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq14-15",
            "eqs. (14)-(15)",
            "I − L†L = F_N F_Nᵀ / |F_N|², so (I − L†L)κ = k F_N with F_N of (15), and L F_N = 0",
            lambda: conjunction(
                [],
                "matrix identities",
                time.perf_counter(),
                [
                    prove_identity(
                        sp.eye(4) - P.L_printed.T * _LLt().inv() * P.L_printed,
                        P.F_N_printed * P.F_N_printed.T / (P.F_N_printed.T * P.F_N_printed)[0],
                    ),
                    prove_identity(P.L_printed * P.F_N_printed),
                ],
            ),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq14-15-orth",
            "eqs. (14)-(15)",
            "F_T ⊥ F_N",
            identity(lambda: (P.F_T_printed.T * P.F_N_printed)[0]),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq16",
            "eq. (16)",
            "F = F_T + k F_N solves L F = M for every k",
            identity(
                lambda: P.L_printed * (P.F_T_printed + k * P.F_N_printed), lambda: P.M_printed
            ),
            hypotheses=(),
        )
    )
    add(
        Claim(
            "eq6-7",
            "§2.2.4",
            "(8) and (10) imply N1 > 0 (6); (9) and (11) imply N2 > 0 "
            "(7); and (8), (10) [(9), (11)] together are |F_i| < μ_i N_i",
            lambda: conjunction(
                [],
                "both contacts",
                time.perf_counter(),
                [_abs_decomposition(1), _abs_decomposition(2)],
            ),
            hypotheses=("μ_i > 0",),
        )
    )
    factors, signs = [], []
    for n in (1, 2, 3, 4):
        add(
            Claim(
                f"eq{17 + n}-mu",
                f"eq. {_K[n]}, first line",
                f"k{n}(θ) (μ form) is where the friction inequality {_INEQ[n]} becomes an equality",
                identity(lambda n=n: ineq(n).subs(k, P.k_mu_printed[n - 1])),
                hypotheses=(),
            )
        )
        add(
            Claim(
                f"eq{17 + n}-tan",
                f"eq. {_K[n]}, second line, (22)",
                f"the tan form of k{n}(θ) equals its μ form with tan ξ = μ",
                identity(
                    lambda n=n: P.k_tan_printed[n - 1], lambda n=n: with_xi(P.k_mu_printed[n - 1])
                ),
                hypotheses=(H22,),
            )
        )
        fac = Claim(
            f"eq{7 + n}-factor",
            f"eqs. {_INEQ[n]}, {_K[n]}",
            f"{_INEQ[n]} reads (F_e/(x1 + x2))·d{n}·(k − k{n}), d{n} its divisor",
            identity(
                lambda n=n: ineq(n),
                lambda n=n: F_e / P.D * DIVISOR[n] * (k - P.k_mu_printed[n - 1]),
            ),
            printed=False,
            hypotheses=(),
        )
        sgn = Claim(
            f"eq{7 + n}-divisor-sign",
            f"eqs. {_INEQ[n]}, {_K[n]}, (1)",
            f"the divisor d{n} = {DIVISOR[n]} is positive under (1) with μ = tan ξ, "
            f"so {_INEQ[n]} holds exactly when k > k{n}",
            functools.partial(_divisor_sign, n),
            printed=False,
            hypotheses=("condition (1)", H22),
        )
        factors.append(fac)
        signs.append(sgn)
        add(fac)
        add(sgn)
    add(
        Claim(
            "eq24-25",
            "eqs. (24)-(25)",
            "all of (8)-(11) hold exactly when k > k_n for every "
            "n (24), so the least k ≥ 0 (the infimum) is k_grasp = max(k1, k2, k3, k4, 0) (25)",
            lambda: _eq24_25(factors, signs),
            depends=(*factors, *signs),
            hypotheses=("condition (1)", H22, "k ≥ 0"),
        )
    )
    C.extend(_eq23_claims())
    return C


def _eq23_claims() -> list[Claim]:
    out = []
    for sg, word in ((1, "upper"), (-1, "lower")):
        pm, mp = ("+", "−") if sg == 1 else ("−", "+")
        s_, c_, mu = P.s1, P.c1, mu1
        out.append(
            Claim(
                f"eq23-printed-{word}",
                "eq. (23), first equality as printed",
                f"(c μ {pm} s)/(s μ {mp} c) = (s {pm} c μ)/(c {mp} s μ)",
                identity(
                    lambda sg=sg, s_=s_, c_=c_, mu=mu: (c_ * mu + sg * s_) / (s_ * mu - sg * c_),
                    lambda sg=sg, s_=s_, c_=c_, mu=mu: (s_ + sg * c_ * mu) / (c_ - sg * s_ * mu),
                ),
                corrected_by=f"eq23-corrected-{word}",
                note="a sign is lost: the two sides differ by a factor −1",
                hypotheses=(),
            )
        )
        out.append(
            Claim(
                f"eq23-corrected-{word}",
                "eq. (23), corrected",
                f"(c μ {pm} s)/(s μ {mp} c) = −tan(φ {pm} ξ) (μ = tan ξ); the tan forms of "
                "(18)-(21) carry this minus sign and are right",
                identity(
                    lambda sg=sg: with_xi((P.c1 * mu1 + sg * P.s1) / (P.s1 * mu1 - sg * P.c1)),
                    lambda sg=sg: -sp.tan(phi1 + sg * xi1),
                ),
                printed=False,
                hypotheses=(H22,),
            )
        )
        out.append(
            Claim(
                f"eq23-rest-{word}",
                "eq. (23), other equalities",
                f"(s {pm} c μ)/(c {mp} s μ) = (s/c {pm} μ)/(1 {mp} (s/c) μ) = (tan φ {pm} tan ξ)/"
                f"(1 {mp} tan φ tan ξ) = tan(φ {pm} ξ), for i = 1, 2, where c_i ≠ 0",
                functools.partial(_eq23_rest, sg),
                hypotheses=("condition (1)", H22, "cos φ_i ≠ 0"),
            )
        )
    return out


def _divisor_sign(n: int) -> ProofResult:
    """The divisor d_n of inequality n is positive under condition (1), μ = tan ξ."""
    return sign(with_xi(DIVISOR[n]), +1, DIV_WITNESS[n])


def _eq23_rest(sg: int) -> ProofResult:
    t0 = time.perf_counter()
    parts = []
    implied = []
    for phi, xi, mu in ((phi1, xi1, mu1), (phi2, xi2, mu2)):
        s_, c_, t = sp.sin(phi), sp.cos(phi), sp.tan(xi)
        chain = [
            (s_ + sg * c_ * mu) / (c_ - sg * s_ * mu),
            (s_ / c_ + sg * mu) / (1 - sg * (s_ / c_) * mu),
            (sp.tan(phi) + sg * t) / (1 - sg * sp.tan(phi) * t),
            sp.tan(phi + sg * xi),
        ]
        chain = [with_xi(m) for m in chain]
        parts += [prove_identity(a, b) for a, b in itertools.pairwise(chain)]
        # the denominators other than cos φ_i: cos(φ ± ξ) ≠ 0 and cos ξ ≠ 0 follow from (1)
        w = sp.cos(phi + sg * xi)
        parts.append(sign(w, -sg, [w]))
        parts.append(sign(sp.cos(xi), +1, [sp.cos(xi)]))
        implied += [f"cos({phi} {'+' if sg == 1 else '-'} {xi}) != 0", f"cos({xi}) != 0"]
    r = conjunction(
        [], "polynomial reduction of each equality; signs of the denominators", t0, parts
    )
    cond = tuple(dict.fromkeys((*r.conditions, "cos(phi1) != 0", "cos(phi2) != 0")))
    return ProofResult(
        r.status,
        r.method,
        r.seconds,
        r.counterexample,
        r.detail,
        r.values,
        r.hypotheses,
        cond,
        tuple(dict.fromkeys((*r.implied, *implied))),
        r.certificate,
    )
