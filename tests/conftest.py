"""Shared hypothesis strategies, fixtures and first-principles helpers.

Nothing here calls the code under test to obtain an *expected* value: the
closed forms (18)-(39) of Ito, Tanaka, Sasaki (Robotica 2012) and the grasp
matrix (5) are written out again from the paper, so that the tests compare the
implementation with an independent derivation.

Parameter domains (§2.2.1, condition (1)):  x1, x2 > 0, y >= 0, 0 < φ <= π,
0 < ξ < π/2 and  -π/2 < φ - ξ < π/2 < φ + ξ < 3π/2.  Given φ, condition (1)
with 0 < ξ < π/2 is exactly  |φ - π/2| < ξ < π/2, so the strategies draw φ
first and then ξ (or μ = tan ξ) in that interval with a margin of MARGIN rad.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
import pytest
import sympy as sp
from hypothesis import settings
from hypothesis import strategies as st

from graspcompass import Grasp, internal_force_diagram

# no timed assertions: hypothesis's 200 ms deadline per example failed a test of exact
# decimal text on a loaded 2-core machine; speed lives in bench/
settings.register_profile("graspcompass", deadline=None)
settings.load_profile("graspcompass")

#: Distance (rad) kept from the boundary of condition (1).
MARGIN = 0.05

#: Exact angles φ used for exact random grasps (rational multiples of π).
PHI_CHOICES = (
    sp.pi / 6,
    sp.pi / 4,
    sp.pi / 3,
    sp.pi / 2,
    2 * sp.pi / 3,
    3 * sp.pi / 4,
    5 * sp.pi / 6,
)

PRESET_NAMES = ("fig6", "table1a", "table1b", "table1c")


# ---------------------------------------------------------------------------
# first-principles formulas, written from the paper
# ---------------------------------------------------------------------------
def tan_sides(phi: Any, mu: Any, *, lib: Any = sp) -> tuple[Any, Any]:
    """``(tan(φ + ξ), tan(φ − ξ))`` with tan ξ = μ, in the μ form of eq. (23).

    tan(φ ± ξ) = (sin φ ± μ cos φ) / (cos φ ∓ μ sin φ); exact at φ = π/2.
    """
    s, c = lib.sin(phi), lib.cos(phi)
    return (s + c * mu) / (c - s * mu), (s - c * mu) / (c + s * mu)


def closed_form_SC(x1, x2, y, phi1, phi2, mu1, mu2, *, lib: Any = sp):
    """``((S1..S4), (C1..C4))`` of eqs. (28)-(29), (34)-(39)."""
    t1p, t1m = tan_sides(phi1, mu1, lib=lib)
    t2p, t2m = tan_sides(phi2, mu2, lib=lib)
    h = (x1 + x2) / 2
    S = (-h + y * t1p, h - y * t2p, -h + y * t1m, h - y * t2m)
    C = (x2 * t1p, x1 * t2p, x2 * t1m, x1 * t2m)
    return S, C


def k_paper(theta, x1, x2, y, phi1, phi2, mu1, mu2, *, lib: Any = sp):
    """k1..k4 from the first lines of eqs. (18)-(21) (the μ form, no tan(φ ± ξ))."""
    s, c = lib.sin(theta), lib.cos(theta)
    s1, c1, s2, c2 = lib.sin(phi1), lib.cos(phi1), lib.sin(phi2), lib.cos(phi2)
    h = (x1 + x2) / 2
    return (
        -h * s + (x2 * c - y * s) * (c1 * mu1 + s1) / (s1 * mu1 - c1),
        +h * s + (x1 * c + y * s) * (c2 * mu2 + s2) / (s2 * mu2 - c2),
        -h * s + (x2 * c - y * s) * (c1 * mu1 - s1) / (s1 * mu1 + c1),
        +h * s + (x1 * c + y * s) * (c2 * mu2 - s2) / (s2 * mu2 + c2),
    )


def _grasp_matrix_rows(x1, x2, y, phi1, phi2, sin, cos) -> list[list]:
    """The rows of L, eq. (5), written out from the paper, for any sin/cos."""
    s1, c1, s2, c2 = sin(phi1), cos(phi1), sin(phi2), cos(phi2)
    return [
        [-s1, -c1, s2, c2],
        [-c1, s1, -c2, s2],
        [-c1 * x1 + s1 * y, s1 * x1 + c1 * y, c2 * x2 - s2 * y, -s2 * x2 - c2 * y],
    ]


def grasp_matrix_sympy(x1, x2, y, phi1, phi2) -> sp.Matrix:
    """L of eq. (5), exact."""
    return sp.Matrix(_grasp_matrix_rows(x1, x2, y, phi1, phi2, sp.sin, sp.cos))


def grasp_matrix_numpy(x1, x2, y, phi1, phi2) -> np.ndarray:
    """L of eq. (5) with numpy floats."""
    return np.array(_grasp_matrix_rows(x1, x2, y, phi1, phi2, math.sin, math.cos))


def is_zero(expr: Any) -> bool:
    """Exact zero test: cheap canonical forms first, then ``sympy.simplify``."""
    e = sp.sympify(expr)
    if e == 0:
        return True
    e = sp.expand(sp.radsimp(sp.together(e)))
    if e == 0:
        return True
    return sp.simplify(e) == 0


# ---------------------------------------------------------------------------
# parameter records
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Params:
    """Grasp parameters as drawn (floats or exact sympy values), with μ and ξ both."""

    x1: Any
    x2: Any
    y: Any
    phi1: Any
    phi2: Any
    mu1: Any
    mu2: Any
    xi1: Any
    xi2: Any
    by_xi: bool = False

    def grasp(self) -> Grasp:
        if self.by_xi:
            return Grasp(self.x1, self.x2, self.y, self.phi1, self.phi2, xi1=self.xi1, xi2=self.xi2)
        return Grasp(self.x1, self.x2, self.y, self.phi1, self.phi2, mu1=self.mu1, mu2=self.mu2)

    @property
    def floats(self) -> tuple[float, ...]:
        """``(x1, x2, y, phi1, phi2, mu1, mu2)`` as Python floats."""
        return tuple(
            float(v) for v in (self.x1, self.x2, self.y, self.phi1, self.phi2, self.mu1, self.mu2)
        )

    @property
    def seven(self) -> tuple[Any, ...]:
        """``(x1, x2, y, phi1, phi2, mu1, mu2)`` as drawn."""
        return (self.x1, self.x2, self.y, self.phi1, self.phi2, self.mu1, self.mu2)


_I, _R = sp.Integer, sp.Rational
PRESET_PARAMS = {
    # §4.1 (Fig. 6) and Table I, typed in again from the paper
    "fig6": Params(
        sp.sqrt(3) / 2,
        sp.sqrt(3) / 2,
        _R(1, 2),
        sp.pi / 3,
        sp.pi / 3,
        _I(1),
        sp.sqrt(3),
        sp.pi / 4,
        sp.pi / 3,
        by_xi=True,
    ),
    "table1a": Params(
        _I(2), _I(2), _I(1), sp.pi / 2, sp.pi / 2, _I(1), _R(6, 5), sp.atan(1), sp.atan(_R(6, 5))
    ),
    "table1b": Params(
        _I(2), _I(2), _I(3), sp.pi / 2, sp.pi / 2, _I(1), _R(6, 5), sp.atan(1), sp.atan(_R(6, 5))
    ),
    "table1c": Params(
        _I(2),
        _I(2),
        _I(2),
        sp.pi / 2,
        sp.pi / 2,
        _R(1, 2),
        _R(7, 5),
        sp.atan(_R(1, 2)),
        sp.atan(_R(7, 5)),
    ),
}


# ---------------------------------------------------------------------------
# hypothesis strategies
# ---------------------------------------------------------------------------
def _xi_bounds(phi: float) -> tuple[float, float]:
    """Admissible ξ for φ under condition (1), shrunk by MARGIN."""
    return abs(phi - math.pi / 2) + MARGIN, math.pi / 2 - MARGIN


@st.composite
def float_contact(draw) -> tuple[float, float]:
    """``(φ, ξ)`` as floats with condition (1) holding by MARGIN."""
    phi = draw(st.floats(min_value=2.5 * MARGIN, max_value=math.pi - 2.5 * MARGIN))
    lo, hi = _xi_bounds(phi)
    xi = draw(st.floats(min_value=lo, max_value=hi))
    return phi, xi


@st.composite
def float_params(draw) -> Params:
    """Random valid grasp parameters as Python floats (numeric path)."""
    x1 = draw(st.floats(min_value=0.2, max_value=3.0))
    x2 = draw(st.floats(min_value=0.2, max_value=3.0))
    y = draw(st.floats(min_value=0.0, max_value=3.0))
    phi1, xi1 = draw(float_contact())
    phi2, xi2 = draw(float_contact())
    by_xi = draw(st.booleans())
    return Params(x1, x2, y, phi1, phi2, math.tan(xi1), math.tan(xi2), xi1, xi2, by_xi)


def _rational(lo: float, hi: float, max_denominator: int = 12) -> st.SearchStrategy:
    q = max_denominator
    return st.fractions(
        min_value=Fraction(math.ceil(lo * q), q),
        max_value=Fraction(math.floor(hi * q), q),
        max_denominator=q,
    ).map(lambda f: sp.Rational(f.numerator, f.denominator))


@st.composite
def exact_contact(draw) -> tuple[sp.Expr, sp.Expr]:
    """``(φ, μ)``: φ a rational multiple of π from PHI_CHOICES, μ rational, (1) with margin."""
    phi = draw(st.sampled_from(PHI_CHOICES))
    lo, hi = _xi_bounds(float(phi))
    # keep μ moderate so that the exact expressions stay small
    mu = draw(_rational(math.tan(lo), min(math.tan(hi), math.tan(lo) + 4.0)))
    return phi, mu


@st.composite
def exact_params(draw) -> Params:
    """Random valid grasp parameters as exact sympy values (rationals, multiples of π)."""
    x1 = draw(_rational(0.2, 3.0, 8))
    x2 = draw(_rational(0.2, 3.0, 8))
    y = draw(_rational(0.0, 3.0, 8))
    phi1, mu1 = draw(exact_contact())
    phi2, mu2 = draw(exact_contact())
    return Params(x1, x2, y, phi1, phi2, mu1, mu2, sp.atan(mu1), sp.atan(mu2))


# ---------------------------------------------------------------------------
# fixtures
# ---------------------------------------------------------------------------
@pytest.fixture(scope="session")
def preset_grasps() -> dict[str, Grasp]:
    return {name: Grasp.preset(name) for name in PRESET_NAMES}


@pytest.fixture(scope="session")
def preset_constructions(preset_grasps) -> dict[str, Any]:
    return {name: internal_force_diagram(g) for name, g in preset_grasps.items()}
