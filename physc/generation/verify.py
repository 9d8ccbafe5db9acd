"""Moved to physc.search.verify (physc.moved)."""

from physc.moved import alias

alias(__name__, "physc.search.verify")
