"""Stopping points for long work: the time budget and Ctrl-C, checked cooperatively.

Long work (a search over conjunctions, simulations step by step) calls `check()` at
points where stopping is safe. Two things stop it there:

* the **deadline** of the innermost `deadline(seconds)` block: `check()` raises
  `OutOfTime`, so a budget is kept to within one stopping point (a simulated step, a
  clause choice) instead of one whole layout or one whole simulation. A `Deadline`
  started once may be kept by several blocks (`deadline(started)`): one budget for a
  whole run, however its work is split;
* **Ctrl-C**: inside `interruptible()` SIGINT only records the request, and the next
  `check()` raises KeyboardInterrupt. Raised at once instead, it could land inside a
  callback of the physics engine (cffi prints "Exception ignored" and the run goes on)
  or between an engine call and its bookkeeping. Outside such a block SIGINT raises at
  once, as Python's default does.

Nothing here is specific to a domain or an engine.
"""

from __future__ import annotations

import contextlib
import signal
import threading
import time


class OutOfTime(Exception):
    """The time budget of the innermost `deadline` block ran out."""

    def __init__(self, seconds: float):
        super().__init__(f"the time budget of {seconds:g} s ran out")
        self.seconds = seconds


_deadlines: list[tuple[float, float]] = []  # (monotonic end, budget in seconds), innermost last
_interrupted = False
_stopping_since: float | None = None  # when a KeyboardInterrupt of ours began its way up
_polling = 0  # depth of interruptible() blocks
STOPPING = 2.0  # seconds after an interrupt during which Ctrl-C again adds nothing


def check() -> None:
    """Stop here if Ctrl-C was pressed or the innermost deadline has passed."""
    if _interrupted:
        _raise_interrupt()
    if _deadlines:
        end, seconds = _deadlines[-1]
        if time.monotonic() > end:
            raise OutOfTime(seconds)


def remaining() -> float | None:
    """Seconds left before the innermost deadline (None: no deadline)."""
    return _deadlines[-1][0] - time.monotonic() if _deadlines else None


class Deadline:
    """A time budget started once, when it is made: each `deadline(it)` block ends when it
    does, however late the block begins."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.end = time.monotonic() + seconds


@contextlib.contextmanager
def deadline(seconds: float | Deadline):
    """Work inside the block raises OutOfTime at its next `check()` after `seconds`, or at
    the end of a `Deadline` started before (or at an enclosing block's deadline, whichever
    comes first)."""
    started = seconds if isinstance(seconds, Deadline) else Deadline(seconds)
    end, seconds = started.end, started.seconds
    if _deadlines and _deadlines[-1][0] < end:
        end, seconds = _deadlines[-1]
    _deadlines.append((end, seconds))
    try:
        yield
    finally:
        _deadlines.pop()


def _raise_interrupt() -> None:
    global _interrupted, _stopping_since
    _interrupted = False
    _stopping_since = time.monotonic()
    raise KeyboardInterrupt


def _on_sigint(signum, frame) -> None:
    global _interrupted, _stopping_since
    if _stopping_since is not None:
        if time.monotonic() - _stopping_since < STOPPING:
            return  # pressed again while stopping: raising now could land in a finaliser
        _stopping_since = None  # long since handled (a REPL, a benchmark): as before
    if _polling:
        _interrupted = True
    else:
        raise KeyboardInterrupt


def stopped() -> None:
    """The interrupt has reached the top and the process is about to exit: ignore Ctrl-C
    from now on (one more KeyboardInterrupt during shutdown would only print a traceback)."""
    global _stopping_since
    _stopping_since = None
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


def ignore_in_workers() -> None:
    """A worker process's initializer: Ctrl-C reaches every process of the terminal's group,
    and the parent stops the workers itself (a worker interrupted mid-job would print a
    traceback of its own)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextlib.contextmanager
def interruptible():
    """Inside the block Ctrl-C is a request that the next `check()` honours (and the
    block's end, if no check came). In the main thread only; elsewhere a no-op."""
    global _polling
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.getsignal(signal.SIGINT)
    installed = previous in (signal.default_int_handler, _on_sigint)
    if installed:
        signal.signal(signal.SIGINT, _on_sigint)
    _polling += 1
    try:
        yield
    finally:
        _polling -= 1
        # While an interrupt of ours is on its way up, _on_sigint stays: it ignores a second
        # Ctrl-C for STOPPING seconds, then raises as Python's own handler does.
        if installed and not _polling and _stopping_since is None and not _interrupted:
            signal.signal(signal.SIGINT, previous)
        if _interrupted and not _polling:
            _raise_interrupt()
