"""Claims of the n-contact extension (issue 25), proved like the paper's.

For the symbolic two-contact grasp with the paper's k (the LP of docs/ncontact.md
written here from first principles: edges along the cone sides of §2.2.2, costs
``∓(x1 + x2)/2 · d_x`` from eq. (17), wrenches about O):

* ``nc2-Vn``: the dual vertex of the basis {side n, both sides of the other
  contact} (Cramer's rule, ``G_B^T y = c_B``, q = -(y_1, y_2)) is V_n of (28)-(39);
* ``nc2-Vn-dual``: that basis is dual feasible: the slack of the fourth side,
  ``c_j - g_j·y``, is > 0 under condition (1) (a witness factorisation);
* ``nc2-Vn-cs``: complementary slackness: the primal solution on the basis,
  ``a_B(e) = G_B^{-1}(-e, 0)``, costs ``c_B·a_B(e) = V_n·e`` for every e (an
  identity, checked on e = (1, 0) and (0, 1): both sides are linear in e); with
  the dual feasibility this is the duality certificate: wherever ``a_B(e(θ)) >= 0``
  (the arc of V_n) the least effort is ``V_n·e(θ)``, eqs. (31)-(32);
* ``nc2-short``: the shorter recipe (recipes/short.gc) constructs these V_n
  (the checker's proof of its claims, under (1) and y ≠ 0);
* ``nc3-*`` (three contacts, symbolic): three fingers 120° apart at radius r with
  friction μ and the sum of the normal forces: the vertex of {both edges at P1,
  edge − at P2} is (1, (3 − √3μ)/(3μ + √3)) (Cramer), the three-force recipe replayed
  with the kernel constructs it (if μ² ≠ 1/3), it is dual feasible for ξ < π/3, and
  complementary slackness holds;
* ``table1c-V4-redundant``: in Table I(c), V4 = (4/7, 10/7) lies strictly inside the
  triangle V1V2V3 (exact orientation signs), so V4·e < max(V1·e, V2·e, V3·e) for every
  e ≠ 0 and circle 4 never reaches the envelope of Fig. 7(c).
"""

from __future__ import annotations

import time
from functools import cache, partial
from typing import Any

import sympy as sp

from ..symbols import mu1, mu2, phi1, phi2, x1, x2, xi1, xi2, y
from .catalogue_core import H1, Claim, conjunction
from .prove import ProofResult, Status, prove_identity, prove_sign

__all__ = ["ncontact_claims", "table1c_vertices"]

_S1, _C1, _S2, _C2 = sp.sin(phi1), sp.cos(phi1), sp.sin(phi2), sp.cos(phi2)
#: The cone sides of §2.2.2 (force directions at P1 for n = 1, 3; at P2 for n = 2, 4).
_SIDE = {
    1: (-(_S1 + _C1 * mu1), -(_C1 - _S1 * mu1)),
    3: (-(_S1 - _C1 * mu1), -(_C1 + _S1 * mu1)),
    2: (_S2 + _C2 * mu2, -(_C2 - _S2 * mu2)),
    4: (_S2 - _C2 * mu2, -(_C2 + _S2 * mu2)),
}
_KAPPA = (x1 + x2) / 2
#: V_n's basis: side n and both sides of the other contact.
BASES = {1: (1, 2, 4), 2: (2, 1, 3), 3: (3, 2, 4), 4: (4, 1, 3)}
#: Witness factorisations of the fourth side's slack (found by hand, checked by the prover).
_WITNESS = {
    1: [2, mu1, x1 + x2, -1, sp.cos(xi1), 1 / sp.cos(phi1 + xi1)],
    2: [2, mu2, x1 + x2, -1, sp.cos(xi2), 1 / sp.cos(phi2 + xi2)],
    3: [2, mu1, x1 + x2, sp.cos(xi1), 1 / sp.cos(phi1 - xi1)],
    4: [2, mu2, x1 + x2, sp.cos(xi2), 1 / sp.cos(phi2 - xi2)],
}


def _point(j: int) -> tuple:
    return (x1, y) if j in (1, 3) else (-x2, y)


def _wrench(j: int) -> sp.Matrix:
    (dx, dy), (px, py) = _SIDE[j], _point(j)
    return sp.Matrix([dx, dy, px * dy - py * dx])


def _cost(j: int) -> sp.Expr:
    """eq. (17): k = (x1 + x2)/2 · (f2x - f1x)."""
    return (-_KAPPA if j in (1, 3) else _KAPPA) * _SIDE[j][0]


def _tan(n: int) -> sp.Expr:
    s, c, m = (_S1, _C1, mu1) if n in (1, 3) else (_S2, _C2, mu2)
    return (s + c * m) / (c - s * m) if n in (1, 2) else (s - c * m) / (c + s * m)


def paper_vertex(n: int) -> tuple:
    """V_n of eqs. (28)-(39), written from the paper (μ form of (18)-(21))."""
    t = _tan(n)
    if n in (1, 3):
        return (-_KAPPA + y * t, x2 * t)
    return (_KAPPA - y * t, x1 * t)


@cache
def _basis(n: int) -> tuple:
    """``(G_B, c_B, y_B)`` of V_n's basis (Cramer's rule, factored)."""
    B = BASES[n]
    G = sp.Matrix.hstack(*[_wrench(j) for j in B])
    cb = sp.Matrix([_cost(j) for j in B])
    yb = G.T.LUsolve(cb).applyfunc(lambda v: sp.factor(sp.together(v)))
    return G, cb, yb


def _formula(n: int) -> ProofResult:
    t0 = time.perf_counter()
    _, _, yb = _basis(n)
    V = paper_vertex(n)
    parts = [prove_identity(-yb[i], V[i]) for i in range(2)]
    return conjunction([], "Cramer's rule on the basis vs (28)-(39): two identities", t0, parts)


def _dual(n: int, s: int = 1) -> ProofResult:
    _, _, yb = _basis(n)
    j = ({1, 2, 3, 4} - set(BASES[n])).pop()
    slack = sp.factor(sp.together(_cost(j) - (_wrench(j).T * yb)[0]))
    return prove_sign(slack, s, witness=_WITNESS[n])


def _cs(n: int) -> ProofResult:
    t0 = time.perf_counter()
    G, cb, _ = _basis(n)
    V = paper_vertex(n)
    parts = []
    for ex, ey in ((1, 0), (0, 1)):
        a = G.LUsolve(sp.Matrix([-ex, -ey, 0])).applyfunc(lambda v: sp.factor(sp.together(v)))
        parts.append(prove_identity((cb.T * a)[0], V[0] * ex + V[1] * ey))
    return conjunction(
        [], "primal value on the basis = V_n·e (linear in e: two identities)", t0, parts
    )


def _short() -> ProofResult:
    from importlib import resources

    from ..construction.language import parse
    from .program_check import check_program

    t0 = time.perf_counter()
    text = (resources.files("graspcompass.construction") / "recipes" / "short.gc").read_text()
    report = check_program(parse(text, "short.gc"))
    rows = report.claims
    ok = len(rows) == 4 and all(r.status is Status.PROVED for r in rows)
    conds = tuple(dict.fromkeys(c for r in rows for c in r.result.conditions))
    return ProofResult(
        Status.PROVED if ok else Status.UNDECIDED,
        "check short.gc: V1..V4 == (28)-(39)",
        time.perf_counter() - t0,
        conditions=conds,
    )


def table1c_vertices() -> tuple:
    """V1..V4 of Table I(c) from (28)-(39), exactly: P1 = (2, 2), P2 = (-2, 2), φ = π/2,
    μ1 = 1/2, μ2 = 7/5 (tan(π/2 ± ξ) = ∓1/μ)."""
    vals = {
        x1: 2,
        x2: 2,
        y: 2,
        phi1: sp.pi / 2,
        phi2: sp.pi / 2,
        mu1: sp.Rational(1, 2),
        mu2: sp.Rational(7, 5),
    }
    return tuple(
        tuple(sp.nsimplify(sp.simplify(c.subs(vals))) for c in paper_vertex(n))
        for n in (1, 2, 3, 4)
    )


def _orient(a: tuple, b: tuple, c: tuple) -> sp.Expr:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def redundant_inside(V: tuple, inner: int = 3) -> ProofResult:
    """V[inner] strictly inside the triangle of the other three (exact orientation signs)."""
    t0 = time.perf_counter()
    tri = [v for i, v in enumerate(V) if i != inner]
    p = V[inner]
    whole = _orient(*tri)
    signs = [_orient(tri[0], tri[1], p), _orient(tri[1], tri[2], p), _orient(tri[2], tri[0], p)]
    ok = whole != 0 and all(sp.sign(s) == sp.sign(whole) for s in signs)
    detail = f"V = {V}; orientations {whole}; {', '.join(str(s) for s in signs)}"
    return ProofResult(
        Status.PROVED if ok else Status.REFUTED,
        "exact orientation signs in the rationals (a strict convex combination "
        "of a non-degenerate triangle's corners has V·e < the corners' max for "
        "every e ≠ 0)",
        time.perf_counter() - t0,
        detail=detail,
    )


def _table1c() -> ProofResult:
    V = table1c_vertices()
    if V[3] != (sp.Rational(4, 7), sp.Rational(10, 7)):
        return ProofResult(
            Status.REFUTED, "V4 of Table I(c) by (38)-(39)", 0.0, detail=f"V4 = {V[3]}"
        )
    return redundant_inside(V)


# -- three contacts: three fingers 120° apart on a circle of radius r (x1), friction μ (mu1),
# the sum of the normal forces; the vertex of the basis {both edges at P1, edge - at P2}
_R3 = sp.sqrt(3)
#: The stated vertex (derived by hand from the velocity image: R = T1 + ..., turned).
Q3 = (sp.Integer(1), (3 - _R3 * mu1) / (3 * mu1 + _R3))
_XI_60 = "ξ < π/3 (μ < √3)"


def _three_fingers() -> list[tuple]:
    """(contact, point, edge direction) of the six edges: P_i = r u_i, n_i = -u_i, d = n ± μ J n."""
    us = [
        (sp.Integer(1), sp.Integer(0)),
        (-sp.Rational(1, 2), _R3 / 2),
        (-sp.Rational(1, 2), -_R3 / 2),
    ]
    out = []
    for i, (ux, uy) in enumerate(us):
        nx, ny = -ux, -uy
        for sg in (1, -1):
            out.append((i, (x1 * ux, x1 * uy), (nx - sg * mu1 * ny, ny + sg * mu1 * nx)))
    return out


_B3 = (0, 1, 3)


@cache
def _basis3() -> tuple:
    E = _three_fingers()

    def g(j: int) -> sp.Matrix:
        _, (px, py), (dx, dy) = E[j]
        return sp.Matrix([dx, dy, px * dy - py * dx])

    G = sp.Matrix.hstack(*[g(j) for j in _B3])
    yb = G.T.LUsolve(sp.Matrix([1, 1, 1])).applyfunc(lambda v: sp.factor(sp.simplify(v)))
    slacks = [sp.factor(sp.simplify(1 - (g(j).T * yb)[0])) for j in range(6) if j not in _B3]
    return G, yb, slacks


def _nc3_formula() -> ProofResult:
    t0 = time.perf_counter()
    _, yb, _ = _basis3()
    return conjunction(
        [],
        "Cramer's rule on the basis vs the stated vertex",
        t0,
        [prove_identity(-yb[i], Q3[i]) for i in range(2)],
    )


def _nc3_constructed() -> ProofResult:
    """The three-force recipe replayed with the kernel (symbolic r, μ)."""
    from .. import geometry as geo
    from ..construction.operations import OPERATIONS
    from ..geometry import Point

    t0 = time.perf_counter()
    E = _three_fingers()
    par, turn = OPERATIONS["parallel_to_points"].function, OPERATIONS["quarter_turn"].function
    O = Point(0, 0)  # noqa: E741 - the paper's name
    P1, P2 = Point(*E[0][1]), Point(*E[2][1])
    T1, T2 = Point(0, 1), Point(-_R3 / 2, -sp.Rational(1, 2))  # J^T n_i, n_i = -u_i
    edge = geo.line_with_direction(P2, Point(*E[3][2]))
    cost = geo.parallel(edge, T2)
    image = geo.meet(cost, par(P1, P2, T1))
    R = geo.meet(par(P1, O, T1), par(P2, O, image))
    q = turn(R, O)
    return conjunction(
        [],
        "kernel replay (meets, parallels, quarter turn) vs the stated vertex",
        t0,
        [prove_identity(q.x, Q3[0]), prove_identity(q.y, Q3[1])],
    )


def _nc3_dual(s: int = 1) -> ProofResult:
    from .signs import CONDITION_1

    t0 = time.perf_counter()
    _, _, slacks = _basis3()
    iv = dict(CONDITION_1)
    iv[xi1] = (0, sp.pi / 3)
    iv[sp.pi / 3 - xi1] = (0, sp.pi / 3)
    den = 1 / (3 * mu1 + _R3)
    witnesses = [
        [12, mu1, den],
        [3, _R3 * mu1 + 1, 2 * sp.sin(sp.pi / 3 - xi1), 1 / sp.cos(xi1), den],
        [3 * _R3, mu1**2 + 1, den],
    ]
    parts = [
        prove_sign(e, s, witness=w, intervals=iv, assumptions=[mu1 < _R3])
        for e, w in zip(slacks, witnesses)
    ]
    return conjunction([], "the three other edges' slacks > 0 (witnesses)", t0, parts)


def _nc3_cs() -> ProofResult:
    t0 = time.perf_counter()
    G, _, _ = _basis3()
    parts = []
    for ex, ey in ((1, 0), (0, 1)):
        a = G.LUsolve(sp.Matrix([-ex, -ey, 0])).applyfunc(lambda v: sp.factor(sp.simplify(v)))
        parts.append(prove_identity(a[0] + a[1] + a[2], Q3[0] * ex + Q3[1] * ey))
    return conjunction(
        [], "primal value on the basis = q·e (linear in e: two identities)", t0, parts
    )


def ncontact_claims() -> list[Claim]:
    """The claims of the n-contact extension, in order."""
    out: list[Claim] = []
    for n in (1, 2, 3, 4):
        other = "P2" if n in (1, 3) else "P1"
        out.append(
            Claim(
                f"nc2-V{n}",
                "docs/ncontact.md, eqs. (28)-(39)",
                f"the n-contact LP with the paper's k: the dual vertex of the basis "
                f"{{side {n}, both sides at {other}}} is V{n} of (28)-(39)",
                partial(_formula, n),
                printed=False,
            )
        )
        out.append(
            Claim(
                f"nc2-V{n}-dual",
                "docs/ncontact.md",
                f"V{n}'s basis is dual "
                "feasible: the remaining side's slack is > 0 under condition (1)",
                partial(_dual, n),
                printed=False,
            )
        )
        out.append(
            Claim(
                f"nc2-V{n}-cs",
                "docs/ncontact.md, eqs. (31)-(32)",
                f"complementary slackness: the primal solution on V{n}'s basis costs "
                f"V{n}·e for every load direction e; with the dual feasibility, "
                f"k(θ) = V{n}·e(θ) wherever that solution is >= 0 (the arc of V{n})",
                partial(_cs, n),
                printed=False,
            )
        )
    out.append(
        Claim(
            "nc2-short",
            "recipes/short.gc",
            "the shorter recipe (four parallels and a "
            "quarter turn a vertex) constructs V1..V4 of (28)-(39)",
            _short,
            printed=False,
            hypotheses=(H1, "y ≠ 0"),
        )
    )
    three = "three fingers 120° apart at radius r, friction μ, the sum of the normal forces"
    out.append(
        Claim(
            "nc3-vertex",
            "docs/ncontact.md",
            f"{three}: the dual vertex of the basis "
            "{both edges at P1, edge − at P2} is q = (1, (3 − √3μ)/(3μ + √3))",
            _nc3_formula,
            printed=False,
            hypotheses=(),
        )
    )
    out.append(
        Claim(
            "nc3-constructed",
            "docs/ncontact.md, recipe",
            f"{three}: the three-force "
            "recipe (cost line, two parallels, a quarter turn) constructs that q",
            _nc3_constructed,
            printed=False,
            hypotheses=(),
        )
    )
    out.append(
        Claim(
            "nc3-dual",
            "docs/ncontact.md",
            f"{three}: the basis is dual feasible (the other three edges' slacks > 0) for ξ < π/3",
            _nc3_dual,
            printed=False,
            hypotheses=(_XI_60,),
        )
    )
    out.append(
        Claim(
            "nc3-cs",
            "docs/ncontact.md",
            f"{three}: complementary slackness: the "
            "primal solution on the basis costs q·e for every e (so the least effort "
            "is q·e(θ) wherever it is >= 0)",
            _nc3_cs,
            printed=False,
            hypotheses=(),
        )
    )
    out.append(
        Claim(
            "table1c-V4-redundant",
            "§4.2, Table I(c), Fig. 7(c)",
            "in Table I(c), V4 = (4/7, 10/7) lies strictly inside the triangle V1V2V3, "
            "so circle 4 never touches the envelope of Fig. 7(c)",
            _table1c,
            printed=False,
            hypotheses=(),
        )
    )
    return out


def wrong_claims() -> dict[str, Any]:
    """Deliberately false variants (for the tests): each must be REFUTED."""
    return {
        "dual-sign": lambda: _dual(1, -1),
        "inside-V1": lambda: redundant_inside(table1c_vertices(), inner=0),
        "nc3-dual-sign": lambda: _nc3_dual(-1),
    }
