"""The colours a reader tells apart: no colour carries two meanings in one picture (issue 23).

The explorers (the web page and the matplotlib one) draw the four circles and mark the
worst and the best orientation on the same diagram; red and green carried both circles
4 and 2 and worst and best.  Distances are CIE76 ΔE in CIELAB (D65), computed here from
the sRGB definition, not from any colour library of the package.
"""

from __future__ import annotations

import itertools
import math

import pytest

from graspcompass.scene.palette import PALETTE

#: A ΔE the eye tells apart at a glance on a drawing (a just noticeable difference is ~2.3;
#: matplotlib's red and its orange, told apart in every plot, are ~40 apart).
APART = 25.0


def _lab(hex_colour: str) -> tuple[float, float, float]:
    """CIELAB (D65) of an sRGB colour ``#rrggbb``."""
    rgb = [int(hex_colour[i : i + 2], 16) / 255 for i in (1, 3, 5)]
    lin = [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in rgb]
    x = 0.4124 * lin[0] + 0.3576 * lin[1] + 0.1805 * lin[2]
    y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]
    z = 0.0193 * lin[0] + 0.1192 * lin[1] + 0.9505 * lin[2]

    def f(t: float) -> float:
        return t ** (1 / 3) if t > (6 / 29) ** 3 else t / (3 * (6 / 29) ** 2) + 4 / 29

    fx, fy, fz = f(x / 0.95047), f(y / 1.0), f(z / 1.08883)
    return 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)


def test_lab_of_known_colours() -> None:
    assert _lab("#ffffff") == pytest.approx((100.0, 0.0, 0.0), abs=0.05)
    assert _lab("#ff0000") == pytest.approx((53.24, 80.09, 67.20), abs=0.05)


ONE_PICTURE = ("circle1", "circle2", "circle3", "circle4", "envelope", "side", "worst", "best")


@pytest.mark.parametrize(("a", "b"), list(itertools.combinations(ONE_PICTURE, 2)))
def test_roles_of_one_picture_have_distinct_colours(a: str, b: str) -> None:
    assert math.dist(_lab(PALETTE[a]), _lab(PALETTE[b])) >= APART, (a, b, PALETTE[a], PALETTE[b])
