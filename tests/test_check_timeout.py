"""``--timeout`` on every path of check, verify and certify (issue 19, item 7).

A verdict reached before the limit is kept; every row not decided by then is
UNDECIDED and says it timed out.  The slow rows are made slow on purpose (a
busy loop the alarm interrupts), so the tests do not depend on the machine's
speed; the expected verdicts of the fast rows are first principles (a midpoint).
"""

from __future__ import annotations

import time

import pytest

from graspcompass import cli
from graspcompass.construction import internal_force_diagram
from graspcompass.construction.language import parse
from graspcompass.grasp import Grasp
from graspcompass.proof import certify as certify_fn
from graspcompass.proof import program_check, report
from graspcompass.proof._budget import TIMED_OUT, Budget
from graspcompass.proof.prove import Status

FILE = """param a > 0
A = point (0, 0)
B = point (a, 0)
M = midpoint A B
claim M == point(a/2, 0)
claim M == point(a/2, 1)
claim M == point(a/2, 0)
"""


def _spin(seconds: float = 60.0) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:  # interrupted by the budget's alarm
        time.sleep(0.005)
    raise AssertionError("the timeout did not interrupt the work")


def _slow_second_claim(monkeypatch: pytest.MonkeyPatch) -> None:
    real = program_check._check_claim

    def check_claim(program, claim, *args, **kwargs):
        if claim.line == 6:
            _spin()
        return real(program, claim, *args, **kwargs)

    monkeypatch.setattr(program_check, "_check_claim", check_claim)


def test_check_program_keeps_the_verdicts_reached_before_the_timeout(monkeypatch) -> None:
    _slow_second_claim(monkeypatch)
    r = program_check.check_program(parse(FILE), timeout=3)
    assert [row.status for row in r.claims] == [Status.PROVED, Status.UNDECIDED, Status.UNDECIDED]
    assert [row.result.method == TIMED_OUT for row in r.claims] == [False, True, True]
    assert all(row.status in (Status.GIVEN, Status.PROVED) for row in r.steps)
    assert r.exit_status == 3


def test_check_program_timeout_zero_times_out_every_row() -> None:
    r = program_check.check_program(parse(FILE), timeout=0)
    assert r.rows and all(row.result.method == TIMED_OUT for row in r.rows)
    assert {row.status for row in r.rows} == {Status.UNDECIDED}


def test_check_program_without_timeout_decides_everything() -> None:
    r = program_check.check_program(parse(FILE))
    assert [row.status for row in r.claims] == [Status.PROVED, Status.REFUTED, Status.PROVED]


def test_cli_check_timeout_prints_the_partial_table(tmp_path, capsys, monkeypatch) -> None:
    _slow_second_claim(monkeypatch)
    f = tmp_path / "m.gc"
    f.write_text(FILE)
    assert cli.main(["check", str(f), "--timeout", "2", "-q", "--steps"]) == 3
    out = capsys.readouterr()
    assert "PROVED" in out.out and "UNDECIDED" in out.out
    err = out.err.strip().splitlines()
    assert len(err) == 1 and "timed out" in err[0] and "--timeout" in err[0]


def test_certify_timeout_keeps_the_certificates_made(monkeypatch) -> None:
    import importlib

    cmod = importlib.import_module("graspcompass.proof.certify")
    real = cmod._certify_step
    c = internal_force_diagram(Grasp.preset("fig6"))
    certify_fn(c)  # warm: the steps before X1 then take milliseconds, far inside 3 s

    def step(c, s, *args, **kwargs):
        if s.name == "X1":
            _spin()
        return real(c, s, *args, **kwargs)

    monkeypatch.setattr(cmod, "_certify_step", step)
    certs = certify_fn(c, timeout=3)
    names = [x.step for x in certs]
    i = names.index("X1")
    assert all(x.result.holds for x in certs[:i])
    assert all(
        x.result.status is Status.UNDECIDED and x.result.method == TIMED_OUT for x in certs[i:]
    )


def test_certify_timeout_zero() -> None:
    certs = certify_fn(internal_force_diagram(Grasp.preset("fig6")), timeout=0)
    assert certs and all(x.result.method == TIMED_OUT for x in certs)


def test_run_catalogue_timeout(monkeypatch) -> None:
    real = report.check
    claims = report.CLAIMS[:3]
    first = real(claims[0])  # decided before the clock starts: the budget is the spin's

    def check(c):
        if c.id == claims[0].id:
            return first
        if c.id == claims[1].id:
            _spin()
        return real(c)

    monkeypatch.setattr(report, "check", check)
    out = report.run_catalogue(claims, quiet=True, timeout=2)
    assert out[0].result.method != TIMED_OUT and out[0].result.status is not Status.UNDECIDED
    assert [r.result.method == TIMED_OUT for r in out[1:]] == [True, True]
    assert report.exit_status(out) == 1


def test_cli_verify_timeout(capsys, monkeypatch) -> None:
    monkeypatch.setattr(report, "check", lambda c: _spin())
    assert cli.main(["verify", "--timeout", "1", "-q"]) == 1
    out = capsys.readouterr()
    assert "UNDECIDED" in out.out
    err = out.err.strip().splitlines()
    assert len(err) == 1 and "timed out" in err[0]


def test_budget_refuses_a_negative_timeout() -> None:
    with pytest.raises(ValueError):
        Budget(-1)


def test_nested_deadlines_keep_the_outer_bound() -> None:
    from graspcompass.boundary._deadline import deadline

    class Outer(BaseException):
        pass

    class Inner(BaseException):
        pass

    with pytest.raises(Outer):
        with deadline(0.5, Outer):
            with deadline(0.1, Inner):
                pass  # the inner block ends: the outer alarm is re-armed
            _spin(10)
    with pytest.raises(Outer):
        with deadline(0.2, Outer), deadline(30, Inner):
            _spin(10)
