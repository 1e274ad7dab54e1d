"""k_grasp(θ) of one grasp on many angles from a table of its envelope (issue 13 §5).

The outer envelope ``k_grasp(θ) = max(k1, k2, k3, k4, 0)`` (eq. (25)) is made of
arcs of sinusoids ``k_n(θ) = S_n sin θ − C_n cos θ`` (eq. (27)) and of zero.  A
sinusoid f satisfies ``f(θ0 + d) = f(θ0) cos d + f'(θ0) sin d`` exactly, so on a
grid ``θ0 = j h`` (``h = 2π/M``) the table of ``A_j = k_grasp(θ0)`` and of the
derivative ``B_j`` of the arc active at θ0 gives

    k_grasp(θ0 + d) = A_j cos d + B_j sin d,   |d| <= h/2,

for every θ whose bin contains no break point of the envelope.  With
``M = 2^15`` (|d| <= 9.6e-5) ``cos d = 1 − d²/2`` and ``sin d = d(1 − d²/6)``
to below 4e-18 relative, and the evaluation is written as
``A + (B sin d − A d²/2)``, a correction of at most 1e-4 |V| to A.  Per angle it
costs a dozen multiplications and two table reads, where the direct formula
costs a sine, a cosine (about 15 ns each in glibc's double precision libm) and
sixteen passes over the arrays; it runs in blocks that stay in the cache.

Exactness of the arcs: two sinusoids of period 2π (or one and zero) cross at
points π apart, so within a bin (width h < π) the active arc changes at most
once, and only if the arcs active at the bin's two edges differ.  Those bins
(a few, one per break point of the envelope) hold ``nan`` in the table and their
angles are evaluated by the direct formula ``max_n(S_n sin θ − C_n cos θ, 0)``.

Accuracy: the reduction ``d = θ − j h`` uses a two-part h (``j h_hi`` exact for
``|j| < 2^29``) and is exact to ~1e-20 for |θ| <= 2π, ~1e-16 at |θ| = 2^16;
larger angles use the direct formula.  The table values are computed from
sin θ0, cos θ0 accurate to about one ulp, so the result is within about
3 ε max_n |V_n| of the exact k_grasp (measured in ``tests/test_batch.py``
against mpmath at 50 digits), as accurate as the direct formula.
"""

from __future__ import annotations

import numpy as np

__all__ = ["TABLE_MIN_SIZE", "THETA_MAX", "EnvelopeTable", "direct_k_grasp", "grid_table"]

#: Table size (bins on one turn); a power of two, so that ``j mod M`` is ``j & (M - 1)``.
M = 1 << 15
#: Angles beyond this (rad) take the direct formula (the two-part reduction holds below).
THETA_MAX = float(1 << 16)
#: Arrays below this size take the direct formula (the table costs ~3 ms to build once).
TABLE_MIN_SIZE = 1 << 15
#: Block length of the evaluation (fewer Python calls against the cache's size).
CHUNK = 1 << 15

# 2π as a double-double, and h = 2π/M split so that j·_H_HI is exact for |j| < 2^29
_TWO_PI_HI = 6.283185307179586
_TWO_PI_LO = 2.4492935982947064e-16
_H = _TWO_PI_HI / M  # exact: M is a power of two
_H_HI = float(np.float32(_H))  # 24 significant bits
_H_LO = (_H - _H_HI) + _TWO_PI_LO / M
_INV_H = M / _TWO_PI_HI
#: Adding 1.5·2^52 rounds |t| < 2^51 to an integer (half to even) held in the low mantissa bits.
_ROUND = 1.5 * 2.0**52


def direct_k_grasp(S: np.ndarray, C: np.ndarray, t: np.ndarray, out: np.ndarray | None = None,
                   ) -> np.ndarray:
    """``max(0, max_n(S_n sin θ − C_n cos θ))`` by the formula (eqs. (25), (27))."""
    s, c = np.sin(t), np.cos(t)
    if out is None:
        out = np.zeros(t.shape)
    else:
        out[...] = 0.0
    a, b = np.empty(t.shape), np.empty(t.shape)
    for Sn, Cn in zip(S, C):  # k_n = S_n sin θ - C_n cos θ, without temporaries
        np.multiply(s, Sn, out=a)
        np.multiply(c, Cn, out=b)
        np.subtract(a, b, out=a)
        np.maximum(out, a, out=out)
    return out


def _grid_sincos(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """sin and cos of the real numbers ``points · h`` (points: integers or half-integers).

    ``points · _H_HI`` is exact; the small rest ``b = points · _H_LO`` (< 3e-7) is
    added by ``sin(a + b) = sin a + b cos a − b²/2 sin a`` (the next term < 1e-20).
    """
    a = points * _H_HI
    b = points * _H_LO
    sa, ca = np.sin(a), np.cos(a)
    hb = 0.5 * b * b
    return sa + (b * ca - hb * sa), ca - (b * sa + hb * ca)


_GRID: tuple[np.ndarray, np.ndarray] | None = None


def _grid() -> tuple[np.ndarray, np.ndarray]:
    """sin, cos at the half steps ``(i − 1)/2 · h``, i = 0..2M (computed once, 1 MB)."""
    global _GRID
    if _GRID is None:
        _GRID = _grid_sincos(np.arange(-1, 2 * M) * 0.5)
    return _GRID


_TABLE: tuple[np.ndarray, np.ndarray] | None = None


def grid_table() -> tuple[np.ndarray, np.ndarray]:
    """sin and cos of ``j h``, j = 0..M−1, about one ulp (contiguous, computed once)."""
    global _TABLE
    if _TABLE is None:
        s, c = _grid()
        _TABLE = (np.ascontiguousarray(s[1::2]), np.ascontiguousarray(c[1::2]))
    return _TABLE


class EnvelopeTable:
    """The table ``A_j, B_j`` of one grasp's envelope (see the module docstring).

    Built in about a millisecond (the sines and cosines of the grid are shared
    by every grasp); 512 KB.

    Parameters
    ----------
    S, C : numpy.ndarray
        ``S_1..S_4`` and ``C_1..C_4`` of eqs. (28)-(39), float64.
    """

    def __init__(self, S: np.ndarray, C: np.ndarray) -> None:
        self.S, self.C = np.asarray(S, float), np.asarray(C, float)
        s, c = _grid()  # half steps: edges of bin j at 2j and 2j + 2, its centre at 2j + 1
        best = np.zeros(s.shape)  # the zero arc, index -1
        arc = np.full(s.shape, -1, dtype=np.int8)
        k, upd = np.empty(s.shape), np.empty(s.shape, dtype=bool)
        for n, (Sn, Cn) in enumerate(zip(self.S.tolist(), self.C.tolist())):
            np.subtract(Sn * s, Cn * c, out=k)
            np.greater(k, best, out=upd)  # the first of equal arcs keeps them
            np.copyto(best, k, where=upd)
            arc[upd] = n
        centre = arc[1::2]
        Sx, Cx = np.append(self.S, 0.0)[centre], np.append(self.C, 0.0)[centre]
        A = best[1::2].copy()
        B = Sx * c[1::2] + Cx * s[1::2]  # k_n'(θ) = S_n cos θ + C_n sin θ
        broken = (arc[0:-1:2] != centre) | (arc[2::2] != centre)
        A[broken] = np.nan  # a break point inside the bin: the direct formula
        B[broken] = np.nan
        self.A, self.B = A, B
        self.broken_bins = int(broken.sum())

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """k_grasp at the angles ``t`` (a float64 array, finite, |t| <= THETA_MAX)."""
        flat = np.ascontiguousarray(t).reshape(-1)
        out = np.empty(flat.shape)
        n = flat.size
        size = min(CHUNK, n)
        jj, d, z, s, a, b = (np.empty(size) for _ in range(6))
        A, B = self.A, self.B
        for lo in range(0, n, size):
            m = min(size, n - lo)
            th, o = flat[lo:lo + m], out[lo:lo + m]
            j_, d_, z_, s_, a_, b_ = jj[:m], d[:m], z[:m], s[:m], a[:m], b[:m]
            i_ = z_.view(np.int64)  # z_ holds the table index first
            np.multiply(th, _INV_H, out=j_)
            np.add(j_, _ROUND, out=j_)  # j + 1.5·2^52: j rounded to an integer, in the low bits
            np.bitwise_and(j_.view(np.int64), M - 1, out=i_)  # j mod M
            np.take(A, i_, out=a_, mode="clip")  # 0 <= i < M: no check needed
            np.take(B, i_, out=b_, mode="clip")
            np.subtract(j_, _ROUND, out=j_)  # the nearest grid point θ0 = j h
            np.multiply(j_, _H_HI, out=d_)
            np.subtract(th, d_, out=d_)  # exact (Sterbenz)
            np.multiply(j_, _H_LO, out=z_)
            np.subtract(d_, z_, out=d_)  # d = θ − j h
            np.multiply(d_, d_, out=z_)
            np.multiply(z_, -1.0 / 6.0, out=s_)
            np.add(s_, 1.0, out=s_)
            np.multiply(s_, d_, out=s_)  # sin d
            np.multiply(s_, b_, out=s_)
            np.multiply(z_, 0.5, out=z_)  # 1 − cos d
            np.multiply(z_, a_, out=z_)
            np.subtract(s_, z_, out=s_)
            np.add(s_, a_, out=o)  # A + (B sin d − A (1 − cos d))
        if self.broken_bins:
            bad = np.flatnonzero(np.isnan(out))
            if bad.size:
                out[bad] = direct_k_grasp(self.S, self.C, flat[bad])
        return out.reshape(np.shape(t))
