"""The paper's model of a two-point grasp (§2, §3.2), exact and vectorised.

Frame (§2.2.1): the origin O is the object's centre of mass, the y-axis is
perpendicular to the line through the contacts, ``P1 = (x1, y)`` and
``P2 = (-x2, y)``.  The normal at P1 makes the angle φ1 clockwise, the normal
at P2 the angle φ2 counter-clockwise, with the negative y-axis.  Friction is
given by the coefficient μ or by the friction cone's apex angle ξ (the paper's
term, §2.2.2: the angle between the normal and each side of the cone), tan ξ = μ
(22).  The external force F_e acts at O along ``e(θ) = (sin θ, -cos θ)`` (26).

The code of :class:`Grasp` is here (its documentation is on the package page,
:mod:`graspcompass`), and in private modules
(every name stays importable from here): the errors and the input boundary of the
parameters (``grasp._values``), the validation and condition (1)
(``grasp._checks``), the float path and the forces of §2.3 (``grasp._forces``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from fractions import Fraction
from typing import TYPE_CHECKING, Any, overload

import sympy as sp

from ..boundary.errors import NonFiniteValueError
from ..boundary.inputs import angle_values, force_value, real_value, substitutions  # noqa: F401
from ..geometry import Point
from ..geometry.exact import canon, decide_sign, has_float  # noqa: F401
from ..geometry.trig import sincos
from ..presets import PRESETS
from . import _forces
from ._checks import (
    _angles_pass,  # noqa: F401
    _check,  # noqa: F401
    _check_doubles,
    _check_float_margins,  # noqa: F401
    _friction,
    _length_checks,  # noqa: F401
    _validate,
)
from ._floatpath import side_floats
from ._values import (
    _HALF_MAX,  # noqa: F401
    _PARAMETER_ERRORS,  # noqa: F401
    ComplexParameterError,
    FrozenGraspError,
    InvalidGraspError,
    NonFiniteParameterError,
    ParameterTypeError,
    UnsupportedParameterError,
    _double,  # noqa: F401
    _exact_kind,
    _finite,  # noqa: F401
    _fmt,  # noqa: F401
    _fmt_angle,  # noqa: F401
    _is_numeric,
    _one_angle,
    _pi_multiple,  # noqa: F401
    _rounded_tan,  # noqa: F401
    _sympy,
    _value,
)

if TYPE_CHECKING:
    import numpy as np
else:
    from ..boundary._numpy import np

__all__ = [
    "PRESETS",
    "ComplexParameterError",
    "FrozenGraspError",
    "Grasp",
    "InvalidGraspError",
    "NonFiniteParameterError",
    "ParameterTypeError",
    "UnsupportedParameterError",
]


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

    if TYPE_CHECKING:  # the attributes, set once by __init__ (a Grasp is frozen): exact sympy
        # numbers, or floats on the numeric path; declared for the type checker only (the
        # API page documents them as the parameters above, issue 21)
        # Contact coordinates: ``P1 = (x1, y)``, ``P2 = (-x2, y)``.
        x1: Any
        x2: Any
        y: Any
        # Normal directions φ1, φ2 (§2.2.1).
        phi1: Any
        phi2: Any
        # Friction: coefficients μi and cone half angles ξi (tan ξi = μi, eq. (22)).
        mu1: Any
        mu2: Any
        xi1: Any
        xi2: Any
        # sin φi and cos φi, exact without nested radicals (or floats).
        s1: Any
        c1: Any
        s2: Any
        c2: Any
        # The part's outline (drawing only) and a title, or None.
        shape: tuple | None
        title: str | None
        # True on the float path (a float among the parameters).
        numeric: bool
        # Conditions assumed for symbols that could not be decided.
        assumptions: tuple
        _given: tuple[str, str]
        _SC: Any

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
        m1, x1_ = _friction(1, mu1, xi1)
        m2, x2_ = _friction(2, mu2, xi2)
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
            _check_doubles(self)
        _validate(self)
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
            f"values are computed once); use g.replace({name}=...) for a modified grasp"
        )

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
            raise TypeError(
                f"Grasp.replace() got unexpected field(s) {sorted(unknown)}; "
                f"the fields are {', '.join(_REPLACEABLE)}"
            )
        kw: dict[str, Any] = dict(
            x1=self.x1,
            x2=self.x2,
            y=self.y,
            phi1=self.phi1,
            phi2=self.phi2,
            shape=self.shape,
            title=self.title,
        )
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
        from .. import symbols as s

        if friction not in ("xi", "mu"):
            raise InvalidGraspError(f"friction must be 'xi' or 'mu', got {friction!r}")
        fr = dict(xi1=s.xi1, xi2=s.xi2) if friction == "xi" else dict(mu1=s.mu1, mu2=s.mu2)
        return cls(s.x1, s.x2, s.y, s.phi1, s.phi2, **fr)

    # -- parameters -------------------------------------------------------------
    @property
    def params(self) -> dict[str, sp.Expr]:
        """The seven parameters ``x1, x2, y, phi1, phi2, mu1, mu2`` (plus ``xi1, xi2``)."""
        return dict(
            x1=self.x1,
            x2=self.x2,
            y=self.y,
            phi1=self.phi1,
            phi2=self.phi2,
            mu1=self.mu1,
            mu2=self.mu2,
            xi1=self.xi1,
            xi2=self.xi2,
        )

    def _key(self) -> tuple:
        return tuple(self.params.values())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Grasp) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        p = self.params
        return (
            "Grasp("
            + ", ".join(f"{k}={p[k]}" for k in ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2"))
            + ")"
        )

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
                    "overflows); give the parameters exactly (text such as 'pi/3')"
                )
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
            canon(-h + self.y * self.tan_side(n))
            if n in (1, 3)
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
        return _forces._closed_form_doubles(self)

    # -- k_n and k_grasp --------------------------------------------------------
    @overload
    def k(self, theta: int | str | Fraction) -> tuple[sp.Expr, ...]: ...
    @overload
    def k(self, theta: float | np.ndarray | list[float] | tuple[float, ...]) -> np.ndarray: ...
    @overload
    def k(self, theta: sp.Expr) -> tuple[sp.Expr, ...]: ...
    def k(self, theta: Any) -> Any:
        """The four lower limits ``k_n(θ) = V_n · e(θ)``, eqs. (18)-(21), (27), (32).

        θ goes through :func:`graspcompass.inputs.angle_values`: a float or an
        array (of at most :data:`~graspcompass.boundary.inputs.MAX_ARRAY_SIZE` finite
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

    @overload
    def k_grasp(self, theta: int | str | Fraction) -> sp.Expr: ...
    @overload
    def k_grasp(self, theta: float) -> float: ...
    @overload
    def k_grasp(
        self, theta: np.ndarray | list[float] | tuple[float, ...]
    ) -> np.ndarray | float: ...
    @overload
    def k_grasp(self, theta: sp.Expr) -> sp.Expr: ...
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
        return _forces._k_grasp(self, theta)

    @overload
    def internal_force(self, theta: int | str | Fraction, external_force: Any = 1) -> sp.Expr: ...
    @overload
    def internal_force(self, theta: float, external_force: Any = 1) -> float: ...
    @overload
    def internal_force(
        self, theta: np.ndarray | list[float] | tuple[float, ...], external_force: Any = 1
    ) -> np.ndarray | float: ...
    @overload
    def internal_force(self, theta: sp.Expr, external_force: Any = 1) -> sp.Expr: ...
    def internal_force(self, theta: Any, external_force: Any = 1) -> Any:
        """Magnitude of the least internal force ``F_int = k/(x1 + x2) · F_e``, eq. (17).

        ``external_force`` is the magnitude ``F_e >= 0``
        (:func:`graspcompass.inputs.force_value`); θ as in :meth:`k`.
        """
        return _forces._internal_force(self, theta, external_force)

    # -- the matrices of §2.3 --------------------------------------------------
    def grasp_matrix(self) -> sp.Matrix:
        """The grasp matrix L of eq. (5) (3 × 4)."""
        s1, c1, s2, c2, x1, x2, y = self.s1, self.c1, self.s2, self.c2, self.x1, self.x2, self.y
        return sp.Matrix(
            [
                [-s1, -c1, s2, c2],
                [-c1, s1, -c2, s2],
                [-c1 * x1 + s1 * y, s1 * x1 + c1 * y, c2 * x2 - s2 * y, -s2 * x2 - c2 * y],
            ]
        )

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
        return _forces._F_T(self, theta, external_force)

    def F_N(self, external_force: Any = 1) -> Any:
        """Internal-force direction ``F_N`` of eq. (15), a null vector of L.

        A sympy Matrix; a numpy array of shape (4,) for a float ``external_force``.
        """
        return _forces._F_N(self, external_force)

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
        return _forces._contact_forces(self, theta, k, external_force)

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
        return Grasp(
            p["x1"], p["x2"], p["y"], p["phi1"], p["phi2"], **fr, shape=self.shape, title=self.title
        )


#: The fields :meth:`Grasp.replace` takes (the constructor's arguments).
_REPLACEABLE = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2", "shape", "title")
