"""Choosing the contacts of a gripper with three or four jaws on an outline (issue 25).

Contacts are sampled along the outline's edges (:func:`graspcompass.planning.sample_contacts`),
every set of ``jaws`` of them is formed, and the sets are ranked by the worst squeeze over all
orientations, ``F_e max_q |q|`` (the sum of the jaws' normal forces; :mod:`graspcompass.ncontact`),
computed for all sets at once (:func:`graspcompass.batch.ncontact.ncontact_worst`).
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

__all__ = ["MAX_SETS", "plan_jaws"]

#: Most sets of contacts ranked in one call (memory: 20-70 bases each).
MAX_SETS = 20_000


def plan_jaws(
    outline: Any, jaws: int, *, mu: float, load: float, samples: int, com: Any = None, top: int = 5
) -> dict[str, Any]:
    """The ``top`` best sets of ``jaws`` contacts by the worst total squeeze, in newtons.

    Parameters
    ----------
    outline : shapely Polygon or sequence of (x, y)
        The part's outline.
    jaws : int
        3 or 4.
    mu : float
        Friction coefficient of every pad.
    load : float
        F_e = m (g + A) S in newtons.
    samples : int
        Contact points along the outline (reduced so that at most :data:`MAX_SETS` sets
        are formed).
    com : pair, optional
        Centre of mass (default: the outline's centroid).
    top : int
        How many sets to report.

    Returns
    -------
    dict
        ``samples``, ``sets``, ``force_closure_sets``, ``com_m`` and ``top`` (rank,
        contacts and normals, ``squeeze_N``: the sum of the normal forces in the worst
        orientation).
    """
    from ..batch.ncontact import ncontact_worst
    from . import _ring, _sample

    if jaws not in (3, 4):
        raise ValueError(f"--jaws: expected 2, 3 or 4, got {jaws}")
    ring, centroid = _ring(outline)
    while samples > jaws and math.comb(samples, jaws) > MAX_SETS:
        samples -= 1
    pts, nrm, _ = _sample(ring, samples)
    c = centroid if com is None else tuple(float(v) for v in com)
    idx = np.array(list(itertools.combinations(range(len(pts)), jaws)))
    arr = np.concatenate([pts[idx], nrm[idx], np.full((*idx.shape, 1), float(mu))], axis=-1)
    worst = ncontact_worst(arr, com=c) * load
    order = np.argsort(worst, kind="stable")
    fin = np.isfinite(worst)
    best = [int(i) for i in order[:top] if fin[i]]
    return {
        "jaws": jaws,
        "samples": len(pts),
        "sets": len(idx),
        "force_closure_sets": int(fin.sum()),
        "com_m": list(c),
        "mu": float(mu),
        "load_N": float(load),
        "top": [
            {
                "rank": r + 1,
                "contacts_m": pts[idx[i]].tolist(),
                "normals": nrm[idx[i]].tolist(),
                "squeeze_N": float(worst[i]),
            }
            for r, i in enumerate(best)
        ],
    }
