"""Sizing a two-jaw gripper in newtons: the worst case, the best orientation, the vendor formula.

The model (Ito, Tanaka, Sasaki 2012): for an external force of magnitude F_e in
the direction e(θ) = (sin θ, −cos θ) (eq. (26)) at the centre of mass, the least
internal force is ``F_int = k_grasp(θ)/(x1 + x2) · F_e`` (eq. (17)) with
``k_grasp = max(k1, k2, k3, k4, 0)`` (eq. (25)) and ``k_n(θ) = V_n · e(θ)``
(eq. (27)), ``V_n = (S_n, C_n)`` (eqs. (28)-(39)).  Since ``k_n(θ) F_e = V_n · f``
for the force vector ``f = F_e e(θ)``, the least internal force for any load
vector f is

    F_int(f) = max(0, max_n V_n · f) / (x1 + x2),

the positive part of a maximum of linear functions of f (convex in f).

**Squeeze per jaw.**  The internal force is a pair of equal and opposite forces
along the line P1P2 (eqs. (14)-(16), Appendix (A2)): each jaw pushes the part
towards the other jaw with F_int on top of the least-norm forces F_T that
balance the load.  Equivalently, for *any* contact forces f1, f2 balancing the
load, ``F_int = (f2 − f1)·u / 2`` with u the unit vector from P2 to P1 (F_T is
orthogonal to the null vector F_N, eq. (12), and the map from (N_i, F_i) to the
force vector is a rotation): the mean of the two contacts' pushes along the
line.  This module calls F_int the **squeeze per jaw** and ``2 F_int`` the
**total squeeze** (the sum over both jaws, what a vendor's "total gripping
force" means).  Every number says which one it is.

**Loads.**  A part of mass m held still in gravity g (unit direction ĝ in the
part's frame) and accelerated by a (a world vector) needs the contacts to
supply m(a − g ĝ): the load on the contacts is ``f = m(g ĝ − a)`` (rotational
acceleration is not modelled).  With the nominal ``w = g ĝ − a`` and an extra
acceleration anywhere in the ball ``|a'| <= A``, f ranges over the disc of
centre ``m R w`` and radius ``m A``, where R is the part's orientation, a
rotation by ρ within ``[−τ, τ]`` (a range of tilts), exactly 0 (a given
orientation) or any angle (any orientation).

**The closed forms.**  The maximum of a linear function over a disc is at the
disc's edge in the function's gradient direction, ``max_{|u|<=1} V·(c + r u) =
V·c + r|V|`` (Cauchy-Schwarz; its key identity ``(V·e(θ))² + (V×e(θ))² = |V|²``
is proved by :func:`graspcompass.proof.prove_identity` in the tests), and the
maximum of ``V · R_ρ w`` over ρ in ``[−τ, τ]`` is ``|V||w|`` when the angle
between V and w is at most τ (``V·w >= |V||w| cos τ``), else the larger end
``cos τ (V·w) + sin τ |V × w|``.  So the squeeze per jaw is

    F = S_f · m · max(0, max_n (M_n(w, τ) + A·‖V_n‖)) / (x1 + x2),

and over all orientations ``F = S_f · m (|w| + A) max_n |V_n| / (x1 + x2)``
(the paper's §5 remark: an internal force above max_n ‖V_n‖ holds the part in
every orientation).  ``S_f`` is the safety factor.

**The vendor formula** sizes a part centred between the jaws and loaded along
the pads: total ``m(g + a) S_f / μ``, per jaw ``m(g + a) S_f / (2μ)``; for
unequal friction ``m(g + a) S_f / (μ1 + μ2)`` per jaw (the two pads' friction
adds).  Here ``a = |a| + A``.  It equals the model's squeeze for a part centred
on the line between parallel jaws, loaded along the pads (θ = 0); it is too low
for an offset centre of mass or a load across the pads.

Examples
--------
The worked example of issue 13: 1 kg in parallel jaws 100 mm apart, μ = 0.3,
the centre of mass 25 mm towards jaw A, g = 9.81 m/s² as in the issue:

>>> from graspcompass import place_grasp
>>> wg = place_grasp([("0.05", 0), ("-0.05", 0)], [(-1, 0), (1, 0)], mu=("0.3", "0.3"),
...                  com=("0.025", 0))
>>> s = size_gripper(wg, "1kg", g="9.81")
>>> round(float(s.worst_squeeze), 2), round(float(s.vendor_squeeze), 2), s.per
(25.01, 16.35, 'jaw')
>>> s.worst_squeeze  # exact: 9.81 · sqrt(0.05² + (0.075/0.3)²) / 0.1
981*sqrt(26)/200
>>> s.slipping_contact, round(s.worst_direction_deg, 2)
('A', 348.69)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import sympy as sp

from ..errors import InputError, WrongTypeError
from ..geometry.exact import canon, decide_sign, has_float
from ..geometry.trig import sincos
from ..grasp import Grasp
from ..inputs import real_value
from ..world import FrictionConeError, WorldGrasp
from .units import (
    STANDARD_GRAVITY,
    acceleration_value,
    angle_value,
    force_value_si,
    mass_value,
)

__all__ = [
    "ForceClosure",
    "LeastMu",
    "NotForceClosureError",
    "Sizing",
    "SizingError",
    "force_closure",
    "least_mu",
    "size_gripper",
    "vendor_squeeze",
    "worst_squeeze_many",
]

PER = ("jaw", "total")


class SizingError(InputError):
    """A sizing question that cannot be answered as asked (a bad mass, safety factor, ...)."""


class NotForceClosureError(FrictionConeError):
    """The grasp is not force-closure: squeezing harder cannot hold the part."""


Vec = tuple[Any, Any]


# -- the result -------------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class Sizing:
    """The squeeze a two-jaw gripper needs for one part (:func:`size_gripper`).

    Forces are in newtons, per jaw or total as :attr:`per` says (total = 2 ×
    per jaw), times the safety factor.  Values are exact sympy numbers when the
    grasp and every input are exact, else floats.  Directions are world angles
    in degrees in [0, 360), measured as the paper's θ (eq. (26)):
    counter-clockwise from the frame's negative y-axis, so 0 is the frame's "down".

    Attributes
    ----------
    per : {"jaw", "total"}
        What the squeeze numbers are: the push of one jaw (the paper's F_int,
        eq. (17)), or the sum over both jaws.
    squeeze : number
        The least squeeze for the case asked (the given orientation or range of
        tilts, or any orientation), worst acceleration included.
    worst_squeeze : number
        The least squeeze that holds the part in every orientation:
        ``S_f m (|w| + A) max_n |V_n| / (x1 + x2)``.
    squeeze_per_jaw, worst_squeeze_per_jaw : number
        The same per jaw whatever :attr:`per` is.
    load_direction_deg : float or None
        The direction of the worst load on the part (gravity and inertia,
        ``m(g ĝ − a)``) for the case asked; None when no load needs a squeeze.
    gravity_direction_deg : float or None
        Gravity's direction in the part's frame in the worst orientation of the
        case (hold the part so that this direction points down).
    accel_direction_deg : float or None
        The worst direction of the extra acceleration of the ball ``|a| <= A``.
    worst_direction_deg : float
        The worst load direction over all orientations (the direction of the
        V_n of largest length).
    side : int or None
        The friction cone side n (1-4, eqs. (18)-(21)) that limits the worst case
        of the case asked: 1, 3 at P1 (upper, lower side), 2, 4 at P2.
    slipping_contact : str or None
        The name of the contact at the verge of slipping in that worst case.
    slip_direction : tuple of float or None
        The unit vector (world frame) along which the part starts to slide
        against that jaw.
    slip_direction_deg : float or None
        Its direction, as the other angles.
    worst_side, worst_slipping_contact, worst_slip_direction : int, str, tuple
        The same for the worst case over all orientations.
    best_squeeze : float
        The least squeeze over the orientations of the case (0 when an
        orientation needs none), worst acceleration included.
    best_gravity_direction_deg : float
        Gravity's direction in the part's frame in that best orientation.
    vendor_squeeze : number
        The vendor formula ``m(g + |a| + A) S_f / (μ1 + μ2)`` per jaw (twice that
        in total), per :attr:`per`.
    ratio, worst_ratio : float
        ``squeeze / vendor_squeeze`` and ``worst_squeeze / vendor_squeeze``: above
        1 the vendor formula is too low.
    exact : bool
        True when the numbers are exact.
    """

    per: str
    mass: Any
    g: Any
    safety: Any
    accel_bound: Any
    accel_vector: Vec | None
    gravity: Vec | None
    tilt: Any
    squeeze: Any
    squeeze_per_jaw: Any
    worst_squeeze: Any
    worst_squeeze_per_jaw: Any
    load_direction_deg: float | None
    gravity_direction_deg: float | None
    accel_direction_deg: float | None
    worst_direction_deg: float
    side: int | None
    slipping_contact: str | None
    slip_direction: tuple[float, float] | None
    slip_direction_deg: float | None
    worst_side: int
    worst_slipping_contact: str
    worst_slip_direction: tuple[float, float]
    best_squeeze: float
    best_gravity_direction_deg: float
    vendor_squeeze: Any
    ratio: float
    worst_ratio: float
    exact: bool
    names: tuple[str, str]
    grasp: Grasp = dataclasses.field(repr=False)

    @property
    def case(self) -> str:
        """The case asked, in words."""
        if self.gravity is None:
            return "any orientation"
        g = f"gravity along ({_f(self.gravity[0])}, {_f(self.gravity[1])})"
        if self.tilt is None:
            return g
        return f"{g}, the part tilted by up to ±{math.degrees(float(self.tilt)):.4g}°"

    def to_dict(self) -> dict[str, Any]:
        """The result as JSON-ready data: floats in newtons and degrees, exact values as text.

        ``worst_squeeze_N``, ``squeeze_N``, ``best_squeeze_N`` and
        ``vendor_squeeze_N`` are :attr:`per` (``"per"``); the ``_per_jaw_N``
        and ``_total_N`` keys give both whatever it is.

        Examples
        --------
        >>> from graspcompass import Grasp
        >>> d = size_gripper(Grasp.preset("table1a"), 1, g=10).to_dict()
        >>> d["per"], d["worst_squeeze_N"] == d["worst_squeeze_per_jaw_N"]
        ('jaw', True)
        """
        k = 1 if self.per == "jaw" else 2
        out: dict[str, Any] = {
            "per": self.per,
            "per_note": ("per jaw: each jaw's push along the line between the contacts (the "
                         "paper's F_int, eq. (17)); the total squeeze of both jaws is twice it"
                         if self.per == "jaw" else
                         "total: the sum of both jaws' pushes, twice the paper's F_int "
                         "(eq. (17)) which each jaw applies"),
            "case": self.case,
            "worst_squeeze_N": float(self.worst_squeeze),
            "worst_squeeze_per_jaw_N": float(self.worst_squeeze_per_jaw),
            "worst_squeeze_total_N": 2 * float(self.worst_squeeze_per_jaw),
            "worst_direction_deg": self.worst_direction_deg,
            "slipping_contact": self.worst_slipping_contact,
            "slip_direction": list(self.worst_slip_direction),
            "slip_direction_deg": _deg_of(self.worst_slip_direction),
            "worst_side": self.worst_side,
            "squeeze_N": float(self.squeeze),
            "squeeze_per_jaw_N": float(self.squeeze_per_jaw),
            "squeeze_total_N": 2 * float(self.squeeze_per_jaw),
            "load_direction_deg": self.load_direction_deg,
            "gravity_direction_deg": self.gravity_direction_deg,
            "accel_direction_deg": self.accel_direction_deg,
            "case_slipping_contact": self.slipping_contact,
            "case_slip_direction": (None if self.slip_direction is None
                                    else list(self.slip_direction)),
            "case_side": self.side,
            "best_squeeze_N": self.best_squeeze,
            "best_gravity_direction_deg": self.best_gravity_direction_deg,
            "vendor_squeeze_N": float(self.vendor_squeeze),
            "vendor_squeeze_per_jaw_N": float(self.vendor_squeeze) / k,
            "vendor_formula": ("m(g + a)·S/(μ1 + μ2) per jaw" if self.per == "jaw"
                               else "m(g + a)·S·2/(μ1 + μ2) total (= m(g + a)·S/μ)"),
            "ratio": self.worst_ratio,
            "case_ratio": self.ratio,
            "mass_kg": float(self.mass),
            "g_m_s2": float(self.g),
            "accel_bound_m_s2": float(self.accel_bound),
            "accel_vector_m_s2": (None if self.accel_vector is None
                                  else [float(v) for v in self.accel_vector]),
            "safety": float(self.safety),
            "force_closure": True,
            "contacts": list(self.names),
            "exact": self.exact,
        }
        if self.exact:
            out["worst_squeeze_exact"] = str(self.worst_squeeze)
            out["squeeze_exact"] = str(self.squeeze)
            out["vendor_squeeze_exact"] = str(self.vendor_squeeze)
        return out


def _f(v: Any) -> str:
    return f"{float(v):.6g}"


def _deg_of(v: Sequence[float] | None) -> float | None:
    """The paper's θ of a world vector, in degrees in [0, 360)."""
    if v is None:
        return None
    return math.degrees(math.atan2(float(v[0]), -float(v[1]))) % 360.0


# -- arithmetic on exact values or floats ------------------------------------------------------
def _sqrt(v: Any, exact: bool) -> Any:
    return canon(sp.sqrt(v)) if exact else math.sqrt(v)


def _cmp(a: Any, b: Any, exact: bool) -> int:
    """The sign of ``a - b`` (exact when possible)."""
    if exact:
        s = decide_sign(a - b)
        if s is not None:
            return s
    d = float(a) - float(b)
    return (d > 0) - (d < 0)


def _as(v: Any, exact: bool) -> Any:
    return v if exact else float(v)


# -- reading the inputs ------------------------------------------------------------------------
def _pair(value: Any, what: str) -> tuple[Any, Any]:
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__"):
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {type(value).__name__}")
    items = list(value)
    if len(items) != 2:
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {len(items)} values")
    return items[0], items[1]


def _positive(v: Any, what: str, strict: bool = True) -> Any:
    s = decide_sign(v) if not isinstance(v, float) else (v > 0) - (v < 0)
    if s is None or s < 0 or (strict and s == 0):
        shown = _f(v) if isinstance(v, float) else str(v)
        raise SizingError(f"{what} must be {'positive' if strict else '>= 0'}, got {shown}")
    return v


def _world(grasp: Any) -> WorldGrasp:
    """The placed grasp, or the identity placement of a paper-frame Grasp."""
    if isinstance(grasp, WorldGrasp):
        return grasp
    if not isinstance(grasp, Grasp):
        raise WrongTypeError("grasp: expected a WorldGrasp (graspcompass.place_grasp) or a "
                             f"Grasp, got {type(grasp).__name__}")
    if any(v.free_symbols for v in grasp.params.values() if isinstance(v, sp.Basic)):
        raise SizingError("grasp: a symbolic grasp has no size in newtons; substitute values "
                          "first (Grasp.subs)")
    g = grasp
    zero, one = sp.Integer(0), sp.Integer(1)
    return WorldGrasp(g, (zero, zero), (one, zero), (zero, one), zero, ("P1", "P2"),
                      ((g.x1, g.y), (-g.x2, g.y)), ((-g.s1, -g.c1), (g.s2, -g.c2)), "P1")


@dataclasses.dataclass(frozen=True)
class _Case:
    """The question in numbers: everything exact, or everything float."""

    exact: bool
    mass: Any
    g: Any
    safety: Any
    A: Any
    accel: Vec | None
    gravity: Vec | None  # unit, world frame
    tilt: Any  # None: the given orientation; "any": every orientation; else τ
    per: str


def _read_case(wg: WorldGrasp, mass: Any, g: Any, gravity: Any, tilt: Any, accel: Any,
               safety: Any, per: str) -> _Case:
    if per not in PER:
        raise SizingError(f"per: expected 'jaw' or 'total', got {per!r}")
    m = _positive(mass_value(mass, "mass"), "the mass")
    gv = _positive(acceleration_value(g, "g"), "g (the magnitude of gravity)")
    sf = real_value(safety, "safety")
    if _cmp(sf, 1, not isinstance(sf, float)) < 0:
        raise SizingError(f"the safety factor must be at least 1, got {_f(sf)}")
    A: Any = sp.Integer(0)
    avec = None
    if accel is not None:
        if isinstance(accel, (str, int, float)) or isinstance(accel, sp.Basic) or not hasattr(
                accel, "__len__"):
            A = _positive(acceleration_value(accel, "accel"), "the acceleration bound", False)
        else:
            ax, ay = _pair(accel, "accel")
            avec = (acceleration_value(ax, "accel x"), acceleration_value(ay, "accel y"))
    gdir = None
    if gravity is not None:
        gx, gy = _pair(gravity, "gravity")
        gdir = (real_value(gx, "gravity x"), real_value(gy, "gravity y"))
    elif avec is not None:
        raise SizingError("accel: an acceleration vector needs the gravity direction "
                          "(gravity=...), in the same frame as the contacts")
    t = None
    if tilt is not None:
        if gravity is None:
            raise SizingError("tilt: a range of tilts needs the gravity direction (gravity=...)")
        t = _positive(angle_value(tilt, "tilt"), "the tilt", strict=False)
    raw = [m, gv, sf, A, *(avec or ()), *(gdir or ()), *(() if t is None else (t,))]
    exact = wg.exact and not any(isinstance(v, float) or has_float(v) for v in raw)
    if gdir is not None:
        n2 = gdir[0] ** 2 + gdir[1] ** 2
        if _cmp(n2, 0, exact) <= 0:
            raise SizingError("gravity: the direction must not be the zero vector")
        n = _sqrt(n2, exact) if exact else math.sqrt(float(n2))
        gdir = (canon(gdir[0] / n), canon(gdir[1] / n)) if exact else (
            float(gdir[0]) / n, float(gdir[1]) / n)
    if t is not None and _cmp(t, sp.pi, exact) >= 0:
        t = "any"  # a tilt of ±180° or more reaches every orientation
    conv = (lambda v: v) if exact else float
    return _Case(exact, conv(m), conv(gv), conv(sf), conv(A),
                 None if avec is None else (conv(avec[0]), conv(avec[1])), gdir,
                 t if t in (None, "any") else conv(t), per)


# -- the closed form ---------------------------------------------------------------------------
def _arc_max(S: Any, C: Any, r: Any, w: Vec, wn: Any, tau: Any, exact: bool
             ) -> tuple[Any, Any]:
    """``max over ρ in [−τ, τ] of V·R_ρ w`` and the maximising ρ (τ None: any ρ).

    R_ρ turns counter-clockwise; ``V·R_ρ w = cos ρ (V·w) + sin ρ (V·Jw)`` with
    ``Jw = (−w_y, w_x)``.
    """
    p = S * w[0] + C * w[1]
    q = -S * w[1] + C * w[0]
    atan2 = sp.atan2 if exact else math.atan2
    if _cmp(wn, 0, exact) == 0 or _cmp(r, 0, exact) == 0:
        return (sp.Integer(0) if exact else 0.0), (sp.Integer(0) if exact else 0.0)
    if tau is None or tau == "any":
        return r * wn, atan2(q, p)
    if exact:
        s, c = sincos(tau)
    else:
        s, c = math.sin(tau), math.cos(tau)
    if _cmp(p, r * wn * c, exact) >= 0:  # V within τ of w: the unconstrained maximum
        return r * wn, atan2(q, p)
    sq = 1 if _cmp(q, 0, exact) >= 0 else -1
    return c * p + s * sq * q, sq * tau


def _evaluate(wg: WorldGrasp, case: _Case, any_orientation: bool) -> dict[str, Any]:
    """The squeeze per jaw of the case (or of every orientation) and where it is reached."""
    gr, exact = wg.grasp, case.exact
    if exact:
        S, C = list(gr.S), list(gr.C)
    else:
        Sf, Cf = gr._floats()
        S, C = [float(v) for v in Sf], [float(v) for v in Cf]
    D = gr.D if exact else float(gr.D)
    m, A = case.mass, case.A
    gdir_world = case.gravity if case.gravity is not None else (
        (sp.Integer(0), sp.Integer(-1)) if exact else (0.0, -1.0))
    w_world = (case.g * gdir_world[0], case.g * gdir_world[1])
    if case.accel is not None:
        w_world = (w_world[0] - case.accel[0], w_world[1] - case.accel[1])
    w = _to_paper(wg, w_world, exact)
    ghat = _to_paper(wg, gdir_world, exact)
    wn = _sqrt(w[0] ** 2 + w[1] ** 2, exact) if exact else math.hypot(*w)
    tau = None if (any_orientation or case.tilt == "any" or case.gravity is None) else (
        case.tilt if case.tilt is not None else (sp.Integer(0) if exact else 0.0))
    vals, rhos, rs = [], [], []
    for Sn, Cn in zip(S, C):
        r = _sqrt(Sn ** 2 + Cn ** 2, exact) if exact else math.hypot(Sn, Cn)
        top, rho = _arc_max(Sn, Cn, r, w, wn, tau, exact)
        vals.append(top + A * r)
        rhos.append(rho)
        rs.append(r)
    best = 0
    for n in range(1, 4):
        if _cmp(vals[n], vals[best], exact) > 0:
            best = n
    top = vals[best]
    positive = _cmp(top, 0, exact) > 0
    per_jaw = (m * top / D * case.safety) if positive else (sp.Integer(0) if exact else 0.0)
    if exact:
        per_jaw = canon(per_jaw)
    rho = rhos[best]
    # the worst load, in the paper's frame: m (R_ρ w + A V/|V|)
    cr, sr = math.cos(float(rho)), math.sin(float(rho))
    wf = (float(w[0]), float(w[1]))
    rw = (cr * wf[0] - sr * wf[1], sr * wf[0] + cr * wf[1])
    rf = float(rs[best])
    u = (float(S[best]) / rf, float(C[best]) / rf) if rf > 0 else (0.0, 0.0)
    load = (rw[0] + float(A) * u[0], rw[1] + float(A) * u[1])
    gh = (float(ghat[0]), float(ghat[1]))
    grav = (cr * gh[0] - sr * gh[1], sr * gh[0] + cr * gh[1])
    return {"per_jaw": per_jaw, "side": best + 1, "positive": positive,
            "load": _world_vec(wg, load), "gravity": _world_vec(wg, grav),
            "accel": _world_vec(wg, (-u[0], -u[1])) if float(A) > 0 and rf > 0 else None,
            "S": S, "C": C, "D": D, "w": w, "ghat": ghat, "rs": rs, "tau": tau}


def _to_paper(wg: WorldGrasp, v: Vec, exact: bool) -> Vec:
    ex, ey = wg.ex, wg.ey
    if exact:
        return (canon(v[0] * ex[0] + v[1] * ex[1]), canon(v[0] * ey[0] + v[1] * ey[1]))
    exf, eyf = (float(ex[0]), float(ex[1])), (float(ey[0]), float(ey[1]))
    return (float(v[0]) * exf[0] + float(v[1]) * exf[1],
            float(v[0]) * eyf[0] + float(v[1]) * eyf[1])


def _world_vec(wg: WorldGrasp, v: tuple[float, float]) -> tuple[float, float]:
    ex, ey = (float(wg.ex[0]), float(wg.ex[1])), (float(wg.ey[0]), float(wg.ey[1]))
    return (v[0] * ex[0] + v[1] * ey[0], v[0] * ex[1] + v[1] * ey[1])


def _slip(wg: WorldGrasp, side: int) -> tuple[str, tuple[float, float]]:
    """The contact of cone side n and the world direction the part slides along there.

    At side n the contact force lies on the upper (n = 1, 2: F_i = +μ_i N_i,
    inequalities (8), (9)) or lower (n = 3, 4: F_i = −μ_i N_i, (10), (11)) side of
    its cone; friction pushes the part along ±t_i, so it starts to slide along
    ∓t_i, with t1 = (−cos φ1, sin φ1), t2 = (cos φ2, sin φ2) (the columns of L, eq. (5)).
    """
    g = wg.grasp
    if side in (1, 3):
        t = (-float(g.c1), float(g.s1))
    else:
        t = (float(g.c2), float(g.s2))
    sign = -1.0 if side in (1, 2) else 1.0
    v = _world_vec(wg, (sign * t[0], sign * t[1]))
    return wg.names[0 if side in (1, 3) else 1], (v[0] + 0.0, v[1] + 0.0)


def _best(ev: dict[str, Any], case: _Case) -> tuple[float, tuple[float, float]]:
    """The least squeeze per jaw over the orientations of the case, and ĝ there (paper frame).

    Minimises ``h(ρ) = max_n (a_n cos ρ + b_n sin ρ + c_n)`` over ρ in [−τ, τ]
    (a_n = V_n·w, b_n = V_n·Jw, c_n = A‖V_n‖): the minimum is at an end of the
    range, at the minimum ``ρ = atan2(−b_n, −a_n)`` of one term, or where two terms
    are equal; every such candidate is evaluated.
    """
    S = np.array([float(v) for v in ev["S"]])
    C = np.array([float(v) for v in ev["C"]])
    w = (float(ev["w"][0]), float(ev["w"][1]))
    a = S * w[0] + C * w[1]
    b = -S * w[1] + C * w[0]
    c = float(case.A) * np.hypot(S, C)
    tau = ev["tau"]
    cands = [np.arctan2(-b, -a)]
    for i in range(4):
        for j in range(i + 1, 4):
            da, db, dc = a[i] - a[j], b[i] - b[j], c[j] - c[i]
            R = math.hypot(da, db)
            if R > 0 and abs(dc) <= R:
                phi, off = math.atan2(db, da), math.acos(max(-1.0, min(1.0, dc / R)))
                cands.append(np.array([phi + off, phi - off]))
    rho = np.concatenate([np.atleast_1d(x) for x in cands])
    rho = (rho + math.pi) % (2 * math.pi) - math.pi
    if tau is not None:
        t = float(tau)
        rho = np.concatenate([np.clip(rho, -t, t), [-t, t]])
    h = (np.multiply.outer(np.cos(rho), a) + np.multiply.outer(np.sin(rho), b) + c).max(axis=1)
    k = int(np.argmin(h))
    value = max(0.0, float(h[k])) * float(case.mass) / float(ev["D"]) * float(case.safety)
    cr, sr = math.cos(rho[k]), math.sin(rho[k])
    gh = (float(ev["ghat"][0]), float(ev["ghat"][1]))
    return value, (cr * gh[0] - sr * gh[1], sr * gh[0] + cr * gh[1])


def vendor_squeeze(mass: Any, mu1: Any, mu2: Any | None = None, *, g: Any = None,
                   accel: Any = 0, safety: Any = 1, per: str = "jaw") -> Any:
    """The vendor formula: ``m(g + a) S / (μ1 + μ2)`` per jaw, ``m(g + a) S · 2/(μ1 + μ2)`` total.

    With equal friction these are the catalogue formulas ``m(g + a) S/(2μ)`` per
    jaw and ``m(g + a) S/μ`` total.  They assume a part centred between parallel
    jaws and loaded along the pads.

    Parameters
    ----------
    mass : number or str
        kg, or text with a unit (``"500g"``).
    mu1, mu2 : number or str
        The pads' friction coefficients (``mu2`` defaults to ``mu1``).
    g, accel : number or str, optional
        Gravity (default standard gravity 9.80665 m/s²) and the acceleration
        magnitude (m/s², or text such as ``"0.5g"``).
    safety : number, optional
        The safety factor S.
    per : {"jaw", "total"}

    Examples
    --------
    >>> vendor_squeeze(1, "0.3", g="9.81"), vendor_squeeze(1, "0.3", g="9.81", per="total")
    (327/20, 327/10)
    """
    if per not in PER:
        raise SizingError(f"per: expected 'jaw' or 'total', got {per!r}")
    m = _positive(mass_value(mass, "mass"), "the mass")
    gv = _positive(acceleration_value(_G if g is None else g, "g"), "g")
    a = _positive(acceleration_value(accel, "accel"), "the acceleration", strict=False)
    m1 = _positive(real_value(mu1, "mu1"), "mu1")
    m2 = m1 if mu2 is None else _positive(real_value(mu2, "mu2"), "mu2")
    sf = real_value(safety, "safety")
    out = m * (gv + a) * sf / (m1 + m2) * (1 if per == "jaw" else 2)
    return out if isinstance(out, float) else canon(out)


_G = sp.Rational(*STANDARD_GRAVITY)


def size_gripper(grasp: Any, mass: Any, *, g: Any = None, gravity: Any = None,
                 tilt: Any = None, accel: Any = None, safety: Any = 1,
                 per: str = "jaw") -> Sizing:
    """The squeeze a two-jaw gripper needs to hold a part: worst case, best orientation, vendor.

    Parameters
    ----------
    grasp : WorldGrasp or Grasp
        The placed grasp (:func:`graspcompass.place_grasp`), or a paper-frame
        :class:`~graspcompass.Grasp` (then the world frame is the paper's and the
        contacts are named P1, P2).  Lengths in metres.
    mass : number or str
        The part's mass: kg, or text with a unit (``"500g"``, ``"1.2 kg"``).
    g : number or str, optional
        The magnitude of gravity (default 9.80665 m/s², standard gravity).
    gravity : (x, y), optional
        Gravity's direction in the contacts' frame (any length).  None: any
        orientation of the part.
    tilt : angle, optional
        With ``gravity``: the part may turn by up to ±tilt from that orientation
        (text needs ``deg`` or ``rad``; numbers are radians).
    accel : number, str or (x, y), optional
        A bound A on the acceleration in any direction (``|a| <= A``, m/s² or
        text such as ``"0.5g"``), or a given acceleration vector (with ``gravity``).
    safety : number, optional
        The safety factor (>= 1) that multiplies every squeeze, the vendor's too.
    per : {"jaw", "total"}
        Report the squeeze of one jaw (the paper's F_int, eq. (17)) or the sum
        over both jaws (twice it).

    Returns
    -------
    Sizing
        The numbers, worst directions, slipping contact and the vendor comparison.

    Raises
    ------
    SizingError, UnitError, InputError
        For a mass or g that is not positive, a safety factor below 1, a bad unit.

    Notes
    -----
    The load on the contacts is ``f = m(g ĝ − a)`` at the centre of mass
    (rotational acceleration is not modelled) and the squeeze per jaw for it
    is ``max(0, max_n V_n·f)/(x1 + x2)`` (eqs. (17), (25), (27)); its maxima
    over orientations and acceleration balls are in closed form (module
    docstring).

    Examples
    --------
    Table I(a) of the paper (Fig. 7(a)), in metres, 2 kg, g = 10:

    >>> from graspcompass import Grasp
    >>> s = size_gripper(Grasp.preset("table1a"), 2, g=10)
    >>> s.worst_squeeze, s.worst_side, s.per  # 2·10·|V_1|/4, V_1 = (-3, -2)
    (5*sqrt(13), 1, 'jaw')
    >>> s = size_gripper(Grasp.preset("table1a"), 2, g=10, gravity=(0, -1), accel=1)
    >>> s.squeeze  # 2·(10·k_1(0) + 1·|V_1|)/4, k_1(0) = -C_1 = 2
    sqrt(13)/2 + 10
    """
    wg = _world(grasp)
    case = _read_case(wg, mass, _G if g is None else g, gravity, tilt, accel, safety, per)
    exact = case.exact
    k = 1 if per == "jaw" else 2
    ev = _evaluate(wg, case, any_orientation=False)
    worst = _evaluate(wg, case, any_orientation=True)
    best, best_g = _best(ev, case)
    mu1, mu2 = wg.grasp.mu1, wg.grasp.mu2
    if not exact:
        mu1, mu2 = float(mu1), float(mu2)
    amag = case.A
    if case.accel is not None:
        amag = amag + (_sqrt(case.accel[0] ** 2 + case.accel[1] ** 2, exact) if exact
                       else math.hypot(*case.accel))
    vendor = case.mass * (case.g + amag) * case.safety / (mu1 + mu2)
    if exact:
        vendor = canon(vendor)
    side, slip_name, slip = None, None, None
    if ev["positive"]:
        side = ev["side"]
        slip_name, slip = _slip(wg, side)
    wname, wslip = _slip(wg, worst["side"])
    sq, wsq = ev["per_jaw"] * k, worst["per_jaw"] * k
    return Sizing(
        per=per, mass=case.mass, g=case.g, safety=case.safety, accel_bound=case.A,
        accel_vector=case.accel, gravity=case.gravity,
        tilt=None if case.tilt in (None, "any") else case.tilt,
        squeeze=sq, squeeze_per_jaw=ev["per_jaw"], worst_squeeze=wsq,
        worst_squeeze_per_jaw=worst["per_jaw"],
        load_direction_deg=_deg_of(ev["load"]) if ev["positive"] else None,
        gravity_direction_deg=_deg_of(ev["gravity"]),
        accel_direction_deg=_deg_of(ev["accel"]),
        worst_direction_deg=_deg_of(worst["load"]),  # type: ignore[arg-type]
        side=side, slipping_contact=slip_name, slip_direction=slip,
        slip_direction_deg=_deg_of(slip), worst_side=worst["side"],
        worst_slipping_contact=wname, worst_slip_direction=wslip,
        best_squeeze=best * k, best_gravity_direction_deg=_deg_of(
            _world_vec(wg, best_g)),  # type: ignore[arg-type]
        vendor_squeeze=vendor * k, ratio=float(sq) / float(vendor * k),
        worst_ratio=float(wsq) / float(vendor * k), exact=exact, names=wg.names,
        grasp=wg.grasp)


# -- many grasps at once (float64) -------------------------------------------------------------
def _tan_sides(s1: Any, c1: Any, s2: Any, c2: Any, mu1: Any, mu2: Any) -> tuple[Any, ...]:
    """``tan(φ ± ξ)`` of the four sides in the μ form of eq. (23); μ = inf gives ``−cot φ``."""
    out = []
    for n in (1, 2, 3, 4):
        s, c, mu = (s1, c1, mu1) if n in (1, 3) else (s2, c2, mu2)
        sg = 1.0 if n in (1, 2) else -1.0
        with np.errstate(divide="ignore", invalid="ignore"):
            finite = (s + sg * c * mu) / (c - sg * s * mu)
            out.append(np.where(np.isinf(mu), -c / s, finite))
    return tuple(out)


def _closed_form_many(x1: Any, x2: Any, y: Any, phi1: Any, phi2: Any, mu1: Any, mu2: Any
                      ) -> tuple[np.ndarray, np.ndarray]:
    """S_n, C_n (eqs. (28)-(39)) of many grasps in double precision, shape (..., 4)."""
    t1, t2, t3, t4 = _tan_sides(np.sin(phi1), np.cos(phi1), np.sin(phi2), np.cos(phi2),
                                mu1, mu2)
    h = (x1 + x2) / 2
    S = np.stack([-h + y * t1, h - y * t2, -h + y * t3, h - y * t4], axis=-1)
    C = np.stack([x2 * t1, x1 * t2, x2 * t3, x1 * t4], axis=-1)
    return S, C


def worst_squeeze_many(x1: Any, x2: Any, y: Any, phi1: Any, phi2: Any, mu1: Any, mu2: Any,
                       mass: Any, *, g: float = 9.80665, accel: Any = 0.0, safety: Any = 1.0,
                       per: str = "jaw") -> np.ndarray:
    """The squeeze over all orientations for many grasps at once, float64 (vectorised).

    ``S_f m (g + A) max_n |V_n| / (x1 + x2)`` per jaw (twice that with
    ``per="total"``), the paper-frame parameters broadcasting together (metres,
    radians, kg, m/s²).  The closed form (28)-(39) is evaluated in double
    precision, so near the bounds of condition (1) (a cone side nearly
    horizontal) its relative error grows like ε / abs(cos(φ ± ξ)); the parameters are
    not checked here (:class:`~graspcompass.Grasp` and :func:`size_gripper` do).

    Examples
    --------
    >>> import numpy as np
    >>> F = worst_squeeze_many(0.025, 0.075, 0.0, np.pi / 2, np.pi / 2, 0.3, 0.3, 1.0, g=9.81)
    >>> round(float(F), 2)
    25.01
    """
    if per not in PER:
        raise SizingError(f"per: expected 'jaw' or 'total', got {per!r}")
    arrs = [np.asarray(v, dtype=float) for v in (x1, x2, y, phi1, phi2, mu1, mu2)]
    S, C = _closed_form_many(*arrs)
    r = np.sqrt(S * S + C * C).max(axis=-1)
    out = np.asarray(safety, float) * np.asarray(mass, float) * (g + np.asarray(accel, float))
    return out * r / (arrs[0] + arrs[1]) * (1 if per == "jaw" else 2)


# -- inverse questions -------------------------------------------------------------------------
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


def force_closure(contacts: Any, normals: Any, mu: Any, *,
                  names: tuple[str, str] = ("A", "B")) -> ForceClosure:
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
    pts = [(real_value(x, f"contact {n} x"), real_value(y, f"contact {n} y"))
           for (x, y), n in zip(pts, names)]
    nrm = [(real_value(x, f"normal of contact {n} x"), real_value(y, f"normal of contact {n} y"))
           for (x, y), n in zip(nrm, names)]
    mus = [_positive(real_value(v, f"mu of contact {n}"), f"the friction of contact {n}")
           for v, n in zip(_pair(mu, "mu"), names)]
    exact = not any(isinstance(v, float) for v in [*sum(pts, ()), *sum(nrm, ()), *mus])
    holds, angles, needs, why = True, [], [], ""
    for i in (0, 1):
        p, q, n = pts[i], pts[1 - i], nrm[i]
        d = (q[0] - p[0], q[1] - p[1])
        dot = n[0] * d[0] + n[1] * d[1]
        cross = n[0] * d[1] - n[1] * d[0]
        if _cmp(n[0] ** 2 + n[1] ** 2, 0, exact) <= 0 or _cmp(d[0] ** 2 + d[1] ** 2, 0,
                                                               exact) <= 0:
            raise SizingError(f"contact {names[i]}: a zero normal or coincident contacts")
        ang = math.degrees(math.atan2(abs(float(cross)), float(dot)))
        angles.append(ang)
        needs.append(abs(float(cross)) / float(dot) + 0.0 if float(dot) > 0 else math.inf)
        ok = _cmp(dot, 0, exact) > 0 and _cmp(mus[i] * dot, abs(cross), exact) > 0
        if not ok and holds:
            holds = False
            xi = math.degrees(math.atan(float(mus[i])))
            why = (f"contact {names[i]} at ({_f(p[0])}, {_f(p[1])}): its friction cone "
                   f"(μ = {_f(mus[i])}, half angle {xi:.4g}°) does not contain contact "
                   f"{names[1 - i]}, the normal makes {ang:.4g}° with the line to it")
            why += (f"; force closure needs μ > {needs[-1]:.4g} there" if ang < 90 else
                    "; no friction suffices (the normal points away from the other contact)")
    msg = ("force-closure: each friction cone contains the other contact (condition (1)); "
           "enough squeeze holds the part against any load" if holds else
           f"not force-closure: squeezing harder cannot hold this part: {why}")
    return ForceClosure(holds, (angles[0], angles[1]), (needs[0], needs[1]),
                        (str(names[0]), str(names[1])), msg)


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


def least_mu(grasp: Any, force_limit: Any, mass: Any, *, g: Any = None, gravity: Any = None,
             tilt: Any = None, accel: Any = None, safety: Any = 1, per: str = "jaw") -> LeastMu:
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
        case, exact=False, mass=float(case.mass), g=float(case.g), safety=float(case.safety),
        A=float(case.A), accel=None if case.accel is None else tuple(map(float, case.accel)),
        gravity=None if case.gravity is None else tuple(map(float, case.gravity)),
        tilt=case.tilt if case.tilt in (None, "any") else float(case.tilt))

    def need(mu: float) -> float:
        S, C = _closed_form_many(x1, x2, y, p1, p2, mu, mu)
        return _need_float(wg, fcase, S, C, x1 + x2) * k

    lim = float(limit)
    at_inf = need(math.inf)
    mu_fc = math.tan(xi_fc)
    what = "per jaw" if per == "jaw" else "total"
    if at_inf > lim:
        return LeastMu(None, mu_fc, at_inf, lim, per,
                       f"no friction suffices: even with infinite friction the part needs "
                       f"{at_inf:.4g} N {what}, above the limit {lim:.4g} N")
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
        return LeastMu(mu_fc, mu_fc, at_inf, lim, per,
                       f"any μ above the force-closure bound μ > {mu_fc:.6g} (both pads) "
                       f"makes {lim:.4g} N {what} suffice for this case")
    return LeastMu(mu, mu_fc, at_inf, lim, per,
                   f"μ >= {mu:.6g} at both pads makes {lim:.4g} N {what} suffice "
                   f"(force closure needs μ > {mu_fc:.4g}; with infinite friction "
                   f"{at_inf:.4g} N {what})")


def _need_float(wg: WorldGrasp, case: _Case, S: np.ndarray, C: np.ndarray, D: float) -> float:
    """The case's squeeze per jaw for float S_n, C_n (same as :func:`_evaluate`, floats)."""
    gdir = case.gravity if case.gravity is not None else (0.0, -1.0)
    w_world = (case.g * gdir[0], case.g * gdir[1])
    if case.accel is not None:
        w_world = (w_world[0] - case.accel[0], w_world[1] - case.accel[1])
    w = _to_paper(wg, w_world, False)
    wn = math.hypot(*w)
    tau = None if (case.tilt == "any" or case.gravity is None) else (
        case.tilt if case.tilt is not None else 0.0)
    top = -math.inf
    for Sn, Cn in zip(S.tolist(), C.tolist()):
        r = math.hypot(Sn, Cn)
        v, _ = _arc_max(Sn, Cn, r, w, wn, tau, False)
        top = max(top, v + case.A * r)
    return max(0.0, top) * case.mass / D * case.safety
