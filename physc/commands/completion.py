"""`physc completion SHELL`: the shell's completion script for physc, made by shtab from the
command line's own parser, so it always offers the commands and flags this physc has."""

from __future__ import annotations

from physc.commands.common import EXIT_OK

SHELLS = ("bash", "zsh", "tcsh", "fish", "powershell")
FILE_OPTIONS = {"-o", "--output", "--task", "--png", "--out", "--log-file"}


def cmd_completion(args) -> int:
    import shtab

    parser = args.root  # the whole command line's parser, handed over by physc.cli
    _mark_files(parser, shtab)
    print(shtab.complete(parser, shell=args.shell, root_prefix="physc"))
    return EXIT_OK


def _mark_files(parser, shtab) -> None:
    """File names complete where physc takes a file: the .phys files, levels and paths."""
    for action in parser._actions:
        if action.dest in ("files", "file", "level") or set(action.option_strings) & FILE_OPTIONS:
            action.complete = shtab.FILE
        if isinstance(action.choices, dict):  # the subcommands
            for sub in action.choices.values():
                _mark_files(sub, shtab)


def add_command(commands, common) -> None:
    parser = commands.add_parser(
        "completion",
        parents=[common],
        help="print the shell completion script (bash, zsh, tcsh, fish, powershell)",
        description="Print physc's completion script for SHELL. bash: `physc completion bash >"
        " ~/.local/share/bash-completion/completions/physc`; "
        "zsh: `physc completion zsh > ~/.zfunc/_physc` (with ~/.zfunc in $fpath).",
    )
    parser.add_argument("shell", choices=SHELLS, metavar="SHELL", help=f"one of {', '.join(SHELLS)}")
    parser.set_defaults(run=cmd_completion)
