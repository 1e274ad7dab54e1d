"""The grasp record of a JSON document: its numbers, written and read, and its limits.

A ``<number>`` is exact text read by :func:`~graspcompass.expr.parse_exact`, a JSON
number (a double) or ``{"float": "p/q", "bits": n}`` (:func:`_number`,
:func:`_read`).  :func:`_grasp` reads the record into a
:class:`~graspcompass.Grasp` (step 4 of "Reading JSON files" in
:mod:`graspcompass.export.json`): magnitudes, irrational numbers and generators
within the limits, and the record written the way the grasp writes it.
Private to :mod:`graspcompass.export.json`, which re-exports these names.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.polys.polyerrors import BasePolynomialError

from .. import symbols
from ..boundary.errors import GraspCompassError, InputError
from ..boundary.expr import parse_exact
from ..grasp import Grasp
from ._json_limits import (
    _MAX_NUMBER_GENERATORS_WITH_SYMBOLS,
    _MAX_SHOWN,
    MAX_ANGLE_GENERATORS,
    MAX_GENERATORS,
    MAX_MAGNITUDE,
    MAX_NUMBER_GENERATORS,
    MAX_RADICAND_BITS,
    InconsistentDocumentError,
    JSONDocumentError,
    JSONTooLargeError,
)
from ._json_schema import _GRASP, _check, _difference, _fail, _show

_SYMBOLS = {
    str(s): s
    for s in (
        symbols.x1,
        symbols.x2,
        symbols.y,
        symbols.phi1,
        symbols.phi2,
        symbols.xi1,
        symbols.xi2,
        symbols.mu1,
        symbols.mu2,
        symbols.theta,
        symbols.F_e,
    )
}


_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")


def _number(v: Any) -> str | float | dict[str, Any]:
    v = sp.sympify(v)  # internal: a grasp's value or a step's parameter (sympy, or an int)
    if v.atoms(sp.Float):
        if not v.is_Float:
            v = v.evalf(17)
        if v.free_symbols or not v.is_Float:
            raise ValueError(f"cannot store {v} exactly: it mixes floats and symbols")
        if v._prec == 53:
            return float(v)
        return {"float": str(sp.Rational(v)), "bits": int(v._prec)}  # exact binary value
    return str(v)


def _read_float(v: dict[str, Any], where: str) -> sp.Float:
    p, _, q = v["float"].partition("/")
    num, den = int(p), int(q or 1)
    bits = v["bits"]
    if den == 0 or den & (den - 1):
        raise _fail(
            f"{where}.float",
            "expected the exact binary value of a float (a denominator that is a power of 2)",
            v["float"],
        )
    odd = abs(num) >> ((abs(num) & -abs(num)).bit_length() - 1) if num else 0
    if odd.bit_length() > bits:
        raise _fail(
            f"{where}.float", f"this value needs {odd.bit_length()} bits, not {bits}", v["float"]
        )
    value = sp.Rational(num, den)
    if value != 0 and abs(value) > MAX_MAGNITUDE:
        raise _fail(
            f"{where}.float",
            f"expected a number at most {MAX_MAGNITUDE:g}",
            v["float"],
            JSONTooLargeError,
        )
    return sp.Float(value, precision=bits)


def _read(v: Any, where: str) -> sp.Expr:
    """A validated ``<number>`` as a sympy value (text through the safe parser only)."""
    if isinstance(v, dict):
        return _read_float(v, where)
    if isinstance(v, float):
        return sp.Float(v)
    if isinstance(v, int):
        return sp.Integer(v)
    try:
        return parse_exact(v, symbols=_SYMBOLS)
    except InputError as exc:
        raise JSONDocumentError(f"{where}: {exc}") from None


def _grasp_record(g: Grasp) -> dict[str, Any]:
    p = g.params
    friction = {str(i): ("mu" if sp.atan(p[f"mu{i}"]) == p[f"xi{i}"] else "xi") for i in (1, 2)}
    rec: dict[str, Any] = {k: _number(p[k]) for k in _PARAMS}
    rec["friction"] = friction
    rec["title"] = g.title
    rec["shape"] = list(g.shape) if g.shape else None
    return rec


def _check_grasp_limits(g: Grasp, rec: dict[str, Any]) -> None:
    """Refuse, as :func:`loads` would, a grasp beyond the loader's limits.

    The same checks, in the same order and with the same messages, as step 3
    (the grasp record's schema: title length, number texts, ``bits``, magnitudes)
    and step 4 (sizes, square roots, generators) of "Reading JSON files".
    """
    _check(rec, _GRASP, "grasp")
    _check_magnitudes({k: g.params[k] for k in _PARAMS}, rec)
    _check_generators(g)


def _grasp(rec: dict[str, Any]) -> Grasp:
    vals = {k: _read(rec[k], f"grasp.{k}") for k in _PARAMS}
    floats = [k for k, v in vals.items() if v.atoms(sp.Float)]
    syms = [k for k, v in vals.items() if v.free_symbols]
    if floats and syms:
        raise JSONDocumentError(
            f"grasp: floats ({', '.join(floats)}) and symbols "
            f"({', '.join(syms)}) cannot be mixed in one grasp"
        )
    _check_magnitudes(vals, rec)
    fr = rec["friction"]
    kw = {f"{fr[str(i)]}{i}": vals[f"{fr[str(i)]}{i}"] for i in (1, 2)}
    shape = tuple(rec["shape"]) if rec["shape"] else None
    try:
        g = Grasp(
            vals["x1"],
            vals["x2"],
            vals["y"],
            vals["phi1"],
            vals["phi2"],
            **kw,
            shape=shape,
            title=rec["title"],
        )
    except GraspCompassError as exc:
        raise JSONDocumentError(f"grasp: {exc}") from None
    except (
        ArithmeticError,
        TypeError,
        ValueError,
        NotImplementedError,
        RecursionError,
        BasePolynomialError,
    ) as exc:
        raise JSONDocumentError(
            f"grasp: the exact kernel cannot use these values "
            f"({type(exc).__name__}: {str(exc)[:80]})"
        ) from None
    _check_generators(g)
    again = _grasp_record(g)
    for k in _PARAMS:
        if _difference(rec[k], again[k], k) is None:
            continue
        if _read(rec[k], f"grasp.{k}") == g.params[k]:  # the same value, written otherwise
            raise _fail(
                f"grasp.{k}",
                f"expected {_show(again[k])}, the way dumps writes this value",
                rec[k],
                InconsistentDocumentError,
            )
        src = f"{fr[k[-1]]}{k[-1]}"
        raise _fail(
            f"grasp.{k}",
            f"the grasp gives {_show(again[k])} from {src} = {_show(again[src])}",
            rec[k],
            InconsistentDocumentError,
        )
    if again["friction"] != fr:
        raise _fail(
            "grasp.friction",
            f"the grasp is written {again['friction']}",
            fr,
            InconsistentDocumentError,
        )
    return g


def _check_magnitudes(vals: dict[str, sp.Expr], rec: dict[str, Any]) -> None:
    """Refuse a grasp value of size above :data:`MAX_MAGNITUDE` (``rec`` is shown)."""
    for k, v in vals.items():
        size = sp.N(abs(v), 15) if not v.free_symbols else sp.S.Zero
        if not (size.is_Number and size <= MAX_MAGNITUDE):
            raise _fail(
                f"grasp.{k}",
                f"expected a number at most {MAX_MAGNITUDE:g}",
                rec[k],
                JSONTooLargeError,
            )


def _check_generators(g: Grasp) -> None:
    """Bound the number of irrationals and symbols the exact construction works with."""
    numbers: set[sp.Expr] = set()
    symbolic: set[sp.Expr] = set()
    for name, v in (
        ("x1", g.x1),
        ("x2", g.x2),
        ("y", g.y),
        ("mu1", g.mu1),
        ("mu2", g.mu2),
        ("sin(phi1)", g.s1),
        ("cos(phi1)", g.c1),
        ("sin(phi2)", g.s2),
        ("cos(phi2)", g.c2),
    ):
        if v.atoms(sp.Float):
            continue  # the numeric path: evaluated to floats at once
        walk = sp.preorder_traversal(v)
        for atom in walk:
            if isinstance(atom, sp.Symbol):
                symbolic.add(atom)
            elif isinstance(atom, (sp.Function, sp.NumberSymbol)):
                walk.skip()
                if atom.free_symbols:
                    symbolic.add(atom)
                elif isinstance(atom, (sp.sin, sp.cos)):
                    numbers.add(atom)
                else:
                    raise JSONDocumentError(
                        f"grasp: {name} = {_show(str(v))} uses {str(atom)[:_MAX_SHOWN]}: lengths "
                        "and friction coefficients of exact grasps are rational numbers or square "
                        "roots of them (give floats for the numeric path)"
                    )
            elif isinstance(atom, sp.Pow) and not atom.exp.is_Integer:
                walk.skip()
                if atom.free_symbols:
                    symbolic.add(atom)
                    continue
                base = atom.base
                if atom.exp not in (sp.S.Half, -sp.S.Half) or not base.is_Rational:
                    raise JSONDocumentError(
                        f"grasp: {name} = {_show(str(v))} uses {atom}: only square roots of "
                        "rational numbers are supported in exact grasps"
                    )
                if max(abs(base.p).bit_length(), base.q.bit_length()) > MAX_RADICAND_BITS:
                    raise JSONTooLargeError(
                        f"grasp: {name} uses {_show(str(atom))}, a square root of a number of "
                        f"more than {MAX_RADICAND_BITS} bits"
                    )
                numbers.add(sp.sqrt(base))
    trig = {n for n in numbers if isinstance(n, (sp.sin, sp.cos))}
    roots = numbers - trig
    shown = _show(", ".join(sorted(str(n) for n in roots)))
    limit = _MAX_NUMBER_GENERATORS_WITH_SYMBOLS if symbolic else MAX_NUMBER_GENERATORS
    if len(roots) > limit:  # each square root doubles the degree of the number field
        raise JSONTooLargeError(
            f"grasp: its values use {len(roots)} distinct irrational numbers ({shown}); at "
            f"most {limit} are allowed" + (" next to symbols" if symbolic else "")
        )
    if len(trig) > MAX_ANGLE_GENERATORS:
        raise JSONTooLargeError(
            f"grasp: its values use {len(trig)} sines and cosines of angles that are no "
            f"multiples of pi/12 ({_show(', '.join(sorted(map(str, trig))))}); at most "
            f"{MAX_ANGLE_GENERATORS} are allowed (four angles)"
        )
    if trig and symbolic:
        shown = _show(", ".join(sorted(str(n) for n in numbers)))
        raise JSONTooLargeError(
            f"grasp: its values use sin/cos of an angle that is no multiple of pi/12 next to "
            f"symbols ({shown}); this is not allowed (it could take minutes to construct)"
        )
    if len(numbers) + len(symbolic) > MAX_GENERATORS:
        shown = ", ".join(sorted(str(n) for n in numbers | symbolic))
        raise JSONTooLargeError(
            f"grasp: its values use {len(numbers) + len(symbolic)} "
            f"generators ({_show(shown)}); at most {MAX_GENERATORS} "
            "are allowed"
        )
