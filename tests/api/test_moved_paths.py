"""The plugin API's old paths (physc.generation.*, before issue 72's physc.search) import the new
modules themselves for a release, with a DeprecationWarning that names the new path."""

import importlib
import sys

import pytest


@pytest.mark.parametrize("name", ["outcome", "settings", "verify"])
def test_an_old_path_is_the_new_module_with_a_warning(name, monkeypatch):
    monkeypatch.delitem(sys.modules, f"physc.generation.{name}", raising=False)
    new = importlib.import_module(f"physc.search.{name}")
    with pytest.warns(DeprecationWarning, match=rf"physc\.generation\.{name} moved to physc\.search\.{name}"):
        old = importlib.import_module(f"physc.generation.{name}")
    assert old is new
