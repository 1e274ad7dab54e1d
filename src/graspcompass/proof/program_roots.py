"""Signs and zeros of values with a constructed square root: exact arguments.

Two arguments the polynomial reduction of :mod:`~graspcompass.proof.program_decide`
cannot make:

* :func:`algebraic_zero` — a value without parameters (a length of the regular
  pentagon) is 0 when its minimal polynomial over ℚ is ``x``
  (:func:`sympy.minimal_polynomial`: resultants and factorisation over ℚ, exact);
* :func:`positive_by_squaring` — ``p + q·√R > 0`` (one square root √R ≥ 0, the
  kernel's branch, p and q free of it) where ``p > 0`` and ``q ≥ 0``; or ``p > 0``,
  ``−q > 0`` and ``p² − q²R > 0``; or ``p < 0``, ``q > 0`` and ``q²R − p² > 0``: then
  ``|p| ≠ |q|√R`` and the sign is the one of the larger, e.g. the triangle
  inequality ``a + b > √(a² + b²)`` (Pythagoras) from ``2ab > 0``.  The signs of p, q
  and of the squared difference come from the caller's prover (``positive``), which
  never sees √R again.

Examples
--------
>>> import sympy as sp
>>> a, b = sp.symbols("a b", positive=True)
>>> positive_by_squaring(a + b - sp.sqrt(a**2 + b**2), lambda e: bool(e.is_positive))
True
>>> positive_by_squaring(a - sp.sqrt(a**2 + b**2), lambda e: bool(e.is_positive))
False
>>> algebraic_zero(2 * sp.sin(sp.pi / 5) - sp.sqrt(sp.Rational(5, 2) - sp.sqrt(5) / 2))
True
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import sympy as sp

from .prove import ProofResult, Status

__all__ = ["algebraic_zero", "by_roots_or_hypotheses", "positive_by_squaring"]

_X = sp.Dummy("x")
#: Values with more operations are not tried (the minimal polynomial would cost more).
MAX_OPS = 400


def algebraic_zero(e: sp.Expr) -> bool:
    """``e == 0`` shown exactly for a constant algebraic ``e`` (False: not shown)."""
    e = sp.sympify(e)
    if e.free_symbols or sp.count_ops(e) > MAX_OPS:
        return False
    if e.has(sp.sin, sp.cos, sp.tan):  # trigonometric values of rational multiples of π
        e = sp.expand_trig(e)
        e = e.rewrite(sp.sqrt) if e.has(sp.sin, sp.cos, sp.tan) else e
        if e.has(sp.sin, sp.cos, sp.tan):
            return False
    try:
        m = sp.minimal_polynomial(e, _X)
    except (NotImplementedError, ValueError, TypeError, sp.PolynomialError):
        return False
    return bool(sp.expand(m - _X) == 0)


def positive_by_squaring(e: sp.Expr, positive: Callable[[sp.Expr], bool]) -> bool:
    """``e > 0`` shown for ``e = p + q·√R`` (see the module); False: not shown."""
    e = sp.expand(sp.sympify(e))
    roots = [a for a in e.atoms(sp.Pow) if a.exp == sp.Rational(1, 2) and a.base.free_symbols]
    if len(roots) != 1 or e.is_Add is not True:
        return False
    r = roots[0]
    s = sp.Dummy("s")
    try:
        poly = sp.Poly(e.xreplace({r: s}), s)
    except sp.PolynomialError:
        return False
    if poly.degree() != 1 or any(c.has(r) for c in poly.all_coeffs()):
        return False
    q, p = poly.all_coeffs()
    rad = r.base
    if positive(p) and (q.is_nonnegative or positive(q)):
        return True
    if positive(p) and positive(-q):
        return positive(sp.expand(p**2 - q**2 * rad))
    if positive(-p) and positive(q):
        return positive(sp.expand(q**2 * rad - p**2))
    return False


def by_roots_or_hypotheses(
    e: sp.Expr, relation: str, prover: Callable[[sp.Expr], Any], hyps: Sequence[Any] = ()
) -> tuple[bool | None, Any]:
    """``(True, ProofResult)`` for ``e relation 0`` (``> >= < <= !=``) shown by squaring
    its constructed root (:func:`positive_by_squaring`, the signs of the parts from
    ``prover(x) -> (ok, ProofResult)``, whose conditions the result keeps) or from the
    file's inequality hypotheses (:func:`~.program_hypotheses.sign_from`); else
    ``(None, None)``."""
    from .program_hypotheses import sign_from

    targets = {">": [e], ">=": [e], "<": [-e], "<=": [-e], "!=": [e, -e]}[relation]
    for t in targets:
        conds: list[str] = []

        def pos(x: sp.Expr, conds: list[str] = conds) -> bool:
            ok, r = prover(x)
            if ok and r is not None:
                conds += list(r.conditions)
            return bool(ok)

        if positive_by_squaring(t, pos):
            return True, ProofResult(
                Status.PROVED,
                "p + q√R compared by squaring: the signs of p, q and of "
                "p² − q²R (√R ≥ 0, the constructed branch)",
                0.0,
                conditions=tuple(conds),
            )
        got = sign_from(t, hyps)
        if got is not None and got[0] == 1:
            return True, ProofResult(
                Status.PROVED,
                "from the file's hypotheses (the signs of its factors)",
                0.0,
                hypotheses=tuple(f"hypothesis {n}" for n in got[1]),
            )
    return None, None
