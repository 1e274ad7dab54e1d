"""Values with units for sizing: lengths, masses, accelerations, forces, angles.

A value is text such as ``"100mm"``, ``"500 g"``, ``"0.5g"`` (an acceleration in
standard gravities) or ``"2.5deg"``: an exact expression read by the safe parser
:func:`graspcompass.expr.parse_exact` (never ``eval``) followed by an optional
unit.  Without a unit a value is in SI units (metres, kilograms, m/s², newtons),
except an angle, which needs its unit (``deg`` or ``rad``: a bare ``30`` would be
30 radians, a classic slip).  An unknown unit is refused with
:class:`UnknownUnitError`, a missing angle unit with :class:`MissingUnitError`;
both messages show the value.  Numbers that are not text (int, Fraction, float,
sympy) are taken in SI units through :func:`graspcompass.inputs.real_value`.

Reading the unit (:func:`split_unit`) is plain string work that loads nothing,
so the command line refuses a bad unit before sympy is imported.

Examples
--------
>>> length_value("100mm", "--p1"), mass_value("500 g", "--mass"), mass_value(2, "mass")
(1/10, 1/2, 2)
>>> acceleration_value("0.5g", "--accel"), force_value_si("2kN", "--max-force")
(196133/40000, 2000)
>>> angle_value("90deg", "--tilt"), angle_value("1/2 rad", "--tilt")
(pi/2, 1/2)
>>> try:
...     mass_value("3lb ", "--mass")
... except UnknownUnitError as err:
...     print(err)
--mass: unknown unit 'lb' in '3lb ' (a mass takes kg, g, mg or t, or no unit for kg)
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from ..boundary.errors import InputError

__all__ = [
    "ACCELERATION_UNITS",
    "ANGLE_UNITS",
    "FORCE_UNITS",
    "LENGTH_UNITS",
    "MASS_UNITS",
    "STANDARD_GRAVITY",
    "MissingUnitError",
    "UnitError",
    "UnknownUnitError",
    "acceleration_value",
    "angle_value",
    "force_value_si",
    "length_value",
    "mass_value",
    "split_unit",
]

#: Standard gravity g_n = 9.80665 m/s² (exact, by definition), as ``(numerator, denominator)``.
STANDARD_GRAVITY = (980665, 100000)

#: Each unit's factor to SI as ``(numerator, denominator)`` (exact).
LENGTH_UNITS = {
    "m": (1, 1),
    "cm": (1, 100),
    "mm": (1, 1000),
    "um": (1, 10**6),
    "µm": (1, 10**6),
    "μm": (1, 10**6),
}
MASS_UNITS = {"kg": (1, 1), "g": (1, 1000), "mg": (1, 10**6), "t": (1000, 1)}
ACCELERATION_UNITS = {
    "m/s^2": (1, 1),
    "m/s**2": (1, 1),
    "m/s2": (1, 1),
    "m/s²": (1, 1),
    "g": STANDARD_GRAVITY,
}
FORCE_UNITS = {"N": (1, 1), "kN": (1000, 1), "mN": (1, 1000)}
#: Angles: ``deg`` and ``°`` are degrees, ``rad`` radians; there is no default.
ANGLE_UNITS = {"deg": None, "°": None, "rad": (1, 1)}

#: kind -> (unit -> SI factor p/q, None for degrees; the units it accepts, in words).
_KINDS: dict[str, tuple[Mapping[str, tuple[int, int] | None], str]] = {
    "length": (LENGTH_UNITS, "m, cm, mm or um, or no unit for metres"),
    "mass": (MASS_UNITS, "kg, g, mg or t, or no unit for kg"),
    "acceleration": (ACCELERATION_UNITS, "m/s^2 or g (standard gravities), or no unit for m/s^2"),
    "force": (FORCE_UNITS, "N, kN or mN, or no unit for newtons"),
    "angle": (ANGLE_UNITS, "deg or rad, which an angle needs"),
}
_WORD_START = re.compile(r"[^\W\d]|[°µμ]")
_TRAILING_WORD = re.compile(r"(?:[^\W\d_]|[°µμ])+$")
_NAMES = ("pi",)  # trailing names of the parser that are not units


class UnitError(InputError):
    """A value whose unit is wrong for its quantity, missing where needed, or unknown."""


class UnknownUnitError(UnitError):
    """A unit that the quantity does not take (``"3lb"`` for a mass); the message shows it."""


class MissingUnitError(UnitError):
    """A value without the unit its quantity needs (an angle without ``deg`` or ``rad``)."""


def split_unit(text: str, kind: str, name: str) -> tuple[str, str | None]:
    """``(number text, unit or None)`` of ``text`` for a quantity of ``kind``.

    ``kind`` is ``"length"``, ``"mass"``, ``"acceleration"``, ``"force"`` or
    ``"angle"``.  Only string work: nothing is imported and the number is not
    read (that is :func:`graspcompass.expr.parse_exact`'s job).

    Raises
    ------
    UnknownUnitError
        When the text ends in a word that is not a unit of ``kind`` (nor ``pi``).
    MissingUnitError
        For an angle without ``deg``, ``°`` or ``rad``.

    Examples
    --------
    >>> split_unit("100mm", "length", "x"), split_unit("2*pi", "angle", "t")[1]
    (('100', 'mm'), 'rad')
    """
    units, accepted = _KINDS[kind]
    if not isinstance(text, str):
        raise UnitError(f"{name}: expected text, got {type(text).__name__}")
    body = text.strip()
    for unit in sorted(units, key=len, reverse=True):
        if not body.endswith(unit):
            continue
        head = body[: len(body) - len(unit)]
        core = head.rstrip()
        if not core:
            continue
        if (
            _WORD_START.match(unit[0])
            and head == core
            and (_WORD_START.match(core[-1]) or core[-1] == "_")
        ):
            continue  # the end of a longer word ("10 kg" is kg, "2mg" is mg, not g)
        return core, unit
    word = _TRAILING_WORD.search(body)
    if word and body[: word.start()].rstrip()[-1:] not in ("", "*", "/", "+", "-", "("):
        unit = word.group()
        if unit not in _NAMES:
            raise UnknownUnitError(
                f"{name}: unknown unit {unit!r} in {text!r} (a {kind} takes {accepted})"
            )
    if kind == "angle":
        if "pi" in body:
            return body, "rad"  # pi says radians: "pi/6", "2*pi"
        raise MissingUnitError(
            f"{name}: the angle {text!r} needs a unit, deg or rad (a bare "
            "number would be read as radians)"
        )
    return body, None


def _factor(kind: str, unit: str | None) -> Any:
    import sympy as sp

    if kind == "angle" and unit in ("deg", "°"):
        return sp.pi / 180
    if unit is None:
        return sp.Integer(1)
    ratio = _KINDS[kind][0][unit]
    assert ratio is not None  # only degrees have no ratio, handled above
    return sp.Rational(*ratio)


def _value(value: Any, kind: str, name: str) -> Any:
    """An exact value (text, int, Fraction, sympy) or a float, in SI units."""
    from ..boundary.expr import ExpressionError, parse_exact
    from ..boundary.inputs import real_value

    if not isinstance(value, str):
        return real_value(value, name)  # code's numbers: SI units (angles in radians)
    number, unit = split_unit(value, kind, name)
    try:
        v = parse_exact(number)
    except ExpressionError as exc:
        raise type(exc)(f"{name}: {exc}") from None
    return v * _factor(kind, unit)


def length_value(value: Any, name: str) -> Any:
    """A length in metres: text with an optional unit (m, cm, mm, um) or a number."""
    return _value(value, "length", name)


def mass_value(value: Any, name: str) -> Any:
    """A mass in kilograms: text with an optional unit (kg, g, mg, t) or a number."""
    return _value(value, "mass", name)


def acceleration_value(value: Any, name: str) -> Any:
    """An acceleration in m/s²: text with an optional unit (m/s^2, g) or a number."""
    return _value(value, "acceleration", name)


def force_value_si(value: Any, name: str) -> Any:
    """A force in newtons: text with an optional unit (N, kN, mN) or a number."""
    return _value(value, "force", name)


def angle_value(value: Any, name: str) -> Any:
    """An angle in radians: text needs ``deg``, ``°``, ``rad`` (or ``pi``); numbers are radians."""
    return _value(value, "angle", name)
