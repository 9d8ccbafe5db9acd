"""Large and hostile inputs each get an answer in bounded time and memory.

Makes the inputs of issue 30 in a temporary folder and runs physc on each under
`/usr/bin/time -v`, printing a Markdown table of exit status, wall seconds and peak
memory (maximum resident set size) against the targets, 60 s and 2 GB:

* a scenario of 200 interactions (a chain of slides), compiled with the defaults;
* one 5 MB scenario (a chain of 80,000 interactions), checked;
* 5,000 repeated restrictions in scenario R, compiled with --time-budget 10;
* a level of 5,000 blocks at one spot, simulated for 10 s;
* a billion-laughs level (entity expansion), simulated;
* a 10,000-deep nested level, simulated.

    python benchmarks/hostile_inputs.py [--only NAME]
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET_SECONDS, TARGET_BYTES = 60.0, 2 * 1024**3


def chain(interactions: int) -> str:
    """A scenario: the bird hits s1, each sK slides on hK and hits s(K+1), the last one the pig."""
    n = max((interactions - 2) // 2, 1)
    objects = "\n".join(f"        s{k}: slidableBlock\n        h{k}: hSurface" for k in range(1, n + 1))
    terms = ["hit(bird, s1, left)"]
    for k in range(1, n + 1):
        terms.append(f"slide(s{k}, h{k}, right)")
        if k < n:
            terms.append(f"hit(s{k}, s{k + 1}, left)")
    terms += [f"hit(s{n}, pig, left)", f"destroy(s{n}, pig)"]
    body = "\n        > ".join(terms)
    return f"scenario Long {{\n    objects {{\n{objects}\n    }}\n    interactions {{\n        {body}\n    }}\n}}\n"


def level(objects: str, prolog: str = "") -> str:
    return (
        f'<?xml version="1.0" encoding="utf-16"?>\n{prolog}<Level width="2">\n<Birds><Bird type="BirdRed"/></Birds>\n'
        f"<GameObjects>\n{objects}</GameObjects>\n</Level>\n"
    )


def inputs(folder: Path) -> dict[str, list[str]]:
    """name → the physc command line, with its input written into `folder`."""
    (folder / "long200.phys").write_text(chain(200))
    big = chain(80_000)
    (folder / "big.phys").write_text(big)
    rolling = (ROOT / "examples" / "paper" / "04_R.phys").read_text()
    repeated = rolling.replace("cannotFall(rBlock)", "cannotFall(rBlock)\n" + "        cannotHit(bird, pig, any)\n" * 5000)
    (folder / "repeated.phys").write_text(repeated)
    blocks = '<Block type="SquareSmall" material="wood" x="0" y="-3"/>\n' * 5000
    (folder / "blocks5000.xml").write_text(level(blocks))
    laughs = '<!DOCTYPE Level [<!ENTITY a "aaaaaaaaaa">' + "".join(
        f'<!ENTITY {chr(98 + i)} "{("&" + chr(97 + i) + ";") * 10}">' for i in range(9)
    ) + "]>\n"
    (folder / "laughs.xml").write_text(level('<Block type="SquareSmall" material="wood" x="0" y="-3" name="&j;"/>\n', laughs))
    (folder / "deep.xml").write_text(level("<a>" * 10_000 + "</a>" * 10_000 + "\n"))
    return {
        "200 interactions (compile)": ["compile", str(folder / "long200.phys"), "-o", str(folder / "out.xml")],
        f"one {len(big.encode()) / 1e6:.1f} MB scenario (check)": ["check", str(folder / "big.phys")],
        "5,000 repeated restrictions (compile --time-budget 10)": ["compile", str(folder / "repeated.phys"), "--time-budget", "10", "-o", str(folder / "r.xml")],
        "5,000 blocks at one spot (simulate)": ["simulate", str(folder / "blocks5000.xml")],
        "billion laughs (simulate)": ["simulate", str(folder / "laughs.xml")],
        "10,000-deep nesting (simulate)": ["simulate", str(folder / "deep.xml")],
    }


def measure(command: list[str]) -> tuple[int, float, int]:
    """(exit status, wall seconds, peak bytes) of `physc COMMAND` under /usr/bin/time -v."""
    done = subprocess.run(
        ["/usr/bin/time", "-v", sys.executable, "-m", "physc", *command, "--color", "never"],
        capture_output=True,
        text=True,
    )
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", done.stderr)
    hours, minutes, seconds = (float(g or 0) for g in wall.groups())
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", done.stderr).group(1)) * 1024
    status = int(re.search(r"Exit status: (\d+)", done.stderr).group(1))
    return status, hours * 3600 + minutes * 60 + seconds, peak


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", help="run only the inputs whose name contains this")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as temporary:
        print("| input | exit | wall s | peak MB | within 60 s and 2 GB |")
        print("|---|---|---|---|---|")
        for name, command in inputs(Path(temporary)).items():
            if args.only and args.only not in name:
                continue
            status, wall, peak = measure(command)
            ok = "yes" if wall <= TARGET_SECONDS and peak <= TARGET_BYTES and status != 70 else "**no**"
            print(f"| {name} | {status} | {wall:.1f} | {peak / 1e6:.0f} | {ok} |", flush=True)


if __name__ == "__main__":
    main()
