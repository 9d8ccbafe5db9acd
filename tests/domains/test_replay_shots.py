"""replay_shots.py (phyq_levels.py's script for Phy-Q's agent framework), run against a stand-in of the
framework that records what the script asks of it: the game's speed per level, how it starts the game, and how
and when it sends a timed shot (shots.csv's `wait` and `launch_gap`, phyq_timing.py)."""

import csv
import io
import json
import subprocess
import sys

import pytest
from conftest import TEMPLATES

from physc.domains.angrybirds.phyq_levels import benchmark_files

# The framework's two classes the script uses, with the real constructor's signature
# (phy-q/benchmark sciencebirdsagents/SBEnvironment/SBEnvironmentWrapper.py): a wrong keyword fails.
WRAPPER = """
import json


def record(*event):
    with open("events.jsonl", "a") as handle:
        handle.write(json.dumps(event) + "\\n")


class Point:
    def __init__(self, x, y):
        self.X, self.Y = x, y


class SBEnvironmentWrapper:
    def __init__(self, reward_type="score", speed=100, game_version="Linux", if_head=False, headless_server=False):
        record("made", {"reward_type": reward_type, "speed": speed, "if_head": if_head,
                        "headless_server": headless_server})
        self.simulation_speed = speed
        self.sling_center = Point(127, 256)  # a Phy-Q level's reference point on the 840 x 480 window

    def make(self, agent, if_first_server=True, start_level=1, state_representation_type="symbolic"):
        self.agent = agent
        agent.ar.set_game_simulation_speed(self.simulation_speed)  # as the real make does

    def reset(self):
        record("load", self.current_level)
        self.shots_per_level, self.num_birds, self.steps = 0, 3, 0

    def step(self, action):
        if self.shots_per_level != self.steps:  # shots the script sent itself, counted as the real step counts them
            record("counted", self.shots_per_level, self.num_birds)  # (it waits 0.5 s before a level's first shot)
        record("step", action)
        self.shots_per_level, self.num_birds, self.steps = self.shots_per_level + 1, self.num_birds - 1, self.steps + 1
        return None, 1, True, [True, 0]

    def close(self):
        record("close")
"""
AGENT = """
import struct
import time

from Client.agent_client import GameState
from SBEnvironment.SBEnvironmentWrapper import record


class Client:
    def set_game_simulation_speed(self, speed):
        struct.pack("I", speed)  # agent_client.py sends it as an unsigned int
        record("speed", speed)

    # agent_client.py's signatures: (fx, fy, t1, t2, isPolar), the point absolute, t2 the tap in ms
    def shoot(self, fx, fy, t1, t2, isPolar):
        struct.pack("iiii", fx, fy, t1, t2)
        record("safe", [fx, fy, t1, t2], time.monotonic())
        return 1

    def fast_shoot(self, fx, fy, t1, t2, isPolar):
        struct.pack("iiii", fx, fy, t1, t2)
        record("fast", [fx, fy, t1, t2], time.monotonic())
        return 1

    def get_game_state(self):
        record("state")
        return GameState.WON


class SBAgent:
    def __init__(self, env, level_list=[], id=28888):
        self.ar = Client()
        self.env = env
"""
CLIENT = """
from enum import Enum


class GameState(Enum):  # agent_client.py's, in part
    PLAYING = 5
    WON = 6
    LOST = 7
"""
UNTAPPED = {"release_angle": 43.0, "agent_action": [-100, -93, 0], "agent_angle": 42.98}
TAPPED = {"release_angle": 20.0, "agent_action": [-120, -40, 560], "agent_angle": 20.01}


def framework(tmp_path, solutions):
    """phyq/ for one level a solution, and a stand-in sciencebirdsagents/ beside it."""
    text = TEMPLATES[0].read_text(encoding="utf-8-sig")
    files = benchmark_files([({"scenario": "S", "seed": k, "solution": s}, text) for k, s in enumerate(solutions)])
    for path, data in files.items():
        (tmp_path / path).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / path).write_bytes(data)
    agents = tmp_path / "sciencebirdsagents"
    (agents / "SBEnvironment").mkdir(parents=True)
    (agents / "SBEnvironment" / "__init__.py").write_text("")
    (agents / "SBEnvironment" / "SBEnvironmentWrapper.py").write_text(WRAPPER)
    (agents / "SBAgent.py").write_text(AGENT)
    (agents / "Client").mkdir()
    (agents / "Client" / "__init__.py").write_text("")
    (agents / "Client" / "agent_client.py").write_text(CLIENT)
    return agents


def replay(agents, *args):
    run = subprocess.run(
        [sys.executable, "../phyq/replay_shots.py", "--out", "replayed.csv", *args],
        cwd=agents,
        capture_output=True,
        text=True,
    )
    events = (agents / "events.jsonl").read_text().splitlines() if (agents / "events.jsonl").exists() else []
    return run, [json.loads(line) for line in events]


def replayed(agents):
    return list(csv.DictReader(io.StringIO((agents / "replayed.csv").read_text())))


def test_a_level_with_a_tap_is_played_at_speed_1_the_others_fast_with_the_game_shown(tmp_path):
    agents = framework(tmp_path, [UNTAPPED, {"shots": [UNTAPPED, TAPPED]}, UNTAPPED])
    run, events = replay(agents)
    assert run.returncode == 0, run.stderr
    made = events[0][1]
    assert made["if_head"] is True and made["headless_server"] is False  # the game in its window
    assert events[1:] == [
        ["speed", 50],
        ["load", 1],
        ["step", [-100, -93, 0]],
        ["speed", 1],  # set before the level loads: the whole level, tap and all, at the game's own pace
        ["load", 2],
        ["step", [-100, -93, 0]],
        ["step", [-120, -40, 560]],
        ["speed", 50],
        ["load", 3],
        ["step", [-100, -93, 0]],
    ]
    rows = replayed(agents)
    assert [(r["level"], r["shot"], r["tap_time"], r["speed"], r["solved"]) for r in rows] == [
        ("1", "1", "0", "50", "True"),
        ("2", "1", "0", "1", "True"),
        ("2", "2", "560", "1", "True"),
        ("3", "1", "0", "50", "True"),
    ]


def test_headless_starts_the_game_in_the_background_and_a_timed_shot_slows_it_too(tmp_path):
    agents = framework(tmp_path, [{"shots": [UNTAPPED, UNTAPPED]}, UNTAPPED])
    table = tmp_path / "phyq" / "shots.csv"
    shots = list(csv.DictReader(io.StringIO(table.read_text())))
    if "wait" not in shots[0]:  # a table made before shots.csv carried the wait: add it
        shots = [{**s, "wait": ""} for s in shots]
    shots[1]["wait"] = "0.5"  # level 1's second shot is timed
    with table.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, list(shots[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(shots)
    run, events = replay(agents, "--headless", "--speed", "20")
    assert run.returncode == 0, run.stderr
    made = events[0][1]
    assert made["if_head"] == "headless" and made["headless_server"] is True and made["speed"] == 1
    assert [e for e in events if e[0] in ("speed", "load")] == [["speed", 1], ["load", 1], ["speed", 20], ["load", 2]]
    assert events[-1] == ["close"]  # it started the game, so it closes it


def test_a_speed_the_game_does_not_take_is_refused(tmp_path):
    agents = framework(tmp_path, [UNTAPPED])
    for speed in ("0", "51"):
        run, events = replay(agents, "--speed", speed)
        assert run.returncode == 2 and "--speed is from 1 to 50" in run.stderr and events == []


def two_bird_level() -> str:
    text = TEMPLATES[0].read_text(encoding="utf-8-sig")
    return text.replace('<Bird type="BirdRed" />', '<Bird type="BirdRed" />\n    <Bird type="BirdRed" />', 1)


def test_shots_csv_gives_each_shots_wait_and_when_physc_launched_a_timed_one():
    """`wait`: physc's (empty: once the level rests); `launch_gap`: the seconds from the shot before's launch to a
    timed shot's in physc's play of the level, as the agents send the shots (empty for a level with no timed shot)."""
    import math

    import physc
    from physc.domains.angrybirds.agent_shots import agent_shot
    from physc.domains.angrybirds.launch import Shots

    text = two_bird_level()
    hitting = {"release_angle": 12.5, "agent_action": [-195, -44, 0], "agent_angle": 12.405}  # strikes the pig
    timed = {**UNTAPPED, "bird": "bird2", "wait": 1.5}
    solutions = [{"shots": [hitting, timed]}, {"shots": [hitting, {**UNTAPPED, "bird": "bird2"}]}, UNTAPPED]
    files = benchmark_files(
        [({"scenario": "S", "seed": k, "world": "phyq", "solution": s}, text) for k, s in enumerate(solutions)]
    )
    rows = list(csv.DictReader(io.StringIO(files["phyq/shots.csv"].decode())))
    assert [(r["level"], r["shot"], r["wait"]) for r in rows] == [
        ("1", "1", ""),
        ("1", "2", "1.5"),
        ("2", "1", ""),
        ("2", "2", ""),
        ("3", "1", ""),
    ]
    assert [r["launch_gap"] for r in rows[2:]] == ["", "", ""] and rows[0]["launch_gap"] == ""
    level = physc.read_level(text.encode())
    trace = physc.simulate(
        level,
        Shots((agent_shot(level, hitting["agent_action"]), agent_shot(level, timed["agent_action"], "bird2", 1.5))),
    )
    struck = min(c.time for c in trace.contacts if "bird" in (c.a, c.b))
    column = trace.names.index("bird2")
    launched = next(i for i in range(trace.steps) if not math.isnan(trace.states[i, column, 0])) * trace.dt
    assert float(rows[1]["launch_gap"]) == pytest.approx(launched, abs=1e-6)  # bird was launched at step 0
    # bird2 comes onto the slingshot when bird first strikes something (ABGameWorld.KillBird), and is shot 1.5 s after
    assert float(rows[1]["launch_gap"]) == pytest.approx(struck + 1.5, abs=2.5 * trace.dt)


def rewrite(table, change):
    """shots.csv with `change(rows)` applied."""
    shots = list(csv.DictReader(io.StringIO(table.read_text())))
    change(shots)
    with table.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, list(shots[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(shots)


def shot_times(events):
    return [(e[0], e[1][3], e[2]) for e in events if e[0] in ("fast", "safe")]


def test_a_timed_shot_is_sent_on_time_after_a_fast_shot_before_it(tmp_path):
    """Shot 1 in fast mode (the game answers once it is made, not once the level rests), shot 2 sent
    launch_gap − its tap − the game's 1-s drag after the game answered shot 1; the verdict polled after."""
    agents = framework(tmp_path, [{"shots": [TAPPED, UNTAPPED]}])

    def timed(rows):
        rows[1].update(wait="1.5", launch_gap="2.3")  # sent 2.3 − 0.56 (the tap before) − 1.0 (the drag) = 0.74 s after

    rewrite(tmp_path / "phyq" / "shots.csv", timed)
    run, events = replay(agents)
    assert run.returncode == 0, run.stderr
    (first, tap, answered), (second, _, sent) = shot_times(events)
    assert (first, second, tap) == ("fast", "safe", 560)
    assert 0.74 <= sent - answered < 0.74 + 0.4
    assert not [e for e in events if e[0] == "step"] and events[-1] == ["state"]  # no step: the game's verdict read
    assert [e for e in events if e[0] == "fast"][0][1][:2] == [127 - 120, 256 + 40]  # the point as step makes it
    rows = replayed(agents)
    assert [(r["sent"], r["solved"]) for r in rows] == [("fast", ""), ("safe", "True")]
    assert float(rows[1]["waited"]) == pytest.approx(0.74, abs=0.1) and float(rows[1]["late"]) == 0.0


def test_a_timed_shot_waits_for_its_bird_on_the_slingshot_and_without_its_launch_gap_its_wait(tmp_path):
    """A wait shorter than the game's drag cannot be kept: the shot is sent once its bird is on the slingshot (an
    earlier one is lost), and replayed.csv says how late; a table without launch_gap waits `wait` after the answer."""
    agents = framework(tmp_path, [{"shots": [UNTAPPED, UNTAPPED, UNTAPPED]}, {"shots": [UNTAPPED, UNTAPPED]}])

    def timed(rows):
        rows[1].update(wait="0.3")  # no launch_gap (a table physc could not play): 0.3 s after the answer
        rows[2].update(wait="0.5", launch_gap="0.6")  # due 0.4 s before the answer; its bird is there 0.1 + 0.2 s after
        rows[4].update(wait="1.4", launch_gap="1.7")  # level 2: due 0.7 s after shot 1's answer, its bird there at 0.5

    rewrite(tmp_path / "phyq" / "shots.csv", timed)
    run, events = replay(agents)
    assert run.returncode == 0, run.stderr
    (m1, _, t1), (m2, _, t2), (m3, _, t3), (m4, _, t4), (m5, _, t5) = shot_times(events)
    assert (m1, m2, m3, m4, m5) == ("fast", "fast", "safe", "fast", "safe")
    assert 0.3 <= t2 - t1 < 0.7 and 0.3 <= t3 - t2 < 0.7 and 0.7 <= t5 - t4 < 1.1
    rows = replayed(agents)
    assert float(rows[2]["late"]) == pytest.approx(0.7, abs=0.1) and float(rows[2]["waited"]) == pytest.approx(
        0.3, abs=0.1
    )
    assert float(rows[4]["late"]) == 0.0 and float(rows[1]["late"]) == 0.0
    assert [r["solved"] for r in rows] == ["", "", "True", "", "True"]


def test_an_untimed_shot_after_a_timed_one_is_the_frameworks_step_with_the_shots_counted(tmp_path):
    agents = framework(tmp_path, [{"shots": [UNTAPPED, UNTAPPED, UNTAPPED]}])
    rewrite(tmp_path / "phyq" / "shots.csv", lambda rows: rows[1].update(wait="0.2", launch_gap="1.2"))
    run, events = replay(agents)
    assert run.returncode == 0, run.stderr
    assert [e[0] for e in events if e[0] in ("fast", "safe", "step", "counted")] == ["fast", "safe", "counted", "step"]
    assert ["counted", 2, 1] in events  # the wrapper's counters as its own step leaves them: no 0.5 s wait
    assert [r["sent"] for r in replayed(agents)] == ["fast", "safe", "step"]
