"""Many grasps at once: V_n, k_n(θ), k_grasp(θ), F_int and the worst squeeze (issue 13 §5).

Every function takes the seven paper-frame parameters ``x1, x2, y, phi1, phi2,
mu1, mu2`` as arrays (or numbers) that broadcast together, of any namespace of
the `Array API <https://data-apis.org/array-api/>`_ (numpy, CuPy, torch,
``array_api_strict``, dask.array; found with ``array_api_compat.array_namespace``),
and returns arrays of that namespace.  There are no loops over grasps.

The model (Ito, Tanaka, Sasaki 2012) in closed form, for ``P1 = (x1, y)``,
``P2 = (−x2, y)``, normals at φ1 (clockwise) and φ2 (counter-clockwise) from
the negative y-axis and friction μ_i = tan ξ_i (22):

* ``t_n = tan(φ ± ξ)`` in the μ form of eq. (23),
  ``(sin φ ± μ cos φ) / (cos φ ∓ μ sin φ)``: ``+`` for n = 1 (P1), 2 (P2), the
  upper cone sides; ``−`` for n = 3 (P1), 4 (P2), the lower ones;
* ``S_1 = −(x1 + x2)/2 + y t_1``, ``C_1 = x2 t_1`` (28), (29);
  ``S_2 = (x1 + x2)/2 − y t_2``, ``C_2 = x1 t_2`` (34), (35); n = 3, 4 alike
  (36)-(39); ``V_n = (S_n, C_n)`` (30), (33);
* ``k_n(θ) = S_n sin θ − C_n cos θ`` (27), (32); ``k_grasp = max(k_1..k_4, 0)``
  (25); ``F_int = k_grasp/(x1 + x2) · F_e`` (17);
* the squeeze that holds the part in every orientation,
  ``S_f m (g + A) max_n |V_n| / (x1 + x2)`` per jaw (§5; see
  :mod:`graspcompass.sizing.core`).

Arrays: :func:`closed_form` and :func:`k` put the four sides on a new **last**
axis (shape ``broadcast + (4,)``); θ broadcasts with the parameters.

**Validity.**  The domain is that of :class:`graspcompass.Grasp`: finite values,
``x1 + x2 > 0``, ``y >= 0``, ``0 < φ_i <= π``, ``μ_i > 0`` and condition (1),
``−π/2 < φ_i − ξ_i < π/2 < φ_i + ξ_i < 3π/2``.  Given the others, (1) holds
exactly when the denominators of the μ form have the signs
``cos φ_i − μ_i sin φ_i < 0 < cos φ_i + μ_i sin φ_i`` (the cone's upper side
rises, its lower side falls), which is how :func:`valid` checks it, on the same
computed values the closed form divides by.  ``on_invalid="raise"`` (the
default) raises :class:`InvalidGraspsError` naming the first invalid grasp (its
index in the broadcast shape, the failed inequality and the values) and how many
there are; ``on_invalid="nan"`` returns ``nan`` for invalid grasps instead (a
design sweep keeps its shape; the only choice that stays lazy for dask).
A ``nan`` parameter is invalid.  θ is not checked: a ``nan`` θ gives ``nan``, so
does an infinite one.

**Accuracy** (float64, u = 2^-53).  Near a bound of (1) a cone side is nearly
horizontal and the closed form is ill-conditioned in the parameters
themselves: the denominator ``cos φ ∓ μ sin φ`` cancels.  Computed from the
doubles φ, μ its absolute error is about ``u (|cos φ| + μ |sin φ|)``, so::

    |Δt_n| <= 4u |t_n| (1 + (|sin φ| + μ|cos φ|)/|num_n| + (|cos φ| + μ|sin φ|)/|den_n|)

and ``|ΔS_n| <= |y||Δt_n| + 2u(|S_n| + (|x1| + |x2|)/2)``,
``|ΔC_n| <= |x||Δt_n| + u|C_n|`` (num, den: the μ form's numerator and
denominator).  Away from the bounds this is a few ulp; at a relative margin
ρ of (1) it grows like u/ρ.  :class:`graspcompass.Grasp` evaluates the same
closed form at 40+ digits and rounds once (correct to one ulp); the tests check
this bound against it and against mpmath at 50 digits, with hypothesis, on
random grasps including ones within 1e-11 of a bound.  For numpy and
``array_api_strict`` float64 input the sines and cosines of φ come from a
2^15-entry table and a short series (absolute error below 2u, the size the
bound assumes; about 2× faster than the C library's), so the two namespaces give
bit-identical results.

Examples
--------
>>> import numpy as np
>>> from graspcompass import batch
>>> S, C = batch.closed_form(2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, 1.0, 1.2)
>>> np.round(S, 6).tolist(), np.round(C, 6).tolist()  # Table I (a): V_1 = (-3, -2), ...
([-3.0, 2.833333, -1.0, 1.166667], [-2.0, -1.666667, 2.0, 1.666667])
>>> batch.k_grasp(np.array([0.0, np.pi / 2]), 2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, 1.0, 1.2)
array([2.        , 2.83333333])
>>> mu = np.array([0.05, 0.3, 1.0])  # a sweep over friction; 0.05 is too little here
>>> batch.valid(2.0, 2.0, 1.0, np.pi / 2 - 0.1, np.pi / 2, mu, mu).tolist()
[False, True, True]
>>> batch.worst_squeeze(0.025, 0.075, 0.0, np.pi / 2, np.pi / 2, mu, mu, 1.0, g=9.81,
...                     on_invalid="nan").round(2).tolist()
[147.23, 25.01, 8.84]
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..boundary.errors import InputError
from . import _inputs
from ._inputs import InvalidGraspsError, _check_mode, _prepare, _refuse
from ._xp import (
    _floats,
    _is,
    _namespace,
    _sides,
    _sincos,  # noqa: F401  (tests read it here)
)

__all__ = [
    "MAX_ARRAY_SIZE",
    "PARAMETERS",
    "InvalidGraspsError",
    "closed_form",
    "internal_force",
    "k",
    "k_grasp",
    "valid",
    "worst_squeeze",
]

#: The parameters every function takes first, in this order.
PARAMETERS = _inputs.PARAMETERS
#: Most entries of a list argument, and of a broadcast the arguments do not hold already
#: (as :data:`graspcompass.boundary.inputs.MAX_ARRAY_SIZE`).
MAX_ARRAY_SIZE = _inputs.MAX_ARRAY_SIZE
#: Block length of the numpy evaluation (its temporaries stay in the cache).
_CHUNK = 1 << 13


def _core(xp: Any, p: list) -> tuple[list, list, Any]:
    """S_n, C_n (n = 1..4) and the validity mask, eqs. (28)-(39) and condition (1)."""
    x1, x2, y, phi1, phi2, mu1, mu2 = p
    n1, d1, n3, d3 = _sides(xp, phi1, mu1)
    n2, d2, n4, d4 = _sides(xp, phi2, mu2)
    D = x1 + x2
    h = D * 0.5
    with np.errstate(all="ignore"):
        t1, t2, t3, t4 = n1 / d1, n2 / d2, n3 / d3, n4 / d4
        S = [y * t1 - h, h - y * t2, y * t3 - h, h - y * t4]
        C = [x2 * t1, x1 * t2, x2 * t3, x1 * t4]
        # condition (1): d1, d2 < 0 < d3, d4; with sin φ > 0 it implies μ > 0 exactly (d3 − d1
        # = 2 fl(μ sin φ) in sign).  nan fails every comparison; the sum catches infinities.
        ok = (
            (D > 0)
            & (y >= 0)
            & (phi1 > 0)
            & (phi1 <= math.pi)
            & (phi2 > 0)
            & (phi2 <= math.pi)
            & (xp.maximum(d1, d2) < 0)
            & (xp.minimum(d3, d4) > 0)
            & (h + y + mu1 + mu2 < math.inf)
        )
    return S, C, ok


def _margin_ok(xp: Any, p: list, margin: float) -> Any:
    """Condition (1) with every inequality holding by more than ``margin`` of its bound."""
    _, _, _, phi1, phi2, mu1, mu2 = p
    ok = None
    half = math.pi / 2
    for phi, mu in ((phi1, mu1), (phi2, mu2)):
        xi = xp.atan(mu)
        lo, up = phi - xi, phi + xi
        m = (
            (lo + half > margin * half)
            & (half - lo > margin * half)
            & (up - half > margin * half)
            & (3 * half - up > margin * 3 * half)
        )
        ok = m if ok is None else ok & m
    return ok


def _nan_where(xp: Any, ok: Any, v: Any) -> Any:
    return xp.where(ok, v, xp.asarray(math.nan, dtype=v.dtype))


def _blocks(xp: Any, arrays: list) -> list[list] | None:
    """Row blocks of same-shape numpy arrays (scalars kept), or None: evaluate at once."""
    if not _is(xp, "numpy"):
        return None
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    n = math.prod(shape)
    if n <= 2 * _CHUNK or any(a.ndim and a.shape != shape for a in arrays):
        return None
    flat = [a.reshape(-1) if a.ndim else a for a in arrays]
    return [[a[lo : lo + _CHUNK] if a.ndim else a for a in flat] for lo in range(0, n, _CHUNK)]


# -- the public functions --------------------------------------------------------------------
def _quiet(fn: Any) -> Any:
    """Run ``fn`` without numpy's floating-point warnings: a nan or an infinity given is an
    invalid grasp (or, for θ, gives nan), said by the result or by InvalidGraspsError,
    never by a RuntimeWarning on stderr."""
    import functools

    @functools.wraps(fn)
    def quiet(*args: Any, **kwargs: Any) -> Any:
        with np.errstate(all="ignore"):
            return fn(*args, **kwargs)

    return quiet


@_quiet
def valid(
    x1: Any, x2: Any, y: Any, phi1: Any, phi2: Any, mu1: Any, mu2: Any, *, margin: float = 0.0
) -> Any:
    """Which grasps lie in the domain of the method: condition (1) and the ranges.

    ``x1 + x2 > 0``, ``y >= 0``, ``0 < φ_i <= π``, ``μ_i > 0``, all finite (and
    ``(x1 + x2)/2 + y + μ1 + μ2`` below the largest double), and condition (1)
    ``−π/2 < φ_i − ξ_i < π/2 < φ_i + ξ_i < 3π/2`` (ξ_i = atan μ_i, eq. (22)), decided
    from the signs of the μ form's denominators
    ``cos φ_i ∓ μ_i sin φ_i``.  Within about 1e-16 rad of a bound the verdict
    follows the rounding of those denominators.

    Parameters
    ----------
    x1, x2, y, phi1, phi2, mu1, mu2 : array or number
        Broadcasting together (any Array API namespace).
    margin : float, optional
        Also require every inequality of (1) to hold by more than
        ``margin · |bound|`` (rad); ``margin=1e-12`` refuses what the float path
        of :class:`graspcompass.Grasp` refuses
        (:data:`graspcompass.grasp._floatpath.FLOAT_MARGIN`).

    Returns
    -------
    array of bool
        The broadcast shape of the parameters.

    Examples
    --------
    >>> import numpy as np
    >>> valid(1.0, 1.0, 0.0, np.pi / 2, np.pi / 2, np.array([0.5, -0.5, np.nan]), 0.5)
    array([ True, False, False])
    """
    xp, p, _ = _prepare((x1, x2, y, phi1, phi2, mu1, mu2))
    _, _, ok = _core(xp, p)
    if margin:
        ok = ok & _margin_ok(xp, p, float(margin))
    return xp.broadcast_to(ok, np.broadcast_shapes(*(tuple(a.shape) for a in p)))


@_quiet
def closed_form(
    x1: Any, x2: Any, y: Any, phi1: Any, phi2: Any, mu1: Any, mu2: Any, *, on_invalid: str = "raise"
) -> tuple[Any, Any]:
    """``S_n`` and ``C_n`` of eqs. (28)-(39), ``V_n = (S_n, C_n)`` (30), (33), of many grasps.

    Parameters
    ----------
    x1, x2, y, phi1, phi2, mu1, mu2 : array or number
        The grasps' parameters, broadcasting together (any Array API namespace).
    on_invalid : {"raise", "nan"}
        Raise :class:`InvalidGraspsError` for a grasp outside the domain
        (:func:`valid`), or give it ``nan``.

    Returns
    -------
    S, C : array
        Shape ``broadcast + (4,)``: the last axis is n = 1..4 (upper side at P1,
        upper at P2, lower at P1, lower at P2).

    Examples
    --------
    >>> import numpy as np
    >>> S, C = closed_form(np.sqrt(3) / 2, np.sqrt(3) / 2, 0.5, np.pi / 3, np.pi / 3,
    ...                    1.0, np.sqrt(3))  # Fig. 6: V_1 = (-1 - √3, -3/2 - √3)
    >>> S.shape, bool(np.allclose([S[0], C[0]], [-1 - np.sqrt(3), -1.5 - np.sqrt(3)]))
    ((4,), True)
    """
    _check_mode(on_invalid)
    xp, p, _ = _prepare((x1, x2, y, phi1, phi2, mu1, mu2))
    S, C, ok = _core(xp, p)
    shape = np.broadcast_shapes(*(tuple(a.shape) for a in p))
    if on_invalid == "raise":
        _refuse(xp, p, xp.broadcast_to(ok, shape))
    else:
        S = [_nan_where(xp, ok, v) for v in S]
        C = [_nan_where(xp, ok, v) for v in C]
    S = xp.stack([xp.broadcast_to(v, shape) for v in S], axis=-1)
    C = xp.stack([xp.broadcast_to(v, shape) for v in C], axis=-1)
    return S, C


@_quiet
def k(
    theta: Any,
    x1: Any,
    x2: Any,
    y: Any,
    phi1: Any,
    phi2: Any,
    mu1: Any,
    mu2: Any,
    *,
    on_invalid: str = "raise",
) -> Any:
    """The lower limits ``k_n(θ) = S_n sin θ − C_n cos θ`` (eqs. (27), (32)) of many grasps.

    ``theta`` broadcasts with the parameters; the result has shape
    ``broadcast + (4,)`` (n = 1..4 on the last axis).  Inputs as in
    :func:`closed_form`.

    Examples
    --------
    >>> import numpy as np
    >>> k(0.0, 2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, 1.0, 1.2).round(12).tolist()
    [2.0, 1.666666666667, -2.0, -1.666666666667]
    """
    S, C = closed_form(x1, x2, y, phi1, phi2, mu1, mu2, on_invalid=on_invalid)
    xp = _namespace(S)
    t = _floats(xp, (theta,), ("theta",))[0]
    s, c = xp.sin(t)[..., None], xp.cos(t)[..., None]
    return S * s - C * c


def _k_grasp(xp: Any, theta: Any, p: list, on_invalid: str) -> tuple[Any, Any, list]:
    S, C, ok = _core(xp, p)
    s, c = xp.sin(theta), xp.cos(theta)
    kg = S[0] * s - C[0] * c  # the largest of the four k_n
    for Sn, Cn in zip(S[1:], C[1:]):
        kg = xp.maximum(kg, Sn * s - Cn * c)
    kg = xp.maximum(kg, xp.asarray(0.0, dtype=kg.dtype))
    shape = np.broadcast_shapes(tuple(kg.shape), *(tuple(a.shape) for a in p))
    kg, ok = xp.broadcast_to(kg, shape), xp.broadcast_to(ok, shape)
    if on_invalid == "raise":
        _refuse(xp, [xp.broadcast_to(a, shape) for a in p], ok)
        return kg, ok, p
    return _nan_where(xp, ok, kg), ok, p


@_quiet
def k_grasp(
    theta: Any,
    x1: Any,
    x2: Any,
    y: Any,
    phi1: Any,
    phi2: Any,
    mu1: Any,
    mu2: Any,
    *,
    on_invalid: str = "raise",
) -> Any:
    """The least internal-force parameter ``max(k_1, k_2, k_3, k_4, 0)`` (eq. (25)).

    ``theta`` (rad, eq. (26)) broadcasts with the parameters; the result has
    the broadcast shape.  Inputs as in :func:`closed_form`.  For one grasp on
    many angles :meth:`graspcompass.Grasp.k_grasp` is faster (a table of the
    envelope) and correctly rounds S_n, C_n.

    Examples
    --------
    >>> import numpy as np
    >>> k_grasp(np.linspace(0, np.pi, 3), 2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, 1.0, 1.2)
    array([2.        , 2.83333333, 2.        ])
    """
    _check_mode(on_invalid)
    xp, p, (t,) = _prepare((x1, x2, y, phi1, phi2, mu1, mu2), (theta,), ("theta",))
    return _k_grasp(xp, t, p, on_invalid)[0]


@_quiet
def internal_force(
    theta: Any,
    x1: Any,
    x2: Any,
    y: Any,
    phi1: Any,
    phi2: Any,
    mu1: Any,
    mu2: Any,
    external_force: Any = 1.0,
    *,
    on_invalid: str = "raise",
) -> Any:
    """The least internal force ``F_int = k_grasp(θ)/(x1 + x2) · F_e`` (eq. (17)).

    ``external_force`` (F_e >= 0, broadcasting too) is not checked.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(internal_force(0.0, 2.0, 2.0, 1.0, np.pi / 2, np.pi / 2, 1.0, 1.2, 10.0)), 12)
    5.0
    """
    _check_mode(on_invalid)
    xp, p, (t, fe) = _prepare(
        (x1, x2, y, phi1, phi2, mu1, mu2), (theta, external_force), ("theta", "external_force")
    )
    kg = _k_grasp(xp, t, p, on_invalid)[0]
    return kg / (p[0] + p[1]) * fe


@_quiet
def worst_squeeze(
    x1: Any,
    x2: Any,
    y: Any,
    phi1: Any,
    phi2: Any,
    mu1: Any,
    mu2: Any,
    mass: Any,
    *,
    g: Any = 9.80665,
    accel: Any = 0.0,
    safety: Any = 1.0,
    per: str = "jaw",
    on_invalid: str = "raise",
) -> Any:
    """The squeeze that holds each part in every orientation, for many grasps.

    ``S_f m (g + A) max_n |V_n| / (x1 + x2)`` per jaw, twice that with
    ``per="total"`` (the paper's §5 remark with eq. (17); the derivation is in
    :mod:`graspcompass.sizing.core`), in SI units: metres, radians, kg, m/s²,
    newtons.  The same number as :func:`graspcompass.sizing.worst_squeeze_many`
    and the ``worst_squeeze`` of :func:`graspcompass.sizing.size_gripper`, with
    condition (1) checked and any Array API namespace.

    Parameters
    ----------
    x1, x2, y, phi1, phi2, mu1, mu2 : array or number
        The grasps in the paper's frame (see :func:`closed_form`).
    mass, g, accel, safety : array or number
        Mass m (kg), gravity g and the acceleration bound A (m/s²), the safety
        factor S_f; they broadcast with the grasps and are not checked.
    per : {"jaw", "total"}
    on_invalid : {"raise", "nan"}

    Examples
    --------
    >>> import numpy as np
    >>> F = worst_squeeze(0.025, 0.075, 0.0, np.pi / 2, np.pi / 2, 0.3, 0.3, 1.0, g=9.81)
    >>> round(float(F), 2)  # the worked example of issue 13: 981 √26 / 200 N per jaw
    25.01
    """
    _check_mode(on_invalid)
    if per not in ("jaw", "total"):
        raise InputError(f"per: expected 'jaw' or 'total', got {per!r}")
    xp, p, (m, gg, a, sf) = _prepare(
        (x1, x2, y, phi1, phi2, mu1, mu2),
        (mass, g, accel, safety),
        ("mass", "g", "accel", "safety"),
    )
    factor = 1.0 if per == "jaw" else 2.0
    blocks = _blocks(xp, [*p, m, gg, a, sf])
    if blocks is None:
        out, ok = _squeeze(xp, p, m, gg, a, sf, factor)
        shape = np.broadcast_shapes(*(tuple(v.shape) for v in (*p, m, gg, a, sf)))
        out, ok = xp.broadcast_to(out, shape), xp.broadcast_to(ok, shape)
    else:  # numpy: blocks that stay in the cache (3x faster on 10^6 grasps)
        shape = np.broadcast_shapes(*(v.shape for v in (*p, m, gg, a, sf)))
        out, ok = np.empty(math.prod(shape)), np.empty(math.prod(shape), dtype=bool)
        for lo, b in zip(range(0, out.size, _CHUNK), blocks):
            bm, bg, ba, bsf = b[7:]  # the block's mass, g, acceleration, safety factor
            out[lo : lo + _CHUNK], ok[lo : lo + _CHUNK] = _squeeze(
                xp, b[:7], bm, bg, ba, bsf, factor
            )
        out, ok = out.reshape(shape), ok.reshape(shape)
    if on_invalid == "raise":
        _refuse(xp, [xp.broadcast_to(v, shape) for v in p], ok)
        return out
    return _nan_where(xp, ok, out)


def _squeeze(xp: Any, p: list, m: Any, g: Any, a: Any, sf: Any, factor: float) -> tuple[Any, Any]:
    S, C, ok = _core(xp, p)
    with np.errstate(all="ignore"):
        r2 = None
        for Sn, Cn in zip(S, C):
            v = Sn * Sn + Cn * Cn
            r2 = v if r2 is None else xp.maximum(r2, v)
        out = (sf * m * (g + a) * factor) * xp.sqrt(r2) / (p[0] + p[1])
    ok = xp.broadcast_to(ok, np.broadcast_shapes(tuple(ok.shape), tuple(out.shape)))
    return out, ok
