"""Exact arithmetic helpers of the kernel: canonical form, zero and sign decisions.

The kernel never calls :func:`sympy.simplify`.  Every coordinate a construction
makes is passed once through :func:`canon`, which is cheap and canonical enough
for the expressions of the paper:

* a number free of symbols is put over a rationalised denominator and expanded
  (``radsimp`` then ``expand``), so that ``tan(7*pi/12)`` style quotients come
  out as ``-2 - sqrt(3)`` instead of towers of nested radicals;
* an expression with symbols is brought to one reduced fraction
  (:func:`sympy.cancel`) in its generators (``x1``, ``sin(phi1)``, ``mu1`` ...);
* an expression holding floats is evaluated to a float.

The code lives in private modules, lowest first, and every name stays importable
from here: the float filter and integer balls (``_exact_bounds``), the rings and
their reduction (``_exact_ring``), the conversion of an expression to a fraction
(``_exact_convert``), :func:`canon` and :func:`sym` (``_exact_canon``), the zero and
sign decisions and :func:`approx` (``_exact_decide``), and the fast arithmetic of
:class:`Frac` (``_exact_frac``).
"""

from __future__ import annotations

import sympy as sp

from ._exact_bounds import (
    _IV_PREC,  # noqa: F401
    _U,  # noqa: F401
    _ball_poly,  # noqa: F401
    _balls,  # noqa: F401
    _clearly_nonzero,  # noqa: F401
    _float_sign,  # noqa: F401
    _gen_ball,
    _gen_float,
    _gen_interval,
    _intervals,  # noqa: F401
    _scaled,  # noqa: F401
)
from ._exact_canon import _rationalize, _square_roots, canon, free, has_float, sym, text  # noqa: F401
from ._exact_convert import (
    _GENS,
    _MAX_GENS,  # noqa: F401
    _TRIAL,  # noqa: F401
    _TRIG,  # noqa: F401
    _atom_plan,
    _canon_ring,  # noqa: F401
    _collect,  # noqa: F401
    _convert,  # noqa: F401
    _lift,  # noqa: F401
    _positions,
    _small_primes,  # noqa: F401
    _square_free,  # noqa: F401
    fold_fractions,
)
from ._exact_decide import (
    _PREC,  # noqa: F401
    _ball_quotient,  # noqa: F401
    _interval,  # noqa: F401
    _strict_sign,  # noqa: F401
    approx,
    decide_sign,
    decide_zero,
)
from ._exact_frac import Frac, NotAFraction, _ground, _nd  # noqa: F401
from ._exact_ring import (
    _ADD_ORDER,  # noqa: F401
    _MEMO,
    _SQRT,
    Ring,  # noqa: F401
    _as_expr,  # noqa: F401
    _clear_roots,  # noqa: F401
    _finish,  # noqa: F401
    _gen_key,  # noqa: F401
    _reduce,  # noqa: F401
    _ring,
    reduce_poly,  # noqa: F401
)

__all__ = [
    "Expr",
    "approx",
    "canon",
    "clear_caches",
    "decide_sign",
    "decide_zero",
    "fold_fractions",
    "free",
    "has_float",
    "sym",
    "text",
]

Expr = sp.Expr


def clear_caches() -> None:
    """Forget the generators and memoised canonical forms (for benchmarks and tests)."""
    _GENS.clear()
    _MEMO.clear()
    from . import _exact_canon, trig

    _exact_canon._text.cache_clear()
    _ring.cache_clear()
    _atom_plan.cache_clear()
    _positions.cache_clear()
    _gen_interval.cache_clear()
    _gen_ball.cache_clear()
    _gen_float.cache_clear()
    _SQRT.clear()
    trig.sincos.cache_clear()
    trig._reference.cache_clear()
