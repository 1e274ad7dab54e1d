"""The paper's formulas typed in as printed, for the catalogue to check.

Nothing here is computed by the rest of graspcompass: these are transcriptions
of eqs. (4), (5), (13), (15), (18)-(21), (26), (28)-(39), (A1)-(A8) and Table I, in the
general symbols of :mod:`graspcompass.symbols`.
"""

from __future__ import annotations

import sympy as sp

from ..symbols import F_e, mu1, mu2, phi1, phi2, theta, x1, x2, xi1, xi2, y

__all__ = [
    "TABLE_I",
    "C_printed",
    "D",
    "F_N_printed",
    "F_T_printed",
    "L3_printed",
    "L_printed",
    "M_printed",
    "S_printed",
    "c",
    "c1",
    "c2",
    "e_printed",
    "f_N_printed",
    "k_mu_printed",
    "k_symbol",
    "k_tan_printed",
    "s",
    "s1",
    "s2",
]

s, c = sp.sin(theta), sp.cos(theta)
s1, c1, s2, c2 = sp.sin(phi1), sp.cos(phi1), sp.sin(phi2), sp.cos(phi2)
D = x1 + x2
k_symbol = sp.Symbol("k", real=True)

#: eq. (5): L31, L32, L33, L34 as printed below the matrix
L3_printed = (-c1 * x1 + s1 * y, +s1 * x1 + c1 * y, +c2 * x2 - s2 * y, -s2 * x2 - c2 * y)
#: eq. (5)
L_printed = sp.Matrix(
    [
        [-s1, -c1, s2, c2],
        [-c1, s1, -c2, s2],
        list(L3_printed),
    ]
)
#: eq. (26)
e_printed = sp.Matrix([s, -c])
#: eq. (4)
M_printed = sp.Matrix([-F_e * s, F_e * c, 0])
#: eq. (13)
F_T_printed = (
    F_e
    / (2 * D)
    * sp.Matrix(
        [
            D * s1 * s + 2 * (y * s - x2 * c) * c1,
            D * c1 * s - 2 * (y * s - x2 * c) * s1,
            -D * s2 * s - 2 * (y * s + x1 * c) * c2,
            -D * c2 * s + 2 * (y * s + x1 * c) * s2,
        ]
    )
)
#: eq. (15)
F_N_printed = F_e / (2 * D) * sp.Matrix([2 * s1, 2 * c1, 2 * s2, 2 * c2])

#: f_N1 ... f_N4 of (A1)-(A3): the entries of (15) as printed, one by one
f_N_printed = (
    F_e / (2 * D) * 2 * s1,
    F_e / (2 * D) * 2 * c1,
    F_e / (2 * D) * 2 * s2,
    F_e / (2 * D) * 2 * c2,
)

#: Table I (§4.2): P1, φ1, μ1, P2, φ2, μ2 for cases (a), (b), (c), as printed
TABLE_I = {
    "a": ((2, 1), sp.pi / 2, sp.Rational(10, 10), (-2, 1), sp.pi / 2, sp.Rational(12, 10)),
    "b": ((2, 3), sp.pi / 2, sp.Rational(10, 10), (-2, 3), sp.pi / 2, sp.Rational(12, 10)),
    "c": ((2, 2), sp.pi / 2, sp.Rational(5, 10), (-2, 2), sp.pi / 2, sp.Rational(14, 10)),
}

#: eqs. (18)-(21), first lines (the μ form)
k_mu_printed = (
    -D / 2 * s + (x2 * c - y * s) * (c1 * mu1 + s1) / (s1 * mu1 - c1),
    +D / 2 * s + (x1 * c + y * s) * (c2 * mu2 + s2) / (s2 * mu2 - c2),
    -D / 2 * s + (x2 * c - y * s) * (c1 * mu1 - s1) / (s1 * mu1 + c1),
    +D / 2 * s + (x1 * c + y * s) * (c2 * mu2 - s2) / (s2 * mu2 + c2),
)
#: eqs. (18)-(21), second lines (the tan form), with ξ
k_tan_printed = (
    -D / 2 * s - (x2 * c - y * s) * sp.tan(phi1 + xi1),
    +D / 2 * s - (x1 * c + y * s) * sp.tan(phi2 + xi2),
    -D / 2 * s - (x2 * c - y * s) * sp.tan(phi1 - xi1),
    +D / 2 * s - (x1 * c + y * s) * sp.tan(phi2 - xi2),
)
#: eqs. (28), (34), (36), (38)
S_printed = (
    -D / 2 + y * sp.tan(phi1 + xi1),
    +D / 2 - y * sp.tan(phi2 + xi2),
    -D / 2 + y * sp.tan(phi1 - xi1),
    +D / 2 - y * sp.tan(phi2 - xi2),
)
#: eqs. (29), (35), (37), (39)
C_printed = (
    x2 * sp.tan(phi1 + xi1),
    x1 * sp.tan(phi2 + xi2),
    x2 * sp.tan(phi1 - xi1),
    x1 * sp.tan(phi2 - xi2),
)
