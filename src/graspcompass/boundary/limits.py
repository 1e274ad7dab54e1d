"""Every limit on outside input, in one place, importing nothing.

The safe parser (:mod:`graspcompass.expr`), the ``graspcompass k`` command
and the docs (``docs/security.md``) read their bounds from here, so a limit
is stated once.  This module imports nothing, so the command line can check
options against these limits before loading sympy or numpy.

Examples
--------
>>> from graspcompass import limits
>>> limits.MAX_LENGTH, limits.MAX_ANGLES
(200, 1000000)
"""

from __future__ import annotations

__all__ = [
    "COMMAND_SECONDS",
    "EXACT_ANGLES",
    "EXACT_VALUES",
    "MAX_ANGLES",
    "MAX_ARGUMENT_BITS",
    "MAX_BITS",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_EXPONENT",
    "MAX_INT_BITS",
    "MAX_LENGTH",
    "MAX_LIST_LENGTH",
    "MAX_NODES",
    "MAX_TERMS",
    "MAX_WORK_BITS",
]

#: Longest text :func:`~graspcompass.expr.parse_exact` reads.
MAX_LENGTH = 200
#: Largest ``|p|`` and ``q`` of an exponent ``p/q`` (``10**10**10`` and ``2**(1/65)`` are refused).
MAX_EXPONENT = 64
#: Highest degree a value may have in the names it uses (parameters, and let values through
#: theirs), counted on its tree before anything is expanded: a chain of ``let`` values such
#: as ``(t + 1)**64`` five deep would be a polynomial of degree 64**5 for the replay.
MAX_DEGREE = 64
#: Most terms a value's polynomial could have, ``C(n + d, n)`` for degree ``d`` in ``n``
#: names (``(a + b + c + d + 1)**64`` could have 814,385): a bound known before expanding.
MAX_TERMS = 20_000
#: Most nested function calls and powers (``sqrt(sqrt(...))`` 17 deep is refused).
MAX_DEPTH = 16
#: Most bits of any integer (numerator or denominator) in a value or an intermediate
#: result: 1100 bits, about 331 decimal digits (``1e309`` reads exactly, ``1e400`` is refused).
MAX_BITS = 1100
#: Most bits of any integer in an argument of ``sin cos tan asin acos atan atan2``
#: (about 38 decimal digits: ``sin(10**38)`` reads, ``sin(10**60)`` is refused).
MAX_ARGUMENT_BITS = 128
#: Most bits, added up over every root and function argument of one text: a bound on
#: the work of exact roots (each may factor its radicand).
MAX_WORK_BITS = 8192
#: Most nodes in the tree of a value or an intermediate result: a safety net, since a
#: function value sympy would write out in more than 40 nodes is kept unevaluated
#: (``tan(pi/120)`` stays ``tan(pi/120)`` rather than 313 nodes of nested radicals).
MAX_NODES = 1000
#: Most angles :func:`~graspcompass.expr.parse_angles` returns.
MAX_ANGLES = 1_000_000
#: Longest list of angles :func:`~graspcompass.expr.parse_angles` reads (and the longest
#: ``--theta`` of ``graspcompass k``).
MAX_LIST_LENGTH = 10 * MAX_LENGTH
#: ``graspcompass k``: most angles read exactly (more are made in double precision).
EXACT_ANGLES = 1000
#: ``graspcompass k --exact``: most angles given exact values.
EXACT_VALUES = 72
#: Default ``--timeout`` (seconds) of every command that replays a construction or checks
#: (``check`` has its own, 600 s): the time budget of one command line, known before the
#: work starts, whatever its files and values make it do.
COMMAND_SECONDS = 120.0
#: Most bits of a Python ``int`` (or the numerator and denominator of a Fraction or an
#: exact Decimal) taken as a value: as :data:`MAX_BITS`, which text is held to.
MAX_INT_BITS = MAX_BITS
