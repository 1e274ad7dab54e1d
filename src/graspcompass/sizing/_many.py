"""The squeeze over all orientations for many grasps at once, in float64 (vectorised).

``S_f m (g + A) max_n |V_n| / (x1 + x2)`` per jaw (the paper's §5 remark: an
internal force above ``max_n ‖V_n‖`` holds the part in every orientation), with
``V_n = (S_n, C_n)`` from the closed form (28)-(39) in the μ form of eq. (23),
evaluated over numpy arrays of the paper-frame parameters.  :func:`least_mu`
uses the same closed form at one grasp for its bisection on μ.

Examples
--------
>>> import math  # parallel jaws 4 apart, μ = 1: tan(φ ± ξ) = ∓1 in eqs. (28)-(39)
>>> S, C = _closed_form_many(2.0, 2.0, 0.0, math.pi / 2, math.pi / 2, 1.0, 1.0)
>>> S.round(6).tolist(), C.round(6).tolist()
([-2.0, 2.0, -2.0, 2.0], [-2.0, -2.0, 2.0, 2.0])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._case import PER, SizingError

__all__ = ["worst_squeeze_many"]


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


def _closed_form_many(
    x1: Any, x2: Any, y: Any, phi1: Any, phi2: Any, mu1: Any, mu2: Any
) -> tuple[np.ndarray, np.ndarray]:
    """S_n, C_n (eqs. (28)-(39)) of many grasps in double precision, shape (..., 4)."""
    t1, t2, t3, t4 = _tan_sides(np.sin(phi1), np.cos(phi1), np.sin(phi2), np.cos(phi2), mu1, mu2)
    h = (x1 + x2) / 2
    S = np.stack([-h + y * t1, h - y * t2, -h + y * t3, h - y * t4], axis=-1)
    C = np.stack([x2 * t1, x1 * t2, x2 * t3, x1 * t4], axis=-1)
    return S, C


def worst_squeeze_many(
    x1: Any,
    x2: Any,
    y: Any,
    phi1: Any,
    phi2: Any,
    mu1: Any,
    mu2: Any,
    mass: Any,
    *,
    g: float = 9.80665,
    accel: Any = 0.0,
    safety: Any = 1.0,
    per: str = "jaw",
) -> np.ndarray:
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
