"""The exact refinement of a plan: the best edge pairs, optimised over their continuous parameters.

:func:`refine_plan` takes the edge pairs of the best sampled pairs of a
:class:`~graspcompass.planning.PlanResult` and, for each, proves the least
worst-case squeeze over every force-closure pair of points of the two edges
(:func:`graspcompass.planning._exact.refine_edge_pair`: branch and bound with
outward-rounded interval lower bounds of ``m g max_n |V_n| / (x1 + x2)``,
eqs. (17), (28)-(39), condition (1); or, under a tilt range, of
``max(0, max_n M_n + A|V_n|) / (x1 + x2)``).  What each result proves is in
:meth:`ExactPair.claim`: the hypotheses (the edges, condition (1), the
orientations, the float data), the tolerance, and whether the least squeeze is
approached on the boundary of condition (1).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from ._exact import DEFAULT_TOL, EdgePair, Load, refine_edge_pair

__all__ = ["METHOD", "ExactPair", "refine_plan"]

#: How the exact optimum is backed (printed with every result).
METHOD = (
    "branch and bound over the two edge parameters (s, t) with interval lower bounds "
    "(outward rounded) of the closed form; proved within the relative tolerance"
)


@dataclasses.dataclass(frozen=True)
class ExactPair:
    """The proved best pair of contacts along one pair of edges.

    Attributes
    ----------
    rank : int
        1 for the least squeeze among the refined edge pairs.
    edges : (int, int)
        The two edges (indices in :attr:`PlanResult.outline`, edge k from vertex k
        to k + 1).
    params : (float, float)
        Where along each edge (0 at its first vertex, 1 at the next).
    contacts, normals : tuple of (float, float)
        The contacts (metres) and the edges' inward unit normals.
    squeeze : float
        The squeeze at these contacts, newtons (per jaw or total as the plan):
        an upper bound of the least squeeze along the edge pair.
    lower_bound : float
        Proved: no force-closure pair of points of these edges needs less.
    tol : float
        The relative tolerance asked; ``certified``:
        ``squeeze − lower_bound <= tol · squeeze``.
    certified : bool
        The proof closed within ``tol`` (False: the search hit its box limit;
        ``lower_bound`` still holds).
    sampled_squeeze : float
        The best sampled pair on these two edges (``nan`` if none is force-closure).
    boxes : int
        Boxes bounded by the search.
    cone_margin : float
        How far inside condition (1) the reported pair is, radians: the least angle
        between the line of contact and a side of either friction cone.
    on_boundary : bool
        The least squeeze is approached on the boundary of condition (1)
        (``cone_margin <= 1e-6`` rad): under a tilt range the squeeze stays finite
        there; no force-closure pair attains the infimum, the reported pair
        (just inside, at the edge of a friction cone: no margin for error in μ or
        in placing the jaws) is within ``tol`` of it.
    orientations : str
        The orientations of the worst case (:meth:`PlanResult.orientations`).
    """

    rank: int
    edges: tuple[int, int]
    params: tuple[float, float]
    contacts: tuple[tuple[float, float], tuple[float, float]]
    normals: tuple[tuple[float, float], tuple[float, float]]
    squeeze: float
    lower_bound: float
    tol: float
    certified: bool
    sampled_squeeze: float
    boxes: int
    cone_margin: float = math.nan
    on_boundary: bool = False
    orientations: str = "every orientation"

    def claim(self) -> str:
        """What is proved, with its hypotheses, in one sentence."""
        i, j = self.edges
        out = (
            f"every pair of points of edges {i} and {j} meeting condition (1) (force closure) "
            f"needs at least {self.lower_bound:.9g} N to hold the part in {self.orientations}"
            f" (outward-rounded interval bounds on the float data)"
        )
        if not self.certified:
            return out + f"; not closed: the search stopped with the gap above tol = {self.tol:g}"
        out += (
            f"; the pair reported needs {self.squeeze:.9g} N, within tol = {self.tol:g} of "
            f"the least"
        )
        if self.on_boundary:
            out += (
                " (the least is approached on the boundary of condition (1), where a "
                "contact is at the edge of a friction cone, and attained by no "
                "force-closure pair)"
            )
        return out

    @property
    def improvement(self) -> float:
        """``1 − squeeze / sampled_squeeze``: the fraction saved over the best sample."""
        return 1.0 - self.squeeze / self.sampled_squeeze

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dictionary."""
        imp = self.improvement
        return {
            "rank": self.rank,
            "edges": list(self.edges),
            "params": list(self.params),
            "contacts_m": [list(p) for p in self.contacts],
            "normals": [list(n) for n in self.normals],
            "squeeze_N": self.squeeze,
            "lower_bound_N": self.lower_bound,
            "tolerance": self.tol,
            "certified": self.certified,
            "sampled_squeeze_N": _num(self.sampled_squeeze),
            "improvement": _num(imp),
            "boxes": self.boxes,
            "cone_margin_rad": _num(self.cone_margin),
            "on_boundary": self.on_boundary,
            "proves": self.claim(),
        }


def _num(v: float) -> float | None:
    return v if math.isfinite(v) else None


def _param(p: np.ndarray, a: np.ndarray, e: np.ndarray) -> np.ndarray:
    return ((p - a) @ e) / float(e @ e)


def refine_plan(
    plan: Any,
    count: int,
    load: Load,
    scale: float,
    tol: float = DEFAULT_TOL,
    orientations: str = "every orientation",
) -> tuple[ExactPair, ...]:
    """Refine the ``count`` best distinct edge pairs of ``plan`` (best sampled pairs first).

    Parameters
    ----------
    plan : PlanResult
    count : int
        How many edge pairs.
    load : Load
        The orientations and loads (:class:`graspcompass.planning._exact.Load`).
    scale : float
        Newtons per unit of q: ``S_f m`` per jaw, twice that for the total.
    tol : float
        Relative tolerance of each proof.
    orientations : str
        How the orientations are described in :meth:`ExactPair.claim`.

    Returns
    -------
    tuple of ExactPair
        Sorted by squeeze.
    """
    ring, edges = np.asarray(plan.outline), np.asarray(plan.edges)
    chosen: list[tuple[int, int]] = []
    for k in plan.order:
        pair = tuple(sorted((int(edges[plan.i[k]]), int(edges[plan.j[k]]))))
        if pair not in chosen:
            chosen.append(pair)  # type: ignore[arg-type]
        if len(chosen) >= count:
            break
    ei, ej = edges[plan.i], edges[plan.j]
    out = []
    for ea, eb in chosen:
        a0, a1, b0, b1 = ring[ea], ring[ea + 1], ring[eb], ring[eb + 1]
        ep = EdgePair.of(a0, a1, b0, b1, plan.com, plan.mu)
        # the sampled pairs on these edges, as (s, t) starting points
        fwd = (ei == ea) & (ej == eb)
        rev = (ei == eb) & (ej == ea)
        pa = np.concatenate([plan.points[plan.i[fwd]], plan.points[plan.j[rev]]])
        pb = np.concatenate([plan.points[plan.j[fwd]], plan.points[plan.i[rev]]])
        st = np.stack([_param(pa, a0, a1 - a0), _param(pb, b0, b1 - b0)], axis=-1)
        sampled = np.concatenate([plan.squeeze[fwd], plan.squeeze[rev]])
        best_sampled = float(np.nanmin(sampled)) if np.isfinite(sampled).any() else math.nan
        opt = refine_edge_pair(ep, load, tol=tol, start=st)
        if opt is None:
            continue
        pts = ep.points(opt.s, opt.t)
        out.append(
            ExactPair(
                0,
                (int(ea), int(eb)),
                (opt.s, opt.t),
                (tuple(map(float, pts[0])), tuple(map(float, pts[1]))),  # type: ignore[arg-type]
                ep.normals(),
                opt.value * scale,
                opt.lower * scale,
                opt.tol,
                opt.certified,
                best_sampled,
                opt.boxes,
                opt.margin,
                opt.on_boundary,
                orientations,
            )
        )
    out.sort(key=lambda p: p.squeeze)
    return tuple(dataclasses.replace(p, rank=r + 1) for r, p in enumerate(out))
