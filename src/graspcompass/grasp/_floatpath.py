"""High-precision evaluation behind the float path of :class:`graspcompass.Grasp` (issue 9).

A float parameter is taken as the exact binary number it is.  The closed form
(28)-(39) in the μ form of (23),

    tan(φ ± ξ) = (sin φ ± μ cos φ) / (cos φ ∓ μ sin φ),
    S_n = ∓(x1 + x2)/2 ± y tan(φ ± ξ),  C_n = x_{2|1} tan(φ ± ξ),

is evaluated here with mpmath at ``_DPS`` digits (more when a denominator
cos(φ ± ξ)/cos ξ is small) and rounded once to double, so the float S_n, C_n
are correct to about one unit in the last place whatever the conditioning.

The margins of condition (1),

    −π/2 < φ_i − ξ_i < π/2 < φ_i + ξ_i < 3π/2,

are computed the same way.  Each bound is where a cone side turns horizontal:
cos(φ ± ξ) = 0.  The ruler-and-compass construction of a float grasp runs in
double precision (the geometry kernel rounds every float to ~17 digits), so the
direction of a cone side is known to an absolute ~ε = 2.2e-16, and X_n, Y_n and
V_n, which scale like 1/cos(φ ± ξ) (eqs. (28)-(39)), carry a relative error of
about ε/|cos(φ ± ξ)| ≈ ε/margin.  The kernel itself reads a cross product below
1e-12 of the lengths as zero (parallel lines: X_n or Y_n would not exist).  The
float path therefore refuses a margin below ``FLOAT_MARGIN`` = 1e-12 relative to
its bound (1.6e-12 rad at π/2, 4.7e-12 rad at 3π/2): there the construction
would be wrong in the fourth digit or fail, and the exact path (parameters given
as text such as ``"pi/2"``) is the way to go.

:func:`side_floats` gives the cone sides' directions correctly rounded; a
construction started from them has V_n accurate to a few ε max|V_n| at any
margin above the threshold (measured 1.5e-16 at 2e-12 rad, against 2e-5 when
cos φ ∓ μ sin φ is evaluated in double precision).
"""

from __future__ import annotations

from typing import Any

import mpmath
import sympy as sp

from ..geometry.exact import approx, free, has_float

__all__ = [
    "FLOAT_MARGIN",
    "MarginReport",
    "closed_form_floats",
    "condition_1_margins",
    "mpf",
    "side_floats",
]

#: Smallest margin of condition (1), relative to its bound, the float path accepts.
FLOAT_MARGIN = 1e-12

#: Working digits of the high-precision evaluation.
_DPS = 40
_MAX_DPS = 640
#: Significant digits kept in the smallest denominator cos(φ ± ξ)/cos ξ.
_KEEP = 20


def mpf(value: sp.Expr, dps: int = _DPS) -> mpmath.mpf:
    """``value`` as an mpmath number at the current precision (exact for floats).

    Raises
    ------
    TypeError
        If ``value`` has free symbols.
    """
    if isinstance(value, sp.Float):
        return mpmath.mpf(value._mpf_)  # the exact binary value, rounded to the context
    if isinstance(value, sp.Rational):
        return mpmath.mpf(int(value.p)) / int(value.q)
    value = value if isinstance(value, sp.Basic) else sp.sympify(value, strict=True)
    if free(value):  # free, has_float: read off the kernel's memo (no walk of the tree)
        raise TypeError(f"{value} has free symbols and no numeric value")
    if not has_float(value):  # exact: interval arithmetic on the canonical form (fast)
        try:
            return mpmath.mpf(approx(value, dps + 10))
        except (TypeError, ValueError):
            pass
    v = sp.N(value, dps + 10)
    if not isinstance(v, sp.Float):
        raise TypeError(f"{value} has no real numeric value")
    return mpmath.mpf(v._mpf_)


def _sides(p: dict[str, Any], dps: int) -> list[tuple[mpmath.mpf, mpmath.mpf]]:
    """``(sin(φ ± ξ), cos(φ ± ξ)) / cos ξ`` of sides n = 1..4 (μ form), at ``dps``."""
    out = []
    for n in (1, 2, 3, 4):
        i = 1 if n in (1, 3) else 2
        phi, mu = mpf(p[f"phi{i}"], dps), mpf(p[f"mu{i}"], dps)
        s, c = mpmath.sin(phi), mpmath.cos(phi)
        sg = 1 if n in (1, 2) else -1
        out.append((s + sg * c * mu, c - sg * s * mu))
    return out


def closed_form_floats(p: dict[str, Any]) -> tuple[list[float], list[float]]:
    """``(S1..S4), (C1..C4)`` of eqs. (28)-(39) as correctly evaluated doubles.

    ``p`` holds the grasp's parameters ``x1, x2, y, phi1, phi2, mu1, mu2`` (sympy
    values, floats or exact).  The precision grows until every denominator
    cos(φ ± ξ)/cos ξ keeps ``_KEEP`` significant digits.
    """
    dps = _DPS
    while True:
        with mpmath.workdps(dps):
            sides = _sides(p, dps)
            # relative size of the smallest denominator against the terms cancelling in it
            small = min(abs(c) / (1 + abs(s) + abs(c)) for s, c in sides)
            if small > mpmath.mpf(10) ** (_KEEP - dps):
                break
        if dps >= _MAX_DPS:
            if not small:
                raise ZeroDivisionError("a cone side is horizontal: tan(φ ± ξ) is infinite")
            break
        dps *= 2
    with mpmath.workdps(dps):
        x1, x2, y = (mpf(p[k], dps) for k in ("x1", "x2", "y"))
        h = (x1 + x2) / 2
        S, C = [], []
        for n, (sx, cx) in enumerate(sides, start=1):
            t = sx / cx
            S.append(float(-h + y * t if n in (1, 3) else h - y * t))
            C.append(float((x2 if n in (1, 3) else x1) * t))
    return S, C


def side_floats(p: dict[str, Any], n: int) -> tuple[float, float]:
    """``(sin(φ ± ξ), cos(φ ± ξ)) / cos ξ`` of cone side n (1-4), correctly rounded.

    In double precision the second component, ``cos φ ∓ μ sin φ``, cancels when
    the side is nearly horizontal; evaluated here at ``_DPS`` digits it keeps its
    full relative accuracy, and so do X_n, Y_n and V_n constructed from it.
    """
    with mpmath.workdps(_DPS):
        sx, cx = _sides(p, _DPS)[n - 1]
        return float(sx), float(cx)


class MarginReport:
    """One inequality of condition (1) at one contact, with its margin.

    Attributes
    ----------
    contact : int
        1 or 2.
    text : str
        The inequality, e.g. ``"φ1 + ξ1 > π/2"``.
    value : float
        φ ± ξ (rad), ξ = atan μ (22).
    bound : str
        The bound, e.g. ``"π/2"``.
    margin : float
        Signed distance to the bound (rad), positive when the inequality holds.
    relative : float
        ``margin / |bound|``.
    """

    def __init__(
        self, contact: int, text: str, value: float, bound: str, margin: float, relative: float
    ) -> None:
        self.contact, self.text, self.value = contact, text, value
        self.bound, self.margin, self.relative = bound, margin, relative


def condition_1_margins(p: dict[str, Any]) -> list[MarginReport]:
    """The eight margins of condition (1) (four per contact), at ``_DPS`` digits.

    ξ_i is taken as ``atan(μ_i)`` (22), the value the construction uses.
    """
    out = []
    with mpmath.workdps(_DPS):
        pi = mpmath.pi
        for i in (1, 2):
            phi, xi = mpf(p[f"phi{i}"]), mpmath.atan(mpf(p[f"mu{i}"]))
            lo, up = phi - xi, phi + xi
            for value, sign, bound, b, rel in (
                (lo, "−", -pi / 2, "−π/2", ">"),
                (lo, "−", pi / 2, "π/2", "<"),
                (up, "+", pi / 2, "π/2", ">"),
                (up, "+", 3 * pi / 2, "3π/2", "<"),
            ):
                margin = value - bound if rel == ">" else bound - value
                out.append(
                    MarginReport(
                        i,
                        f"φ{i} {sign} ξ{i} {rel} {b}",
                        float(value),
                        b,
                        float(margin),
                        float(margin / abs(bound)),
                    )
                )
    return out
