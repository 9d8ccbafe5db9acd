"""Ctrl-C ends a running command promptly with exit 130 and no traceback, wherever it
lands: in the layout search, in a simulation, inside a callback of the physics engine."""

from __future__ import annotations

import signal
import subprocess
import sys
import time

import pytest
from conftest import EXAMPLES

RRR = EXAMPLES / "paper" / "16_RRR.phys"  # rarely generates: runs to its time budget


def _interrupted(command: list[str], after: float, tmp_path, repeats: int = 1):
    process = subprocess.Popen(
        [sys.executable, "-m", "physc", *command], stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp_path
    )
    time.sleep(after)
    sent = time.monotonic()
    for _ in range(repeats):
        process.send_signal(signal.SIGINT)
        time.sleep(0.05)
    try:
        out, err = process.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        pytest.fail(f"physc {' '.join(command)} went on for 10 s after Ctrl-C")
    return process.returncode, time.monotonic() - sent, err.decode()


@pytest.mark.parametrize("after", [0.6, 1.1, 1.7, 2.3, 2.9])
def test_ctrl_c_stops_a_compile(after, tmp_path):
    # The signal lands in the layout search, a simulation or the repair search's own work.
    status, waited, err = _interrupted(
        ["compile", str(RRR), "--time-budget", "30", "-o", "out.xml", "--task", "out.json"], after, tmp_path, repeats=2
    )
    assert status == 130, err
    assert "Traceback" not in err and "Exception ignored" not in err
    assert "physc: interrupted" in err
    assert not (tmp_path / "out.xml").exists()  # whole or not at all
    assert not list(tmp_path.glob(".*.tmp"))
    assert waited < 3.0


def test_ctrl_c_stops_a_simulation(tmp_path):
    level = tmp_path / "level.xml"
    # 300 balls (the most a level may hold) in a heap: seconds of play to simulate.
    balls = "".join(f'<Block type="Circle" material="ice" x="{(i % 20) * 0.8 - 8}" y="{(i // 20) * 0.8 - 3}"/>\n' for i in range(300))
    level.write_text(
        '<?xml version="1.0" encoding="utf-16"?>\n<Level width="2">\n<Birds><Bird type="BirdRed"/></Birds>\n'
        f"<GameObjects>\n{balls}</GameObjects>\n</Level>\n"
    )
    status, waited, err = _interrupted(["trace", str(level), "--shot=3,-3", "--seconds", "60"], 0.8, tmp_path)
    if status == 0:
        pytest.skip("the play ended before the signal")
    assert status == 130 and "Traceback" not in err and waited < 3.0


def test_ctrl_c_stops_an_eval_with_workers(tmp_path):
    # Workers ignore the signal; the parent ends them and keeps the records made so far.
    status, waited, err = _interrupted(
        ["eval", str(RRR), "--tasks", "4", "--jobs", "2", "--time-budget", "60", "--out", "out", "-q"], 2.0, tmp_path, repeats=2
    )
    assert status == 130, err
    assert "Traceback" not in err and "Exception ignored" not in err
    assert waited < 3.0


def test_a_second_interrupt_long_after_the_first_is_not_ignored():
    """In a process that goes on after an interrupt (a REPL, a benchmark), Ctrl-C works again."""
    import os

    from physc import budget

    with pytest.raises(KeyboardInterrupt):
        with budget.interruptible():
            os.kill(os.getpid(), signal.SIGINT)
            budget.check()
    budget._stopping_since -= budget.STOPPING  # as if it were long ago
    with pytest.raises(KeyboardInterrupt):
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.5)  # the handler runs between bytecodes
    signal.signal(signal.SIGINT, signal.default_int_handler)



@pytest.mark.parametrize("after", [0.0, 0.02, 0.05, 0.1])
def test_ctrl_c_while_physc_starts(after):
    """A Ctrl-C while the command line is still importing its modules is an interrupt like any
    other. The signal is timed from the entry point on (before it, Python's own start-up runs)."""
    code = (
        "import os, signal, sys, threading\n"
        "from physc.console import main\n"
        f"threading.Timer({after}, lambda: os.kill(os.getpid(), signal.SIGINT)).start()\n"
        "status = main(['domains'])\n"
        "import time; time.sleep(0.5)\n"  # the signal lands now if it had not: physc is done
        "sys.exit(status)\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=30)
    if result.returncode != 130 and "physc: interrupted" not in result.stderr:
        pytest.skip("physc had ended before the signal")
    assert result.returncode == 130, result.stderr
    assert "Traceback" not in result.stderr and "physc: interrupted" in result.stderr
