"""GeoGebra definitions of the kernel operations: commands on sliders, not coordinates.

Each construction step becomes a GeoGebra ``<command>`` (internal English
command names, as in ``geogebra.xml``: ``OrthogonalLine`` is the user's
``PerpendicularLine``, ``Mirror`` is ``Reflect``, ``CurveCartesian`` is
``Curve``) or a dependent ``<expression>`` in the sliders and the earlier
objects.  Nested commands use square brackets, which every GeoGebra version
since 3 reads.

The given data are the seven sliders ``x_1, x_2, y_P, φ_1, φ_2, μ_1, μ_2``
(radians for φ); ``P1 = (x_1, y_P)`` and ``P2 = (-x_2, y_P)``.  GeoGebra drags a
point whose coordinates are free numbers by moving those numbers, so dragging
P1 moves the sliders x_1 and y_P and the whole construction follows; P2
follows the sliders x_2 and y_P.  The cone sides are lines through P_i along
``(∓sin(φ ± ξ), −cos(φ ± ξ)) / cos ξ`` written with μ = tan ξ, as
:meth:`graspcompass.Grasp.side_direction`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import sympy as sp

__all__ = ["SLIDERS", "Definition", "definition", "envelope_functions", "ggb_label", "ggb_number"]

#: Slider label in GeoGebra, parameter of :class:`graspcompass.Grasp`, caption.
SLIDERS = (
    ("x_1", "x1", "x1: P1 = (x1, y), §2.2.1"),
    ("x_2", "x2", "x2: P2 = (−x2, y), §2.2.1"),
    ("y_P", "y", "y: height of the contacts, §2.2.1"),
    ("φ_1", "phi1", "φ1 (rad): normal at P1, clockwise from −y"),
    ("φ_2", "phi2", "φ2 (rad): normal at P2, counter-clockwise from −y"),
    ("μ_1", "mu1", "μ1 = tan ξ1: friction at P1, eq. (22)"),
    ("μ_2", "mu2", "μ2 = tan ξ2: friction at P2, eq. (22)"),
)

if TYPE_CHECKING:
    from ..construction.protocol import Step

_LABELS = {"x-axis": "axisX", "y-axis": "axisY", "envelope": "kGrasp"}

_SIDE = {  # (x, y) of side n's direction, in the sliders
    1: "(-(sin(φ_1) + cos(φ_1) * μ_1), -(cos(φ_1) - sin(φ_1) * μ_1))",
    3: "(-(sin(φ_1) - cos(φ_1) * μ_1), -(cos(φ_1) + sin(φ_1) * μ_1))",
    2: "(sin(φ_2) + cos(φ_2) * μ_2, -(cos(φ_2) - sin(φ_2) * μ_2))",
    4: "(sin(φ_2) - cos(φ_2) * μ_2, -(cos(φ_2) + sin(φ_2) * μ_2))",
}


@dataclass(frozen=True)
class Definition:
    """How GeoGebra makes one object.

    ``command`` is a command name with ``inputs`` (GeoGebra text), or None for
    an ``<expression>`` ``exp``; ``element`` is the GeoGebra element type.
    """

    element: str
    command: str | None = None
    inputs: tuple[str, ...] = ()
    exp: str = ""
    var: str | None = None


def ggb_label(name: str) -> str:
    """A valid GeoGebra label for a step name (``x-axis`` -> ``axisX``)."""
    return _LABELS.get(name, name)


def ggb_number(value: Any) -> str:
    """GeoGebra text of an exact or float number (``sqrt(3)/2``, ``pi``, ``0.5``)."""
    v = sp.sympify(value)
    if isinstance(v, sp.Float):
        return repr(float(v))
    if v.free_symbols:
        raise ValueError(f"cannot write the symbolic value {v} to GeoGebra: substitute numbers")
    return f"({str(v).replace('**', '^')})" if not v.is_Atom else str(v)


def _pair(a: Any, b: Any) -> str:
    return f"({ggb_number(a)}, {ggb_number(b)})"


def _signed_length(inputs: tuple[str, ...], steps: dict[str, Any]) -> str:
    a, b, axis = (ggb_label(n) for n in inputs[:3])
    d = steps[inputs[2]].params if steps[inputs[2]].op == "line_with_direction" else ()
    if tuple(map(sp.sympify, d)) == (1, 0):
        return f"x({b}) - x({a})"
    if tuple(map(sp.sympify, d)) == (0, 1):
        return f"y({b}) - y({a})"
    return f"Vector[{a}, {b}] * UnitVector[{axis}]"


def envelope_functions(step: Step, steps: dict[str, Any]) -> list[tuple[str, str, str]]:
    """The envelope's k_grasp(θ) (eq. (25)) as short named functions of ``t``, one line
    each: ``k_n(t) = x(V_n) sin(t) - y(V_n) cos(t)`` for the circle on each diameter O V_n
    (eq. (32)), the larger of two (``m_i``, max written with abs: every version has it),
    and ``kg(t)``, the largest and 0.  ``(label, definition, caption)`` in order."""
    vs = [
        ggb_label(steps[c].inputs[1])
        for c in step.inputs
        if c in steps and steps[c].op == "circle_on_diameter"
    ] or [f"V{n}" for n in (1, 2, 3, 4)]
    out = []
    level = []
    for i, v in enumerate(vs, start=1):
        out.append(
            (
                f"k_{i}",
                f"x({v}) sin(t) - y({v}) cos(t)",
                f"k{i}(θ) = V{i} · e(θ): the polar graph is the circle on O{v}, eq. (32)",
            )
        )
        level.append(f"k_{i}")
    m = 1
    while len(level) > 1:
        nxt = []
        for a, b in zip(level[::2], level[1::2]):
            out.append(
                (
                    f"m_{m}",
                    f"({a}(t) + {b}(t) + abs({a}(t) - {b}(t))) / 2",
                    f"the larger of {a} and {b}",
                )
            )
            nxt.append(f"m_{m}")
            m += 1
        level = nxt + level[len(level) - len(level) % 2 :]
    top = level[0]
    out.append(
        ("kg", f"({top}(t) + abs({top}(t))) / 2", "k_grasp(θ) = max(k1, ..., k4, 0), eq. (25)")
    )
    return out


def definition(step: Step, steps: dict[str, Any], with_grasp: bool) -> Definition:
    """The GeoGebra definition of ``step`` (``steps``: name -> Step, for the inputs).

    Raises
    ------
    ValueError
        For an operation GeoGebra cannot replay here.
    """
    ins = tuple(ggb_label(n) for n in step.inputs)
    op, name = step.op, step.name
    role, n = getattr(step, "role", ""), (getattr(step, "n", ()) or (0,))[0]
    if op == "point":
        if with_grasp and role == "contact" and n in (1, 2):  # the contacts, by role
            return Definition("point", exp="(x_1, y_P)" if n == 1 else "(-x_2, y_P)")
        if with_grasp and all(sp.sympify(p) == 0 for p in step.params):
            return Definition("point", "Intersect", ("xAxis", "yAxis"))
        return Definition("point", exp=_pair(*step.params))
    if op == "line_with_direction":
        if with_grasp and role == "cone_side" and n in _SIDE:  # the cone sides, by role
            return Definition("line", "Line", (ins[0], f"{ins[0]} + {_SIDE[n]}"))
        return Definition("line", "Line", (ins[0], f"{ins[0]} + {_pair(*step.params)}"))
    simple = {
        "line_through": ("line", "Line", ins),
        "meet": ("point", "Intersect", ins),
        "foot": ("point", "ClosestPoint", (ins[1], ins[0]) if len(ins) == 2 else ins),
        "perpendicular": ("line", "OrthogonalLine", ins[::-1]),
        "midpoint": ("point", "Midpoint", ins),
        "circle_on_diameter": ("conic", "Circle", (f"Midpoint[{', '.join(ins)}]", ins[0])),
    }
    if op in simple:
        kind, cmd, args = simple[op]
        return Definition(kind, cmd, tuple(args))
    if op == "signed_length":
        return Definition("numeric", exp=_signed_length(step.inputs, steps))
    if op == "point_from_lengths":
        sx, sy = (ggb_number(p) for p in step.params[:2])
        return Definition("point", exp=f"({sx} * {ins[0]}, {sy} * {ins[1]})")
    if op == "second_intersection":
        c1, c2, known = ins
        return Definition("point", "Mirror", (known, f"Line[Center[{c1}], Center[{c2}]]"))
    # issue 25: the n-contact vertex recipe (docs/ncontact.md)
    if op == "parallel":  # GeoGebra's Line[point, line] is the parallel through the point
        return Definition("line", "Line", (ins[1], ins[0]))
    if op == "parallel_to_points":
        return Definition("line", "Line", (ins[2], f"Vector[{ins[0]}, {ins[1]}]"))
    if op == "quarter_turn":
        return Definition("point", "Rotate", (ins[0], "-90°", ins[1]))
    if op == "envelope":  # the polar graph of kg(t), envelope_functions
        return Definition(
            "curvecartesian",
            "CurveCartesian",
            ("kg(t) sin(t)", "-kg(t) cos(t)", "t", "0", "2 pi"),
            var="t",
        )
    made = _class_definition(step, steps, ins)
    if made is not None:
        return made
    raise ValueError(f"no GeoGebra definition for the operation {op!r} of step {name!r}")


def _left_of(a: str, b: str, p: str) -> str:
    """GeoGebra text: the point p lies left of the directed line from a to b."""
    return f"(x({b}) - x({a})) (y({p}) - y({a})) - (y({b}) - y({a})) (x({p}) - x({a})) > 0"


def _branch(first: str, second: str, test: str) -> Definition:
    """The kernel's branch among GeoGebra's two intersections: ``first`` if ``test`` (in
    the point ``_P_``), else ``second``."""
    return Definition("point", "If", (test.replace("_P_", first), first, second))


def _class_definition(step: Step, steps: dict[str, Any], ins: tuple[str, ...]) -> Definition | None:
    """The operations of a geometry class (issue 24) and the intersections, branch by
    branch as the kernel takes them (``If`` between GeoGebra's two intersection points)."""
    op = step.op
    params = tuple(step.params)
    simple = {
        "parallel": ("line", "Line", (ins[1], ins[0]) if len(ins) == 2 else ins),
        "reflect": ("point", "Mirror", ins),
        "circle_through": ("conic", "Circle", ins),
        "circumcircle": ("conic", "Circle", ins),
        "circle_compass": (
            "conic",
            "Circle",
            (ins[0], f"Segment[{ins[1]}, {ins[2]}]") if len(ins) == 3 else ins,
        ),
        "bisector": ("line", "AngularBisector", ins),
        "tangent_at": (
            "line",
            "OrthogonalLine",
            (ins[1], f"Line[Center[{ins[0]}], {ins[1]}]") if len(ins) == 2 else ins,
        ),
        "point_reflect": ("point", "Mirror", ins),
        "point_on_line": ("point", "Point", ins[:1]),
        "point_on_circle": ("point", "Point", ins[:1]),
    }
    if op in simple:
        kind, cmd, args = simple[op]
        return Definition(kind, cmd, tuple(args))
    if op == "circle_radius":
        return Definition("conic", "Circle", (ins[0], ggb_number(params[0])))
    if op == "rotate":
        return Definition("point", "Rotate", (ins[0], ggb_number(params[0]), ins[1]))
    if op == "homothety":
        return Definition("point", "Dilate", (ins[0], ggb_number(params[0]), ins[1]))
    if op == "radical_axis":  # (C1 − C2)·X = −(power difference)/2: the kernel's scale,
        c1, c2 = (f"Center[{c}]" for c in ins)  # so a point on it keeps its parameter
        return Definition(
            "line",
            exp=(
                f"(x({c1}) - x({c2})) x + (y({c1}) - y({c2})) y = -(Radius[{ins[0]}]^2 - "
                f"Radius[{ins[1]}]^2 + x({c2})^2 + y({c2})^2 - x({c1})^2 - y({c1})^2) / 2"
            ),
        )
    k = int(params[0]) if params else 0
    if op == "intersect_circles":
        one, two = (f"Intersect[{ins[0]}, {ins[1]}, {i}]" for i in (1, 2))
        first, second = (one, two) if k == 0 else (two, one)
        test = _left_of(f"Center[{ins[0]}]", f"Center[{ins[1]}]", "_P_")
        return _branch(first, second, test if k == 0 else test.replace("> 0", "< 0"))
    if op == "tangent_point":
        polar = f"Polar[{ins[0]}, {ins[1]}]"
        one, two = (f"Intersect[{polar}, {ins[1]}, {i}]" for i in (1, 2))
        test = _left_of(f"Center[{ins[1]}]", ins[0], "_P_")
        return _branch(one, two, test if k == 0 else test.replace("> 0", "< 0"))
    if op == "intersect_line_circle":
        # branch 0 lies further along the line's direction (the kernel's, at export)
        line = steps[step.inputs[0]].obj
        dx, dy = (ggb_number(sp.sympify(v).evalf(17)) for v in (line.direction.x, line.direction.y))
        one, two = (f"Intersect[{ins[0]}, {ins[1]}, {i}]" for i in (1, 2))
        sign = ">" if k == 0 else "<"
        test = f"(x({one}) - x({two})) ({dx}) + (y({one}) - y({two})) ({dy}) {sign} 0"
        return Definition("point", "If", (test, one, two))
    return None
