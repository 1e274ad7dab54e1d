"""A fuzz test of the command line (issue 10): random hostile argv for every command.

Each case is a cheap valid command line with one to three options replaced by
values from hostile classes (huge, tiny, negative, nan, inf, complex, junk
text, control characters, long lists of angles, odd output paths: /dev/full,
a missing folder, a folder, a file used as a folder, a read-only folder,
unicode names).  ``main(argv)`` runs in-process in a fresh working folder, and
for every case the test asserts:

* the exit status is one the command documents (:data:`graspcompass.cli.EXIT_STATUSES`:
  0, 2, and 1 for ``verify``/``crosscheck``); status 4, an internal error, is a bug;
* on status 2: nothing on stdout, exactly one line on stderr, no traceback;
* no file appears except at the output path the command line names (or the
  command's default name), and none at all when the command fails;
* no number printed as ``nan`` or ``inf``;
* no call runs past a generous hang bound (hang detection, not a speed test).

The run is bounded in time: ``GRASPCOMPASS_FUZZ_SECONDS`` (default 5) seconds of
new cases; ``GRASPCOMPASS_FUZZ_SEED`` fixes the seed (default 0; random when only
the time is raised); ``GRASPCOMPASS_FUZZ_HANG`` sets the hang bound (default 30 s,
for loaded CI machines).  A failure prints the seed and the argv to replay.
"""

from __future__ import annotations

import os
import random
import re
import signal
import threading
import time
from pathlib import Path

import pytest

from graspcompass.cli import build_parser, main

SECONDS = float(os.environ.get("GRASPCOMPASS_FUZZ_SECONDS", "5"))
HANG = float(os.environ.get("GRASPCOMPASS_FUZZ_HANG", "30"))
SEED = int(
    os.environ.get(
        "GRASPCOMPASS_FUZZ_SEED",
        "0" if "GRASPCOMPASS_FUZZ_SECONDS" not in os.environ else str(random.randrange(2**32)),
    )
)

#: Without a display ``explore`` is refused at once; with one it would open a window.
HEADLESS = not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
#: Exit statuses each command documents (4, an internal error, is never acceptable here).
STATUSES = {"verify": {0, 1, 2}, "crosscheck": {0, 1, 2}}
DEFAULT_STATUSES = {0, 2}
COMMANDS = ("draw", "steps", "k", "presets", "animate", "export", "explore", "verify", "crosscheck")


def _registered() -> tuple[str, ...]:
    """Every sub-command of ``graspcompass --help``."""
    p = build_parser()
    sub = next(a for a in p._actions if a.dest == "command")  # the subparsers action
    return tuple(sub.choices)


#: Sub-commands without a generator of their own: grasp options and refused outputs.
OTHERS = tuple(c for c in _registered() if c not in COMMANDS)

NUMBERS = [
    "1e309",
    "-1e309",
    "1e-309",
    "0",
    "-0",
    "nan",
    "inf",
    "-inf",
    "1j",
    "1+2j",
    "10**64",
    "10**65",
    "9" * 300,
    "1e1000",
    "1/0",
    "",
    " ",
    "abc",
    "sqrt(-1)",
    "asin(2)",
    "()",
    "(" * 60 + "1" + ")" * 60,
    "1" + "+1" * 99,
    "\x00",
    "é",
    "🙂",
    "-1",
    "2**-64",
    "1e-1000",
    "3.14159265358979323846264338327950288",
    "atan2(0,0)",
    "tan(pi/2)",
    "cos(10**60)",
    "sin(1e300)",
    "1e300",
    "1e-300",
    "2",
    "0.5",
    "pi/3",
    "60deg",
    "1.2",
    "10**-64",
    "2**64",
    "1e100",
    "-1e100",
    "1e20",
    "1e-20",
    "90deg",
    "pi/2",
    "asin(1/3)",
    "atan(10**30)",
    "0.1",
    "100",
    "1\n2",
    "1 is 1",
    "'\\d'",
    "__import__('os')",
    "().__class__",
    "x" * 100_000,
    "1" * 4301,
    "sqrt(sqrt(2))",
    "°",
    "deg",
    "1°",
]
REFUSED = ["nan", "inf", "1j", "abc", "1/0", "", "asin(2)", "-1", "0", "1e1000", "\x00"]
INTS = [
    "-1",
    "0",
    "1",
    "2",
    "3",
    "1000000000",
    "-999999999999",
    "1e3",
    "nan",
    "9" * 5000,
    "inf",
    "x",
    "",
    "10",
    "44",
    "-44",
    "2147483648",
    "0x10",
    "1_0",
    "٣",
]
FLOATS = [
    "1e-300",
    "0",
    "-1",
    "nan",
    "inf",
    "-inf",
    "1e300",
    "1e309",
    "0.001",
    "1",
    "20",
    "120",
    "121",
    "1e6",
    "x",
    "",
    "1j",
    "10",
    "600",
    "601",
    "0.5",
    "1e-320",
    "5",
]
THETAS = [
    "0:360:1e-300deg",
    "0:1e300:1",
    "0:360:0.0001deg",
    "0:2*pi:pi/5000000",
    "1e309",
    "nan",
    "0:inf:1",
    ":",
    "::",
    "0:1:1:1",
    "0:10**64:1",
    "0:360:30deg",
    "pi/2",
    "0:2*pi:pi/4",
    "0:1:1/1500",
    "1e300",
    "1e-300",
    "10**64",
    "0:10**60:10**53",
    "0:360:1deg",
    "x",
    "",
    "0:360:-1deg",
    "0:pi:pi/4, 30deg",
    "-1e300:1e300:1e293",
    "0:1e-300:1e-307",
    "2**64",
    "cos(10**60)",
    "0:1:1e-6,0:1:1e-6",
    ",".join(["1"] * 600),
    "1," * 1500 + "1",
    "0:90deg:1",
    "0:1:1j",
    "atan2(1, 2), 0:1:0.5",
    "0:1:0.5deg",
    "10**300*10**10",
]
# "0:1:1/1500" takes the float path (1500 rows); a million valid rows take seconds: not here.
GRASP_OPTIONS = ["--x1", "--x2", "--y", "--phi1", "--phi2", "--mu1", "--mu2", "--xi1", "--xi2"]
PRESETS = ["fig6", "table1a", "table1b", "table1c", "nope", ""]
PATHS = [
    "/dev/full",
    "full.{e}",
    "/dev/null",
    "missing/x.{e}",
    "adir",
    "adir/",
    "afile/x.{e}",
    "ro/x.{e}",
    "é🙂.{e}",
    "y" * 300 + ".{e}",
    "\x00.{e}",
    "",
    "x.{e}",
    "/proc/version/x.{e}",
    "a/b/x.{e}",
    "x",
    "x.bogus",
    "adir/y.{e}",
    "~/x.{e}",
    "x.{e}/",
    " .{e}",
    "dir.{e}",
    "-",
    "/nonexistent-graspcompass/x.{e}",
]
REFUSED_PATHS = [
    "missing/x.md",
    "adir",
    "adir/",
    "afile/x.md",
    "",
    "\x00.md",
    "y" * 300,
    "/proc/version/x.md",
    "a/b/x.md",
    "x.md/",
    "dir.md",
    "/nonexistent-gc/x.md",
]
EXTENSIONS = {
    "draw": ["png", "svg", "pdf"],
    "export": ["ggb", "tex", "svg", "json", "html"],
    "animate": ["gif", "html", "mp4"],
    "verify": ["md"],
}


class Hang(BaseException):
    """Raised by the alarm past the hang bound (escapes ``except Exception``)."""


def _grasp(r: random.Random) -> list[str]:
    argv: list[str] = []
    for _ in range(r.choice([0, 1, 1, 2])):
        argv += [r.choice(GRASP_OPTIONS), r.choice(NUMBERS)]
    if r.random() < 0.3:
        argv += ["--preset", r.choice(PRESETS)]
    return argv


def _path(r: random.Random, command: str) -> str:
    return r.choice(PATHS).format(e=r.choice(EXTENSIONS[command]))


def argv_for(r: random.Random) -> list[str]:
    """One random command line: a cheap valid base with hostile values mixed in."""
    command = r.choice(
        [
            "main",
            "draw",
            "steps",
            "k",
            "k",
            "presets",
            "animate",
            "export",
            *(["explore"] * HEADLESS),
            "verify",
            "crosscheck",
            *OTHERS,
        ]
    )
    junk = [r.choice(["--bogus", "x", "-", "--", "\x00", "-q"])] if r.random() < 0.1 else []
    if command == "main":  # a valid main job takes seconds: only refused folders here
        folder = r.choice(
            [
                "missing/out",
                "afile",
                "/dev/null",
                "",
                "\x00",
                "afile/out",
                "/proc/version/out",
                "dir.png/x/y",
            ]
            + ["ro/out"] * (os.geteuid() != 0)
        )  # root writes in ro/
        return [*r.choice([[], ["-q"]]), "--out", folder, *junk]
    argv = [command]
    if command in OTHERS:  # a command added later: hostile grasp values, refused outputs
        return [*argv, *_grasp(r), "-o", r.choice(REFUSED_PATHS), *junk]
    if command == "presets":
        return argv + junk
    if command == "steps":
        return argv + _grasp(r) + r.choice([[], ["--json"]]) + junk
    if command == "k":
        argv += [
            "--preset",
            "table1a",
            *_grasp(r),
            "--theta",
            r.choice(THETAS) if r.random() < 0.8 else "0:90:30deg",
        ]
        if r.random() < 0.3:
            argv += ["--external-force", r.choice(NUMBERS)]
        return argv + [o for o in ("--exact", "--json") if r.random() < 0.3] + junk
    if command == "explore":  # no display: always refused, after the grasp is read
        return argv + _grasp(r) + junk
    if command == "verify":  # a valid run takes seconds: refused options only
        return (
            argv
            + r.choice(
                [
                    ["--markdown", r.choice(REFUSED_PATHS)],
                    ["--bogus"],
                    ["--certify", "--x1", r.choice(REFUSED)],
                ]
            )
            + ["--preset", "nope"] * (r.random() < 0.5)
            + junk
        )
    if command == "crosscheck":
        for option in ("--grasps", "--thetas", "--seed"):
            argv += [option, r.choice(INTS) if r.random() < 0.4 else "1"]
        return [*argv, "-q", *junk]
    mutate = r.random() < 0.7
    argv += _grasp(r) if not mutate or r.random() < 0.4 else ["--preset", "table1a"]
    argv += [
        "-o",
        _path(r, command)
        if mutate and r.random() < 0.6
        else f"out.{EXTENSIONS[command][r.randrange(2)]}",
    ]
    if command == "draw":
        if r.random() < 0.3:
            argv += ["--format", r.choice(["png", "svg", "pdf", "gif", ""])]
        if r.random() < 0.3:
            argv += ["--step", r.choice(INTS)]
        return argv + ["--no-overlay"] * (r.random() < 0.5) + ["-q"] + junk
    if command == "export":
        if r.random() < 0.3:
            argv += ["--format", r.choice(["ggb", "tikz", "svg", "json", "html", "png", "doc"])]
        if r.random() < 0.3:
            argv += ["--step", r.choice(INTS)]
        if r.random() < 0.3:
            argv += ["--title", r.choice([*NUMBERS, "<script>", "}{\\", "a\tb"])]
        return argv + ["--fragment"] * (r.random() < 0.2) + ["-q"] + junk
    # a valid construction animation has hundreds of frames (seconds): its options are
    # checked by the same code as the sweep's
    argv += ["--kind", r.choice(["sweep", "orientation", "spin"])]
    cheap = {"--frames": "2", "--dpi": "10", "--frames-per-step": "1"}
    for option, pool in (
        ("--fps", FLOATS),
        ("--frames", INTS),
        ("--frames-per-step", INTS),
        ("--weight", FLOATS),
        ("--dpi", FLOATS),
    ):
        if mutate and r.random() < 0.3:
            value = r.choice(pool)
            if option in cheap and value.isdigit() and len(value) < 12 and int(value) > 100:
                value = str(int(value) + 10**9)  # refused; a valid big value takes minutes
            argv += [option, value]
        elif option in cheap:
            argv += [option, cheap[option]]
    return [*argv, "-q", *junk]


def _files(root: Path) -> set[str]:
    return {str(p.relative_to(root)) for p in root.rglob("*")}


def _allowed(argv: list[str], new: set[str]) -> set[str]:
    """The new files the command line names (its outputs, or a default name), at any depth."""
    named = {
        argv[i + 1]
        for i, a in enumerate(argv[:-1])
        if a in ("-o", "--output", "--out", "--markdown")
    }
    named = {os.path.normpath(n) for n in named if n.strip() and "\0" not in n}
    default = re.compile(r"^(fig6|table1[abc])(\.\w+|-\w+\.gif)$")
    return {
        f
        for f in new
        if default.match(f) or any(f == n or f.startswith(n.rstrip("/") + "/") for n in named)
    }


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    for name in ("adir", "ro", "dir.png", "dir.svg", "dir.gif", "dir.ggb", "dir.md"):
        (tmp_path / name).mkdir()
    (tmp_path / "afile").write_text("x")
    for ext in {e for exts in EXTENSIONS.values() for e in exts}:
        (tmp_path / f"full.{ext}").symlink_to("/dev/full")  # a good name, a full disk
    (tmp_path / "ro").chmod(0o555)
    monkeypatch.chdir(tmp_path)
    yield tmp_path
    (tmp_path / "ro").chmod(0o755)


def _run(argv: list[str]) -> tuple[int, float]:
    """``main(argv)`` with the hang alarm; returns (status, seconds)."""

    def alarm(signum, frame):
        raise Hang

    use_alarm = threading.current_thread() is threading.main_thread()
    if use_alarm:
        old = signal.signal(signal.SIGALRM, alarm)
        signal.setitimer(signal.ITIMER_REAL, HANG)
    start = time.perf_counter()
    try:
        code = main(argv)
    except Hang:
        pytest.fail(f"hang: over {HANG:g} s for argv={argv!r} (seed {SEED})")
    finally:
        if use_alarm:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    return code, time.perf_counter() - start


def test_cli_fuzz(workdir, capsys):
    r = random.Random(SEED)
    stop = time.perf_counter() + SECONDS
    cases, slowest, seen = 0, (0.0, []), set()
    while time.perf_counter() < stop:
        argv = argv_for(r)
        before = _files(workdir)
        code, seconds = _run(argv)
        out, err = capsys.readouterr()
        cases += 1
        slowest = max(slowest, (seconds, argv))
        where = f"argv={argv!r} (seed {SEED}, case {cases})"
        command = argv[0] if argv[0] in COMMANDS + OTHERS else "main"
        assert code in STATUSES.get(command, DEFAULT_STATUSES), (
            f"status {code}: {err.strip()[-300:]!r} for {where}"
        )
        assert "Traceback" not in err, f"traceback for {where}: {err[-500:]}"
        if code == 2:
            assert out == "", where
            assert len(err.strip().splitlines()) == 1, f"{err!r} for {where}"
        else:
            assert not re.search(r"(?<![\w.])-?(nan|inf)(?![\w])", out), where
        new = _files(workdir) - before
        if code == 2:
            assert not new, f"files {sorted(new)} made by a refused {where}"
        else:
            assert new <= _allowed(argv, new), (
                f"files {sorted(new - _allowed(argv, new))} outside the outputs of {where}"
            )
        seen.add(command)
        for name in new:  # keep the folder as it was for the next case
            p = workdir / name
            if p.is_file():
                p.unlink()
        for name in sorted(new, key=len, reverse=True):
            p = workdir / name
            if p.is_dir():
                p.rmdir()
    print(
        f"cli fuzz: {cases} cases, seed {SEED}, commands {sorted(seen)}, slowest "
        f"{slowest[0]:.2f} s: {slowest[1]!r}"[:400]
    )
    assert cases >= 1
