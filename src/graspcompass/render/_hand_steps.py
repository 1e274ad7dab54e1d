"""The steps of a worksheet and its numbered instructions in words (§3.3).

Which protocol steps a worksheet covers (every step, or those that draw one V_n,
eqs. (30)-(33)), which of them page 1 already shows, and the instructions for the
rest, numbered as ``graspcompass steps`` numbers the protocol and ending with the
paper's reference.  Text only: no drawing here.  Private to
:mod:`graspcompass.render.handdrawing`, which re-exports these names.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..scene.layout import numeric_objects

if TYPE_CHECKING:
    from ..construction.protocol import Construction, Step

#: Values of ``steps``: every step, or the steps of one V_n.
STEP_CHOICES = ("all", "V1", "V2", "V3", "V4")
#: Values of ``given``, each including the ones before it: what is drawn on page 1.
GIVEN_LEVELS = ("grasp", "feet", "sides", "perpendiculars")
_WORD = {1: "upper", 2: "upper", 3: "lower", 4: "lower"}
_COMMON = ("O", "x-axis", "y-axis", "P1", "P2", "P1x", "P2x", "O_M")
_GREEK = {"phi": "φ", "mu": "μ", "xi": "ξ"}


@dataclass(frozen=True)
class Instruction:
    """One numbered instruction of the worksheet.

    Attributes
    ----------
    steps : tuple of int
        Protocol indices (as ``graspcompass steps`` prints them) the instruction makes.
    names : tuple of str
        Names of the objects made (``"X1"``).
    text : str
        The instruction in words, mathtext allowed (``$X_1$``), ending with the
        paper's reference in brackets.
    """

    steps: tuple[int, ...]
    names: tuple[str, ...]
    text: str

    @property
    def number(self) -> str:
        """The label printed before the text: ``"12"`` or ``"40–45"``."""
        a, b = self.steps[0], self.steps[-1]
        return str(a) if a == b else f"{a}–{b}"


def _n_of(name: str) -> int | None:
    m = re.fullmatch(r"(?:side|X|perp|Y|OMX|OY|V|circle)([1-4])", name)
    return int(m.group(1)) if m else None


def selected_names(construction: Construction, steps: str = "all") -> tuple[str, ...]:
    """Names of the protocol steps of a worksheet for ``steps``, in protocol order.

    ``"all"`` is every step; ``"Vn"`` the steps that draw V_n (§3.3): the axes,
    the contacts, the cone side n, P1x, P2x, O_M, X_n, the perpendicular, Y_n,
    the two signed lengths, V_n and the circle on O V_n (eq. (31)-(32)).

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> selected_names(internal_force_diagram(), "V2")[5:]
    ('side2', 'P1x', 'P2x', 'O_M', 'X2', 'perp2', 'Y2', 'OMX2', 'OY2', 'V2', 'circle2')
    """
    if steps not in STEP_CHOICES:
        raise ValueError(f"steps must be one of {', '.join(STEP_CHOICES)}, got {steps!r}")
    if steps == "all":
        return tuple(construction.names)
    want = int(steps[1])
    keep = []
    for s in construction.steps:
        n = _n_of(s.name)
        if n == want or (n is None and s.name in _COMMON):
            keep.append(s.name)
    return tuple(keep)


def given_names(selected: Sequence[str], given: str | Iterable[str] = "grasp") -> tuple[str, ...]:
    """Names of the objects drawn on page 1 (always O, the axes, P1 and P2).

    ``given`` is a level of :data:`GIVEN_LEVELS` (``"grasp"``: O, the axes,
    P1, P2 and the friction cones; ``"feet"``: also P1x, P2x, O_M; ``"sides"``:
    also the extended cone sides and X_n; ``"perpendiculars"``: also the
    perpendiculars and Y_n) or names of protocol steps (a list, or one string
    with commas), added to the grasp.

    Raises
    ------
    ValueError
        For an unknown level or a name that is not a step of the worksheet.

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> sel = selected_names(internal_force_diagram(), "V1")
    >>> given_names(sel, "sides")
    ('O', 'x-axis', 'y-axis', 'P1', 'P2', 'side1', 'P1x', 'P2x', 'O_M', 'X1')
    >>> given_names(sel, "P1x, P2x")
    ('O', 'x-axis', 'y-axis', 'P1', 'P2', 'P1x', 'P2x')
    """
    base = {"O", "x-axis", "y-axis", "P1", "P2"}
    if isinstance(given, str) and given.strip() in GIVEN_LEVELS:
        level = GIVEN_LEVELS.index(given.strip())
        want = set(base)
        if level >= 1:
            want |= {"P1x", "P2x", "O_M"}
        if level >= 2:
            want |= {s for s in selected if re.fullmatch(r"(side|X)[1-4]", s)}
        if level >= 3:
            want |= {s for s in selected if re.fullmatch(r"(perp|Y)[1-4]", s)}
    else:
        items = given.split(",") if isinstance(given, str) else list(given)
        names = [str(x).strip() for x in items if str(x).strip()]
        if not names:
            raise ValueError(
                f"given: expected one of {', '.join(GIVEN_LEVELS)} or names of "
                "steps separated by commas"
            )
        bad = [x for x in names if x not in selected]
        if bad:
            raise ValueError(
                f"given: {bad[0]!r} is not a step of this worksheet; use one of "
                f"{', '.join(GIVEN_LEVELS)} or names among {', '.join(selected[5:])}"
            )
        want = base | set(names)
    return tuple(s for s in selected if s in want)


def _m(name: str) -> str:
    """Mathtext of a point name: ``P1x`` -> ``$P_{1x}$``."""
    special = {"O_M": "O_M", "P1x": "P_{1x}", "P2x": "P_{2x}"}
    if name in special:
        return f"${special[name]}$"
    m = re.fullmatch(r"([A-Z])(\d+)", name)
    return f"${m.group(1)}_{{{m.group(2)}}}$" if m else name


def _side_parts(n: int) -> tuple[int, str, str]:
    """(contact i, foot of the perpendicular, word) of cone side n (§3.3)."""
    i = 1 if n in (1, 3) else 2
    return i, ("P2x" if i == 1 else "P1x"), _WORD[n]


def _text(step: Step, num: dict[str, Any]) -> str:
    """One step of the protocol in words, for a person with ruler and compass (§3.3)."""
    name, n = step.name, _n_of(step.name)
    if name in ("P1x", "P2x"):
        p = _m(name[:2])
        return (
            f"Drop the perpendicular from {p} to the x-axis (set square, or an arc about "
            f"{p} cutting the x-axis twice, then bisect): its foot is {_m(name)}."
        )
    if name == "O_M":
        same = (
            "  Here $x_1 = x_2$, so $O_M$ is $O$."
            if abs(num["O_M"][0]) <= 1e-12 * max(1.0, abs(num["P1"][0]))
            else ""
        )
        return (
            "Bisect $P_{1x}P_{2x}$ with the compass (equal arcs about both ends, join "
            "their two crossings): the midpoint is $O_M$." + same
        )
    if name == "envelope":
        return (
            "Outside extraction: in every direction from $O$ trace the outermost arc of the "
            "circles (where every circle lies behind $O$, the outline passes through $O$): "
            "$k_{grasp}(\\theta)$, eq. (25), Fig. 5."
        )
    if n is None:
        return step.caption + "."
    i, foot, word = _side_parts(n)
    P, X, Y, V, F = (_m(f"P{i}"), _m(f"X{n}"), _m(f"Y{n}"), _m(f"V{n}"), _m(foot))
    omx, oy = f"$\\overline{{O_MX_{n}}}$", f"$\\overline{{OY_{n}}}$"
    kind = re.sub(r"[1-4]$", "", name)
    return {
        "side": (
            f"Lay the ruler along the {word} side of the friction cone at {P} and extend "
            "it across the sheet, well past the x-axis."
        ),
        "X": f"Mark where the extended {word} side of the cone at {P} meets the x-axis: {X}.",
        "perp": (
            f"Draw the perpendicular from {F} to the line {P}{X} (the {word} side at {P}), "
            "long enough to cross the y-axis."
        ),
        "Y": f"Mark where this perpendicular meets the y-axis: {Y}.",
        "OMX": (
            f"Open the compass from $O_M$ to {X}: the signed length {omx}, + if {X} lies "
            f"right of $O_M$, − if left (it is $-S_{n}$)."
        ),
        "OY": (
            f"Open the compass from $O$ to {Y}: the signed length {oy}, + if {Y} lies above "
            f"$O$, − if below (it is $-C_{n}$)."
        ),
        "V": (
            f"Transfer to $O$ (not $O_M$): mark the x-axis at the distance $O_MX_{n}$ from $O$ "
            f"on the side opposite to the direction $O_M \\to X_{n}$, and mark {Y} mirrored "
            f"through $O$ on the y-axis; the perpendiculars to the axes there meet at "
            f"{V} = $(-\\overline{{O_MX_{n}}}, -\\overline{{OY_{n}}})$."
        ),
        "circle": (
            f"Bisect $OV_{n}$ for the centre and draw the circle through $O$ and {V}: "
            f"the polar graph of $k_{n}(\\theta)$ (Thales, Fig. 3)."
        ),
    }.get(kind, step.caption + ".")


def _ref_bits(ref: str) -> list[str]:
    return re.findall(r"Fig\. \d\(\w\)|eq\. \S+", ref)


def _brief_block(c: Construction, n: int, todo: list[Any], first: int) -> Instruction:
    """The steps of V_n (n after the first) as one instruction, each step numbered."""
    i, foot, word = _side_parts(n)
    P, X, Y, V, F = (_m(f"P{i}"), _m(f"X{n}"), _m(f"Y{n}"), _m(f"V{n}"), _m(foot))
    parts = {
        "X": f"mark {X} where the {word} side at {P} meets the x-axis;",
        "perp": f"draw the perpendicular from {F} to the line {P}{X},",
        "Y": f"it meets the y-axis at {Y};",
        "OMX": f"measure $\\overline{{O_MX_{n}}}$",
        "OY": f"and $\\overline{{OY_{n}}}$ with their signs;",
        "V": f"lay them off from $O$: {V} = $(-\\overline{{O_MX_{n}}}, -\\overline{{OY_{n}}})$.",
    }
    words = [f"{V}, as {_m(f'V{first}')}:"]
    for s in todo:
        words.append(f"#{s.index} {parts[re.sub(r'[1-4]$', '', s.name)]}")
    refs = _ref_bits(c.step(f"X{n}").ref) + _ref_bits(c.step(f"V{n}").ref)
    text = " ".join(words) + f" [§3.3 V{n} steps (1)-(3), {', '.join(refs)}]"
    return Instruction(tuple(s.index for s in todo), tuple(s.name for s in todo), text)


def instructions_for(
    construction: Construction,
    names: Sequence[str],
    given: Sequence[str] = (),
    num: dict[str, Any] | None = None,
) -> list[Instruction]:
    """The numbered instructions for the steps ``names`` not in ``given``, in protocol order.

    Each carries the protocol indices of its steps (as ``graspcompass steps``
    prints them) and ends with the paper's reference from the steps.  With one
    V_n, every step is an instruction.  With more, the first V_n is explained
    step by step and each further V_n is one instruction numbering its steps
    (``#18``, printed bold), and the cone sides, the feet, the circles and the
    second intersections are grouped.  ``num`` are the numeric objects
    (:func:`graspcompass.layout.numeric_objects`) if the caller has them.

    Examples
    --------
    >>> from graspcompass import internal_force_diagram
    >>> c = internal_force_diagram()
    >>> ins = instructions_for(c, selected_names(c, "V1"), ("O", "x-axis", "y-axis", "P1", "P2"))
    >>> [(i.number, i.names[0]) for i in ins][4:7]
    [('12', 'X1'), ('13', 'perp1'), ('14', 'Y1')]
    >>> print(ins[4].text)  # doctest: +NORMALIZE_WHITESPACE
    Mark where the extended upper side of the cone at $P_{1}$ meets the x-axis: $X_{1}$.
    [§3.3 V1 step (1), Fig. 4(a)]
    >>> [i.number for i in instructions_for(c, c.names, ("O", "x-axis", "y-axis", "P1", "P2"))]
    ... # doctest: +NORMALIZE_WHITESPACE
    ['5–8', '9–10', '11', '12', '13', '14', '15', '16', '17', '18–23', '24–29', '30–35',
     '36–39', '40–45', '46']
    """
    if num is None:  # the caller's, when it has them (computed once per worksheet)
        num = numeric_objects(construction)
    skip = set(given)
    todo = sorted((construction.step(n) for n in names if n not in skip), key=lambda s: s.index)
    ns = sorted(
        {n for s in todo if (n := _n_of(s.name)) and not s.name.startswith(("side", "circle"))}
    )
    compact = len({_n_of(n) for n in names if _n_of(n)}) > 1
    first = ns[0] if ns else None
    out: list[Instruction] = []
    done: set[str] = set()

    def group(kind: str) -> list[Any]:
        return [s for s in todo if re.fullmatch(kind, s.name)]

    for s in todo:
        if s.name in done:
            continue
        n = _n_of(s.name)
        members: list[Any] = []
        if compact and s.name.startswith("side"):
            members = group(r"side[1-4]")
            listed = "; ".join(
                f"#{m.index} the {_WORD[_n_of(m.name) or 1]} side at "
                f"{_m('P' + str(_side_parts(_n_of(m.name) or 1)[0]))}"
                for m in members
            )
            text = (
                f"Extend the sides of the friction cones across the sheet with the ruler: "
                f"{listed}. [{s.ref}]"
            )
        elif compact and s.name in ("P1x", "P2x"):
            members = group(r"P[12]x")
            text = (
                "Drop the perpendiculars from "
                + " and ".join(f"#{m.index} {_m(m.name[:2])}" for m in members)
                + " to the x-axis: their "
                "feet are $P_{1x}$, $P_{2x}$. [§3.3]"
            )
        elif compact and n is not None and n != first and not s.name.startswith(("side", "circle")):
            members = [
                m for m in todo if _n_of(m.name) == n and not m.name.startswith(("side", "circle"))
            ]
            ins = _brief_block(construction, n, members, first or 1)
            out.append(ins)
            done.update(ins.names)
            continue
        elif compact and s.name.startswith("circle"):
            members = group(r"circle[1-4]")
            m0 = _n_of(members[0].name)
            more = ", ".join(f"#{m.index} $OV_{_n_of(m.name)}$" for m in members[1:])
            text = (
                f"#{members[0].index} Bisect $OV_{m0}$ for the centre and draw the circle "
                f"through $O$ and $V_{m0}$: the polar graph of $k_{m0}(\\theta)$ (Thales, "
                f"Fig. 3)" + (f"; likewise the circles on {more}." if more else ".") + f" [{s.ref}]"
            )
        elif s.op == "second_intersection":
            members = group(r"B\d\d")
            listed = ", ".join(f"#{b.index} $B_{{{b.name[1:]}}}$" for b in members)
            text = f"Mark where two circles cross besides $O$: {listed}. [{s.ref}]"
        if members:
            out.append(
                Instruction(tuple(m.index for m in members), tuple(m.name for m in members), text)
            )
            done.update(m.name for m in members)
            continue
        out.append(Instruction((s.index,), (s.name,), f"{_text(s, num)} [{s.ref}]"))
    return out


Instruction.__module__ = "graspcompass.render.handdrawing"  # documented and pickled there
