"""Interval arithmetic rounded outward (numpy.nextafter), vectorised over boxes.

An interval is a pair ``(lo, hi)`` of float64 arrays; every operation widens its
float result by one ulp each way, so the exact result of the operation on any
reals in the operands lies inside (IEEE 754 round-to-nearest is within half an ulp).
"""

from __future__ import annotations

from typing import Any

import numpy as np


def _dn(x: Any) -> Any:
    return np.nextafter(x, -np.inf)


def _up(x: Any) -> Any:
    return np.nextafter(x, np.inf)


def _pt(x: float) -> tuple[np.ndarray, np.ndarray]:
    return np.float64(x), np.float64(x)


def _add(a: tuple, b: tuple) -> tuple:
    return _dn(a[0] + b[0]), _up(a[1] + b[1])


def _sub(a: tuple, b: tuple) -> tuple:
    return _dn(a[0] - b[1]), _up(a[1] - b[0])


def _neg(a: tuple) -> tuple:
    return -a[1], -a[0]


def _mul(a: tuple, b: tuple) -> tuple:
    # fmin/fmax skip the nan of 0 · inf: the endpoint 0 bounds the product by the others
    with np.errstate(invalid="ignore"):
        p0, p1, p2, p3 = a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1]
    lo = np.fmin(np.fmin(p0, p1), np.fmin(p2, p3))
    hi = np.fmax(np.fmax(p0, p1), np.fmax(p2, p3))
    return _dn(np.where(lo != lo, 0.0, lo)), _up(np.where(hi != hi, 0.0, hi))


def _half(a: tuple, sign: Any) -> tuple:
    """``sign · a / 2`` for signs ±1 (exact: a power of two)."""
    lo, hi = a[0] * (0.5 * sign), a[1] * (0.5 * sign)
    return np.minimum(lo, hi), np.maximum(lo, hi)


def _sq_lo(a: tuple) -> np.ndarray:
    m = np.where(a[0] > 0, a[0], np.where(a[1] < 0, -a[1], 0.0))
    return _dn(m * m)


def _sq_hi(a: tuple) -> np.ndarray:
    m = np.maximum(np.abs(a[0]), np.abs(a[1]))
    return _up(m * m)


def _dot(u: tuple, v: tuple) -> tuple:
    return _add(_mul(u[0], v[0]), _mul(u[1], v[1]))


def _cross(u: tuple, v: tuple) -> tuple:
    return _sub(_mul(u[0], v[1]), _mul(u[1], v[0]))


class _Affine:
    """Interval coefficients of ``f0 + s fs + t ft``: exact (outward rounded) over a box."""

    def __init__(self, f0: tuple, fs: tuple, ft: tuple) -> None:
        self.f0, self.fs, self.ft = f0, fs, ft

    def over(self, s: tuple, t: tuple) -> tuple:
        return _add(_add(self.f0, _mul(s, self.fs)), _mul(t, self.ft))

    def neg(self) -> _Affine:
        return _Affine(_neg(self.f0), _neg(self.fs), _neg(self.ft))


def _vec(f0: tuple, fs: tuple, ft: tuple) -> tuple[_Affine, _Affine]:
    """An affine vector field from coefficient vectors (each a pair of intervals)."""
    return _Affine(f0[0], fs[0], ft[0]), _Affine(f0[1], fs[1], ft[1])


def _lin(v: tuple[_Affine, _Affine], c: tuple, kind: str) -> _Affine:
    """The affine scalar ``v·c`` or ``v × c`` for a constant interval vector c."""
    op = _dot if kind == "dot" else _cross
    return _Affine(*(op((getattr(v[0], k), getattr(v[1], k)), c) for k in ("f0", "fs", "ft")))


def _vadd(u: tuple, v: tuple) -> tuple:
    return _add(u[0], v[0]), _add(u[1], v[1])


def _vscale(k: tuple, v: tuple) -> tuple:
    return _mul(k, v[0]), _mul(k, v[1])


def _J(v: tuple) -> tuple:
    return _neg(v[1]), v[0]


def _norm(v: tuple) -> tuple:
    lo = _dn(np.sqrt(np.maximum(_dn(_sq_lo(v[0]) + _sq_lo(v[1])), 0.0)))
    return lo, _up(np.sqrt(_up(_sq_hi(v[0]) + _sq_hi(v[1]))))


def _stack(forms: list) -> _Affine:
    return _Affine(
        *(
            (
                np.array([[f_.__dict__[k][0]] for f_ in forms]).reshape(4, 1),
                np.array([[f_.__dict__[k][1]] for f_ in forms]).reshape(4, 1),
            )
            for k in ("f0", "fs", "ft")
        )
    )


def _div_pos(n: tuple, d: tuple) -> tuple:
    """``n / d`` over the part of d that is > 0 (d's upper end > 0; else anything)."""
    dl, dh = np.maximum(d[0], 0.0), np.where(d[1] > 0, d[1], 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = [n[0] / dl, n[0] / dh, n[1] / dl, n[1] / dh]
        lo = _dn(np.minimum(np.minimum(q[0], q[1]), np.minimum(q[2], q[3])))
        hi = _up(np.maximum(np.maximum(q[0], q[1]), np.maximum(q[2], q[3])))
    open_ = dl <= 0  # d reaches 0: κ unbounded on the side of n's sign
    lo = np.where(open_, np.where(n[0] >= 0, _dn(n[0] / dh), -np.inf), lo)
    hi = np.where(open_, np.where(n[1] <= 0, _up(n[1] / dh), np.inf), hi)
    return np.where(np.isnan(lo), -np.inf, lo), np.where(np.isnan(hi), np.inf, hi)
