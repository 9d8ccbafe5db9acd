"""What long commands say while they work when stderr is a log, not a terminal: a line per
finished task (generate, eval), and a line every few seconds of one task (compile), from the
layout search on."""

from __future__ import annotations

import subprocess
import sys
import time

from conftest import EXAMPLES

from physc.commands.progress import Heartbeat, Progress
from physc.driver.layout_loop import Progress as Report

SF = EXAMPLES / "paper" / "01_SF.phys"


def test_a_heartbeat_speaks_before_the_first_layout_and_after(capsys):
    with Heartbeat("[1/1] X", every=0.05) as heartbeat:
        time.sleep(0.17)
        heartbeat.update(Report(3, 40, 1.0, 2, 5))
        time.sleep(0.12)
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) >= 4
    assert "layout search is still going" in lines[0] and lines[0].startswith("[1/1] X: 0 s;")
    assert lines[-1].endswith("3 layouts tried, 40 simulations; best so far: 2 of 5 interactions in order")


def test_a_heartbeat_stops_with_its_task(capsys):
    with Heartbeat("t", every=0.05):
        pass
    time.sleep(0.15)
    assert capsys.readouterr().err == ""


def test_progress_in_a_log_is_a_line_per_result(capsys):
    progress = Progress("generate", False, lambda result: f"{result} done")
    progress.start(3, 1, "2 local processes")
    progress.advance("a")
    progress.advance("b")
    progress.stop()
    lines = capsys.readouterr().err.splitlines()
    assert lines[:2] == ["generate: 3 tasks on 2 local processes", "generate: resuming: 1 of 3 tasks already done"]
    assert lines[2].startswith("generate: 2/3, ") and lines[2].endswith(": a done") and lines[3].startswith("generate: 3/3, ")


def test_generate_writes_its_lines_as_tasks_finish(tmp_path):
    """Each line reaches the log when its task is done, not at the end."""
    process = subprocess.Popen(
        [sys.executable, "-m", "physc", "generate", str(SF), "--tasks", "3", "--out", str(tmp_path / "d"), "--no-validate"],
        stderr=subprocess.PIPE, text=True,
    )
    first = process.stderr.readline()
    second = process.stderr.readline()
    running = process.poll() is None
    rest = process.stderr.read()
    assert process.wait() == 0
    assert first.startswith("generate: 3 tasks on ") and second.startswith("generate: 1/3, ")
    assert running  # the first task's line came while the others were still being made
    assert "3 of 3 tasks generated" in rest
