"""The ``size`` sub-command: the squeeze a two-jaw gripper needs for a part, in newtons.

``graspcompass size --p1 X,Y --p2 X,Y --n1 X,Y --n2 X,Y --com X,Y --mass M --mu1 A
--mu2 B`` sizes the grasp given in one world frame (contact points, inward unit
normals, centre of mass; or ``--outline`` instead of the normals, whose centroid
is the default centre of mass).  A value that starts with a minus sign is written
``--p2=-50mm,0`` (argparse would read ``-50mm,0`` as an option).  Lengths are
metres unless a unit is written
(``100mm``), the mass kilograms (``500g``), accelerations m/s² (``0.5g``),
forces newtons.  It prints the squeeze **per jaw** (each jaw's push, the paper's
F_int, eq. (17)) or ``--per total`` (both jaws, twice it) for the worst
orientation and acceleration, which contact slips and which way, the best
orientation, and the vendor formula beside it; ``--json`` prints an object.

The module imports nothing heavy at its top: the options are checked (pairs,
units, signs) before sympy is loaded, so a usage error is refused at once.
:mod:`graspcompass.cli` reports errors (a ``ValueError`` is one line on stderr,
exit status 2).

Examples
--------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="graspcompass")
>>> sub = parser.add_subparsers(dest="command")
>>> register(sub, lambda p: None)
>>> args = parser.parse_args(["size", "--p1", "50mm,0", "--p2=-50mm,0", "--n1=-1,0",
...                          "--n2", "1,0", "--com", "25mm,0", "--mass", "1kg", "--mu", "0.3"])
>>> args.per, read_pair(args.p1, "--p1", "length")
('jaw', ('50', 'mm', '0', None))
"""

from __future__ import annotations

import argparse
import json
import re
from collections.abc import Callable
from typing import Any

from ..boundary.errors import InputError
from ..sizing.units import split_unit

__all__ = ["add_outline_options", "read_pair", "register", "run"]

_NEGATIVE = re.compile(r"\s*-\s*(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[^\d\s.]*\s*$")
_NAMES = ("jaw1", "jaw2")


def add_outline_options(group: Any, *, shape_required: bool) -> None:
    """``--shape``, ``--shape-unit`` and ``--com``: the part's outline from a drawing and
    its centre of mass, as ``graspcompass size`` and ``graspcompass plan`` read them."""
    group.add_argument(
        "--shape",
        required=shape_required,
        metavar="FILE",
        help="the part's outline from a drawing: an SVG or DXF file; the "
        "closed shape of largest area, curves flattened, in the "
        "drawing's units",
    )
    group.add_argument(
        "--shape-unit",
        metavar="LENGTH",
        help="with --shape: the length of one drawing unit when the file "
        "does not say (default: SVG 96 per inch, DXF mm)",
    )
    group.add_argument(
        "--com", metavar="X,Y", help="centre of mass (default: the outline's centroid)"
    )


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``size`` sub-command to ``subparsers``.

    The part is given in its own world frame, not as a preset, so
    ``add_grasp_options`` is not used; it is taken for the same signature as
    the other sub-command modules.
    """
    del add_grasp_options
    s = subparsers.add_parser(
        "size",
        help="size a gripper: the squeeze in newtons (per jaw or total), worst case, "
        "vendor formula",
        description="The least squeeze a two-jaw gripper needs to hold a part (Ito, Tanaka, "
        "Sasaki 2012, eq. (17)): in the worst orientation and acceleration, in a "
        "given orientation or range of tilts, with the contact that slips and "
        "which way, the best orientation, and the vendor formula m(g + a)·S/μ "
        "beside it. 'Per jaw' is each jaw's push along the line between the "
        "contacts (the paper's internal force F_int); 'total' is both jaws "
        "together, twice it.",
        epilog="Values: exact expressions such as 0.05, 1/20 or sqrt(2)/2. Lengths are metres "
        "unless a unit is written (m, cm, mm, um: 100mm); the mass kg (kg, g, mg, t: "
        "500g); accelerations m/s^2 (or g: 0.5g); forces N (N, kN, mN); angles need "
        "deg or rad. Directions in the output are degrees counter-clockwise from the "
        "frame's -y axis (the paper's θ, eq. (26)): 0 is the frame's down. "
        "exit status: 0; 2 for a user error, including a grasp that is not "
        "force-closure (squeezing harder cannot hold the part).",
    )
    part = s.add_argument_group("the part, in one world frame (right-handed, y up)")
    part.add_argument("--p1", metavar="X,Y", help="contact of jaw 1 (required unless --contact)")
    part.add_argument("--p2", metavar="X,Y", help="contact of jaw 2 (required unless --contact)")
    part.add_argument(
        "--contact",
        action="append",
        metavar="X,Y,NX,NY,MU",
        help="n jaws or fingers (three-jaw grippers, hands): one contact a time "
        "(point, inward normal or one angle, μ); the worst squeeze over all "
        "orientations is F_e max|q| (docs/ncontact.md)",
    )
    part.add_argument("--contacts", metavar="FILE", help="the --contact lines in a file")
    part.add_argument(
        "--effort",
        metavar="NAME",
        help="with --contact: sum-normal (default), max-normal or pair:I,J",
    )
    part.add_argument(
        "--n1", metavar="X,Y", help="inward normal at jaw 1's contact (any nonzero length)"
    )
    part.add_argument(
        "--n2", metavar="X,Y", help="inward normal at jaw 2's contact (any nonzero length)"
    )
    part.add_argument(
        "--outline",
        metavar="X,Y;X,Y;...",
        help="the part's outline (vertices separated by ';'): normals of the "
        "edges the contacts lie on, centroid as the default --com",
    )
    add_outline_options(part, shape_required=False)
    part.add_argument("--mass", required=True, metavar="M", help="mass (kg unless a unit: 500g)")
    part.add_argument("--mu", metavar="MU", help="friction coefficient of both pads")
    part.add_argument("--mu1", metavar="MU", help="friction coefficient at jaw 1")
    part.add_argument("--mu2", metavar="MU", help="friction coefficient at jaw 2")
    load = s.add_argument_group("the load")
    load.add_argument(
        "--g", default="9.80665", metavar="G", help="magnitude of gravity (default 9.80665 m/s^2)"
    )
    load.add_argument(
        "--gravity",
        metavar="X,Y",
        help="gravity's direction in the frame (default: any orientation of the part)",
    )
    load.add_argument(
        "--tilt",
        metavar="ANGLE",
        help="with --gravity: the part may turn by up to ±ANGLE (deg or rad needed: 15deg)",
    )
    load.add_argument(
        "--accel", metavar="A", help="acceleration bound |a| <= A in any direction (m/s^2, or 0.5g)"
    )
    load.add_argument(
        "--accel-vector",
        metavar="X,Y",
        help="with --gravity: a given acceleration of the part, in the frame",
    )
    s.add_argument("--safety", default="1", metavar="S", help="safety factor >= 1 (default 1)")
    s.add_argument(
        "--per",
        choices=("jaw", "total"),
        default="jaw",
        help="report the squeeze per jaw (default) or the total of both jaws",
    )
    s.add_argument(
        "--max-force",
        metavar="F",
        help="the gripper's squeeze (per --per): also "
        "print the least μ (both pads) for which it suffices",
    )
    s.add_argument("--json", action="store_true", help="print a JSON object")


def _split(text: str) -> list[str]:
    """Split at commas outside parentheses (``atan2(1, 2)`` stays whole)."""
    items, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if ch == "," and depth == 0:
            items.append(text[start:i])
            start = i + 1
    items.append(text[start:])
    return items


def read_pair(text: str, option: str, kind: str | None) -> tuple[Any, ...]:
    """``(x, x unit, y, y unit)`` of an ``X,Y`` option, units checked (no import).

    ``kind`` is the quantity (``"length"``, ``"acceleration"``) or None for a
    direction without a unit.
    """
    parts = [p.strip() for p in _split(text)]
    if len(parts) != 2 or not all(parts):
        raise InputError(f"{option}: expected X,Y (two values separated by a comma), got {text!r}")
    out: list[Any] = []
    for p in parts:
        if kind is None:
            out += [p, None]
        else:
            out += list(split_unit(p, kind, option))
    return tuple(out)


def _check_cheap(args: argparse.Namespace) -> None:
    """Every check that needs no sympy: pairs, units, plain negative numbers, combinations."""
    for opt in ("p1", "p2", "com"):
        if getattr(args, opt) is not None:
            read_pair(getattr(args, opt), f"--{opt}", "length")
    for opt in ("n1", "n2", "gravity"):
        if getattr(args, opt) is not None:
            read_pair(getattr(args, opt), f"--{opt}", None)
    if args.accel_vector is not None:
        read_pair(args.accel_vector, "--accel-vector", "acceleration")
    if args.shape is not None:
        if args.outline is not None:
            raise InputError("give the outline as --outline or as --shape FILE, not both")
        if not args.shape.lower().endswith((".svg", ".dxf")):
            raise InputError(f"--shape {args.shape!r}: an outline is read from a .svg or .dxf file")
    elif args.shape_unit is not None:
        raise InputError("--shape-unit goes with --shape FILE")
    if args.outline is not None:
        vertices = args.outline.split(";")
        if len(vertices) < 3:
            raise InputError(
                f"--outline: expected at least 3 vertices X,Y;X,Y;X,Y, got {args.outline!r}"
            )
        for i, v in enumerate(vertices):
            read_pair(v, f"--outline vertex {i + 1}", "length")
    elif (args.n1 is None or args.n2 is None) and args.shape is None:
        raise InputError(
            "give the inward normals (--n1 and --n2) or the part's --outline (or --shape FILE)"
        )
    if args.com is None and args.outline is None and args.shape is None:
        raise InputError("give the centre of mass --com (or an --outline: its centroid)")
    if args.mu is not None and (args.mu1 is not None or args.mu2 is not None):
        raise InputError("give the friction as --mu (both pads) or as --mu1 and --mu2, not both")
    if args.mu is None and (args.mu1 is None or args.mu2 is None):
        raise InputError("give the friction: --mu for both pads, or --mu1 and --mu2")
    if args.accel is not None and args.accel_vector is not None:
        raise InputError(
            "give either --accel (a bound in any direction) or --accel-vector (a "
            "given acceleration), not both"
        )
    if args.accel_vector is not None and args.gravity is None:
        raise InputError("--accel-vector needs --gravity (the same frame as the contacts)")
    if args.tilt is not None and args.gravity is None:
        raise InputError("--tilt needs --gravity (the orientation it tilts from)")
    checks = [
        ("--mass", args.mass, "mass"),
        ("--g", args.g, "acceleration"),
        ("--accel", args.accel, "acceleration"),
        ("--tilt", args.tilt, "angle"),
        ("--max-force", args.max_force, "force"),
        ("--safety", args.safety, None),
    ]
    for opt, text, kind in checks:
        if text is None:
            continue
        if kind is not None:
            split_unit(text, kind, opt)
        if _NEGATIVE.match(text):
            raise InputError(f"{opt} must not be negative, got {text!r}")


def _pair_values(text: str, option: str, kind: str | None) -> tuple[Any, Any]:
    from ..sizing.units import acceleration_value, length_value

    x, y = (p.strip() for p in _split(text))
    if kind is None:
        from ..boundary.expr import ExpressionError, parse_exact

        try:
            return parse_exact(x), parse_exact(y)
        except ExpressionError as exc:
            raise type(exc)(f"{option}: {exc}") from None
    read = length_value if kind == "length" else acceleration_value
    return read(x, f"{option} x"), read(y, f"{option} y")


def _run_ncontact(args: argparse.Namespace) -> int:
    """``size --contact ...``: the worst squeeze of n jaws over all orientations."""
    from ..sizing.ncontact import size_ncontact
    from ._ncontact import grasp_from_args

    for opt in (
        "p1",
        "p2",
        "n1",
        "n2",
        "outline",
        "shape",
        "gravity",
        "tilt",
        "accel_vector",
        "max_force",
        "mu",
        "mu1",
        "mu2",
    ):
        if getattr(args, opt, None) is not None:
            raise InputError(
                f"--{opt.replace('_', '-')} is for two jaws; with --contact give μ in each contact"
            )
    if args.per != "jaw":
        raise InputError("--per is for two jaws; with --contact the effort says what is summed")
    ns = argparse.Namespace(
        contact=args.contact,
        contacts=args.contacts,
        com=args.com or "0,0",
        effort=args.effort or "sum-normal",
    )
    rec = size_ncontact(
        grasp_from_args(ns), args.mass, g=args.g, accel=args.accel, safety=args.safety
    )
    if args.json:
        print(json.dumps(rec, indent=1, allow_nan=False))
        return 0
    what = {"sum-normal": "sum of the normal forces", "max-normal": "largest normal force"}
    print(
        f"{rec['contacts']} contacts, effort {rec['effort']} "
        f"({what.get(rec['effort'], 'the named normal forces')}): worst squeeze "
        f"{rec['worst_N']:.6g} N over all orientations (load {rec['load_N']:.6g} N "
        f"× max|q| = {rec['max_q']:.6g}), at θ = {rec['theta_deg']:.2f}° "
        "(the load's direction from the part's -y axis)"
    )
    return 0


def run(args: argparse.Namespace) -> int:
    """Run ``graspcompass size``; returns the exit status (0).

    Raises
    ------
    ValueError
        A refused option or value, a grasp that is not force-closure
        (:class:`~graspcompass.sizing.NotForceClosureError`) or that
        :func:`~graspcompass.place_grasp` refuses: one line on stderr, exit 2.
    """
    if args.contact or args.contacts:
        return _run_ncontact(args)
    if args.p1 is None or args.p2 is None:
        raise InputError(
            "the following arguments are required: --p1, --p2 (or --contact, once per contact)"
        )
    _check_cheap(args)
    from ..sizing import NotForceClosureError, force_closure, least_mu, size_gripper
    from ..world import FrictionConeError, place_grasp

    contacts = [_pair_values(args.p1, "--p1", "length"), _pair_values(args.p2, "--p2", "length")]
    mu = (args.mu, args.mu) if args.mu is not None else (args.mu1, args.mu2)
    normals = None
    if args.n1 is not None and args.n2 is not None:
        normals = [_pair_values(args.n1, "--n1", None), _pair_values(args.n2, "--n2", None)]
        verdict = force_closure(contacts, normals, mu, names=_NAMES)
        if not verdict.holds:
            raise NotForceClosureError(verdict.message)
    outline = (
        None
        if args.outline is None
        else [
            _pair_values(v, f"--outline vertex {i + 1}", "length")
            for i, v in enumerate(args.outline.split(";"))
        ]
    )
    if args.shape is not None:
        from ..outlines import read_outline

        outline = read_outline(args.shape, unit=args.shape_unit)
    com = None if args.com is None else _pair_values(args.com, "--com", "length")
    try:
        wg = place_grasp(contacts, normals, mu=mu, com=com, outline=outline, names=_NAMES)
    except FrictionConeError as exc:
        raise NotForceClosureError(
            f"not force-closure: squeezing harder cannot hold this part: {exc}"
        ) from None
    gravity = None if args.gravity is None else _pair_values(args.gravity, "--gravity", None)
    accel: Any = args.accel
    if args.accel_vector is not None:
        accel = _pair_values(args.accel_vector, "--accel-vector", "acceleration")
    kw = dict(g=args.g, gravity=gravity, tilt=args.tilt, safety=args.safety, per=args.per)
    s = size_gripper(wg, args.mass, accel=accel, **kw)
    lm = None
    if args.max_force is not None:
        lm = least_mu(wg, args.max_force, args.mass, accel=accel, **kw)
    record = s.to_dict()
    record["force_closure_verdict"] = (
        "force-closure: each friction cone contains the other contact (condition (1))"
    )
    if lm is not None:
        record["least_mu"] = {
            "mu": lm.mu,
            "mu_force_closure": lm.mu_force_closure,
            f"squeeze_infinite_friction_{args.per}_N": lm.squeeze_infinite_friction,
            f"max_force_{args.per}_N": lm.force_limit,
            "message": lm.message,
        }
    from ..boundary._output import finite_record

    finite_record(record, "give the mass, the lengths or the accelerations in other units")
    if args.json:
        print(json.dumps(record, indent=1, allow_nan=False))
        return 0
    print(_text(record, s, lm))
    return 0


def _text(d: dict[str, Any], s: Any, lm: Any) -> str:
    per = "per jaw" if d["per"] == "jaw" else "total (both jaws)"
    head = "PER JAW" if d["per"] == "jaw" else "TOTAL (both jaws)"
    other = (
        "the total of both jaws is twice this"
        if d["per"] == "jaw"
        else "each jaw pushes half of this"
    )
    a = f", |a| <= {d['accel_bound_m_s2']:.4g} m/s^2" if d["accel_bound_m_s2"] else ""
    if d["accel_vector_m_s2"] is not None:
        a += ", a = ({:.4g}, {:.4g}) m/s^2".format(*d["accel_vector_m_s2"])
    lines = [
        f"squeeze {head} in N ({other}); {d['mass_kg']:.6g} kg, g = "
        f"{d['g_m_s2']:.6g} m/s^2{a}, safety factor {d['safety']:.4g}",
        "directions: degrees counter-clockwise from the frame's -y axis (0 = the frame's down)",
        f"worst over all orientations: {d['worst_squeeze_N']:.4g} N {per}, load towards "
        f"{d['worst_direction_deg']:.4g}°; contact {d['slipping_contact']} slips, the part "
        f"sliding towards {d['slip_direction_deg']:.4g}° against that jaw",
    ]
    if d["case"] != "any orientation":
        slip = (
            "nothing slips"
            if d["case_slipping_contact"] is None
            else f"contact {d['case_slipping_contact']} slips"
        )
        load = (
            ""
            if d["load_direction_deg"] is None
            else f", worst load towards {d['load_direction_deg']:.4g}°"
        )
        lines.append(f"{d['case']}: {d['squeeze_N']:.4g} N {per}{load}; {slip}")
    if d["accel_direction_deg"] is not None:
        lines.append(f"worst acceleration direction: {d['accel_direction_deg']:.4g}°")
    lines.append(
        f"best orientation: {d['best_squeeze_N']:.4g} N {per}, with gravity towards "
        f"{d['best_gravity_direction_deg']:.4g}° in the part's frame"
    )
    lines.append(
        f"vendor formula {d['vendor_formula']}: {d['vendor_squeeze_N']:.4g} N {per}; "
        f"the paper's worst case is {d['ratio']:.3g}× that"
    )
    if lm is not None:
        lines.append(f"least friction: {lm.message}")
    return "\n".join(lines)
