"""One point contact with Coulomb friction, exact or float, and its two cone edges.

The inward normal may be any nonzero vector (it is normalised) or an angle (the
direction of the normal, counter-clockwise from the x-axis).  The two edges are
``d = n ± μ J n`` with ``n`` the unit normal and ``J`` the quarter turn
counter-clockwise: their normal component is 1, so an edge weight is a normal
force (the cone sides of §2.2, Fig. 2, as in eqs. (8)-(11)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..boundary.errors import InputError
from ..boundary.inputs import real_value
from ..geometry.exact import canon, decide_zero, has_float
from ..geometry.trig import sincos
from ._signs import sign
from .errors import InvalidContactError

__all__ = ["Contact", "read_contact", "read_number"]


def read_number(value: Any, name: str, error: type[InputError] = InvalidContactError) -> sp.Expr:
    """``value`` through the input boundary (:func:`graspcompass.inputs.real_value`), a
    number without symbols; anything refused is raised again as ``error`` (the contacts'
    and the efforts' named errors)."""
    try:
        v = real_value(value, name)
    except InputError as exc:
        raise error(str(exc)) from None
    if v.free_symbols:
        raise error(f"{name}: symbols are not supported by the n-contact model, got {v}")
    return v


@dataclass(frozen=True)
class Contact:
    """A contact point ``p`` with unit inward normal ``n`` and friction coefficient ``mu``.

    Attributes
    ----------
    p : tuple of sympy.Expr
        The contact point (in the object's frame; the centre of mass is given
        to :class:`~graspcompass.ncontact.NContactGrasp`).
    n : tuple of sympy.Expr
        The unit inward normal.
    mu : sympy.Expr
        The friction coefficient μ >= 0 (tan ξ, eq. (22)).
    numeric : bool
        True when a value was a float (the numeric path).
    """

    p: tuple
    n: tuple
    mu: sp.Expr
    numeric: bool

    def edges(self) -> tuple[tuple, tuple]:
        """The two cone edges ``n + μ J n`` and ``n - μ J n`` (normal component 1)."""
        nx, ny = self.n
        jx, jy = -ny, nx
        if self.numeric:
            m = float(self.mu)
            return ((nx + m * jx, ny + m * jy), (nx - m * jx, ny - m * jy))
        return (
            (canon(nx + self.mu * jx), canon(ny + self.mu * jy)),
            (canon(nx - self.mu * jx), canon(ny - self.mu * jy)),
        )


def _unit(nx: sp.Expr, ny: sp.Expr, where: str, numeric: bool) -> tuple:
    if numeric:
        fx, fy = float(nx), float(ny)
        r = math.hypot(fx, fy)
        if not r > 0 or not math.isfinite(r):
            raise InvalidContactError(
                f"{where}: the normal ({fx}, {fy}) must be a nonzero finite vector"
            )
        return (fx / r, fy / r)
    r2 = canon(nx**2 + ny**2)
    if sign(r2, f"{where}: the squared length of the normal") == 0:
        raise InvalidContactError(f"{where}: the normal ({nx}, {ny}) is the zero vector")
    if decide_zero(r2 - 1):
        return (canon(nx), canon(ny))
    if not r2.is_Rational:
        raise InvalidContactError(
            f"{where}: give the normal as a unit vector, as a vector whose squared length is "
            f"rational, or as an angle (its squared length is {r2})"
        )
    r = sp.sqrt(r2)
    return (canon(nx / r), canon(ny / r))


def read_contact(spec: Any, index: int) -> Contact:
    """A :class:`Contact` from a Contact, a tuple or a mapping (outside values are checked).

    Parameters
    ----------
    spec : Contact, tuple or dict
        ``(x, y, nx, ny, mu)``, ``(x, y, angle, mu)`` (the normal's direction
        counter-clockwise from the x-axis), or a dict with keys ``x, y`` and
        ``nx, ny`` or ``angle``, and ``mu`` or ``xi`` (the cone's half angle).
    index : int
        The contact's number (1-based), for messages.

    Raises
    ------
    InvalidContactError
        For a missing or refused value, a zero normal, μ < 0 or ξ outside [0, π/2).
    """
    where = f"contact {index}"
    if isinstance(spec, Contact):
        return spec
    if isinstance(spec, dict):
        d = dict(spec)
    elif isinstance(spec, (tuple, list)):
        if len(spec) == 5:
            d = dict(zip(("x", "y", "nx", "ny", "mu"), spec))
        elif len(spec) == 4:
            d = dict(zip(("x", "y", "angle", "mu"), spec))
        else:
            raise InvalidContactError(
                f"{where}: expected (x, y, nx, ny, mu) or (x, y, angle, mu), got {len(spec)} values"
            )
    else:
        raise InvalidContactError(f"{where}: expected a tuple or a dict, got {type(spec).__name__}")
    unknown = set(d) - {"x", "y", "nx", "ny", "angle", "mu", "xi"}
    if unknown:
        raise InvalidContactError(f"{where}: unknown key(s) {sorted(unknown)}")
    if ("angle" in d) == ("nx" in d or "ny" in d) or ("mu" in d) == ("xi" in d):
        raise InvalidContactError(
            f"{where}: give the normal as nx, ny or as angle, and the "
            "friction as mu or as xi (exactly one of each)"
        )
    if "x" not in d or "y" not in d:
        raise InvalidContactError(f"{where}: the point needs x and y")
    vals = {k: read_number(v, f"{where}: {k}") for k, v in d.items()}
    numeric = any(has_float(v) for v in vals.values())
    if "angle" in vals:
        a = vals["angle"]
        if numeric:
            n = (math.cos(float(a)), math.sin(float(a)))
        else:
            s, c = sincos(a)
            n = (canon(c), canon(s))
    else:
        if "nx" not in vals or "ny" not in vals:
            raise InvalidContactError(f"{where}: the normal needs nx and ny")
        n = _unit(vals["nx"], vals["ny"], where, numeric)
    if "mu" in vals:
        mu = vals["mu"]
        if (float(mu) < 0) if numeric else sign(mu, f"{where}: μ") < 0:
            raise InvalidContactError(f"{where}: the friction coefficient μ = {mu} must be >= 0")
    else:
        xi = vals["xi"]
        if numeric:
            if not 0 <= float(xi) < math.pi / 2:
                raise InvalidContactError(f"{where}: ξ = {xi} must be in [0, π/2)")
            mu = sp.Float(math.tan(float(xi)))
        else:
            if sign(xi, f"{where}: ξ") < 0 or sign(xi - sp.pi / 2, f"{where}: ξ - π/2") >= 0:
                raise InvalidContactError(f"{where}: ξ = {xi} must be in [0, π/2)")
            s, c = sincos(xi)
            mu = canon(s / c)
    if numeric:
        p = (float(vals["x"]), float(vals["y"]))
        if not all(math.isfinite(v) for v in (*p, float(mu))):
            raise InvalidContactError(f"{where}: values must be finite")
        return Contact(p, (float(n[0]), float(n[1])), sp.Float(float(mu)), True)
    return Contact((canon(vals["x"]), canon(vals["y"])), n, canon(mu), False)
