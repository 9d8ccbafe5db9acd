"""Fuzzing the two parsers and the command line: whatever the input, an answer, never a crash.

The properties (the `check_*` functions, also run at scale by benchmarks/fuzz.py): parsing and
checking `.phys` text raises nothing, every diagnostic points into the text, renders without a
character that a terminal would act on and serialises to JSON, and a file without syntax errors
formats to text that parses to the same tree; reading level XML raises nothing but a LevelError;
a command exits with a documented status (0, 1, 2, 3), never 70, never prints a traceback, and
ends within its time. The inputs: generated text, mutations of the example files and of real
levels (tests/strategies.py), hostile numeric arguments. This short version is deterministic
(derandomized, no example database) and takes well under a minute.
"""

from __future__ import annotations

import atexit
import contextlib
import io
import json
import re
import shutil
import signal
import tempfile
from pathlib import Path

import pytest
from conftest import EXAMPLES, GOLDEN, ROOT, run_physc
from hypothesis import given
from hypothesis import strategies as st
from strategies import NUMBERS, PHYS_CORPUS, PHYS_PIECES, _texts, fuzz, mutate_level, mutate_text, random_phys, randoms

from physc import error_codes
from physc.diagnostics import exit_status, render, to_json
from physc.domains.angrybirds.level_xml import LevelError, read_level
from physc.domains.words import INSTALLED
from physc.dsl.check import check_file
from physc.dsl.fmt import format_file
from physc.dsl.parser import parse_text

# What a terminal would act on (diagnostics.py escapes these): C0 controls but tab and newline,
# DEL, C1 controls, bidirectional controls, line and paragraph separators.
TERMINAL_CONTROLS = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
EXIT_STATUSES = (0, 1, 2, 3)


# Real levels (tests/data/sciencebirds) when the checkout has them, and physc's own.
LEVEL_FILES = sorted((ROOT / "tests" / "data" / "sciencebirds").rglob("*.xml")) + sorted((GOLDEN / "level").glob("*.xml"))

_LEVEL = '<?xml version="1.0" encoding="utf-16"?>\n<Level width="2">\n<Camera x="0" y="-1" minWidth="25" maxWidth="35" />\n<Birds><Bird type="BirdRed" /></Birds>\n<Slingshot x="-12" y="-2.5" />\n<GameObjects>\n{}\n</GameObjects>\n</Level>\n'
_BLOCK = '<Block type="SquareHole" material="wood" x="{x}" y="{y}" rotation="0" />'
# Documents that attack the reader rather than get a value wrong: entity expansion, external
# entities, deep nesting, a huge document, thousands of blocks at one spot, absurd numbers.
HOSTILE_LEVELS = {
    "entity expansion": '<?xml version="1.0"?>\n<!DOCTYPE Level [<!ENTITY a "aaaaaaaaaaaaaaaa">'
    + "".join(f'<!ENTITY {chr(98 + i)} "{("&" + chr(97 + i) + ";") * 16}">' for i in range(8))
    + ']>\n<Level width="&i;"><GameObjects /></Level>\n',
    "external entity": '<?xml version="1.0"?>\n<!DOCTYPE Level [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n<Level width="&x;" />\n',
    "external DTD": '<?xml version="1.0"?>\n<!DOCTYPE Level SYSTEM "http://example.invalid/level.dtd">\n<Level />\n',
    "deep nesting": "<Level>" + "<GameObjects>" * 100_000 + "</GameObjects>" * 100_000 + "</Level>",
    "unclosed nesting": "<Level>" + "<a>" * 300_000,
    "huge": _LEVEL.format(_BLOCK.format(x=1, y=1) + "<!--" + "x" * 5_000_000 + "-->"),
    "5,000 blocks at one spot": _LEVEL.format("\n".join([_BLOCK.format(x=0, y=0)] * 5000)),
    "150 blocks at one spot": _LEVEL.format("\n".join([_BLOCK.format(x=0, y=0)] * 150)),
    "NaN and huge coordinates": _LEVEL.format(_BLOCK.format(x="nan", y="1e308") + _BLOCK.format(x="inf", y="-0")),
    "no birds": _LEVEL.replace('<Bird type="BirdRed" />', "").format(_BLOCK.format(x=1, y=1)),
}
LEVEL_CORPUS = _texts(LEVEL_FILES) + [text for text in HOSTILE_LEVELS.values() if len(text) < 100_000]
SMALL_LEVEL = min(LEVEL_FILES, key=lambda p: p.stat().st_size)
PAPER = EXAMPLES / "paper" / "04_R.phys"


# ---- the properties ---------------------------------------------------------------------------
def check_phys(text: str) -> None:
    """Parse and check `text`; every diagnostic must be well-formed and safe to print."""
    parsed = parse_text(text, "fuzz.phys")
    checked = check_file(parsed.file, "fuzz.phys", vocabularies=INSTALLED)
    found = parsed.diagnostics + checked.diagnostics
    for diagnostic in found:
        error_codes.lookup(diagnostic.code)
        for span in [diagnostic.span] + [note.span for note in diagnostic.notes]:
            assert span is None or 0 <= span.start <= span.end <= len(text), (diagnostic, span)
        shown = render(diagnostic, parsed.source, "fuzz.phys")
        assert not TERMINAL_CONTROLS.search(shown), shown
        json.dumps(to_json(diagnostic, "fuzz.phys"), ensure_ascii=False)
    assert exit_status(found) in (0, 1)
    if not any(d.is_error for d in parsed.diagnostics):
        formatted = format_file(parsed.file, parsed.source)
        again = parse_text(formatted, "formatted.phys")
        assert not any(d.is_error for d in again.diagnostics), (formatted, again.diagnostics)
        assert again.file == parsed.file, formatted


def check_level(data: bytes) -> None:
    """Read level XML: a Level, or a LevelError with a level code; nothing else."""
    try:
        read_level(data)
    except LevelError as error:
        assert error.code.startswith("E09"), error.code


class Hang(BaseException):
    """A command ran past its time (a BaseException: physc's internal-error handler lets it through)."""


@contextlib.contextmanager
def deadline(seconds: float):
    """Raise Hang after `seconds`, and again every 0.1 s until caught (a callback of a C library may
    swallow the first)."""

    def expire(signum, frame):
        raise Hang(f"still running after {seconds} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds, 0.1)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def check_cli(*argv, seconds: float = 60.0):
    """Run physc in-process: a documented exit status, no traceback, no internal error, in time."""
    with deadline(seconds):
        run = run_physc(*argv)
    assert run.status in EXIT_STATUSES, (argv, run.status, run.stderr[-2000:])
    assert "Traceback" not in run.stderr and "internal error" not in run.stderr, (argv, run.stderr[-2000:])
    return run


def check_parse(argv, safe_output: bool = False):
    """Parse a command line only: a namespace, or a usage error (exit 2); nothing else. With
    `safe_output`, the usage error must not print a character that a terminal would act on."""
    from physc.cli import build_parser

    with contextlib.redirect_stderr(io.StringIO()) as err, contextlib.redirect_stdout(io.StringIO()):
        try:
            return build_parser().parse_args([str(a) for a in argv])
        except SystemExit as exit_:
            assert exit_.code in (0, 2), (argv, exit_.code, err.getvalue())
            assert "Traceback" not in err.getvalue()
            found = TERMINAL_CONTROLS.search(err.getvalue()) if safe_output else None
            assert found is None, f"unsafe output: {found.group()!r} in {err.getvalue()[-300:]!r}"
            return None


# ---- the short version run by the test suite ----------------------------------------------------


FOLDER = Path(tempfile.mkdtemp(prefix="physc-fuzz-"))  # the inputs written for the command line
atexit.register(shutil.rmtree, FOLDER, ignore_errors=True)


def _write(name: str, data: bytes | str) -> Path:
    path = FOLDER / name
    path.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8", "surrogatepass"))
    return path


@fuzz(1000)
@given(randoms)
def test_generated_phys_text(rng):
    check_phys(random_phys(rng))


@fuzz(2000)
@given(randoms, st.sampled_from(PHYS_CORPUS))
def test_mutated_phys_files(rng, text):
    check_phys(mutate_text(rng, text, PHYS_PIECES, PHYS_CORPUS))


@fuzz(1500)
@given(randoms, st.sampled_from(LEVEL_CORPUS))
def test_mutated_levels(rng, text):
    check_level(mutate_level(rng, text, LEVEL_CORPUS))


@fuzz(150)
@given(randoms, st.sampled_from(PHYS_CORPUS), st.sampled_from(["check", "fmt", "scenario", "qsr", "json"]))
def test_mutated_phys_through_the_command_line(rng, text, how):
    path = _write("mutant.phys", mutate_text(rng, text, PHYS_PIECES, PHYS_CORPUS))
    command = {
        "check": ["check", path],
        "fmt": ["fmt", path],
        "scenario": ["compile", path, "--emit", "scenario"],
        "qsr": ["compile", path, "--emit", "qsr"],
        "json": ["check", "--format", "json", path],
    }[how]
    check_cli(*command, "--color", "always")


@pytest.mark.parametrize("name", HOSTILE_LEVELS)
def test_hostile_level_documents(name):
    """Each is read or refused within seconds, with a level error; simulating it too."""
    data = HOSTILE_LEVELS[name].encode("utf-8")
    with deadline(10):
        check_level(data)
    check_cli("simulate", _write("hostile.xml", data), "--angle", "30", "--seconds", "0.2", "--color", "never", seconds=30)


@fuzz(100)
@given(randoms, st.sampled_from(LEVEL_CORPUS), st.sampled_from(["simulate", "trace"]))
def test_mutated_levels_through_the_command_line(rng, text, command):
    path = _write("mutant.xml", mutate_level(rng, text, LEVEL_CORPUS))
    check_cli(command, path, "--seconds", "0.05", "--color", "never", seconds=30)


numbers = st.sampled_from(NUMBERS) | st.floats().map(repr) | st.integers().map(str)
COMPILE_OPTIONS = ["--seed", "--layouts", "--time-budget", "--clause-budget", "--min-robustness"]
PLAY_OPTIONS = ["--seconds", "--angle", "--shot"]
EVAL_OPTIONS = ["--tasks", "--jobs", "--seed", "--time-budget", "--min-robustness"]


@fuzz(150)
@given(st.lists(st.tuples(st.sampled_from(COMPILE_OPTIONS), numbers), min_size=1, max_size=3))
def test_numeric_options_of_compile(options):
    """Cheap stages only: the options are checked before any work, whatever the stage."""
    check_cli("compile", PAPER, "--emit", "scenario", *[part for option in options for part in option], "-q")


@fuzz(100)
@given(st.sampled_from(["simulate", "trace"]), st.sampled_from(PLAY_OPTIONS), numbers, numbers)
def test_numeric_options_of_play(command, option, value, other):
    if option == "--shot":
        value = f"{value},{other}"
    argv = [command, SMALL_LEVEL, f"{option}={value}"]
    if option != "--seconds":
        argv += ["--seconds", "0.2"]
    check_cli(*argv, seconds=30)


@fuzz(60)
@given(st.lists(st.tuples(st.sampled_from(EVAL_OPTIONS), numbers), min_size=1, max_size=3))
def test_numeric_options_of_eval(options):
    """Every combination parses or is refused; one that asks for little work (a task or two of at
    most a second) also runs, to reach the checks that `physc eval` makes after parsing."""
    argv = ["eval", PAPER, "-s", "R", "--out", FOLDER / "eval", "-q", "--tasks", "1", "--time-budget", "0.05"]
    argv += [part for option in options for part in option]
    parsed = check_parse(argv)
    if parsed is not None and parsed.tasks <= 2 and parsed.time_budget <= 1 and parsed.jobs <= 2:
        check_cli(*argv, seconds=60)


@pytest.mark.parametrize("budget", ["1e-9", "0.01", "0.3"])
def test_generation_with_a_tiny_time_budget_answers(budget):
    run = check_cli("compile", EXAMPLES / "paper" / "05_F.phys", "--time-budget", budget, "-o", FOLDER / "f.xml", seconds=30)
    assert run.status in (0, 3)
