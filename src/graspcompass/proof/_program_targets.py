"""The targets of ``check_program(..., against="paper")``: each object against the paper.

Every object named like a point of the paper is compared with the paper's statement
for it (:class:`~graspcompass.proof.certify_paper.PaperModel`) for every grasp that
satisfies condition (1).  Private to :mod:`graspcompass.proof.program_check`, which
re-exports :data:`PAPER_TARGETS`.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from typing import Any

import sympy as sp

from .. import symbols as S
from ..construction.program import Program
from ._program_claims import _ancestors, _hypotheses, _line, _row, _vacuous
from ._program_rows import CheckRow
from .certify_paper import PaperModel, model_at
from .program_decide import DOMAIN_WORDS, CheckError, coords, nonzero, prove_zero
from .prove import ProofResult, Status

#: Names of objects graded by ``against="paper"`` -> (what the paper says it is, reference).
PAPER_TARGETS: dict[str, str] = {
    **{f"X{n}": f"X{n} on the x-axis, O_M X{n} = −S{n} (§3.3 step (1), (A7))" for n in range(1, 5)},
    **{f"Y{n}": f"Y{n} on the y-axis, O Y{n} = −C{n} (§3.3 step (2), (A8))" for n in range(1, 5)},
    **{f"V{n}": f"V{n} = (S{n}, C{n}), eqs. (28)-(39)" for n in range(1, 5)},
    **{f"circle{n}": f"the circle on the diameter O V{n} (§3.2, Fig. 3)" for n in range(1, 5)},
    "O_M": "the midpoint of P1x P2x, ((x1 − x2)/2, 0) (§3.3)",
    "P1x": "the foot of P1 on the x-axis, (x1, 0) (§3.3)",
    "P2x": "the foot of P2 on the x-axis, (−x2, 0) (§3.3)",
}
#: The parameters a file must declare to be graded against the paper.
_PAPER_PARAMS = ("x1", "x2", "y", "phi1", "phi2")


# -- targets (against the paper) ----------------------------------------------------------
def _paper_model(program: Program) -> PaperModel:
    names = {p.name for p in program.params}
    missing = [n for n in _PAPER_PARAMS if n not in names]
    for d in "12":
        if f"mu{d}" not in names and f"xi{d}" not in names:
            missing.append(f"mu{d} (or xi{d})")
    if missing:
        raise CheckError(
            f"{program.file}: grading against the paper needs the parameters "
            f"x1, x2, y, phi1, phi2 and mu1/xi1, mu2/xi2; missing: "
            f"{', '.join(missing)}"
        )
    values: dict[sp.Symbol, sp.Expr] = {getattr(S, n): getattr(S, n) for n in _PAPER_PARAMS}
    mu_form = []
    for i in (1, 2):
        mu, xi = getattr(S, f"mu{i}"), getattr(S, f"xi{i}")
        if f"mu{i}" in names:
            values[mu], values[xi] = mu, sp.atan(mu)
            mu_form.append(True)
        else:
            values[mu], values[xi] = sp.tan(xi), xi
            mu_form.append(False)
    return PaperModel(values, (mu_form[0], mu_form[1]), False)


def _paper_object(model: PaperModel, name: str) -> tuple[sp.Expr, ...]:
    if name == "O_M":
        return model.O_M
    if name in ("P1x", "P2x"):
        return model.Px(int(name[1]))
    kind, n = name.rstrip("1234"), int(name[-1])
    if kind == "circle":
        (cx, cy), r2 = model.circle(n)
        return cx, cy, r2
    return {"X": model.X, "Y": model.Y, "V": model.V}[kind](n)


def _model_point(pt: Mapping[str, Any]) -> dict[sp.Symbol, sp.Expr]:
    out = {getattr(S, k): sp.sympify(v) for k, v in pt.items() if k in DOMAIN_WORDS}
    for i in (1, 2):  # the model holds both μ and ξ
        mu, xi = getattr(S, f"mu{i}"), getattr(S, f"xi{i}")
        if mu in out and xi not in out:
            out[xi] = sp.atan(out[mu])
        elif xi in out and mu not in out:
            out[mu] = sp.tan(out[xi])
    return out


def _check_target(
    program: Program,
    name: str,
    env: dict[str, Any],
    model: PaperModel,
    step_conds: Mapping[str, tuple[list[str], list[str]]],
    vacuous: Mapping[str, str] | None = None,
) -> CheckRow:
    t0 = time.perf_counter()
    obj = env[name]
    want = _paper_object(model, name)
    hyps = _hypotheses(program, True)
    gone = [f"{n}: {vacuous[n]}" for n in _ancestors(program, [name]) if vacuous and n in vacuous]
    if gone:
        return _vacuous(name, "target", _line(program, name), t0, hyps, "; ".join(gone))
    try:
        have = coords(obj)
    except CheckError:
        have = ()
    if len(have) != len(want):
        what = {2: "a point", 3: "a circle", 1: "a number"}[len(want)]
        return CheckRow(
            name,
            "target",
            _line(program, name),
            ProofResult(
                Status.REFUTED,
                f"the file's {name} is a {type(obj).__name__}; the paper's is "
                f"{PAPER_TARGETS[name]}",
                time.perf_counter() - t0,
                hypotheses=hyps,
                detail=f"no counterexample needed: the file's {name} is a {type(obj).__name__} "
                f"for every value of the parameters (the kind of an object does not depend on "
                f"them) and the paper's {name} is {what}, so they differ at every point of the "
                f"model",
            ),
        )
    implied: list[str] = []
    extra: list[str] = []
    for n in _ancestors(program, [name]):
        imp, ext = step_conds.get(n, ([], []))
        implied += imp
        extra += ext
    ok, imp, ext, method = prove_zero([h - w for h, w in zip(have, want)], True)

    def fails(env_at: dict[str, Any], pt: Any) -> bool:
        at = model_at(model, _model_point(pt))
        return any(nonzero(h - w) for h, w in zip(coords(env_at[name]), _paper_object(at, name)))

    return _row(
        program,
        name,
        "target",
        _line(program, name),
        ok,
        fails,
        t0,
        hyps,
        implied + imp,
        extra + ext,
        method,
        {"cond1": True, "names": _ancestors(program, [name])},
    )
