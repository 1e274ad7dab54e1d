"""``graspcompass k --contact X,Y,NX,NY,MU ...``: the least effort of an n-contact grasp.

Each ``--contact`` gives one contact (n >= 2): its point, its inward normal (any
nonzero vector, or one angle: ``X,Y,ANGLE,MU``) and its friction coefficient, as
exact text (``sqrt(3)/2``, ``60deg``, ``1.2`` = 6/5).  ``--effort`` chooses what is
minimised (``paper``: the paper's k, n = 2; ``sum-normal``; ``pair:I,J``;
``max-normal``), ``--com X,Y`` the centre of mass (default the origin).  One row
per θ of ``--theta`` (as for the two-contact ``k``): the least effort k for a unit
load e(θ) at the centre of mass and F = k F_e for ``--external-force`` F_e, null
(JSON) or ``-`` where the load cannot be held, and the tight cone edges at the
optimum (for ``max-normal`` the edges that carry load, from the optimal forces); ``--exact``
adds the exact values (at most ``EXACT_VALUES`` angles).  A
value starting with ``-`` needs the ``--contact=-1,0,1,0,1/2`` form.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import IO, TYPE_CHECKING, Any

from ..boundary.errors import InputError

if TYPE_CHECKING:
    from ..ncontact import NContactGrasp

__all__ = ["add_options", "contacts_file", "draw", "grasp_from_args", "run", "wants_contacts"]

_HEAD = ["θ", "deg", "k", "F", "tight"]


def add_options(p: argparse.ArgumentParser) -> None:
    """Add ``--contact``, ``--effort`` and ``--com`` to the ``k`` command."""
    g = p.add_argument_group(
        "n contacts",
        "give --contact once per contact (n >= 2) instead of the two-contact grasp options",
    )
    g.add_argument(
        "--contact",
        action="append",
        metavar="X,Y,NX,NY,MU",
        help="a contact: point, inward normal (or one angle X,Y,ANGLE,MU), friction "
        "coefficient; write --contact=-1,... for a value starting with '-'",
    )
    g.add_argument(
        "--effort",
        default=None,
        metavar="NAME",
        help="paper (n = 2: the paper's k, default for 2 contacts), sum-normal "
        "(default for more), pair:I,J or max-normal",
    )
    g.add_argument("--com", default="0,0", metavar="X,Y", help="centre of mass (default: 0,0)")
    g.add_argument(
        "--contacts",
        metavar="FILE",
        help="a contacts file: one contact X,Y,NX,NY,MU (or X,Y,ANGLE,MU) a line, "
        "'#' starts a comment; 'com X,Y' and 'effort NAME' lines are allowed",
    )


def contacts_file(name: str) -> tuple[list[str], str | None, str | None]:
    """``(contact texts, com text, effort)`` of a contacts file (bounded, UTF-8).

    Raises
    ------
    graspcompass.errors.InputError
        A file that cannot be read, or a line that is neither a contact, ``com X,Y``
        nor ``effort NAME`` (``FILE:LINE: what``).
    """
    from ._check import read_file

    text, shown = read_file(name)
    contacts: list[str] = []
    com = effort = None
    for i, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word, _, rest = line.partition(" ")
        if word == "com":
            com = rest.strip()
        elif word == "effort":
            effort = rest.strip()
        elif "," in line:
            contacts.append(line)
        else:
            raise InputError(
                f"{shown}:{i}: expected a contact X,Y,NX,NY,MU, 'com X,Y' or "
                f"'effort NAME', got {line[:40]!r}"
            )
    if not contacts:
        raise InputError(f"{shown}: no contact in the file")
    return contacts, com, effort


def wants_contacts(args: argparse.Namespace) -> bool:
    """True when the options describe an n-contact grasp (``--contact`` or ``--contacts``)."""
    return bool(getattr(args, "contact", None) or getattr(args, "contacts", None))


def _values(text: str, name: str, counts: tuple[int, ...]) -> list[str]:
    from ._k import _split_items

    if len(text) > 2000:
        raise InputError(f"{name} is longer than 2000 characters")
    items = [v.strip() for v in _split_items(text)]
    if len(items) not in counts or not all(items):
        want = " or ".join(str(c) for c in counts)
        raise InputError(f"{name}: expected {want} comma-separated values, got {text!r}")
    return items


def grasp_from_args(args: argparse.Namespace) -> NContactGrasp:
    """The :class:`~graspcompass.ncontact.NContactGrasp` of the options."""
    from ..ncontact import NContactGrasp

    texts, com_text, effort = list(args.contact or []), None, None
    if getattr(args, "contacts", None):
        if texts:
            raise InputError(
                "give the contacts either with --contact or in --contacts FILE, not both"
            )
        texts, com_text, effort = contacts_file(args.contacts)
    if len(texts) < 2:
        raise InputError("--contact: give at least two contacts")
    contacts = [tuple(_values(t, f"--contact {i + 1}", (4, 5))) for i, t in enumerate(texts)]
    if com_text is not None and args.com != "0,0":
        raise InputError("--com and a 'com' line of the contacts file: give one")
    com = tuple(_values(com_text or args.com, "--com", (2,)))
    effort = args.effort or effort or ("paper" if len(contacts) == 2 else "sum-normal")
    return NContactGrasp(contacts, com=com, effort=effort)


def run(args: argparse.Namespace, out: IO[str] | None = None) -> int:
    """Run ``graspcompass k --contact ...``; returns the exit status (0)."""
    import numpy as np

    from ._k import _fe, read_angles, table

    out = sys.stdout if out is None else out
    fe_exact, fe = _fe(args.external_force)
    exact, t = read_angles(args.theta)
    from ..boundary.limits import EXACT_VALUES

    want_exact = bool(getattr(args, "exact", False))
    if want_exact and (exact is None or len(exact) > EXACT_VALUES):
        raise InputError(
            f"--exact computes exact values for at most {EXACT_VALUES} angles; "
            f"--theta gives {t.size}"
        )
    g = grasp_from_args(args)
    if want_exact and g.numeric:
        raise InputError(
            "--exact needs exact contacts (no value of --contact may be a float "
            "written with an exponent)"
        )
    Q = g.polygon()
    with np.errstate(all="ignore"):
        k = np.asarray(Q.support(t), dtype=float).reshape(-1)
    V = Q.float_vertices()
    labels = g.constraint_labels()
    e = np.stack([np.sin(t), -np.cos(t)])
    arg = np.argmax(V @ e, axis=0) if V.size else np.zeros(t.size, dtype=int)
    tight = [
        " ".join(labels[r] for r in Q.candidates[Q.vertex_index[i]].bases[0] if r < len(labels))
        if g.effort.linear
        else ""
        for i in range(len(V))
    ]
    twin = _float_twin(g) if not g.effort.linear else None  # max-normal: forces per θ
    names = [str(v) for v in exact] if exact is not None else [repr(float(v)) for v in t]
    records: list[dict[str, Any]] = []
    for i, name in enumerate(names):
        held = math.isfinite(k[i])
        records.append(
            {
                "theta": name,
                "theta_deg": float(np.degrees(t[i])),
                "k": float(k[i]) if held else None,
                "F": float(k[i] * fe) if held else None,
                "tight": (
                    _carrying(twin, float(t[i]))
                    if twin is not None
                    else tight[arg[i]].split()
                    if tight
                    else None
                )
                if held
                else None,
            }
        )
        if want_exact and exact is not None:
            kx = Q.support_exact(exact[i])[0]
            records[-1]["k_exact"] = str(kx)
            records[-1]["F_exact"] = str(kx * fe_exact)
    if args.json:
        print(json.dumps(records, indent=1), file=out)
        return 0
    rows = [
        [
            r["theta"],
            f"{r['theta_deg']:.4g}",
            f"{r['k']:.6g}" if r["k"] is not None else "-",
            f"{r['F']:.6g}" if r["F"] is not None else "-",
            " ".join(r["tight"]) if r["tight"] else "-",
        ]
        for r in records
    ]
    print(table(rows, _HEAD), file=out)
    if want_exact:
        for r in records:
            print(f"θ = {r['theta']}: k = {r['k_exact']}, F = {r['F_exact']}", file=out)
    arc = Q.arc()
    closure = "yes" if g.force_closure else "no"
    span = (
        "every direction"
        if arc == (0.0, 2 * math.pi)
        else "no open arc"
        if arc is None
        else f"θ in [{math.degrees(arc[0]):.6g}°, {math.degrees(arc[1]):.6g}°]"
    )
    print(
        f"{g.n} contacts, effort {g.effort.name}: Q has {len(V)} vertices; force closure: "
        f"{closure}; the load is held for {span}",
        file=out,
    )
    return 0


def _float_twin(g: Any) -> Any:
    """The grasp on the float path (its optimal forces cost about a millisecond per θ)."""
    from ..ncontact import NContactGrasp

    if g.numeric:
        return g
    return NContactGrasp(
        [
            (float(c.p[0]), float(c.p[1]), float(c.n[0]), float(c.n[1]), float(c.mu))
            for c in g.contacts
        ],
        com=tuple(float(v) for v in g.com),
        effort=g.effort.name,
    )


def _carrying(g: Any, theta: float) -> list[str] | None:
    """The edges carrying load at the optimum for θ (``max-normal``), or None."""
    from ..ncontact import NContactError

    try:
        return g.forces(theta)["basis"]
    except NContactError:  # a degenerate optimum: no row of edges, the value stands
        return None


def draw(args: argparse.Namespace) -> int:
    """``graspcompass draw --contact ...``: the n-contact diagram to a PNG, SVG or PDF file."""
    from pathlib import Path

    from ..boundary._output import check_target, writing

    name = args.output if args.output is not None else f"ncontact.{args.format or 'png'}"
    fmt = args.format or Path(name).suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise InputError(
            f"cannot tell the format of {name!r}: use a .png, .svg or .pdf file name or --format"
        )
    path = check_target(name)
    g = grasp_from_args(args)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..render.ncontact import draw_ncontact

    fig = draw_ncontact(g)
    with writing(path):
        fig.savefig(path, format=fmt, dpi=110)
    plt.close(fig)
    if not args.quiet:
        print(f"wrote {path}")
    return 0
