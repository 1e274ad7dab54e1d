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
