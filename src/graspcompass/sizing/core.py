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

**The code.**  This module holds the result (:class:`Sizing`) and
:func:`size_gripper`; the case is read in ``_case`` (with
:class:`SizingError`, :class:`NotForceClosureError`), the closed forms are in
``_closed``, the vectorised :func:`worst_squeeze_many` in ``_many``,
:func:`force_closure` and :func:`least_mu` in ``_closure`` and
:func:`vendor_squeeze` in ``_vendor``; every name is importable from here.

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
from typing import TYPE_CHECKING, Any

from ..geometry.exact import canon
from ..grasp import Grasp
from ._case import (  # noqa: F401  (re-exported: the old home of these names)
    _G,
    PER,
    NotForceClosureError,
    SizingError,
    Vec,
    _as,
    _Case,
    _cmp,
    _deg_of,
    _f,
    _pair,
    _positive,
    _read_case,
    _sqrt,
    _world,
)
from ._closed import (  # noqa: F401
    _arc_max,
    _best,
    _evaluate,
    _need_float,
    _slip,
    _to_paper,
    _world_vec,
)
from ._closure import ForceClosure, LeastMu, force_closure, least_mu
from ._many import _closed_form_many, _tan_sides, worst_squeeze_many  # noqa: F401
from ._vendor import vendor_squeeze

if TYPE_CHECKING:
    from ..world import WorldGrasp

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
            "per_note": (
                "per jaw: each jaw's push along the line between the contacts (the "
                "paper's F_int, eq. (17)); the total squeeze of both jaws is twice it"
                if self.per == "jaw"
                else "total: the sum of both jaws' pushes, twice the paper's F_int "
                "(eq. (17)) which each jaw applies"
            ),
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
            "case_slip_direction": (
                None if self.slip_direction is None else list(self.slip_direction)
            ),
            "case_side": self.side,
            "best_squeeze_N": self.best_squeeze,
            "best_gravity_direction_deg": self.best_gravity_direction_deg,
            "vendor_squeeze_N": float(self.vendor_squeeze),
            "vendor_squeeze_per_jaw_N": float(self.vendor_squeeze) / k,
            "vendor_formula": (
                "m(g + a)·S/(μ1 + μ2) per jaw"
                if self.per == "jaw"
                else "m(g + a)·S·2/(μ1 + μ2) total (= m(g + a)·S/μ)"
            ),
            "ratio": self.worst_ratio,
            "case_ratio": self.ratio,
            "mass_kg": float(self.mass),
            "g_m_s2": float(self.g),
            "accel_bound_m_s2": float(self.accel_bound),
            "accel_vector_m_s2": (
                None if self.accel_vector is None else [float(v) for v in self.accel_vector]
            ),
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


def size_gripper(
    grasp: WorldGrasp | Grasp,
    mass: Any,
    *,
    g: Any = None,
    gravity: Any = None,
    tilt: Any = None,
    accel: Any = None,
    safety: Any = 1,
    per: str = "jaw",
) -> Sizing:
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
        amag = amag + (
            _sqrt(case.accel[0] ** 2 + case.accel[1] ** 2, exact)
            if exact
            else math.hypot(*case.accel)
        )
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
        per=per,
        mass=case.mass,
        g=case.g,
        safety=case.safety,
        accel_bound=case.A,
        accel_vector=case.accel,
        gravity=case.gravity,
        tilt=None if case.tilt in (None, "any") else case.tilt,
        squeeze=sq,
        squeeze_per_jaw=ev["per_jaw"],
        worst_squeeze=wsq,
        worst_squeeze_per_jaw=worst["per_jaw"],
        load_direction_deg=_deg_of(ev["load"]) if ev["positive"] else None,
        gravity_direction_deg=_deg_of(ev["gravity"]),
        accel_direction_deg=_deg_of(ev["accel"]),
        worst_direction_deg=_deg_of(worst["load"]),  # type: ignore[arg-type]
        side=side,
        slipping_contact=slip_name,
        slip_direction=slip,
        slip_direction_deg=_deg_of(slip),
        worst_side=worst["side"],
        worst_slipping_contact=wname,
        worst_slip_direction=wslip,
        best_squeeze=best * k,
        best_gravity_direction_deg=_deg_of(_world_vec(wg, best_g)),  # type: ignore[arg-type]
        vendor_squeeze=vendor * k,
        ratio=float(sq) / float(vendor * k),
        worst_ratio=float(wsq) / float(vendor * k),
        exact=exact,
        names=wg.names,
        grasp=wg.grasp,
    )
