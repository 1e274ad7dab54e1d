"""Factorisation of the prover's sparse polynomials in C (python-flint).

The prover keeps its polynomials in sympy's sparse rings (:mod:`._ring`,
:mod:`.certify_algebra`); their factorisation goes through python-flint's
``fmpq_mpoly.factor`` (FLINT's multivariate factoriser), which is exact and one
to two orders of magnitude faster than sympy's Zassenhaus on the conditions of a
construction.  The factors come back in the ring they came from.
"""

from __future__ import annotations

from typing import Any

import flint

__all__ = ["divide", "factor_list"]


def _ctx(n: int) -> Any:
    return flint.fmpq_mpoly_ctx.get(tuple(f"g{i}" for i in range(max(n, 1))), "lex")


def factor_list(p: Any) -> tuple[Any, list[tuple[Any, int]]]:
    """``(content, [(factor, multiplicity), ...])`` of a sympy ``PolyElement`` over QQ.

    The same contract as ``PolyElement.factor_list``: ``p`` is the content times the
    product of the factors to their multiplicities; each factor is irreducible over
    Q and lies in ``p.ring``.

    Examples
    --------
    >>> import sympy as sp
    >>> R, x, y = sp.ring("x, y", sp.QQ)
    >>> c, fs = factor_list(2 * x**2 * y - 2 * y)
    >>> c == 2 and sorted(str(f) for f, _ in fs)
    ['x + 1', 'x - 1', 'y']
    """
    R = p.ring
    dom = R.domain
    q = _ctx(R.ngens).from_dict(
        {
            m if R.ngens else (0,): flint.fmpq(int(c.numerator), int(c.denominator))
            for m, c in p.terms()
        }
    )
    c, fs = q.factor()
    out = []
    for f, k in fs:
        terms = {
            tuple(int(e) for e in m[: R.ngens]): dom(int(v.p), int(v.q))
            for m, v in f.to_dict().items()
        }
        out.append((R.from_dict(terms), int(k)))
    return dom(int(c.p), int(c.q)), out


def _to_flint(p: Any, ctx: Any) -> Any:
    n = p.ring.ngens
    return ctx.from_dict(
        {m if n else (0,): flint.fmpq(int(c.numerator), int(c.denominator)) for m, c in p.terms()}
    )


def _from_flint(q: Any, R: Any) -> Any:
    dom = R.domain
    return R.from_dict(
        {
            tuple(int(e) for e in m[: R.ngens]): dom(int(v.p), int(v.q))
            for m, v in q.to_dict().items()
        }
    )


def divide(p: Any, divisors: list[Any]) -> tuple[list[Any], Any]:
    """``(quotients, remainder)`` with ``p = sum q_i d_i + remainder``, dividing by each
    divisor in turn (python-flint's ``divmod`` in the ring's lex order).

    For divisors whose leading monomials are pairwise coprime, taken in an order where
    no later divisor brings back the leading monomial of an earlier one (the relations
    of :mod:`._ring`: outer roots, inner roots, then sin² + cos² − 1), the remainder is
    the unique normal form modulo the Gröbner basis they form, as sympy's ``div``
    gives; the quotients certify it.

    Examples
    --------
    >>> import sympy as sp
    >>> R, s, c = sp.ring("s, c", sp.QQ, sp.lex)
    >>> q, r = divide(s**3 + s * c, [s**2 + c**2 - 1])
    >>> r == s * c + s - s * c**2 and q[0] * (s**2 + c**2 - 1) + r == s**3 + s * c
    True
    """
    R = p.ring
    ctx = flint.fmpq_mpoly_ctx.get(tuple(f"g{i}" for i in range(max(R.ngens, 1))), "lex")
    rem = _to_flint(p, ctx)
    quotients = []
    for d in divisors:
        q, rem = divmod(rem, _to_flint(d, ctx))
        quotients.append(_from_flint(q, R))
    return quotients, _from_flint(rem, R)
