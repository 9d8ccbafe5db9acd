"""Levels made by Phy-Q's own task generator, with a recorded seed: the calibration set's source.

    python tools/phyq_generate.py GENERATOR TEMPLATES OUT --seed 1 --variants 5 [--scenarios 1_1 2_1 ...]

GENERATOR is `tasks/task_generator/` of a checkout of phy-q/benchmark (commit 514491c, the
templates' commit); TEMPLATES a folder of Phy-Q's templates (`category_scenario_template_1.xml`);
OUT the folder the levels are written to, flat, under the generator's own names
(`2_03_02_00001.xml`: scenario 2_3, template 2, variant 1). Phy-Q's generator draws from
Python's `random` without a seed and lists its input folder in the file system's order; this
driver runs the generator's own code unchanged, one template at a time in sorted order, with
`random` seeded from (seed, template) before each, so that the same seed gives the same levels.
physc does not import the generator: it is another project's code, run here only to make data
(benchmarks/data/phyq-generated-levels/PROVENANCE.md says how the stored samples were made).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import random
import shutil
import sys
import tempfile
from pathlib import Path


def generate(generator: Path, templates: Path, out: Path, seed: int, variants: int, scenarios: list[str]) -> list[Path]:
    """Run Phy-Q's generator on each template of `scenarios`; return the levels written."""
    sys.path.insert(0, str(generator.resolve()))
    sys.argv = [sys.argv[0], str(variants)]  # the generator reads its count from argv[1]
    from generate_tasks import GenerateVariations  # type: ignore[import-not-found]  # noqa: PLC0415 - another project's script
    from utils.generate_variations import GenerateLevels  # type: ignore[import-not-found]  # noqa: PLC0415

    writer, levels = GenerateVariations(), GenerateLevels()
    out = out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    paths = sorted(p.resolve() for p in templates.glob("*.xml") if any(p.name.startswith(s + "_") for s in scenarios))
    with tempfile.TemporaryDirectory() as work, contextlib.chdir(work), open(os.devnull, "w") as quiet, contextlib.redirect_stdout(quiet):
        for path in paths:
            name = path.name.rsplit("_", 1)[0]
            random.seed(f"{seed}:{name}")
            birds, blocks, pigs, tnts, meta = writer.read_level_file(str(path))
            made = levels.generate_levels_from_template(name, [blocks, pigs, tnts])
            writer.write_all_levels(birds, meta, made, name)
        for level in sorted(Path(work, "output").rglob("*.xml")):
            target = out / level.name
            shutil.copyfile(level, target)
            written.append(target)
    return written


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("generator", type=Path, help="tasks/task_generator/ of phy-q/benchmark at 514491c")
    parser.add_argument("templates", type=Path, help="a folder of Phy-Q's templates")
    parser.add_argument("out", type=Path, help="where the levels go")
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--variants", type=int, default=5, help="levels per template (default 5)")
    parser.add_argument("--scenarios", nargs="+", default=["1_1", "2_1", "2_2", "2_3", "2_4"], help="Phy-Q scenarios (default: single force, rolling, falling, sliding, bouncing)")
    args = parser.parse_args()
    written = generate(args.generator, args.templates, args.out, args.seed, args.variants, args.scenarios)
    print(f"{len(written)} levels in {args.out}")


if __name__ == "__main__":
    main()
