"""The README's picture is a build artefact: made by the command its caption names.

    python tools/readme_picture.py          # make docs/images/task_F.png again
    python tools/readme_picture.py --check  # exit 1 if the picture or caption no longer match

The caption's command (`physc compile … --png f.png`) is read from the README, run in a
temporary folder, and its picture written over the README's (or, with --check, compared with
it: the same size and pixels within a rendering's anti-aliasing, TOLERANCE). The check also
asks that the task realises what the caption says happens (CLAIMS).
"""

from __future__ import annotations

import json
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
TOLERANCE = 0.01  # mean absolute difference of the pixels' channels, in [0, 1]
# What the caption says the intended solution does, as interactions its trace must hold in order.
CLAIMS = ("hit(bird, fBlock, left)", "fall(fBlock, pig)", "destroy(fBlock, pig)")


def caption() -> tuple[Path, list[str]]:
    """The README's picture and the command its caption names (as arguments to physc)."""
    text = README.read_text(encoding="utf-8")
    image = re.search(r"!\[[^\]]*\]\(([^)]+\.png)\)", text)
    command = re.search(r"`physc (compile [^`]*--png [^`]*)`", text[image.end() :]) if image else None
    if not image or not command:
        sys.exit("README.md: no picture followed by a caption naming `physc compile … --png …`")
    return ROOT / image.group(1), shlex.split(command.group(1))


def make(arguments: list[str], folder: Path) -> tuple[Path, dict]:
    """Run the caption's command in `folder` (with --task beside it): its picture and task."""
    task = folder / "task.json"
    subprocess.run([sys.executable, "-m", "physc", *arguments, "--task", str(task), "-q"], cwd=folder, check=True, env=_env())
    picture = folder / arguments[arguments.index("--png") + 1]
    return picture, json.loads(task.read_text(encoding="utf-8"))


def _env() -> dict:
    import os

    # The examples' paths in the caption are relative to the repository.
    return dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH", "")])))


def differences(made: Path, kept: Path) -> list[str]:
    import matplotlib.image as image
    import numpy as np

    a, b = image.imread(made), image.imread(kept)
    if a.shape != b.shape:
        return [f"{kept.name} is {b.shape[1]}×{b.shape[0]}, the command draws {a.shape[1]}×{a.shape[0]}"]
    gap = float(np.abs(a - b).mean())
    return [f"{kept.name} differs from what the command draws (mean difference {gap:.4f} > {TOLERANCE})"] if gap > TOLERANCE else []


def main(argv: list[str]) -> int:
    picture, arguments = caption()
    arguments = [str(ROOT / a) if a.endswith(".phys") else a for a in arguments]
    with tempfile.TemporaryDirectory() as folder:
        made, task = make(arguments, Path(folder))
        trace = task["trace"].split(" > ")
        positions = [trace.index(c) if c in trace else -1 for c in CLAIMS]
        problems = [] if -1 not in positions and positions == sorted(positions) else [f"the task's trace ({task['trace']}) does not show the caption's {' > '.join(CLAIMS)}"]
        if "--check" in argv:
            problems += differences(made, picture)
            for problem in problems:
                print(f"readme_picture: {problem}", file=sys.stderr)
            return 1 if problems else 0
        picture.write_bytes(made.read_bytes())
        print(f"wrote {picture.relative_to(ROOT)}; trace {task['trace']}")
        return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
