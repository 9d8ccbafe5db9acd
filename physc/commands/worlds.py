"""`physc worlds [-v] [DOMAIN...]`: each domain's worlds; -v, every setting and its source."""

from __future__ import annotations

from physc.commands.common import EXIT_OK, chosen, print_json


def _value(value) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, tuple):
        return "(" + ", ".join(_value(v) for v in value) + ")"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k or '(none)'}: {_value(v)}" for k, v in value.items()) + "}"
    if hasattr(value, "__attrs_attrs__"):
        return (
            type(value).__name__
            + "("
            + ", ".join(f"{a.name}={_value(getattr(value, a.name))}" for a in value.__attrs_attrs__)
            + ")"
        )
    return str(value)


def _json(value):
    if isinstance(value, (tuple, list)):
        return [_json(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _json(v) for k, v in value.items()}
    if hasattr(value, "__attrs_attrs__"):
        return {a.name: _json(getattr(value, a.name)) for a in value.__attrs_attrs__}
    return value


def cmd_worlds(args) -> int:
    from physc.domains import installed_domains, load_domain

    listing = []
    for name in chosen(args.name, list(installed_domains()), "domain"):
        domain = load_domain(name)
        default = domain.world.name if domain.worlds else None
        for world in domain.worlds:
            entry = {
                "domain": name,
                "world": world.name,
                "default": world.name == default,
                "description": world.description,
                "derived_from": world.parent,
                "reading": world.reading or None,
                "changes": list(world.changed),
                "concerns": list(world.concerns) if world.parent else None,  # None: a world of its own
            }
            entry["open_points"] = [
                {"setting": p.setting, "readings": _json(p.readings), "question": p.question, "source": p.source}
                for p in world.open_points()
            ]
            if args.verbose:
                entry["settings"] = [
                    {"setting": s.path, "value": _json(s.value), "source": s.source} for s in world.settings()
                ]
            listing.append((world, entry))
    if args.format == "json":
        print_json([entry for _, entry in listing])
        return EXIT_OK
    for world, entry in listing:
        mark = " (default)" if entry["default"] else ""
        print(f"{entry['domain']}/{world.name}{mark}: {world.description}")
        settings = world.settings()
        if world.parent:
            values = {s.path: s.value for s in settings}
            print(
                f"  derived from {world.parent}: "
                + ", ".join(f"{path} = {_value(values[path])}" for path in world.changed)
            )
            kinds = ", ".join(world.concerns) or "any kind (not declared)"
            print(f"  its changes concern links of: {kinds} (exit 3 tries and names it only for such a scenario)")
        points = world.open_points()
        if points:
            print(
                f"  open in its files ({len(world.readings())} readings; a task must hold under each): "
                + "; ".join(f"{p.setting} {' or '.join(_value(v) for v in p.readings)}" for p in points)
            )
        if args.verbose:
            width = max(len(s.path) for s in settings)
            for s in settings:
                print(f"  {s.path:<{width}}  {_value(s.value)}  [{s.source}]")
            for p in points:
                print(f"  open: {p.setting}: {p.question} [{p.source}]")
    return EXIT_OK
