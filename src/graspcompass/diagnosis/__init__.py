"""Slip diagnosis: which friction inequality binds at the least internal force (issue 13 §4).

With the internal force at its least value ``k_grasp(θ) = max(k1, k2, k3, k4, 0)``
(25), the contact forces ``F = F_T + k_grasp F_N`` (16) meet every contact force
condition (8)-(11), and, unless ``k_grasp = 0``, one of them with equality: the
inequality n whose lower limit ``k_n(θ) = V_n · e(θ)`` (18)-(21), (32) is the
largest.  Squeeze any less and that inequality fails: its contact slips, one
way along the surface.

==  =========================  ======  =======  =========  ==============================
n   condition                  limit   contact  cone side  object's contact point slides
==  =========================  ======  =======  =========  ==============================
1   (8)  ``μ1 N1 − F1 > 0``    (18)    P1       upper      down, along −t1 = (cos φ1, −sin φ1)
2   (9)  ``μ2 N2 − F2 > 0``    (19)    P2       upper      down, along −t2 = (−cos φ2, −sin φ2)
3   (10) ``μ1 N1 + F1 > 0``    (20)    P1       lower      up, along t1 = (−cos φ1, sin φ1)
4   (11) ``μ2 N2 + F2 > 0``    (21)    P2       lower      up, along t2 = (cos φ2, sin φ2)
==  =========================  ======  =======  =========  ==============================

``t1 = (−cos φ1, sin φ1)`` and ``t2 = (cos φ2, sin φ2)`` are the 2nd and 4th columns
of the grasp matrix L (5): the direction in which a positive tangential force F_i
acts on the object.  When (8) binds, ``F1 = μ1 N1``: the contact force at P1 lies
on the *upper* side of its cone (angle φ1 + ξ1), friction pushes the object up
along the surface as hard as it can, and the object's contact point is about to
slide the other way, *down* along −t1, relative to the finger ("down" is −y, away
from the contacts' line towards the centre of mass side; at φ = π the slide is
along x).  Dynamic friction opposes the relative velocity, which is why the slide
is opposite to the friction force.

``n = 0`` is the *zero-force region*: ``k_grasp = 0``, all ``k_n ≤ 0``; the
external force is resisted with no internal force (the contact forces F_T of
eq. (13) already lie in both friction cones) and no contact is about to slip.
The region is closed: where ``k_grasp = 0 = k_n``, n = 0 and n is listed among
the binding indices.

:func:`slip` answers per direction θ, :func:`slip_intervals` gives the θ-intervals
of each binding inequality and of the zero-force region from the construction's
outer envelope (:func:`graspcompass.construction.outer_envelope`), with exact
break points for exact grasps.

Examples
--------
>>> from graspcompass import Grasp
>>> from graspcompass.diagnosis import slip, slip_intervals
>>> g = Grasp.preset("table1a")
>>> s = slip(g, 0)            # θ = 0: the external force points straight down
>>> s.n, s.contact, s.side, s.binding, s.k_grasp
(1, 1, 'upper', (1,), 2)
>>> s.slide                   # P1's contact point slides down relative to finger 1
(0, -1)
>>> s.runner_up, s.margin     # next: (9) at P2 (μ2 = 1.2 > μ1 = 1), k2 = 5/3
(2, 1/3)
>>> [(iv.n, iv.theta_start) for iv in slip_intervals(g)][:2]
[(2, atan(2/35)), (4, pi - atan(2))]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..boundary.errors import NonFiniteValueError, SymbolicValueError
from ..boundary.inputs import angle_values
from ..geometry.exact import canon, decide_sign

if TYPE_CHECKING:
    from ..grasp import Grasp

__all__ = [
    "INEQUALITIES",
    "SLIP_DTYPE",
    "TIE_TOL",
    "Inequality",
    "Slip",
    "SlipInterval",
    "slip",
    "slip_intervals",
    "zero_force_intervals",
]

#: Relative tolerance of a float tie: ``|k_n − k_m| <= TIE_TOL · max|V_n|`` (floats only;
#: exact values tie when exactly equal).  The float k_n are correct to a few ε max|V_n|.
TIE_TOL = 1e-12


@dataclass(frozen=True)
class Inequality:
    """One contact force condition of (8)-(11) and what its binding means.

    Attributes
    ----------
    n : int
        1-4, the index of k_n and V_n.
    contact : int
        1 (P1) or 2 (P2).
    side : str
        ``"upper"`` (cone side φ + ξ) or ``"lower"`` (φ − ξ).
    equation : str
        The condition's number in the paper, ``"(8)"`` .. ``"(11)"``.
    text : str
        The condition, e.g. ``"μ1 N1 − F1 > 0"``.
    limit : str
        The number of the equation for its lower limit k_n, ``"(18)"`` .. ``"(21)"``.
    way : str
        ``"down"`` or ``"up"``: the way the object's contact point slides along the
        surface relative to the finger when this condition fails.
    """

    n: int
    contact: int
    side: str
    equation: str
    text: str
    limit: str
    way: str


#: The four conditions (8)-(11) by index n (1-4).
INEQUALITIES: dict[int, Inequality] = {
    1: Inequality(1, 1, "upper", "(8)", "μ1 N1 − F1 > 0", "(18)", "down"),
    2: Inequality(2, 2, "upper", "(9)", "μ2 N2 − F2 > 0", "(19)", "down"),
    3: Inequality(3, 1, "lower", "(10)", "μ1 N1 + F1 > 0", "(20)", "up"),
    4: Inequality(4, 2, "lower", "(11)", "μ2 N2 + F2 > 0", "(21)", "up"),
}

#: Fields of the structured array :func:`slip` returns for an array of float θ.
#: ``contact``, ``side`` (+1 upper, −1 lower) and ``slide_x``, ``slide_y`` are 0 in the
#: zero-force region (n = 0); ``runner_up`` is −1 (and ``margin`` 0) if every index ties;
#: ``binding[j]`` is True for each index j = 0..4 attaining k_grasp (both j = 1, 3 or
#: both j = 2, 4: that contact carries no force, see :attr:`Slip.unloaded`).
SLIP_DTYPE = np.dtype(
    [
        ("theta", "f8"),
        ("n", "i1"),
        ("contact", "i1"),
        ("side", "i1"),
        ("slide_x", "f8"),
        ("slide_y", "f8"),
        ("k_grasp", "f8"),
        ("runner_up", "i1"),
        ("margin", "f8"),
        ("binding", "?", (5,)),
    ]
)


def _slide(grasp: Grasp, n: int) -> tuple[Any, Any]:
    """Direction the object's contact point slides relative to the finger (table above)."""
    s1, c1, s2, c2 = grasp.s1, grasp.c1, grasp.s2, grasp.c2
    return {1: (c1, -s1), 2: (-c2, -s2), 3: (-c1, s1), 4: (c2, s2)}[n]


def _words(x: Any) -> str:
    try:
        return f"{float(x):.4g}"
    except (TypeError, OverflowError):  # pragma: no cover - symbols are refused earlier
        return str(x)


@dataclass(frozen=True)
class Slip:
    """The slip diagnosis at one direction θ of the external force.

    Values are exact (sympy) for an exact θ on an exact grasp, floats otherwise.

    Attributes
    ----------
    theta : sympy.Expr or float
        The direction θ of F_e, e(θ) = (sin θ, −cos θ) (26).
    n : int
        The binding condition's index (1-4; see :data:`INEQUALITIES`), or 0 in the
        zero-force region (k_grasp = 0).  With a tie, the smallest binding index.
    binding : tuple of int
        Every index attaining k_grasp (0 for the no-internal-force bound): two or
        more on a tie, e.g. ``(2, 4)`` where k2 = k4 is largest.
    k_grasp : sympy.Expr or float
        ``max(k1, .., k4, 0)``, eq. (25); F_int = k_grasp/(x1 + x2) · F_e (17).
    runner_up : int or None
        The index (0-4) of the next largest of ``0, k1, .., k4`` outside ``binding``:
        the condition that binds next (0: the internal force reaching zero).
    margin : sympy.Expr or float
        ``k_grasp − (that value) > 0``, in the units of k (times F_e/(x1 + x2)
        it is a force, eq. (17)): the slack the runner-up keeps at the least
        internal force; in the zero-force region, how far the largest k_n stays
        below 0.
    slide : tuple or None
        Unit direction (object frame) in which the object's contact point slides
        along the surface relative to the finger when the binding condition fails;
        None in the zero-force region.
    """

    theta: Any
    n: int
    binding: tuple[int, ...]
    k_grasp: Any
    runner_up: int | None
    margin: Any
    slide: tuple[Any, Any] | None

    @property
    def zero_force(self) -> bool:
        """True in the zero-force region: no internal force is needed (k_grasp = 0)."""
        return self.n == 0

    @property
    def tie(self) -> bool:
        """True when two or more of ``0, k1, .., k4`` attain k_grasp."""
        return len(self.binding) > 1

    @property
    def unloaded(self) -> tuple[int, ...]:
        """Contacts whose two cone sides bind together: ``μ_i N_i ∓ F_i = 0`` both, so
        ``N_i = F_i = 0``; such a contact carries no force and is about to lose contact
        rather than slide one way (e.g. where e(θ) is along the line from O to the other
        contact, which then carries the external force alone)."""
        return tuple(i for i, pair in ((1, (1, 3)), (2, (2, 4))) if set(pair) <= set(self.binding))

    @property
    def inequality(self) -> Inequality | None:
        """The binding condition (:data:`INEQUALITIES`), None in the zero-force region."""
        return INEQUALITIES.get(self.n)

    @property
    def contact(self) -> int | None:
        """The contact about to slip (1 or 2), None in the zero-force region."""
        return self.inequality.contact if self.inequality else None

    @property
    def side(self) -> str | None:
        """``"upper"`` or ``"lower"``: the cone side the contact force lies on."""
        return self.inequality.side if self.inequality else None

    @property
    def description(self) -> str:
        """One sentence for a robot designer.

        Examples
        --------
        >>> from graspcompass import Grasp
        >>> print(slip(Grasp.preset("table1a"), 0).description)  # doctest: +NORMALIZE_WHITESPACE
        condition (8) μ1 N1 − F1 > 0 binds (k1 of eq. (18) is largest, k_grasp = 2):
        the contact force at P1 lies on the upper side of its friction cone; with less
        internal force the object slips at P1, its contact point sliding down along
        the surface relative to finger 1, in direction (0, -1). Next to bind: k2 of
        eq. (19), margin 0.3333.
        """
        nxt = (
            "none"
            if self.runner_up is None
            else "no internal force (k = 0)"
            if self.runner_up == 0
            else f"k{self.runner_up} of eq. {INEQUALITIES[self.runner_up].limit}"
        )
        ties = [j for j in self.binding if j != self.n]
        also = (
            ""
            if not ties
            else " Tie: "
            + ", ".join(
                "k = 0" if j == 0 else f"condition {INEQUALITIES[j].equation} (k{j})" for j in ties
            )
            + " binds as well."
        )
        for i in self.unloaded:
            also += (
                f" Both sides of the cone at P{i} bind: N{i} = F{i} = 0, contact {i} "
                "carries no force and is about to lose contact rather than slide."
            )
        if self.inequality is None:
            return (
                "zero-force region: k_grasp = 0, the external force is resisted with no "
                "internal force (the contact forces F_T of eq. (13) lie inside both "
                f"friction cones) and no contact is about to slip. Next to bind: {nxt}, "
                f"margin {_words(self.margin)}." + also
            )
        q = self.inequality
        assert self.slide is not None
        d = f"({_words(self.slide[0])}, {_words(self.slide[1])})"
        return (
            f"condition {q.equation} {q.text} binds (k{q.n} of eq. {q.limit} is largest, "
            f"k_grasp = {_words(self.k_grasp)}): the contact force at P{q.contact} lies on "
            f"the {q.side} side of its friction cone; with less internal force the object "
            f"slips at P{q.contact}, its contact point sliding {q.way} along the surface "
            f"relative to finger {q.contact}, in direction {d}. Next to bind: {nxt}, "
            f"margin {_words(self.margin)}." + also
        )


@dataclass(frozen=True)
class SlipInterval:
    """A θ-interval on which one condition binds (or the zero-force region, n = 0).

    ``theta_start < theta_end``; the intervals of :func:`slip_intervals` partition
    ``[θ0, θ0 + 2π)`` (``0 <= θ0 < 2π``), exactly for exact grasps.  ``binding`` holds
    n and any other index whose circle is the same (V_m = V_n: k_m = k_n all along).
    """

    n: int
    theta_start: Any
    theta_end: Any
    binding: tuple[int, ...]
    slide: tuple[Any, Any] | None

    @property
    def zero_force(self) -> bool:
        """True for the zero-force region (k_grasp = 0)."""
        return self.n == 0

    @property
    def contact(self) -> int | None:
        """The contact about to slip (1 or 2), None in the zero-force region."""
        return INEQUALITIES[self.n].contact if self.n else None

    @property
    def side(self) -> str | None:
        """``"upper"`` or ``"lower"`` cone side, None in the zero-force region."""
        return INEQUALITIES[self.n].side if self.n else None


def _sign(expr: sp.Expr, what: str) -> int:
    s = decide_sign(expr)
    if s is None:
        raise SymbolicValueError(
            f"cannot decide the sign of {what} = {expr}: the slip diagnosis needs numbers; "
            "substitute values first (Grasp.subs)"
        )
    return s


def _exact(grasp: Grasp, theta: sp.Expr) -> Slip:
    cand = (sp.Integer(0), *grasp.k(theta))
    best = 0
    for j in range(1, 5):
        if _sign(cand[j] - cand[best], f"k{j} − k{best}" if best else f"k{j}") == 1:
            best = j
    binding = tuple(
        j for j in range(5) if j == best or _sign(cand[j] - cand[best], "a difference of k's") == 0
    )
    rest = [j for j in range(5) if j not in binding]
    runner: int | None = None
    for j in rest:
        if runner is None or _sign(cand[j] - cand[runner], "a difference of k's") == 1:
            runner = j
    n = binding[0]
    kg = cand[best]
    margin = sp.Integer(0) if runner is None else canon(kg - cand[runner])
    return Slip(theta, n, binding, kg, runner, margin, _slide(grasp, n) if n else None)


def _float_table(grasp: Grasp) -> tuple[np.ndarray, np.ndarray]:
    """slide_x, slide_y by index 0..4 as doubles (0 for n = 0)."""
    xs, ys = [0.0], [0.0]
    for n in (1, 2, 3, 4):
        x, y = _slide(grasp, n)
        xs.append(float(x))
        ys.append(float(y))
    return np.array(xs), np.array(ys)


def _numeric(grasp: Grasp, t: np.ndarray, tie_tol: float) -> np.ndarray:
    K = np.asarray(grasp.k(t), dtype=float)  # (4,) + shape
    S, C = grasp._floats()
    scale = float(np.hypot(S, C).max())
    cand = np.concatenate([np.zeros((1, *t.shape)), K])
    kg = cand.max(axis=0)
    binding = cand >= kg - tie_tol * scale
    n = np.argmax(binding, axis=0)  # the smallest binding index (0 first)
    masked = np.where(binding, -np.inf, cand)
    runner = np.argmax(masked, axis=0)
    nxt = masked.max(axis=0)
    all_tie = ~np.isfinite(nxt)
    sx, sy = _float_table(grasp)
    out = np.zeros(t.shape, dtype=SLIP_DTYPE)
    out["theta"] = t
    out["n"] = n
    out["contact"] = np.array([0, 1, 2, 1, 2])[n]
    out["side"] = np.array([0, 1, 1, -1, -1])[n]
    out["slide_x"], out["slide_y"] = sx[n], sy[n]
    out["k_grasp"] = kg
    out["runner_up"] = np.where(all_tie, -1, runner)
    out["margin"] = np.where(all_tie, 0.0, kg - np.where(all_tie, 0.0, nxt))
    out["binding"] = np.moveaxis(binding, 0, -1)
    return out


def _record(row: np.void | np.ndarray) -> Slip:
    n = int(row["n"])
    runner = int(row["runner_up"])
    return Slip(
        float(row["theta"]),
        n,
        tuple(int(j) for j in np.flatnonzero(row["binding"])),
        float(row["k_grasp"]),
        None if runner < 0 else runner,
        float(row["margin"]),
        (float(row["slide_x"]), float(row["slide_y"])) if n else None,
    )


def _as_float(theta: sp.Expr) -> float:
    try:
        v = float(theta)
    except TypeError:
        raise SymbolicValueError(
            f"theta = {theta} is not a number: a float grasp needs a numeric θ"
        ) from None
    if not math.isfinite(v):
        raise NonFiniteValueError(f"theta = {theta} is beyond double precision")
    return v


def slip(grasp: Grasp, theta: Any, *, tie_tol: float = TIE_TOL) -> Slip | np.ndarray:
    """Which friction condition binds at the least internal force, per direction θ.

    Parameters
    ----------
    grasp : Grasp
        A grasp with numeric parameters (exact or float).
    theta : float, array of floats, str, int or sympy expression
        The direction of the external force, read by
        :func:`graspcompass.inputs.angle_values`: text such as ``"pi/3"`` is parsed
        safely and exactly; ``nan``, infinities, complex values and non-numbers are
        refused with a named :class:`~graspcompass.errors.InputError`.
    tie_tol : float, optional
        Float path only: ``k_n`` within ``tie_tol · max|V_n|`` of k_grasp tie.

    Returns
    -------
    Slip or numpy.ndarray
        A :class:`Slip` for one angle (exact values for an exact θ on an exact
        grasp; floats for a float θ or a float grasp); for an array of θ a
        structured array of dtype :data:`SLIP_DTYPE` and θ's shape.

    Raises
    ------
    graspcompass.errors.SymbolicValueError
        When a sign cannot be decided (a symbolic grasp or θ).

    Examples
    --------
    >>> import numpy as np
    >>> from graspcompass import Grasp
    >>> g = Grasp.preset("fig6")
    >>> s = slip(g, "2*pi/3")            # a break point: k2 = k4 there
    >>> s.binding, s.tie
    ((2, 4), True)
    >>> a = slip(g, np.array([0.0, 2.0, 3.5]))
    >>> a["n"].tolist(), a["contact"].tolist(), a["side"].tolist()
    ([1, 2, 3], [1, 2, 1], [1, 1, -1])
    """
    t = angle_values(theta)
    if isinstance(t, float):
        return _record(_numeric(grasp, np.asarray(t), tie_tol)[()])
    if isinstance(t, np.ndarray):
        return _numeric(grasp, t, tie_tol)
    if grasp.numeric:
        return _record(_numeric(grasp, np.asarray(_as_float(t)), tie_tol)[()])
    return _exact(grasp, t)


def _envelope(grasp: Grasp) -> Any:
    if any(v.free_symbols for v in grasp.params.values()):
        raise SymbolicValueError(
            "the θ-intervals of a symbolic grasp depend on its values; "
            "substitute values first (Grasp.subs)"
        )
    from ..construction import internal_force_diagram

    return internal_force_diagram(grasp)["envelope"]


def _same_circle(grasp: Grasp, V: tuple, n: int, m: int) -> bool:
    d = V[n - 1] - V[m - 1]
    if grasp.numeric:
        scale = max(math.hypot(float(v.x), float(v.y)) for v in V)
        return math.hypot(float(d.x), float(d.y)) <= TIE_TOL * scale
    return decide_sign(d.x) == 0 and decide_sign(d.y) == 0


def slip_intervals(grasp: Grasp) -> tuple[SlipInterval, ...]:
    """The θ-intervals of each binding condition and of the zero-force region.

    Read off the arcs of the outer envelope that the construction builds (§3.3,
    eq. (25), :func:`graspcompass.construction.outer_envelope`): an arc of the
    circle on O V_n is an interval where condition n binds, the envelope staying
    at O is the zero-force region.  The break points are exact for an exact
    grasp (the second intersections of the circles, or O), doubles for a float
    grasp.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> for iv in slip_intervals(Grasp.preset("table1c")):
    ...     print(iv.n, iv.contact, iv.side, iv.theta_start, iv.theta_end)
    2 2 upper atan(3/11) pi - atan(19/5)
    3 1 lower pi - atan(19/5) 5*pi/4
    1 1 upper 5*pi/4 atan(3/11) + 2*pi
    """
    env = _envelope(grasp)
    out = []
    for a in env.arcs:
        same = (
            (a.n,)
            if not a.n
            else tuple(m for m in (1, 2, 3, 4) if m == a.n or _same_circle(grasp, env.V, a.n, m))
        )
        out.append(
            SlipInterval(a.n, a.theta_start, a.theta_end, same, _slide(grasp, a.n) if a.n else None)
        )
    return tuple(out)


def zero_force_intervals(grasp: Grasp) -> tuple[tuple[Any, Any], ...]:
    """The θ-intervals of the zero-force region (k_grasp = 0), possibly none.

    Examples
    --------
    >>> from graspcompass import Grasp
    >>> zero_force_intervals(Grasp.preset("fig6"))
    ()
    """
    return tuple((iv.theta_start, iv.theta_end) for iv in slip_intervals(grasp) if iv.zero_force)
