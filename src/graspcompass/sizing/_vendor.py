"""The vendor formula: ``m(g + a) S_f / (μ1 + μ2)`` per jaw, twice that in total.

The catalogue formula of gripper vendors, ``m(g + a) S_f / μ`` total or
``m(g + a) S_f / (2μ)`` per jaw, for unequal friction ``m(g + a) S_f /
(μ1 + μ2)`` per jaw (the two pads' friction adds).  It equals the model's
squeeze (eq. (17)) for a part centred on the line between parallel jaws and
loaded along the pads (θ = 0 in eq. (26)); it is too low for an offset centre
of mass or a load across the pads (:mod:`graspcompass.sizing.core`).
"""

from __future__ import annotations

from typing import Any

from ..boundary.inputs import real_value
from ..geometry.exact import canon
from ._case import _G, PER, SizingError, _positive
from .units import acceleration_value, mass_value

__all__ = ["vendor_squeeze"]


def vendor_squeeze(
    mass: Any,
    mu1: Any,
    mu2: Any | None = None,
    *,
    g: Any = None,
    accel: Any = 0,
    safety: Any = 1,
    per: str = "jaw",
) -> Any:
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
