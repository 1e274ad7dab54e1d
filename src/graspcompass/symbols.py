"""Public sympy symbols of the model, with their domains (§2.2).

``x1, x2`` are positive, ``y`` non-negative; ``phi1, phi2`` lie in (0, π];
``xi1, xi2`` in (0, π/2) and ``mu1, mu2 = tan(xi)`` are positive; ``theta``
is real; ``F_e`` (the magnitude of the external force) is positive.  Sympy
only knows the signs; the full domains are in :data:`DOMAINS`.
"""

from __future__ import annotations

import sympy as sp

__all__ = ["DOMAINS", "F_e", "mu1", "mu2", "phi1", "phi2", "theta", "x1", "x2", "xi1", "xi2", "y"]

x1, x2 = sp.symbols("x1 x2", positive=True)
y = sp.Symbol("y", nonnegative=True)
phi1, phi2 = sp.symbols("phi1 phi2", positive=True)
xi1, xi2 = sp.symbols("xi1 xi2", positive=True)
mu1, mu2 = sp.symbols("mu1 mu2", positive=True)
theta = sp.Symbol("theta", real=True)
F_e = sp.Symbol("F_e", positive=True)

#: The domain of each symbol as sympy relations (§2.2.1, §2.2.2).
DOMAINS: dict[sp.Symbol, tuple] = {
    x1: (x1 > 0,),
    x2: (x2 > 0,),
    y: (y >= 0,),
    phi1: (phi1 > 0, phi1 <= sp.pi),
    phi2: (phi2 > 0, phi2 <= sp.pi),
    xi1: (xi1 > 0, xi1 < sp.pi / 2),
    xi2: (xi2 > 0, xi2 < sp.pi / 2),
    mu1: (mu1 > 0,),
    mu2: (mu2 > 0,),
    theta: (),
    F_e: (F_e > 0,),
}
