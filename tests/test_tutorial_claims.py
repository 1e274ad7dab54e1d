"""The tutorial's statements about the model, checked against the paper (issue 23).

Each statement the tutorial makes in words is recomputed here from the paper's formulas
or read from the paper's text (/work/shared/paper is not needed: the quotes are here):
§2.2.1 puts x1 > 0, x2 > 0, y ≥ 0; §2.2.2 calls ξ_i the apex angle; (12) makes F_T
= L†M, the minimum-norm solution; and which contact slips depends on θ (on Fig. 6,
contact 2 for θ between about 21° and 172°, by k2 up to about 120°), from
k_n(θ) = S_n sin θ − C_n cos θ (32) with S_n, C_n of eqs. (28)-(39) written out again.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

TUTORIAL = (Path(__file__).parent.parent / "docs" / "tutorial.md").read_text("utf-8")


def test_tutorial_states_the_frame_and_the_cone_as_the_paper() -> None:
    # §2.2.1: "Here, x1 > 0, x2 > 0, y ≥ 0, and 0 < φ1 ≤ π, 0 < φ2 ≤ π."
    assert "$y \\ge 0$" in TUTORIAL and "$x_1 > 0$, $x_2 > 0$" in TUTORIAL
    assert "nothing is proved" in TUTORIAL  # x1 ≤ 0 is computed, not covered by the proofs
    # §2.2.2: "ξ_i (0 < ξ_i < π/2) is an apex angle of the friction cone"
    assert "**apex\nangle**" in TUTORIAL or "**apex angle**" in TUTORIAL
    assert "half-angle" not in TUTORIAL
    # (12): F = L†M + (I − L†L)κ, F_T = L†M: the minimum-norm solution
    assert "minimum-norm solution" in TUTORIAL
    assert "is the one about to slip.  This is not a rule" in TUTORIAL


def _k(theta: float) -> list[float]:
    """k_1..k_4 of Fig. 6 (x = √3/2, y = 1/2, φ = π/3, ξ1 = π/4, ξ2 = π/3), eqs. (28)-(39)."""
    x1 = x2 = math.sqrt(3) / 2
    y, phi, xi = 0.5, math.pi / 3, (math.pi / 4, math.pi / 3)
    h = (x1 + x2) / 2
    t1p, t1m = math.tan(phi + xi[0]), math.tan(phi - xi[0])
    t2p, t2m = math.tan(phi + xi[1]), math.tan(phi - xi[1])
    V = [
        (-h + y * t1p, x2 * t1p),
        (h - y * t2p, x1 * t2p),
        (-h + y * t1m, x2 * t1m),
        (h - y * t2m, x1 * t2m),
    ]
    return [S * math.sin(theta) - C * math.cos(theta) for S, C in V]


@pytest.mark.parametrize("deg", [0, 10, 20, 22, 60, 119, 121, 171, 173, 200, 300])
def test_which_contact_slips_depends_on_theta(deg: int) -> None:
    ks = _k(math.radians(deg))
    n = max(range(4), key=lambda i: ks[i]) + 1  # the largest limit k_n, eq. (25)
    contact = 1 if n in (1, 3) else 2  # k1, k3 belong to contact 1; k2, k4 to contact 2
    assert contact == (2 if 21 < deg < 172 else 1), (deg, ks)
    assert n == 2 if 21 < deg < 120 else n != 2
    m = re.search(r"between about (\d+)° and (\d+)°", TUTORIAL)
    assert m and (int(m.group(1)), int(m.group(2))) == (21, 172)
    assert "the largest up to about 120°, then $k_4$" in TUTORIAL
