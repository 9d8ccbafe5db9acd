"""`physc domains`: the installed domains and their vocabulary."""

from __future__ import annotations

import sys

from physc.commands.common import EXIT_OK, EXIT_USAGE, chosen, print_json


def cmd_domains(args) -> int:
    from physc.domains import DomainError, installed_domains, load_domain

    names = chosen(args.name, list(installed_domains()), "domain")
    loaded = []
    for name in names:
        try:
            loaded.append(load_domain(name))
        except DomainError as error:
            print(f"physc: error[{error.code}]: {error.message}", file=sys.stderr)
            return EXIT_USAGE
    if args.format == "json":
        from physc.serialize import to_data

        print_json(
            [{"name": d.name, "description": d.description, "vocabulary": to_data(d.vocabulary)} for d in loaded]
        )
        return EXIT_OK
    if not loaded:
        print("no domains installed (physc.domains entry points)")
    for index, domain in enumerate(loaded):
        if index:
            print()
        print(_describe_domain(domain))
    return EXIT_OK


def _describe_domain(domain) -> str:
    vocabulary = domain.vocabulary
    lines = [f"{domain.name}: {domain.description}", "  object terms:"]
    for term in vocabulary.object_terms:
        label = term.name + (f" ({term.abbreviation})" if term.abbreviation else "")
        pinned = f"  (pinned only: {' | '.join(term.pinnable)})" if term.pinnable else ""
        lines.append(f"    {label:<34} {' | '.join(term.concrete)}{pinned}")
    for kind in ("interaction", "restriction"):
        lines.append(f"  {kind} terms:")
        for term in vocabulary.terms:
            if term.kind == kind:
                lines.append(f"    {term.usage():<58} {term.description}")
    statics = [c.name for c in vocabulary.concrete_objects if c.static]
    lines.append(f"  static objects: {', '.join(statics)}")
    materials = vocabulary.materials(every=False)
    if materials:
        lines.append(
            f"  materials: {', '.join(materials)}"
            f" (a declaration may name them: `name: term({' | '.join(materials[:2])})`)"
        )
    aliases = "; ".join(f"{a} = {' | '.join(v)}" for a, v in vocabulary.direction_aliases.items())
    lines.append(f"  directions: {', '.join(vocabulary.directions)}" + (f" ({aliases})" if aliases else ""))
    rule = f" ({vocabulary.goal_rule})" if vocabulary.goal_rule else ""
    lines.append(f"  the player moves: {vocabulary.player}; goals: {vocabulary.goal}{rule}")
    return "\n".join(lines)
