"""A part of a domain: a small typed group of hooks that one layer asks, bound to the domain.

A domain is one value that describes a target, as LLVM's `TargetMachine` is, and what each
layer asks of it lives in a part of its own (the search's hooks, the level files, the player's
actions), as a `TargetMachine` hands out its instruction and frame information. A domain
names the class of each part (`search = part(PhyreSearch)`); a part's class subclasses the
part's base class and writes only what differs. Read from a domain, the part is bound to it
(`self.domain`: its world and engine, after `Domain.at`), so a hook reads the world it
simulates in; read from the class, it is the declaration.
"""

from __future__ import annotations

from typing import Generic, TypeVar, overload

P = TypeVar("P", bound="Part")


class Part:
    """The base of a part: bound to one domain (`domain`)."""

    def __init__(self, domain) -> None:
        self.domain = domain


class part(Generic[P]):
    """A domain's part of class `kind` (a descriptor): `domain.NAME` is a `kind` bound to that
    domain, so that a copy bound to another world (`Domain.at`) hands out its own."""

    def __init__(self, kind: type[P]) -> None:
        self.kind = kind

    @overload
    def __get__(self, domain: None, owner: type | None = None) -> part[P]: ...

    @overload
    def __get__(self, domain: object, owner: type | None = None) -> P: ...

    def __get__(self, domain: object, owner: type | None = None) -> part[P] | P:
        return self if domain is None else self.kind(domain)
