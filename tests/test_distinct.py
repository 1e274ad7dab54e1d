"""``distinct``: the Rabinowitsch proof that two constructed points differ.

Expected answers come from the geometry of each pair (a point of the unit circle is
never the origin; two lengths are equal somewhere), never from the implementation.
Each pair is asked through the model's ring (python-flint) and through the general
route (sympy), which must agree.
"""

from __future__ import annotations

import pytest
import sympy as sp

from graspcompass.geometry import Point
from graspcompass.proof import program_conditions as pc
from graspcompass.symbols import mu1, phi1, phi2, x1, x2, y

s1, c1, s2, c2 = sp.sin(phi1), sp.cos(phi1), sp.sin(phi2), sp.cos(phi2)

CASES = [
    # (a, b, assumed non-zero, they differ wherever the assumed are non-zero)
    ((x1, 0), (-x2, 0), [], True),  # x1 + x2 > 0 on the domains
    ((x1, 0), (x2, 0), [], False),  # equal where x1 = x2
    ((c1, s1), (0, 0), [], True),  # a point of the unit circle is not O
    ((c1, 0), (0, 0), [], False),  # φ1 = π/2
    ((x1 - x2, y), (0, y), [x1 - x2], True),
    ((x1 - x2, y), (0, y), [], False),
    ((mu1 * c1, s1), (0, 0), [], True),  # μ1 > 0 and sin² + cos² = 1
    ((c1 * c2 - s1 * s2, 0), (0, 0), [], False),  # cos(φ1 + φ2) = 0 somewhere
    ((c1 * c2 - s1 * s2, 0), (0, 0), [c1 * c2 - s1 * s2], True),
    ((x1 * s1 - x2 * s2, y), (0, 0), [], False),
]


@pytest.mark.parametrize(("a", "b", "assumed", "expected"), CASES)
def test_distinct(a, b, assumed, expected) -> None:
    pa, pb = Point(*a), Point(*b)
    assert pc.distinct(pa, pb, assumed) is expected
    # the general route (sympy's together, the same Gröbner test) agrees
    assert pc._distinct_general(pa, pb, assumed) is expected
    assert pc._distinct_in_ring(pa, pb, assumed) is expected


def test_outside_the_ring_takes_the_general_route() -> None:
    t = sp.Symbol("t", positive=True)
    assert pc._distinct_in_ring(Point(t, 0), Point(0, 0), []) is None
    assert pc.distinct(Point(t, 0), Point(0, 0), []) is False  # no sign used for t
    assert pc.distinct(Point(t, 0), Point(0, 0), [t]) is True
