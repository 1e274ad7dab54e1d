"""The results of :func:`graspcompass.planning.plan_contacts`: ranked pairs (plain data).

Private to :mod:`graspcompass.planning`, which re-exports :class:`PlannedPair` and
:class:`PlanResult` (documented and pickled there: their ``__module__``).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from ._refine import METHOD, ExactPair

__all__ = ["PlanResult", "PlannedPair"]


@dataclasses.dataclass(frozen=True)
class PlannedPair:
    """One ranked pair of contacts.

    Attributes
    ----------
    rank : int
        1 for the best (least squeeze).
    index : int
        The pair's index in :attr:`PlanResult.i`, :attr:`PlanResult.j`.
    samples : tuple of int
        The indices of its two contacts in :attr:`PlanResult.points`.
    contacts, normals : tuple of (float, float)
        The contact points (world frame, metres) and inward unit normals.
    squeeze : float
        The squeeze that holds the part in every orientation, newtons (per jaw
        or total, :attr:`PlanResult.per`).
    squeeze_per_kg : float
        The same per kilogram of mass (N/kg).
    paper : dict of float
        ``x1, x2, y, phi1, phi2`` of the pair in the paper frame (P1 the first of
        ``contacts``).
    """

    rank: int
    index: int
    samples: tuple[int, int]
    contacts: tuple[tuple[float, float], tuple[float, float]]
    normals: tuple[tuple[float, float], tuple[float, float]]
    squeeze: float
    squeeze_per_kg: float
    paper: dict[str, float]

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dictionary."""
        return {
            "rank": self.rank,
            "pair": self.index,
            "samples": list(self.samples),
            "contacts_m": [list(p) for p in self.contacts],
            "normals": [list(n) for n in self.normals],
            "squeeze_N": self.squeeze,
            "squeeze_N_per_kg": self.squeeze_per_kg,
            "paper_frame": dict(self.paper),
        }


@dataclasses.dataclass(frozen=True)
class PlanResult:
    """The contact pairs of an outline ranked by their worst-case squeeze (read-only arrays).

    Attributes
    ----------
    outline : ndarray, shape (V + 1, 2)
        The counter-clockwise exterior ring (closed) the contacts lie on.
    com : (float, float)
        The centre of mass used.
    mu, mass, g : float
        Friction coefficient of both pads, mass (kg), gravity (m/s²).
    per : {"jaw", "total"}
        Squeezes are per jaw (the paper's F_int) or both jaws together.
    points, normals : ndarray, shape (N, 2)
        The sampled contacts and their inward unit normals.
    edges : ndarray of int, shape (N,)
        Each contact's edge of :attr:`outline`.
    i, j : ndarray of int, shape (M,)
        The pairs (``i < j``), all ``N (N − 1) / 2`` of them.
    squeeze : ndarray, shape (M,)
        Each pair's squeeze in newtons; ``nan`` where condition (1) fails.
    force_closure : ndarray of bool, shape (M,)
        Condition (1) holds (both friction cones contain the other contact).
    order : ndarray of int
        The force-closure pairs, best first (ties in pair order).
    exact : tuple of ExactPair
        The proved optima along the best edge pairs, least squeeze first (empty
        with ``exact=0``).
    gravity : (float, float) or None
        Gravity's unit direction when the ranking is over tilts of it; None: every
        orientation.
    tilt : float or None
        With ``gravity``: the tilt bound in radians (0: the given orientation).
    """

    outline: np.ndarray
    com: tuple[float, float]
    mu: float
    mass: float
    g: float
    per: str
    points: np.ndarray
    normals: np.ndarray
    edges: np.ndarray
    i: np.ndarray
    j: np.ndarray
    squeeze: np.ndarray
    force_closure: np.ndarray
    order: np.ndarray
    frames: dict[str, np.ndarray] = dataclasses.field(repr=False)
    exact: tuple[ExactPair, ...] = ()
    gravity: tuple[float, float] | None = None
    tilt: float | None = None

    def pair(self, index: int, rank: int = 0) -> PlannedPair:
        """The :class:`PlannedPair` of pair ``index`` (``rank`` 0: not ranked)."""
        a, b = int(self.i[index]), int(self.j[index])
        if self.frames["swapped"][index]:
            a, b = b, a
        pts = tuple((float(self.points[k, 0]), float(self.points[k, 1])) for k in (a, b))
        nrm = tuple((float(self.normals[k, 0]), float(self.normals[k, 1])) for k in (a, b))
        f = float(self.squeeze[index])
        return PlannedPair(
            rank,
            int(index),
            (a, b),
            pts,  # type: ignore[arg-type]
            nrm,  # type: ignore[arg-type]
            f,
            f / self.mass,
            {k: float(self.frames[k][index]) for k in ("x1", "x2", "y", "phi1", "phi2")},
        )

    def top(self, k: int = 5) -> tuple[PlannedPair, ...]:
        """The ``k`` best force-closure pairs (fewer if there are fewer)."""
        return tuple(self.pair(int(p), r + 1) for r, p in enumerate(self.order[: max(0, k)]))

    def matrix(self) -> np.ndarray:
        """The squeeze as a symmetric N × N matrix over the contacts (``nan`` off force closure)."""
        n = len(self.points)
        m = np.full((n, n), np.nan)
        m[self.i, self.j] = self.squeeze
        m[self.j, self.i] = self.squeeze
        return m

    def to_dict(self, k: int = 5) -> dict[str, Any]:
        """A JSON-ready summary with the ``k`` best pairs."""
        return {
            "samples": len(self.points),
            "pairs": len(self.i),
            "force_closure_pairs": int(self.force_closure.sum()),
            "mu": self.mu,
            "mass_kg": self.mass,
            "g_m_s2": self.g,
            "per": self.per,
            "com_m": list(self.com),
            "orientations": self.orientations(),
            "gravity": None if self.gravity is None else list(self.gravity),
            "tilt_deg": None if self.tilt is None else math.degrees(self.tilt),
            "top": [p.to_dict() for p in self.top(k)],
            "exact": [p.to_dict() for p in self.exact],
            "exact_method": METHOD if self.exact else None,
        }

    def orientations(self) -> str:
        """Which orientations the squeezes hold the part in, in words."""
        if self.gravity is None:
            return "every orientation"
        g = f"gravity along ({self.gravity[0]:.6g}, {self.gravity[1]:.6g})"
        if not self.tilt:
            return g
        if self.tilt >= math.pi:
            return "every orientation"
        return f"{g}, the part tilted by up to ±{math.degrees(self.tilt):.6g}°"


PlannedPair.__module__ = PlanResult.__module__ = "graspcompass.planning"
