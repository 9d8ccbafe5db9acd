"""The `physc` executable's entry point: nothing but the interrupt guard around the command line.

Importing the command line takes a moment (numpy, the engines); a Ctrl-C in that moment, or
while the arguments are parsed, must end as any other interrupt does (exit 130, one line),
never with a traceback from the imports. physc.cli.main handles interrupts once it runs.
"""

from __future__ import annotations

import sys

from physc.exits import EXIT_INTERRUPTED


def main(argv=None) -> int:
    try:
        from physc.cli import main as run

        return run(argv)
    except KeyboardInterrupt:
        print("physc: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
