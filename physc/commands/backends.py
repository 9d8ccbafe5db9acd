"""`physc backends`: the installed physics engines, their versions, and what each makes of
a target world's engine settings."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

from physc.commands.common import EXIT_OK, chosen, print_json


def _version(package: str) -> str | None:
    try:
        return version(package) if package else None
    except PackageNotFoundError:
        return None


def describe(name: str) -> dict:
    """One backend: its name, whether it loads (and why not), its engine's version, the
    default's mark, and what it does with each engine setting."""
    from physc.backends import DEFAULT_BACKEND, BackendError, load_backend

    entry = {"name": name, "default": name == DEFAULT_BACKEND}
    try:
        backend = load_backend(name)
    except BackendError as error:
        return entry | {"installed": False, "error": str(error)}
    return entry | {
        "installed": True,
        "description": backend.description,
        "package": backend.package or None,
        "version": _version(backend.package),
        "honours": dict(backend.honours),
    }


def cmd_backends(args) -> int:
    from physc.backends import installed_backends

    names = chosen(args.name, list(installed_backends()), "backend")
    entries = [describe(name) for name in names]
    if args.format == "json":
        print_json(entries)
        return EXIT_OK
    if not entries:
        print("no physics backends installed (physc.backends entry points)")
    for entry in entries:
        mark = " (default)" if entry["default"] else ""
        if not entry["installed"]:
            print(f"{entry['name']}{mark}: not usable: {entry['error']}")
            continue
        engine = (
            f"{entry['package']} {entry['version']}" if entry["version"] else (entry["package"] or "version unknown")
        )
        print(f"{entry['name']}{mark}: {engine}: {entry['description']}")
        if args.verbose:
            for setting, how in entry["honours"].items():
                print(f"    {setting:<24} {how}")
    return EXIT_OK
