"""The examples in `Margin`'s docstring run as tests (issue 72): a named constructor, `.share`
and `.text()`, as the docstring shows them."""

from __future__ import annotations

import doctest

import physc.simulation.margin
import physc.simulation.margins


def test_the_margin_docstring_examples_hold():
    result = doctest.testmod(physc.simulation.margin)
    assert result.attempted > 0 and result.failed == 0


def test_the_margins_module_still_names_the_margin_and_its_docstring_examples_hold():
    assert physc.simulation.margins.Margin is physc.simulation.margin.Margin
    assert doctest.testmod(physc.simulation.margins).failed == 0
