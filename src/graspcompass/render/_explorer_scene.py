"""The explorer's picture as plain float arrays (no matplotlib, no sympy per move).

:func:`float_scene` computes everything the explorer draws from the closed form
of §3.3 in double precision with numpy:

- the cone sides: directions ``(∓(sin φ ± μ cos φ), −(cos φ ∓ μ sin φ))``, the
  unit direction at angle φ ± ξ divided by cos ξ (eqs. (18)-(23)), the same
  vectors :meth:`graspcompass.Grasp.side_direction` gives;
- tan(φ ± ξ) and ``S_n = ∓(x1 + x2)/2 ± y tan(φ ± ξ)``, ``C_n = x_{2|1} tan(φ ± ξ)``
  (eqs. (28)-(39)), ``V_n = (S_n, C_n)``, ``X_n = (O_M.x − S_n, 0)``,
  ``Y_n = (0, −C_n)`` (V_n = (−O_M X_n, −O Y_n));
- the perpendiculars through P2x (n = 1, 3) or P1x (n = 2, 4), the circles on
  the diameters O V_n (centre V_n / 2, radius |V_n| / 2, eq. (31));
- k_grasp(θ) = max(0, S_n sin θ − C_n cos θ) (eq. (25)) on a θ grid and the
  envelope polyline k_grasp(θ) e(θ), e(θ) = (sin θ, −cos θ) (26).

It returns None instead of a scene when the grasp is not comfortably valid:
a parameter outside its range, condition (1) failing or within ``_MARGIN`` rad
of a bound, or a cone side so nearly horizontal that ``cos φ ∓ μ sin φ`` loses
more than four digits to cancellation.  The explorer then builds a
:class:`graspcompass.Grasp`, which either refuses the grasp with the failing
inequality or is valid, and :func:`grasp_scene` takes the correctly rounded
S_n, C_n and sides of the float path (:mod:`graspcompass.grasp._floatpath`).

:func:`construction_scene` is the old way, the ruler-and-compass construction
replayed by :func:`graspcompass.internal_force_diagram`; the tests and the
benchmark compare the two.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = [
    "GRASP_KEYS",
    "POINT_NAMES",
    "Scene",
    "ThetaGrid",
    "construction_scene",
    "float_scene",
    "grasp_scene",
]

#: The grasp's parameters among the explorer's (θ is the explorer's own).
GRASP_KEYS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")
#: The small points, in the order of :attr:`Scene.points`.
POINT_NAMES = ("P1x", "P2x", "O_M", *(f"{k}{n}" for k in "XYV" for n in (1, 2, 3, 4)))

#: Distance (rad) from a bound of condition (1) below which the Grasp decides.
_MARGIN = 1e-6
#: Smallest |cos φ ∓ μ sin φ| / (|cos φ| + μ |sin φ|) of the double evaluation.
_CANCEL = 1e-4


@dataclass
class Scene:
    """Everything the explorer draws for one valid grasp (floats).

    ``sides[n-1]`` and ``perps[n-1]`` are ``((px, py), (dx, dy))``: a point and a
    direction of the line.  ``points`` are the coordinates of :data:`POINT_NAMES`.
    ``theta``, ``k`` and ``envelope`` are the θ grid, k_grasp on it and the polyline.
    """

    P1: tuple[float, float]
    P2: tuple[float, float]
    S: np.ndarray
    C: np.ndarray
    sides: np.ndarray  # (4, 2, 2)
    perps: np.ndarray  # (4, 2, 2)
    points: np.ndarray  # (15, 2)
    theta: np.ndarray
    k: np.ndarray
    envelope: np.ndarray  # (samples, 2)

    @property
    def V(self) -> np.ndarray:
        """``V_n = (S_n, C_n)``, shape (4, 2)."""
        return np.column_stack([self.S, self.C])

    @property
    def centres(self) -> np.ndarray:
        """Centres V_n / 2 of the circles on O V_n, shape (4, 2)."""
        return self.V / 2

    @property
    def radii(self) -> np.ndarray:
        """Radii |V_n| / 2."""
        return np.hypot(self.S, self.C) / 2

    def point(self, name: str) -> tuple[float, float]:
        """A named point: ``P1``, ``P2`` or one of :data:`POINT_NAMES`."""
        if name in ("P1", "P2"):
            return self.P1 if name == "P1" else self.P2
        x, y = self.points[POINT_NAMES.index(name)]
        return float(x), float(y)

    def k_grasp(self, theta: float) -> float:
        """k_grasp(θ) of eq. (25) for one θ."""
        s, c = math.sin(theta), math.cos(theta)
        return max(0.0, *(float(a) * s - float(b) * c for a, b in zip(self.S, self.C)))


class ThetaGrid:
    """A θ grid on [0, 2π] with its sines and cosines (computed once)."""

    def __init__(self, samples: int) -> None:
        self.theta = np.linspace(0.0, 2 * np.pi, samples)
        self.sin, self.cos = np.sin(self.theta), np.cos(self.theta)


def _assemble(
    p: dict[str, float], S: np.ndarray, C: np.ndarray, sc: np.ndarray, grid: ThetaGrid
) -> Scene:
    """The scene from S_n, C_n and the sides' ``(sin(φ ± ξ), cos(φ ± ξ)) / cos ξ``."""
    x1, x2, y = p["x1"], p["x2"], p["y"]
    sign = np.array([-1.0, 1.0, -1.0, 1.0])  # −sx at P1 (n = 1, 3), +sx at P2 (n = 2, 4)
    d = np.column_stack([sign * sc[:, 0], -sc[:, 1]])
    P1, P2 = (x1, y), (-x2, y)
    at = np.array([P1, P2, P1, P2])
    foot = np.array([(-x2, 0.0), (x1, 0.0), (-x2, 0.0), (x1, 0.0)])  # P2x, P1x, P2x, P1x
    sides = np.stack([at, d], axis=1)
    perps = np.stack([foot, np.column_stack([-d[:, 1], d[:, 0]])], axis=1)
    om = (x1 - x2) / 2
    zeros = np.zeros(4)
    points = np.vstack(
        [
            [(x1, 0.0), (-x2, 0.0), (om, 0.0)],
            np.column_stack([om - S, zeros]),  # X_n
            np.column_stack([zeros, -C]),  # Y_n
            np.column_stack([S, C]),
        ]
    )  # V_n
    kn = np.multiply.outer(S, grid.sin) - np.multiply.outer(C, grid.cos)
    k = np.maximum(kn.max(axis=0), 0.0)
    envelope = np.column_stack([k * grid.sin, -k * grid.cos])
    return Scene(P1, P2, S, C, sides, perps, points, grid.theta, k, envelope)


def float_scene(p: dict[str, float], grid: ThetaGrid) -> Scene | None:
    """The scene in double precision, or None when the Grasp must decide (see above)."""
    try:
        x1, x2, y, phi1, phi2, mu1, mu2 = (float(p[k]) for k in GRASP_KEYS)
    except (TypeError, ValueError, OverflowError):
        return None
    if not all(math.isfinite(v) and abs(v) < 1e150 for v in (x1, x2, y, phi1, phi2, mu1, mu2)):
        return None
    if not (
        x1 + x2 > 0
        and y >= 0
        and 0 < phi1 <= math.pi
        and 0 < phi2 <= math.pi
        and mu1 > 0
        and mu2 > 0
    ):
        return None
    half = math.pi / 2
    sc = np.empty((4, 2))
    for i, (phi, mu) in enumerate(((phi1, mu1), (phi2, mu2))):
        xi = math.atan(mu)
        lo, up = phi - xi, phi + xi
        if min(lo + half, half - lo, up - half, 3 * half - up) < _MARGIN:
            return None  # condition (1) fails or is too close to call in doubles
        s, c = math.sin(phi), math.cos(phi)
        for n, sg in ((i, 1.0), (i + 2, -1.0)):  # upper side n = i+1, lower n = i+3
            cx = c - sg * s * mu
            if abs(cx) < _CANCEL * (abs(c) + abs(s) * mu):
                return None
            sc[n] = (s + sg * c * mu, cx)
    t = sc[:, 0] / sc[:, 1]  # tan(φ ± ξ), eq. (23)
    h = (x1 + x2) / 2
    S = np.array([-h + y * t[0], h - y * t[1], -h + y * t[2], h - y * t[3]])
    C = np.array([x2 * t[0], x1 * t[1], x2 * t[2], x1 * t[3]])
    return _assemble(dict(x1=x1, x2=x2, y=y), S, C, sc, grid)


def grasp_scene(grasp: Grasp, grid: ThetaGrid) -> Scene:
    """The scene of a valid float :class:`~graspcompass.Grasp`, correctly rounded.

    S_n, C_n and the sides come from :mod:`graspcompass.grasp._floatpath` (evaluated at
    40 digits or more and rounded once): the path for grasps near a bound of
    condition (1), where the double evaluation of :func:`float_scene` cancels.
    """
    from ..grasp._floatpath import closed_form_floats, side_floats

    params = grasp.params
    S, C = closed_form_floats(params)
    sc = np.array([side_floats(params, n) for n in (1, 2, 3, 4)])
    p = {k: float(params[k]) for k in ("x1", "x2", "y")}
    return _assemble(p, np.array(S), np.array(C), sc, grid)


def construction_scene(p: dict[str, float], grid: ThetaGrid) -> Scene:
    """The scene read off the replayed construction (the explorer before issue 12).

    :func:`graspcompass.internal_force_diagram` of the float grasp, each step
    evaluated, and the envelope from its arcs; slow (tens of ms and more), for
    tests and the benchmark's baseline.
    """
    from ..construction import internal_force_diagram
    from ..geometry import evaluate
    from ..grasp import Grasp

    g = Grasp(p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], mu1=p["mu1"], mu2=p["mu2"])
    c = internal_force_diagram(g)
    num = {s.name: evaluate(s.obj) for s in c.steps if s.kind in ("point", "line", "circle")}
    sides = np.array([num[f"side{n}"] for n in (1, 2, 3, 4)], dtype=float)
    perps = np.array([num[f"perp{n}"] for n in (1, 2, 3, 4)], dtype=float)
    points = np.array([num[k] for k in POINT_NAMES], dtype=float)
    V = points[-4:]
    env = c["envelope"]
    k = env.k(grid.theta)
    return Scene(
        tuple(num["P1"]),
        tuple(num["P2"]),
        V[:, 0].copy(),
        V[:, 1].copy(),
        sides,
        perps,
        points,
        grid.theta,
        k,
        env.polyline(len(grid.theta)),
    )
