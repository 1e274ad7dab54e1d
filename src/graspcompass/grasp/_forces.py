"""The float path of a grasp's closed form and the forces of §2.3.

``g._floats()`` gives S_n, C_n of eqs. (28)-(39) as doubles correct to about one
ulp (:func:`~graspcompass.grasp._floatpath.closed_form_floats`); ``k_grasp`` of eq. (25)
evaluates many float angles through the envelope table of
:mod:`graspcompass.batch`; ``F_T`` (13), ``F_N`` (15), the contact forces (16) and
``F_int`` (17) are exact for an exact θ and arrays for a float or numpy θ.  The
methods of :class:`~graspcompass.grasp.Grasp` keep the documentation and call
these.  Private to :mod:`graspcompass.grasp`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..boundary._numpy import is_a
from ..boundary.errors import InputError, NonFiniteValueError, SymbolicValueError
from ..boundary.inputs import angle_values, force_value, real_value
from ..geometry.exact import canon, decide_sign
from . import _envelope
from ._floatpath import closed_form_floats
from ._values import _HALF_MAX, _double, _finite, _is_numeric, _sympy

if TYPE_CHECKING:
    import numpy as np

    from . import Grasp
else:
    from ..boundary._numpy import np


def _closed_form_doubles(g: Grasp) -> tuple[np.ndarray, np.ndarray]:
    """:meth:`Grasp._floats` of ``g``: S_n, C_n of eqs. (28)-(39) in doubles, cached."""
    if g._SC is None:
        try:
            S, C = closed_form_floats(g.params)
        except TypeError as exc:
            raise SymbolicValueError(
                "a symbolic grasp cannot be evaluated on numeric θ; substitute values "
                "first (Grasp.subs) or give θ exactly"
            ) from exc
        except OverflowError:
            S, C = [math.inf], [math.inf]
        if not all(abs(v) <= _HALF_MAX for v in (*S, *C)):  # also catches nan
            raise NonFiniteValueError(
                "the grasp's S_n, C_n (eqs. (28)-(39)) are beyond double precision "
                f"(|S_n|, |C_n| must stay below {_HALF_MAX:.2g}); the numeric path "
                "cannot use this grasp: give θ exactly (text such as 'pi/3')"
            )
        object.__setattr__(g, "_SC", (np.array(S), np.array(C)))
    return g._SC


def _k_grasp(g: Grasp, theta: Any) -> Any:
    """:meth:`Grasp.k_grasp` of ``g``."""
    t = angle_values(theta)
    if isinstance(t, float):  # one angle: no array machinery
        S, C = g._floats()
        s, c = math.sin(t), math.cos(t)
        return max(0.0, *(float(Sn) * s - float(Cn) * c for Sn, Cn in zip(S, C)))
    if is_a(t, "ndarray"):
        S, C = g._floats()
        if t.size >= _envelope.TABLE_MIN_SIZE:  # many angles: the table of the envelope
            table = g.__dict__.get("_ktable")  # (issue 13 §5)
            if table is None:
                table = _envelope.EnvelopeTable(S, C)
                object.__setattr__(g, "_ktable", table)
            return table(t)
        out = _envelope.direct_k_grasp(S, C, t)
        return out if t.ndim else float(out)
    ks = g.k(t)
    if any(k.free_symbols for k in ks):
        return sp.Max(*ks, sp.Integer(0))
    best = sp.Integer(0)
    for k in ks:
        if decide_sign(k - best) == 1:
            best = k
    return best


def _internal_force(g: Grasp, theta: Any, external_force: Any) -> Any:
    """:meth:`Grasp.internal_force` of ``g``."""
    t = angle_values(theta)
    fe = force_value(external_force)
    kg = g.k_grasp(t)
    if _is_numeric(t):
        with np.errstate(over="ignore", invalid="ignore"):
            out = kg * _double(fe, "external_force") / _double(g.D, "x1 + x2")
        return _finite(out, "F_int")
    out = kg * fe / g.D
    return out if isinstance(kg, sp.Max) else canon(out)


def _F_T(g: Grasp, theta: Any, external_force: Any) -> Any:
    """:meth:`Grasp.F_T` of ``g``."""
    t = angle_values(theta)
    fe = force_value(external_force)
    numeric = _is_numeric(t)
    if numeric:
        s, c, fe = np.sin(t), np.cos(t), _double(fe, "external_force")
        D, x1, x2, y, s1, c1, s2, c2 = (
            _double(v, name)
            for v, name in (
                (g.D, "x1 + x2"),
                (g.x1, "x1"),
                (g.x2, "x2"),
                (g.y, "y"),
                (g.s1, "sin φ1"),
                (g.c1, "cos φ1"),
                (g.s2, "sin φ2"),
                (g.c2, "cos φ2"),
            )
        )
    else:
        fe = _sympy(fe)
        s, c = sp.sin(t), sp.cos(t)
        D, x1, x2, y = g.D, g.x1, g.x2, g.y
        s1, c1, s2, c2 = g.s1, g.c1, g.s2, g.c2
    a, b = y * s - x2 * c, y * s + x1 * c
    v = [
        D * s1 * s + 2 * a * c1,
        D * c1 * s - 2 * a * s1,
        -D * s2 * s - 2 * b * c2,
        -D * c2 * s + 2 * b * s2,
    ]
    if numeric:
        with np.errstate(over="ignore", invalid="ignore"):
            out = fe / (2 * D) * np.array(v)
        return _finite(out, "F_T")
    return sp.Matrix([fe / (2 * D) * e for e in v])


def _F_N(g: Grasp, external_force: Any) -> Any:
    """:meth:`Grasp.F_N` of ``g``."""
    fe = force_value(external_force)
    if isinstance(fe, float):
        with np.errstate(over="ignore", invalid="ignore"):
            out = (
                fe
                / _double(g.D, "x1 + x2")
                * np.array(
                    [
                        _double(v, name)
                        for v, name in (
                            (g.s1, "sin φ1"),
                            (g.c1, "cos φ1"),
                            (g.s2, "sin φ2"),
                            (g.c2, "cos φ2"),
                        )
                    ]
                )
            )
        return _finite(out, "F_N")
    return sp.Matrix([fe / g.D * e for e in (g.s1, g.c1, g.s2, g.c2)])


def _contact_forces(g: Grasp, theta: Any, k: Any, external_force: Any) -> Any:
    """:meth:`Grasp.contact_forces` of ``g``."""
    t = angle_values(theta)
    fe = force_value(external_force)
    if _is_numeric(t):
        kk = angle_values(k, "k")
        if not _is_numeric(kk):
            kk = _double(kk, "k")
        kk = np.asarray(kk, dtype=float)
        shape = np.shape(t)
        try:
            ok = np.broadcast_shapes(shape, kk.shape) == shape
        except ValueError:
            ok = False
        if not ok:
            raise InputError(
                f"k: an array of shape {kk.shape} does not broadcast with theta's shape {shape}"
            )
        fe = _double(fe, "external_force")
        fn = g.F_N(fe)
        ft = g.F_T(t, fe)
        with np.errstate(over="ignore", invalid="ignore"):
            out = ft + np.multiply.outer(fn, np.ones(ft.shape[1:])) * kk
        return _finite(out, "the contact forces")
    kv = real_value(k, "k")
    fe = _sympy(fe)
    return g.F_T(t, fe) + kv * g.F_N(fe)
