"""The validation of a grasp: the parameters' ranges and the contact conditions (1).

A :class:`~graspcompass.grasp.Grasp` is checked once, when it is made: the
friction of each contact (μ > 0 or 0 < ξ < π/2, eq. (22)), ``x1 + x2 > 0``,
``y >= 0``, ``0 < φ <= π``, and condition (1) on ``φ ± ξ`` for each contact; a
condition that cannot be decided for symbols becomes an assumption.  A float grasp
must be all doubles and not within rounding of a bound of (1).
Private to :mod:`graspcompass.grasp`, which re-exports these names.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..geometry.exact import canon, decide_sign, has_float
from ..geometry.trig import tan_exact
from ._floatpath import FLOAT_MARGIN, condition_1_margins
from ._values import (
    InvalidGraspError,
    NonFiniteParameterError,
    _exact_kind,
    _fmt,
    _fmt_angle,
    _pi_multiple,
    _rounded_tan,
    _value,
)

if TYPE_CHECKING:
    from . import Grasp


def _degrees_hint(angle: Any, most: int) -> str:
    """The hint for an angle typed in degrees without its unit (``90`` for ``90deg``)."""
    if angle.is_Rational and 3 < angle <= most:
        return f"; a number without a unit is in radians: for {angle} degrees write {angle}deg"
    return ""


def _length_checks(g: Grasp) -> list[tuple[Any, ...]]:
    """The domain of x1, x2: ``x1 + x2 > 0`` for a grasp of numbers (issue 13 §1).

    Eqs. (12)-(39) only divide by x1 + x2 (det L L^T = 2 (x1 + x2)^2), so they hold
    when the centre of mass projects beyond a contact, x1 <= 0 or x2 <= 0.  A grasp
    with symbols keeps the paper's x1 > 0, x2 > 0 (§2.2.1): the proof checker's
    symbolic verdicts state those domains as hypotheses.
    """
    if any(v.free_symbols for v in g.params.values()):
        beyond = (
            " for a grasp with symbols (the symbolic proofs assume the paper's domain "
            "x1, x2 > 0 of §2.2.1; give every parameter a value to place the centre "
            "of mass beyond a contact)"
        )
        return [
            (
                g.x1,
                True,
                "x1 = {v} must be positive: P1 = (x1, y) lies right of the y-axis" + beyond,
            ),
            (
                g.x2,
                True,
                "x2 = {v} must be positive: P2 = (-x2, y) lies left of the y-axis" + beyond,
            ),
        ]
    return [
        (
            g.x1 + g.x2,
            True,
            "x1 + x2 = {v} must be positive: P1 = (x1, y) lies right of "
            "P2 = (-x2, y) (x1 <= 0 or x2 <= 0 alone is allowed: the centre of mass then "
            "projects onto the line through the contacts beyond a contact)",
        )
    ]


def _friction(i: int, mu: Any, xi: Any) -> tuple[sp.Expr, sp.Expr]:
    if (mu is None) == (xi is None):
        raise InvalidGraspError(
            f"contact {i}: give the friction either as mu{i} (coefficient) or as "
            f"xi{i} (cone half angle), exactly one of them"
        )
    if mu is not None:
        m = _exact_kind(_value(mu, f"mu{i}"), f"mu{i}")
        if decide_sign(m) in (-1, 0):
            raise InvalidGraspError(
                f"contact {i}: the friction coefficient μ{i} = {_fmt(m)} must be positive"
            )
        return m, sp.atan(m)
    x = _value(xi, f"xi{i}")
    q = _pi_multiple(x)
    bounds = (
        ()
        if q is not None and 0 < q < sp.Rational(1, 2)
        else ((x, (-1, 0), "positive"), (sp.pi / 2 - x, (-1, 0), "< π/2"))
    )
    for bound, sign, words in bounds:
        if decide_sign(bound) in sign:
            raise InvalidGraspError(
                f"contact {i}: the friction cone half angle ξ{i} = {_fmt_angle(x)} "
                f"must be {words} (0 < ξ < π/2){_degrees_hint(x, 90)}"
            )
    if x.free_symbols:
        return sp.tan(x), x  # a symbol: tan(xi) is one generator
    if has_float(x):  # μ = tan ξ correctly rounded to a double, eq. (22) (sympy's
        return _rounded_tan(x), x  # 53-bit tan can be an ulp off, and k moves with it)
    return canon(tan_exact(x)), x


def _validate(g: Grasp) -> None:
    pi = sp.pi
    checks: list[tuple[Any, ...]] = _length_checks(g)
    checks.append((g.y, False, "y = {v} must be non-negative (the frame of §2.2.1 puts y >= 0)"))
    for i, phi in ((1, g.phi1), (2, g.phi2)):
        q = _pi_multiple(phi)
        if q is not None and 0 < q <= 1:
            continue  # 0 < φ ≤ π, decided in rationals
        hint = _degrees_hint(phi, 180)
        checks += [
            (phi, True, f"contact {i}: φ{i} = {{a}} must be positive (0 < φ ≤ π){hint}"),
            (
                pi - phi,
                False,
                f"contact {i}: φ{i} = {{a}} must not exceed π (0 < φ ≤ π){hint}",
                phi,
            ),
        ]
    assumed: list[sp.Basic] = []
    for expr, strict, msg, *shown in checks:
        _check(expr, strict, msg, assumed, *shown)
    _check_float_margins(g)  # floats within rounding of (1): refuse, with advice
    if _angles_pass(g):
        object.__setattr__(g, "assumptions", tuple(assumed))
        return
    for i in (1, 2):
        phi, xi = (g.phi1, g.xi1) if i == 1 else (g.phi2, g.xi2)
        up, lo = phi + xi, phi - xi
        who = f"the friction cone at P{i}"
        other = f"P{3 - i}"
        cond = [
            (
                lo + pi / 2,
                f"φ{i} − ξ{i} = {{a}} must exceed −π/2 — {who} turns past the "
                "contact's tangent line (condition (1))",
                lo,
            ),
            (
                pi / 2 - lo,
                f"φ{i} − ξ{i} = {{a}} must be below π/2 — {who} does not "
                f"contain {other} (its lower side passes above {other}; condition (1))",
                lo,
            ),
            (
                up - pi / 2,
                f"φ{i} + ξ{i} = {{a}} must exceed π/2 — {who} does not contain "
                f"{other} (its upper side passes below {other}; condition (1))",
                up,
            ),
            (
                3 * pi / 2 - up,
                f"φ{i} + ξ{i} = {{a}} must be below 3π/2 — {who} turns past "
                "the contact's tangent line (condition (1))",
                up,
            ),
        ]
        for expr, msg, shown in cond:
            _check(expr, True, f"contact {i}: " + msg, assumed, shown)
    object.__setattr__(g, "assumptions", tuple(assumed))


def _angles_pass(g: Grasp) -> bool:
    """Condition (1) decided in rationals when every φ and ξ is a rational multiple of π
    (the common case, without building sympy expressions); False: check one by one."""
    qs = [q for q in (_pi_multiple(a) for a in (g.phi1, g.xi1, g.phi2, g.xi2)) if q is not None]
    if len(qs) < 4:
        return False
    half, three_halves = sp.Rational(1, 2), sp.Rational(3, 2)
    for phi, xi in (qs[:2], qs[2:]):
        if not (-half < phi - xi < half and half < phi + xi < three_halves):
            return False
    return True


def _check_doubles(g: Grasp) -> None:
    """A grasp with a float parameter computes in doubles: every parameter must be one."""
    for name, v in g.params.items():
        if v.free_symbols:
            raise InvalidGraspError(
                f"{name} = {v} is symbolic but other parameters are floats: give every "
                "parameter as a number, or all exactly (text such as 'pi/3')"
            )
        try:
            finite = math.isfinite(float(v))
        except OverflowError:
            finite = False
        if not finite:
            raise NonFiniteParameterError(
                f"{name} = {_fmt(v)} is beyond double precision (about 1.8e308) and other "
                "parameters are floats, so the grasp computes in doubles: give every "
                "parameter exactly (text such as '1e309') instead"
            )


def _check_float_margins(g: Grasp) -> None:
    """Refuse a float grasp within rounding of a bound of condition (1).

    The float construction's X_n, Y_n, V_n scale like 1/cos(φ ± ξ) (eqs.
    (28)-(39)) and carry a relative error of about ε/|cos(φ ± ξ)|; below a
    margin of :data:`~graspcompass.grasp._floatpath.FLOAT_MARGIN` (1e-12) of the
    bound, double precision cannot resolve them (see :mod:`._floatpath`).
    """
    if not g.numeric or any(v.free_symbols for v in g.params.values()):
        return
    for m in condition_1_margins(g.params):
        if abs(m.relative) >= FLOAT_MARGIN:  # clearly inside, or clearly outside
            continue
        where = "within" if m.margin > 0 else "on the wrong side of, and within"
        raise InvalidGraspError(
            f"contact {m.contact}: {m.text} of condition (1) is within rounding of its "
            f"bound: φ{m.contact} {m.text[3]} ξ{m.contact} = {m.value!r} rad is {where} "
            f"{abs(m.margin):.2g} rad of {m.bound}, below the {FLOAT_MARGIN:g}·|{m.bound}| "
            "that double precision resolves here (the cone side is nearly horizontal and "
            f"X_n, Y_n, V_n scale like 1/cos(φ{m.contact} {m.text[3]} ξ{m.contact})). "
            "Give the parameters exactly, as text such as 'pi/2', '3*pi/4' or '1/3', "
            "to use the exact path"
        )


def _check(expr: sp.Expr, strict: bool, msg: str, assumed: list, shown: Any = None) -> None:
    sign = decide_sign(expr)
    bad = sign == -1 or (strict and sign == 0)
    if bad:
        v = expr if shown is None else shown
        raise InvalidGraspError(msg.format(v=_fmt(v), a=_fmt_angle(v)))
    if sign is None:
        rel = expr > 0 if strict else expr >= 0
        if rel is not sp.true:
            assumed.append(rel)
