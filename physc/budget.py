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

A deadline is scoped to the context that entered it: the stack of deadlines is a
`contextvars.ContextVar` (a tuple, innermost last) that each `deadline` block sets and
resets, so work in another thread or asyncio task (which runs in a context of its own)
keeps its own budget and never sees, nor pops, another's. Ctrl-C is the process's, as
signals are.

Nothing here is specific to a domain or an engine.
"""

from __future__ import annotations

import contextlib
import contextvars
import signal
import threading
import time
from collections.abc import Iterator


class OutOfTime(Exception):
    """The time budget of the innermost `deadline` block ran out."""

    def __init__(self, seconds: float):
        super().__init__(f"the time budget of {seconds:g} s ran out")
        self.seconds = seconds


# The deadlines of this context: (monotonic end, budget in seconds), innermost last.
_deadlines: contextvars.ContextVar[tuple[tuple[float, float], ...]] = contextvars.ContextVar(
    "physc.budget.deadlines", default=()
)
_current = _deadlines.get  # bound once: `check` runs every simulated step
_interrupted = False
_stopping_since: float | None = None  # when a KeyboardInterrupt of ours began its way up
_polling = 0  # depth of interruptible() blocks
STOPPING = 2.0  # seconds after an interrupt during which Ctrl-C again adds nothing


def check() -> None:
    """Stop here if Ctrl-C was pressed or the innermost deadline has passed."""
    if _interrupted:
        _raise_interrupt()
    deadlines = _current()
    if deadlines:
        end, seconds = deadlines[-1]
        if time.monotonic() > end:
            raise OutOfTime(seconds)


def remaining() -> float | None:
    """Seconds left before the innermost deadline (None: no deadline)."""
    deadlines = _deadlines.get()
    return deadlines[-1][0] - time.monotonic() if deadlines else None


def current() -> tuple[float | None, float]:
    """(the monotonic end, the budget in seconds) of the innermost deadline; (None, 0): none."""
    deadlines = _deadlines.get()
    return deadlines[-1] if deadlines else (None, 0.0)


class Deadline:
    """A time budget started once, when it is made: each `deadline(it)` block ends when it
    does, however late the block begins."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.end = time.monotonic() + seconds

    @classmethod
    def until(cls, end: float, seconds: float) -> Deadline:
        """The budget of `seconds` that ends at the monotonic `end` (the machine's clock, so one
        process may hand its deadline to another: physc.driver.workers)."""
        started = cls(seconds)
        started.end = end
        return started


@contextlib.contextmanager
def deadline(seconds: float | Deadline) -> Iterator[None]:
    """Work inside the block raises OutOfTime at its next `check()` after `seconds`, or at
    the end of a `Deadline` started before (or at an enclosing block's deadline, whichever
    comes first). The block's deadline is its context's (module docstring)."""
    started = seconds if isinstance(seconds, Deadline) else Deadline(seconds)
    end, seconds = started.end, started.seconds
    enclosing = _deadlines.get()
    if enclosing and enclosing[-1][0] < end:
        end, seconds = enclosing[-1]
    token = _deadlines.set((*enclosing, (end, seconds)))
    try:
        yield
    finally:
        _deadlines.reset(token)


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
def interruptible() -> Iterator[None]:
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
