"""Grasps in the user's frame: from world-frame contacts to the paper's frame and back.

The paper works in the object frame of §2.2.1 (Fig. 2): the origin at the centre
of mass O, the y-axis perpendicular to the line through the two contacts,
``P1 = (x1, y)`` and ``P2 = (-x2, y)`` with ``x1, x2 > 0`` and ``y >= 0`` (here
``x1 + x2 > 0``: the centre of mass may project beyond a contact, issue 13 §1), the
inward normal at P1 at the angle φ1 clockwise from the negative y-axis,
``n1 = (-sin φ1, -cos φ1)``, at P2 at φ2 counter-clockwise,
``n2 = (sin φ2, -cos φ2)`` (the columns of L in eq. (5)).

:func:`place_grasp` takes what a designer has in a CAD frame (a right-handed
world frame, y up when x points right): two contact points, their inward unit
normals or the outline they lie on, the friction of each contact (μ or the cone
half angle ξ, tan ξ = μ, eq. (22)) and the centre of mass (given, or the
outline's centroid for a uniform density).  It returns a :class:`WorldGrasp`:
the paper-frame :class:`~graspcompass.Grasp` and the rigid motion (a rotation
and a translation, never a reflection) between the two frames, so directions
and forces computed in the paper's frame are read in the world frame.

How the frame is chosen.  The x-axis runs along the line through the contacts,
the y-axis is its counter-clockwise perpendicular.  Of the two directions of the
line, the one that gives the contacts ``y >= 0`` is taken: P1 is the
contact that makes the line's direction P2 → P1 point along +x with the centre
of mass below the line.  When the centre of mass lies on the line (``y = 0``)
both directions qualify and P1 is the first contact given.  The friction of a
contact follows it, whichever of P1, P2 it becomes.

Outlines.  A contact on an edge of the outline takes that edge's inward unit
normal.  At a vertex the normal is undefined: ``at_vertex="refuse"`` (the
default) raises :class:`VertexContactError`, ``at_vertex="bisector"`` takes the
normalised sum of the two adjacent edges' inward normals; a normal given for
that contact (``normals=(n, None)``) is used instead of either.

Exact input stays exact: text (``"1/20"``, ``"sqrt(2)/2"``), ints, Fractions and
sympy numbers give an exact grasp (the lengths then hold square roots of
rationals, the contacts' distance ``sqrt(...)``); a float anywhere (a shapely
outline's coordinates are floats) selects the numeric path for all values.

Angles in the world frame use the paper's convention for θ (eq. (26)): measured
counter-clockwise from the world's negative y-axis, so the world's gravity
``(0, -1)`` is at θ = 0.  A paper-frame θ is the world angle ``θ + β``, β the
angle of the paper's x-axis in the world frame (:attr:`WorldGrasp.beta`).

Examples
--------
>>> wg = place_grasp([("3", "5"), ("-1", "5")], [(-1, 0), (1, 0)], mu=("1", "6/5"),
...                  com=("1", "4"))
>>> wg.grasp == Grasp(2, 2, 1, "pi/2", "pi/2", mu1=1, mu2="6/5")  # Table I(a)
True
>>> wg.internal_force((0, -10))  # 10 N straight down in the world: k_grasp(0) = 2 (x1 = 2)
5
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import sympy as sp

from .errors import InputError, SymbolicValueError, WrongTypeError
from .geometry.exact import canon, decide_sign, has_float
from .geometry.trig import sincos
from .grasp import Grasp, InvalidGraspError
from .inputs import real_value

__all__ = [
    "CenterOfMassError",
    "CoincidentContactsError",
    "ContactOffOutlineError",
    "FrictionConeError",
    "NormalNotUnitError",
    "NormalOutwardError",
    "OutlineError",
    "VertexContactError",
    "WorldGrasp",
    "WorldGraspError",
    "place_grasp",
]


class WorldGraspError(InvalidGraspError):
    """World-frame data that do not make a grasp; the message names the contact."""


class CoincidentContactsError(WorldGraspError):
    """The two contacts are the same point."""


class NormalNotUnitError(WorldGraspError):
    """A given normal is not a unit vector (floats: within 1e-9)."""


class FrictionConeError(WorldGraspError):
    """Condition (1) fails: a contact's friction cone does not contain the other contact."""


class NormalOutwardError(FrictionConeError):
    """A normal points out of the object (away from the other contact or the outline)."""


class CenterOfMassError(WorldGraspError):
    """Not raised any more: the centre of mass may project beyond a contact (x1 <= 0 or
    x2 <= 0, issue 13 §1).  Kept so that code catching it keeps working."""


class OutlineError(WorldGraspError):
    """An outline that is not a simple polygon with area."""


class ContactOffOutlineError(WorldGraspError):
    """A contact that does not lie on the outline's boundary."""


class VertexContactError(WorldGraspError):
    """A contact at a vertex of the outline, where the normal is undefined."""


#: Floats: a normal is unit when ``|n·n - 1| <= UNIT_TOL``; a contact is on the outline
#: (at a vertex) when within ``ON_OUTLINE_TOL`` times the outline's size.
UNIT_TOL = 1e-9
ON_OUTLINE_TOL = 1e-9

Vec = tuple[Any, Any]


# -- arithmetic on exact values or floats --------------------------------------------
def _sqrt(v: Any, exact: bool) -> Any:
    return canon(sp.sqrtdenest(sp.sqrt(v))) if exact else math.sqrt(v)


def _sign(v: Any, exact: bool) -> int | None:
    return decide_sign(canon(v)) if exact else (v > 0) - (v < 0)


def _dot(a: Vec, b: Vec) -> Any:
    return a[0] * b[0] + a[1] * b[1]


def _cross(a: Vec, b: Vec) -> Any:
    return a[0] * b[1] - a[1] * b[0]


def _sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _scaled(a: Vec, k: Any, exact: bool) -> Vec:
    return _c((a[0] * k, a[1] * k), exact)


def _c(a: Vec, exact: bool) -> Vec:
    return (canon(a[0]), canon(a[1])) if exact else (float(a[0]), float(a[1]))


def _fmt(v: Any) -> str:
    return f"{v:.6g}" if isinstance(v, float) else str(v)


def _pt(p: Vec) -> str:
    return f"({_fmt(p[0])}, {_fmt(p[1])})"


def _deg(a: Any) -> str:
    return f"{math.degrees(float(a)):.4g}°"


# -- reading the inputs ----------------------------------------------------------------
def _pair(value: Any, what: str) -> tuple[Any, Any]:
    if hasattr(value, "geom_type") and getattr(value, "geom_type", None) == "Point":
        return (value.x, value.y)  # a shapely Point
    if isinstance(value, (str, bytes, dict)) or (
            not isinstance(value, Sequence) and not hasattr(value, "__array__")):
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {type(value).__name__}")
    items = list(value)
    if len(items) != 2:
        raise WrongTypeError(f"{what}: expected a pair (x, y), got {len(items)} values")
    return items[0], items[1]


def _vec(value: Any, what: str) -> Vec:
    x, y = _pair(value, what)
    return (real_value(x, f"{what} x"), real_value(y, f"{what} y"))


def _no_symbols(values: list[Any]) -> None:
    for v in values:
        if isinstance(v, sp.Basic) and v.free_symbols:
            raise SymbolicValueError(
                f"world-frame data must be numbers, got {v} (for symbols use Grasp)")


def _as_kind(v: Any, exact: bool) -> Any:
    return canon(v) if exact else float(v)


# -- outlines ----------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class _Outline:
    rings: tuple[tuple[Vec, ...], ...]  # material on the left of every edge
    centroid: Vec
    size: float  # largest |coordinate|, the scale of the float tolerance


def _outline(outline: Any, exact: bool) -> _Outline:
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    if isinstance(outline, Polygon):
        if outline.is_empty or not outline.is_valid or outline.area <= 0:
            raise OutlineError("the outline is not a valid polygon with area (shapely "
                               "is_valid is False, or it is empty)")
        poly = orient(outline, 1.0)  # exterior counter-clockwise, holes clockwise
        rings = tuple(tuple((float(x), float(y)) for x, y in list(r.coords)[:-1])
                      for r in (poly.exterior, *poly.interiors))
        c = poly.centroid
        size = max(abs(v) for r in rings for p in r for v in p)
        return _Outline(rings, (float(c.x), float(c.y)), size)
    pts = [(_as_kind(x, exact), _as_kind(y, exact)) for x, y in outline]
    if len(pts) >= 2 and pts[0] == pts[-1]:
        pts = pts[:-1]  # a closed ring given with its first vertex repeated
    if len(pts) < 3 or not Polygon([(float(x), float(y)) for x, y in pts]).is_valid:
        raise OutlineError("the outline must be a simple polygon of at least 3 vertices "
                           "(its edges must not cross)")
    # the centroid of a uniform polygon (shoelace sums), exact for exact vertices
    a2 = cx = cy = 0
    for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
        w = x0 * y1 - x1 * y0
        a2, cx, cy = a2 + w, cx + (x0 + x1) * w, cy + (y0 + y1) * w
    if _sign(a2, exact) == -1:
        pts = pts[::-1]
    elif _sign(a2, exact) == 0:
        raise OutlineError("the outline has zero area")
    centroid = _c((cx / (3 * a2), cy / (3 * a2)), exact)
    size = max(abs(float(v)) for p in pts for v in p)
    return _Outline((tuple(pts),), centroid, size)


def _vertices(outline: Any) -> list[Vec]:
    """The vertices of an outline given as a sequence, through the input boundary."""
    if isinstance(outline, (str, bytes, dict)):
        raise WrongTypeError("outline: expected a shapely Polygon or a sequence of (x, y) "
                             f"vertices, got {type(outline).__name__}")
    try:
        return [_vec(p, f"outline vertex {i}") for i, p in enumerate(outline)]
    except TypeError:
        raise WrongTypeError("outline: expected a shapely Polygon or a sequence of (x, y) "
                             f"vertices, got {type(outline).__name__}") from None


def _inward(p: Vec, q: Vec, exact: bool) -> Vec:
    """Unit normal to the edge p → q on its left (the material's side)."""
    e = _sub(q, p)
    return _scaled((-e[1], e[0]), 1 / _sqrt(_dot(e, e), exact), exact)


def _outline_normal(out: _Outline, x: Vec, name: str, at_vertex: str, exact: bool
                    ) -> tuple[Vec, bool]:
    """The inward normal of the outline at contact ``x`` and whether x is a vertex."""
    tol = ON_OUTLINE_TOL * max(out.size, 1.0)
    for ring in out.rings:  # vertices first: a vertex also ends two edges
        for i, p in enumerate(ring):
            if not _near(x, p, tol, exact):
                continue
            if at_vertex != "bisector":
                raise VertexContactError(
                    f"contact {name} at {_pt(x)} is at a vertex {_pt(p)} of the outline, "
                    "where the normal is undefined: move it onto an edge, give its normal "
                    "(normals=...), or pass at_vertex='bisector'")
            a = _inward(ring[i - 1], p, exact)
            b = _inward(p, ring[(i + 1) % len(ring)], exact)
            s = (a[0] + b[0], a[1] + b[1])
            if _sign(_dot(s, s), exact) != 1:
                raise VertexContactError(f"contact {name} at {_pt(x)}: the outline "
                                         "folds back at this vertex (no bisector)")
            return _scaled(s, 1 / _sqrt(_dot(s, s), exact), exact), True
    for ring in out.rings:
        for p, q in zip(ring, ring[1:] + ring[:1]):
            if _on_segment(x, p, q, tol, exact):
                return _inward(p, q, exact), False
    raise ContactOffOutlineError(
        f"contact {name} at {_pt(x)} does not lie on the outline"
        + ("" if exact else f" (tolerance {tol:.2g})"))


def _near(x: Vec, p: Vec, tol: float, exact: bool) -> bool:
    if exact:
        return canon(x[0] - p[0]) == 0 and canon(x[1] - p[1]) == 0
    return math.hypot(x[0] - p[0], x[1] - p[1]) <= tol


def _on_segment(x: Vec, p: Vec, q: Vec, tol: float, exact: bool) -> bool:
    e, r = _sub(q, p), _sub(x, p)
    t = _dot(r, e)
    if exact:
        return (_sign(_cross(e, r), True) == 0 and _sign(t, True) in (0, 1)
                and _sign(_dot(e, e) - t, True) in (0, 1))
    ee = _dot(e, e)
    u = min(max(t / ee, 0.0), 1.0)
    return math.hypot(r[0] - u * e[0], r[1] - u * e[1]) <= tol


# -- the placed grasp --------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class WorldGrasp:
    """A paper-frame grasp with the rigid motion that places it in the world frame.

    A world point ``w`` has paper coordinates ``((w - origin)·ex, (w - origin)·ey)``;
    a paper point ``p`` is at ``origin + p.x ex + p.y ey`` in the world.

    Attributes
    ----------
    grasp : Grasp
        The grasp in the paper's frame (§2.2.1).
    origin : tuple
        The centre of mass O in world coordinates.
    ex, ey : tuple
        The paper's x- and y-axis as world unit vectors (``ey`` is ``ex`` turned
        counter-clockwise by a quarter turn: a rotation, never a reflection).
    beta : sympy.Expr or float
        The angle of ``ex`` from the world's x-axis (counter-clockwise): a
        paper-frame angle θ (eq. (26)) is the world angle ``θ + beta``.
    names : tuple of str
        The names of the paper's P1 and P2 (``("B", "A")`` when the contacts swapped).
    contacts, normals : tuple
        The world contact points and inward unit normals, as P1, P2.
    """

    grasp: Grasp
    origin: Vec
    ex: Vec
    ey: Vec
    beta: Any
    names: tuple[str, str]
    contacts: tuple[Vec, Vec]
    normals: tuple[Vec, Vec]

    @property
    def exact(self) -> bool:
        """True for an exact grasp, False on the numeric path (floats)."""
        return not self.grasp.numeric

    @property
    def swapped(self) -> bool:
        """True when the second contact given became the paper's P1."""
        return self.names[0] != self._given_first

    _given_first: str = dataclasses.field(default="A", repr=False)

    def to_paper(self, point: Any) -> Vec:
        """Paper-frame coordinates of a world point.

        Examples
        --------
        >>> wg = place_grasp([(3, 5), (-1, 5)], [(-1, 0), (1, 0)], mu=(1, 1), com=(1, 4))
        >>> wg.to_paper((3, 5)), wg.to_world((2, 1))
        ((2, 1), (3, 5))
        """
        p, num = self._read(point, "point")
        o, ex, ey = self._frame(num)
        w = _sub(p, o)
        return _c((_dot(w, ex), _dot(w, ey)), not num)

    def to_world(self, point: Any) -> Vec:
        """World coordinates of a paper-frame point."""
        p, num = self._read(point, "point")
        o, ex, ey = self._frame(num)
        return _c((o[0] + p[0] * ex[0] + p[1] * ey[0], o[1] + p[0] * ex[1] + p[1] * ey[1]),
                  not num)

    def vector_to_paper(self, vector: Any) -> Vec:
        """Paper-frame components of a world vector (a force, a direction)."""
        v, num = self._read(vector, "vector")
        _, ex, ey = self._frame(num)
        return _c((_dot(v, ex), _dot(v, ey)), not num)

    def vector_to_world(self, vector: Any) -> Vec:
        """World components of a paper-frame vector."""
        v, num = self._read(vector, "vector")
        _, ex, ey = self._frame(num)
        return _c((v[0] * ex[0] + v[1] * ey[0], v[0] * ex[1] + v[1] * ey[1]), not num)

    def theta_to_world(self, theta: Any) -> Any:
        """The world angle of the paper-frame direction e(θ) (eq. (26)): ``θ + beta``.

        Both angles are counter-clockwise from the negative y-axis of their frame;
        a float θ (or a float grasp) gives a float.

        Examples
        --------
        >>> wg = place_grasp([(0, 1), (0, -1)], [(0, -1), (0, 1)], mu=(1, 1), com=(-1, 0))
        >>> wg.names, wg.ey  # the contacts swapped: the paper's y-axis is the world's +x
        (('B', 'A'), (1, 0))
        >>> wg.beta, wg.theta_to_world(0)  # the paper's "down" (θ = 0) is the world's -x
        (-pi/2, -pi/2)
        """
        t = real_value(theta, "theta")
        return t + self.beta if self._exact_value(t) else float(t) + float(self.beta)

    def theta_to_paper(self, theta_world: Any) -> Any:
        """The paper-frame θ of a world angle: ``theta_world - beta``."""
        t = real_value(theta_world, "theta_world")
        return t - self.beta if self._exact_value(t) else float(t) - float(self.beta)

    def world_degrees(self, theta: Any) -> float:
        """The world angle of a paper-frame θ in degrees, in [0, 360): for reports.

        Examples
        --------
        >>> wg = place_grasp([(0, 1), (0, -1)], [(0, -1), (0, 1)], mu=(1, 1), com=(-1, 0))
        >>> wg.world_degrees(0), wg.world_degrees("pi/2")  # the paper's down, its +x
        (270.0, 0.0)
        """
        return math.degrees(float(self.theta_to_world(theta))) % 360.0

    def external_force(self, force: Any) -> tuple[Any, Any]:
        """``(θ, F_e)`` in the paper's frame of a world external force vector at O.

        θ is the paper-frame angle of eq. (26) (``e(θ) = (sin θ, -cos θ)``) and F_e
        the magnitude; exact for an exact grasp and force, floats when either has a
        float.  A zero force is refused.
        """
        f = self.vector_to_paper(force)
        num = isinstance(f[0], float)
        fe = _sqrt(_dot(f, f), not num)
        if _sign(fe, not num) != 1:
            raise InputError("force: the external force must not be zero")
        if num:
            return math.atan2(f[0], -f[1]), fe
        return sp.atan2(f[0], -f[1]), fe

    def internal_force(self, force: Any) -> Any:
        """The least internal force (squeeze along P1P2) for a world external force at O.

        ``F_int = k_grasp(θ)/(x1 + x2) · F_e``, eqs. (17), (25), with θ and F_e read
        off the world vector.  Exact for an exact grasp and force, else a float.
        """
        theta, fe = self.external_force(force)
        return self.grasp.internal_force(theta, fe)

    def contact_forces(self, force: Any) -> dict[str, Vec]:
        """The contact forces at the least internal force, as world vectors by contact name.

        ``F = F_T + k_grasp F_N`` (eq. (16)) in the paper's frame, the normal and
        tangential parts put together with ``n1 = (-s1, -c1)``, ``t1 = (-c1, s1)``,
        ``n2 = (s2, -c2)``, ``t2 = (c2, s2)`` (the columns of L, eq. (5)), then
        turned into the world frame.  They balance the external force and its
        moment about O.  Exact for an exact grasp and force, else floats.
        """
        theta, fe = self.external_force(force)
        g = self.grasp
        F = g.contact_forces(theta, g.k_grasp(theta), fe)
        sc: tuple[Any, ...] = (g.s1, g.c1, g.s2, g.c2)
        if isinstance(theta, float):
            F, sc = [float(v) for v in F], tuple(float(v) for v in sc)
        N1, F1, N2, F2 = F
        s1, c1, s2, c2 = sc
        f1 = (-N1 * s1 - F1 * c1, -N1 * c1 + F1 * s1)
        f2 = (N2 * s2 + F2 * c2, -N2 * c2 + F2 * s2)
        return {self.names[0]: self.vector_to_world(f1), self.names[1]: self.vector_to_world(f2)}

    def _exact_value(self, v: Any) -> bool:
        return self.exact and not has_float(v)

    def _read(self, v: Any, what: str) -> tuple[Vec, bool]:
        """A world or paper vector from outside, and whether it takes the numeric path."""
        p = _vec(v, what)
        _no_symbols(list(p))
        if self._exact_value(p[0]) and self._exact_value(p[1]):
            return p, False
        return (float(p[0]), float(p[1])), True

    def _frame(self, numeric: bool) -> tuple[Vec, Vec, Vec]:
        """The origin and axes, as floats for the numeric path."""
        if not numeric:
            return self.origin, self.ex, self.ey
        return tuple((float(v[0]), float(v[1])) for v in (self.origin, self.ex, self.ey))


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
        Their inward unit normals (pointing into the object); an entry may be
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
    na, nb = (str(names[0]), str(names[1]))
    if na == nb:
        raise InputError(f"names: the two contacts need different names, got {na!r} twice")
    pts = [_vec(p, f"contact {n}") for p, n in zip(_pair(contacts, "contacts"), (na, nb))]
    given_n = [None, None] if normals is None else list(_pair(normals, "normals"))
    nrm = [None if v is None else _vec(v, f"normal of contact {n}")
           for v, n in zip(given_n, (na, nb))]
    fric = _friction(mu, xi, (na, nb))
    c = None if com is None else _vec(com, "com")
    raw = [v for p in pts for v in p] + [v for n in nrm if n for v in n]
    raw += [v for _, v in fric] + ([] if c is None else list(c))
    vertices = None if outline is None or _is_shapely(outline) else _vertices(outline)
    raw += [v for p in vertices or () for v in p]
    _no_symbols(raw)
    exact = not any(has_float(v) for v in raw) and not _is_shapely(outline)
    pts = [(_as_kind(x, exact), _as_kind(y, exact)) for x, y in pts]
    out = None if outline is None else _outline(
        outline if vertices is None else vertices, exact)
    if c is None:
        if out is None:
            raise InputError("com: give the centre of mass, or an outline (its centroid)")
        c = out.centroid
    c = (_as_kind(c[0], exact), _as_kind(c[1], exact))
    nrm = _normals(pts, nrm, out, at_vertex, (na, nb), exact)
    fric = [(kind, _as_kind(v, exact)) for kind, v in fric]
    return _place(pts, nrm, fric, c, (na, nb), exact)


def _is_shapely(outline: Any) -> bool:
    return outline is not None and hasattr(outline, "geom_type")


def _friction(mu: Any, xi: Any, names: tuple[str, str]) -> list[tuple[str, Any]]:
    mus = [None, None] if mu is None else list(_pair(mu, "mu"))
    xis = [None, None] if xi is None else list(_pair(xi, "xi"))
    out = []
    for m, x, n in zip(mus, xis, names):
        if (m is None) == (x is None):
            raise InputError(f"contact {n}: give its friction either as mu (coefficient) or "
                             "as xi (cone half angle), exactly one of them")
        out.append(("mu", real_value(m, f"mu of contact {n}")) if m is not None
                   else ("xi", real_value(x, f"xi of contact {n}")))
    return out


def _normals(pts: list[Vec], nrm: list, out: _Outline | None, at_vertex: str,
             names: tuple[str, str], exact: bool) -> list[Vec]:
    result = []
    for p, n, name in zip(pts, nrm, names):
        if out is not None:
            edge_n, _ = _outline_normal(out, p, name, "bisector" if n is not None else at_vertex,
                                        exact)
        if n is None:
            if out is None:
                raise InputError(f"normal of contact {name}: give the inward normal, or an "
                                 "outline the contact lies on")
            result.append(edge_n)
            continue
        n = (_as_kind(n[0], exact), _as_kind(n[1], exact))
        nn = _dot(n, n)
        unit = _sign(nn - 1, True) == 0 if exact else abs(nn - 1) <= UNIT_TOL
        if not unit:
            raise NormalNotUnitError(
                f"contact {name} at {_pt(p)}: its normal {_pt(n)} is not a unit vector "
                f"(length {_fmt(math.sqrt(float(nn)))}); divide it by its length")
        if not exact:
            n = _scaled(n, 1 / math.sqrt(nn), False)
        if out is not None and _sign(_dot(n, edge_n), exact) != 1:
            raise NormalOutwardError(
                f"contact {name} at {_pt(p)}: its normal {_pt(n)} points out of the outline "
                f"(the outline's inward normal there is {_pt(edge_n)})")
        result.append(n)
    return result


def _place(pts: list[Vec], nrm: list[Vec], fric: list[tuple[str, Any]], c: Vec,
           names: tuple[str, str], exact: bool) -> WorldGrasp:
    a, b = pts
    d2 = _dot(_sub(a, b), _sub(a, b))
    if _sign(d2, exact) != 1:
        raise CoincidentContactsError(f"contacts {names[0]} and {names[1]} are the same point "
                                      f"{_pt(a)}")
    d = _sqrt(d2, exact)
    if exact and not _square_roots_only(d):
        raise WorldGraspError(
            f"the distance between contacts {names[0]} and {names[1]} is {d}, not built from "
            "square roots of rational numbers, which the exact paper frame needs (its lengths "
            "are divided by it): give the coordinates as floats, or exactly with a rational "
            "squared distance")
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
        raise WorldGraspError(f"{exc} [contact 1 (P1) is {p_names[0]}, contact 2 (P2) is "
                              f"{p_names[1]}]") from None
    return WorldGrasp(g, c, ex, ey, atan2(ex[1], ex[0]), p_names, (p1, p2),
                      (nrm[order[0]], nrm[order[1]]), names[0])


def _square_roots_only(v: sp.Expr) -> bool:
    return all(not a.is_Pow or a.exp.is_Integer or (a.exp in (sp.S.Half, -sp.S.Half)
                                                    and a.base.is_Rational)
               for a in sp.preorder_traversal(v))


def _condition_1(p: Vec, n: Vec, fric: tuple[str, Any], q: Vec, name: str, other: str,
                 d: Any, exact: bool) -> None:
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
            "the object (condition (1): the friction cone must contain the other contact)")
    if _sign(cos_a - cos_xi, exact) in (-1, 0):
        shown = f"μ = {_fmt(v)}, " if kind == "mu" else ""
        raise FrictionConeError(
            f"contact {name} at {_pt(p)}: its friction cone ({shown}half angle {_deg(xi)}) "
            f"does not contain contact {other} at {_pt(q)}: the inward normal {_pt(n)} makes "
            f"{_deg(math.acos(max(-1, min(1, float(cos_a)))))} with the direction to "
            f"contact {other} (condition (1): each friction cone must contain the other "
            "contact; more friction or a normal closer to the line through the contacts)")
