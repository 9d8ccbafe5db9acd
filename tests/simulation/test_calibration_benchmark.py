"""benchmarks/calibration.py, the words' calibration on Phy-Q's labelled levels, on two templates."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from conftest import ROOT

TEMPLATES = ROOT / "tests" / "data" / "sciencebirds" / "phyq-templates"


def calibration():
    spec = importlib.util.spec_from_file_location("calibration", ROOT / "benchmarks" / "calibration.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_labels_come_from_phyqs_file_names():
    bench = calibration()
    assert bench.label_of(Path("2_3_2_1.xml")) == "2_3"  # a template
    assert bench.label_of(Path("2_01_08_00003.xml")) == "2_1"  # a level of Phy-Q's generator
    assert bench.label_of(Path("3_9_1_1.xml")) is None  # not one of the calibrated scenarios


def test_a_rolling_template_reads_as_a_roll_and_a_block_against_the_pig_is_counted_apart():
    bench = calibration()
    rolling = bench.sweep(TEMPLATES / "2_1_8_1.xml", "phyq", 1.0, readings=False)
    sliding = bench.sweep(TEMPLATES / "2_3_2_1.xml", "phyq", 1.0, readings=True)
    assert rolling["shots"] and any(bench.reads(shot, "roll") for shot in rolling["shots"])
    assert sliding["shots"] and not any(bench.reads(shot, "slide") for shot in sliding["shots"])
    assert bench.below_floor(sliding["shots"], 0.22)  # the block met the pig before any slide
    assert len(sliding["readings"]) == 8 and all(count > 0 for count in sliding["readings"].values())
    table = bench.report([rolling, sliding], {"phyq": 0.22})
    assert "| rolling (2_1) | 1 | 1 | 1 | 0 | 100 % |" in table
    assert "| sliding (2_3) | 1 | 1 | 0 | 1 | - |" in table
