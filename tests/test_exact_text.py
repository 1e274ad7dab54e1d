"""The text of exact numbers in sines and cosines names the same number (issue 20).

``geometry._exact_text._fast_text`` prints the long sums of a typed grasp without
sympy's printer.  Each text, and sympy's own ``sstr`` of the same value, is evaluated
at 150 digits by the tests' own reader (``_evaluator.num``: Python's ``ast`` walked into
mpmath), which shares no code with graspcompass; the two must agree, on whole grasps
with every angle typed.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _evaluator import num
from graspcompass import Grasp, internal_force_diagram
from graspcompass.geometry.exact import text


def _values(c):
    for s in c.steps:
        o = s.obj
        for sub in (o, getattr(o, "point", None), getattr(o, "direction", None)):
            for a in ("x", "y"):
                v = getattr(sub, a, None) if sub is not None else None
                if isinstance(v, sp.Basic) and v.has(sp.sin, sp.cos):
                    yield s.name, v
        if s.kind == "circle":
            yield s.name, o.radius2


angles = st.integers(5, 175)


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(
    st.integers(2, 30),
    st.integers(2, 30),
    st.integers(0, 20),
    angles,
    angles,
    st.integers(1, 9),
    st.integers(1, 9),
)
def test_texts_read_back_to_their_numbers(x1, x2, y, phi1, phi2, d1, d2):
    # ξ_i inside condition (1): |φ_i − 90°| < ξ_i < 90°
    xi1 = min(89, abs(phi1 - 90) + d1)
    xi2 = min(89, abs(phi2 - 90) + d2)
    g = Grasp(
        f"{x1 / 10}",
        f"{x2 / 10}",
        f"{y / 10}",
        f"{phi1}.5deg",
        f"{phi2}deg",
        xi1=f"{xi1}deg",
        xi2=f"{xi2}.5deg" if xi2 < 89 else "89deg",
    )
    c = internal_force_diagram(g)
    values = list(_values(c))
    values += [("envelope", t) for a in c["envelope"].arcs for t in (a.theta_start, a.theta_end)]
    assert len(values) >= 8
    for name, v in values:
        with mpmath.workdps(150):  # long sums cancel: the two orders of terms round apart
            ours, sympys = num(text(v), {}), num(sp.sstr(v, order="none"), {})
        assert abs(ours - sympys) <= mpmath.mpf(10) ** -40 * (1 + abs(sympys)), (
            name,
            text(v)[:200],
        )
