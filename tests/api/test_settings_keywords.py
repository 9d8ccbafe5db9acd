"""The API takes the run's settings as one value, with its fields as keyword overrides."""

from __future__ import annotations

import pytest
from conftest import EXAMPLES

import physc
from physc.driver.run_settings import RunSettings, overridden

SF = EXAMPLES / "paper" / "01_SF.phys"


def test_a_keyword_overrides_the_settings_value_and_an_unknown_one_is_a_type_error():
    base = RunSettings(time_budget=30, layouts=5)
    assert overridden(base, "compile", layouts=7) == RunSettings(time_budget=30, layouts=7)
    assert overridden(None, "compile") == RunSettings()
    with pytest.raises(TypeError, match="compile\\(\\) got an unexpected keyword argument 'time_budjet'"):
        overridden(base, "compile", time_budjet=3)


def test_compile_takes_a_settings_value_or_its_fields():
    made = physc.compile(SF, settings=RunSettings(time_budget=60, validate=False), layouts=20)
    again = physc.compile(SF, time_budget=60, validate=False, layouts=20)
    assert (made.level, made.solution, made.trace) == (again.level, again.solution, again.trace)  # the seconds differ
    with pytest.raises(TypeError, match="unexpected keyword argument 'budget'"):
        physc.compile(SF, budget=60)
