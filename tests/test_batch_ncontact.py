"""Batched n-contact values (graspcompass.batch.ncontact) against the test's LP."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("scipy")

from _ncontact_lp import SweepLP, random_contacts
from graspcompass.batch.ncontact import ncontact_k


@pytest.mark.parametrize("n", [3, 4])
def test_batch_matches_the_lp_with_and_without_closure(n) -> None:
    rng = np.random.default_rng(60 + n)
    grasps = [random_contacts(rng, n, closure=k % 3 != 2) for k in range(24)]
    theta = np.sort(rng.uniform(0, 2 * math.pi, 16))
    for effort in ("sum-normal", f"pair:1,{n}"):
        got = ncontact_k(np.array(grasps), theta, effort)
        assert got.shape == (24, 16)
        for g, row in zip(grasps, got):
            want = SweepLP(g, effort)(theta)
            fin = np.isfinite(want)
            assert np.array_equal(np.isfinite(row), fin)
            assert np.allclose(row[fin], want[fin], rtol=1e-9, atol=1e-9)
    assert not np.isfinite(ncontact_k(np.array(grasps), theta)).all()  # arcs were met


def test_batch_refuses_bad_shapes() -> None:
    with pytest.raises(ValueError, match="expected shape"):
        ncontact_k(np.zeros((3, 4)), [0.0])
    with pytest.raises(ValueError, match="batch takes"):
        ncontact_k(np.zeros((2, 5)) + 1, [0.0], effort="max-normal")


def test_worst_is_the_farthest_vertex_and_inf_without_closure() -> None:
    from graspcompass.batch.ncontact import ncontact_worst
    from graspcompass.ncontact import NContactGrasp

    rng = np.random.default_rng(5)
    grasps = [random_contacts(rng, 3 + k % 2, closure=k % 3 != 2) for k in range(12)]
    got = ncontact_worst(np.array(grasps[::2]))  # n = 3 only (one shape per array)
    for g, w in zip(grasps[::2], got):
        m = NContactGrasp(g)
        want = m.worst()[0] if m.force_closure else math.inf
        assert (w == want) if math.isinf(want) else w == pytest.approx(want, rel=1e-9)


def test_plan_three_jaws_ranks_by_the_models_worst_squeeze(capsys) -> None:
    """plan --jaws 3: the best set's squeeze is F_e max|q| of the model on those contacts,
    and the LP on 720 θ never needs more."""
    import json
    from pathlib import Path

    from graspcompass import cli
    from graspcompass.ncontact import NContactGrasp

    svg = Path(__file__).resolve().parents[1] / "docs" / "_static" / "outlines" / "bracket.svg"
    assert (
        cli.main(
            ["plan", "--shape", str(svg), "--jaws", "3", "--samples", "18", "--mass", "1", "--json"]
        )
        == 0
    )
    rec = json.loads(capsys.readouterr().out)
    best = rec["top"][0]
    contacts = [(p[0], p[1], n[0], n[1], 0.5) for p, n in zip(best["contacts_m"], best["normals"])]
    g = NContactGrasp(contacts, com=tuple(rec["com_m"]))
    assert best["squeeze_N"] == pytest.approx(g.worst(rec["load_N"])[0], rel=1e-9)
    grid = SweepLP(contacts, "sum-normal", tuple(rec["com_m"]))(
        np.linspace(0, 2 * math.pi, 720, endpoint=False)
    )
    assert grid.max() * rec["load_N"] <= best["squeeze_N"] * (1 + 1e-9)
    assert all(a["squeeze_N"] <= b["squeeze_N"] for a, b in zip(rec["top"], rec["top"][1:]))
