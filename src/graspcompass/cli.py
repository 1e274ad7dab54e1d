"""Command line: ``graspcompass [draw|steps|k|presets] ...``.

With no sub-command, runs the main job on the paper's Fig. 6 grasp: replays
the construction, writes the diagram to ``./graspcompass-out/`` and prints the
protocol with exact coordinates.  A user error prints one line on stderr and
exits with status 2.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any, NoReturn

import numpy as np
import sympy as sp

from . import __version__, _cli_export
from ._cli_animate import register as _register_animate
from ._cli_animate import write_main_animation
from .construction import Construction, describe, internal_force_diagram, to_records
from .expr import parse_angles, parse_exact
from .grasp import PRESETS, Grasp

__all__ = ["build_parser", "grasp_from_args", "main"]

_PARAMS = ("x1", "x2", "y", "phi1", "phi2", "mu1", "mu2", "xi1", "xi2")
_FORMATS = ("png", "svg", "pdf")


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2, no usage block)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see --help)\n")


def _add_grasp_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group(
        "grasp", "a preset, optionally with parameters overridden; values are exact "
        "expressions such as sqrt(3)/2, pi/3, 60deg or 1.2 (= 6/5)")
    g.add_argument("--preset", default="fig6", choices=sorted(PRESETS),
                   help="start from one of the paper's examples (default: fig6)")
    for name in _PARAMS:
        g.add_argument(f"--{name}", metavar="EXPR", help=f"set {name}")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``graspcompass`` command."""
    p = _Parser(prog="graspcompass", description=(
        "Ruler-and-compass internal force diagram of a two-point grasp "
        "(Ito, Tanaka, Sasaki, Robotica 2012). Without a command: the main job on "
        "the paper's Fig. 6 grasp."))
    p.add_argument("--version", action="version", version=f"graspcompass {__version__}")
    p.add_argument("--out", default="graspcompass-out", metavar="DIR",
                   help="output folder of the main job (default: ./graspcompass-out)")
    p.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    d = sub.add_parser("draw", help="draw the diagram to a PNG, SVG or PDF file")
    _add_grasp_options(d)
    d.add_argument("-o", "--output", metavar="FILE", help="output file (default: PRESET.png)")
    d.add_argument("--format", choices=_FORMATS, help="file format (default: from the extension)")
    d.add_argument("--step", type=int, metavar="N",
                   help="draw the state after protocol step N (default: the whole diagram)")
    d.add_argument("--no-overlay", action="store_true",
                   help="leave out the computer plot of k_grasp (Fig. 6(b))")
    d.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")

    s = sub.add_parser("steps", help="print the construction protocol")
    _add_grasp_options(s)
    s.add_argument("--json", action="store_true", help="print the steps as JSON")

    k = sub.add_parser("k", help="k_n(θ), k_grasp(θ) and F_int (eqs. (17)-(25))")
    _add_grasp_options(k)
    k.add_argument("--theta", default="0:360:30deg", metavar="ANGLES",
                   help="angles: a list and/or ranges start:stop:step, radians unless "
                        "suffixed with deg (default: 0:360:30deg)")
    k.add_argument("--external-force", default="1", metavar="EXPR",
                   help="magnitude F_e of the external force (default: 1)")
    k.add_argument("--exact", action="store_true", help="also print exact values")
    k.add_argument("--json", action="store_true", help="print JSON")

    sub.add_parser("presets", help="list the built-in grasps of the paper")
    _register_animate(sub, _add_grasp_options)
    _cli_export.register(sub, _add_grasp_options)

    v = sub.add_parser(
        "verify", help="machine-check every claim of the paper (symbolic)",
        description="Check every claim of the paper for general symbolic parameters under "
        "condition (1) (and μ = tan ξ where both appear); print each claim's status, "
        "hypotheses and non-degeneracy conditions.",
        epilog="exit status: 0 when every claim is decided (none UNDECIDED) and every REFUTED "
        "claim names a correction that is PROVED (with --certify: and every construction "
        "step holds); 1 otherwise; 2 for a usage error.")
    v.add_argument("--json", action="store_true",
                   help="print the results as JSON (with hypotheses, conditions, certificates)")
    v.add_argument("--markdown", metavar="FILE", help="write the report as a Markdown page")
    v.add_argument("--certify", action="store_true",
                   help="also certify the symbolic construction (every admissible grasp) and, "
                   "if grasp options are given, that grasp's construction")
    _add_grasp_options(v)
    v.add_argument("-q", "--quiet", action="store_true", help="no progress bar")

    x = sub.add_parser("crosscheck", help="closed form vs scipy linprog on random grasps")
    x.add_argument("--grasps", type=int, default=20, metavar="N", help="random grasps (20)")
    x.add_argument("--thetas", type=int, default=36, metavar="M", help="θ grid size (36)")
    x.add_argument("--seed", type=int, default=0, help="random seed (0)")
    x.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    return p


def grasp_from_args(args: argparse.Namespace) -> Grasp:
    """The grasp named by ``--preset`` with any parameter options applied."""
    params: dict[str, Any] = dict(PRESETS[args.preset]["params"])
    given = {k: getattr(args, k) for k in _PARAMS if getattr(args, k, None) is not None}
    for i in ("1", "2"):  # a given mu replaces the preset's xi and vice versa
        if f"mu{i}" in given:
            params.pop(f"xi{i}", None)
        if f"xi{i}" in given:
            params.pop(f"mu{i}", None)
    params.update(given)
    if not given:
        return Grasp.preset(args.preset)
    return Grasp(**params)


def _table(rows: list[list[str]], head: list[str]) -> str:
    widths = [max(3, *(len(r[i]) for r in [head, *rows])) for i in range(len(head))]
    widths[-1] = max(3, len(head[-1]))  # the last column is not padded
    fmt = "  ".join(f"{{:<{w}}}" for w in widths[:-1]) + "  {}"
    lines = [fmt.format(*head).rstrip(), fmt.format(*("-" * w for w in widths)).rstrip()]
    lines += [fmt.format(*r).rstrip() for r in rows]
    return "\n".join(lines)


def protocol_table(c: Construction) -> str:
    """The protocol as a text table with exact values."""
    rows = [[str(s.index), s.name, s.instrument, s.ref, describe(s.obj)] for s in c.steps]
    return _table(rows, ["#", "name", "instrument", "paper", "exact value"])


def _draw(c: Construction, path: Path, fmt: str | None, step: int | None,
          overlay: bool) -> Path:
    from .render import figure_diagram, save_figure

    fig = figure_diagram(c, step=step, overlay=overlay)
    save_figure(fig, path, format=fmt)
    return path


def _cmd_main(args: argparse.Namespace) -> int:
    c = internal_force_diagram(Grasp.preset("fig6"))
    out = Path(args.out)
    png = _draw(c, out / "fig6-diagram.png", None, None, True)
    _draw(c, out / "fig6-diagram.svg", None, None, True)
    (out / "fig6-steps.json").write_text(json.dumps(to_records(c), indent=1) + "\n")
    if not args.quiet:
        print(f"{c.grasp.title}\n")
        print(protocol_table(c))
    gif = write_main_animation(c, out, args.quiet)
    if not args.quiet:
        print(f"\nwrote {png}, {out / 'fig6-diagram.svg'}, {out / 'fig6-steps.json'} and {gif}")
    return 0


def _cmd_draw(args: argparse.Namespace) -> int:
    g = grasp_from_args(args)
    c = internal_force_diagram(g)
    if args.step is not None and not -len(c) <= args.step < len(c):
        raise ValueError(f"--step {args.step} is out of range: the protocol has {len(c)} "
                         f"steps, 0 to {len(c) - 1}")
    path = Path(args.output or f"{args.preset}.{args.format or 'png'}")
    fmt = args.format
    if fmt is None and path.suffix.lower().lstrip(".") not in _FORMATS:
        raise ValueError(f"cannot tell the format of {str(path)!r}: use a .png, .svg or .pdf "
                         "file name or --format")
    _draw(c, path, fmt, args.step, not args.no_overlay)
    if not args.quiet:
        print(f"wrote {path}")
    return 0


def _cmd_steps(args: argparse.Namespace) -> int:
    c = internal_force_diagram(grasp_from_args(args))
    if args.json:
        print(json.dumps(to_records(c), indent=1))
    else:
        print(protocol_table(c))
    return 0


def _cmd_k(args: argparse.Namespace) -> int:
    g = grasp_from_args(args)
    thetas = parse_angles(args.theta)
    fe = parse_exact(args.external_force)
    if not (fe.is_number and fe.is_extended_real and fe >= 0):
        raise ValueError(f"--external-force must be a non-negative number, got {fe}")
    t = np.array([float(sp.N(v, 17)) for v in thetas])
    ks, kg = g.k(t), g.k_grasp(t)
    fint = g.internal_force(t, float(fe))
    records = []
    for i, th in enumerate(thetas):
        rec: dict[str, Any] = {
            "theta": str(th), "theta_deg": float(np.degrees(t[i])),
            "k": [float(v) for v in ks[:, i]], "k_grasp": float(kg[i]), "F_int": float(fint[i]),
            "limiting": int(np.argmax(ks[:, i]) + 1) if kg[i] > 0 else 0,
        }
        if args.exact:
            rec["k_exact"] = [str(v) for v in g.k(th)]
            rec["k_grasp_exact"] = str(g.k_grasp(th))
            rec["F_int_exact"] = str(g.internal_force(th, fe))
        records.append(rec)
    if args.json:
        print(json.dumps(records, indent=1))
        return 0
    head = ["θ", "deg", "k1", "k2", "k3", "k4", "k_grasp", "F_int", "limit"]
    rows = [[r["theta"], f"{r['theta_deg']:.4g}", *(f"{v:.6g}" for v in r["k"]),
             f"{r['k_grasp']:.6g}", f"{r['F_int']:.6g}",
             f"k{r['limiting']}" if r["limiting"] else "-"] for r in records]
    print(_table(rows, head))
    if args.exact:
        for r in records:
            print(f"θ = {r['theta']}: k_grasp = {r['k_grasp_exact']}, F_int = {r['F_int_exact']}")
    return 0


def _cmd_presets(args: argparse.Namespace) -> int:
    for name, p in PRESETS.items():
        print(f"{name:8}  {p['title']}")
    return 0


def _cmd_animate(args: argparse.Namespace) -> int:
    from ._cli_animate import run

    return run(args, grasp_from_args(args))


def _cmd_export(args: argparse.Namespace) -> int:
    return _cli_export.run_export(args, grasp_from_args(args))


def _cmd_explore(args: argparse.Namespace) -> int:
    return _cli_export.run_explore(args, grasp_from_args(args))


def _certify_table(title: str, c: Construction) -> tuple[str, bool]:
    from . import proof

    certs = proof.certify(c)
    lines = [title]
    for cert in certs:
        lines.append(f"{cert.step:9} {cert.result.status.value:9} {'; '.join(cert.facts)}")
    return "\n".join(lines), all(x.result.holds for x in certs)


def _cmd_verify(args: argparse.Namespace) -> int:
    from . import proof

    reports = proof.run_catalogue(quiet=args.quiet or args.json)
    status = proof.exit_status(reports)
    if args.markdown:
        Path(args.markdown).parent.mkdir(parents=True, exist_ok=True)
        Path(args.markdown).write_text(proof.to_markdown(reports))
    if args.json:
        print(proof.to_json(reports))
    elif not args.markdown or not args.quiet:
        print(proof.to_table(reports))
    if args.certify:
        out = sys.stderr if args.json else sys.stdout
        text, ok = _certify_table("certify: the symbolic construction (all admissible grasps)",
                                  internal_force_diagram(Grasp.symbolic("mu")))
        print("\n" + text, file=out)
        given = any(getattr(args, k, None) is not None for k in _PARAMS)
        if given or args.preset != "fig6":
            t2, ok2 = _certify_table(f"certify: {args.preset} with the options given",
                                     internal_force_diagram(grasp_from_args(args)))
            print("\n" + t2, file=out)
            ok = ok and ok2
        status = status or (0 if ok else 1)
    return status


def _cmd_crosscheck(args: argparse.Namespace) -> int:
    from .proof.crosscheck import run_crosscheck

    if args.grasps < 1 or args.thetas < 1:
        raise ValueError(f"--grasps and --thetas must be positive, got {args.grasps}, "
                         f"{args.thetas}")
    r = run_crosscheck(args.grasps, args.thetas, args.seed, quiet=args.quiet)
    print(f"{r.grasps} random grasps × {r.thetas} directions: largest |k_grasp − linprog| = "
          f"{r.max_abs_diff:.3e}")
    return 0 if r.max_abs_diff < 1e-7 else 1


_COMMANDS = {None: _cmd_main, "draw": _cmd_draw, "steps": _cmd_steps, "k": _cmd_k,
             "presets": _cmd_presets, "animate": _cmd_animate, "verify": _cmd_verify,
             "crosscheck": _cmd_crosscheck, "export": _cmd_export, "explore": _cmd_explore}


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (2 for a user error)."""
    args = build_parser().parse_args(argv)
    try:
        return _COMMANDS[args.command](args)
    except BrokenPipeError:  # pragma: no cover - e.g. piped into head
        return 0
    except (ValueError, OSError) as exc:  # InvalidGraspError, ExpressionError, GeometryError
        msg = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        print(f"graspcompass: error: {msg}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
