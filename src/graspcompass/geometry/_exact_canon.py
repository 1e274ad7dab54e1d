"""The canonical form of the kernel's exact expressions (:func:`canon`) and its inputs.

Every coordinate a construction makes is passed once through :func:`canon`; a
number whose atoms the ring of :mod:`~graspcompass.geometry._exact_convert` cannot
hold is put over a rationalised denominator by conjugates (:func:`_rationalize`).
Private to :mod:`graspcompass.geometry.exact`, which re-exports these names.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from ..boundary.expr import parse_exact
from ._exact_convert import _canon_ring
from ._exact_ring import _MEMO, _SORTED_TERMS
from ._exact_text import _fast_text


def sym(value: object) -> sp.Expr:
    """Return ``value`` as a sympy expression without any parsing of text.

    Python ints become :class:`sympy.Integer`, floats :class:`sympy.Float`;
    sympy expressions pass through; text is read exactly and safely by
    :func:`graspcompass.expr.parse_exact` (``"1.2"`` is 6/5).

    Examples
    --------
    >>> sym(3), sym(0.5), sym("1.2")
    (3, 0.500000000000000, 6/5)
    """
    if isinstance(value, sp.Basic):
        return value  # type: ignore[return-value]
    if isinstance(value, str):
        return parse_exact(value)
    if isinstance(value, bool):
        raise TypeError(f"expected a number or a sympy expression, got {value!r}")
    if isinstance(value, int):
        return sp.Integer(value)
    if isinstance(value, float):
        return sp.Float(value)
    try:
        return sp.sympify(value, strict=True)  # numpy scalars, Fraction
    except (sp.SympifyError, TypeError) as exc:
        raise TypeError(f"expected a number or a sympy expression, got {value!r}") from exc


def text(expr: object) -> str:
    """``str(expr)`` in sympy's own term order, without its numeric sorting of terms.

    The default printer sorts the terms of a sum of numbers by evaluating each one,
    which is slow for long exact sums; this text is the same for equal canonical
    forms.

    Examples
    --------
    >>> text(sp.sqrt(3) / 2 + 1)
    'sqrt(3)/2 + 1'
    """
    if not isinstance(expr, sp.Basic):
        return str(expr)
    return _text(expr)


@lru_cache(maxsize=4096)
def _text(expr: sp.Basic) -> str:
    """:func:`text`, once per expression (an envelope's break angle ends one arc and
    starts the next)."""
    hit = _MEMO.get(expr)
    if hit is not None and len(hit[1]) + len(hit[2]) > _SORTED_TERMS:
        return _poly_text(*hit)  # a long canonical number: printed from its polynomials
    if free(expr) or not expr.has(sp.sin, sp.cos, sp.atan):
        return str(expr)  # small radicals and symbols: sympy's usual order
    fast = _fast_text(expr)
    return fast if fast is not None else sp.sstr(expr, order="none")


def _poly_text(R, n, d) -> str:
    """``n/d`` as text, term by term in the ring's monomial order (``sympy.sstr`` of
    the same expression sorts its terms first, which costs seconds for long ones)."""
    names: dict[tuple[int, int], str] = {}

    def poly(p) -> str:
        roots = set(R.roots)
        out = []
        for monom, c in p.terms():
            m, factors = 1, []
            for i, e in enumerate(monom):
                if not e:
                    continue
                if i in roots and e == 1:
                    m *= int(R.symbols[i].base)
                    continue
                f = names.get((i, e))
                if f is None:
                    g = str(R.symbols[i])
                    f = names[(i, e)] = g if e == 1 else f"{g}**{e}"
                factors.append(f)
            if m > 1:
                factors.insert(0, f"sqrt({m})")
            num, den = int(c.p), int(c.q)
            sign = "-" if num < 0 else "+"
            num = abs(num)
            body = "*".join(([str(num)] if num != 1 or not factors else []) + factors)
            if den != 1:
                body += f"/{den}"
            out.append((sign, body))
        if not out:
            return "0"
        head = ("-" if out[0][0] == "-" else "") + out[0][1]
        return head + "".join(f" {sg} {b}" for sg, b in out[1:])

    if d.is_one():
        return poly(n)
    return f"({poly(n)})/({poly(d)})"


def has_float(expr: sp.Expr) -> bool:
    """True when ``expr`` holds a floating-point number (the numeric path)."""
    if expr in _MEMO:  # the kernel's canonical numbers are exact
        return False
    return bool(expr.atoms(sp.Float))


def free(expr: sp.Expr) -> bool:
    """``bool(expr.free_symbols)``, read off the ring of a canonical number at once."""
    hit = _MEMO.get(expr)
    if hit is not None:
        return hit[0].free
    return bool(expr.free_symbols)


def canon(expr: sp.Expr) -> sp.Expr:
    """Canonical, small form of an exact expression (no ``simplify``).

    Numbers and symbolic expressions alike become one reduced fraction of
    sparse polynomials in their generators (symbols, ``sqrt(p)`` for primes p,
    ``sin(a)`` and ``cos(a)`` of each angle, other atoms), with the numerator
    and denominator reduced modulo ``sqrt(p)**2 = p`` and
    ``sin(a)**2 + cos(a)**2 = 1`` and square roots cleared from the denominator
    by conjugates.

    Examples
    --------
    >>> from sympy import sqrt, pi, tan, sin, cos, symbols
    >>> canon((sqrt(3) + 1) / (1 - sqrt(3)))
    -2 - sqrt(3)
    >>> canon(tan(7*pi/12) * sqrt(3)/2)
    -sqrt(3) - 3/2
    >>> a, b = symbols("a b")
    >>> canon((a**2 - b**2) / (a - b))
    a + b
    >>> canon(sin(a)**2 + cos(a)**2 - 1), canon(sqrt(6) - sqrt(2)*sqrt(3))
    (0, 0)
    """
    expr = sym(expr)
    if expr.is_Rational or expr.is_Symbol or expr in _MEMO:  # memo keys are canonical
        return expr
    if has_float(expr):
        return sp.Float(expr.evalf(17)) if not expr.free_symbols else sp.expand(expr)
    fast = _canon_ring(expr)
    if fast is not None:
        return fast
    if expr.free_symbols:
        return sp.cancel(sp.together(expr))
    num, den = sp.fraction(sp.together(expr))
    if den.is_Rational:
        return sp.expand(num) / den
    num, den = _rationalize(sp.expand(num), sp.expand(den))
    return sp.expand(num) / sp.expand(den)


def _square_roots(expr: sp.Expr) -> list[sp.Pow]:
    return sorted(
        (p for p in expr.atoms(sp.Pow) if p.exp == sp.S.Half and p.base.is_Rational),
        key=sp.default_sort_key,
    )


def _rationalize(num: sp.Expr, den: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Clear square roots of rationals from ``den`` by conjugates, one root at a time.

    ``den = A + B*r`` with r a square root; multiplying by ``A - B*r`` leaves
    ``A**2 - B**2*r**2``, free of r.  Much cheaper than ``radsimp`` (which runs
    ``nsimplify``) on the quadratic fields of the paper's examples.
    """
    for _ in range(6):
        roots = _square_roots(den)
        if not roots or den.is_Rational:
            break
        r = roots[0]
        b = den.coeff(r)
        a = sp.expand(den - b * r)
        if a.has(r) or b.has(r):
            break
        num = sp.expand(num * (a - b * r))
        den = sp.expand(a**2 - b**2 * r.base)
    return num, den
