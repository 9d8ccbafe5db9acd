"""The sequential strategy: stages, the generic depth-first search, and the angrybirds chain builder."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import attrs

from physc.generation.sequential import ChainBuilder, Sequential, Stage, State, stages

ROOT = Path(__file__).resolve().parents[1]
PAPER = ROOT / "examples" / "paper"


@attrs.frozen
class Term:
    name: str
    objects: tuple[str, ...]


def test_stages_begin_where_objects_enter():
    terms = [Term("hit", ("bird", "a")), Term("roll", ("a", "s")), Term("hit", ("a", "b")), Term("destroy", ("a", "b"))]
    plan = stages(terms, {"a": 0, "s": 0, "b": 2})
    assert plan == [Stage(0, 0, 2, ("a", "s")), Stage(1, 2, 4, ("b",))]


def test_objects_no_interaction_names_enter_in_a_last_stage():
    terms = [Term("hit", ("bird", "a")), Term("destroy", ("bird", "a"))]
    plan = stages(terms, {"a": 0, "extra": 2})
    assert plan == [Stage(0, 0, 2, ("a",)), Stage(1, 2, 2, ("extra",))]


class Toy(ChainBuilder):
    """Three stages; a scene is the tuple of choices made. Stage 1 works only after choice 2
    at stage 0; stage 2 only for choice 1 at stage 1."""

    def __init__(self):
        self.calls = []

    def stages(self):
        return [Stage(0, 0, 1, ("a",)), Stage(1, 1, 2, ("b",)), Stage(2, 2, 3, ("c",))]

    def root(self):
        return State((), (), -1)

    def variants(self, parent, stage):
        for choice in range(4):
            yield f"{stage.index}:{choice}", parent.scene + (choice,), 0

    def realised(self, scene, parent, stage, lead=0):
        self.calls.append(scene)
        if stage.index == 0:
            works = True
        elif stage.index == 1:
            works = scene[0] == 2
        else:
            works = scene[1:] == (1, 3)
        return ("attempt",) if works else None


def test_search_backtracks_until_every_stage_is_realised():
    builder = Toy()
    search = Sequential(builder)
    found = search.run()
    assert found is not None
    assert found.scene == (2, 1, 3)
    assert found.steps == ("0:2", "1:1", "2:3")
    assert search.furthest == 3
    # Stage 0's choices 0 and 1 each cost four failed tries at stage 1; after choice 2,
    # stage 1's choice 0 costs four at stage 2, its choice 1 three.
    assert search.failed_at == {1: 8, 2: 7}
    assert search.tried == len(builder.calls)


def test_search_keeps_its_budget():
    search = Sequential(Toy(), budget=5)
    assert search.run() is None
    assert search.tried == 5
    assert search.furthest == 1


def test_variants_per_stage_are_bounded():
    search = Sequential(Toy(), variants_per_stage=2)  # stage 0's choice 2 is never reached
    assert search.run() is None
    assert search.furthest == 1


def _ab(scenario_name: str, seed: int = 0):
    from physc.compiler.pipeline import Pipeline
    from physc.domains import load_domain
    from physc.domains.angrybirds.build import AngryBirdsChain
    from physc.domains.angrybirds.satisfy import Satisfier
    from physc.dsl.frontend import analyze

    scenario = next(s for s in analyze(str(PAPER / "all.paper.phys")).scenarios if s.name == scenario_name)
    domain = load_domain("angrybirds")
    layout = Pipeline(domain, scenario, seed).placed.layout
    return AngryBirdsChain(Satisfier(domain, scenario, layout))


def test_a_shelf_enters_with_the_first_ball_on_it():
    chain = _ab("RRR")
    plan = chain.stages()
    assert [(s.start, s.end) for s in plan] == [(0, 2), (2, 4), (4, 6), (6, 8)]
    assert {"rBlock1", "surface1", "surface2", "surface3"} <= set(plan[0].new)
    assert plan[1].new == ("rBlock2",) and plan[2].new == ("rBlock3",) and plan[3].new == ("pig",)


def test_a_stage_scene_holds_only_what_has_entered():
    chain = _ab("SRF")
    level = chain.s.level
    first = {o.name for o in chain.prefix(level, 0).objects}
    assert "sBlock" in first and "pig" not in first and "rBlock" not in first
    assert {o.name for o in chain.prefix(level, 8).objects} == {o.name for o in level.objects}


def test_the_next_target_goes_on_its_actors_simulated_path():
    chain = _ab("F", seed=2)
    root = chain.root()
    plan = chain.stages()
    description, scene, lead = next(iter(chain.variants(root, plan[0])))
    attempts = chain.realised(scene, root, plan[0], lead)
    assert attempts, "F seed 2's first stage is realised as placed"
    parent = State(scene, attempts, 0)
    offered = list(chain.variants(parent, plan[1]))
    placed = [d for d, _, _ in offered if "on its path" in d]
    assert placed, offered[:3]
    # The first of them: the target where the actor passes, realised by simulation.
    description, scene, lead = next((v for v in offered if "on its path" in v[0]))
    assert chain.realised(scene, parent, plan[1], lead)


def _compile(*arguments, cwd=None):
    return subprocess.run([sys.executable, "-m", "physc", *arguments], capture_output=True, text=True, cwd=cwd, timeout=300)


def test_a_failure_says_what_the_furthest_simulation_shows(tmp_path):
    done = _compile("compile", str(PAPER / "16_RRR.phys"), "--layouts", "2", "-q", "-o", str(tmp_path / "l.xml"), "--color", "never")
    assert done.returncode == 3, done.stderr
    # e.g. "(never `roll(rBlock3, surface3, right)` after them: rBlock3 moved at most 0.21
    # units/s after `hit(rBlock2, rBlock3, left)`, too slow to roll on surface3)"
    assert re.search(r"never `[^`]+` after them: (rBlock\d|pig) [^;]*(units/s|did not|damage)", done.stderr), done.stderr
    assert not (tmp_path / "l.xml").exists()
