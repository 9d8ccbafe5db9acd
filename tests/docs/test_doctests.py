"""The examples in the small value types' docstrings run as written: a QSR's atoms
(physc.compiler.qsr), a world's readings (physc.worlds) and a link's margin
(physc.simulation.margin)."""

import doctest
import importlib

import pytest

MODULES = ("physc.compiler.qsr", "physc.worlds", "physc.simulation.margin")


@pytest.mark.parametrize("name", MODULES)
def test_the_docstring_examples_hold(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0
    assert result.attempted > 0, f"{name} has no example to run"
