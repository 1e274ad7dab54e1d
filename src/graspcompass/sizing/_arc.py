"""The worst load over a range of tilts, vectorised: ``max over |ρ| <= τ of V·R_ρ w``.

The float64 array form of :func:`graspcompass.sizing.core._arc_max` (one value
there, exact or float), for many vectors ``V_n = (S_n, C_n)`` (eqs. (28)-(39))
at once, as :func:`graspcompass.planning.plan_contacts` needs over every contact
pair.  ``R_ρ`` turns counter-clockwise and ``V·R_ρ w = cos ρ (V·w) + sin ρ
(V·Jw)`` with ``Jw = (−w_y, w_x)``: the maximum is ``|V||w|`` when V is within τ
of w (``V·w >= |V||w| cos τ``), else the larger end ``cos τ (V·w) + sin τ |V·Jw|``
(the derivation in :mod:`graspcompass.sizing.core`).

Examples
--------
>>> import numpy as np
>>> arc_max_many(np.array([0.0, 1.0]), np.array([-1.0, 0.0]), (0.0, -1.0), np.pi / 2)
array([1., 1.])
>>> arc_max_many(1.0, 0.0, (0.0, -1.0), np.pi / 6)  # sin 30°
array(0.5)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["arc_max_many"]


def arc_max_many(S: Any, C: Any, w: tuple[float, float], tau: float | None) -> np.ndarray:
    """``max over ρ in [−τ, τ] of V·R_ρ w`` for arrays of ``V = (S, C)`` (float64).

    Parameters
    ----------
    S, C : array
        The components of V_n (any broadcasting shapes).
    w : (float, float)
        The load direction times its magnitude (``g ĝ``), in the frame of V.
    tau : float or None
        The tilt bound τ >= 0 in radians; None (or τ >= π): every orientation,
        ``|V||w|``.

    Returns
    -------
    ndarray
        The broadcast shape of S and C.
    """
    S, C = np.asarray(S, float), np.asarray(C, float)
    wx, wy = float(w[0]), float(w[1])
    r = np.hypot(S, C) * math.hypot(wx, wy)
    if tau is None or tau >= math.pi:
        return r
    p = S * wx + C * wy
    q = C * wx - S * wy
    c, s = math.cos(tau), math.sin(tau)
    return np.where(p >= r * c, r, c * p + s * np.abs(q))
