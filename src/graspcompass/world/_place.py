"""Placing a grasp: :func:`place_grasp`, from world-frame contacts to the paper's frame.

The contacts, normals (given, or the outline's), friction (μ or ξ, tan ξ = μ,
eq. (22)) and centre of mass are read, condition (1) is checked at each contact
(the friction cone contains the other contact, Fig. 2), and the frame of §2.2.1
is chosen: the x-axis along the line through the contacts, the centre of mass
below it (the rules in :mod:`graspcompass.world`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import sympy as sp

from ..boundary.errors import InputError
from ..boundary.inputs import real_value
from ..geometry.exact import canon, has_float
from ..geometry.trig import sincos
from ..grasp import Grasp, InvalidGraspError
from ._arith import (
    Vec,
    _as_kind,
    _c,
    _deg,
    _dot,
    _fmt,
    _no_symbols,
    _pair,
    _pt,
    _scaled,
    _sign,
    _sqrt,
    _sub,
    _vec,
)
from ._errors import (
    CoincidentContactsError,
    FrictionConeError,
    NormalNotUnitError,
    NormalOutwardError,
    WorldGraspError,
)
from ._grasp import WorldGrasp
from ._outline import _Outline, _outline, _outline_normal, _vertices

__all__ = ["place_grasp"]


def place_grasp(
    contacts: Sequence[Any],
    normals: Sequence[Any] | None = None,
    *,
    mu: Sequence[Any] | None = None,
    xi: Sequence[Any] | None = None,
    com: Any = None,
    outline: Any = None,
    at_vertex: str = "refuse",
    names: tuple[str, str] = ("A", "B"),
) -> WorldGrasp:
    """Build the paper-frame grasp of two world-frame contacts (§2.2.1, condition (1)).

    Parameters
    ----------
    contacts : pair of (x, y)
        The two contact points in the world frame (right-handed).
    normals : pair of (x, y) or None, optional
        Their inward normals (pointing into the object), of any nonzero length
        (scaled to 1, exactly for exact input); an entry may be
        None when ``outline`` is given (the outline's edge normal is taken).
    mu, xi : pair, optional
        The friction of each contact as the coefficient μ or the cone half angle
        ξ (tan ξ = μ, eq. (22); text such as ``"20deg"``); per contact exactly
        one of ``mu[i]``, ``xi[i]`` (the other None).
    com : (x, y), optional
        The centre of mass; default the outline's centroid (uniform density).
    outline : shapely Polygon or sequence of (x, y), optional
        The object's outline: a vertex sequence is read exactly (like the points);
        a shapely polygon's coordinates are floats.
    at_vertex : {"refuse", "bisector"}
        What a contact at a vertex of the outline gets (when its normal is not given).
    names : pair of str
        The contacts' names in messages and in :meth:`WorldGrasp.contact_forces`.

    Returns
    -------
    WorldGrasp
        The paper-frame grasp and the rigid motion between the frames.

    Raises
    ------
    WorldGraspError
        Subclasses name the contact: :class:`FrictionConeError` (condition (1)),
        :class:`NormalOutwardError`, :class:`NormalNotUnitError`,
        :class:`ContactOffOutlineError`, :class:`VertexContactError`,
        :class:`CoincidentContactsError`,
        :class:`OutlineError`.

    Examples
    --------
    A rectangle 4 × 8 held on its long sides, 1 above the centroid (Table I(a), Fig. 7):

    >>> box = [(-2, -4), (2, -4), (2, 4), (-2, 4)]
    >>> wg = place_grasp([(2, 1), (-2, 1)], outline=box, mu=("1", "1.2"))
    >>> wg.grasp == Grasp.preset("table1a"), wg.normals[0]
    (True, (-1, 0))
    >>> place_grasp([(2, 1), (-2, 4)], outline=box, mu=(1, 1))
    Traceback (most recent call last):
    ...
    graspcompass.world.VertexContactError: contact B at (-2, 4) is at a vertex (-2, 4) ...
    """
    if at_vertex not in ("refuse", "bisector"):
        raise InputError(f"at_vertex: expected 'refuse' or 'bisector', got {at_vertex!r}")
    if isinstance(names, (str, bytes)) or not isinstance(names, Sequence) or len(names) != 2:
        raise InputError(
            f"names: expected the two contacts' names, a pair such as "
            f"('A', 'B'), got {str(names)[:40]!r}"
        )
    na, nb = (str(names[0]), str(names[1]))
    if na == nb:
        raise InputError(f"names: the two contacts need different names, got {na!r} twice")
    pts = [_vec(p, f"contact {n}") for p, n in zip(_pair(contacts, "contacts"), (na, nb))]
    given_n = [None, None] if normals is None else list(_pair(normals, "normals"))
    nrm = [
        None if v is None else _vec(v, f"normal of contact {n}") for v, n in zip(given_n, (na, nb))
    ]
    fric = _friction(mu, xi, (na, nb))
    c = None if com is None else _vec(com, "com")
    raw = [v for p in pts for v in p] + [v for n in nrm if n for v in n]
    raw += [v for _, v in fric] + ([] if c is None else list(c))
    vertices = None if outline is None or _is_shapely(outline) else _vertices(outline)
    raw += [v for p in vertices or () for v in p]
    _no_symbols(raw)
    exact = not any(has_float(v) for v in raw) and not _is_shapely(outline)
    pts = [(_as_kind(x, exact), _as_kind(y, exact)) for x, y in pts]
    out = None if outline is None else _outline(outline if vertices is None else vertices, exact)
    if c is None:
        if out is None:
            raise InputError("com: give the centre of mass, or an outline (its centroid)")
        c = out.centroid
    c = (_as_kind(c[0], exact), _as_kind(c[1], exact))
    normals = _normals(pts, nrm, out, at_vertex, (na, nb), exact)
    fric = [(kind, _as_kind(v, exact)) for kind, v in fric]
    return _place(pts, normals, fric, c, (na, nb), exact)


def _is_shapely(outline: Any) -> bool:
    return outline is not None and hasattr(outline, "geom_type")


def _friction(mu: Any, xi: Any, names: tuple[str, str]) -> list[tuple[str, Any]]:
    mus = [None, None] if mu is None else list(_pair(mu, "mu"))
    xis = [None, None] if xi is None else list(_pair(xi, "xi"))
    out = []
    for m, x, n in zip(mus, xis, names):
        if (m is None) == (x is None):
            raise InputError(
                f"contact {n}: give its friction either as mu (coefficient) or "
                "as xi (cone half angle), exactly one of them"
            )
        out.append(
            ("mu", real_value(m, f"mu of contact {n}"))
            if m is not None
            else ("xi", real_value(x, f"xi of contact {n}"))
        )
    return out


def _normals(
    pts: list[Vec],
    nrm: list,
    out: _Outline | None,
    at_vertex: str,
    names: tuple[str, str],
    exact: bool,
) -> list[Vec]:
    result = []
    for p, n, name in zip(pts, nrm, names):
        if out is not None:
            edge_n, _ = _outline_normal(
                out, p, name, "bisector" if n is not None else at_vertex, exact
            )
        if n is None:
            if out is None:
                raise InputError(
                    f"normal of contact {name}: give the inward normal, or an "
                    "outline the contact lies on"
                )
            result.append(edge_n)
            continue
        n = _unit(n, p, name, exact)
        if out is not None and _sign(_dot(n, edge_n), exact) != 1:
            raise NormalOutwardError(
                f"contact {name} at {_pt(p)}: its normal {_pt(n)} points out of the outline "
                f"(the outline's inward normal there is {_pt(edge_n)})"
            )
        result.append(n)
    return result


def _unit(n: Vec, p: Vec, name: str, exact: bool) -> Vec:
    """The direction ``n`` as a unit vector: a normal of any nonzero length, scaled exactly.

    A zero normal, or one whose length is not a finite float, is refused
    (:class:`NormalNotUnitError`).
    """
    n = (_as_kind(n[0], exact), _as_kind(n[1], exact))
    if exact:
        nn = canon(_dot(n, n))
        if _sign(nn, True) != 1:
            raise NormalNotUnitError(
                f"contact {name} at {_pt(p)}: its normal {_pt(n)} is the "
                "zero vector, which has no direction"
            )
        if _sign(nn - 1, True) == 0:
            return n
        return _scaled(n, 1 / _sqrt(nn, True), True)
    length = math.hypot(n[0], n[1])
    if not math.isfinite(length) or length == 0:
        raise NormalNotUnitError(
            f"contact {name} at {_pt(p)}: its normal {_pt(n)} "
            f"{'is the zero vector' if length == 0 else 'is not finite'}"
            ", which has no direction"
        )
    return (n[0] / length, n[1] / length)


def _place(
    pts: list[Vec],
    nrm: list[Vec],
    fric: list[tuple[str, Any]],
    c: Vec,
    names: tuple[str, str],
    exact: bool,
) -> WorldGrasp:
    a, b = pts
    d2 = _dot(_sub(a, b), _sub(a, b))
    if _sign(d2, exact) != 1:
        raise CoincidentContactsError(
            f"contacts {names[0]} and {names[1]} are the same point {_pt(a)}"
        )
    d = _sqrt(d2, exact)
    if exact and not _square_roots_only(d):
        raise WorldGraspError(
            f"the distance between contacts {names[0]} and {names[1]} is {d}, not built from "
            "square roots of rational numbers, which the exact paper frame needs (its lengths "
            "are divided by it): give the coordinates as floats, or exactly with a rational "
            "squared distance"
        )
    for i in (0, 1):
        _condition_1(pts[i], nrm[i], fric[i], pts[1 - i], names[i], names[1 - i], d, exact)
    order = [0, 1]
    ex = _scaled(_sub(a, b), 1 / d, exact)
    ey = (-ex[1], ex[0])
    if _sign(_dot(_sub(a, c), ey), exact) == -1:  # the centre of mass above the line: turn
        order, ex, ey = [1, 0], (-ex[0], -ex[1]), (-ey[0], -ey[1])
    p1, p2 = pts[order[0]], pts[order[1]]
    x1 = canon(_dot(_sub(p1, c), ex)) if exact else _dot(_sub(p1, c), ex)
    x2 = canon(_dot(_sub(c, p2), ex)) if exact else _dot(_sub(c, p2), ex)
    y = canon(_dot(_sub(p1, c), ey)) if exact else abs(_dot(_sub(p1, c), ey))
    n1 = _c((_dot(nrm[order[0]], ex), _dot(nrm[order[0]], ey)), exact)
    n2 = _c((_dot(nrm[order[1]], ex), _dot(nrm[order[1]], ey)), exact)
    # x1 + x2 = |P1 − P2| > 0; x1 <= 0 or x2 <= 0 (the centre of mass projecting beyond
    # a contact) is a grasp of the model too: eqs. (12)-(39) only divide by x1 + x2
    atan2 = sp.atan2 if exact else math.atan2
    phi1 = atan2(-n1[0], -n1[1])  # n1 = (-sin φ1, -cos φ1)
    phi2 = atan2(n2[0], -n2[1])  # n2 = (sin φ2, -cos φ2)
    kw = {}
    for i, k in ((1, order[0]), (2, order[1])):
        kind, v = fric[k]
        kw[f"{kind}{i}"] = v
    p_names = (names[order[0]], names[order[1]])
    try:
        g = Grasp(x1, x2, y, phi1, phi2, **kw)
    except InvalidGraspError as exc:  # what the world checks did not catch (float margins)
        raise WorldGraspError(
            f"{exc} [contact 1 (P1) is {p_names[0]}, contact 2 (P2) is {p_names[1]}]"
        ) from None
    return WorldGrasp(
        g,
        c,
        ex,
        ey,
        atan2(ex[1], ex[0]),
        p_names,
        (p1, p2),
        (nrm[order[0]], nrm[order[1]]),
        names[0],
    )


def _square_roots_only(v: sp.Expr) -> bool:
    return all(
        not a.is_Pow
        or a.exp.is_Integer
        or (a.exp in (sp.S.Half, -sp.S.Half) and a.base.is_Rational)
        for a in sp.preorder_traversal(v)
    )


def _condition_1(
    p: Vec, n: Vec, fric: tuple[str, Any], q: Vec, name: str, other: str, d: Any, exact: bool
) -> None:
    """Condition (1) at contact p: the angle between n and q - p is below ξ."""
    kind, v = fric
    cos_a = _dot(n, _sub(q, p)) / d  # cosine of the angle between n and the line to q
    if exact:
        cos_xi = sincos(v)[1] if kind == "xi" else 1 / sp.sqrt(1 + v**2)
        xi = v if kind == "xi" else sp.atan(v)
    else:
        xi = float(v) if kind == "xi" else math.atan(float(v))
        cos_xi = math.cos(xi)
    if _sign(cos_a, exact) in (-1, 0):
        raise NormalOutwardError(
            f"contact {name} at {_pt(p)}: its inward normal {_pt(n)} points away from contact "
            f"{other} at {_pt(q)} (at {_deg(math.acos(max(-1, min(1, float(cos_a)))))} from "
            "the direction to it): is it the outward normal? An inward normal points into "
            "the object (condition (1): the friction cone must contain the other contact)"
        )
    if _sign(cos_a - cos_xi, exact) in (-1, 0):
        shown = f"μ = {_fmt(v)}, " if kind == "mu" else ""
        raise FrictionConeError(
            f"contact {name} at {_pt(p)}: its friction cone ({shown}half angle {_deg(xi)}) "
            f"does not contain contact {other} at {_pt(q)}: the inward normal {_pt(n)} makes "
            f"{_deg(math.acos(max(-1, min(1, float(cos_a)))))} with the direction to "
            f"contact {other} (condition (1): each friction cone must contain the other "
            "contact; more friction or a normal closer to the line through the contacts)"
        )
