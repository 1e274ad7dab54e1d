"""The paper's drawing recipe (§3.3, §3.2) replayed with the exact kernel.

:func:`internal_force_diagram` replays the shipped file of the construction
language, ``recipes/paper.gc`` (:func:`~graspcompass.construction.language.paper_program`,
printed by ``graspcompass recipe``): what the file says is what is drawn.  It
never uses the closed form (27)-(39): the points V_n come out of
ruler-and-compass steps on the friction cones, and the proof checker compares
them with the closed form afterwards.

:func:`diagram_specs` states the same steps from Python (the JSON reader
rebuilds a document's construction from them, step by step, and the tests check
that both give the same protocol, names, order and exact objects).
"""

from __future__ import annotations

from itertools import combinations
from typing import Any

from ..geometry import GeometryError
from ..grasp import Grasp
from .envelope import outer_envelope
from .protocol import Construction, Step, StepSpec, run_step

__all__ = ["diagram_specs", "internal_force_diagram"]

_SIDE_WORD = {1: "upper", 2: "upper", 3: "lower", 4: "lower"}
# O_M X_n = −S_n (§3.3 step (1)) and O Y_n = −C_n (step (2)): one equation each
_S_EQ = {1: "(28)", 2: "(34)", 3: "(36)", 4: "(38)"}
_C_EQ = {1: "(29)", 2: "(35)", 3: "(37)", 4: "(39)"}


def diagram_specs(grasp: Grasp) -> list[StepSpec]:
    """The step declarations of the diagram of ``grasp`` (without the envelope).

    The same steps as the shipped ``recipes/paper.gc``, which
    :func:`internal_force_diagram` replays.
    """
    S = StepSpec
    specs = [
        S(
            "O",
            "point",
            (),
            "mark",
            "Origin O at the object's centre of mass",
            "§2.2.1",
            (0, 0),
            role="given",
        ),
        S(
            "x-axis",
            "line_with_direction",
            ("O",),
            "ruler",
            "The x-axis, parallel to the line through the contacts",
            "§2.2.1",
            (1, 0),
            role="axis",
            n=(1,),
        ),
        S(
            "y-axis",
            "line_with_direction",
            ("O",),
            "ruler",
            "The y-axis, perpendicular to the line through the contacts",
            "§2.2.1",
            (0, 1),
            role="axis",
            n=(2,),
        ),
        S(
            "P1",
            "point",
            (),
            "mark",
            "Contact point P1 = (x1, y)",
            "§2.2.1",
            (grasp.x1, grasp.y),
            role="contact",
            n=(1,),
        ),
        S(
            "P2",
            "point",
            (),
            "mark",
            "Contact point P2 = (−x2, y)",
            "§2.2.1",
            (-grasp.x2, grasp.y),
            role="contact",
            n=(2,),
        ),
    ]
    for n in (1, 3, 2, 4):
        i = 1 if n in (1, 3) else 2
        d = grasp.side_direction(n)
        sign = "+" if n in (1, 2) else "−"
        specs.append(
            S(
                f"side{n}",
                "line_with_direction",
                (f"P{i}",),
                "ruler",
                f"The {_SIDE_WORD[n]} side of the friction cone at P{i} (angle φ{i} {sign} ξ{i})",
                "§2.2.2, Fig. 2",
                (d.x, d.y),
                role="cone_side",
                n=(n,),
            )
        )
    specs += [
        S(
            "P1x",
            "foot",
            ("P1", "x-axis"),
            "perpendicular",
            "Drop a perpendicular from P1 to the x-axis: its foot P1x",
            "§3.3",
            role="foot",
            n=(1,),
        ),
        S(
            "P2x",
            "foot",
            ("P2", "x-axis"),
            "perpendicular",
            "Drop a perpendicular from P2 to the x-axis: its foot P2x",
            "§3.3",
            role="foot",
            n=(2,),
        ),
        S(
            "O_M",
            "midpoint",
            ("P1x", "P2x"),
            "compass",
            "Bisect P1x P2x: its midpoint O_M",
            "§3.3",
            role="midpoint",
        ),
    ]
    for n in (1, 2, 3, 4):
        i = 1 if n in (1, 3) else 2
        foot = "P2x" if i == 1 else "P1x"
        ref = f"§3.3 V{n} step"
        specs += [
            S(
                f"X{n}",
                "meet",
                (f"side{n}", "x-axis"),
                "ruler",
                f"Extend the {_SIDE_WORD[n]} side of the cone at P{i} to the x-axis: X{n}",
                f"{ref} (1), Fig. 4({'abcd'[n - 1]})",
                role="X",
                n=(n,),
            ),
            S(
                f"perp{n}",
                "perpendicular",
                (f"side{n}", foot),
                "perpendicular",
                f"Perpendicular from {foot} to the {_SIDE_WORD[n]} side of the cone at P{i}",
                f"{ref} (2)",
                role="perpendicular",
                n=(n,),
            ),
            S(
                f"Y{n}",
                "meet",
                (f"perp{n}", "y-axis"),
                "ruler",
                f"The perpendicular meets the y-axis at Y{n}",
                f"{ref} (2)",
                role="Y",
                n=(n,),
            ),
            S(
                f"OMX{n}",
                "signed_length",
                ("O_M", f"X{n}", "x-axis"),
                "compass",
                f"Signed length O_M X{n} = −S{n}",
                f"{ref} (1), eq. {_S_EQ[n]}",
                role="S_length",
                n=(n,),
            ),
            S(
                f"OY{n}",
                "signed_length",
                ("O", f"Y{n}", "y-axis"),
                "compass",
                f"Signed length O Y{n} = −C{n}",
                f"{ref} (2), eq. {_C_EQ[n]}",
                role="C_length",
                n=(n,),
            ),
            S(
                f"V{n}",
                "point_from_lengths",
                (f"OMX{n}", f"OY{n}"),
                "compass",
                f"Plot V{n} = (−O_M X{n}, −O Y{n})",
                f"{ref} (3), eq. (30)/(33)",
                (-1, -1),
                key=True,
                role="V",
                n=(n,),
            ),
        ]
    for n in (1, 2, 3, 4):
        specs.append(
            S(
                f"circle{n}",
                "circle_on_diameter",
                ("O", f"V{n}"),
                "compass",
                f"Circle on the diameter O V{n}: the polar graph of k{n}(θ)",
                "§3.2 eq. (31)-(32), Fig. 3",
                key=True,
                role="circle",
                n=(n,),
            )
        )
    for n, m in combinations((1, 2, 3, 4), 2):
        specs.append(
            S(
                f"B{n}{m}",
                "second_intersection",
                (f"circle{n}", f"circle{m}", "O"),
                "mark",
                f"Second intersection of circles {n} and {m}: there k{n}(θ) = k{m}(θ)",
                "§3.3 outside extraction, §5",
                role="break_point",
                n=(n, m),
            )
        )
    return specs


def internal_force_diagram(grasp: Grasp | None = None) -> Construction:
    """Replay the paper's drawing of the internal force diagram of ``grasp``.

    The shipped recipe ``recipes/paper.gc`` is replayed
    (:func:`~graspcompass.construction.language.replay` of
    :func:`~graspcompass.construction.language.paper_program`).  The steps:
    the axes; P1, P2; the upper and lower sides of both friction cones; P1x,
    P2x, O_M; for n = 1..4 the extended cone side and X_n, the
    perpendicular from P2x (n = 1, 3) or P1x (n = 2, 4) and Y_n, the signed
    lengths O_M X_n, O Y_n and V_n = (−O_M X_n, −O Y_n) (§3.3); the circles on
    the diameters O V_n (§3.2); their second intersections; and, for numeric
    parameters, the outer envelope k_grasp (eq. (25)) as exact arcs.

    Parameters
    ----------
    grasp : Grasp, optional
        Defaults to the paper's Fig. 6 grasp.  With symbolic parameters the
        result is the general construction and lists its non-degeneracy
        conditions (``.conditions``); the envelope, whose shape depends on the
        numbers, is then left out.

    Examples
    --------
    >>> from sympy import sqrt, Rational
    >>> from graspcompass.geometry import Point
    >>> c = internal_force_diagram()
    >>> c["V1"] == Point(-1 - sqrt(3), -Rational(3, 2) - sqrt(3))
    True
    >>> c["V2"] == Point(sqrt(3), -Rational(3, 2))
    True
    >>> c.step("X1").ref
    '§3.3 V1 step (1), Fig. 4(a)'
    """
    from .language import paper_steps, replay

    return replay(paper_steps(), Grasp.preset("fig6") if grasp is None else grasp)


def _internal_force_diagram_from_specs(grasp: Grasp) -> Construction:
    """The same construction from :func:`diagram_specs` (the tests compare the two)."""
    env: dict[str, Any] = {}
    steps: list[Step] = []
    skipped: list[tuple[str, str]] = []
    for spec in diagram_specs(grasp):
        try:
            step = run_step(spec, env, len(steps))
        except GeometryError as exc:
            if spec.op != "second_intersection":
                raise
            skipped.append((spec.name, str(exc)))
            continue
        env[spec.name] = step.obj
        steps.append(step)
    symbolic = any(v.free_symbols for v in grasp.params.values())
    if not symbolic:
        names = [s.name for s in steps if s.op in ("circle_on_diameter", "second_intersection")]
        env_obj = outer_envelope(env)
        steps.append(
            Step(
                len(steps),
                "envelope",
                "envelope",
                "compass",
                tuple(names),
                env_obj,
                (),
                "Outer envelope of the four circles: the polar graph of k_grasp(θ)",
                "§3.3 outside extraction, eq. (25), Fig. 5",
                key=True,
                role="envelope",
            )
        )
    return Construction(tuple(steps), grasp, tuple(skipped))


def _read_shipped_recipe() -> None:
    """Parse ``recipes/paper.gc`` once, when this module is imported (about 3 ms).

    The shipped recipe is a constant of the package, like the module's own code: it is
    read when the package is, and each :func:`internal_force_diagram` replays it
    (``bench/bench_replay.py`` reports the import times beside the first call).
    """
    from .language import paper_steps

    paper_steps()


_read_shipped_recipe()
