"""``graspcompass crosscheck``: the closed form k_grasp(θ) against scipy's linprog.

Eq. (25) on random grasps and directions against the least internal force that
:func:`scipy.optimize.linprog` finds (:mod:`graspcompass.proof.crosscheck`).
"""

from __future__ import annotations

import argparse
from typing import Any

from ..boundary.errors import InputError
from ._animate import bounded, quiet_option

__all__ = ["CROSSCHECK_GRASPS", "CROSSCHECK_RUNS", "CROSSCHECK_THETAS", "register", "run"]

#: Bounds of ``crosscheck``: random grasps, θ grid size, and their product (linprog runs).
CROSSCHECK_GRASPS, CROSSCHECK_THETAS, CROSSCHECK_RUNS = 200, 3600, 36_000


def register(sub: Any) -> None:
    """Add the ``crosscheck`` sub-command to ``sub`` (argparse's sub-parsers)."""
    x = sub.add_parser(
        "crosscheck",
        help="closed form vs scipy linprog on random grasps",
        description="Compare the closed form k_grasp(θ) (eq. (25)) with the least internal "
        "force found by scipy's linprog on random grasps and directions "
        "(needs scipy: pip install 'graspcompass[crosscheck]').",
        epilog=f"limits: --grasps × --thetas at most {CROSSCHECK_RUNS} linprog problems. "
        "exit status: 0 when they agree to 1e-7, 1 otherwise, 2 for a usage error.",
    )
    x.add_argument(
        "--grasps",
        type=bounded(int, 1, CROSSCHECK_GRASPS),
        default=20,
        metavar="N",
        help=f"random grasps, 1 to {CROSSCHECK_GRASPS} (20)",
    )
    x.add_argument(
        "--thetas",
        type=bounded(int, 1, CROSSCHECK_THETAS),
        default=36,
        metavar="M",
        help=f"θ grid size, 1 to {CROSSCHECK_THETAS} (36)",
    )
    x.add_argument(
        "--seed", type=bounded(int, 0, 2**63 - 1), default=0, help="random seed, 0 to 2**63 - 1 (0)"
    )
    quiet_option(x, "no progress bar")


def run(args: argparse.Namespace) -> int:
    import importlib.util

    if importlib.util.find_spec("scipy") is None:
        raise InputError("crosscheck needs scipy: pip install 'graspcompass[crosscheck]'")
    from ..proof.crosscheck import run_crosscheck

    if args.grasps * args.thetas > CROSSCHECK_RUNS:
        raise ValueError(
            f"--grasps × --thetas = {args.grasps * args.thetas} linprog problems; "
            f"at most {CROSSCHECK_RUNS}"
        )
    r = run_crosscheck(args.grasps, args.thetas, args.seed, quiet=args.quiet)
    print(
        f"{r.grasps} random grasps × {r.thetas} directions: largest |k_grasp − linprog| = "
        f"{r.max_abs_diff:.3e}"
    )
    return 0 if r.max_abs_diff < 1e-7 else 1
