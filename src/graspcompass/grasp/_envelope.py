"""k_grasp(θ) of one grasp on many angles from a table of its envelope (issue 13 §5).

The outer envelope ``k_grasp(θ) = max(k1, k2, k3, k4, 0)`` (eq. (25)) is made of
arcs of sinusoids ``k_n(θ) = S_n sin θ − C_n cos θ`` (eq. (27); the circles on the
diameters O V_n, eqs. (28)-(39)) and of zero.  A sinusoid f satisfies
``f(θ0 + d) = f(θ0) cos d + f'(θ0) sin d`` exactly, so on the grid ``θ0 = j h``
the table of ``A_j = k_grasp(θ0)`` and of the derivative ``B_j`` of the arc
active at θ0 gives

    k_grasp(θ0 + d) = A_j + d (B_j + d (−A_j/2 + d (−B_j/6))),   |d| <= h/2,

for every θ whose bin contains no break point of the envelope (the next term,
``A d⁴/24``, is below 1e-17 |V|: the step is ``h = 2^-12``).  The zero arc has
``A = B = 0``, so the zero region of the envelope stays exactly 0.

The grid is made of doubles (h is a power of two) and covers [−π − 2h, 2π + 2h]:
adding ``1.5·2^40`` to θ rounds it to the nearest grid point ``j h``, whose
index j is in the low bits of the sum, and ``d = θ − j h`` is exact.  Per angle
this is 14 passes over a block that stays in the cache (one read of ``A_j, B_j``
included), where the direct formula costs a sine, a cosine (about 15 ns each in
glibc's libm) and sixteen passes.

Everything else gives nan in that loop and is done afterwards, all at once: the
first and last bins are sentinels (nan) that an index beyond the table is
clipped onto; angles beyond the table with ``|θ| <= THETA_MAX`` are reduced to
``θ − 2πk = hi + lo`` (|hi| <= π, exact to ~1e-30: 2π in three parts, TwoSum)
and read from the table with ``d = (hi − j h) + lo``; the bins holding a break
point (nan in the table: two sinusoids of period 2π, or one and zero, cross at
points π apart, so within a bin of width h < π the active arc changes at most
once, and only if the arcs at the bin's two edges differ), ``|θ| > THETA_MAX``,
nan and ±inf take the direct formula ``max_n(S_n sin θ − C_n cos θ, 0)`` (nan
for nan and ±inf).

Accuracy: the table values come from sin and cos of the exact grid points
(glibc: below one ulp), so the result is within about 3 ε max_n |V_n| of the
exact k_grasp (``tests/test_batch.py``: against mpmath at 40 digits, and
against the max of the four dot products on random grasps, break points ± 1 ulp,
negative and huge angles), as accurate as the direct formula.
"""

from __future__ import annotations

import math
import struct
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
else:
    from ..boundary._numpy import np

__all__ = ["TABLE_MIN_SIZE", "THETA_MAX", "EnvelopeTable", "direct_k_grasp", "grid_table"]

#: Size of the table of sin, cos on one turn (:func:`grid_table`, read by the batch
#: module's sines of φ); a power of two, so that ``j mod M`` is ``j & (M - 1)``.
M = 1 << 15
#: Angles beyond this (rad) take the direct formula (the reductions hold below).
THETA_MAX = float(1 << 22)
#: Arrays below this size take the direct formula (the table costs ~2 ms to build once).
TABLE_MIN_SIZE = 1 << 15
#: Block length of the evaluation (fewer Python calls against the cache's size).
CHUNK = 1 << 15

# 2π as a double-double, and h = 2π/M split so that j·_H_HI is exact for |j| < 2^29
_TWO_PI_HI = 6.283185307179586
_TWO_PI_LO = 2.4492935982947064e-16
_H = _TWO_PI_HI / M  # exact: M is a power of two
_H_HI = struct.unpack("<f", struct.pack("<f", _H))[0]  # 24 significant bits
_H_LO = (_H - _H_HI) + _TWO_PI_LO / M
_INV_H = M / _TWO_PI_HI


def direct_k_grasp(
    S: np.ndarray,
    C: np.ndarray,
    t: np.ndarray,
    out: np.ndarray | None = None,
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


#: The step of the envelope's table, ``h = 2^-P`` rad: a power of two, so that the grid
#: points ``j h`` are doubles and ``θ − j h`` is exact.
P = 12
_STEP = 2.0**-P
#: Adding ``1.5·2^(52−P)`` rounds θ to the nearest multiple of h (half to even); the
#: bits of the sum are those of the constant plus j.
_ROUND_P = 1.5 * 2.0 ** (52 - P)
_ROUND_P_BITS = struct.unpack("<q", struct.pack("<d", _ROUND_P))[0]
#: The table's bins ``j = J_LO .. J_HI`` (centres ``j h``) cover [−π − 2h, 2π + 2h]; the
#: first and the last are sentinels (nan): an angle beyond them is clipped onto one.
J_LO = -math.floor(math.pi / _STEP) - 3
J_HI = math.ceil(2 * math.pi / _STEP) + 3
#: 2π = _P1 + _P2 + _P3 (+ 4e-37): _P1, _P2 of 32 bits, so ``k _P1``, ``k _P2`` are exact
#: for ``|k| < 2^21``, i.e. for ``|θ| <= THETA_MAX``.
_P1 = 6.2831853069365025
_P2 = 2.4308402025215864e-10
_P3 = 8.089064995183803e-21
_INV_2PI = 1.0 / _TWO_PI_HI

_HALF_GRID: tuple[np.ndarray, np.ndarray] | None = None


def _half_grid() -> tuple[np.ndarray, np.ndarray]:
    """sin, cos at the half steps ``i h/2``, i = 2 J_LO − 1 .. 2 J_HI + 1 (exact points)."""
    global _HALF_GRID
    if _HALF_GRID is None:
        x = np.arange(2 * J_LO - 1, 2 * J_HI + 2) * (0.5 * _STEP)
        _HALF_GRID = (np.sin(x), np.cos(x))
    return _HALF_GRID


def _reduce(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``θ − 2πk = hi + lo`` (k = round(θ/2π), |hi| <= π + 1e-6), for |θ| <= THETA_MAX.

    ``θ − k _P1`` is exact (Sterbenz) and so is ``k _P2``; their difference is split
    exactly (TwoSum) and ``k _P3`` goes to the low part, so ``hi + lo`` is within
    about 1e-30 of the true remainder.
    """
    k = np.rint(t * _INV_2PI)
    t1 = t - k * _P1
    q = k * _P2
    hi = t1 - q
    bb = hi - t1
    lo = ((t1 - (hi - bb)) - (q + bb)) - k * _P3
    return hi, lo


class EnvelopeTable:
    """The table ``A_j, B_j`` of one grasp's envelope (see the module docstring).

    Built in about a millisecond (the sines and cosines of the grid are shared by
    every grasp); 620 KB.  Evaluates k_grasp (eq. (25)) at any float64 angles.

    Parameters
    ----------
    S, C : numpy.ndarray
        ``S_1..S_4`` and ``C_1..C_4`` of eqs. (28)-(39), float64.
    """

    def __init__(self, S: np.ndarray, C: np.ndarray) -> None:
        self.S, self.C = np.asarray(S, float), np.asarray(C, float)
        s, c = _half_grid()  # bin j: edges at half steps 2i and 2i + 2, centre 2i + 1
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
        B = Sx * c[1::2] + Cx * s[1::2]  # k_n'(θ) = S_n cos θ + C_n sin θ; 0 on the zero arc
        broken = (arc[0:-1:2] != centre) | (arc[2::2] != centre)
        broken[[0, -1]] = True  # the sentinels
        A[broken] = np.nan  # a break point inside the bin: the direct formula
        B[broken] = np.nan
        self.AB = np.stack([A, B], axis=1)  # one read per angle
        self.A, self.B = self.AB[:, 0], self.AB[:, 1]
        self.broken_bins = int(broken.sum()) - 2

    @staticmethod
    def _index(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The bin (clipped to a sentinel when out of the table) and ``θ − j h`` (exact)."""
        r = t + _ROUND_P
        i = r.view(np.int64) - (_ROUND_P_BITS + J_LO)
        return i, t - (r - _ROUND_P)

    def _small(self, t: np.ndarray) -> np.ndarray:
        """k_grasp at a few angles (those the fast loop left as nan), with temporaries."""
        out = np.full(t.shape, np.nan)
        with np.errstate(all="ignore"):
            ok = np.abs(t) <= THETA_MAX  # nan: False
        hi, lo = _reduce(t[ok])
        i, d = self._index(hi)
        d += lo
        a = np.take(self.A, i, mode="clip")
        b = np.take(self.B, i, mode="clip")
        out[ok] = a + d * (b + d * (a * -0.5 + d * (b * (-1.0 / 6.0))))
        bad = np.flatnonzero(np.isnan(out))  # break points, |θ| > THETA_MAX, nan, inf
        if bad.size:
            with np.errstate(all="ignore"):
                out[bad] = direct_k_grasp(self.S, self.C, t[bad])
        return out

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """k_grasp (eq. (25)) at the angles ``t``, a float64 array; nan and ±inf give nan."""
        flat = np.ascontiguousarray(t, dtype=float).reshape(-1)
        out = np.empty(flat.shape)
        with np.errstate(all="ignore"):  # inf − inf for θ = ±inf (then the direct path)
            self._loop(flat, out, max(1, min(CHUNK, flat.size)))
        return out.reshape(np.shape(t))

    def _loop(self, flat: np.ndarray, out: np.ndarray, size: int) -> None:
        """The blocks of :meth:`__call__`: 14 passes each, in buffers that stay in the cache."""
        AB, minimum, add, sub, mul, take = (
            self.AB,
            np.minimum.reduce,
            np.add,
            np.subtract,
            np.multiply,
            np.take,
        )
        bias, c2, c3 = _ROUND_P_BITS + J_LO, -0.5, -1.0 / 6.0
        rbuf, wbuf, abbuf = np.empty(size), np.empty(size), np.empty((size, 2))
        views, bad = None, []
        for lo in range(0, flat.size, size):
            m = min(size, flat.size - lo)
            if views is None or m < size:
                r, w, ab = rbuf[:m], wbuf[:m], abbuf[:m]
                views = r, w, w.view(np.int64), ab, r.view(np.int64), ab[:, 0], ab[:, 1]
            r, w, i, ab, r_bits, a, b = views
            th, o = flat[lo : lo + m], out[lo : lo + m]
            add(th, _ROUND_P, out=r)  # j h + 1.5·2^(52−P): j in the low bits
            sub(r_bits, bias, out=i)  # the index (in w's memory: w is free until the take)
            take(AB, i, axis=0, out=ab, mode="clip")  # out of the table: a sentinel (nan)
            sub(r, _ROUND_P, out=r)  # j h
            sub(th, r, out=r)  # d = θ − j h, exact
            mul(b, c3, out=o)  # A + d (B + d (−A/2 + d (−B/6))), accumulated in the output
            mul(o, r, out=o)
            mul(a, c2, out=w)
            add(o, w, out=o)
            mul(o, r, out=o)
            add(o, b, out=o)
            mul(o, r, out=o)
            add(o, a, out=o)
            v = minimum(o)
            if v != v:  # nan: a break point, beyond the table, nan, inf
                bad.append(np.flatnonzero(np.isnan(o)) + lo)
        if bad:  # all at once: a few calls more on a few angles
            where = np.concatenate(bad)
            out[where] = self._small(flat[where])
