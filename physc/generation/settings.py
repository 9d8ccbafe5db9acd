"""Moved to physc.search.settings (physc.moved)."""

from physc.moved import alias

alias(__name__, "physc.search.settings")
