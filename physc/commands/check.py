"""`physc check`: report every error and warning of .phys files."""

from __future__ import annotations

import json
import sys

from physc import diagnostics
from physc.commands.common import (
    EXIT_OK,
    reporter,
    summary,
)


def cmd_check(args) -> int:
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze

    status = EXIT_OK
    errors = warnings = 0
    as_json = []
    report = reporter(args)
    for path in args.files:
        analysis = analyze(path, vocabularies=INSTALLED)
        found = analysis.diagnostics
        status = max(status, diagnostics.exit_status(found))
        errors += sum(d.is_error for d in found)
        warnings += sum(not d.is_error for d in found)
        if args.format == "json":
            as_json += [diagnostics.to_json(d, path) for d in found]
        else:
            report(path, analysis.source, found)
    if args.format == "json":
        print(json.dumps(as_json, indent=2, ensure_ascii=False))
    elif not args.quiet:
        print(summary(errors, warnings, len(args.files)), file=sys.stderr)
    return status
