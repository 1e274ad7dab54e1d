"""The values of a replayed program: the parameters bound and each step's values.

A program is replayed on a grasp or a mapping of values (:func:`_bindings`, each
checked against its declared domain); ``sin`` and ``cos`` of a parameter take the
grasp's exact values.  A step's values are exact fractions of the kernel
(:func:`_exact_value`, :func:`_frac`) or, for a float grasp, evaluated at 40
digits from the exact binary values and rounded once (:func:`_float_value`).
Private to :mod:`graspcompass.construction.language`, which re-exports these names.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import mpmath
import sympy as sp

from ..boundary.errors import InputError
from ..geometry.exact import Frac, NotAFraction, canon, decide_sign, has_float
from ..geometry.trig import sincos
from ..grasp._floatpath import mpf
from .program import DOMAINS, Param, Program

if TYPE_CHECKING:
    from ..grasp import Grasp


_FLOAT_DIGITS = 40  # working digits of a float grasp's values, rounded once to doubles


def _bindings(program: Program, grasp: Grasp | Mapping[str, Any] | None) -> dict[sp.Basic, sp.Expr]:
    """Symbol (and sin/cos of a parameter) -> value, from a Grasp or a mapping."""
    if grasp is None:
        return {}
    if isinstance(grasp, Mapping):
        from ..boundary.inputs import real_value

        given = {k: real_value(v, k) for k, v in grasp.items()}
    else:
        given = grasp.params
    table: dict[sp.Basic, sp.Expr] = {}
    for p in program.params:
        if p.name not in given:
            raise InputError(f"{program.file}:{p.line}:1: no value for the parameter {p.name!r}")
        table[p.symbol] = given[p.name]
        if isinstance(grasp, Mapping):
            _check_domain(program, p, given[p.name])
    if any(has_float(v) for v in table.values()):
        return table  # floats: each step's value is evaluated from them (_float_value)
    known = {}  # the grasp's own exact sin φi, cos φi (computed when it was made)
    if not isinstance(grasp, Mapping):
        known = {
            getattr(grasp, f"phi{i}"): (getattr(grasp, f"s{i}"), getattr(grasp, f"c{i}"))
            for i in (1, 2)
        }
    for atom in program.trig_atoms:  # exact sines of the grasp's angles (no nested radicals)
        angle = atom.args[0].xreplace(table)
        s, c = known[angle] if angle in known else sincos(angle)
        table[atom] = s if isinstance(atom, sp.sin) else c
    return table


#: Domain -> (bound, sign of value - bound, whether the bound itself is allowed).
_BOUNDS = {
    "positive": ((0, 1, False),),
    "friction": ((0, 1, False),),
    "nonnegative": ((0, 1, True),),
    "angle": ((0, 1, False), (sp.pi, -1, True)),
    "half_angle": ((0, 1, False), (sp.pi / 2, -1, False)),
}


def _check_domain(program: Program, p: Param, value: sp.Expr) -> None:
    """Refuse a value outside the parameter's declared domain (when its sign is decided)."""
    for bound, direction, equal in _BOUNDS.get(p.domain, ()):
        sign = decide_sign(value - bound)
        if sign is not None and sign != direction and not (sign == 0 and equal):
            raise InputError(
                f"{program.file}:{p.line}:1: {p.name} = {value} is outside its "
                f"domain ({p.domain}: {DOMAINS[p.domain]})"
            )


def _float_value(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> sp.Expr:
    """A step's value for a float grasp: a parameter (or its negative) as the double it
    is, a constant as written, anything else evaluated from the exact binary values of
    the parameters at 40 digits and rounded once, as
    :meth:`graspcompass.Grasp.side_direction` does (``cos φ ∓ μ sin φ`` cancels in
    double precision for a nearly horizontal cone side)."""
    if not v.free_symbols:
        return v
    if v.is_Symbol or (v.is_Mul and len(v.args) == 2 and v.args[0] == -1 and v.args[1].is_Symbol):
        return v.xreplace(table)
    try:
        with mpmath.workdps(_FLOAT_DIGITS):
            value = float(_mp(v, table))
    except (ArithmeticError, TypeError, ValueError):  # 1/0, a complex root
        value = float("nan")
    if not math.isfinite(value):
        raise InputError(f"the value {v} is not a finite real number for these parameters")
    return canon(sp.Float(value))


_MP_FUNCTIONS = {
    sp.sin: mpmath.sin,
    sp.cos: mpmath.cos,
    sp.tan: mpmath.tan,
    sp.asin: mpmath.asin,
    sp.acos: mpmath.acos,
    sp.atan: mpmath.atan,
}


def _mp(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> mpmath.mpf:
    """``v`` in mpmath at the working precision, symbols from ``table`` (exact binary)."""
    if v.is_Symbol:
        return mpf(table[v])
    if v.is_Number or not v.free_symbols:
        return mpf(v)
    args = [_mp(a, table) for a in v.args]
    if v.is_Add:
        return mpmath.fsum(args)
    if v.is_Mul:
        return mpmath.fprod(args)
    if v.is_Pow:
        return args[0] ** args[1]
    if type(v) in _MP_FUNCTIONS:
        return _MP_FUNCTIONS[type(v)](*args)
    if isinstance(v, sp.atan2):
        return mpmath.atan2(*args)
    return mpf(v.xreplace(table))  # pragma: no cover - every function of the parser is above


def _exact_value(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> sp.Expr:
    """A step's value for exact parameters, in canonical form (:func:`canon`).

    Computed with the kernel's fractions of polynomials (no sympy trees built on the
    way), or by substitution where they cannot hold it.
    """
    try:
        return _frac(v, table).expr()
    except (NotAFraction, ZeroDivisionError):
        pass
    value = v.xreplace(table)
    if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise InputError(f"the value {v} is not finite for these parameters")
    if value.has(sp.I):
        raise InputError(f"the value {v} is not a real number for these parameters")
    return value if value.is_Atom else canon(value)


def _frac(v: sp.Expr, table: Mapping[sp.Basic, sp.Expr]) -> Frac:
    if v.is_Rational:
        return Frac.of(v)
    hit = table.get(v)
    if hit is not None:
        return Frac.of(hit)
    if v.is_Add or v.is_Mul:
        parts = [_frac(a, table) for a in v.args]
        out = parts[0]
        for f in parts[1:]:
            out = out + f if v.is_Add else out * f
        return out
    if v.is_Pow and v.exp.is_Integer and abs(int(v.exp)) <= 64:
        base, out = _frac(v.base, table), Frac.of(sp.Integer(1))
        for _ in range(abs(int(v.exp))):
            out = out * base
        return out if v.exp > 0 else Frac.of(sp.Integer(1)) / out
    return Frac.of(v.xreplace(table))
