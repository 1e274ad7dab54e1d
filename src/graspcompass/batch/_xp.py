"""The Array API side of :mod:`graspcompass.batch`: namespaces, dtypes, sines and cosines.

Private (issue 21: the batch module under 600 lines).  numpy arrays, lists and numbers
use numpy; CuPy, torch, JAX and Dask arrays their own namespace through
``array_api_compat``.  :func:`_sincos` of many angles reads the table of
:mod:`graspcompass.grasp._envelope` on numpy (sin and cos of the grid points, then a
short Taylor step) and calls the namespace's own sin and cos elsewhere.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..boundary.errors import ComplexValueError, WrongTypeError
from ..grasp import _envelope

__all__: list[str] = []


# -- namespaces ------------------------------------------------------------------------------
def _namespace(*values: Any) -> Any:
    """The Array API namespace of the arrays among ``values`` (numbers and lists are numpy)."""
    arrays = [v for v in values if not isinstance(v, (int, float, list, tuple, np.generic))]
    try:
        from array_api_compat import array_namespace
    except ImportError:  # numpy alone works without array-api-compat
        if all(isinstance(v, np.ndarray) for v in arrays):
            return np
        raise ImportError(
            "arrays other than numpy need array-api-compat: pip install 'graspcompass[batch]'"
        ) from None
    if not arrays:
        arrays = [np.empty(0)]
    return array_namespace(*arrays)


def _is(xp: Any, name: str) -> bool:
    try:
        import array_api_compat as aac
    except ImportError:
        return name == "numpy" and xp is np
    return bool(getattr(aac, f"is_{name}_namespace")(xp))


def _astype(xp: Any, a: Any, dtype: Any) -> Any:
    f = getattr(xp, "astype", None)
    return f(a, dtype) if f is not None else a.astype(dtype)


def _isdtype(xp: Any, dtype: Any, kind: str) -> bool:
    f = getattr(xp, "isdtype", None)
    if f is not None:
        return bool(f(dtype, kind))
    np_kind = {"bool": "b", "complex floating": "c", "real floating": "f", "integral": "iu"}
    return np.dtype(dtype).kind in np_kind[kind]


def _floats(xp: Any, values: tuple, names: tuple) -> list:
    """The values as real floating arrays of ``xp`` (integers become float64)."""
    out = []
    for v, name in zip(values, names):
        if isinstance(v, (list, tuple)):
            v = np.asarray(v)
        if isinstance(v, (bool, np.bool_)):
            raise WrongTypeError(f"{name}: expected numbers, got a bool")
        if isinstance(v, complex):
            raise ComplexValueError(f"{name}: expected real numbers, got {v!r}")
        a = xp.asarray(v)
        if _isdtype(xp, a.dtype, "bool"):
            raise WrongTypeError(f"{name}: expected numbers, got an array of bools")
        if _isdtype(xp, a.dtype, "complex floating"):
            raise ComplexValueError(f"{name}: expected real numbers, got a complex array")
        if not _isdtype(xp, a.dtype, "real floating"):
            if not _isdtype(xp, a.dtype, "integral"):
                raise WrongTypeError(f"{name}: expected numbers, got dtype {a.dtype}")
            a = _astype(xp, a, xp.float64)
        out.append(a)
    return out


# -- the closed form -------------------------------------------------------------------------
def _sincos(xp: Any, x: Any) -> tuple[Any, Any]:
    """sin x, cos x; for float64 numpy / array_api_strict arrays from a table (|error| < 2u).

    ``x = j h + d`` with ``h = 2π/2^15`` (two-part h: the reduction is exact to
    ~1e-20 for |x| <= 2π), ``sin(jh + d) = s_j cos d + c_j sin d`` with the
    table's s_j, c_j (one ulp) and ``cos d = 1 − d²/2``, ``sin d = d(1 − d²/6)``
    (|d| <= 9.6e-5: below 4e-18).  Meant for angles of a few turns at most (the
    contact angles φ ∈ (0, π]); a non-finite x gives nan.
    """
    numpy = _is(xp, "numpy")
    if x.dtype != xp.float64 or not (numpy or _is(xp, "array_api_strict")):
        return xp.sin(x), xp.cos(x)
    s_tab, c_tab = _envelope.grid_table()
    if numpy:  # the same operations in place, and a faster table read
        return _sincos_numpy(np.asarray(x), s_tab, c_tab)
    shape = x.shape
    flat = xp.reshape(x, (-1,))
    with np.errstate(all="ignore"):  # nan -> an arbitrary index; d stays nan
        j = xp.round(flat * _envelope._INV_H)
        i = _astype(xp, j, xp.int64) & (_envelope.M - 1)
    d = (flat - j * _envelope._H_HI) - j * _envelope._H_LO
    s0, c0 = xp.take(xp.asarray(s_tab), i), xp.take(xp.asarray(c_tab), i)
    z = d * d
    sd = d * (1.0 - z * (1.0 / 6.0))
    w = 0.5 * z
    s = s0 + (c0 * sd - s0 * w)
    c = c0 - (s0 * sd + c0 * w)
    return xp.reshape(s, shape), xp.reshape(c, shape)


def _sincos_numpy(
    x: np.ndarray, s_tab: np.ndarray, c_tab: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_sincos` for numpy, operation for operation (bit-identical), in place."""
    shape, x = x.shape, x.reshape(-1)
    j = np.multiply(x, _envelope._INV_H)
    np.rint(j, out=j)  # = round half to even, as xp.round
    with np.errstate(all="ignore"):
        i = j.astype(np.int64)
    np.bitwise_and(i, _envelope.M - 1, out=i)
    d = np.multiply(j, _envelope._H_HI)
    np.subtract(x, d, out=d)
    np.multiply(j, _envelope._H_LO, out=j)
    np.subtract(d, j, out=d)
    s0 = np.take(s_tab, i, mode="clip")  # 0 <= i < M
    c0 = np.take(c_tab, i, mode="clip")
    z = np.multiply(d, d)
    sd = np.multiply(z, 1.0 / 6.0)
    np.subtract(1.0, sd, out=sd)
    np.multiply(d, sd, out=sd)  # d (1 − z/6)
    np.multiply(z, 0.5, out=z)  # w
    s = np.multiply(c0, sd)
    t = np.multiply(s0, z)
    np.subtract(s, t, out=s)
    np.add(s0, s, out=s)  # s0 + (c0 sd − s0 w)
    np.multiply(s0, sd, out=t)
    np.multiply(c0, z, out=z)
    np.add(t, z, out=t)
    np.subtract(c0, t, out=c0)  # c0 − (s0 sd + c0 w)
    return s.reshape(shape), c0.reshape(shape)


def _sides(xp: Any, phi: Any, mu: Any) -> tuple[Any, Any, Any, Any]:
    """Numerators and denominators of tan(φ + ξ) and tan(φ − ξ) in the μ form (23)."""
    s, c = _sincos(xp, phi)
    ms, mc = mu * s, mu * c
    return s + mc, c - ms, s - mc, c + ms
