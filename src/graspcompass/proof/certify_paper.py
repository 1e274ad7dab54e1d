"""What each object of the drawing must be, transcribed from the paper (§3.3, Appendix).

:class:`PaperModel` takes the printed formulas of :mod:`graspcompass.proof.paper`
(S_n, C_n of eqs. (28)-(39) in the tan form) and the statements of §3.3 and of
the Appendix ((A4)-(A8)), and substitutes a grasp's parameter values.  It never
calls the grasp's own closed form (``Grasp.S``, ``Grasp.V``, ``side_direction``):
those are code under test, like the construction.

For a contact whose friction is given by μ the tangents are written in the μ
form, the corrected eq. (23)::

    tan(a·φ + b·ξ) = (a·s + b·c·μ) / (c − a·b·s·μ),   s = sin φ, c = cos φ, a, b = ±1,

and the cone sides' directions are divided by cos ξ > 0 (tan ξ = μ, eq. (22)).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import sympy as sp

from .. import symbols as S
from ..geometry.trig import sincos
from . import paper

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["SIDES", "PaperModel", "model_at", "paper_model"]

#: The contact (1 or 2) and the sign of ξ (+1 upper side, −1 lower side) of side n.
SIDES: dict[int, tuple[int, int]] = {1: (1, 1), 2: (2, 1), 3: (1, -1), 4: (2, -1)}
_PHI = {1: S.phi1, 2: S.phi2}
_XI = {1: S.xi1, 2: S.xi2}
_MU = {1: S.mu1, 2: S.mu2}

Pt = tuple[sp.Expr, sp.Expr]


@dataclass(frozen=True)
class PaperModel:
    """The paper's objects for one grasp (coordinates as sympy expressions).

    Attributes
    ----------
    values : dict
        Model symbol -> the grasp's value (the symbol itself for a symbolic grasp).
    mu_form : tuple of bool
        Per contact: friction given by μ (the μ form of (23)) rather than by ξ.
    numeric : bool
        True when the grasp holds floats (facts are then tested to rounding).
    """

    values: Mapping[sp.Symbol, sp.Expr]
    mu_form: tuple[bool, bool]
    numeric: bool

    def _v(self, expr: sp.Expr) -> sp.Expr:
        vals = dict(self.values)
        e = sp.sympify(expr)  # internal: the model's
        if not self.numeric:  # sin, cos of a typed angle as the grasp writes them (trig.sincos)
            e = e.replace(sp.sin, lambda a: _sincos(a, vals)[0])
            e = e.replace(sp.cos, lambda a: _sincos(a, vals)[1])
            e = e.replace(sp.tan, lambda a: _div(*_sincos(a, vals)))
        return e.xreplace(vals)

    # -- data (§2.2.1, Fig. 2) -------------------------------------------------
    @property
    def length(self) -> sp.Expr:
        """``x1 + x2 + y``: the length scale of the grasp (for float tolerances)."""
        return self._v(S.x1 + S.x2 + S.y)

    def P(self, i: int) -> Pt:
        """Contact ``P1 = (x1, y)``, ``P2 = (−x2, y)`` (§2.2.1)."""
        return (self._v(S.x1), self._v(S.y)) if i == 1 else (self._v(-S.x2), self._v(S.y))

    def Px(self, i: int) -> Pt:
        """Feet on the x-axis: ``P1x = (x1, 0)``, ``P2x = (−x2, 0)`` (§3.3)."""
        return self.P(i)[0], sp.Integer(0)

    @property
    def O_M(self) -> Pt:
        """Midpoint of P1x P2x, ``((x1 − x2)/2, 0)`` (§3.3)."""
        return self._v((S.x1 - S.x2) / 2), sp.Integer(0)

    def _tan(self, arg: sp.Expr) -> sp.Expr:
        """tan(a·φ_i + b·ξ_i), in the μ form (23) for a contact given by μ."""
        for i in (1, 2):
            a, b = arg.coeff(_PHI[i]), arg.coeff(_XI[i])
            if a in (1, -1) and b in (1, -1) and sp.expand(arg - a * _PHI[i] - b * _XI[i]) == 0:
                if not self.mu_form[i - 1]:
                    return sp.tan(arg)
                s, c, mu = sp.sin(_PHI[i]), sp.cos(_PHI[i]), _MU[i]
                return (a * s + b * c * mu) / (c - a * b * s * mu)
        raise ValueError(f"not an angle of a cone side: {arg}")  # pragma: no cover

    def _printed(self, expr: sp.Expr) -> sp.Expr:
        return self._v(expr.replace(sp.tan, self._tan))

    def tan_side(self, n: int) -> sp.Expr:
        """tan(φ_i ± ξ_i) of side n (n = 1, 3 at P1; 2, 4 at P2; ± by n ≤ 2)."""
        i, sg = SIDES[n]
        return self._v(self._tan(_PHI[i] + sg * _XI[i]))

    def side_direction(self, n: int) -> Pt:
        """Direction of cone side n at angle φ_i ± ξ_i from the negative y-axis.

        P1 clockwise: ``(−sin α, −cos α)``; P2 counter-clockwise: ``(sin α, −cos α)``
        (§2.2.2, Fig. 2); in the μ form divided by cos ξ > 0.
        """
        i, sg = SIDES[n]
        phi, xi = _PHI[i], _XI[i]
        if self.mu_form[i - 1]:
            s, c, mu = sp.sin(phi), sp.cos(phi), _MU[i]
            sa, ca = s + sg * c * mu, c - sg * s * mu
        else:
            sa, ca = sp.sin(phi + sg * xi), sp.cos(phi + sg * xi)
        sx = -sa if i == 1 else sa
        return self._v(sx), self._v(-ca)

    # -- the drawing (§3.3 with the Appendix) -----------------------------------
    def S(self, n: int) -> sp.Expr:
        """S_n as printed, eqs. (28), (34), (36), (38)."""
        return self._printed(paper.S_printed[n - 1])

    def C(self, n: int) -> sp.Expr:
        """C_n as printed, eqs. (29), (35), (37), (39)."""
        return self._printed(paper.C_printed[n - 1])

    def V(self, n: int) -> Pt:
        """V_n = (S_n, C_n), eq. (30), (33)."""
        return self.S(n), self.C(n)

    def X(self, n: int) -> Pt:
        """X_n on the x-axis with signed length O_M X_n = −S_n (§3.3 step (1), (A7))."""
        return self.O_M[0] - self.S(n), sp.Integer(0)

    def PxX(self, n: int) -> sp.Expr:
        """Signed P_ix X_n = ∓y·tan(φ_i ± ξ_i), (A4) with (A6) (− at P1, + at P2)."""
        i, _ = SIDES[n]
        return (-1 if i == 1 else 1) * self._v(S.y) * self.tan_side(n)

    def Y(self, n: int) -> Pt:
        """Y_n on the y-axis with signed O Y_n = −C_n (§3.3 step (2), (A5), (A8))."""
        return sp.Integer(0), -self.C(n)

    def foot_of(self, n: int) -> Pt:
        """The foot the perpendicular of step (2) starts from: P2x (n = 1, 3), P1x (n = 2, 4)."""
        return self.Px(2 if SIDES[n][0] == 1 else 1)

    def circle(self, n: int) -> tuple[Pt, sp.Expr]:
        """Circle on the diameter O V_n: centre V_n/2, radius² |V_n|²/4 (§3.2, Fig. 3)."""
        s, c = self.V(n)
        return (s / 2, c / 2), (s**2 + c**2) / 4

    def k(self, n: int, theta: Any) -> sp.Expr:
        """k_n(θ) = S_n sin θ − C_n cos θ, eq. (27)."""
        return self.S(n) * sp.sin(theta) - self.C(n) * sp.cos(theta)


def _sincos(angle: sp.Expr, vals: Mapping[sp.Symbol, sp.Expr]) -> tuple[sp.Expr, sp.Expr]:
    """sin, cos of ``angle`` at the grasp's values as the grasp writes them
    (:func:`~graspcompass.geometry.trig.sincos`); a sum φ ± ξ whose value is not a
    rational multiple of π (6/5 + 1/2) by the addition formula, so that its
    generators are those of φ and ξ."""
    v = angle.xreplace(dict(vals))
    if v.free_symbols or not v.is_number:
        return sp.sin(v), sp.cos(v)
    if (v / sp.pi).is_Rational:
        return sincos(v)
    if v.could_extract_minus_sign():  # sin(−ξ) = −sin ξ: the generators of ξ
        s, c = _sincos(-angle, vals)
        return -s, c
    if not angle.is_Add:
        return sincos(v)
    first, rest = angle.as_two_terms()
    (sa, ca), (sb, cb) = _sincos(first, vals), _sincos(rest, vals)
    return sa * cb + ca * sb, ca * cb - sa * sb


def _div(s: sp.Expr, c: sp.Expr) -> sp.Expr:
    return s / c


def _mu_form(xi: sp.Expr, mu: sp.Expr) -> bool:
    return isinstance(xi, sp.atan) and xi.args[0] == mu


def paper_model(grasp: Grasp | None) -> PaperModel:
    """The paper's objects for ``grasp`` (a :class:`~graspcompass.grasp.Grasp`)."""
    if grasp is None:
        raise ValueError("the paper's objects need a grasp; this construction has none")
    p = grasp.params
    values = {getattr(S, k): v for k, v in p.items()}
    mu_form = (_mu_form(p["xi1"], p["mu1"]), _mu_form(p["xi2"], p["mu2"]))
    return PaperModel(values, mu_form, bool(getattr(grasp, "numeric", False)))


def model_at(model: PaperModel, point: Mapping[sp.Symbol, sp.Expr]) -> PaperModel:
    """``model`` with its symbols replaced by the exact values ``point``."""
    # internal: a Grasp's values (read by graspcompass.inputs) and a sampled point
    vals = {k: sp.sympify(v).xreplace(dict(point)) for k, v in model.values.items()}
    return PaperModel(vals, model.mu_form, False)
