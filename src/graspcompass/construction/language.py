"""The construction language: a plain-text file of named ruler-and-compass steps.

One statement a line; ``#`` starts a comment.  The reference is ``docs/language.md``;
in short::

    param x1 > 0                      # parameters with their domains
    param phi1 angle                  # 0 < phi1 <= pi
    param mu1 friction                # mu1 > 0 (or: param xi1 half_angle)
    hypothesis condition1             # condition (1) of the paper, by name
    let S1 = -(x1 + x2)/2 + y*tan(phi1)   # a named value (safe expression syntax)
    P1 = point (x1, y)  role contact 1  ref "§2.2.1"  "Contact point P1"
    X1 = meet side1 x-axis  role X 1  "Extend the side to the x-axis: X1"
    B12 = second_intersection circle1 circle2 O  optional
    claim V1 == point(S1, C1)
    claim collinear O_M X1 X2
    claim sign x1 + x2 > 0 under condition1

A step is ``NAME = OPERATION INPUT... [(VALUE, ...)] [CLAUSE...]``: the
operation is a key of :data:`~graspcompass.construction.operations.OPERATIONS`
(or ``envelope``), the inputs are names of earlier objects of the kinds the
operation takes, the values (in one pair of parentheses) are read by the safe
parser :func:`graspcompass.expr.parse_exact` with the declared parameters and
``let`` names as symbols (never ``eval``).  The clauses are a caption (a
double-quoted string), ``ref "…"`` (the paper's section or equation), ``role
ROLE N...`` (:data:`~graspcompass.construction.operations.ROLES`), ``key`` (an
animation pauses there) and ``optional`` (a degenerate step is left out, as the
break points of tangent circles are).

:func:`parse` returns a :class:`Program` (plain data); :func:`replay` runs it
on a grasp; :class:`ConstructionBuilder` makes the same :class:`Program` from
Python (the program's data, the checks and the builder live in
:mod:`graspcompass.construction.program`).  Errors are
:class:`ConstructionSyntaxError` (``FILE:LINE:COL: what``) and, at replay,
:class:`DegenerateStepError` (the step, its line and objects).  The statements'
tokens and checks are in the private ``_lang_lines``, the values of a replay
(parameters bound, each step's values exact or as doubles) in ``_lang_values``;
every name stays importable from here.

Examples
--------
>>> prog = parse('''
... A = point (0, 0)
... B = point (2, 0)
... M = midpoint A B  "the midpoint"
... claim M == point(1, 0)
... ''')
>>> [s.name for s in prog.steps], prog.claims[0].kind
(['A', 'B', 'M'], 'equal')
>>> replay(prog)["M"]
Point(1, 0)
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..boundary.errors import InputError, NotTextError
from ..geometry import GeometryError
from ..geometry.exact import has_float
from ._lang_lines import (
    _claim,  # noqa: F401
    _find_relation,  # noqa: F401
    _group_end,  # noqa: F401
    _Line,  # noqa: F401
    _split_items,  # noqa: F401
    _statement,
    _step,  # noqa: F401
    _strip_comment,
    _term_text,  # noqa: F401
)
from ._lang_values import (
    _BOUNDS,  # noqa: F401
    _FLOAT_DIGITS,  # noqa: F401
    _MP_FUNCTIONS,  # noqa: F401
    _bindings,
    _check_domain,  # noqa: F401
    _exact_value,
    _float_value,
    _frac,  # noqa: F401
    _mp,  # noqa: F401
)
from .operations import OPERATIONS
from .program import (
    _CLAIM_KINDS,  # noqa: F401
    _ENVELOPE,
    _KEYWORDS,  # noqa: F401
    _NAME,  # noqa: F401
    _RELATIONS,  # noqa: F401
    _TOKEN,  # noqa: F401
    DOMAINS,
    HYPOTHESES,
    MAX_LINE_LENGTH,
    MAX_LINES,
    Claim,
    ConstructionBuilder,
    ConstructionSyntaxError,
    DegenerateStepError,
    Param,
    PointValue,
    Program,
    Ref,
    Statement,
    Value,
    _Checker,
    _Problem,  # noqa: F401
)
from .protocol import Construction, Step, StepSpec, run_step

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = [
    "DOMAINS",
    "EXAMPLES",
    "HYPOTHESES",
    "MAX_LINES",
    "MAX_LINE_LENGTH",
    "Claim",
    "ConstructionBuilder",
    "ConstructionSyntaxError",
    "DegenerateStepError",
    "Param",
    "PointValue",
    "Program",
    "Ref",
    "Statement",
    "Value",
    "example_text",
    "paper_program",
    "paper_steps",
    "paper_text",
    "parse",
    "replay",
]


# -- the parser ---------------------------------------------------------------------------


def parse(text: str, file: str = "<text>") -> Program:
    """Read a program in the construction language.

    Parameters
    ----------
    text : str
        The file's text (at most :data:`MAX_LINES` lines of :data:`MAX_LINE_LENGTH`).
    file : str
        The file's name, for messages.

    Returns
    -------
    Program
        Plain data: parameters, hypotheses, let values, steps and claims.

    Raises
    ------
    ConstructionSyntaxError
        ``FILE:LINE:COL: what`` for an unknown name or operation, inputs of the
        wrong kind, a duplicate name, a bad value or anything unreadable.

    Examples
    --------
    >>> p = parse("param a > 0\\nA = point (a, 0)\\nB = point (0, a)\\nl = line_through A B")
    >>> p.steps[2].op, p.steps[2].inputs, p.params[0].domain
    ('line_through', ('A', 'B'), 'positive')
    >>> parse("l = line_through A B", file="f.gc")
    Traceback (most recent call last):
    ...
    graspcompass.construction.program.ConstructionSyntaxError: f.gc:1:18: unknown name 'A' ...
    """
    if not isinstance(text, str):
        raise NotTextError(
            f"expected the text of a construction file (a str), got {type(text).__name__}"
        )
    lines = text.split("\n")
    if len(lines) > MAX_LINES:
        raise ConstructionSyntaxError(f"more than {MAX_LINES} lines", file, MAX_LINES + 1, 1)
    chk = _Checker()
    for number, raw in enumerate(lines, 1):

        def err(what: str, col: int, number: int = number) -> ConstructionSyntaxError:
            return ConstructionSyntaxError(what, file, number, col)

        if len(raw) > MAX_LINE_LENGTH:
            raise err(f"the line is longer than {MAX_LINE_LENGTH} characters", MAX_LINE_LENGTH + 1)
        body = _strip_comment(raw.rstrip("\r"))
        if not body.strip():
            continue
        _statement(body, chk, number, err)
    return chk.program(file)


# -- replay ---------------------------------------------------------------------------------


def replay(program: Program, grasp: Grasp | Mapping[str, Any] | None = None) -> Construction:
    """Run a program's steps in order with the exact kernel.

    Parameters
    ----------
    program : Program
        From :func:`parse` or :meth:`ConstructionBuilder.build`.
    grasp : Grasp or Mapping, optional
        Values of the parameters: a :class:`~graspcompass.Grasp` (its ``params``:
        x1, x2, y, phi1, phi2, mu1, mu2, xi1, xi2) or a mapping name -> value
        (read at the input boundary).  ``sin`` and ``cos`` of a parameter take the
        grasp's exact values (:func:`graspcompass.geometry.trig.sincos`).  Without
        values the construction is symbolic, in the parameters' symbols.

    Returns
    -------
    Construction
        The steps (with caption, ref, role), the grasp, and the ``optional``
        steps left out as ``skipped``.  An ``envelope`` step is made only when
        no value is symbolic (§3.3, eq. (25)).

    Raises
    ------
    DegenerateStepError
        A step the kernel cannot make (not ``optional``), naming it and its line.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> c = replay(paper_program(), Grasp.preset("fig6"))
    >>> c.step("V1").role, c.step("V1").n, c.step("V1").ref
    ('V', (1,), '§3.3 V1 step (3), eq. (30)/(33)')
    """
    from .envelope import outer_envelope

    table = _bindings(program, grasp)
    floats = any(has_float(v) for v in table.values())
    env: dict[str, Any] = {}
    steps: list[Step] = []
    skipped: list[tuple[str, str]] = []
    symbolic = any(v.free_symbols for v in table.values()) if table else bool(program.params)
    for s in program.steps:
        if s.op == _ENVELOPE:
            if symbolic:
                continue
            ins = tuple(n for n in s.inputs if n in env)
            steps.append(
                Step(
                    len(steps),
                    s.name,
                    _ENVELOPE,
                    "compass",
                    ins,
                    outer_envelope(_by_role(steps, env)),
                    (),
                    s.caption,
                    s.ref,
                    (),
                    s.key,
                    s.role,
                    s.n,
                )
            )
            env[s.name] = steps[-1].obj
            continue
        try:
            if floats:
                values = tuple(_float_value(v, table) for v in s.values)
            else:
                values = (
                    tuple(_exact_value(v, table) if v.free_symbols else v for v in s.values)
                    if table
                    else s.values
                )
        except (InputError, ArithmeticError, ValueError) as exc:
            raise InputError(f"{program.file}:{s.line}:1: step {s.name}: {exc}") from None
        spec = StepSpec(
            s.name,
            s.op,
            s.inputs,
            OPERATIONS[s.op].instrument,
            s.caption,
            s.ref,
            values,
            s.key,
            s.role,
            s.n,
        )
        try:
            step = run_step(spec, env, len(steps))
        except GeometryError as exc:
            if s.optional:
                skipped.append((s.name, str(exc)))
                continue
            raise DegenerateStepError(
                f"{program.file}:{s.line}:1: step {s.name} = {s.op} {' '.join(s.inputs)} is "
                f"degenerate: {exc}",
                s.name,
                s.line,
                *(env[n] for n in s.inputs),
            ) from exc
        except ZeroDivisionError as exc:  # a divisor that is 0 modulo sin² + cos² = 1
            raise DegenerateStepError(
                f"{program.file}:{s.line}:1: step {s.name} = {s.op} {' '.join(s.inputs)} "
                "divides by an expression that is 0 for every value of the parameters "
                "(0/0: it exists nowhere)",
                s.name,
                s.line,
                *(env[n] for n in s.inputs),
            ) from exc
        env[s.name] = step.obj
        steps.append(step)
    return Construction(
        tuple(steps), grasp if not isinstance(grasp, Mapping) else None, tuple(skipped)
    )


def _by_role(steps: list[Step], env: dict[str, Any]) -> dict[str, Any]:
    """The objects the envelope reads, found by role: ``role V n`` is V_n and
    ``role break_point n m`` is B_nm, whatever the file names them (eq. (25))."""
    out = dict(env)
    for st in steps:
        if st.role == "V" and len(st.n) == 1:
            out[f"V{st.n[0]}"] = st.obj
        elif st.role == "break_point" and len(st.n) == 2:
            out[f"B{st.n[0]}{st.n[1]}"] = st.obj
    return out


# -- the shipped recipe -------------------------------------------------------------------------
def paper_text() -> str:
    """The text of the paper's recipe as shipped (``recipes/paper.gc``).

    Examples
    --------
    >>> paper_text().splitlines()[0]
    '# The internal force diagram of a two-point grasp, drawn by ruler and compass:'
    """
    return _shipped("paper.gc")


def _shipped(name: str) -> str:
    """A file of ``recipes/``: read from the folder beside this module when it is one
    (5 ms faster in a fresh process than :mod:`importlib.resources`), else as a resource."""
    here = Path(__file__).with_name("recipes") / name
    if here.is_file():
        return here.read_text("utf-8")
    return resources.files(__package__).joinpath("recipes").joinpath(name).read_text("utf-8")


def example_text(name: str) -> str:
    """A construction file shipped with the package beside the recipe: ``thales.gc``
    (Fig. 3) or ``exercise-v3.gc`` (a student's V3 with one slip, for grading).

    Examples
    --------
    >>> parse(example_text("thales.gc")).claims[0].kind
    'on'
    """
    if name not in EXAMPLES:
        raise InputError(f"no shipped example {name!r}: choose one of {', '.join(EXAMPLES)}")
    return _shipped(name)


#: The example files shipped beside the recipe.
EXAMPLES = ("thales.gc", "exercise-v3.gc")


@lru_cache(maxsize=1)
def paper_program() -> Program:
    """The paper's recipe (§3.3, §3.2), parsed once; replay it with :func:`replay`.

    Examples
    --------
    >>> p = paper_program()
    >>> len(p.steps), [q.name for q in p.params][:3], p.hypotheses
    (47, ['x1', 'x2', 'y'], ('condition1',))
    """
    return parse(paper_text(), "paper.gc")


def paper_steps() -> Program:
    """:func:`paper_program` for replaying: the recipe's steps, without parsing its claims
    and the let values they use into exact terms (they are for ``check``; a replay never
    reads them), unless the whole program is parsed already.  Twice as fast in a fresh
    process.

    Examples
    --------
    >>> len(paper_steps().steps) == len(paper_program().steps)
    True
    """
    if paper_program.cache_info().currsize:
        return paper_program()
    return _paper_steps()


@lru_cache(maxsize=1)
def _paper_steps() -> Program:
    lines = paper_text().split("\n")
    kept = ["" if line.lstrip().startswith("claim ") else line for line in lines]
    try:  # its let values too, which only claims use: a step that used one would not parse
        return parse(
            "\n".join("" if line.lstrip().startswith("let ") else line for line in kept), "paper.gc"
        )
    except InputError:
        return parse("\n".join(kept), "paper.gc")
