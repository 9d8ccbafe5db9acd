"""`physc fmt`: print or rewrite .phys files in the canonical block form."""

from __future__ import annotations

import sys

from physc import diagnostics
from physc.commands.common import (
    EXIT_INPUT,
    EXIT_OK,
    UsageError,
    print_json,
    reporter,
)
from physc.files import write_atomic


def cmd_fmt(args) -> int:
    from physc.dsl.fmt import format_file
    from physc.dsl.frontend import analyze

    if args.write and "-" in args.files:
        raise UsageError("--write cannot rewrite standard input")
    status = EXIT_OK
    report = reporter(args)
    changed, listed = [], []
    for path in args.files:
        analysis = analyze(path, None, check=False)  # formatting checks nothing: no vocabularies
        if analysis.file is None or any(d.is_error for d in analysis.syntax):
            report(path, analysis.source, analysis.diagnostics)
            status = max(status, diagnostics.exit_status(analysis.diagnostics))
            continue
        assert analysis.source is not None, "a parsed file was read"
        formatted = format_file(analysis.file, analysis.source)
        canonical = formatted == analysis.source.text
        printing = not (args.check or args.write)
        if not canonical:
            changed.append(path)
            if args.write:
                write_atomic(path, formatted)
        if args.format == "json":
            entry = {"file": str(path), "canonical": canonical}
            if args.write and not canonical:
                entry["rewritten"] = True
            elif printing:
                entry["formatted"] = formatted
            listed.append(entry)
        elif printing:
            sys.stdout.write(formatted)
        elif not canonical:
            print(f"{'reformatted' if args.write else 'would reformat'} {diagnostics.safe(str(path))}", file=sys.stderr)
    if args.format == "json":
        print_json(listed)
    if args.check and changed:
        status = max(status, EXIT_INPUT)
    return status
