"""Typed command-line values: every numeric option is checked where it is parsed.

Each function here is an argparse `type=`: it turns the text of an option into its
value or raises `argparse.ArgumentTypeError` with a sentence saying what the option
takes, so a careless argument (`--seconds nan`, `--layouts -5`, `--shot=1e999,0`) ends
as a usage error, exit status 2, before any work starts. The limits are the ones the
README documents.
"""

from __future__ import annotations

import argparse
import math

MAX_SECONDS = 60.0  # simulated seconds of one play at most (memory grows with it)
MAX_COORDINATE = 1000.0  # |x|, |y| of a shot's target point, in level units
MAX_SEED = 2**63 - 1
MAX_COUNT = 10**9  # any count option: more is a typo, never a plan
MAX_TIME_BUDGET = 7 * 24 * 3600.0  # a week


def _finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"'{text}' is not a finite number")
    return value


def _whole(text: str) -> int:
    try:
        return int(text, 10)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a whole number") from None


def seconds(text: str) -> float:
    """Simulated seconds: more than 0 and at most MAX_SECONDS."""
    value = _finite(text)
    if not 0 < value <= MAX_SECONDS:
        raise argparse.ArgumentTypeError(f"takes seconds more than 0 and at most {MAX_SECONDS:g}, not {text}")
    return value


def time_budget(text: str) -> float:
    """Wall-clock seconds per task: more than 0 and at most a week."""
    value = _finite(text)
    if not 0 < value <= MAX_TIME_BUDGET:
        raise argparse.ArgumentTypeError(
            f"takes seconds more than 0 and at most {MAX_TIME_BUDGET:g} (a week), not {text}"
        )
    return value


def count(text: str) -> int:
    """A whole number of at least 1 (layouts, tasks, jobs, clause choices)."""
    return _within(text, MAX_COUNT)


MAX_JOBS = 1024  # processes: each is forked when the pool starts
MAX_TASKS = 100_000  # tasks per scenario of one evaluation


def jobs(text: str) -> int:
    """--jobs: processes, from 1 to MAX_JOBS."""
    return _within(text, MAX_JOBS)


def tasks(text: str) -> int:
    """--tasks: tasks per scenario, from 1 to MAX_TASKS."""
    return _within(text, MAX_TASKS)


def wave(text: str) -> int:
    """--wave: a scenario's tasks made side by side, from 0 (each on its own) to MAX_TASKS."""
    value = _whole(text)
    if not 0 <= value <= MAX_TASKS:
        raise argparse.ArgumentTypeError(f"takes a whole number from 0 to {MAX_TASKS:,}, not {text}")
    return value


MAX_REPLAYS = 1000


def replays(text: str) -> int:
    """--replays: noisy replays, from 0 (none) to MAX_REPLAYS."""
    value = _whole(text)
    if not 0 <= value <= MAX_REPLAYS:
        raise argparse.ArgumentTypeError(f"takes a whole number from 0 to {MAX_REPLAYS:,}, not {text}")
    return value


def _within(text: str, most: int) -> int:
    value = _whole(text)
    if not 1 <= value <= most:
        raise argparse.ArgumentTypeError(f"takes a whole number from 1 to {most:,}, not {text}")
    return value


def seed(text: str) -> int:
    """A random seed: a whole number from 0 to 2**63 - 1."""
    value = _whole(text)
    if not 0 <= value <= MAX_SEED:
        raise argparse.ArgumentTypeError(f"takes a whole number from 0 to 2**63 - 1, not {text}")
    return value


def angle(text: str) -> float:
    """A release angle in degrees, from -90 to 90 (the slingshot shoots to the right)."""
    value = _finite(text)
    if not -90 <= value <= 90:
        raise argparse.ArgumentTypeError(f"takes degrees from -90 to 90, not {text}")
    return value


def shot(text: str) -> tuple[float, float, str]:
    """X,Y[,low|high]: a target point within MAX_COORDINATE and a trajectory."""
    parts = [p.strip() for p in text.split(",")]
    trajectory = parts[2] if len(parts) == 3 else "low"
    if len(parts) not in (2, 3) or trajectory not in ("low", "high"):
        raise argparse.ArgumentTypeError(f"takes X,Y or X,Y,low or X,Y,high, not '{text}'")
    point = []
    for part in parts[:2]:
        value = _finite(part)
        if abs(value) > MAX_COORDINATE:
            raise argparse.ArgumentTypeError(
                f"takes coordinates from -{MAX_COORDINATE:g} to {MAX_COORDINATE:g}, not {part}"
            )
        point.append(value)
    return point[0], point[1], trajectory


MAX_PIXELS = 100_000  # |dx|, |dy| of an agent's action: any drag of more than a unit is full stretch
MAX_TAP_MS = int(MAX_SECONDS * 1000)


def tap(text: str) -> float:
    """--tap: seconds after the launch, more than 0 and at most MAX_SECONDS."""
    value = _finite(text)
    if not 0 < value <= MAX_SECONDS:
        raise argparse.ArgumentTypeError(
            f"takes seconds after the launch, more than 0 and at most {MAX_SECONDS:g}, not {text}"
        )
    return value


def wait(text: str) -> float:
    """--wait: seconds, from 0 to MAX_SECONDS."""
    value = _finite(text)
    if not 0 <= value <= MAX_SECONDS:
        raise argparse.ArgumentTypeError(f"takes seconds from 0 to {MAX_SECONDS:g}, not {text}")
    return value


def agent_action(text: str) -> tuple[int, int, int]:
    """DX,DY[,TAP]: what Phy-Q's agents send, `env.step([dx, dy, tap_time])`: whole screen pixels
    from the slingshot's reference point (y up) and a tap time in whole milliseconds after the
    launch (0, the default: no tap)."""
    parts = [p.strip() for p in text.split(",")]
    if len(parts) not in (2, 3):
        raise argparse.ArgumentTypeError(
            f"takes DX,DY or DX,DY,TAP (whole pixels from the slingshot's reference point, the tap in ms), not '{text}'"
        )
    values = []
    for part, what in zip(parts, ("DX", "DY", "TAP"), strict=False):
        try:
            values.append(int(part, 10))
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"takes whole numbers, as env.step sends them: {what} '{part}' is not one (in '{text}')"
            ) from None
    if any(abs(v) > MAX_PIXELS for v in values[:2]):
        raise argparse.ArgumentTypeError(f"takes pixels from -{MAX_PIXELS:,} to {MAX_PIXELS:,}, not '{text}'")
    if len(values) == 3 and not 0 <= values[2] <= MAX_TAP_MS:
        raise argparse.ArgumentTypeError(
            f"takes a tap time in ms from 0 (no tap) to {MAX_TAP_MS:,}, not {values[2]} (in '{text}')"
        )
    return values[0], values[1], values[2] if len(values) == 3 else 0


def backend(text: str) -> str:
    """An installed physics backend that loads (loading it now: a missing or broken engine
    is a usage error before any work, with "did you mean" for a misspelt name)."""
    from physc.backends import BackendError, load_backend

    try:
        load_backend(text)
    except BackendError as error:
        raise argparse.ArgumentTypeError(str(error)) from None
    return text


def world(text: str) -> str:
    """A world of some installed domain (`physc worlds`): which domain's it must be is checked
    when the domain is known, with "did you mean"."""
    from physc.domains import installed_domains, load_domain
    from physc.suggest import did_you_mean

    names = set()
    for name in installed_domains():
        try:
            names |= {w.name for w in load_domain(name).worlds}
        except Exception:  # a broken plugin is reported where it is used, not here
            continue
    if text not in names:
        hint = did_you_mean(text, sorted(names)) or "the worlds: " + ", ".join(sorted(names))
        raise argparse.ArgumentTypeError(f"no installed domain has a world '{text}'; {hint} (physc worlds lists them)")
    return text
