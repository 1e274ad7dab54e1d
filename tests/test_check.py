"""``graspcompass check``: claims proved or refuted, exercises graded against the paper.

The expected values come from outside the checker: the paper's printed closed
form (eqs. (28)-(39), written out below with mpmath at 50 digits), condition (1)
evaluated here from its definition, and points replayed by the test itself.
Wrong constructions and wrong claims are fed on purpose: the checker must
refute them with a counterexample that is a point of the model, never prove them.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import mpmath
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graspcompass import PRESETS, cli
from graspcompass.construction.language import paper_text, parse, replay
from graspcompass.construction.program import ConstructionSyntaxError
from graspcompass.expr import parse_exact
from graspcompass.proof.program_check import CheckError, check_program
from graspcompass.proof.program_report import to_json, to_markdown, to_table
from graspcompass.proof.prove import Status

mpmath.mp.dps = 50
_TEXT = paper_text()
#: The recipe up to the four points V_n (no circles: quick to replay symbolically).
HEAD = _TEXT[: _TEXT.index("# -- the circles")]


# -- an oracle independent of the package: the paper's printed formulas -----------------------
def _num(text: str) -> mpmath.mpf:
    return mpmath.mpf(str(parse_exact(text).evalf(60)))


def paper_objects(point: dict[str, str]) -> dict[str, tuple[mpmath.mpf, ...]]:
    """X_n, Y_n, V_n, circles, O_M, P1x, P2x from eqs. (28)-(39) and §3.3, at 50 digits."""
    v = {k: _num(t) for k, t in point.items()}
    x1, x2, y = v["x1"], v["x2"], v["y"]
    xi = {i: v[f"xi{i}"] if f"xi{i}" in v else mpmath.atan(v[f"mu{i}"]) for i in (1, 2)}
    t = {
        1: mpmath.tan(v["phi1"] + xi[1]),
        2: mpmath.tan(v["phi2"] + xi[2]),
        3: mpmath.tan(v["phi1"] - xi[1]),
        4: mpmath.tan(v["phi2"] - xi[2]),
    }
    S = {
        1: -(x1 + x2) / 2 + y * t[1],
        2: (x1 + x2) / 2 - y * t[2],
        3: -(x1 + x2) / 2 + y * t[3],
        4: (x1 + x2) / 2 - y * t[4],
    }
    C = {1: x2 * t[1], 2: x1 * t[2], 3: x2 * t[3], 4: x1 * t[4]}
    om = (x1 - x2) / 2
    out: dict[str, tuple[mpmath.mpf, ...]] = {"O_M": (om, 0), "P1x": (x1, 0), "P2x": (-x2, 0)}
    for n in (1, 2, 3, 4):
        out[f"V{n}"] = (S[n], C[n])
        out[f"X{n}"] = (om - S[n], 0)
        out[f"Y{n}"] = (0, -C[n])
        out[f"circle{n}"] = (S[n] / 2, C[n] / 2, (S[n] ** 2 + C[n] ** 2) / 4)
    return out


def is_model_point(point: dict[str, str]) -> bool:
    """Domains and condition (1) (§2.2.2) from their definitions, at 50 digits."""
    v = {k: _num(t) for k, t in point.items()}
    if not (v["x1"] > 0 and v["x2"] > 0 and v["y"] >= 0):
        return False
    for i in (1, 2):
        phi = v[f"phi{i}"]
        xi = v[f"xi{i}"] if f"xi{i}" in v else mpmath.atan(v[f"mu{i}"])
        if not (0 < phi <= mpmath.pi and 0 < xi < mpmath.pi / 2):
            return False
        if not (mpmath.pi / 2 < phi + xi < 3 * mpmath.pi / 2 and abs(phi - xi) < mpmath.pi / 2):
            return False
    return True


def file_object(text: str, name: str, point: dict[str, str]) -> tuple[mpmath.mpf, ...]:
    """The object ``name`` of the file replayed exactly at ``point``, at 50 digits."""
    obj = replay(parse(text), point)[name]
    parts = (obj.center.x, obj.center.y, obj.radius2) if hasattr(obj, "center") else (obj.x, obj.y)
    return tuple(mpmath.mpf(str(p.evalf(60))) for p in parts)


def differs(a: tuple, b: tuple) -> bool:
    return any(abs(p - q) > mpmath.mpf(10) ** -30 for p, q in zip(a, b))


# -- the shipped recipe ------------------------------------------------------------------------
def test_shipped_recipe_is_proved_against_the_paper() -> None:
    r = check_program(parse(_TEXT, "paper.gc"), "paper")
    assert r.exit_status == 0
    assert {t.name for t in r.targets} == {
        *(f"{k}{n}" for k in ("X", "Y", "V", "circle") for n in range(1, 5)),
        "O_M",
        "P1x",
        "P2x",
    }
    assert all(t.status is Status.PROVED for t in (*r.targets, *r.claims))
    # targets are proved under condition (1) with no extra condition left
    assert all(
        not t.result.conditions and "condition (1)" in t.result.hypotheses for t in r.targets
    )


# -- wrong student constructions ---------------------------------------------------------------
#: (what the student did, the replacement in the recipe, the refuted target, right for every
#: preset of the paper?).  The presets all have x1 = x2, which hides some mistakes.
WRONG = [
    (
        "perpendicular from the wrong foot",
        "perp1 = perpendicular side1 P2x",
        "perp1 = perpendicular side1 P1x",
        "V1",
        False,
    ),
    (
        "V1 from the lower side of the cone",
        "X1 = meet side1 x-axis",
        "X1 = meet side3 x-axis",
        "V1",
        False,
    ),
    (
        "sign of S lost",
        "V1 = point_from_lengths OMX1 OY1 (-1, -1)",
        "V1 = point_from_lengths OMX1 OY1 (1, -1)",
        "V1",
        False,
    ),
    (
        "sign of C lost",
        "V2 = point_from_lengths OMX2 OY2 (-1, -1)",
        "V2 = point_from_lengths OMX2 OY2 (-1, 1)",
        "V2",
        False,
    ),
    ("X2 on the wrong axis", "X2 = meet side2 x-axis", "X2 = meet side2 y-axis", "X2", False),
    ("Y3 on the wrong axis", "Y3 = meet perp3 y-axis", "Y3 = meet perp3 x-axis", "Y3", False),
    ("V3 from the cone at P2", "X3 = meet side3 x-axis", "X3 = meet side4 x-axis", "V3", False),
    (
        "V4 perpendicular through P2x",
        "perp4 = perpendicular side4 P1x",
        "perp4 = perpendicular side4 P2x",
        "V4",
        False,
    ),
    ("O_M taken as the origin", "O_M = midpoint P1x P2x", "O_M = foot O x-axis", "O_M", True),
    (
        "O_M taken as the origin: V1 follows",
        "O_M = midpoint P1x P2x",
        "O_M = foot O x-axis",
        "V1",
        True,
    ),
    ("P2x by symmetry", "P2x = foot P2 x-axis", "P2x = point (-x1, 0)", "P2x", True),
    ("P2x by symmetry: V1 follows", "P2x = foot P2 x-axis", "P2x = point (-x1, 0)", "V1", True),
    ("P1x mirrored from P2", "P1x = foot P1 x-axis", "P1x = point (x2, 0)", "V2", True),
]


def _mutated(old: str, new: str) -> str:
    assert _TEXT.count(old) == 1, old
    return HEAD.replace(old, new)


@pytest.mark.parametrize(
    "what, old, new, target, right_for_presets", WRONG, ids=[w[0] for w in WRONG]
)
def test_wrong_construction_is_refuted_at_a_point_of_the_model(
    what: str, old: str, new: str, target: str, right_for_presets: bool
) -> None:
    text = _mutated(old, new)
    report = check_program(parse(text, "student.gc"), "paper")
    row = next(r for r in report.targets if r.name == target)
    assert row.status is Status.REFUTED, (what, row.result)
    assert report.exit_status == 1
    cx = row.counterexample
    assert cx is not None and is_model_point(cx), cx
    assert differs(file_object(text, target, cx), paper_objects(cx)[target])
    if right_for_presets:  # the mistake is invisible on every example of the paper
        for name, spec in PRESETS.items():
            p = dict(spec["params"])
            for i in "12":  # the file declares mu: μ = tan ξ (22)
                if f"xi{i}" in p:
                    p[f"mu{i}"] = f"tan({p.pop(f'xi{i}')})"
            assert not differs(file_object(text, target, p), paper_objects(p)[target]), name


def test_untouched_objects_of_a_wrong_file_stay_proved() -> None:
    report = check_program(
        parse(_mutated("perp1 = perpendicular side1 P2x", "perp1 = perpendicular side1 P1x")),
        "paper",
    )
    status = {r.name: r.status for r in report.targets}
    assert status["Y1"] is Status.REFUTED and status["V1"] is Status.REFUTED
    assert all(status[n] is Status.PROVED for n in ("X1", "V2", "V3", "V4", "O_M"))


@pytest.mark.parametrize(
    "old, new",
    [
        # the perpendicular as the line through P2x and its foot on the side
        ("perp1 = perpendicular side1 P2x", "F1 = foot P2x side1\nperp1 = line_through P2x F1"),
        # the signed length read the other way, and the sign of the plot turned with it
        ("OMX1 = signed_length O_M X1 x-axis", "OMX1 = signed_length X1 O_M x-axis"),
        # X2 as the meet of the x-axis with the side (inputs the other way round)
        ("X2 = meet side2 x-axis", "X2 = meet x-axis side2"),
    ],
)
def test_right_alternative_constructions_are_proved(old: str, new: str) -> None:
    text = _mutated(old, new)
    if "signed_length X1 O_M" in new:
        text = text.replace(
            "V1 = point_from_lengths OMX1 OY1 (-1, -1)", "V1 = point_from_lengths OMX1 OY1 (1, -1)"
        )
    report = check_program(parse(text), "paper")
    assert report.exit_status == 0, [
        (r.name, r.status) for r in report.rows if r.status is not Status.PROVED
    ]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(n=st.integers(1, 4), sx=st.sampled_from([-1, 1]), sy=st.sampled_from([-1, 1]))
def test_any_sign_of_the_plot_is_graded_right(n: int, sx: int, sy: int) -> None:
    """Only (−1, −1) is the paper's V_n = (−O_M X_n, −O Y_n); every other sign is refuted."""
    old = f"V{n} = point_from_lengths OMX{n} OY{n} (-1, -1)"
    report = check_program(parse(_mutated(old, old.replace("(-1, -1)", f"({sx}, {sy})"))), "paper")
    row = next(r for r in report.targets if r.name == f"V{n}")
    if (sx, sy) == (-1, -1):
        assert row.status is Status.PROVED
    else:
        assert row.status is Status.REFUTED and is_model_point(row.counterexample)


def test_xi_form_file_is_graded_too() -> None:
    text = HEAD.replace("param mu1 friction", "param xi1 half_angle")
    text = text.replace("mu1", "tan(xi1)").replace("param tan(xi1) friction", "")
    report = check_program(parse(text), "paper")
    assert report.exit_status == 0
    wrong = text.replace(
        "V3 = point_from_lengths OMX3 OY3 (-1, -1)", "V3 = point_from_lengths OMX3 OY3 (-1, 1)"
    )
    row = next(r for r in check_program(parse(wrong), "paper").targets if r.name == "V3")
    assert row.status is Status.REFUTED and "xi1" in row.counterexample
    assert is_model_point(row.counterexample)


def test_grading_needs_the_papers_parameters() -> None:
    with pytest.raises(CheckError, match="missing: x2"):
        check_program(parse("param x1 > 0\nV1 = point (x1, 0)\n"), "paper")
    with pytest.raises(CheckError, match="nothing to grade"):
        check_program(parse(HEAD.split("# -- the feet")[0]), "paper")
    with pytest.raises(CheckError, match="domain"):
        check_program(parse("param x1 real\nA = point (x1, 0)\n"))


# -- claims of every kind ----------------------------------------------------------------------
BASE = """param a > 0
param b > 0
A = point (0, 0)
B = point (a, 0)
C = point (0, b)
D = point (a, b)
M = midpoint A D
AB = line_through A B
AC = line_through A C
CD = line_through C D
BD = line_through B D
diag1 = line_through A D
diag2 = line_through B C
mid = line_with_direction M (1, 0)
circ = circle_on_diameter A D
la = line_with_direction A (1, 2)
H = foot D la
F = foot B diag1
L = signed_length A B AB
"""

CLAIMS = [  # (claim, true?)
    ("claim M == point(a/2, b/2)", True),
    ("claim M == point(a/2, b/3)", False),
    ("claim L == a", True),
    ("claim L == b", False),
    ("claim on M diag2", True),
    ("claim on M AB", False),
    ("claim on B circ", True),
    ("claim on M circ", False),
    ("claim on H circ", True),  # Thales (Fig. 3): the foot of D on a line through A
    ("claim on F circ", False),  # a foot on the diameter itself is not on the circle
    ("claim collinear A M D", True),
    ("claim collinear A M B", False),
    ("claim concurrent diag1 diag2 mid", True),
    ("claim concurrent AB CD diag1", False),
    ("claim perpendicular AB AC", True),
    ("claim perpendicular AB diag1", False),
    ("claim parallel AB CD", True),
    ("claim parallel AB diag1", False),
    ("claim sign L > 0", True),
    ("claim sign L < 0", False),
    ("claim sign a*b >= 0", True),
    ("claim sign a - b >= 0", False),
    ("claim sign -a <= 0", True),
    ("claim sign L - a != 0", False),
    ("claim sign a + b != 0", True),
    ("claim sign a - 1 > 0", False),
]


@pytest.mark.parametrize("claim, true", CLAIMS, ids=[c for c, _ in CLAIMS])
def test_claims_are_proved_or_refuted(claim: str, true: bool) -> None:
    text = BASE + claim + "\n"
    row = check_program(parse(text)).claims[0]
    if true:
        assert row.status is Status.PROVED, row.result
        return
    assert row.status is Status.REFUTED, row.result
    cx = row.counterexample
    vals = {k: _num(v) for k, v in cx.items()}
    assert vals["a"] > 0 and vals["b"] > 0
    # the test's own check of the point: the statement is false there
    a, b = vals["a"], vals["b"]
    false_at = {
        "claim M == point(a/2, b/3)": b / 2 != b / 3,
        "claim L == b": a != b,
        "claim on M AB": b / 2 != 0,
        "claim on M circ": True,
        "claim on F circ": True,
        "claim collinear A M B": b != 0,
        "claim concurrent AB CD diag1": True,
        "claim perpendicular AB diag1": a != 0,
        "claim parallel AB diag1": b != 0,
        "claim sign L < 0": a > 0,
        "claim sign a - b >= 0": a - b < 0,
        "claim sign L - a != 0": True,
        "claim sign a - 1 > 0": a - 1 <= 0,
    }[claim]
    assert false_at


def test_concurrency_through_a_doubled_line_is_never_refuted() -> None:
    """AB and BA are one line: with AC the three lines meet at A (a true claim that the
    determinant route cannot prove; the exact replay must not refute it)."""
    row = check_program(parse(BASE + "BA = line_through B A\nclaim concurrent AB BA AC\n")).claims[
        0
    ]
    assert row.status in (Status.PROVED, Status.UNDECIDED)


def test_an_undecidable_sign_is_undecided_not_proved() -> None:
    """a⁴ − a + 1 > 0 is true, but no factor has a sign of its own and it is no square
    sum of degree 2: UNDECIDED, exit 3.  (a − 1)² + 1 > 0, a positive semi-definite
    quadratic, is PROVED where it does not vanish (issue 24), the condition stated."""
    r = check_program(parse(BASE + "claim sign a**4 - a + 1 > 0\n"))
    assert r.claims[0].status is Status.UNDECIDED and r.exit_status == 3
    r = check_program(parse(BASE + "claim sign a**2 - 2*a + 2 > 0\n"))
    assert r.claims[0].status is Status.PROVED
    assert r.claims[0].result.conditions == ("a**2 - 2*a + 2 ≠ 0",) or any(
        "a**2 - 2*a + 2" in t for t in r.claims[0].result.implied
    )


def test_a_step_degenerate_for_every_parameter_is_refused() -> None:
    from graspcompass.construction.program import DegenerateStepError

    with pytest.raises(DegenerateStepError, match=r"bad\.gc:20:"):
        check_program(parse(BASE + "P = meet AB CD\n", "bad.gc"))


def test_hypotheses_and_conditions_are_stated() -> None:
    quick = HEAD + _TEXT[_TEXT.index("let t1") :]  # the recipe's claims, without the circles
    v1 = next(c for c in check_program(parse(quick)).claims if c.name.startswith("V1"))
    assert v1.status is Status.PROVED and not v1.result.conditions
    assert "condition (1)" in v1.result.hypotheses
    assert any(h.startswith("domains") and "x1: positive" in h for h in v1.result.hypotheses)
    # without "under condition1" the denominator cos(φ1 + ξ1) stays a stated condition
    plain = quick.replace("x2*t1) under condition1", "x2*t1)")
    v1 = next(c for c in check_program(parse(plain)).claims if c.name.startswith("V1"))
    assert v1.status is Status.PROVED and "condition (1)" not in v1.result.hypotheses
    assert v1.result.conditions == ("mu1*sin(phi1) - cos(phi1) ≠ 0",)


# -- reports and the command line ----------------------------------------------------------
def test_json_has_the_documented_shape() -> None:
    doc = json.loads(
        to_json(
            check_program(
                parse(_mutated("X1 = meet side1 x-axis", "X1 = meet side3 x-axis")), "paper"
            )
        )
    )
    assert set(doc) >= {"targets", "claims", "steps", "status"}
    for row in doc["targets"] + doc["claims"]:
        assert set(row) >= {
            "name",
            "status",
            "hypotheses",
            "conditions",
            "counterexample",
            "seconds",
        }
    bad = [r for r in doc["targets"] if r["status"] == "REFUTED"]
    assert bad and all(isinstance(r["counterexample"], dict) for r in bad)
    assert doc["status"] == 1


def test_table_and_markdown_name_every_row() -> None:
    r = check_program(parse(BASE + "claim M == point(a/2, b/3)\n"))
    table, md = to_table(r), to_markdown(r)
    assert "REFUTED" in table and "counterexamples" in table
    assert md.startswith("# Check of") and "| claim |" in md


@pytest.fixture()
def files(tmp_path: Path) -> dict[str, Path]:
    out = {}
    for name, text in {
        "good.gc": HEAD,
        "wrong.gc": _mutated("X1 = meet side1 x-axis", "X1 = meet side3 x-axis"),
        "undecided.gc": BASE + "claim sign a**4 - a + 1 > 0\n",
        "syntax.gc": "A = point (0, 0)\nB = midpoint A Q\n",
    }.items():
        (tmp_path / name).write_text(text)
        out[name] = tmp_path / name
    return out


def test_cli_exit_statuses(files: dict[str, Path], capsys) -> None:
    assert cli.main(["check", str(files["good.gc"]), "--against", "paper", "-q"]) == 0
    assert cli.main(["check", str(files["wrong.gc"]), "--against", "paper", "-q"]) == 1
    assert cli.main(["check", str(files["undecided.gc"]), "-q"]) == 3
    capsys.readouterr()
    assert cli.main(["check", str(files["syntax.gc"])]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "syntax.gc:2:" in err[0] and "'Q'" in err[0]


@pytest.mark.parametrize(
    "argv, needle",
    [
        (["check", "/no/such/file.gc"], "cannot read"),
        (["check", "{good}", "--draw", "{tmp}/x.png"], "--against paper"),
        (["check", "{good}", "--against", "paper", "--draw", "{tmp}/x.gif"], ".png"),
        (["check", "{good}", "--markdown", "/no/such/folder/r.md"], "does not exist"),
        (["check", "{good}", "--against", "moon"], "invalid choice"),
    ],
)
def test_cli_usage_errors_are_one_line(files, tmp_path, capsys, argv, needle) -> None:
    argv = [a.format(good=files["good.gc"], tmp=tmp_path) for a in argv]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0], err


def test_cli_refuses_a_huge_or_binary_file(tmp_path: Path, capsys) -> None:
    big = tmp_path / "big.gc"
    big.write_bytes(b"# x\n" * 300_000)
    assert cli.main(["check", str(big)]) == 2
    assert "larger than" in capsys.readouterr().err
    binary = tmp_path / "bin.gc"
    binary.write_bytes(b"\xff\xfe\x00A = point")
    assert cli.main(["check", str(binary)]) == 2
    assert "UTF-8" in capsys.readouterr().err


def test_cli_json_markdown_and_draw(files, tmp_path: Path, capsys) -> None:
    md, png = tmp_path / "r.md", tmp_path / "cx.png"
    status = cli.main(
        [
            "check",
            str(files["wrong.gc"]),
            "--against",
            "paper",
            "--json",
            "--markdown",
            str(md),
            "--draw",
            str(png),
        ]
    )
    assert status == 1
    out = capsys.readouterr()
    doc = json.loads(out.out)
    assert any(t["name"] == "X1" and t["status"] == "REFUTED" for t in doc["targets"])
    assert md.read_text().startswith("# Check of")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "drew" in out.err


def test_cli_timeout_stops_with_status_3(tmp_path: Path, capsys, monkeypatch) -> None:
    """A check longer than --timeout stops with status 3.  The check is made slow on
    purpose: the paper's file alone may finish within a second once caches are warm."""
    import time

    from graspcompass.proof import program_check

    def slow(*args, **kwargs):
        end = time.monotonic() + 30
        while time.monotonic() < end:  # interrupted by the alarm of --timeout
            time.sleep(0.01)
        raise AssertionError("--timeout did not stop the check")

    monkeypatch.setattr(program_check, "check_program", slow)
    full = tmp_path / "paper.gc"
    full.write_text(_TEXT)
    assert cli.main(["check", str(full), "--timeout", "1", "-q"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--timeout" in err[0]


def test_a_claim_on_an_object_made_only_for_numbers_is_undecided() -> None:
    text = HEAD + "circle1 = circle_on_diameter O V1\nenv = envelope circle1\nclaim env == env\n"
    assert check_program(parse(text)).claims[0].status is Status.UNDECIDED


def test_check_reads_stdin() -> None:
    p = subprocess.run(
        [sys.executable, "-m", "graspcompass", "check", "-", "-q"],
        input=BASE + "claim collinear A M D\n",
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0 and "PROVED" in p.stdout


def test_parse_errors_carry_file_line_and_column() -> None:
    with pytest.raises(ConstructionSyntaxError, match=r"^f\.gc:2:\d+: "):
        parse("A = point (0, 0)\nB = frobnicate A\n", "f.gc")


def test_a_file_without_parameters_is_decided_on_its_numbers() -> None:
    text = (
        "A = point (0, 0)\nB = point (sqrt(2), 0)\nl = line_through A B\nM = midpoint A B\n"
        "L = signed_length A B l\nclaim M == point(sqrt(2)/2, 0)\nclaim M == point(1/2, 0)\n"
        "claim sign L - sqrt(2) != 0\n"
    )
    r = check_program(parse(text))
    assert [c.status for c in r.claims] == [Status.PROVED, Status.REFUTED, Status.REFUTED]
    assert r.claims[1].counterexample == {}
    assert "no parameters" in to_table(r)


#: Wrong versions of the recipe's own claims (each false at a point of the model): the
#: checker must never prove one, and must refute each at a point of the model.
_CLAIMS_TAIL = _TEXT[_TEXT.index("let t1") :]
MUTATIONS = [
    ("x2*t1) under condition1", "x1*t1) under condition1"),
    ("-(x1 + x2)/2 + y*t1, x2*t1)", "(x1 + x2)/2 + y*t1, x2*t1)"),
    ("(x1 + x2)/2 - y*t2, x1*t2)", "(x1 + x2)/2 - y*t4, x1*t2)"),
    ("-(x1 + x2)/2 + y*t3, x2*t3)", "-(x1 - x2)/2 + y*t3, x2*t3)"),
    ("claim OMX1 == -(-(x1 + x2)/2 + y*t1)", "claim OMX1 == -(x1 + x2)/2 + y*t1"),
    ("claim on X1 side1", "claim on X3 side1"),
    ("claim perpendicular perp1 side1", "claim perpendicular perp1 side3"),
    ("claim collinear O_M X1 X3", "claim collinear O_M X1 Y1"),
    ("claim sign x1 + x2 > 0", "claim sign x1 - x2 > 0"),
    ("let t1 = (sin(phi1) + cos(phi1)*mu1)", "let t1 = (sin(phi1) + cos(phi1)*mu2)"),
]


@pytest.fixture(scope="module")
def right_claims() -> set[str]:
    return {r.name for r in check_program(parse(HEAD + _CLAIMS_TAIL)).claims}


@pytest.mark.parametrize("old, new", MUTATIONS, ids=[n for _, n in MUTATIONS])
def test_wrong_claims_are_never_proved(old: str, new: str, right_claims: set[str]) -> None:
    assert _CLAIMS_TAIL.count(old) == 1, old
    rows = check_program(parse(HEAD + _CLAIMS_TAIL.replace(old, new))).claims
    changed = [r for r in rows if r.name not in right_claims]
    assert changed
    for r in changed:
        assert r.status is Status.REFUTED, (r.name, r.status)
        assert is_model_point(r.counterexample), r.counterexample


def test_an_equivalent_rewriting_stays_proved_with_its_condition() -> None:
    """x1*t4 + (y² − y)/(y − 1) − y is x1*t4 wherever it is defined: PROVED, with the
    condition y − 1 ≠ 0 stated (sympy does not cancel the fraction by itself)."""
    text = HEAD + _CLAIMS_TAIL.replace(
        "x1*t4) under condition1", "x1*t4 + (y**2 - y)/(y - 1) - y) under condition1"
    )
    v4 = next(r for r in check_program(parse(text)).claims if r.name.startswith("V4"))
    assert v4.status is Status.PROVED
    assert any("y - 1" in c for c in v4.result.conditions), v4.result.conditions
