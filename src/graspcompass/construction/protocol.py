"""The construction protocol: declarative, replayable steps.

A :class:`Step` is a plain record: which operation (``op``) of the kernel made
which named object from which named inputs, with what instrument, under which
non-degeneracy conditions, with a caption and the paper's reference.  A
:class:`Construction` is the ordered list of steps; :func:`replay` runs a list
of step declarations again (possibly on other parameters) through :data:`OPS`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..geometry import Circle, Line, Point
from .operations import OPERATIONS

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = ["INSTRUMENTS", "OPS", "Construction", "Step", "StepSpec", "replay"]

#: The instruments of a ruler-and-compass drawing.
INSTRUMENTS = ("ruler", "compass", "perpendicular", "mark")


#: Operation name -> function(*input objects, *params), derived from
#: :data:`~graspcompass.construction.operations.OPERATIONS` (one record per operation).
OPS: dict[str, Callable[..., Any]] = {name: op.function for name, op in OPERATIONS.items()}


@dataclass(frozen=True)
class StepSpec:
    """The declaration of a step, before it is run.

    ``params`` are exact values passed after the input objects (coordinates of a
    given point, a direction, signs); ``role`` and ``n`` say what the object is
    in the drawing (see :class:`Step`).
    """

    name: str
    op: str
    inputs: tuple[str, ...]
    instrument: str
    caption: str
    ref: str
    params: tuple[Any, ...] = ()
    key: bool = False
    role: str = ""
    n: tuple[int, ...] = ()


@dataclass(frozen=True)
class Step:
    """One step of a construction, as plain data.

    Attributes
    ----------
    index : int
        Position in the protocol, from 0.
    name : str
        Name of the object the step makes (``"X1"``, ``"circle2"``).
    op : str
        Kernel operation that made it (a key of :data:`OPS`, or ``"envelope"``).
    instrument : str
        One of :data:`INSTRUMENTS`.
    inputs : tuple of str
        Names of the objects the step uses.
    obj : Point, Line, Circle, sympy.Expr or Envelope
        The exact object made.
    conditions : tuple of sympy.Expr
        Non-degeneracy conditions this step adds: each expression is assumed
        non-zero (empty for numbers, where they are checked instead).
    caption, ref : str
        One line of text, and the paper's section or equation.
    key : bool
        A key result (V_n, a circle, the envelope) where an animation pauses.
    role : str
        What the object is in the drawing, as data (one of
        :data:`~graspcompass.construction.operations.ROLES`: ``"cone_side"``,
        ``"X"``, ``"V"``, ...; ``""`` for none), so that no painter reads it from
        the name.
    n : tuple of int
        The indices that go with the role: ``(1,)`` for V1 or side 1, ``(1, 2)``
        for the break point B12, ``()`` for none.
    """

    index: int
    name: str
    op: str
    instrument: str
    inputs: tuple[str, ...]
    obj: Any
    conditions: tuple[sp.Expr, ...]
    caption: str
    ref: str
    params: tuple[Any, ...] = ()
    key: bool = False
    role: str = ""
    n: tuple[int, ...] = ()

    @property
    def kind(self) -> str:
        """``"point"``, ``"line"``, ``"circle"``, ``"length"`` or ``"envelope"``."""
        for cls, name in ((Point, "point"), (Line, "line"), (Circle, "circle")):
            if isinstance(self.obj, cls):
                return name
        return "length" if isinstance(self.obj, sp.Expr) else "envelope"

    @property
    def spec(self) -> StepSpec:
        """The declaration that makes this step again."""
        return StepSpec(
            self.name,
            self.op,
            self.inputs,
            self.instrument,
            self.caption,
            self.ref,
            self.params,
            self.key,
            self.role,
            self.n,
        )


@dataclass(frozen=True)
class Construction:
    """An ordered, replayable list of named steps.

    Objects are looked up by name (``c["X1"]``); ``c.steps`` lists the steps
    and ``c.upto(i)`` is the state after step ``i``.
    """

    steps: tuple[Step, ...]
    grasp: Grasp | None = None
    skipped: tuple[tuple[str, str], ...] = field(default=())

    def __post_init__(self) -> None:
        object.__setattr__(self, "_by_name", {s.name: s for s in self.steps})

    def __getitem__(self, name: str) -> Any:
        try:
            return self._by_name[name].obj  # type: ignore[attr-defined]
        except KeyError:
            raise KeyError(f"no object named {name!r} in this construction") from None

    def __contains__(self, name: object) -> bool:
        return name in self._by_name  # type: ignore[attr-defined]

    def __iter__(self) -> Iterator[Step]:
        return iter(self.steps)

    def __len__(self) -> int:
        return len(self.steps)

    def step(self, name: str) -> Step:
        """The step that made ``name``."""
        return self._by_name[name]  # type: ignore[attr-defined]

    @property
    def names(self) -> tuple[str, ...]:
        """Names of the objects, in protocol order."""
        return tuple(s.name for s in self.steps)

    @property
    def objects(self) -> dict[str, Any]:
        """Name -> object, in protocol order."""
        return {s.name: s.obj for s in self.steps}

    @property
    def conditions(self) -> tuple[sp.Expr, ...]:
        """Every non-degeneracy condition assumed (each expression ≠ 0)."""
        seen: dict[sp.Expr, None] = {}
        for s in self.steps:
            seen.update(dict.fromkeys(s.conditions))
        return tuple(seen)

    def upto(self, i: int) -> Construction:
        """The construction after step ``i`` (inclusive; negative counts from the end)."""
        n = len(self.steps)
        if not -n <= i < n:
            raise IndexError(f"step {i} out of range for a construction of {n} steps")
        return replace(self, steps=self.steps[: (i % n) + 1])


def run_step(
    spec: StepSpec,
    env: dict[str, Any],
    index: int,
    extra_ops: dict[str, Callable[..., Any]] | None = None,
) -> Step:
    """Run one declaration against the named objects ``env``; return the step."""
    ops = OPS if not extra_ops else {**OPS, **extra_ops}
    args = [env[n] for n in spec.inputs]
    obj = ops[spec.op](*args, *spec.params)
    before: frozenset = frozenset()
    for a in args:
        before |= getattr(a, "conditions", frozenset())
    new = tuple(sorted(getattr(obj, "conditions", frozenset()) - before, key=sp.default_sort_key))
    return Step(
        index,
        spec.name,
        spec.op,
        spec.instrument,
        spec.inputs,
        obj,
        new,
        spec.caption,
        spec.ref,
        spec.params,
        spec.key,
        spec.role,
        spec.n,
    )


def replay(
    specs: Sequence[StepSpec], grasp: Grasp | None = None, subs: dict | None = None
) -> Construction:
    """Run step declarations in order; ``subs`` substitutes symbols in the params.

    Examples
    --------
    >>> specs = [StepSpec("A", "point", (), "mark", "A", "-", (0, 0)),
    ...          StepSpec("B", "point", (), "mark", "B", "-", (2, 0)),
    ...          StepSpec("M", "midpoint", ("A", "B"), "compass", "midpoint", "-")]
    >>> replay(specs)["M"]
    Point(1, 0)
    """
    env: dict[str, Any] = {}
    steps = []
    # the caller's parameters and values: read at the boundary (text by the safe parser,
    # numpy arrays and other objects refused by name), never sympify'd
    from ..boundary.inputs import real_value, substitutions

    specs = [
        replace(
            spec,
            params=tuple(
                p if isinstance(p, sp.Basic) else real_value(p, f"{spec.name}.params[{j}]")
                for j, p in enumerate(spec.params)
            ),
        )
        for spec in specs
    ]
    if subs:
        known = set().union(*(p.free_symbols for spec in specs for p in spec.params))
        subs = substitutions(subs, known, "subs", strict=False)
    for i, spec in enumerate(specs):
        if subs:
            spec = replace(spec, params=tuple(p.subs(subs) for p in spec.params))
        step = run_step(spec, env, i)
        env[spec.name] = step.obj
        steps.append(step)
    return Construction(tuple(steps), grasp)
