"""The inverse questions: force closure (condition (1)) and the least friction for a squeeze.

:func:`force_closure` decides condition (1), that each contact's friction cone
contains the other contact (Nguyen 1988, Fig. 2), exactly for exact input.
:func:`least_mu` finds the least friction coefficient, the same at both pads,
for which a given squeeze holds the part in the case asked: the squeeze of
:func:`graspcompass.sizing.size_gripper` falls as μ grows, from infinity at the
force-closure bound to its limit at infinite friction (``tan(φ ± ξ) → −cot φ``
in eqs. (28)-(39)), and is bisected on the cone half angle ξ.

Examples
--------
>>> force_closure([(1, 0), (-1, 0)], [(-1, 0), (1, 0)], mu=(0, 0)).holds
Traceback (most recent call last):
...
graspcompass.sizing.core.SizingError: the friction of contact A must be positive, got 0
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

from ..boundary.inputs import real_value
from ._case import _G, SizingError, _cmp, _f, _pair, _positive, _read_case, _world
from ._closed import _need_float
from ._many import _closed_form_many
from .units import force_value_si

if TYPE_CHECKING:
    from ..grasp import Grasp
    from ..world import WorldGrasp

__all__ = ["ForceClosure", "LeastMu", "force_closure", "least_mu"]


@dataclasses.dataclass(frozen=True)
class ForceClosure:
    """Whether squeezing harder can hold the part: condition (1), the two-contact force closure.

    Attributes
    ----------
    holds : bool
        True when each contact's friction cone contains the other contact.
    angles_deg : tuple of float
        At each contact, the angle between its inward normal and the line to the
        other contact (at or above 90°: the normal points away from it).
    least_mu : tuple of float
        The friction each contact needs for force closure, ``tan`` of that angle
        (must be exceeded; ``inf`` at or above 90°).
    names : tuple of str
        The contacts' names.
    message : str
        One line: the verdict and why.
    """

    holds: bool
    angles_deg: tuple[float, float]
    least_mu: tuple[float, float]
    names: tuple[str, str]
    message: str


def force_closure(
    contacts: Any, normals: Any, mu: Any, *, names: tuple[str, str] = ("A", "B")
) -> ForceClosure:
    """The force-closure verdict of two contacts with friction (condition (1), Fig. 2).

    Two point contacts with friction can resist every load, given enough
    squeeze, exactly when each friction cone contains the other contact
    (Nguyen 1988; the paper's condition (1)).  When it fails no squeeze holds
    the part in every direction: the friction along the line to the other jaw
    is too small.  The decision is exact for exact input.

    Parameters
    ----------
    contacts, normals : pair of (x, y)
        World contact points and inward normals (any length).
    mu : pair
        Friction coefficients.

    Examples
    --------
    >>> v = force_closure([(1, 0), (-1, 0)], [(-1, 0), (1, 0)], mu=("0.3", "0.3"))
    >>> v.holds, v.least_mu
    (True, (0.0, 0.0))
    >>> v = force_closure([(1, 0), (-1, 0)], [(-1, "0.5"), (1, 0)], mu=("0.3", "0.3"))
    >>> v.holds, round(v.least_mu[0], 6)
    (False, 0.5)
    >>> v.message  # doctest: +ELLIPSIS
    'not force-closure: squeezing harder cannot hold this part: contact A at (1, 0): ...'
    """
    pts = [_pair(p, f"contact {n}") for p, n in zip(_pair(contacts, "contacts"), names)]
    nrm = [_pair(v, f"normal of contact {n}") for v, n in zip(_pair(normals, "normals"), names)]
    pts = [
        (real_value(x, f"contact {n} x"), real_value(y, f"contact {n} y"))
        for (x, y), n in zip(pts, names)
    ]
    nrm = [
        (real_value(x, f"normal of contact {n} x"), real_value(y, f"normal of contact {n} y"))
        for (x, y), n in zip(nrm, names)
    ]
    mus = [
        _positive(real_value(v, f"mu of contact {n}"), f"the friction of contact {n}")
        for v, n in zip(_pair(mu, "mu"), names)
    ]
    exact = not any(isinstance(v, float) for v in [*sum(pts, ()), *sum(nrm, ()), *mus])
    holds, angles, needs, why = True, [], [], ""
    for i in (0, 1):
        p, q, n = pts[i], pts[1 - i], nrm[i]
        d = (q[0] - p[0], q[1] - p[1])
        dot = n[0] * d[0] + n[1] * d[1]
        cross = n[0] * d[1] - n[1] * d[0]
        if _cmp(n[0] ** 2 + n[1] ** 2, 0, exact) <= 0 or _cmp(d[0] ** 2 + d[1] ** 2, 0, exact) <= 0:
            raise SizingError(f"contact {names[i]}: a zero normal or coincident contacts")
        ang = math.degrees(math.atan2(abs(float(cross)), float(dot)))
        angles.append(ang)
        needs.append(abs(float(cross)) / float(dot) + 0.0 if float(dot) > 0 else math.inf)
        ok = _cmp(dot, 0, exact) > 0 and _cmp(mus[i] * dot, abs(cross), exact) > 0
        if not ok and holds:
            holds = False
            xi = math.degrees(math.atan(float(mus[i])))
            why = (
                f"contact {names[i]} at ({_f(p[0])}, {_f(p[1])}): its friction cone "
                f"(μ = {_f(mus[i])}, half angle {xi:.4g}°) does not contain contact "
                f"{names[1 - i]}, the normal makes {ang:.4g}° with the line to it"
            )
            why += (
                f"; force closure needs μ > {needs[-1]:.4g} there"
                if ang < 90
                else "; no friction suffices (the normal points away from the other contact)"
            )
    msg = (
        "force-closure: each friction cone contains the other contact (condition (1)); "
        "enough squeeze holds the part against any load"
        if holds
        else f"not force-closure: squeezing harder cannot hold this part: {why}"
    )
    return ForceClosure(
        holds, (angles[0], angles[1]), (needs[0], needs[1]), (str(names[0]), str(names[1])), msg
    )


@dataclasses.dataclass(frozen=True)
class LeastMu:
    """The least friction coefficient (both pads alike) for which a squeeze limit suffices.

    Attributes
    ----------
    mu : float or None
        The least μ (both contacts) at which the squeeze needed is at most the
        limit; None when no friction suffices; :attr:`mu_force_closure` when
        every force-closure μ suffices (possible for a given orientation, whose
        squeeze can stay finite at the bound).
    mu_force_closure : float
        Below (and at) this μ the grasp is not force-closure (condition (1)).
    squeeze_infinite_friction : float
        The squeeze still needed with infinite friction (per :attr:`per`).
    force_limit : float
        The limit asked (per :attr:`per`).
    per : str
        ``"jaw"`` or ``"total"``.
    message : str
        One line in words.
    """

    mu: float | None
    mu_force_closure: float
    squeeze_infinite_friction: float
    force_limit: float
    per: str
    message: str


def least_mu(
    grasp: WorldGrasp | Grasp,
    force_limit: Any,
    mass: Any,
    *,
    g: Any = None,
    gravity: Any = None,
    tilt: Any = None,
    accel: Any = None,
    safety: Any = 1,
    per: str = "jaw",
) -> LeastMu:
    """The least friction coefficient, the same at both pads, for which ``force_limit`` suffices.

    The squeeze needed (as :func:`size_gripper` computes it for the case) falls
    as μ grows (the friction cones widen, so every balancing set of contact
    forces stays admissible), from infinity at the force-closure bound of
    condition (1) to a limit at infinite friction (``tan(φ ± ξ) → −cot φ``).
    The least μ is found by bisection on the cone half angle ξ in float64
    (about 1e-12 relative).

    Parameters
    ----------
    force_limit : number or str
        The gripper's squeeze, per jaw or total as ``per`` says (N, or text such
        as ``"40N"``).
    grasp, mass, g, gravity, tilt, accel, safety, per
        As for :func:`size_gripper`; the grasp's own friction is replaced.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> g = Grasp(1, 1, 0, "pi/2", "pi/2", mu1=1, mu2=1)
    >>> r = least_mu(g, 30, 2, g=10)  # per jaw: 2·10·sqrt(1 + 1/μ²)/2 <= 30
    >>> round(r.mu, 9), r.mu_force_closure
    (0.353553391, 0.0)
    """
    wg = _world(grasp)
    limit = _positive(force_value_si(force_limit, "force_limit"), "the force limit")
    case = _read_case(wg, mass, _G if g is None else g, gravity, tilt, accel, safety, per)
    k = 1 if per == "jaw" else 2
    gr = wg.grasp
    x1, x2, y, p1, p2 = (float(v) for v in (gr.x1, gr.x2, gr.y, gr.phi1, gr.phi2))
    xi_fc = max(abs(p1 - math.pi / 2), abs(p2 - math.pi / 2))
    fcase = dataclasses.replace(
        case,
        exact=False,
        mass=float(case.mass),
        g=float(case.g),
        safety=float(case.safety),
        A=float(case.A),
        accel=None if case.accel is None else (float(case.accel[0]), float(case.accel[1])),
        gravity=None if case.gravity is None else (float(case.gravity[0]), float(case.gravity[1])),
        tilt=case.tilt if case.tilt in (None, "any") else float(case.tilt),
    )

    def need(mu: float) -> float:
        S, C = _closed_form_many(x1, x2, y, p1, p2, mu, mu)
        return _need_float(wg, fcase, S, C, x1 + x2) * k

    lim = float(limit)
    at_inf = need(math.inf)
    mu_fc = math.tan(xi_fc)
    what = "per jaw" if per == "jaw" else "total"
    if at_inf > lim:
        return LeastMu(
            None,
            mu_fc,
            at_inf,
            lim,
            per,
            f"no friction suffices: even with infinite friction the part needs "
            f"{at_inf:.4g} N {what}, above the limit {lim:.4g} N",
        )
    lo, hi = xi_fc, math.pi / 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if need(math.tan(mid)) <= lim:
            hi = mid
        else:
            lo = mid
    mu = math.tan(hi)
    if hi - xi_fc <= 1e-12:  # the squeeze stays below the limit down to force closure
        return LeastMu(
            mu_fc,
            mu_fc,
            at_inf,
            lim,
            per,
            f"any μ above the force-closure bound μ > {mu_fc:.6g} (both pads) "
            f"makes {lim:.4g} N {what} suffice for this case",
        )
    return LeastMu(
        mu,
        mu_fc,
        at_inf,
        lim,
        per,
        f"μ >= {mu:.6g} at both pads makes {lim:.4g} N {what} suffice "
        f"(force closure needs μ > {mu_fc:.4g}; with infinite friction "
        f"{at_inf:.4g} N {what})",
    )


# public, documented and pickled as graspcompass.sizing.core's (which re-exports them)
ForceClosure.__module__ = LeastMu.__module__ = "graspcompass.sizing.core"
