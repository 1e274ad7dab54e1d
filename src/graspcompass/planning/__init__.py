"""Choosing the contacts of a two-jaw grasp on an outline (issue 13 §3): ``graspcompass plan``.

:func:`plan_contacts` samples contact points along the edges of a part's
outline (each with its edge's inward normal; vertices, where the normal is
undefined, are never sampled), forms every pair of them, and ranks the pairs by
the squeeze that holds the part **in every orientation** (Ito, Tanaka, Sasaki
2012, §5 with eq. (17))::

    F = m g max_n |V_n| / (x1 + x2)   per jaw,

``V_n = (S_n, C_n)`` of eqs. (28)-(39) in the paper frame of each pair
(§2.2.1, Fig. 2: the origin at the centre of mass, the x-axis along the line
through the contacts).  Pairs that are not force-closure, i.e. violate
condition (1) (each friction cone must contain the other contact), have no
finite squeeze and are left out of the ranking.

Everything is vectorised: the paper frame of all pairs (:func:`pair_frames`,
the same construction as :func:`graspcompass.place_grasp`, in float64) and the
worst squeeze (:func:`graspcompass.batch.worst_squeeze`, condition (1) through
:func:`graspcompass.batch.valid`).

**The user's orientations.**  With ``gravity=(x, y)`` (and ``tilt=τ``) the
ranking is by the worst case over the tilts ``|ρ| <= τ`` of that gravity (0: the
given orientation) instead of every orientation:
``S_f m max(0, max_n (M_n + A |V_n|)) / (x1 + x2)``, ``M_n`` the largest
``V_n · R_ρ (g ĝ)`` (:mod:`graspcompass.sizing.core`, vectorised over the pairs by
:func:`graspcompass.sizing._arc.arc_max_many`).

**Exact along edges.**  For the edge pairs of the best sampled pairs
(``exact=3`` of them by default), the least squeeze over every force-closure
pair of points of the two edges, not only the samples, is found and *proved*
within a relative tolerance (default 1e-6) by branch and bound over the two
edge parameters with interval lower bounds of the closed form
(:mod:`graspcompass.planning._exact`); :attr:`PlanResult.exact`, each with what
it proves (:meth:`ExactPair.claim`).  Over every orientation or under the
user's tilt range alike; under a tilt range the least squeeze may be approached
on the boundary of condition (1), where it stays finite: then ``on_boundary``
says so (the infimum over the force-closure pairs, attained by none; the pair
reported is just inside, at the edge of a friction cone).

Examples
--------
A 100 mm × 60 mm plate, μ = 0.5, 1 kg: the best pairs are the centred ones, at
``m g sqrt(1 + 1/μ²) / 2`` per jaw (``y = 0``, ``x1 = x2``: all four ``|V_n|``
equal ``x1 sqrt(1 + 1/μ²)``):

>>> plan = plan_contacts([(-0.05, -0.03), (0.05, -0.03), (0.05, 0.03), (-0.05, 0.03)],
...                      mu=0.5, mass=1.0, samples=48, g=9.81)
>>> best = plan.top(1)[0]
>>> best.contacts, round(best.squeeze, 4), round(9.81 * (1 + 1 / 0.5**2) ** 0.5 / 2, 4)
(((0.0, -0.03), (0.0, 0.03)), 10.9679, 10.9679)
>>> ex = plan.exact[0]  # proved: no pair on these two edges needs less than lower_bound
>>> ex.certified, bool(ex.lower_bound <= 9.81 * 5 ** 0.5 / 2 <= ex.squeeze)
(True, True)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..boundary.errors import InputError, InputTooLargeError, NonFiniteValueError
from ..sizing.core import NotForceClosureError
from ..world import OutlineError
from ._exact import DEFAULT_TOL, Load
from ._refine import ExactPair, refine_plan
from ._result import PlannedPair, PlanResult

__all__ = [
    "DEFAULT_SAMPLES",
    "DEFAULT_TOL",
    "MAX_PAIRS",
    "ExactPair",
    "PlanResult",
    "PlannedPair",
    "pair_frames",
    "plan_contacts",
    "sample_contacts",
]

#: Most contact pairs evaluated (``samples · (samples − 1) / 2``).
MAX_PAIRS = 20_000
#: Contact points sampled along the outline by default.
DEFAULT_SAMPLES = 120
_PER = ("jaw", "total")


def _readonly(a: Any, dtype: Any = float) -> np.ndarray:
    out = np.array(a, dtype=dtype)
    out.flags.writeable = False
    return out


def _ring(outline: Any) -> tuple[np.ndarray, tuple[float, float]]:
    """The counter-clockwise exterior ring (closed, float64) and the area centroid."""
    try:
        from shapely.geometry import Polygon
        from shapely.geometry.polygon import orient
    except ImportError:  # pragma: no cover - shapely comes with the outlines extra
        raise InputError(
            "planning on an outline needs shapely: pip install 'graspcompass[outlines]'"
        ) from None
    if hasattr(outline, "geom_type"):
        if outline.geom_type != "Polygon":
            raise OutlineError(f"expected a polygon outline, got a {outline.geom_type}")
        poly = outline
    else:
        try:
            pts = [(float(x), float(y)) for x, y in outline]
        except (TypeError, ValueError) as exc:
            raise OutlineError(f"outline: expected a sequence of (x, y) vertices ({exc})") from None
        if len(pts) < 3:
            raise OutlineError(f"outline: expected at least 3 vertices, got {len(pts)}")
        poly = Polygon(pts)
    coords = np.asarray(poly.exterior.coords, float) if not poly.is_empty else np.empty((0, 2))
    if not np.isfinite(coords).all():
        raise OutlineError("outline: the vertices must be finite numbers")
    if poly.is_empty or not poly.is_valid or not poly.area > 0:
        raise OutlineError(
            "outline: not a simple closed polygon with an area (it crosses itself, or has no area)"
        )
    poly = orient(poly, 1.0)
    c = poly.centroid
    return np.asarray(poly.exterior.coords, float), (float(c.x), float(c.y))


def sample_contacts(
    outline: Any, samples: int = DEFAULT_SAMPLES
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Contact points spread evenly along an outline, with their edges' inward normals.

    The perimeter is divided into ``samples`` equal lengths; edge ``e`` gets
    ``round(samples · L_e⁺ / L) − round(samples · L_e⁻ / L)`` points (``L_e⁻``,
    ``L_e⁺`` the arc length at its ends), at the centres of equal parts of the
    edge, so no point is a vertex and an edge with an odd count has its midpoint.
    Short edges (chords of a flattened curve) may get none.

    Parameters
    ----------
    outline : shapely Polygon or sequence of (x, y)
        The part's outline (its exterior ring; holes are not sampled).
    samples : int
        How many points in all.

    Returns
    -------
    points, normals : ndarray, shape (samples, 2)
        The contacts and their inward unit normals (into the material).
    edges : ndarray of int, shape (samples,)
        The index of each point's edge in the counter-clockwise exterior ring.
    """
    ring, _ = _ring(outline)
    return _sample(ring, samples)


def _sample(ring: np.ndarray, samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    a, b = ring[:-1], ring[1:]
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    total = float(length.sum())
    cum = np.concatenate([[0.0], np.cumsum(length)])
    marks = np.round(samples * cum / total).astype(np.int64)
    counts = marks[1:] - marks[:-1]
    edges = np.repeat(np.arange(len(length)), counts)
    # the j-th of n points of an edge at (j + 1/2)/n along it
    start = np.cumsum(counts) - counts
    j = np.arange(edges.size) - np.repeat(start, counts)
    t = (j + 0.5) / counts[edges]
    points = a[edges] + t[:, None] * d[edges]
    u = d[edges] / length[edges, None]
    normals = np.stack([-u[:, 1], u[:, 0]], axis=-1)  # counter-clockwise: material on the left
    return points, normals, edges


def pair_frames(pa: Any, na: Any, pb: Any, nb: Any, com: Any) -> dict[str, np.ndarray]:
    """The paper-frame parameters of many contact pairs at once (§2.2.1, Fig. 2), float64.

    The same frame as :func:`graspcompass.place_grasp`: the x-axis along
    ``a − b``, turned round when the centre of mass lies above the line so that
    ``y >= 0``; P1 is then the contact on the +x side.  ``x1 = (P1 − O)·e_x``,
    ``x2 = (O − P2)·e_x``, ``y = |(P1 − O)·e_y|``, and the normals give
    ``φ1 = atan2(−n1x, −n1y)``, ``φ2 = atan2(n2x, −n2y)`` (``n1 = (−sin φ1, −cos φ1)``,
    ``n2 = (sin φ2, −cos φ2)``, the columns of L in eq. (5)).

    Parameters
    ----------
    pa, na, pb, nb : array, shape (..., 2)
        Contact points and inward unit normals of the two contacts of each pair.
    com : (x, y)
        The centre of mass O.

    Returns
    -------
    dict of ndarray
        ``x1, x2, y, phi1, phi2``, ``swapped`` (True where P1 is contact b) and
        ``ex_x, ex_y``, the paper's x-axis in the world frame (``e_y = J e_x``).
    """
    pa, na, pb, nb = (np.asarray(v, float) for v in (pa, na, pb, nb))
    c = np.asarray(com, float)
    diff = pa - pb
    dist = np.hypot(diff[..., 0], diff[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        ex = diff / dist[..., None]
    ey = np.stack([-ex[..., 1], ex[..., 0]], axis=-1)
    swapped = np.einsum("...i,...i->...", pa - c, ey) < 0
    sign = np.where(swapped, -1.0, 1.0)[..., None]
    ex, ey = ex * sign, ey * sign
    p1 = np.where(swapped[..., None], pb, pa)
    p2 = np.where(swapped[..., None], pa, pb)
    n1 = np.where(swapped[..., None], nb, na)
    n2 = np.where(swapped[..., None], na, nb)

    def dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
        return np.einsum("...i,...i->...", u, v)

    x1, x2, y = dot(p1 - c, ex), dot(c - p2, ex), np.abs(dot(p1 - c, ey))
    phi1 = np.arctan2(-dot(n1, ex), -dot(n1, ey))
    phi2 = np.arctan2(dot(n2, ex), -dot(n2, ey))
    return {
        "x1": x1,
        "x2": x2,
        "y": y,
        "phi1": phi1,
        "phi2": phi2,
        "swapped": swapped,
        "ex_x": ex[..., 0],
        "ex_y": ex[..., 1],
    }


def _positive(v: Any, what: str, strict: bool = True) -> float:
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise InputError(f"{what}: expected a number, got {v!r}") from None
    if not math.isfinite(x) or not (x > 0 if strict else x >= 0):
        raise InputError(f"{what} must be a finite number {'>' if strict else '>='} 0, got {v!r}")
    return x


def plan_contacts(
    outline: Any,
    *,
    mu: float,
    mass: float = 1.0,
    samples: int = DEFAULT_SAMPLES,
    com: Sequence[float] | None = None,
    g: float = 9.80665,
    accel: float = 0.0,
    safety: float = 1.0,
    per: str = "jaw",
    gravity: Sequence[float] | None = None,
    tilt: Any = None,
    exact: int = 3,
    tol: float = DEFAULT_TOL,
) -> PlanResult:
    """Rank the contact pairs of an outline by the squeeze that holds it in any orientation.

    For every pair of :func:`sample_contacts` points, the squeeze
    ``S_f m (g + A) max_n |V_n| / (x1 + x2)`` per jaw (twice that with
    ``per="total"``; V_n of eqs. (28)-(39), F_int of eq. (17), the worst case
    over all directions of the load as in §5), vectorised; pairs violating
    condition (1) are not force-closure and are left out.

    Parameters
    ----------
    outline : shapely Polygon or sequence of (x, y)
        The part (metres), e.g. from :func:`graspcompass.outlines.read_outline`.
    mu : float
        Friction coefficient of both pads, ``μ = tan ξ`` (22).
    mass : float
        Mass in kg (1: the squeezes are newtons per kilogram).
    samples : int
        Contact points along the outline, from 3; at most
        ``samples (samples − 1) / 2 <=`` :data:`MAX_PAIRS` pairs.
    com : (x, y), optional
        Centre of mass (default the outline's centroid, uniform density).
    g, accel, safety : float
        Gravity, an acceleration bound ``|a| <= A`` in any direction (m/s²), and a
        safety factor >= 1.
    per : {"jaw", "total"}
    gravity : (x, y), optional
        Gravity's direction in the outline's frame: rank by the worst case over
        the tilts of the part within ``tilt`` of it (default: every orientation).
    tilt : angle, optional
        With ``gravity``: the part may turn by up to ±tilt (radians, or text with
        a unit such as ``"15deg"``; ±180° or more is every orientation); without
        it the given orientation.
    exact : int
        How many edge pairs (those of the best sampled pairs) to optimise over
        their continuous parameters, with a proof (over every orientation only).
    tol : float
        The relative tolerance of those proofs, in (0, 0.1].

    Returns
    -------
    PlanResult

    Raises
    ------
    graspcompass.errors.InputTooLargeError
        Too many pairs.
    graspcompass.sizing.NotForceClosureError
        No sampled pair is force-closure (more friction, or more samples).
    graspcompass.world.OutlineError
        An outline that is not a simple polygon with an area.
    """
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)):
        raise InputError(f"samples: expected an integer, got {samples!r}")
    samples = int(samples)
    if samples < 3:
        raise InputError(f"samples must be at least 3, got {samples}")
    pairs = samples * (samples - 1) // 2
    if pairs > MAX_PAIRS:
        most = int((1 + math.isqrt(1 + 8 * MAX_PAIRS)) // 2)
        raise InputTooLargeError(
            f"samples {samples} give {pairs} pairs; at most {MAX_PAIRS} (samples <= {most})"
        )
    if per not in _PER:
        raise InputError(f"per: expected 'jaw' or 'total', got {per!r}")
    mu_, mass_ = _positive(mu, "mu"), _positive(mass, "mass")
    g_, a_ = _positive(g, "g", strict=False), _positive(accel, "accel", strict=False)
    sf = _positive(safety, "safety")
    if sf < 1:
        raise InputError(f"safety must be at least 1, got {safety!r}")
    if isinstance(exact, bool) or not isinstance(exact, (int, np.integer)) or not 0 <= exact <= 50:
        raise InputError(f"exact: expected an integer from 0 to 50, got {exact!r}")
    tol_ = _positive(tol, "tol")
    if tol_ > 0.1:
        raise InputError(f"tol must be at most 0.1, got {tol!r}")
    load = _load(g_, a_, gravity, tilt, mass_, sf, per)
    ring, centroid = _ring(outline)
    c = centroid
    if com is not None:
        try:
            c = (float(com[0]), float(com[1]))
        except (TypeError, ValueError, IndexError):
            raise InputError(f"com: expected (x, y), got {com!r}") from None
        if not all(math.isfinite(v) for v in c):
            raise InputError(f"com must be finite, got {com!r}")
    points, normals, edges = _sample(ring, samples)
    i, j = np.triu_indices(len(points), 1)
    fr = pair_frames(points[i], normals[i], points[j], normals[j], c)
    from .. import batch

    squeeze = batch.worst_squeeze(
        fr["x1"],
        fr["x2"],
        fr["y"],
        fr["phi1"],
        fr["phi2"],
        mu_,
        mu_,
        mass_,
        g=g_,
        accel=a_,
        safety=sf,
        per=per,
        on_invalid="nan",
    )
    factor = sf * mass_ * (1.0 if per == "jaw" else 2.0)
    if not load.any_orientation:
        squeeze = _tilted(fr, mu_, load) * factor
    # condition (1) with the float path's margin (a cone side within 1e-12 rad of the other
    # contact is not force-closure: its squeeze would be ~1e16 N, rounding noise)
    valid = batch.valid(fr["x1"], fr["x2"], fr["y"], fr["phi1"], fr["phi2"], mu_, mu_, margin=1e-12)
    overflow = valid & np.isinf(squeeze)
    if overflow.any():  # force-closure pairs whose squeeze is beyond a double: say so
        raise NonFiniteValueError(
            f"the squeeze of {int(overflow.sum())} force-closure pairs is beyond double "
            "precision (1.8e308 N): give the mass, g or the acceleration in other units"
        )
    fc = np.isfinite(squeeze) & valid
    squeeze = np.where(fc, squeeze, np.nan)
    if not fc.any():
        need = _least_mu_hint(fr)
        raise NotForceClosureError(
            f"none of the {len(i)} pairs of the {len(points)} contacts sampled is force-closure "
            f"with μ = {mu_:g} (condition (1): each friction cone must contain the other "
            f"contact){need}"
        )
    ok = np.flatnonzero(fc)
    order = ok[np.argsort(squeeze[ok], kind="stable")]
    frames = {k: _readonly(v, bool if k == "swapped" else float) for k, v in fr.items()}
    plan = PlanResult(
        _readonly(ring),
        (float(c[0]), float(c[1])),
        mu_,
        mass_,
        g_,
        per,
        _readonly(points),
        _readonly(normals),
        _readonly(edges, np.int64),
        _readonly(i, np.int64),
        _readonly(j, np.int64),
        _readonly(squeeze),
        _readonly(fc, bool),
        _readonly(order, np.int64),
        frames,
        gravity=load.gravity,
        tilt=None if load.gravity is None else load.tau,
    )
    if exact:
        plan = dataclasses.replace(
            plan, exact=refine_plan(plan, int(exact), load, factor, tol_, plan.orientations())
        )
    return plan


def _load(g: float, a: float, gravity: Any, tilt: Any, mass: float, sf: float, per: str) -> Load:
    """The orientations asked, read as :func:`graspcompass.size_gripper` reads them."""
    if gravity is None and tilt is None:
        return Load(g, a)
    from ..sizing.core import _read_case

    case = _read_case(None, mass, g, gravity, tilt, a, sf, per)
    gdir = (float(case.gravity[0]), float(case.gravity[1]))  # type: ignore[index]
    if case.tilt == "any":
        return Load(g, a, gdir, math.pi)
    return Load(g, a, gdir, 0.0 if case.tilt is None else float(case.tilt))


def _tilted(fr: dict[str, np.ndarray], mu: float, load: Load) -> np.ndarray:
    """``max(0, max_n M_n + A|V_n|) / (x1 + x2)`` of every pair (tilts of gravity), nan off (1)."""
    from .. import batch
    from ..sizing._arc import arc_max_many

    S, C = batch.closed_form(
        fr["x1"], fr["x2"], fr["y"], fr["phi1"], fr["phi2"], mu, mu, on_invalid="nan"
    )
    ex, ey = fr["ex_x"][..., None], fr["ex_y"][..., None]
    vx, vy = S * ex - C * ey, S * ey + C * ex  # V_n = S_n e_x + C_n e_y, e_y = J e_x
    w = (load.g * load.gravity[0], load.g * load.gravity[1])  # type: ignore[index]
    top = (arc_max_many(vx, vy, w, load.tau) + load.accel * np.hypot(vx, vy)).max(axis=-1)
    return np.maximum(top, 0.0) / (fr["x1"] + fr["x2"])


def _least_mu_hint(fr: dict[str, np.ndarray]) -> str:
    """``; the best pair needs μ > …`` from the angles between normals and the contact line."""
    with np.errstate(invalid="ignore"):
        # φ1 = π/2 is the normal along the line; the cone needs ξ > |φ − π/2| at both
        dev = np.maximum(np.abs(fr["phi1"] - np.pi / 2), np.abs(fr["phi2"] - np.pi / 2))
    dev = dev[np.isfinite(dev) & (fr["x1"] + fr["x2"] > 0)]
    if not dev.size or dev.min() >= np.pi / 2:
        return ""
    return f"; the best pair sampled needs μ > {math.tan(float(dev.min())):.3g}"
