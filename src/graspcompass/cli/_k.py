"""The ``graspcompass k`` sub-command: k_n(θ), k_grasp(θ) and F_int for a list of angles.

The angles of ``--theta`` are read in one of two ways, chosen by their number
before any of them is computed:

* at most :data:`EXACT_ANGLES` angles: :func:`graspcompass.expr.parse_angles`
  reads every angle exactly (the θ column shows ``pi/6``); ``--exact`` adds the
  exact values, for at most :data:`EXACT_VALUES` angles (each takes exact
  comparisons of four radicals);
* more, up to :data:`MAX_ANGLES` (the parser's maximum): the ranges are read
  exactly (start, stop and step by :func:`~graspcompass.expr.parse_exact`, with
  the same rules) and their values made in double precision; a note on stderr
  says so, and the rows are written in chunks as they are computed, so a
  million rows stream out instead of piling up.

On the exact path every number printed is the exact value rounded to the
nearest double (:func:`rounded_rows`): ``k_n(θ) = S_n sin θ − C_n cos θ``
(eqs. (18)-(21), (27)) evaluated from the exact S_n, C_n and θ at
:data:`DIGITS` digits, a value that small next to |V_n| settled exactly (an
exact zero prints 0, not ``-4.97e-42``; −3/2 prints −1.5, not
``-1.4999999999999998``).

Every number printed is finite: a grasp or an angle whose values overflow a
double is refused with one line (exit status 2).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable, Iterator
from typing import IO, TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..boundary.errors import InputTooLargeError, NonFiniteValueError
from ..boundary.expr import _split_items, _split_unit, parse_angles, parse_exact
from ..boundary.inputs import force_value
from ..boundary.limits import EXACT_ANGLES, EXACT_VALUES, MAX_ANGLES, MAX_LIST_LENGTH
from ..geometry.numeric import to_float

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["EXACT_ANGLES", "EXACT_VALUES", "MAX_ANGLES", "count_angles", "read_angles", "run"]

#: Longest ``--theta`` text.
MAX_TEXT = MAX_LIST_LENGTH
#: Rows computed and written at a time on the float path.
CHUNK = 20_000
#: Digits of the evaluation the exact path's printed doubles are rounded from.
DIGITS = 60

_JSON_RECORD = (
    ' {"theta": "%r", "theta_deg": %r, "k": [%r, %r, %r, %r], "k_grasp": %r, '
    '"F_int": %r, "limiting": %d}'
)
_HEAD = ["θ", "deg", "k1", "k2", "k3", "k4", "k_grasp", "F_int", "limit"]


def _range(item: str) -> tuple[sp.Expr, sp.Expr, int, bool] | None:
    """``(start, step, count, degrees)`` of a valid range item; None for anything else.

    The checks are those of the parser (real numbers, a positive step, a
    non-empty range), so None means the parser refuses the item, or reads it
    as a single angle.
    """
    if ":" not in item:
        return None
    body, degrees = _split_unit(item)
    parts = body.split(":")
    if len(parts) != 3 or any(_split_unit(part)[1] for part in parts):
        return None
    try:
        start, stop, step = (parse_exact(part) for part in parts)
    except ValueError:
        return None
    if not all(v.is_number and v.is_extended_real for v in (start, stop, step)):
        return None
    if (step > 0) is not sp.true:
        return None
    try:
        estimate = float(stop - start) / float(step)
    except (ArithmeticError, TypeError, ValueError):
        estimate = math.inf
    if not estimate < 2 * MAX_ANGLES:
        return start, step, 2 * MAX_ANGLES, degrees  # too many to count exactly
    count = sp.ceiling((stop - start) / step)
    if not count.is_Integer or count <= 0:
        return None
    return start, step, int(count), degrees


def count_angles(text: str) -> int:
    """How many angles ``text`` gives, without making them.

    An item that is not a valid range counts 1; a range of more than twice
    :data:`MAX_ANGLES` values counts ``2 * MAX_ANGLES``.
    """
    total = 0
    for item in _split_items(text):
        r = _range(item)
        total += 1 if r is None else r[2]
    return total


def read_angles(text: str) -> tuple[list[sp.Expr] | None, np.ndarray]:
    """The angles of ``--theta``: exact values (or None past :data:`EXACT_ANGLES`) and floats.

    Raises
    ------
    graspcompass.expr.ExpressionError
        For text the parser refuses.
    InputTooLargeError
        For more than :data:`MAX_ANGLES` angles (refused before any is made) or
        text longer than :data:`MAX_TEXT`.
    NonFiniteValueError
        For an angle beyond the range of a double.
    """
    if len(text) > MAX_TEXT:
        raise InputTooLargeError(f"--theta is longer than {MAX_TEXT} characters")
    n = count_angles(text)
    if n <= EXACT_ANGLES:
        from ..boundary.inputs import exact_denominators

        exact = [exact_denominators(v, "--theta") for v in parse_angles(text)]
        floats = np.array([_float(v) for v in exact], dtype=float)
    elif n > MAX_ANGLES:
        many = f"{n}" if n < 2 * MAX_ANGLES else f"more than {2 * MAX_ANGLES}"
        raise InputTooLargeError(f"--theta gives {many} angles; at most {MAX_ANGLES} are allowed")
    else:
        exact, floats = None, _float_angles(text)
    bad = np.flatnonzero(~np.isfinite(floats))
    if bad.size:
        raise NonFiniteValueError(
            f"--theta: angle {bad[0] + 1} is too large for double precision (|θ| > 1.8e308)"
        )
    return exact, floats


def _float(value: sp.Expr) -> float:
    try:
        return to_float(value, 17)
    except (OverflowError, TypeError, ValueError):
        return math.inf


def _float_angles(text: str) -> np.ndarray:
    pieces = []
    for item in _split_items(text):
        r = _range(item)
        if r is None:  # a single angle, or an item the parser refuses with its message
            pieces.append(np.array([_float(v) for v in parse_angles(item)], dtype=float))
            continue
        start, step, count, degrees = r
        values = _float(start) + np.arange(count, dtype=float) * _float(step)
        pieces.append(np.radians(values) if degrees else values)
    return np.concatenate(pieces)


def _fe(text: str) -> tuple[sp.Expr, float]:
    fe = force_value(text, "--external-force")  # exact, real, finite, >= 0
    value = _float(fe)
    if not math.isfinite(value):
        raise NonFiniteValueError(f"--external-force {text} is too large for double precision")
    return fe, value


def _values(g: Grasp, t: np.ndarray, fe: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    with np.errstate(all="ignore"):
        ks = np.asarray(g.k(t), dtype=float).reshape(4, -1)
        kg = np.asarray(g.k_grasp(t), dtype=float).reshape(-1)
        fint = np.asarray(g.internal_force(t, fe), dtype=float).reshape(-1)
    for name, arr in (("k_n", ks), ("k_grasp", kg), ("F_int", fint)):
        if not np.all(np.isfinite(arr)):
            raise NonFiniteValueError(
                f"{name} overflows double precision for this grasp and force (a value beyond "
                "1.8e308): give the lengths or the force in other units"
            )
    return ks, kg, fint


def _check_range(g: Grasp, fe: float) -> None:
    """Refuse a grasp whose k_n or F_int could overflow a double at some θ.

    Over all θ, ``|k_n(θ)| <= |V_n| = hypot(S_n, C_n)`` and ``F_int <= max |V_n| · F_e / D``.
    """
    with np.errstate(all="ignore"):
        largest = max(math.hypot(_float(S), _float(C)) for S, C in zip(g.S, g.C))
        bound = largest * fe / _float(g.D) if fe else largest
    if not math.isfinite(bound):
        raise NonFiniteValueError(
            "k_n or F_int overflows double precision for this grasp and "
            "force (a value beyond 1.8e308): give the lengths or the "
            "force in other units"
        )


def _limiting(ks: np.ndarray, kg: np.ndarray) -> np.ndarray:
    return np.where(kg > 0, np.argmax(ks, axis=0) + 1, 0)


def run(
    args: argparse.Namespace, g: Grasp | Callable[[], Grasp], out: IO[str] | None = None
) -> int:
    """Run ``graspcompass k`` for the grasp ``g``; returns the exit status (0).

    Parameters
    ----------
    args : argparse.Namespace
        ``theta``, ``external_force``, ``exact``, ``json`` and ``quiet``.
    g : Grasp or callable
        A numeric grasp, or a function that makes it, called once ``--theta``
        and ``--external-force`` are read (so their errors come first and fast).
    out : file, optional
        Where the rows go (default: stdout).

    Raises
    ------
    ValueError
        For a refused ``--theta`` or ``--external-force`` and values that
        overflow a double (one line each on the command line).
    """
    out = sys.stdout if out is None else out
    fe, fe_float = _fe(args.external_force)
    exact, t = read_angles(args.theta)
    if args.exact and (exact is None or len(exact) > EXACT_VALUES):
        raise InputTooLargeError(
            f"--exact computes exact values for at most {EXACT_VALUES} "
            f"angles; --theta gives {t.size}"
        )
    if callable(g):
        g = g()
    if exact is None:
        _check_range(g, fe_float)  # before the first row: an error is then the only line
        if not getattr(args, "quiet", False):
            print(
                f"graspcompass: note: {t.size} angles: θ read in double precision (exactly "
                f"for at most {EXACT_ANGLES} angles)",
                file=sys.stderr,
            )
        _stream(args, g, t, fe_float, out)
        return 0
    _check_range(g, fe_float)
    records = []
    for th, (deg, ks, kg, fint, lim) in zip(exact, rounded_rows(g, exact, fe)):
        rec: dict[str, Any] = {
            "theta": str(th),
            "theta_deg": deg,
            "k": ks,
            "k_grasp": kg,
            "F_int": fint,
            "limiting": lim,
        }
        if args.exact:
            rec["k_exact"] = [str(v) for v in g.k(th)]
            rec["k_grasp_exact"] = str(g.k_grasp(th))
            rec["F_int_exact"] = str(g.internal_force(th, fe))
        records.append(rec)
    if args.json:
        print(json.dumps(records, indent=1), file=out)
        return 0
    rows = [
        [
            r["theta"],
            f"{r['theta_deg']:.4g}",
            *(f"{v:.6g}" for v in r["k"]),
            f"{r['k_grasp']:.6g}",
            f"{r['F_int']:.6g}",
            f"k{r['limiting']}" if r["limiting"] else "-",
        ]
        for r in records
    ]
    print(table(rows, _HEAD), file=out)
    if args.exact:
        for r in records:
            print(
                f"θ = {r['theta']}: k_grasp = {r['k_grasp_exact']}, F_int = {r['F_int_exact']}",
                file=out,
            )
    return 0


def rounded_rows(
    g: Grasp, thetas: list[sp.Expr], fe: sp.Expr
) -> Iterator[tuple[float, list[float], float, float, int]]:
    """``(θ in degrees, [k1..k4], k_grasp, F_int, limiting n)`` per exact θ, rounded from exact.

    ``k_n(θ) = S_n sin θ − C_n cos θ`` (eqs. (18)-(21)) is evaluated at
    :data:`DIGITS` digits from the exact S_n, C_n (eqs. (28)-(39)) and θ and
    rounded once to a double; a value below ``10**-(DIGITS - 15)·|V_n|``, where
    those digits could be cancellation, is computed exactly and its zero
    decided by :func:`graspcompass.geometry.exact.decide_zero` (an exact zero
    is 0).  Rounding is monotone, so ``k_grasp = max(k1..k4, 0)`` (eq. (25)) is
    the rounded exact maximum; ``F_int = k_grasp·F_e/(x1 + x2)`` (eq. (17)) is
    rounded from the same digits.

    Raises
    ------
    NonFiniteValueError
        For a value beyond the largest double.
    """
    import mpmath

    from ..geometry.exact import canon, decide_zero

    with mpmath.workdps(DIGITS + 10):

        def mp(value: Any) -> Any:
            return mpmath.mpf(sp.N(value, DIGITS + 10))

        S, C = [mp(v) for v in g.S], [mp(v) for v in g.C]
        norm = [abs(a) + abs(b) for a, b in zip(S, C)]
        scale, tiny = mp(fe / g.D), mpmath.mpf(10) ** (15 - DIGITS)
        for th in thetas:
            t = mp(th)
            s, c = mpmath.sin(t), mpmath.cos(t)
            ks = [S[n] * s - C[n] * c for n in range(4)]
            exact_ks: list[Any] = [None] * 4
            for n in range(4):
                if abs(ks[n]) <= tiny * norm[n]:
                    exact_ks[n] = canon(g.S[n] * sp.sin(th) - g.C[n] * sp.cos(th))
                    ks[n] = mpmath.mpf(0) if decide_zero(exact_ks[n]) else mp(exact_ks[n])
            best = max(range(4), key=lambda n: ks[n])
            top = ks[best] if ks[best] > 0 else mpmath.mpf(0)
            values = [_double(v) for v in (*ks, top, top * scale, t * 180 / mpmath.pi)]
            yield values[6], values[:4], values[4], values[5], best + 1 if top > 0 else 0


def _double(value: Any) -> float:
    """The double nearest ``value`` (an mpmath number), refused beyond the largest one."""
    out = float(value)
    if not math.isfinite(out):
        raise NonFiniteValueError(
            "a value of k_n, k_grasp, F_int or θ in degrees is beyond "
            "double precision (1.8e308): give the lengths, the force "
            "or the angles in other units"
        )
    return out + 0.0  # -0.0 prints as 0


def table(rows: list[list[str]], head: list[str]) -> str:
    """Rows under a head, columns padded to their widest cell (the last is not padded).

    Parameters
    ----------
    rows : list of list of str
        The cells, row by row.
    head : list of str
        The column names.
    """
    widths = [max(3, *(len(r[i]) for r in [head, *rows])) for i in range(len(head))]
    widths[-1] = max(3, len(head[-1]))
    fmt = "  ".join(f"{{:<{w}}}" for w in widths[:-1]) + "  {}"
    lines = [fmt.format(*head).rstrip(), fmt.format(*("-" * w for w in widths)).rstrip()]
    lines += [fmt.format(*r).rstrip() for r in rows]
    return "\n".join(lines)


def _chunks(g: Grasp, t: np.ndarray, fe: float) -> Iterator[tuple[np.ndarray, ...]]:
    for lo in range(0, t.size, CHUNK):
        tc = t[lo : lo + CHUNK]
        ks, kg, fint = _values(g, tc, fe)
        yield tc, ks, kg, fint, _limiting(ks, kg)


def _stream(args: argparse.Namespace, g: Grasp, t: np.ndarray, fe: float, out: IO[str]) -> None:
    """Write the rows of the float path chunk by chunk (a table of fixed widths, or JSON)."""
    if args.json:
        out.write("[")
        sep = "\n"
        for tc, ks, kg, fint, lim in _chunks(g, t, fe):
            records = [
                _JSON_RECORD % cells
                for cells in zip(
                    tc.tolist(),
                    np.degrees(tc).tolist(),
                    *ks.tolist(),
                    kg.tolist(),
                    fint.tolist(),
                    lim.tolist(),
                )
            ]
            out.write(sep + ",\n".join(records))
            out.flush()
            sep = ",\n"
        out.write("\n]\n")
        return
    widths = [12, 8, 11, 11, 11, 11, 11, 11]
    fmt = "  ".join(f"{{:<{w}}}" for w in widths) + "  {}"
    out.write(fmt.format(*_HEAD).rstrip() + "\n")
    out.write(fmt.format(*("-" * w for w in [*widths, 5])).rstrip() + "\n")
    row = "  ".join(["%-12.9g", "%-8.4g", *["%-11.6g"] * 6]) + "  %s\n"
    for tc, ks, kg, fint, lim in _chunks(g, t, fe):
        names = [f"k{n}" if n else "-" for n in lim.tolist()]
        out.write(
            "".join(
                [
                    row % cells
                    for cells in zip(
                        tc.tolist(),
                        np.degrees(tc).tolist(),
                        *ks.tolist(),
                        kg.tolist(),
                        fint.tolist(),
                        names,
                    )
                ]
            )
        )
        out.flush()
