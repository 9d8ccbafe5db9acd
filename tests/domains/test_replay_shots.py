"""replay_shots.py (phyq_levels.py's script for Phy-Q's agent framework), run against a stand-in of the
framework that records what the script asks of it: the game's speed per level, how it starts the game."""

import csv
import io
import json
import subprocess
import sys

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

    def step(self, action):
        record("step", action)
        return None, 1, True, [True, 0]

    def close(self):
        record("close")
"""
AGENT = """
import struct

from SBEnvironment.SBEnvironmentWrapper import record


class Client:
    def set_game_simulation_speed(self, speed):
        struct.pack("I", speed)  # agent_client.py sends it as an unsigned int
        record("speed", speed)


class SBAgent:
    def __init__(self, env, level_list=[], id=28888):
        self.ar = Client()
        self.env = env
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
