"""Same input and seed, same output bytes, whatever Python's string hashing does."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from conftest import EXAMPLES, SCIENCEBIRDS

CASES = [
    ["compile", str(EXAMPLES / "paper" / "15_RRF.phys"), "--emit", "layout", "--seed", "3"],
    ["trace", str(SCIENCEBIRDS / "phyq-templates" / "3_6_7_1.xml"), "--shot=-3.5,-0.8,high", "--seconds", "6"],
]


@pytest.mark.parametrize("arguments", CASES, ids=["compile", "trace"])
def test_output_does_not_depend_on_hash_seed(arguments):
    outputs = set()
    for seed in ("0", "1", "12345"):
        environment = dict(os.environ, PYTHONHASHSEED=seed)
        run = subprocess.run([sys.executable, "-m", "physc", *arguments], capture_output=True, text=True, env=environment)
        assert run.returncode == 0, run.stderr
        outputs.add(run.stdout)
    assert len(outputs) == 1
