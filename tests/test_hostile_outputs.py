"""Leftovers of issue 10: no ``sympify`` on outside values, writers refuse missing folders.

Each test here failed before its fix (see the issue's "Found" list).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from graspcompass.errors import InputError, OutputError, WrongTypeError
from graspcompass.symbols import mu1, phi1


def _payload(tmp_path: Path) -> tuple[str, Path]:
    marker = tmp_path / "ran"
    return f"__import__('os').system('touch {marker}') or 0", marker


# -- 1. the proof checker's boundary ------------------------------------------------
@pytest.mark.parametrize("wrap", [np.array, lambda s: [s], lambda s: (s,)],
                         ids=["ndarray", "list", "tuple"])
def test_violations_never_runs_text_in_containers(tmp_path: Path, wrap) -> None:
    from graspcompass.proof import violations

    code, marker = _payload(tmp_path)
    with pytest.raises(InputError):
        violations({"x1": wrap(code)})
    assert not marker.exists()


def test_violations_reads_text_with_the_safe_parser(tmp_path: Path) -> None:
    from graspcompass.proof import violations

    code, marker = _payload(tmp_path)
    with pytest.raises(InputError):
        violations({"x1": code})
    assert not marker.exists()
    assert violations({"phi1": "pi/2", "mu1": "1"}) == []


class _Sneaky:
    """An unknown object whose ``str`` is code (``sympify`` falls back to ``str``)."""

    def __init__(self, code: str) -> None:
        self.code = code

    def __str__(self) -> str:
        return self.code


@pytest.mark.parametrize("call", ["prove_identity", "prove_sign", "reduce_expr", "trig_to_poly",
                                  "is_identically_zero", "assumption", "domain"])
def test_proof_functions_never_sympify_outside_values(tmp_path: Path, call: str) -> None:
    import random

    from graspcompass import proof
    from graspcompass.proof.model import sample

    code, marker = _payload(tmp_path)
    for bad in (np.array([code]), _Sneaky(code)):
        with pytest.raises(WrongTypeError):
            if call == "prove_identity":
                proof.prove_identity(bad, 0)
            elif call == "prove_sign":
                proof.prove_sign(bad, 1)
            elif call == "assumption":
                proof.violations({phi1: sp.pi / 2}, [bad])
            elif call == "domain":
                sample([sp.Symbol("r")], random.Random(1), {sp.Symbol("r"): (bad, None)})
            else:
                getattr(proof, call)(bad)
    assert not marker.exists()


def test_proof_text_is_parsed_with_the_models_symbols() -> None:
    from graspcompass.proof import prove_identity

    r = prove_identity("sin(2*phi1)", 2 * sp.sin(phi1) * sp.cos(phi1))
    assert r.proved
    assert prove_identity(mu1 * 2, "2*mu1").proved


def test_sincos_refuses_text(tmp_path: Path) -> None:
    from graspcompass.geometry.trig import sincos

    code, marker = _payload(tmp_path)
    with pytest.raises(ValueError):
        sincos(code)
    assert not marker.exists()
    assert sincos(sp.pi / 3) == (sp.sqrt(3) / 2, sp.Rational(1, 2))
