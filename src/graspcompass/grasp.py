"""The paper's model of a two-point grasp (§2, §3.2), exact and vectorised.

Frame (§2.2.1): the origin O is the object's centre of mass, the y-axis is
perpendicular to the line through the contacts, ``P1 = (x1, y)`` and
``P2 = (-x2, y)``.  The normal at P1 makes the angle φ1 clockwise, the normal
at P2 the angle φ2 counter-clockwise, with the negative y-axis.  Friction is
given by the coefficient μ or by the friction cone's half angle ξ, tan ξ = μ
(22).  The external force F_e acts at O along ``e(θ) = (sin θ, -cos θ)`` (26).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from ._floatpath import FLOAT_MARGIN, closed_form_floats, condition_1_margins, side_floats
from .batch import _envelope
from .errors import (
    ComplexValueError,
    GraspCompassError,
    InputError,
    NonFiniteValueError,
    SymbolicValueError,
    WrongTypeError,
)
from .expr import ExpressionError
from .geometry import Point
from .geometry.exact import canon, decide_sign, has_float
from .geometry.trig import sincos, tan_exact
from .inputs import angle_values, force_value, real_value, substitutions
from .presets import PRESETS

__all__ = ["PRESETS", "ComplexParameterError", "FrozenGraspError", "Grasp",
           "InvalidGraspError", "NonFiniteParameterError", "ParameterTypeError",
           "UnsupportedParameterError"]


class FrozenGraspError(dataclasses.FrozenInstanceError):
    """Assignment to (or deletion of) a field of a :class:`Grasp`, an immutable value.

    An :class:`AttributeError`, like :class:`dataclasses.FrozenInstanceError`;
    :meth:`Grasp.replace` makes a modified copy instead.
    """


class InvalidGraspError(GraspCompassError):
    """The parameters do not describe a grasp the paper's method applies to."""


class ParameterTypeError(WrongTypeError, InvalidGraspError):
    """A grasp parameter that is not a number (``None``, ``True``, a list, a dict)."""


class ComplexParameterError(ComplexValueError, InvalidGraspError):
    """A grasp parameter given as a complex number (``1j``, ``sympy.I``)."""


class NonFiniteParameterError(NonFiniteValueError, InvalidGraspError):
    """A grasp parameter that is ``nan`` or infinite."""


class UnsupportedParameterError(InputError, InvalidGraspError):
    """An exact length or friction coefficient outside what the exact kernel computes
    with: other roots than square roots of rationals (cube roots, nested roots)."""


_PARAMETER_ERRORS: dict[type, type] = {
    WrongTypeError: ParameterTypeError,
    ComplexValueError: ComplexParameterError,
    NonFiniteValueError: NonFiniteParameterError,
}


def _rounded_tan(x: sp.Expr) -> sp.Float:
    """``tan x`` of a float angle, correctly rounded to a double (40-digit mpmath)."""
    import mpmath

    with mpmath.workdps(40):
        return sp.Float(float(mpmath.tan(mpmath.mpf(sp.Float(x, 53)._mpf_))), 53)


def _value(v: Any, name: str) -> sp.Expr:
    """A parameter through the input boundary; a refusal is also an :class:`InvalidGraspError`."""
    try:
        return real_value(v, name)
    except ExpressionError:
        raise  # text the parser refuses (a complex value: also a ComplexValueError)
    except InputError as exc:
        for base, kind in _PARAMETER_ERRORS.items():
            if isinstance(exc, base):
                raise kind(str(exc)) from None
        raise InvalidGraspError(str(exc)) from None


def _pi_multiple(a: sp.Expr) -> sp.Rational | None:
    """q with a = q π exactly, read off the expression (no arithmetic), or None."""
    if a is sp.pi:
        return sp.Integer(1)
    if a.is_Rational:
        return sp.Integer(0) if a == 0 else None
    if a.is_Mul and len(a.args) == 2 and a.args[1] is sp.pi and a.args[0].is_Rational:
        return a.args[0]
    return None


def _exact_kind(v: sp.Expr, name: str) -> sp.Expr:
    """Refuse exact lengths and friction coefficients the kernel cannot compute with.

    They may hold rationals, square roots of rationals, π, symbols and functions
    such as sin or atan of anything; a cube root or a nested root would make every
    canonical form of the construction explode, so it is refused (give a decimal,
    which is exact, or a float).
    """
    if has_float(v):
        return v
    for a in sp.preorder_traversal(v):
        if a.is_Pow and not a.exp.is_Integer and not a.free_symbols and not (
                a.exp in (sp.S.Half, -sp.S.Half) and a.base.is_Rational):
            raise UnsupportedParameterError(
                f"{name} = {_fmt(v)} uses {a}: exact lengths and friction coefficients may "
                "hold square roots of rational numbers, not other roots; give the value as "
                "a decimal (read exactly) or a float")
    return v


def _double(v: sp.Expr, what: str) -> float:
    """A grasp value as a double; a value beyond double precision is refused."""
    try:
        out = float(v)
    except OverflowError:
        out = math.inf
    except TypeError:
        raise SymbolicValueError(f"{what} = {v} is not a number: the numeric path (a float θ) "
                                 "needs numbers; give θ exactly or substitute values first"
                                 ) from None
    if not math.isfinite(out):
        raise NonFiniteValueError(
            f"{what} = {_fmt(v)} is beyond double precision (about 1.8e308): the numeric "
            "path cannot use it; give θ exactly (text such as 'pi/3') for exact values")
    return out


def _finite(out: Any, what: str) -> Any:
    """Refuse a numeric result that overflowed double precision."""
    if not np.isfinite(out).all():
        raise NonFiniteValueError(
            f"{what} overflows double precision (|x| > 1.8e308) for these values; give θ "
            "and the force exactly (text such as 'pi/3') for exact values")
    return out


def _fmt_angle(v: sp.Expr) -> str:
    try:
        f = float(v / sp.pi)
    except (TypeError, OverflowError):
        return str(v)
    return f"{f:.3g}π" if math.isfinite(f) and abs(f) < 1e6 else f"{sp.N(v, 4)} rad"


def _fmt(v: sp.Expr) -> str:
    try:
        f = float(v)
    except (TypeError, OverflowError):
        return str(v)
    return str(v) if v.is_Rational else f"{v} ≈ {f:.4g}"


class Grasp:
    """A planar object held at two point contacts with friction (§2.2).

    Text such as ``"sqrt(3)/2"``, ``"pi/3"`` or ``"1.2"`` (= 6/5) is read
    exactly; Python floats select the numeric path.  Symbols are accepted;
    a condition that cannot be decided for them becomes an assumption
    (:attr:`assumptions`).

    Parameters
    ----------
    x1, x2, y : number or str
        Contacts ``P1 = (x1, y)``, ``P2 = (-x2, y)`` with ``x1 + x2 > 0``, ``y >= 0``.
        The paper (§2.2.1) takes ``x1, x2 > 0``; eqs. (12)-(39) hold as well when the
        centre of mass projects beyond a contact (``x1 <= 0`` or ``x2 <= 0``): they
        only divide by ``x1 + x2``.  A grasp with symbols keeps ``x1, x2 > 0``.
    phi1, phi2 : number or str
        Normal directions: φ1 clockwise, φ2 counter-clockwise from the negative
        y-axis, ``0 < φi <= π``.
    mu1, mu2, xi1, xi2 : number or str, optional
        Friction at each contact: the coefficient μi or the cone half angle ξi
        (tan ξi = μi, eq. (22)); give exactly one of the two per contact.

    Raises
    ------
    InvalidGraspError
        When a parameter is out of range or the contact point conditions (1)
        fail, naming the inequality, the contact and the values.

    Examples
    --------
    >>> from sympy import sqrt, Rational
    >>> g = Grasp.preset("fig6")
    >>> g.V[0] == Point(-1 - sqrt(3), -Rational(3, 2) - sqrt(3))
    True
    >>> Grasp(1, 1, 0, "pi/2", "pi/2", mu1="0.5", mu2="-1")
    Traceback (most recent call last):
    ...
    graspcompass.grasp.InvalidGraspError: contact 2: the friction coefficient μ2 = -1 must be ...
    """

    def __init__(
        self,
        x1: Any,
        x2: Any,
        y: Any,
        phi1: Any,
        phi2: Any,
        mu1: Any = None,
        mu2: Any = None,
        xi1: Any = None,
        xi2: Any = None,
        *,
        shape: tuple | None = None,
        title: str | None = None,
    ) -> None:
        x1, x2, y = (_exact_kind(_value(v, k), k) for v, k in ((x1, "x1"), (x2, "x2"), (y, "y")))
        init = object.__setattr__  # frozen: attributes are set here, once
        init(self, "x1", x1)
        init(self, "x2", x2)
        init(self, "y", y)
        init(self, "phi1", _value(phi1, "phi1"))
        init(self, "phi2", _value(phi2, "phi2"))
        m1, x1_ = self._friction(1, mu1, xi1)
        m2, x2_ = self._friction(2, mu2, xi2)
        init(self, "mu1", m1)
        init(self, "xi1", x1_)
        init(self, "mu2", m2)
        init(self, "xi2", x2_)
        init(self, "_given", ("mu" if mu1 is not None else "xi", "mu" if mu2 is not None else "xi"))
        init(self, "shape", shape)
        init(self, "title", title)
        init(self, "numeric", any(has_float(v) for v in self.params.values()))
        init(self, "assumptions", ())
        init(self, "_SC", None)  # float S_n, C_n, on demand (derived from frozen values)
        if self.numeric:
            self._check_doubles()
        self._validate()
        # exact sines and cosines without nested radicals (generators where needed)
        s1, c1 = sincos(self.phi1)
        s2, c2 = sincos(self.phi2)
        init(self, "s1", s1)
        init(self, "c1", c1)
        init(self, "s2", s2)
        init(self, "c2", c2)

    def __setattr__(self, name: str, value: Any) -> None:
        raise FrozenGraspError(
            f"cannot assign to field {name!r}: a Grasp is an immutable value (its derived "
            f"values are computed once); use g.replace({name}=...) for a modified grasp")

    def __delattr__(self, name: str) -> None:
        raise FrozenGraspError(f"cannot delete field {name!r}: a Grasp is an immutable value")

    def replace(self, **changes: Any) -> Grasp:
        """A new grasp with some parameters changed, validated again (like
        :func:`dataclasses.replace`); the grasp itself never changes.

        Keys are the constructor's: ``x1, x2, y, phi1, phi2``, the friction as
        ``mu1``/``xi1`` and ``mu2``/``xi2`` (giving one of a contact's pair drops
        the other), ``shape`` and ``title``.

        Examples
        --------
        >>> g = Grasp.preset("table1a")
        >>> h = g.replace(x1=3, mu2="1/2")
        >>> (h.x1, h.mu2, g.x1), h.k_grasp(0) == g.replace(x1=3).replace(mu2="0.5").k_grasp(0)
        ((3, 1/2, 2), True)
        """
        unknown = set(changes) - set(_REPLACEABLE)
        if unknown:
            raise TypeError(f"Grasp.replace() got unexpected field(s) {sorted(unknown)}; "
                            f"the fields are {', '.join(_REPLACEABLE)}")
        kw: dict[str, Any] = dict(x1=self.x1, x2=self.x2, y=self.y, phi1=self.phi1,
                                  phi2=self.phi2, shape=self.shape, title=self.title)
        for i in (1, 2):
            mu, xi = f"mu{i}", f"xi{i}"
            if mu in changes or xi in changes:
                kw[mu], kw[xi] = changes.pop(mu, None), changes.pop(xi, None)
            else:
                kind = self._given[i - 1]  # the form given: ξ stays ξ (no atan(tan ξ))
                kw[kind + str(i)] = getattr(self, kind + str(i))
        kw.update(changes)
        return Grasp(**kw)

    # -- construction -----------------------------------------------------------
    def _friction(self, i: int, mu: Any, xi: Any) -> tuple[sp.Expr, sp.Expr]:
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
        bounds = () if q is not None and 0 < q < sp.Rational(1, 2) else (
            (x, (-1, 0), "positive"), (sp.pi / 2 - x, (-1, 0), "< π/2"))
        for bound, sign, words in bounds:
            if decide_sign(bound) in sign:
                raise InvalidGraspError(
                    f"contact {i}: the friction cone half angle ξ{i} = {_fmt_angle(x)} "
                    f"must be {words} (0 < ξ < π/2)"
                )
        if x.free_symbols:
            return sp.tan(x), x  # a symbol: tan(xi) is one generator
        if has_float(x):  # μ = tan ξ correctly rounded to a double, eq. (22) (sympy's
            return _rounded_tan(x), x  # 53-bit tan can be an ulp off, and k moves with it)
        return canon(tan_exact(x)), x

    @classmethod
    def preset(cls, name: str) -> Grasp:
        """One of the paper's examples: ``"fig6"``, ``"table1a"``, ``"table1b"``, ``"table1c"``."""
        try:
            p = PRESETS[name]
        except KeyError:
            raise InvalidGraspError(
                f"unknown preset {name!r}; choose one of {', '.join(PRESETS)}"
            ) from None
        return cls(**p["params"], shape=p["shape"], title=p["title"])

    @classmethod
    def symbolic(cls, friction: str = "xi") -> Grasp:
        """The general grasp with every parameter a symbol of :mod:`graspcompass.symbols`.

        ``friction="xi"`` gives the friction by ξ1, ξ2; ``"mu"`` by μ1, μ2.
        """
        from . import symbols as s

        if friction not in ("xi", "mu"):
            raise InvalidGraspError(f"friction must be 'xi' or 'mu', got {friction!r}")
        fr = dict(xi1=s.xi1, xi2=s.xi2) if friction == "xi" else dict(mu1=s.mu1, mu2=s.mu2)
        return cls(s.x1, s.x2, s.y, s.phi1, s.phi2, **fr)

    # -- validation -------------------------------------------------------------
    def _validate(self) -> None:
        pi = sp.pi
        checks: list[tuple[Any, ...]] = _length_checks(self)
        checks.append(
            (self.y, False, "y = {v} must be non-negative (the frame of §2.2.1 puts y >= 0)"))
        for i, phi in ((1, self.phi1), (2, self.phi2)):
            q = _pi_multiple(phi)
            if q is not None and 0 < q <= 1:
                continue  # 0 < φ ≤ π, decided in rationals
            checks += [
                (phi, True, f"contact {i}: φ{i} = {{a}} must be positive (0 < φ ≤ π)"),
                (pi - phi, False, f"contact {i}: φ{i} = {{a}} must not exceed π (0 < φ ≤ π)",
                 phi),
            ]
        assumed: list[sp.Basic] = []
        for expr, strict, msg, *shown in checks:
            self._check(expr, strict, msg, assumed, *shown)
        self._check_float_margins()  # floats within rounding of (1): refuse, with advice
        if self._angles_pass():
            object.__setattr__(self, "assumptions", tuple(assumed))
            return
        for i in (1, 2):
            phi, xi = (self.phi1, self.xi1) if i == 1 else (self.phi2, self.xi2)
            up, lo = phi + xi, phi - xi
            who = f"the friction cone at P{i}"
            other = f"P{3 - i}"
            cond = [
                (lo + pi / 2, f"φ{i} − ξ{i} = {{a}} must exceed −π/2 — {who} turns past the "
                 "contact's tangent line (condition (1))", lo),
                (pi / 2 - lo, f"φ{i} − ξ{i} = {{a}} must be below π/2 — {who} does not "
                 f"contain {other} (its lower side passes above {other}; condition (1))", lo),
                (up - pi / 2, f"φ{i} + ξ{i} = {{a}} must exceed π/2 — {who} does not contain "
                 f"{other} (its upper side passes below {other}; condition (1))", up),
                (3 * pi / 2 - up, f"φ{i} + ξ{i} = {{a}} must be below 3π/2 — {who} turns past "
                 "the contact's tangent line (condition (1))", up),
            ]
            for expr, msg, shown in cond:
                self._check(expr, True, f"contact {i}: " + msg, assumed, shown)
        object.__setattr__(self, "assumptions", tuple(assumed))

    def _angles_pass(self) -> bool:
        """Condition (1) decided in rationals when every φ and ξ is a rational multiple of π
        (the common case, without building sympy expressions); False: check one by one."""
        qs = [_pi_multiple(a) for a in (self.phi1, self.xi1, self.phi2, self.xi2)]
        if None in qs:
            return False
        half, three_halves = sp.Rational(1, 2), sp.Rational(3, 2)
        for phi, xi in (qs[:2], qs[2:]):
            if not (-half < phi - xi < half and half < phi + xi < three_halves):
                return False
        return True

    def _check_doubles(self) -> None:
        """A grasp with a float parameter computes in doubles: every parameter must be one."""
        for name, v in self.params.items():
            if v.free_symbols:
                raise InvalidGraspError(
                    f"{name} = {v} is symbolic but other parameters are floats: give every "
                    "parameter as a number, or all exactly (text such as 'pi/3')")
            try:
                finite = math.isfinite(float(v))
            except OverflowError:
                finite = False
            if not finite:
                raise NonFiniteParameterError(
                    f"{name} = {_fmt(v)} is beyond double precision (about 1.8e308) and other "
                    "parameters are floats, so the grasp computes in doubles: give every "
                    "parameter exactly (text such as '1e309') instead")

    def _check_float_margins(self) -> None:
        """Refuse a float grasp within rounding of a bound of condition (1).

        The float construction's X_n, Y_n, V_n scale like 1/cos(φ ± ξ) (eqs.
        (28)-(39)) and carry a relative error of about ε/|cos(φ ± ξ)|; below a
        margin of :data:`~graspcompass._floatpath.FLOAT_MARGIN` (1e-12) of the
        bound, double precision cannot resolve them (see :mod:`._floatpath`).
        """
        if not self.numeric or any(v.free_symbols for v in self.params.values()):
            return
        for m in condition_1_margins(self.params):
            if abs(m.relative) >= FLOAT_MARGIN:  # clearly inside, or clearly outside
                continue
            where = ("within" if m.margin > 0 else "on the wrong side of, and within")
            raise InvalidGraspError(
                f"contact {m.contact}: {m.text} of condition (1) is within rounding of its "
                f"bound: φ{m.contact} {m.text[3]} ξ{m.contact} = {m.value!r} rad is {where} "
                f"{abs(m.margin):.2g} rad of {m.bound}, below the {FLOAT_MARGIN:g}·|{m.bound}| "
                "that double precision resolves here (the cone side is nearly horizontal and "
                f"X_n, Y_n, V_n scale like 1/cos(φ{m.contact} {m.text[3]} ξ{m.contact})). "
                "Give the parameters exactly, as text such as 'pi/2', '3*pi/4' or '1/3', "
                "to use the exact path"
            )

    @staticmethod
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

    # -- parameters -------------------------------------------------------------
    @property
    def params(self) -> dict[str, sp.Expr]:
        """The seven parameters ``x1, x2, y, phi1, phi2, mu1, mu2`` (plus ``xi1, xi2``)."""
        return dict(x1=self.x1, x2=self.x2, y=self.y, phi1=self.phi1, phi2=self.phi2,
                    mu1=self.mu1, mu2=self.mu2, xi1=self.xi1, xi2=self.xi2)

    def _key(self) -> tuple:
        return tuple(self.params.values())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Grasp) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        p = self.params
        return ("Grasp(" + ", ".join(f"{k}={p[k]}" for k in
                ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2")) + ")")

    @property
    def P1(self) -> Point:
        """Contact point 1, ``(x1, y)``."""
        return Point(self.x1, self.y)

    @property
    def P2(self) -> Point:
        """Contact point 2, ``(-x2, y)``."""
        return Point(-self.x2, self.y)

    @property
    def D(self) -> sp.Expr:
        """``x1 + x2``, the distance between the contacts."""
        return self.x1 + self.x2

    # -- friction cone sides ----------------------------------------------------
    def _side(self, n: int) -> tuple[sp.Expr, sp.Expr]:
        """``(sin(φ ± ξ), cos(φ ± ξ)) / cos ξ`` of side n, free of ``cos ξ``."""
        if self.numeric:  # correctly rounded: cos φ ∓ μ sin φ cancels in double precision
            sides = side_floats(self.params, n)
            if not all(math.isfinite(v) for v in sides):
                raise NonFiniteValueError(
                    f"the friction cone side {n} is beyond double precision (tan(φ ± ξ) "
                    "overflows); give the parameters exactly (text such as 'pi/3')")
            return tuple(sp.Float(v) for v in sides)  # type: ignore
        s, c, mu = (self.s1, self.c1, self.mu1) if n in (1, 3) else (self.s2, self.c2, self.mu2)
        sg = 1 if n in (1, 2) else -1
        return s + sg * c * mu, c - sg * s * mu

    def side_direction(self, n: int) -> Point:
        """Direction of friction-cone side n (n = 1, 3 at P1; 2, 4 at P2).

        n = 1, 2 are the upper sides (angle φ + ξ), n = 3, 4 the lower sides
        (φ − ξ).  The vector is the unit direction ``(∓sin(φ ± ξ), -cos(φ ± ξ))``
        divided by ``cos ξ > 0``, which keeps it free of ``cos ξ``.
        """
        sx, cx = self._side(n)
        return Point.canonical(-sx if n in (1, 3) else sx, -cx)

    def tan_side(self, n: int) -> sp.Expr:
        """``tan(φ ± ξ)`` of side n in the μ form of (18)-(21) and (23).

        Exact even at φ = π/2, where ``tan φ`` is undefined.
        """
        sx, cx = self._side(n)
        return canon(sx / cx)

    # -- the closed form, eqs. (27)-(39) ---------------------------------------
    @property
    def S(self) -> tuple[sp.Expr, ...]:
        """``(S1, S2, S3, S4)``, eqs. (28), (34), (36), (38)."""
        h = self.D / 2
        return tuple(
            canon(-h + self.y * self.tan_side(n)) if n in (1, 3)
            else canon(h - self.y * self.tan_side(n))
            for n in (1, 2, 3, 4)
        )

    @property
    def C(self) -> tuple[sp.Expr, ...]:
        """``(C1, C2, C3, C4)``, eqs. (29), (35), (37), (39)."""
        return tuple(
            canon((self.x2 if n in (1, 3) else self.x1) * self.tan_side(n)) for n in (1, 2, 3, 4)
        )

    @property
    def V(self) -> tuple[Point, Point, Point, Point]:
        """The four points ``V_n = (S_n, C_n)``, eqs. (30), (33)."""
        return tuple(Point(s, c) for s, c in zip(self.S, self.C))  # type: ignore[return-value]

    def _floats(self) -> tuple[np.ndarray, np.ndarray]:
        """``(S1..S4), (C1..C4)`` of eqs. (28)-(39) as doubles, for numeric θ.

        Evaluated from the parameters (floats taken as their exact binary values)
        at 40 digits or more and rounded once, so they are correct to about one
        unit in the last place even where a cone side is nearly horizontal and
        S_n, C_n ~ 1/cos(φ ± ξ) are ill-conditioned in double precision.

        Raises :class:`~graspcompass.errors.NonFiniteValueError` when a value is
        beyond half the largest double (then ``S_n sin θ - C_n cos θ`` could
        overflow): such a grasp is used with exact θ only.
        """
        if self._SC is None:
            try:
                S, C = closed_form_floats(self.params)
            except TypeError as exc:
                raise SymbolicValueError(
                    "a symbolic grasp cannot be evaluated on numeric θ; substitute values "
                    "first (Grasp.subs) or give θ exactly") from exc
            except OverflowError:
                S, C = [math.inf], [math.inf]
            if not all(abs(v) <= _HALF_MAX for v in (*S, *C)):  # also catches nan
                raise NonFiniteValueError(
                    "the grasp's S_n, C_n (eqs. (28)-(39)) are beyond double precision "
                    f"(|S_n|, |C_n| must stay below {_HALF_MAX:.2g}); the numeric path "
                    "cannot use this grasp: give θ exactly (text such as 'pi/3')")
            object.__setattr__(self, "_SC", (np.array(S), np.array(C)))
        return self._SC

    # -- k_n and k_grasp --------------------------------------------------------
    def k(self, theta: Any) -> Any:
        """The four lower limits ``k_n(θ) = V_n · e(θ)``, eqs. (18)-(21), (27), (32).

        θ goes through :func:`graspcompass.inputs.angle_values`: a float or an
        array (of at most :data:`~graspcompass.inputs.MAX_ARRAY_SIZE` finite
        values) gives an array of shape ``(4,) + shape(θ)``; anything else (int,
        text such as ``"pi/3"``, a sympy expression) a tuple of four exact
        expressions.  ``nan`` and infinities are refused
        (:class:`~graspcompass.errors.NonFiniteValueError`).
        """
        t = angle_values(theta)
        if _is_numeric(t):
            S, C = self._floats()
            s, c = np.sin(t), np.cos(t)
            return np.multiply.outer(S, s) - np.multiply.outer(C, c)
        s, c = sp.sin(t), sp.cos(t)
        return tuple(canon(S * s - C * c) for S, C in zip(self.S, self.C))

    def k_grasp(self, theta: Any) -> Any:
        """Least internal-force parameter ``max(k1, k2, k3, k4, 0)``, eq. (25).

        Exact for an exact θ (a ``Max`` when θ is a symbol); a float for a float
        θ, an array for an array.  θ is read as by :meth:`k`: text is parsed
        safely and exactly, and ``nan``, infinities, complex values, ``None``,
        bools and other objects are refused with a named
        :class:`~graspcompass.errors.InputError`.

        Examples
        --------
        >>> g = Grasp.preset("fig6")
        >>> from sympy import sqrt, Rational
        >>> g.k_grasp(0) == Rational(3, 2) + sqrt(3)
        True
        >>> float(g.k_grasp(0.0))
        3.232050807568877
        >>> g.k_grasp("108deg") == g.k_grasp(3 * sp.pi / 5)
        True
        """
        t = angle_values(theta)
        if isinstance(t, float):  # one angle: no array machinery
            S, C = self._floats()
            s, c = math.sin(t), math.cos(t)
            return max(0.0, *(float(Sn) * s - float(Cn) * c for Sn, Cn in zip(S, C)))
        if isinstance(t, np.ndarray):
            S, C = self._floats()
            if t.size >= _envelope.TABLE_MIN_SIZE:  # many angles: the table of the envelope
                table = self.__dict__.get("_ktable")  # (issue 13 §5)
                if table is None:
                    table = _envelope.EnvelopeTable(S, C)
                    object.__setattr__(self, "_ktable", table)
                return table(t)
            out = _envelope.direct_k_grasp(S, C, t)
            return out if t.ndim else float(out)
        ks = self.k(t)
        if any(k.free_symbols for k in ks):
            return sp.Max(*ks, sp.Integer(0))
        best = sp.Integer(0)
        for k in ks:
            if decide_sign(k - best) == 1:
                best = k
        return best

    def internal_force(self, theta: Any, external_force: Any = 1) -> Any:
        """Magnitude of the least internal force ``F_int = k/(x1 + x2) · F_e``, eq. (17).

        ``external_force`` is the magnitude ``F_e >= 0``
        (:func:`graspcompass.inputs.force_value`); θ as in :meth:`k`.
        """
        t = angle_values(theta)
        fe = force_value(external_force)
        kg = self.k_grasp(t)
        if _is_numeric(t):
            with np.errstate(over="ignore", invalid="ignore"):
                out = kg * _double(fe, "external_force") / _double(self.D, "x1 + x2")
            return _finite(out, "F_int")
        out = kg * fe / self.D
        return out if isinstance(kg, sp.Max) else canon(out)

    # -- the matrices of §2.3 --------------------------------------------------
    def grasp_matrix(self) -> sp.Matrix:
        """The grasp matrix L of eq. (5) (3 × 4)."""
        s1, c1, s2, c2, x1, x2, y = self.s1, self.c1, self.s2, self.c2, self.x1, self.x2, self.y
        return sp.Matrix([
            [-s1, -c1, s2, c2],
            [-c1, s1, -c2, s2],
            [-c1 * x1 + s1 * y, s1 * x1 + c1 * y, c2 * x2 - s2 * y, -s2 * x2 - c2 * y],
        ])

    def external_wrench(self, theta: Any, external_force: Any = 1) -> sp.Matrix:
        """``M = [-F_e sin θ, F_e cos θ, 0]^T`` of eq. (4), for one angle."""
        t = _one_angle(theta)
        fe = _sympy(force_value(external_force))
        return sp.Matrix([-fe * sp.sin(t), fe * sp.cos(t), 0])

    def F_T(self, theta: Any, external_force: Any = 1) -> Any:
        """Particular solution ``F_T = L^† M`` as printed in eq. (13).

        A sympy Matrix (4 × 1) for an exact θ; for a float or numpy θ an array of
        shape ``(4,) + shape(θ)``.  Inputs as in :meth:`internal_force`.
        """
        t = angle_values(theta)
        fe = force_value(external_force)
        numeric = _is_numeric(t)
        if numeric:
            s, c, fe = np.sin(t), np.cos(t), _double(fe, "external_force")
            D, x1, x2, y, s1, c1, s2, c2 = (_double(v, name) for v, name in (
                (self.D, "x1 + x2"), (self.x1, "x1"), (self.x2, "x2"), (self.y, "y"),
                (self.s1, "sin φ1"), (self.c1, "cos φ1"), (self.s2, "sin φ2"),
                (self.c2, "cos φ2")))
        else:
            fe = _sympy(fe)
            s, c = sp.sin(t), sp.cos(t)
            D, x1, x2, y = self.D, self.x1, self.x2, self.y
            s1, c1, s2, c2 = self.s1, self.c1, self.s2, self.c2
        a, b = y * s - x2 * c, y * s + x1 * c
        v = [D * s1 * s + 2 * a * c1, D * c1 * s - 2 * a * s1,
             -D * s2 * s - 2 * b * c2, -D * c2 * s + 2 * b * s2]
        if numeric:
            with np.errstate(over="ignore", invalid="ignore"):
                out = fe / (2 * D) * np.array(v)
            return _finite(out, "F_T")
        return sp.Matrix([fe / (2 * D) * e for e in v])

    def F_N(self, external_force: Any = 1) -> Any:
        """Internal-force direction ``F_N`` of eq. (15), a null vector of L.

        A sympy Matrix; a numpy array of shape (4,) for a float ``external_force``.
        """
        fe = force_value(external_force)
        if isinstance(fe, float):
            with np.errstate(over="ignore", invalid="ignore"):
                out = fe / _double(self.D, "x1 + x2") * np.array([
                    _double(v, name) for v, name in ((self.s1, "sin φ1"), (self.c1, "cos φ1"),
                                                     (self.s2, "sin φ2"), (self.c2, "cos φ2"))])
            return _finite(out, "F_N")
        return sp.Matrix([fe / self.D * e for e in (self.s1, self.c1, self.s2, self.c2)])

    def contact_forces(self, theta: Any, k: Any, external_force: Any = 1) -> Any:
        """``F = [N1, F1, N2, F2]^T = F_T + k F_N``, eq. (16).

        Exact for an exact θ (and ``k`` a number); for a float or numpy θ (and
        ``k`` a number or an array broadcasting with θ) an array of shape
        ``(4,) + shape(θ)``.  Inputs as in :meth:`internal_force`; ``k`` is read
        like θ (:func:`graspcompass.inputs.angle_values`).

        Examples
        --------
        >>> import numpy as np
        >>> g = Grasp.preset("table1a")
        >>> F = g.contact_forces(np.array([0.0, 1.0]), g.k_grasp(np.array([0.0, 1.0])))
        >>> F.shape
        (4, 2)
        """
        t = angle_values(theta)
        fe = force_value(external_force)
        if _is_numeric(t):
            kk = angle_values(k, "k")
            if not _is_numeric(kk):
                kk = _double(kk, "k")
            kk = np.asarray(kk, dtype=float)
            shape = np.shape(t)
            try:
                ok = np.broadcast_shapes(shape, kk.shape) == shape
            except ValueError:
                ok = False
            if not ok:
                raise InputError(f"k: an array of shape {kk.shape} does not broadcast with "
                                 f"theta's shape {shape}")
            fe = _double(fe, "external_force")
            fn = self.F_N(fe)
            ft = self.F_T(t, fe)
            with np.errstate(over="ignore", invalid="ignore"):
                out = ft + np.multiply.outer(fn, np.ones(ft.shape[1:])) * kk
            return _finite(out, "the contact forces")
        kv = real_value(k, "k")
        fe = _sympy(fe)
        return self.F_T(t, fe) + kv * self.F_N(fe)

    def subs(self, values: Mapping) -> Grasp:
        """The grasp with symbols replaced by ``values`` (validated again).

        Keys are the grasp's symbols or their names (``"x1"``); values are read
        by :func:`graspcompass.inputs.real_value` (text is parsed safely and
        exactly).  A key that is not a symbol of the grasp is refused.

        Examples
        --------
        >>> g = Grasp.symbolic("mu").subs({"x1": 2, "x2": 2, "y": 1, "phi1": "pi/2",
        ...                                "phi2": "pi/2", "mu1": 1, "mu2": "1.2"})
        >>> g.V == Grasp.preset("table1a").V
        True
        """
        free = set().union(*(v.free_symbols for v in self.params.values()))
        given = substitutions(values, free, "values")
        p = {k: v.xreplace(given) for k, v in self.params.items()}
        fr = dict(mu1=p["mu1"], mu2=p["mu2"])
        return Grasp(p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], **fr,
                     shape=self.shape, title=self.title)


#: The fields :meth:`Grasp.replace` takes (the constructor's arguments).
_REPLACEABLE = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2", "shape", "title")

_HALF_MAX = 0.5 * 1.7976931348623157e308  # k_n = S_n sin θ - C_n cos θ cannot overflow below


def _length_checks(g: Grasp) -> list[tuple[Any, ...]]:
    """The domain of x1, x2: ``x1 + x2 > 0`` for a grasp of numbers (issue 13 §1).

    Eqs. (12)-(39) only divide by x1 + x2 (det L L^T = 2 (x1 + x2)^2), so they hold
    when the centre of mass projects beyond a contact, x1 <= 0 or x2 <= 0.  A grasp
    with symbols keeps the paper's x1 > 0, x2 > 0 (§2.2.1): the proof checker's
    symbolic verdicts state those domains as hypotheses.
    """
    if any(v.free_symbols for v in g.params.values()):
        beyond = (" for a grasp with symbols (the symbolic proofs assume the paper's domain "
                  "x1, x2 > 0 of §2.2.1; give every parameter a value to place the centre "
                  "of mass beyond a contact)")
        return [
            (g.x1, True, "x1 = {v} must be positive: P1 = (x1, y) lies right of the y-axis"
             + beyond),
            (g.x2, True, "x2 = {v} must be positive: P2 = (-x2, y) lies left of the y-axis"
             + beyond),
        ]
    return [(g.x1 + g.x2, True, "x1 + x2 = {v} must be positive: P1 = (x1, y) lies right of "
             "P2 = (-x2, y) (x1 <= 0 or x2 <= 0 alone is allowed: the centre of mass then "
             "projects onto the line through the contacts beyond a contact)")]


def _is_numeric(theta: Any) -> bool:
    """After :func:`angle_values`: a float or an array selects the numeric path."""
    return isinstance(theta, (float, np.ndarray))


def _sympy(value: sp.Expr | float) -> sp.Expr:
    """A checked value for the exact path (a float becomes a sympy Float)."""
    return sp.Float(value) if isinstance(value, float) else value


def _one_angle(theta: Any) -> sp.Expr:
    t = angle_values(theta)
    if isinstance(t, np.ndarray):
        raise WrongTypeError(f"theta: expected one angle, got an array of shape {t.shape}")
    return _sympy(t)
