"""Domains are plugins, the built-in `angrybirds` included.

A domain is registered under the entry-point group `physc.domains`; the entry
point names an object with at least `name`, `description` and `vocabulary`
(a `physc.domains.vocabulary.Vocabulary`). See `docs/plugins.md`.
"""

from __future__ import annotations

import functools
from importlib.metadata import EntryPoint, entry_points
from typing import Protocol

from physc.domains.vocabulary import Vocabulary
from physc.suggest import did_you_mean

ENTRY_POINT_GROUP = "physc.domains"
DEFAULT_DOMAIN = "angrybirds"


class Domain(Protocol):
    name: str
    description: str
    vocabulary: Vocabulary


class DomainError(Exception):
    """A domain is unknown (`code` E0701) or its plugin fails to load (E0702)."""

    def __init__(self, code: str, message: str, help: str | None = None):
        super().__init__(message)
        self.code = code
        self.message = message
        self.help = help


def installed_domains() -> dict[str, EntryPoint]:
    """Every installed domain's entry point, by name, sorted."""
    found = {ep.name: ep for ep in entry_points(group=ENTRY_POINT_GROUP)}
    return dict(sorted(found.items()))


@functools.cache
def load_domain(name: str) -> Domain:
    installed = installed_domains()
    if name not in installed:
        known = ", ".join(installed) or "none"
        raise DomainError(
            "E0701",
            f"the domain '{name}' is not installed",
            did_you_mean(name, installed) or f"installed domains: {known}",
        )
    try:
        domain = installed[name].load()
    except Exception as error:  # a broken third-party plugin must not crash physc
        raise DomainError(
            "E0702",
            f"the plugin of domain '{name}' ({installed[name].value}) fails to load: {error}",
        ) from error
    for attribute in ("name", "description", "vocabulary"):
        if not hasattr(domain, attribute):
            raise DomainError(
                "E0702",
                f"the plugin of domain '{name}' ({installed[name].value}) has no '{attribute}'",
            )
    return domain
