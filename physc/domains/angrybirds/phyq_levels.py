"""A dataset's tasks as a level set Phy-Q's game loads and its agents replay (`physc generate`).

`physc generate` writes, beside physc's own files, `phyq/`:

* `Levels/<scenario>_<seed>_<n>.xml`: the levels as they are (each names its world in an
  attribute the game's loader passes over), numbered n = 1, 2, … in the dataset's order; the
  agent framework sorts a folder's levels by that last number (Utils/Config.py);
* `config.xml`: the game's level list (StreamingAssets/config.xml's form), the levels in that
  order, where `PrepareTestConfig.py` puts them (`9001_Data/StreamingAssets/Levels/physc/Levels/`),
  the last listed twice as Phy-Q's own script does (its note: the game does not load the last);
* `shots.csv`: per shot, its level's number (`load_level(n)`), file, scenario, seed, world, the
  shot's place among the level's (`shot`: 1, 2, … for a task of several, language version 2),
  the release angle, and the action Phy-Q's agents send for it, `env.step([dx, dy, tap_time])`
  (the task's own record, which `physc verify` replayed; the tap in milliseconds), with the
  angle the game launches that at and the slingshot reference point it was computed from, the
  shot's `wait` (seconds after its bird came onto the slingshot; empty: once the level rests)
  and, in a level with a timed shot, its `launch_gap` in physc's play (phyq_timing.py);
* `replay_shots.py`: a script for `sciencebirdsagents/` that loads each level, sends its shot
  and writes whether the level was solved (it carries agent_action.py's functions, to compute
  the shot again if the game's reference point differs from the one expected); it plays a level
  with a tapped or timed shot at the game's speed 1, where a tap keeps its time, sends a timed
  shot when its time comes by the clock (the shot before it in the framework's fast mode, not its
  safe mode, which waits for the level to rest), and starts the game without its window with
  `--headless`;
* `README.md`: how to install the levels in the game and replay the shots.
"""

from __future__ import annotations

import csv
import inspect
import io

from physc.domains.angrybirds import agent_action
from physc.domains.angrybirds.level_xml import parse_level
from physc.domains.angrybirds.phyq_timing import launch_gaps

GAME_FOLDER = "9001_Data/StreamingAssets/Levels/physc/Levels"  # where the game reads them, relative to its folder
COLUMNS = (
    "level",
    "file",
    "scenario",
    "seed",
    "world",
    "shot",
    "release_angle",
    "dx",
    "dy",
    "tap_time",
    "agent_angle",
    "reference_x",
    "reference_y",
    "wait",
    "launch_gap",
)


def level_file(row: dict, number: int) -> str:
    return f"{row['scenario']}_{row['seed']}_{number}.xml"


def benchmark_files(tasks: list[tuple[dict, str]]) -> dict[str, bytes]:
    """{path: bytes} of the `phyq/` folder for the dataset's (manifest row, level text) pairs."""
    files: dict[str, bytes] = {}
    shots = []
    worlds = set()
    for number, (row, text) in enumerate(tasks, start=1):
        name = level_file(row, number)
        files[f"phyq/Levels/{name}"] = text.encode("utf-8")
        level = parse_level(text)
        solution = row.get("solution") or {}
        reference = agent_action.reference_point(level.slingshot, level.camera.y, level.camera.max_width)
        world = level.world or row.get("world") or "phyq"
        worlds.add(world)
        gaps = launch_gaps(text, solution, world, row.get("backend"))  # a level with a timed shot: physc's times
        for k, shot in enumerate(solution.get("shots") or [solution], start=1):  # a ShotsSolution's, or the one
            angle = shot.get("release_angle")
            action, launched = shot.get("agent_action"), shot.get("agent_angle")
            if action is None or launched is None:  # a task made before solutions recorded it
                action, launched = agent_action.agent_action(
                    angle, level.slingshot, level.camera.y, level.camera.max_width
                )
            shots.append(
                {
                    "level": number,
                    "file": name,
                    "scenario": row["scenario"],
                    "seed": row["seed"],
                    "world": world,
                    "shot": k,
                    "release_angle": angle,
                    "dx": action[0],
                    "dy": action[1],
                    "tap_time": action[2],
                    "agent_angle": round(launched, 5),
                    "reference_x": reference[0],
                    "reference_y": reference[1],
                    "wait": "" if shot.get("wait") is None else shot["wait"],
                    "launch_gap": "" if gaps[k - 1] is None else gaps[k - 1],
                }
            )
    table = io.StringIO()
    writer = csv.DictWriter(table, COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(shots)
    files["phyq/shots.csv"] = table.getvalue().encode("utf-8")
    files["phyq/config.xml"] = config(list(dict.fromkeys(s["file"] for s in shots))).encode("utf-8")
    files["phyq/replay_shots.py"] = replay_script().encode("utf-8")
    files["phyq/README.md"] = readme(len(shots), sorted(worlds)).encode("utf-8")
    return files


def config(names: list[str]) -> str:
    """The game's config.xml listing the levels in order (the last twice, as Phy-Q's scripts do)."""
    lines = [
        '<?xml version="1.0" encoding="utf-16"?>',
        "<evaluation>",
        '  <novelty_detection_measurement step="1" measure_in_training="True" measure_in_testing="True" />',
        "  <trials>",
        '    <trial id="0" number_of_executions="1" checkpoint_time_limit="200" checkpoint_interaction_limit="200"'
        ' notify_novelty="False">',
        '      <game_level_set mode="training" time_limit="6000" total_interaction_limit="6000"'
        ' attempt_limit_per_level="1" allow_level_selection="False">',
    ]
    for name in names + names[-1:]:
        lines.append(f'        <game_levels level_path="{GAME_FOLDER}/{name}" />')
    lines += ["      </game_level_set>", "    </trial>", "  </trials>", "</evaluation>", ""]
    return "\n".join(lines)


REPLAY_MAIN = '''

import time

TIMED_SPEED = 1  # the game's speed for a level with a tapped or timed shot (README.md beside this file says why)
DRAG_SECONDS = 1.0  # HUD.cs `_simulateDragTime`: the game drags the bird this long before it releases a shot it got
# After the bird before struck something, the next one jumps onto the slingshot (ABGameWorld.KillBird, ABBird
# SetBirdOnSlingshot at BirdRed.prefab's `_dragSpeed` 15 units/s over the 1 to 2 units from where it waits): a shot
# sent before that finds no bird to drag (HUD.cs ClickDown) and is lost.
ON_SLINGSHOT_SECONDS = 0.2
OUTCOME_SECONDS = 30.0  # after a level's last shot sent directly, how long to wait for the game's verdict


def main():
    """Replay every shot of shots.csv in the running game; write replayed.csv."""
    import argparse
    import csv
    import os
    import sys

    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--shots", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "shots.csv"))
    parser.add_argument("--out", default="replayed.csv")
    parser.add_argument("--game-version", default="Linux")
    parser.add_argument("--headless", action="store_true", help="start the game with no window and no terminal "
                        "(the framework's --headless server, in the background; closed at the end if this started it)")
    parser.add_argument("--speed", type=int, default=50, help="the game's speed (1 to 50) for a level whose shots are "
                        f"neither tapped nor timed; a level with a tapped or timed shot is played at {TIMED_SPEED}")
    args = parser.parse_args()
    if not 1 <= args.speed <= 50:
        parser.error("--speed is from 1 to 50 (the game caps it at 50)")
    sys.path.insert(0, os.getcwd())  # run from sciencebirdsagents/
    from SBEnvironment.SBEnvironmentWrapper import SBEnvironmentWrapper
    from SBAgent import SBAgent

    with open(args.shots, newline="") as handle:
        shots = list(csv.DictReader(handle))
    speeds = level_speeds(shots, args.speed)
    speed = speeds[shots[0]["level"]] if shots else args.speed
    started = args.headless and not server_running()
    env = SBEnvironmentWrapper(reward_type="passing", speed=speed, game_version=args.game_version,
                               if_head="headless" if args.headless else True, headless_server=args.headless)
    agent = SBAgent(env=env)
    env.make(agent=agent, start_level=1, state_representation_type="symbolic")
    try:
        with open(args.out, "w", newline="") as handle:
            out = csv.writer(handle)
            out.writerow(["level", "file", "shot", "dx", "dy", "tap_time", "reference_x", "reference_y", "speed",
                          "sent", "waited", "late", "solved"])
            before = None  # the level's shot before: when the game answered it, and its tap
            for k, shot in enumerate(shots):
                if int(shot.get("shot") or 1) == 1:  # a level's first shot: load it (its later shots go on from there)
                    if speeds[shot["level"]] != speed:  # the game takes a new speed at any time (README.md, command 2)
                        speed = speeds[shot["level"]]
                        agent.ar.set_game_simulation_speed(speed)
                    env.current_level = int(shot["level"])
                    env.reset()  # loads the level, zooms out fully, reads the slingshot's reference point
                    before = None
                action = [int(shot["dx"]), int(shot["dy"]), int(shot["tap_time"])]
                expected = (int(shot["reference_x"]), int(shot["reference_y"]))
                live = (env.sling_center.X, env.sling_center.Y)
                if live != expected:  # another screen or camera than expected: aim from the game's own reference point
                    level_text = open(os.path.join(os.path.dirname(args.shots), "Levels", shot["file"])).read()
                    action = aimed_again(float(shot["release_angle"]), level_text, live) + [int(shot["tap_time"])]
                later = shots[k + 1] if k + 1 < len(shots) and int(shots[k + 1].get("shot") or 1) > 1 else None
                if (before is not None and timed(shot)) or (later is not None and timed(later)):
                    sent, waited, late, solved = shot_in_time(env, agent, shot, action, before, later)
                else:  # the framework's own step, in safe mode: it answers once the level is static
                    _, _, _, info = env.step(action)
                    sent, waited, late, solved = "step", "", "", bool(info[0])
                before = (time.monotonic(), action[2])
                out.writerow([shot["level"], shot["file"], shot.get("shot") or 1, action[0], action[1], action[2],
                              live[0], live[1], speed, sent, waited, late, solved])
    finally:
        if started:  # the game and its server this run started in the background
            env.close()


def timed(shot):
    """Whether a shot is timed: taken `wait` s after its bird came onto the slingshot, not once the level rests."""
    return (shot.get("wait") or "").strip() != ""


def shot_in_time(env, agent, shot, action, before, later):
    """A shot of a level with a timed shot, sent to the game directly rather than through the framework's `step`,
    which asks the game for its state before each shot (SBEnvironmentWrapper.py `step`) and sends it in safe mode,
    answered once the level is static (Client/agent_client.py `shoot`, command 31): a timed shot is sent when its
    time comes (`send_time`), and a shot followed by a timed one in fast mode (`fast_shoot`, command 41: answered
    once the shot is made, HUD.cs `shootDone` after the release and its tap). (sent, seconds waited, seconds late,
    solved: the game's verdict after the level's last shot, else whether it has been won already)."""
    waited, late = "", ""
    if before is not None and timed(shot):
        due, earliest = send_time(shot, before)
        now = time.monotonic()
        at = max(due, earliest, now)
        waited, late = round(at - now, 3), round(at - due, 3)
        if at > now:
            time.sleep(at - now)
    fast = later is not None and timed(later)
    x, y = int(env.sling_center.X + action[0]), int(env.sling_center.Y - action[1])  # as `step` makes the point
    (agent.ar.fast_shoot if fast else agent.ar.shoot)(x, y, 0, int(action[2]), 0)
    env.shots_per_level += 1  # as `step` counts its shots (a level's first `step` waits 0.5 s, a later one not)
    env.num_birds -= 1
    return ("fast", waited, late, "") if fast else ("safe", waited, late, outcome(agent, wait=later is None))


def send_time(shot, before):
    """(when it is due, the earliest it can be taken), by time.monotonic(), for a timed shot: due `launch_gap`
    seconds (physc's play: from the shot before's launch to its own) after the shot before was released, which is
    when the game answered it less its tap time, less DRAG_SECONDS, since the game releases a shot that long after
    it gets it; but not before its bird is on the slingshot, ON_SLINGSHOT_SECONDS after the bird before struck
    something (`launch_gap` − `wait` after its launch): the game's click finds no bird to drag before, and the shot
    is lost. Without `launch_gap`: `wait` seconds after the game answered the shot before."""
    answered, tap_ms = before
    gap = (shot.get("launch_gap") or "").strip()
    if not gap:
        return answered + float(shot["wait"]), answered
    released = answered - tap_ms / 1000.0
    struck = released + float(gap) - float(shot["wait"])
    return released + float(gap) - DRAG_SECONDS, struck + ON_SLINGSHOT_SECONDS


def outcome(agent, wait):
    """Whether the level was won: with `wait` (its last shot), the game's verdict, polled as `step` polls it, within
    OUTCOME_SECONDS; without, whether it is won already."""
    from Client.agent_client import GameState

    deadline = time.monotonic() + (OUTCOME_SECONDS if wait else 0.0)
    while True:
        state = agent.ar.get_game_state()
        if state in (GameState.WON, GameState.LOST) or time.monotonic() >= deadline:
            return state == GameState.WON
        time.sleep(0.5)


def level_speeds(shots, fast):
    """{level: the game's speed to play it at}: TIMED_SPEED for a level with a tapped shot (tap_time > 0) or a
    timed one (a wait), `fast` for the others. HUD.cs taps tap_time / speed milliseconds of the wall clock
    after the release, while the game steps its physics at most 0.02 s a frame (TimeManager.asset): the
    tap keeps its time only where the game makes 50 × speed frames a second."""
    speeds = {}
    for shot in shots:
        timed = int(shot.get("tap_time") or 0) > 0 or (shot.get("wait") or "").strip() != ""
        speeds[shot["level"]] = TIMED_SPEED if timed or speeds.get(shot["level"]) == TIMED_SPEED else fast
    return speeds


def server_running():
    """Whether the game's server (game_playing_interface.jar) runs already (the wrapper then starts none);
    True where `ps` cannot tell, so that nothing this run did not start is closed."""
    import subprocess

    try:
        listing = subprocess.run(["ps", "-eo", "args"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return True
    return any("game_playing_interface.jar" in line for line in listing.splitlines())


def aimed_again(angle, level_text, reference):
    """The action for `angle` from the game's reference point `reference`."""
    import re

    sling = re.search(r'<Slingshot x="([^"]+)" y="([^"]+)"', level_text)
    camera = re.search(r'<Camera x="[^"]+" y="([^"]+)" minWidth="[^"]+" maxWidth="([^"]+)"', level_text)
    slingshot = (float(sling.group(1)), float(sling.group(2))) if sling else (-12.0, -2.5)
    camera_y, max_width = (float(camera.group(1)), float(camera.group(2))) if camera else (-1.0, 35.0)
    return agent_action(angle, slingshot, camera_y, max_width, reference=reference)[0][:2]


if __name__ == "__main__":
    main()
'''


def replay_script() -> str:
    """replay_shots.py: agent_action.py's functions as they are, and a main for sciencebirdsagents/."""
    header = (
        '"""Replay physc\'s shots in Phy-Q\'s game with its agent framework (written by physc generate).\n\n'
        "Run from phy-q/benchmark's sciencebirdsagents/ with the game's config.xml listing these levels\n"
        '(README.md beside this file): python path/to/replay_shots.py --out replayed.csv [--headless]\n"""\n\n'
    )
    body = inspect.getsource(agent_action).split('"""', 2)[2].lstrip("\n")
    return header + body.rstrip("\n") + "\n" + REPLAY_MAIN


def readme(count: int, worlds: list[str]) -> str:
    rolling = [w for w in worlds if w != "phyq"]
    build = (
        f"These levels were made for the world(s) {', '.join(rolling)}: play them in a game built with "
        "physc's patches/rolling (its README), not the stock Phy-Q game, which plays them otherwise.\n\n"
        if rolling
        else "These levels were made for `phyq`, Phy-Q's game as it ships.\n\n"
    )
    return (
        "# physc's tasks for Phy-Q's game\n\n"
        f"{count} levels, in the order of the dataset (level n is `load_level(n)`), made by physc generate.\n\n"
        + build
        + "To play them in the game (phy-q/benchmark, `sciencebirdsgames/Linux/`):\n\n"
        "```sh\n"
        f"mkdir -p sciencebirdsgames/Linux/{GAME_FOLDER}\n"
        f"cp phyq/Levels/*.xml sciencebirdsgames/Linux/{GAME_FOLDER}/\n"
        "cp phyq/config.xml sciencebirdsgames/Linux/config.xml   # keep a copy of the game's own first\n"
        "cd sciencebirdsagents && python ../phyq/replay_shots.py --out replayed.csv   # --headless: no window\n"
        "```\n\n"
        "`--headless` starts the game with no window and no terminal, in the background (the framework's\n"
        "`game_playing_interface.jar --headless`), and closes it at the end if it started it; without it the\n"
        "game is shown. A level with a tapped or timed shot is played at the game's speed 1, the others at\n"
        "`--speed` (50 by default): the game waits a tap's time divided by the speed on the wall clock but\n"
        "steps at most 0.02 s a frame, so at a higher speed the tap comes early unless the game makes 50 ×\n"
        'speed frames a second (physc\'s docs/angrybirds.md, "At a speed under which a tap keeps its time").\n'
        "`replayed.csv` has the speed of each shot.\n\n"
        "A timed shot (a `wait` in `shots.csv`: taken that many seconds after its bird came onto the slingshot,\n"
        "not once the level rests) is sent by the clock: the shot before it in the framework's fast mode (the game\n"
        "answers once the shot is made, not once the level rests), then the timed one `launch_gap` seconds (physc's\n"
        "play) after the shot before was released, less the 1 s the game drags a bird before releasing it, but not\n"
        "before its bird is on the slingshot. `replayed.csv` says how each shot was sent (`step`, `fast`, `safe`),\n"
        "how long the script waited, and how late a timed shot was sent (a wait shorter than the drag cannot be\n"
        "kept in the game).\n\n"
        "`shots.csv` holds each level's intended solution as physc's release angle and as the action Phy-Q's\n"
        "agents send, `env.step([dx, dy, tap_time])`: whole pixels from the slingshot's reference point on\n"
        "the game's 840 × 480 window, zoomed out fully (what `env.reset()` leaves), and the angle the game\n"
        "launches it at (`agent_angle`, within 0.15° of the release angle; `physc verify` replays both).\n"
        "`replay_shots.py` sends them, aiming again from the game's own reference point if it differs\n"
        "from `reference_x`, `reference_y` (another window size).\n"
    )
