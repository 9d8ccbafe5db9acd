"""Fuzzing at scale: the properties of tests/dsl/test_fuzz.py over a hundred thousand inputs or more.

    python benchmarks/fuzz.py [--inputs 100000] [--seed 0] [--out fuzz-failures] [--cli 0.01]

Every input is one of (shares of the run):

* `phys-mutant` (45 %): an example `.phys` file, mutated (tests/strategies.py), parsed and checked;
  its diagnostics rendered and serialised, and formatted back when it has no syntax error;
* `phys-random` (10 %): text of the language's pieces, or of any characters, the same way;
* `level-mutant` (27 %): a real Science Birds level (tests/data/sciencebirds, physc's own golden
  levels), mutated and re-encoded, read by the level reader;
* `argv` (17 %): a command line with random numeric options, parsed and validated (a usage error
  must not print terminal control characters either);
* `cli` (`--cli`, 1 %): a whole cheap command, in-process: check, fmt, or compile to a stage before
  generation (scenario to layout) of a mutant; simulate or trace of a mutated level for 0.05 or
  0.5 s, with or without a shot; a command line of random numeric options when it asks for little
  work.

One process, one core, inputs drawn from a seeded `random.Random`: the same seed, the same inputs.
Every failure (an exception, a broken property, an exit status other than 0-3, a traceback, a run
past its time, and for `cli` also terminal control characters in what it printed) is counted;
the first input of each kind of failure is saved in the output folder with what happened. Prints
the counts per share, the rate, and the failures.
"""

from __future__ import annotations

import argparse
import random
import re
import sys
import tempfile
import time
import traceback
from collections import Counter
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1] / "tests"
sys.path[:0] = [str(TESTS), str(TESTS / "dsl")]

import strategies  # noqa: E402  (tests/strategies.py: the mutations)
import test_fuzz  # noqa: E402  (tests/dsl/test_fuzz.py: the properties and corpora)

SHARES = [("phys-mutant", 0.45), ("phys-random", 0.10), ("level-mutant", 0.27), ("argv", 0.17)]
PER_INPUT_SECONDS = 60.0
OWN_COLOURS = re.compile(r"\x1b\[(?:1;3[1346]|1|0)m")  # the colours physc's diagnostics use (--color always)


class Fuzzer:
    def __init__(self, rng: random.Random, folder: Path, cli_share: float):
        self.rng = rng
        self.cli_share = cli_share
        self.folder = folder
        self.work = Path(tempfile.mkdtemp(prefix="physc-fuzz-"))
        self.counts: Counter[str] = Counter()
        self.failures: Counter[tuple] = Counter()
        self.saved: dict[tuple, Path] = {}  # the reproducer of each kind of failure
        self.first: dict[tuple, str] = {}  # and the first line of its message

    def pick(self) -> str:
        if self.rng.random() < self.cli_share:
            return "cli"
        roll = self.rng.random() * sum(share for _, share in SHARES)
        for name, share in SHARES:
            roll -= share
            if roll < 0:
                return name
        return SHARES[-1][0]

    # ---- inputs and their properties ------------------------------------------------------------
    def phys_mutant(self) -> str:
        return strategies.mutate_text(self.rng, self.rng.choice(test_fuzz.PHYS_CORPUS), strategies.PHYS_PIECES, test_fuzz.PHYS_CORPUS)

    def level_mutant(self) -> bytes:
        return strategies.mutate_level(self.rng, self.rng.choice(test_fuzz.LEVEL_CORPUS), test_fuzz.LEVEL_CORPUS)

    def argv(self) -> list[str]:
        return strategies.random_argv(self.rng, str(test_fuzz.PAPER), str(test_fuzz.SMALL_LEVEL), str(self.work))

    def one(self, kind: str):
        """Make one input of `kind`; returns (the input, a function that tests it)."""
        if kind == "phys-mutant":
            text = self.phys_mutant()
            return text, lambda: test_fuzz.check_phys(text)
        if kind == "phys-random":
            text = strategies.random_phys(self.rng)
            return text, lambda: test_fuzz.check_phys(text)
        if kind == "level-mutant":
            data = self.level_mutant()
            return data, lambda: test_fuzz.check_level(data)
        if kind == "argv":
            argv = self.argv()
            return argv, lambda: test_fuzz.check_parse(argv, safe_output=True)
        return self.cli_input()

    def cli_input(self):
        choice = self.rng.randrange(3)
        if choice == 0:
            path = self.work / "mutant.phys"
            path.write_bytes(self.phys_mutant().encode("utf-8", "surrogatepass"))
            stage = self.rng.choice(("scenario", "ast", "layout-graph", "qsr", "dimension-graphs", "layout"))
            argv = self.rng.choice((["check", path], ["fmt", path], ["compile", path, "--emit", stage], ["check", "--format", "json", path]))
        elif choice == 1:
            path = self.work / "mutant.xml"
            path.write_bytes(self.level_mutant())
            argv = [self.rng.choice(("simulate", "trace")), path, "--seconds", self.rng.choice(("0.05", "0.5"))]
            if self.rng.random() < 0.5:
                argv.append(self.rng.choice((f"--angle={self.rng.uniform(-90, 90)}", f"--shot={self.rng.uniform(-20, 40)},{self.rng.uniform(-10, 10)}")))
        else:
            argv = self.argv()
            parsed = test_fuzz.check_parse(argv)
            if parsed is None or not _little_work(parsed):
                return argv, lambda: None  # tested as `argv` already; running it would be long
        argv = [str(a) for a in argv] + ["--color", self.rng.choice(("never", "always"))]

        def run():
            done = test_fuzz.check_cli(*argv, seconds=PER_INPUT_SECONDS)
            found = test_fuzz.TERMINAL_CONTROLS.search(OWN_COLOURS.sub("", done.stderr))
            assert found is None, f"unsafe output: {found.group()!r} in {done.stderr[-500:]!r}"

        return argv, run

    # ---- running --------------------------------------------------------------------------------
    def run(self, inputs: int) -> None:
        started = time.perf_counter()
        for index in range(inputs):
            kind = self.pick()
            self.counts[kind] += 1
            made, test = self.one(kind)
            try:
                with test_fuzz.deadline(PER_INPUT_SECONDS):
                    test()
            except (Exception, test_fuzz.Hang) as error:
                self.record(kind, made, error)
            if (index + 1) % 10_000 == 0:
                elapsed = time.perf_counter() - started
                print(f"{index + 1:,} inputs, {elapsed:.0f} s, {sum(self.failures.values())} failures", file=sys.stderr, flush=True)
        self.seconds = time.perf_counter() - started

    def record(self, kind: str, made, error: BaseException) -> None:
        # A kind of failure: where physc raised it, or which property failed (the line of its assert).
        frames = traceback.extract_tb(error.__traceback__)
        ours = [f for f in frames if "/physc/" in f.filename] or frames[-1:]
        where = f"{Path(ours[-1].filename).name}:{ours[-1].lineno}" if ours else "?"
        key = (kind, type(error).__name__, where)
        self.failures[key] += 1
        if key in self.saved:
            return
        self.first[key] = (str(error).splitlines() or [""])[0]
        self.folder.mkdir(parents=True, exist_ok=True)
        stem = self.folder / f"{len(self.saved) + 1:03d}-{kind}"
        if isinstance(made, bytes):
            stem.with_suffix(".xml").write_bytes(made)
        elif isinstance(made, str):
            stem.with_suffix(".phys").write_text(made, encoding="utf-8", errors="surrogatepass")
        report = "".join(traceback.format_exception(error))
        argv = f"argv: {made!r}\n\n" if isinstance(made, list) else ""
        stem.with_suffix(".txt").write_text(f"{kind}: {type(error).__name__}\n{argv}{report}", encoding="utf-8", errors="replace")
        self.saved[key] = stem


def _little_work(parsed) -> bool:
    """Whether a parsed command line runs in about a second or two."""
    if parsed.command == "eval":
        return parsed.tasks <= 1 and parsed.time_budget <= 0.5 and parsed.jobs <= 2
    if parsed.command == "compile":
        return parsed.emit != "level" or parsed.time_budget <= 0.5
    return getattr(parsed, "seconds", 0) <= 2


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--inputs", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="fuzz-failures", help="where the reproducers go")
    parser.add_argument("--cli", type=float, default=0.01, help="share of whole commands (default 0.01)")
    args = parser.parse_args()
    fuzzer = Fuzzer(random.Random(args.seed), Path(args.out), args.cli)
    fuzzer.run(args.inputs)
    total = sum(fuzzer.counts.values())
    print(f"{total:,} inputs in {fuzzer.seconds:.0f} s ({total / fuzzer.seconds:,.0f}/s), seed {args.seed}")
    print("  " + ", ".join(f"{kind} {count:,}" for kind, count in sorted(fuzzer.counts.items())))
    failed = sum(fuzzer.failures.values())
    print(f"{failed} failures" + (f", {len(fuzzer.failures)} kinds; reproducers in {args.out}/" if failed else ""))
    for key, count in fuzzer.failures.most_common():
        kind, name, where = key
        print(f"  {count:6d}  {kind}: {name} at {where}: {fuzzer.first[key][:150]!r}  ({fuzzer.saved[key].name}.*)")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
