"""The vertex recipe of an n-contact grasp, written in the construction language.

Each vertex q of the internal force polygon Q (:mod:`graspcompass.ncontact`) is
the quarter turn of the *velocity image* R of the centre of mass O under the dual
motion of its basis (docs/ncontact.md, "The construction of a vertex"): the
rotated velocity field is a homothety mapping each basis edge's line of action
onto its *cost line*, the parallel through the cost point ``T_i = O + J^T w_i`` of
its contact.  Two recipes (straightedge, parallels, one quarter turn):

* three-force basis (both edges of contact i, edge a of contact k): the cost line
  of a through T_k; I = (parallel to P_i P_k through T_i) ∩ that cost line (the
  image of P_k); R = (parallel to P_i O through T_i) ∩ (parallel to P_k O through I);
* general basis (three contacts): A12 = l1 ∩ l2, A13 = l1 ∩ l3, their images
  A'12, A'13 on the cost lines; R = (parallel to A12 O through A'12) ∩ (parallel to
  A13 O through A'13);

then q = R turned a quarter turn clockwise about O, and the circle on the diameter
O q is q's part of the polar diagram (eqs. (31)-(32)).  A vertex whose recipe
degenerates (O on P_i P_k, parallel edges, ...) or whose basis holds a sign
constraint is written as a given point, marked so in its caption.

The text is replayed like any construction file (``steps``, ``draw``, ``animate``,
``export``); :func:`ncontact_recipe` writes it from an
:class:`~graspcompass.ncontact.NContactGrasp`.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any

import sympy as sp

if TYPE_CHECKING:
    from ..ncontact.model import NContactGrasp

__all__ = ["ncontact_recipe"]

_TOL = 1e-9


def _txt(v: Any) -> str:
    """A value as an exact expression of the language (floats by their repr)."""
    if isinstance(v, float):
        return repr(v)
    return str(sp.sympify(v)).replace("**", "^")


def _pt(p: Any) -> str:
    return f"({_txt(p[0])}, {_txt(p[1])})"


def _f(p: Any) -> tuple[float, float]:
    return float(p[0]), float(p[1])


def _cross(a: tuple, b: tuple) -> float:
    return a[0] * b[1] - a[1] * b[0]


def _sub(a: tuple, b: tuple) -> tuple:
    return a[0] - b[0], a[1] - b[1]


def _meet_f(p: tuple, d: tuple, q: tuple, e: tuple) -> tuple | None:
    den = _cross(d, e)
    if abs(den) <= _TOL * (abs(d[0]) + abs(d[1])) * (abs(e[0]) + abs(e[1])):
        return None
    t = _cross(_sub(q, p), e) / den
    return p[0] + t * d[0], p[1] + t * d[1]


def _far(a: tuple, b: tuple, scale: float) -> bool:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) > _TOL * scale


def _at(q: Any, o: Any) -> bool:
    """q = o, exactly (floats: to 1e-12)."""
    if any(abs(float(a) - float(b)) > 1e-12 for a, b in zip(q, o)):
        return False
    return all(isinstance(a, float) or sp.simplify(sp.sympify(a) - b) == 0 for a, b in zip(q, o))


def ncontact_recipe(grasp: NContactGrasp) -> str:
    """The construction-language text of Q's vertices and their circles.

    Parameters
    ----------
    grasp : NContactGrasp
        An n-contact grasp with a linear effort (the cost points need the weights
        ``w_i``; for ``"max-normal"`` the vertices are written as given points).

    Returns
    -------
    str
        A construction file: the contacts, the cone edges (lines of action), the cost
        points, for each vertex of Q its steps, and the circles on O q.
    """
    g = grasp
    Q = g.polygon()
    n2 = 2 * g.n
    com = g.com
    lines = [
        f"# The internal force diagram of {g.n} contacts, effort {g.effort.name}: "
        "each vertex of Q as the quarter turn of the velocity image of O (docs/ncontact.md)",
        f'O = point {_pt(com)} role given ref "§2.2.1" "The centre of mass O"',
    ]
    edges = g.edges()
    for i, c in enumerate(g.contacts):
        lines.append(
            f'P{i + 1} = point {_pt(c.p)} role contact {i + 1} ref "§2.2.1" '
            f'"Contact point P{i + 1}"'
        )
    for j, (i, s, d) in enumerate(edges):
        tag = "+" if s > 0 else "−"
        lines.append(
            f"l{j + 1} = line_with_direction P{i + 1} {_pt(d)} role edge {j + 1} "
            f'ref "§2.2.2" "Edge {tag} of the friction cone at P{i + 1}: its line of '
            'action"'
        )
    linear = g.effort.linear
    weights = g.effort.weights or ()
    if linear:
        for i, w in enumerate(weights):
            t = (com[0] + w[1], com[1] - w[0])
            lines.append(
                f"T{i + 1} = point {_pt(t)} role cost_point {i + 1} ref "
                f'"docs/ncontact.md" "Cost point T{i + 1} = O + (w{i + 1} turned a '
                'quarter turn clockwise)"'
            )
    O = _f(com)  # noqa: E741 - the paper's name of the centre of mass
    P = [_f(c.p) for c in g.contacts]
    D = [_f(d) for _, _, d in edges]
    W = [(O[0] + float(w[1]), O[1] - float(w[0])) for w in weights] if linear else []
    scale = 1.0 + max(abs(v) for p in [*P, O] for v in p)
    cost_lines: set[int] = set()

    def cost_line(j: int) -> str:
        if j not in cost_lines:
            cost_lines.add(j)
            i = edges[j][0]
            lines.append(
                f"c{j + 1} = parallel l{j + 1} T{i + 1} role cost_line {j + 1} ref "
                f'"docs/ncontact.md step 1" "Cost line of edge {j + 1}: the '
                f'parallel to it through T{i + 1}"'
            )
        return f"c{j + 1}"

    def three_force(k: int, pair: tuple, a: int) -> list[str] | None:
        i, kk = edges[pair[0]][0], edges[a][0]
        Pi, Pk, Ti = P[i], P[kk], W[i]
        if not (_far(Pi, O, scale) and _far(Pk, O, scale) and _far(Pi, Pk, scale)):
            return None
        if abs(_cross(_sub(Pi, O), _sub(Pk, O))) <= _TOL * scale * scale:
            return None  # O on P_i P_k: the two transfers through O coincide
        if _meet_f(W[kk], D[a], Ti, _sub(Pk, Pi)) is None:
            return None
        cl = cost_line(a)
        pi, pk, ti = f"P{i + 1}", f"P{kk + 1}", f"T{i + 1}"
        return [
            f'm{k} = parallel_to_points {pi} {pk} {ti} role transfer {k} ref "docs/ncontact.md '
            f'step 2" "Parallel to {pi}{pk} through {ti}"',
            f'I{k} = meet {cl} m{k} role image {k} ref "docs/ncontact.md step 2" "The image '
            f'of {pk}: where {cl} meets m{k}"',
            f'o{k} = parallel_to_points {pi} O {ti} role transfer {k} ref "docs/ncontact.md '
            f'step 3" "Parallel to {pi}O through {ti}"',
            f'b{k} = parallel_to_points {pk} O I{k} role transfer {k} ref "docs/ncontact.md '
            f'step 3" "Parallel to {pk}O through I{k}"',
            f'R{k} = meet o{k} b{k} role image {k} ref "docs/ncontact.md step 3" "The image '
            f'R{k} of O"',
        ]

    def general(k: int, basis: tuple) -> list[str] | None:
        for a, b, c in itertools.permutations(basis):
            A12 = _meet_f(P[edges[a][0]], D[a], P[edges[b][0]], D[b])
            A13 = _meet_f(P[edges[a][0]], D[a], P[edges[c][0]], D[c])
            B12 = _meet_f(W[edges[a][0]], D[a], W[edges[b][0]], D[b])
            B13 = _meet_f(W[edges[a][0]], D[a], W[edges[c][0]], D[c])
            if A12 is None or A13 is None or B12 is None or B13 is None:
                continue
            if not (_far(A12, O, scale) and _far(A13, O, scale)):
                continue
            if abs(_cross(_sub(A12, O), _sub(A13, O))) <= _TOL * scale * scale:
                continue
            ca, cb, cc = cost_line(a), cost_line(b), cost_line(c)
            la, lb, lc = f"l{a + 1}", f"l{b + 1}", f"l{c + 1}"
            ref = 'ref "docs/ncontact.md, general basis"'
            return [
                f'A{k}b = meet {la} {lb} role image {k} {ref} "Where {la} meets {lb}"',
                f'A{k}c = meet {la} {lc} role image {k} {ref} "Where {la} meets {lc}"',
                f'B{k}b = meet {ca} {cb} role image {k} {ref} "Its image: where {ca} meets {cb}"',
                f'B{k}c = meet {ca} {cc} role image {k} {ref} "Its image: where {ca} meets {cc}"',
                f'o{k} = parallel_to_points A{k}b O B{k}b role transfer {k} {ref} "Parallel to '
                f'A{k}b O through B{k}b"',
                f'b{k} = parallel_to_points A{k}c O B{k}c role transfer {k} {ref} "Parallel to '
                f'A{k}c O through B{k}c"',
                f'R{k} = meet o{k} b{k} role image {k} {ref} "The image R{k} of O"',
            ]
        return None

    for k, idx in enumerate(Q.vertex_index, start=1):
        cand = Q.candidates[idx]
        steps = None
        if linear:
            for basis in cand.bases:
                es = tuple(j for j in basis if j < n2)
                if len(es) != 3:
                    continue
                owners = [edges[j][0] for j in es]
                pairs = [
                    (x, y) for x, y in itertools.combinations(es, 2) if edges[x][0] == edges[y][0]
                ]
                if pairs:
                    a = next(j for j in es if j not in pairs[0])
                    steps = three_force(k, pairs[0], a) or general(k, es)
                elif len(set(owners)) == 3:
                    steps = general(k, es)
                if steps:
                    break
        if steps:
            lines += steps
            lines.append(
                f'q{k} = quarter_turn R{k} O role V {k} key ref "docs/ncontact.md step '
                f'4" "Turn R{k} a quarter turn clockwise about O: the vertex q{k}"'
            )
        else:
            why = (
                "a sign constraint in its basis"
                if linear
                else "the effort max-normal has no cost points"
            )
            lines.append(
                f'q{k} = point {_pt(cand.q)} role V {k} key ref "docs/ncontact.md" '
                f'"The vertex q{k}, given (not constructed: {why})"'
            )
    for k, idx in enumerate(Q.vertex_index, start=1):
        if _at(Q.candidates[idx].q, com):
            lines.append(f"# q{k} = O: its circle is the point O (no effort on its arc)")
            continue
        lines.append(
            f"circle{k} = circle_on_diameter O q{k} role circle {k} key ref "
            f'"§3.2 eq. (31)-(32)" "Circle on the diameter O q{k}: q{k}\'s part of '
            'the polar diagram"'
        )
    return "\n".join(lines) + "\n"
