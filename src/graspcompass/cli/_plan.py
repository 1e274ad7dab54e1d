"""``graspcompass plan``: choose the contacts of a two-jaw grasp on a drawn outline (issue 13 §3).

Reads the part from an SVG or DXF drawing (:func:`graspcompass.outlines.read_outline`),
ranks the pairs of contacts sampled along its edges by the squeeze that holds it in
every orientation (:func:`graspcompass.planning.plan_contacts`; Ito, Tanaka, Sasaki
2012, eqs. (17), (28)-(39) and condition (1)) and prints the best pairs, or JSON, and
optionally draws them.  Nothing heavy is imported at module top: the option checks
run before numpy, sympy or shapely are loaded.

Examples
--------
>>> import argparse
>>> sub = argparse.ArgumentParser().add_subparsers(dest="command")
>>> register(sub, lambda p: None)
>>> args = sub.choices["plan"].parse_args(["--shape", "part.svg", "--samples", "40"])
>>> args.samples, args.top, args.mu
(40, 5, '0.5')
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Callable
from typing import Any

from ..boundary.errors import InputError, InputTooLargeError
from ..sizing.units import split_unit
from ._size import add_outline_options, read_pair

__all__ = ["MAX_SAMPLES", "register", "run"]

#: Most contacts sampled: ``MAX_SAMPLES (MAX_SAMPLES − 1) / 2`` pairs is within
#: :data:`graspcompass.planning.MAX_PAIRS` (20,000).
MAX_SAMPLES = 200
_MAX_TOP = 1000
_MAX_EXACT = 50


def register(subparsers: Any, add_grasp_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add the ``plan`` sub-command to ``subparsers`` (``add_grasp_options`` is not used)."""
    del add_grasp_options
    s = subparsers.add_parser(
        "plan",
        help="choose the contacts on a drawn outline: pairs ranked by the worst-case "
        "squeeze in newtons",
        description="Sample contact points along the edges of a part's outline (an SVG or DXF "
        "drawing), form every pair, and rank the force-closure pairs (condition "
        "(1): each friction cone contains the other contact) by the squeeze that "
        "holds the part in every orientation, m(g + A)·S·max_n |V_n|/(x1 + x2) per "
        "jaw (Ito, Tanaka, Sasaki 2012, eqs. (17), (28)-(39)).",
        epilog="Values: lengths in metres unless a unit is written (mm, cm, m); the mass kg "
        "(kg, g: 500g); accelerations m/s^2 (or g). Contacts are printed in mm in the "
        "drawing's frame (y up). Squeezes are per jaw (the paper's internal force) "
        "unless --per total. The ranking is over the sampled points (no vertex is "
        f"sampled); --samples at most {MAX_SAMPLES} ({MAX_SAMPLES * (MAX_SAMPLES - 1) // 2}"
        " pairs). exit status: 0; 2 for a user error, including an outline on which no "
        "sampled pair is force-closure.",
    )
    add_outline_options(s, shape_required=True)
    s.add_argument(
        "--mass",
        default="1kg",
        metavar="M",
        help="mass (kg unless a unit: 500g; default 1kg, so N per kg)",
    )
    s.add_argument(
        "--mu",
        default="0.5",
        metavar="MU",
        help="friction coefficient of both pads (default 0.5: give yours)",
    )
    s.add_argument("--g", default="9.80665", metavar="G", help="gravity (default 9.80665 m/s^2)")
    s.add_argument(
        "--accel", metavar="A", help="acceleration bound |a| <= A in any direction (m/s^2, or 0.5g)"
    )
    s.add_argument("--safety", default="1", metavar="S", help="safety factor >= 1 (default 1)")
    s.add_argument(
        "--per",
        choices=("jaw", "total"),
        default="jaw",
        help="the squeeze per jaw (default) or of both jaws together",
    )
    s.add_argument(
        "--gravity",
        metavar="X,Y",
        help="gravity's direction in the drawing's frame "
        "(y up): rank by the worst case in that orientation (default: every "
        "orientation)",
    )
    s.add_argument(
        "--tilt",
        metavar="ANGLE",
        help="with --gravity: the part may turn by up to ±ANGLE (deg or rad needed: 15deg)",
    )
    s.add_argument(
        "--exact",
        type=int,
        default=3,
        metavar="K",
        help="optimise the edge pairs of the K best sampled pairs over the whole "
        "edges, with a proof (branch and bound, over the orientations asked; 0 "
        f"to {_MAX_EXACT}, default 3)",
    )
    s.add_argument(
        "--tol",
        default="1e-6",
        metavar="T",
        help="relative tolerance of those proofs (default 1e-6)",
    )
    s.add_argument(
        "--samples",
        type=int,
        default=120,
        metavar="N",
        help=f"contact points along the outline, 3 to {MAX_SAMPLES} (default 120)",
    )
    s.add_argument(
        "--top",
        type=int,
        default=5,
        metavar="K",
        help=f"how many of the best pairs to print, 1 to {_MAX_TOP} (default 5)",
    )
    s.add_argument(
        "--jaws",
        type=int,
        choices=(2, 3, 4),
        default=2,
        help="jaws of the gripper (default 2); 3 or 4: rank sets of sampled contacts "
        "by the worst total squeeze over all orientations, F_e max|q| "
        "(docs/ncontact.md; --per, --gravity, --tilt, --exact do not apply)",
    )
    s.add_argument("--json", action="store_true", help="print a JSON object")
    s.add_argument(
        "--draw",
        metavar="FILE",
        help="also draw the outline, the best pairs with "
        "their friction cones and a heat map of the squeeze (PNG, SVG or PDF; the "
        "folder must exist)",
    )


def _check_cheap(args: argparse.Namespace) -> None:
    """Every check that needs no numpy, sympy or shapely."""
    if not args.shape.lower().endswith((".svg", ".dxf")):
        raise InputError(f"--shape {args.shape!r}: an outline is read from a .svg or .dxf file")
    if not 3 <= args.samples:
        raise InputError(f"--samples must be at least 3, got {args.samples}")
    if args.samples > MAX_SAMPLES:
        raise InputTooLargeError(
            f"--samples {args.samples} gives {args.samples * (args.samples - 1) // 2} pairs; "
            f"at most {MAX_SAMPLES} samples ({MAX_SAMPLES * (MAX_SAMPLES - 1) // 2} pairs)"
        )
    if not 1 <= args.top <= _MAX_TOP:
        raise InputError(f"--top must be from 1 to {_MAX_TOP}, got {args.top}")
    if not 0 <= args.exact <= _MAX_EXACT:
        raise InputError(f"--exact must be from 0 to {_MAX_EXACT}, got {args.exact}")
    if args.tilt is not None and args.gravity is None:
        raise InputError("--tilt needs --gravity (the orientation it tilts from)")
    if args.gravity is not None:
        read_pair(args.gravity, "--gravity", None)
    if args.tilt is not None:
        split_unit(args.tilt, "angle", "--tilt")
    if args.com is not None:
        read_pair(args.com, "--com", "length")
    for opt, text, kind in (
        ("--mass", args.mass, "mass"),
        ("--g", args.g, "acceleration"),
        ("--accel", args.accel, "acceleration"),
        ("--shape-unit", args.shape_unit, "length"),
    ):
        if text is not None:
            split_unit(text, kind, opt)
    if args.draw is not None:
        if not args.draw.lower().endswith((".png", ".svg", ".pdf")):
            raise InputError(f"--draw {args.draw!r}: use a .png, .svg or .pdf file name")


def _number(text: str, option: str, kind: str | None, low: float, strict: bool) -> float:
    """A finite float from an option's text (with units of ``kind``), at least ``low``."""
    import math

    from ..boundary.expr import ExpressionError, parse_exact
    from ..sizing.units import acceleration_value, length_value, mass_value

    if kind is None:
        try:
            v = parse_exact(text)
        except ExpressionError as exc:
            raise type(exc)(f"{option}: {exc}") from None
    else:
        v = {"mass": mass_value, "acceleration": acceleration_value, "length": length_value}[kind](
            text, option
        )
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise InputError(f"{option}: expected a real number, got {text!r}") from None
    if not math.isfinite(x) or x < low or (strict and x == low):
        raise InputError(
            f"{option} must be a finite number {'>' if strict else '>='} {low:g}, got {text!r}"
        )
    return x


def run(args: argparse.Namespace) -> int:
    """Run ``graspcompass plan``; returns the exit status (0).

    Raises
    ------
    ValueError
        A refused option, file or outline, or no force-closure pair
        (:class:`~graspcompass.sizing.NotForceClosureError`): one line on stderr,
        exit 2.
    """
    _check_cheap(args)
    draw = None
    if args.draw is not None:
        from ..boundary._output import check_target

        draw = check_target(args.draw)
    mass = _number(args.mass, "--mass", "mass", 0, True)
    mu = _number(args.mu, "--mu", None, 0, True)
    g = _number(args.g, "--g", "acceleration", 0, False)
    accel = 0.0 if args.accel is None else _number(args.accel, "--accel", "acceleration", 0, False)
    safety = _number(args.safety, "--safety", None, 1, False)
    tol = _number(args.tol, "--tol", None, 0, True)
    gravity = None
    if args.gravity is not None:
        from ._size import _pair_values

        try:
            gravity = tuple(float(v) for v in _pair_values(args.gravity, "--gravity", None))
        except TypeError:
            raise InputError(
                f"--gravity: expected two real numbers, got {args.gravity!r}"
            ) from None
    com = None
    if args.com is not None:
        from ._size import _pair_values

        try:
            com = tuple(float(v) for v in _pair_values(args.com, "--com", "length"))
        except TypeError:
            raise InputError(f"--com: expected two real lengths, got {args.com!r}") from None
    from ..outlines import read_outline
    from ..planning import plan_contacts

    if args.jaws > 2:
        if args.gravity is not None or args.tilt is not None or args.per != "jaw":
            raise InputError(
                "--gravity, --tilt and --per are for two jaws; --jaws 3 ranks by "
                "the worst total squeeze over all orientations"
            )
        from ..planning.ncontact import plan_jaws

        rec = plan_jaws(
            read_outline(args.shape, unit=args.shape_unit),
            args.jaws,
            mu=mu,
            load=mass * (g + accel) * safety,
            samples=args.samples,
            com=com,
            top=args.top,
        )
        if args.json:
            print(json.dumps(rec, indent=1, allow_nan=False))
            return 0
        print(
            f"{args.shape}: {rec['samples']} contacts sampled, {rec['sets']} sets of "
            f"{args.jaws}, {rec['force_closure_sets']} force-closure with μ = {mu:.4g}; "
            f"load {rec['load_N']:.6g} N; total squeeze (sum of the normal forces) that "
            "holds the part in every orientation"
        )
        for p in rec["top"]:
            cs = "  ".join(
                "(" + ", ".join(f"{v * 1e3:.3f}" for v in q) + ")" for q in p["contacts_m"]
            )
            print(f"{p['rank']:>4}  {cs}  {p['squeeze_N']:.4g} N")
        return 0

    outline = read_outline(args.shape, unit=args.shape_unit)
    plan = plan_contacts(
        outline,
        mu=mu,
        mass=mass,
        samples=args.samples,
        com=com,
        g=g,
        accel=accel,
        safety=safety,
        per=args.per,
        gravity=gravity,
        tilt=args.tilt,
        exact=args.exact,
        tol=tol,
    )
    record = plan.to_dict(args.top)
    record["shape"] = args.shape
    from ..boundary._output import finite_record

    finite_record(record, "give the mass or the drawing's unit in other units")
    if draw is not None:
        from ..boundary._output import writing
        from ..render.output import save_figure
        from ..render.planning import figure_plan

        with writing(draw):
            save_figure(figure_plan(plan, top=min(args.top, 10)), draw)
        record["drawing"] = str(draw)
    if args.json:
        print(json.dumps(record, indent=1, allow_nan=False))
        return 0
    print(_text(record))
    if draw is not None:
        print(f"wrote {draw}")
    return 0


def _text(d: dict[str, Any]) -> str:
    per = "per jaw" if d["per"] == "jaw" else "total (both jaws)"
    lines = [
        f"{d['shape']}: {d['samples']} contacts sampled, {d['pairs']} pairs, "
        f"{d['force_closure_pairs']} force-closure with μ = {d['mu']:.4g}; "
        f"{d['mass_kg']:.6g} kg, g = {d['g_m_s2']:.6g} m/s^2",
        f"centre of mass ({d['com_m'][0] * 1e3:.3f}, {d['com_m'][1] * 1e3:.3f}) mm; squeeze "
        f"{per} that holds the part in {d['orientations']}",
        f"{'rank':>4}  {'contact 1 (mm)':>20}  {'contact 2 (mm)':>20}  {'squeeze N':>10}  "
        f"{'N/kg':>8}",
    ]
    for p in d["top"]:
        a, b = ([f"{v * 1e3:.3f}" for v in c] for c in p["contacts_m"])
        lines.append(
            f"{p['rank']:>4}  {'(' + ', '.join(a) + ')':>20}  "
            f"{'(' + ', '.join(b) + ')':>20}  {p['squeeze_N']:>10.4g}  "
            f"{p['squeeze_N_per_kg']:>8.4g}"
        )
    if d["exact"]:
        lines.append(
            f"exact along the best edge pairs ({d['exact_method']}; tolerance "
            f"{d['exact'][0]['tolerance']:.0e}):"
        )
        lines.append(
            f"{'rank':>4}  {'edges':>7}  {'contact 1 (mm)':>20}  {'contact 2 (mm)':>20}  "
            f"{'squeeze N':>10}  {'proved >=':>10}  {'sampled':>10}  saved"
        )
        for p in d["exact"]:
            a, b = ([f"{v * 1e3:.3f}" for v in c] for c in p["contacts_m"])
            saved = "" if p["improvement"] is None else f"{100 * p['improvement']:.2f}%"
            samp = "-" if p["sampled_squeeze_N"] is None else f"{p['sampled_squeeze_N']:.6g}"
            lines.append(
                f"{p['rank']:>4}  {'{},{}'.format(*p['edges']):>7}  "
                f"{'(' + ', '.join(a) + ')':>20}  {'(' + ', '.join(b) + ')':>20}  "
                f"{p['squeeze_N']:>10.6g}  {p['lower_bound_N']:>10.6g}  {samp:>10}  "
                f"{saved}{'' if p['certified'] else ' (not closed)'}"
                f"{' (on the boundary of (1))' if p['on_boundary'] else ''}"
            )
        if any(p["on_boundary"] for p in d["exact"]):
            lines.append(
                "(on the boundary of (1): the least squeeze is approached where a "
                "contact is at the edge of its friction cone; the pair shown is just "
                "inside, with no margin for error in μ or in placing the jaws)"
            )
    return "\n".join(lines)
