"""The annotations hold at run time (issue 21, "types that hold").

``Grasp.k``, ``Grasp.k_grasp`` and ``Grasp.internal_force`` are overloaded: exact input
(an int, text, a Fraction, a sympy expression) gives exact sympy values, a float gives a
float (four floats in an array for ``k``), a list or an array gives an array.  Each
overload is checked here against the kind of value it promises, for inputs of every
kind; the overloads themselves are read from the class (``typing.get_overloads``), so a
new overload without a case here fails.
"""

from __future__ import annotations

import typing
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from graspcompass import Grasp

G = Grasp.preset("fig6")

#: Input -> (kind of k, kind of k_grasp, kind of internal_force), from the docstrings.
CASES = [
    (0, "exact4", "exact", "exact"),
    ("pi/3", "exact4", "exact", "exact"),
    (Fraction(1, 2), "exact4", "exact", "exact"),
    (sp.pi / 5, "exact4", "exact", "exact"),
    (sp.Symbol("t", real=True), "exact4", "exact", "exact"),
    (0.5, "array4", "float", "float"),
    (np.float64(0.5), "array4", "float", "float"),
    ([0.1, 0.2, 0.3], "array", "array", "array"),
    ((0.1, 0.2), "array", "array", "array"),
    (np.linspace(0.0, 1.0, 5), "array", "array", "array"),
]


def _kind(value: object) -> str:
    if isinstance(value, tuple) and len(value) == 4 and all(isinstance(v, sp.Expr) for v in value):
        return "exact4"
    if isinstance(value, np.ndarray):
        return "array4" if value.shape == (4,) else "array"
    if isinstance(value, float):  # a Python float (np.float64 is one too)
        return "float"
    return "exact" if isinstance(value, sp.Expr) else type(value).__name__


@pytest.mark.parametrize(("theta", "k", "k_grasp", "force"), CASES)
def test_the_overloads_say_what_comes_back(theta: object, k: str, k_grasp: str, force: str) -> None:
    assert _kind(G.k(theta)) == k
    assert _kind(G.k_grasp(theta)) == k_grasp
    assert _kind(G.internal_force(theta)) == force


def test_float_results_are_plain_floats_not_sympy() -> None:
    """The float path never hands back a sympy Float (it would pass as exact)."""
    assert not isinstance(G.k_grasp(0.5), sp.Basic)
    assert not isinstance(G.internal_force(0.5), sp.Basic)
    assert G.k_grasp(0) == sp.Rational(3, 2) + sp.sqrt(3)  # exact: Fig. 6 at θ = 0
    assert G.k_grasp(0.0) == pytest.approx(1.5 + 3**0.5, rel=1e-15)


@pytest.mark.skipif(not hasattr(typing, "get_overloads"), reason="Python 3.11")
@pytest.mark.parametrize(("method", "count"), [("k", 3), ("k_grasp", 4), ("internal_force", 4)])
def test_every_overload_is_covered(method: str, count: int) -> None:
    assert len(typing.get_overloads(getattr(Grasp, method))) == count


def test_an_animation_of_a_construction_without_a_grasp_is_refused() -> None:
    """``Construction.grasp`` is ``Grasp | None``: the animations need a grasp and say so."""
    from graspcompass.construction.language import parse, replay
    from graspcompass.render.anim_physics import animate_sweep
    from graspcompass.render.timeline import AnimationError

    c = replay(parse("A = point (0, 0)\n"))
    assert c.grasp is None
    with pytest.raises(AnimationError, match="needs the construction of a grasp"):
        animate_sweep(c, frames=3)
