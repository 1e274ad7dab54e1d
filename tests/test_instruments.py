"""The instruments of the scene (issue 23): compass arcs, right-angle marks, V_n's guides.

Expected values from the paper's conventions (docs: conventions.md), computed here with
numpy independently of the construction: the sides at P_i, X_n on the x-axis, Y_n on the
y-axis, V_n = (−O_M X_n, −O Y_n)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from graspcompass import Grasp, internal_force_diagram
from graspcompass.scene.picture import scene_of

S3 = math.sqrt(3)


def _expected_v(x1, x2, y, phi1, phi2, xi1, xi2):
    """V_1..V_4 of the conventions: side n at its contact, X_n, the perpendicular from the
    other foot, Y_n; V_n = (−(X_n.x − O_M.x), −Y_n.y)."""
    p = {1: np.array([x1, y]), 2: np.array([-x2, y])}
    foot = {1: np.array([x1, 0.0]), 2: np.array([-x2, 0.0])}
    om = (x1 - x2) / 2
    out = {}
    for n, (i, ang) in {
        1: (1, phi1 + xi1),
        2: (2, phi2 + xi2),
        3: (1, phi1 - xi1),
        4: (2, phi2 - xi2),
    }.items():
        d = (
            np.array([-math.sin(ang), -math.cos(ang)])
            if i == 1
            else np.array([math.sin(ang), -math.cos(ang)])
        )
        xn = p[i][0] - p[i][1] * d[0] / d[1]
        f = foot[3 - i]
        normal = np.array([-d[1], d[0]])  # the perpendicular through f has direction ⊥ d
        yn = f[1] - f[0] * normal[1] / normal[0]
        out[n] = (-(xn - om), -yn)
    return out


@pytest.fixture(scope="module")
def fig6():
    return internal_force_diagram(Grasp.preset("fig6"))


def test_bisection_arcs_cross_above_and_below_the_midpoint(fig6):
    sc = scene_of(fig6)
    arcs = [i for i in sc.instruments if i.role == "bisection_arc"]
    assert len(arcs) == 4 and {i.step for i in arcs} == {"O_M"}
    # P1x = (√3/2, 0), P2x = (−√3/2, 0): circles of radius √3 about each cross at (0, ±3/2)
    for a in arcs:
        pts = np.asarray(a.points)
        r = [np.hypot(*(pts - c).T) for c in ((S3 / 2, 0), (-S3 / 2, 0))]
        assert any(np.allclose(x, S3) for x in r)
        mid = pts[len(pts) // 2]
        assert np.allclose(np.abs(mid), (0, 1.5), atol=1e-9)
    (b,) = [i for i in sc.instruments if i.role == "bisector"]
    assert np.allclose(sorted(b.points), [(0, -1.5), (0, 1.5)])


@pytest.mark.parametrize(
    "preset, args",
    [
        ("fig6", (S3 / 2, S3 / 2, 0.5, math.pi / 3, math.pi / 3, math.pi / 4, math.pi / 3)),
        ("table1a", (2, 2, 1, math.pi / 2, math.pi / 2, math.atan(1.0), math.atan(1.2))),
    ],
)
def test_transfers_end_at_the_coordinates_of_v(preset, args):
    c = internal_force_diagram(Grasp.preset(preset))
    sc = scene_of(c)
    expected = _expected_v(*args)
    for n, (vx, vy) in expected.items():
        coords = [i for i in sc.instruments if i.role == "coordinate" and i.n == n]
        ends = {tuple(np.round(i.points[1], 9)) for i in coords}
        starts = sorted(tuple(np.round(i.points[0], 9)) for i in coords)
        assert all(np.allclose(e, (vx, vy)) for e in ends), (n, ends)
        feet = [q for q in ((vx, 0.0), (0.0, vy)) if math.dist(q, (vx, vy)) > 1e-9]
        assert np.allclose(sorted(tuple(np.round(q, 9)) for q in feet), starts), (n, starts)
        # each length laid off from O: an arc about O through the foot
        for a in (i for i in sc.instruments if i.role == "transfer_arc" and i.n == n):
            r = np.hypot(*np.asarray(a.points).T)
            assert np.allclose(r, r[0])
            assert min(abs(r[0] - abs(vx)), abs(r[0] - abs(vy))) < 1e-9


def test_right_angle_marks_sit_on_perpendicular_lines(fig6):
    sc = scene_of(fig6)
    marks = [i for i in sc.instruments if i.role == "right_angle"]
    steps = {i.step for i in marks}
    assert {"P1x", "P2x", "perp1", "perp2", "perp3", "perp4"} <= steps
    for m in marks:
        a, b, c = (np.asarray(p) for p in m.points)
        corner = a + c - b
        assert abs(np.dot(a - corner, c - corner)) < 1e-9
        assert np.isclose(np.linalg.norm(a - corner), np.linalg.norm(c - corner))
    # the mark at P1x = (√3/2, 0): one leg up along P1 P1x, one along the x-axis
    (p1x,) = [m for m in marks if m.step == "P1x"]
    a, b, c = (np.asarray(p) for p in p1x.points)
    assert np.allclose(a + c - b, (S3 / 2, 0))


def test_instruments_come_with_their_step(fig6):
    sc = scene_of(fig6)
    index = {s.name: s.index for s in fig6.steps}
    for n in range(len(fig6.steps)):
        cut = sc.upto(n)
        assert {i.step for i in cut.instruments} <= set(fig6.upto(n).names)
        assert len(cut.instruments) == sum(index[i.step] <= n for i in sc.instruments)
