"""`physc lsp`: run the language server for .phys files over stdio (docs/editors.md)."""

from __future__ import annotations

from physc.commands.common import EXIT_OK, UsageError


def add_command(commands, common) -> None:
    lsp = commands.add_parser("lsp", parents=[common], help="run the language server for editors (stdio)")
    lsp.add_argument("--stdio", action="store_true", help="talk over stdin and stdout (the default; editors pass it)")
    lsp.add_argument("--log-file", metavar="PATH", help="log the server's requests and errors to this file")
    lsp.set_defaults(run=cmd_lsp)


def cmd_lsp(args) -> int:
    try:
        from physc.lsp.server import serve
    except ImportError as error:
        raise UsageError(
            f"the language server needs the 'lsp' extra ({error.name} is missing):"
            " pip install -e '.[lsp]' in physc's checkout"
        ) from error
    if args.log_file:
        try:
            open(args.log_file, "a", encoding="utf-8").close()
        except OSError as error:
            raise UsageError(f"cannot write the log file {args.log_file}: {error.strerror or error}") from error
    serve(args.log_file)
    return EXIT_OK
