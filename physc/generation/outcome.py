"""Moved to physc.search.outcome (physc.moved)."""

from physc.moved import alias

alias(__name__, "physc.search.outcome")
