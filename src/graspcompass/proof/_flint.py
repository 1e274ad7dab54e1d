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

__all__ = ["factor_list"]


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
        {m if R.ngens else (0,): flint.fmpq(int(c.numerator), int(c.denominator))
         for m, c in p.terms()})
    c, fs = q.factor()
    out = []
    for f, k in fs:
        terms = {m[:R.ngens]: dom(int(v.p), int(v.q)) for m, v in f.to_dict().items()}
        out.append((R.from_dict(terms), int(k)))
    return dom(int(c.p), int(c.q)), out
