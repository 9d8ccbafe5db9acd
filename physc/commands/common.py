"""What every command shares: exit statuses, usage errors, diagnostic output."""

from __future__ import annotations

import argparse
import os
import sys
from typing import Sequence

from physc import diagnostics
from physc.compiler.task import MIN_ROBUSTNESS
from physc.diagnostics import Diagnostic

EXIT_OK, EXIT_INPUT, EXIT_USAGE, EXIT_INFEASIBLE, EXIT_INTERNAL = 0, 1, 2, 3, 70
EXIT_INTERRUPTED = 130  # Ctrl-C: 128 + SIGINT, as shells report it


class UsageError(Exception):
    pass


class Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse's own errors: usage, exit 2
        self.print_usage(sys.stderr)
        print(f"{self.prog}: error: {diagnostics.safe(message)}", file=sys.stderr)  # the value as typed: escaped
        raise SystemExit(EXIT_USAGE)


def reporter(args):
    def use_color() -> bool:
        if args.color == "always":
            return True
        if args.color == "never" or os.environ.get("NO_COLOR"):
            return False
        return sys.stderr.isatty()

    color = use_color()

    def report(analysis_path: str, source, found: Sequence[Diagnostic]) -> None:
        for diagnostic in found:
            print(diagnostics.render(diagnostic, source, analysis_path, color=color), file=sys.stderr)

    return report


def summary(errors: int, warnings: int, files: int) -> str:
    def plural(n, word):
        return f"{n} {word}{'' if n == 1 else 's'}"

    return f"{plural(errors, 'error')}, {plural(warnings, 'warning')} in {plural(files, 'file')}"


def add_min_robustness(parser) -> None:
    from physc.commands.arguments import count

    parser.add_argument(
        "--min-robustness",
        type=count,
        default=MIN_ROBUSTNESS,
        metavar="K",
        help="when no layout within the budget gives a solution that passes every noisy replay of the generator "
        f"(6 in angrybirds), use the most robust one that passes at least K of them, and as many fresh replays "
        f"(default {MIN_ROBUSTNESS}; 6: no such fallbacks); the task JSON records the replays passed",
    )


def check_min_robustness(value: int, domain) -> None:
    """--min-robustness counts the domain's noisy replays: more than there are cannot be passed."""
    replays = getattr(domain, "robustness_replays", None)
    if replays is not None and value > replays:
        raise UsageError(
            f"--min-robustness takes a whole number from 1 to {replays} (the noisy replays of domain "
            f"'{domain.name}'), not {value}"
        )


def chosen(asked: Sequence[str], installed: Sequence[str], kind: str) -> list[str]:
    """The installed plugins a listing command names (`physc domains`, `physc backends`): all
    of them, or those `asked`; an unknown name is a usage error with a did-you-mean."""
    from physc.suggest import did_you_mean

    names = list(installed)
    unknown = [n for n in asked if n not in names]
    if unknown:
        hint = did_you_mean(unknown[0], names) or f"installed {kind}s: " + (", ".join(names) or "none")
        raise UsageError(f"the {kind} '{unknown[0]}' is not installed; {hint}")
    return list(asked) or names


def check_backends(args) -> None:
    """--verify-backend must name another engine than the one that simulates."""
    if getattr(args, "verify_backend", None) and args.verify_backend == args.backend:
        raise UsageError(f"--verify-backend {args.verify_backend} is the engine that already simulates (--backend): name another one")


def add_backend(parser, verify: bool = True) -> None:
    """--backend (the engine that simulates) and, with `verify`, --verify-backend (a second
    engine the task's solution must pass in too)."""
    from physc.backends import DEFAULT_BACKEND
    from physc.commands.arguments import backend

    parser.add_argument(
        "--backend", type=backend, default=DEFAULT_BACKEND, metavar="NAME",
        help=f"the physics engine that simulates (default {DEFAULT_BACKEND}, the game's; pymunk and bullet are built in too: physc backends)",
    )
    if verify:
        parser.add_argument(
            "--verify-backend", type=backend, metavar="NAME",
            help="a second physics backend (e.g. bullet) in which the task's solution must also solve the level and "
            "realise the sequence, in its noisy replays too",
        )
