"""Domains are plugins, the built-in `angrybirds` included.

A domain is registered under the entry-point group `physc.domains`; the entry
point names an instance of a `physc.domains.base.Domain` subclass, whose
interface (what every domain must say, what generation asks for, the defaults)
is documented there and in `docs/plugins.md`. `load_domain` checks at load that
the plugin is such an instance and calls itself by its entry point's name (E0702).
"""

from __future__ import annotations

import functools
from importlib.metadata import EntryPoint, entry_points

from physc.domains.base import Domain, DomainError, MissingCapability
from physc.domains.vocabulary import Vocabulary
from physc.suggest import asking, closest

__all__ = [
    "DEFAULT_DOMAIN",
    "ENTRY_POINT_GROUP",
    "Domain",
    "DomainError",
    "MissingCapability",
    "bound",
    "installed_domains",
    "load_domain",
    "world_name",
]

ENTRY_POINT_GROUP = "physc.domains"
DEFAULT_DOMAIN = "angrybirds"


def installed_domains() -> dict[str, EntryPoint]:
    """Every installed domain's entry point, by name, sorted."""
    found = {ep.name: ep for ep in entry_points(group=ENTRY_POINT_GROUP)}
    return dict(sorted(found.items()))


@functools.cache
def load_domain(name: str) -> Domain:
    """The installed domain `name`, checked: E0701 when it is not installed, E0702 when
    its plugin fails to import or is not a domain (see `_not_a_domain`)."""
    installed = installed_domains()
    if name not in installed:
        known = ", ".join(installed) or "none"
        found = closest(name, installed)
        raise DomainError(
            "E0701",
            f"the domain '{name}' is not installed",
            asking(found) or f"installed domains: {known}",
            tuple(found),
        )
    plugin = f"the plugin of domain '{name}' ({installed[name].value})"
    try:
        domain = installed[name].load()
    except Exception as error:  # a broken third-party plugin must not crash physc
        raise DomainError("E0702", f"{plugin} fails to load: {error}") from error
    problem = _not_a_domain(domain, name)
    if problem:
        raise DomainError(
            "E0702",
            f"{plugin} {problem}",
            "the entry point names an instance of a physc.domains.base.Domain subclass (docs/plugins.md)",
        )
    return domain


def bound(domain: Domain, world: str | None = None, backend: str | None = None) -> Domain:
    """`domain` simulating in `world` with `backend` (`Domain.at`)."""
    return domain.at(world, backend)


def world_name(domain) -> str:
    """The name of the world `domain` simulates in; "" for a domain that names none."""
    return domain.world.name if domain.worlds else ""


def _not_a_domain(domain, name: str) -> str | None:
    """What makes the loaded object unfit to be the domain `name`, or None. Checked at
    load so that a mistake is reported once, naming the plugin, and not as an internal
    error in the middle of a compilation."""
    if isinstance(domain, type):
        return f"names the class '{domain.__name__}', not a domain: write `DOMAIN = {domain.__name__}()` and name that"
    if not isinstance(domain, Domain):
        return f"is a {type(domain).__name__}, not a physc.domains.base.Domain: subclass Domain (or SimulatedDomain)"
    if not isinstance(domain.vocabulary, Vocabulary):
        return (
            f"has a 'vocabulary' that is a {type(domain.vocabulary).__name__}, "
            "not a physc.domains.vocabulary.Vocabulary"
        )
    if domain.name != name:
        return f"calls itself '{domain.name}': its 'name' must be its entry point's name, '{name}'"
    return None
