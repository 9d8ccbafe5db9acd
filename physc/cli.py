"""The `physc` command line.

Exit statuses (spec section 7): 0 success; 1 the input has errors; 2 usage error
or unreadable file; 3 no task could be generated. An internal error (a bug in
physc) exits with 70 and asks for a report; `--traceback` shows the Python
traceback for developers.
"""

from __future__ import annotations

import argparse
import os
import sys
import traceback
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from physc import __version__, budget
from physc.commands import arguments
from physc.commands.common import (
    EXIT_INTERNAL,
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_STATUSES,
    EXIT_USAGE,
    Parser,
    UsageError,
    add_format,
)
from physc.commands.completion import add_command as add_completion_command
from physc.commands.evaluate import add_command as add_eval_command
from physc.commands.generate import add_command as add_generate_command
from physc.commands.lsp import add_command as add_lsp_command
from physc.commands.options import add_generation, add_target
from physc.commands.play import add_commands as add_play_commands
from physc.commands.verify import add_command as add_verify_command
from physc.diagnostics import safe
from physc.driver.stages import STAGES

if TYPE_CHECKING:
    from physc.commands.common import Commands


def command(module: str, name: str) -> Callable[[argparse.Namespace], int]:
    """The command `name` of `module`, imported when it runs: building the parser loads no
    command's work (the compiler, the engines, pictures), so `physc -V` answers at once."""

    def run(args: argparse.Namespace) -> int:
        import importlib

        return getattr(importlib.import_module(module), name)(args)

    return run


def usage_errors() -> tuple[type[Exception], ...]:
    """The errors a command reports as a usage error (exit 2), imported once one is raised."""
    from physc.execution import ExecutorError
    from physc.files import OutputError
    from physc.worlds import WorldError

    return (UsageError, OutputError, ExecutorError, WorldError)


# ---- the parser -----------------------------------------------------------------------
def build_parser() -> argparse.ArgumentParser:
    """physc's whole parser: the top level's options and every command, group by group."""
    top, common = _global_options()
    parser = Parser(
        prog="physc",
        description="Compile physical scenarios (.phys) into physics tasks.",
        epilog=EXIT_STATUSES,
        parents=[top],
    )
    parser.add_argument("-V", "--version", action="version", version=f"physc {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)

    _add_source_commands(commands, common)
    _add_compile_command(commands, common)

    add_play_commands(commands, common)
    add_generate_command(commands, common)
    add_eval_command(commands, common)
    add_verify_command(commands, common)

    add_lsp_command(commands, common)
    add_completion_command(commands, common)
    commands.choices["completion"].set_defaults(root=parser)  # the completion script is made from this parser

    _add_listing_commands(commands, common)
    return parser


def _global_options() -> tuple[Parser, Parser]:
    """The options every command takes (--color, --traceback): the top level's, and the copy
    each subcommand takes as a parent."""
    # --color and --traceback go before or after the command: a subcommand sets them only
    # when given there (SUPPRESS), so its defaults never undo the top level's.
    top = Parser(add_help=False)
    top.add_argument("--color", choices=("auto", "always", "never"), default="auto", help="colour diagnostics")
    top.add_argument("--no-color", dest="color", action="store_const", const="never", help="the same as --color never")
    top.add_argument("--traceback", action="store_true", help="show Python tracebacks of internal errors")
    common = Parser(add_help=False)
    common.add_argument(
        "--color", choices=("auto", "always", "never"), default=argparse.SUPPRESS, help="colour diagnostics"
    )
    common.add_argument(
        "--no-color",
        dest="color",
        action="store_const",
        const="never",
        default=argparse.SUPPRESS,
        help="the same as --color never",
    )
    common.add_argument(
        "--traceback", action="store_true", default=argparse.SUPPRESS, help="show Python tracebacks of internal errors"
    )
    return top, common


def _add_source_commands(commands: Commands, common: Parser) -> None:
    """`physc check` and `physc fmt`: the commands that read .phys files as text."""
    check = commands.add_parser("check", parents=[common], help="check .phys files and report every problem")
    check.add_argument("files", nargs="+", metavar="FILE", help="files to check ('-' reads standard input)")
    add_format(check, "the diagnostics")
    check.add_argument("-q", "--quiet", action="store_true", help="no summary line")
    check.set_defaults(run=command("physc.commands.check", "cmd_check"))

    fmt = commands.add_parser("fmt", parents=[common], help="print files in the canonical block form")
    fmt.add_argument("files", nargs="+", metavar="FILE", help="files to format ('-' reads standard input)")
    mode = fmt.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 if a file is not canonical; change nothing")
    mode.add_argument("--write", action="store_true", help="rewrite the files in place")
    add_format(fmt, "each file's canonical form")
    fmt.set_defaults(run=command("physc.commands.fmt", "cmd_fmt"))


def _add_compile_command(commands: Commands, common: Parser) -> None:
    """`physc compile`: one task from a scenario, or a stage of its compile (--emit)."""
    stage_names = ", ".join(s.name for s in STAGES)
    compile_ = commands.add_parser(
        "compile", parents=[common], help="generate a task from a scenario (or print a stage with --emit)"
    )
    compile_.add_argument("file", metavar="FILE")
    compile_.add_argument(
        "-s", "--scenario", action="append", metavar="NAME", help="a scenario of the file (repeatable; default all)"
    )
    compile_.add_argument(
        "--emit", metavar="STAGE", default="level", help=f"the stage to print (default level): {stage_names}"
    )
    compile_.add_argument(
        "-o",
        "--output",
        metavar="PATH",
        help="write the output here instead of stdout (a folder for several scenarios)",
    )
    compile_.add_argument(
        "--task", metavar="PATH", help="also write the task as JSON: scenario, seed, level, solution, trace, timings"
    )
    add_generation(compile_)
    add_target(compile_)
    compile_.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr")
    compile_.add_argument("--seed", type=arguments.seed, default=0, metavar="N", help="the random seed (default 0)")
    compile_.add_argument(
        "--format",
        choices=("json", "dot", "xml"),
        help="the printed stage's format: by default its own (a level: the domain's level file; the other stages:"
        " json); dot (Graphviz) for graph stages",
    )
    compile_.add_argument("--png", metavar="PATH", help="draw the layout or the task (.png or .svg)")
    compile_.set_defaults(run=command("physc.commands.compile", "cmd_compile"))


def _add_listing_commands(commands: Commands, common: Parser) -> None:
    """`physc backends`, `physc worlds`, `physc domains`: what is installed, listed."""
    backends = commands.add_parser(
        "backends", parents=[common], help="list installed physics engines, their versions and what each honours"
    )
    backends.add_argument("name", nargs="*", help="only these backends")
    backends.add_argument(
        "-v",
        "--verbose",
        action="store_true",
        help="say, setting by setting, what each engine does with a world's engine settings",
    )
    add_format(backends, "the engines")
    backends.set_defaults(run=command("physc.commands.backends", "cmd_backends"))

    worlds = commands.add_parser(
        "worlds", parents=[common], help="list each domain's worlds; -v: every setting and where it comes from"
    )
    worlds.add_argument("name", nargs="*", help="only these domains")
    worlds.add_argument(
        "-v",
        "--verbose",
        action="store_true",
        help="every setting of each world, with the file it is read from (a variant's changes: its reading)",
    )
    add_format(worlds, "the worlds")
    worlds.set_defaults(run=command("physc.commands.worlds", "cmd_worlds"))

    domains = commands.add_parser("domains", parents=[common], help="list installed domains and their vocabulary")
    domains.add_argument("name", nargs="*", help="only these domains")
    add_format(domains, "the domains")
    domains.set_defaults(run=command("physc.commands.domains", "cmd_domains"))


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help(sys.stderr)
        return EXIT_USAGE
    try:
        try:
            return args.run(args)
        except Exception as error:
            if isinstance(error, usage_errors()):
                print(f"physc {args.command}: error: {safe(str(error))}", file=sys.stderr)
                return EXIT_USAGE
            raise
    except KeyboardInterrupt:
        budget.stopped()
        print("physc: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # The reader went away (`physc … | head`): not an error of ours.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except Exception as error:  # a bug in physc: never a bare traceback for users
        if args.traceback:
            traceback.print_exc()
            return EXIT_INTERNAL
        print(
            f"physc: internal error: {type(error).__name__}: {safe(str(error))}\n"
            "This is a bug in physc. Please report it with the input that caused it; "
            "run again with --traceback for the details.",
            file=sys.stderr,
        )
        return EXIT_INTERNAL
