"""Tasks that hold in the game (issue 53): a generated task passes what `physc verify` runs,
under each reading of what the game's files leave open, and fallbacks are made only on request."""

from __future__ import annotations

import re
from unittest import mock

import attrs
import pytest
from middle_end import DOMAIN, paper_scenarios

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ, ROLLING
from physc.driver import workers
from physc.driver.layout_loop import LayoutLoop
from physc.driver.pipeline import Pipeline
from physc.driver.run_settings import RunSettings
from physc.search.outcome import Outcome
from physc.search.verify import verify
from physc.simulation.trace import ContactRecord

BOX2D = load_backend("box2d")


def test_the_games_open_points_are_declared_once_and_give_every_combination_of_readings():
    for world in (PHYQ, ROLLING):
        points = world.open_points()
        assert [p.setting for p in points] == ["rules.relative_velocity", "rules.platform_mass", "rules.near_tie"]
        assert all(p.source and p.question for p in points)
        readings = world.readings()
        assert len(readings) == 8 and readings[0] is world
        assert {r.open_values() for r in readings} == {(a, b, c) for a in points[0].readings for b in points[1].readings for c in points[2].readings}
        platform = next(r for r in readings if r.changed == ("rules.platform_mass",))
        assert platform.rules.platform_mass == 0.0 and platform.name == f"{world.name}, platform mass 0"
        assert world.read_as(world.open_values()) is world
    contact_model = attrs.evolve(PHYQ, rules=attrs.evolve(PHYQ.rules, attacker="contact"))
    assert contact_model.readings() == (contact_model,)  # physc's earlier model leaves nothing open


def test_each_object_picks_its_attacker_after_the_step_as_the_reading_says():
    """A moving block strikes a resting pig: after the step the block still moves on, the pig
    barely. Read as other-minus-this, the block (the body that comes at the pig) attacks it; read
    the other way, the pig is its own attacker and takes the damage of its own mass."""
    pig = LevelObject("Pig", "BasicSmall", 0.0, 0.0, 0.0, name="pig")
    block = LevelObject("Block", "SquareSmall", -1.0, 0.0, 0.0, "stone", name="block")
    amounts = {}
    for world in PHYQ.readings()[:1] + tuple(r for r in PHYQ.readings() if r.changed == ("rules.relative_velocity",)):
        game = Game(Level(objects=(pig, block)), world, BOX2D)
        built = game.build()
        built.set_velocity("block", 3.0, 0.0)
        contact = ContactRecord(0.0, "block", "pig", (-0.5, 0.0), (1.0, 0.0), (3.0, 0.0), (3.0, 0.0), (0.0, 0.0))
        game.life["pig"] = 1000.0
        out = []
        game._damage(built, contact, out, 3.0)
        (record,) = [r for r in out if r.target == "pig"]
        amounts[world.rules.relative_velocity] = record.amount
    stone = built.mass("block")
    small_pig = built.mass("pig")
    assert amounts["other-minus-this"] == pytest.approx(3.0 * stone * 11.22 * 0.5 - 1.0)
    assert amounts["this-minus-other"] == pytest.approx(3.0 * small_pig * 11.22 * 0.5 - 1.0)
    assert amounts["this-minus-other"] < amounts["other-minus-this"]


def test_a_generated_task_passes_physc_verify_in_every_reading():
    scenario = paper_scenarios()["SF"]
    task = Pipeline(DOMAIN, scenario, seed=0).task
    assert not task.fallback and task.robustness == (6, 6)
    for world in PHYQ.readings():
        check = verify(DOMAIN.at(world), scenario, task.level, task.solution, "box2d", noisy=6)
        assert check.passes(6), (world.name, check.why)


def test_a_solution_that_fails_a_reading_gives_the_layout_up():
    scenario = paper_scenarios()["SF"]
    task = Pipeline(DOMAIN, scenario, seed=0).task
    loop = LayoutLoop(DOMAIN, scenario, None, RunSettings(time_budget=10.0, layouts=1, min_robustness=6, validate=False))
    parts = mock.Mock(level=task.level, solution=task.solution)
    passed = workers.checked(loop.run_of, Outcome(True, 5, parts), None)
    check = verify(DOMAIN, scenario, task.level, task.solution, "box2d", noisy=6)
    # The recorded solution and 6 noisy replays, each in every reading that can change it: the
    # pig's destroying strike depends on relativeVelocity's sign in each, so two at least.
    assert passed.satisfied and passed.simulations == 5 + check.simulations and check.simulations >= 2 * 7
    x, y = task.solution.target
    failing = attrs.evolve(task.solution, target=(x - 3.0, y - 1.0))  # a shot that misses
    given_up = workers.checked(loop.run_of, Outcome(True, 5, mock.Mock(level=task.level, solution=failing)), None)
    assert not given_up.satisfied and given_up.given_up == "the solution fails physc verify in the world 'phyq'"


def test_a_chain_that_noise_breaks_names_the_link_and_its_physics():
    """R seed 1, 10 layouts: a layout realises all four links, but not robustly; the message
    names the link the failed noisy replays lost most often and what the replay shows about it,
    and the weakest link with how far it failed at best.
    (The damage a struck object is left with: tests/simulation/test_stopped.py.)"""
    from conftest import EXAMPLES, run_physc

    run = run_physc("compile", EXAMPLES / "paper" / "04_R.phys", "--seed", "1", "--layouts", "10", "--color", "never", "-q", "--emit", "task")
    assert run.status == 3
    assert "the best simulation realised 4 of the 4 interactions in order" in run.stderr
    assert re.search(r"lost `(roll|hit|destroy)\(rBlock, [^`]+` first \(rBlock (moved|struck) [^)]*units/s", run.stderr), run.stderr
    # The weakest link, with its margin in its own physics and units.
    assert re.search(r"the weakest link was `[a-zA-Z]+\(rBlock, [^`]+`: it failed by [0-9.]+ (damage|s|units|degrees) at best", run.stderr), run.stderr
