"""Reading a sizing question: the case in numbers, exact or float, and its errors.

The load on the contacts of a part of mass m held still in gravity g (unit
direction ĝ in the part's frame) and accelerated by a is ``f = m(g ĝ − a)``
(the derivation is in :mod:`graspcompass.sizing.core`).  :func:`_read_case`
reads m, g, ĝ, a given vector or a bound A on the acceleration, the range of
tilts τ and the safety factor S_f, with units (:mod:`graspcompass.sizing.units`),
into a :class:`_Case`: every number exact when the grasp and every input are
exact, else every number a float.  The helpers compare and take square roots
the same way in both cases.

Examples
--------
>>> from graspcompass import Grasp
>>> c = _read_case(_world(Grasp.preset("table1a")), "500g", 10, (0, -2), "30deg", 1, 2, "jaw")
>>> c.exact, c.mass, c.gravity, c.tilt, c.A
(True, 1/2, (0, -1), pi/6, 1)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import sympy as sp

from ..boundary.errors import InputError, WrongTypeError
from ..boundary.inputs import real_value
from ..geometry.exact import canon, decide_sign, has_float
from ..grasp import Grasp
from ..world import FrictionConeError, WorldGrasp
from .units import (
    STANDARD_GRAVITY,
    acceleration_value,
    angle_value,
    mass_value,
)

__all__ = ["NotForceClosureError", "SizingError"]

PER = ("jaw", "total")


class SizingError(InputError):
    """A sizing question that cannot be answered as asked (a bad mass, safety factor, ...)."""


class NotForceClosureError(FrictionConeError):
    """The grasp is not force-closure: squeezing harder cannot hold the part."""


Vec = tuple[Any, Any]

# public, documented and pickled as graspcompass.sizing.core's (which re-exports them)
SizingError.__module__ = NotForceClosureError.__module__ = "graspcompass.sizing.core"

_G = sp.Rational(*STANDARD_GRAVITY)


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


#: Most bits of a numerator or denominator in an exact sizing: beyond it (a centre of mass at
#: 1e300 m) the square roots |V_n| = sqrt(S_n² + C_n²) would factor numbers of thousands of
#: bits, so the sizing takes the float path (to its stated accuracy) instead.
MAX_EXACT_BITS = 256


def _within_exact_budget(values: list[Any]) -> bool:
    """Whether every rational in ``values`` has at most :data:`MAX_EXACT_BITS` bits."""
    for v in values:
        if not isinstance(v, sp.Basic):
            continue
        for r in v.atoms(sp.Rational):
            if max(int(r.p).bit_length(), int(r.q).bit_length()) > MAX_EXACT_BITS:
                return False
    return True


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


def _world(grasp: WorldGrasp | Grasp) -> WorldGrasp:
    """The placed grasp, or the identity placement of a paper-frame Grasp."""
    if isinstance(grasp, WorldGrasp):
        return grasp
    if not isinstance(grasp, Grasp):
        raise WrongTypeError(
            "grasp: expected a WorldGrasp (graspcompass.place_grasp) or a "
            f"Grasp, got {type(grasp).__name__}"
        )
    if any(v.free_symbols for v in grasp.params.values() if isinstance(v, sp.Basic)):
        raise SizingError(
            "grasp: a symbolic grasp has no size in newtons; substitute values first (Grasp.subs)"
        )
    g = grasp
    zero, one = sp.Integer(0), sp.Integer(1)
    return WorldGrasp(
        g,
        (zero, zero),
        (one, zero),
        (zero, one),
        zero,
        ("P1", "P2"),
        ((g.x1, g.y), (-g.x2, g.y)),
        ((-g.s1, -g.c1), (g.s2, -g.c2)),
        "P1",
    )


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


def _read_case(
    wg: WorldGrasp | None,
    mass: Any,
    g: Any,
    gravity: Any,
    tilt: Any,
    accel: Any,
    safety: Any,
    per: str,
) -> _Case:
    """The checked case; ``wg`` None: a load alone, in floats (the planner's)."""
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
        if (
            isinstance(accel, (str, int, float))
            or isinstance(accel, sp.Basic)
            or not hasattr(accel, "__len__")
        ):
            A = _positive(acceleration_value(accel, "accel"), "the acceleration bound", False)
        else:
            ax, ay = _pair(accel, "accel")
            avec = (acceleration_value(ax, "accel x"), acceleration_value(ay, "accel y"))
    gdir = None
    if gravity is not None:
        gx, gy = _pair(gravity, "gravity")
        gdir = (real_value(gx, "gravity x"), real_value(gy, "gravity y"))
    elif avec is not None:
        raise SizingError(
            "accel: an acceleration vector needs the gravity direction "
            "(gravity=...), in the same frame as the contacts"
        )
    t = None
    if tilt is not None:
        if gravity is None:
            raise SizingError("tilt: a range of tilts needs the gravity direction (gravity=...)")
        t = _positive(angle_value(tilt, "tilt"), "the tilt", strict=False)
    raw = [m, gv, sf, A, *(avec or ()), *(gdir or ()), *(() if t is None else (t,))]
    exact = (
        wg is not None and wg.exact and not any(isinstance(v, float) or has_float(v) for v in raw)
    )
    if exact and wg is not None and not _within_exact_budget([*raw, *wg.grasp.S, *wg.grasp.C]):
        exact = False  # square roots of such numbers would factor them: the float path
    if gdir is not None:
        n2 = gdir[0] ** 2 + gdir[1] ** 2
        if _cmp(n2, 0, exact) <= 0:
            raise SizingError("gravity: the direction must not be the zero vector")
        n = _sqrt(n2, exact) if exact else math.sqrt(float(n2))
        gdir = (
            (canon(gdir[0] / n), canon(gdir[1] / n))
            if exact
            else (float(gdir[0]) / n, float(gdir[1]) / n)
        )
    if t is not None and _cmp(t, sp.pi, exact) >= 0:
        t = "any"  # a tilt of ±180° or more reaches every orientation
    conv = (lambda v: v) if exact else float
    return _Case(
        exact,
        conv(m),
        conv(gv),
        conv(sf),
        conv(A),
        None if avec is None else (conv(avec[0]), conv(avec[1])),
        gdir,
        t if t in (None, "any") else conv(t),
        per,
    )
