"""Shared helpers for the physc test suite."""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import attrs
import pytest

from physc.cli import main

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
GOLDEN = Path(__file__).resolve().parent / "golden"
# Real Science Birds levels kept with the tests (tests/data/sciencebirds/README.md says whence).
SCIENCEBIRDS = Path(__file__).resolve().parent / "data" / "sciencebirds"
TEMPLATES = sorted((SCIENCEBIRDS / "phyq-templates").glob("*.xml"))
GENERATED = sorted((SCIENCEBIRDS / "phyq-generated").rglob("*.xml")) + sorted((SCIENCEBIRDS / "novphy-level0").rglob("*.xml"))
UPDATE_GOLDEN = os.environ.get("PHYSC_UPDATE_GOLDEN") == "1"


@attrs.frozen
class Run:
    status: int
    stdout: str
    stderr: str


def run_physc(*args: str, stdin: bytes | None = None) -> Run:
    """Run the CLI in-process and capture what it prints."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main([str(a) for a in args])
        except SystemExit as exit_:  # argparse usage errors and --version
            status = exit_.code if isinstance(exit_.code, int) else 1
    return Run(status, out.getvalue(), err.getvalue())


def check_golden(path: Path, actual: str) -> None:
    """Compare with a golden file; PHYSC_UPDATE_GOLDEN=1 rewrites it."""
    if UPDATE_GOLDEN or not path.exists():
        if not UPDATE_GOLDEN:
            pytest.fail(f"golden file {path} is missing; run with PHYSC_UPDATE_GOLDEN=1 to create it")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(actual, encoding="utf-8")
        return
    expected = path.read_text(encoding="utf-8")
    assert actual == expected, f"{path.name} differs from its golden file (PHYSC_UPDATE_GOLDEN=1 to accept)"


@pytest.fixture
def physc():
    return run_physc
