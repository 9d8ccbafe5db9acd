"""What a stopped chain says about its first unrealised link (physc.simulation.stopped)."""

from __future__ import annotations

import numpy as np
from middle_end import paper_scenarios

from physc.simulation.fidelity import Fidelity
from physc.simulation.stopped import why_stopped
from physc.simulation.trace import DamageRecord, Trace


def test_a_strike_that_does_not_destroy_says_the_speed_the_damage_and_the_life_left():
    scenario = paper_scenarios()["R"]  # hit(bird, rBlock) > roll(rBlock, surface) > hit(rBlock, pig) > destroy(rBlock, pig)
    states = np.zeros((50, 2, 6))
    states[:, 0, 3] = 1.5  # rBlock moving at 1.5 units/s
    damage = (DamageRecord(0.6, "pig", 0.4, 0.6, "rBlock"),)
    trace = Trace(0.02, ("rBlock", "pig"), {"rBlock": "block", "pig": "pig"}, states, damage=damage)
    fidelity = Fidelity(3, 4, (), False, (0.1, 0.3, 0.5))
    why = why_stopped(scenario, trace, fidelity)
    assert why == (
        "rBlock struck pig at up to 1.50 units/s after `hit(rBlock, pig, left)`, dealing 0.40 damage: "
        "not enough to destroy it (0.60 of its life left)"
    )


def test_a_strike_says_whose_mass_set_the_damage_and_the_speed_that_would_have_destroyed():
    scenario = paper_scenarios()["R"]
    states = np.zeros((50, 2, 6))
    states[:, 0, 3] = 1.0
    damage = (DamageRecord(0.6, "pig", 0.26, 0.74, "rBlock", attacker="pig", needed=2.38),)
    trace = Trace(0.02, ("rBlock", "pig"), {"rBlock": "block", "pig": "pig"}, states, damage=damage)
    why = why_stopped(scenario, trace, Fidelity(3, 4, (), False, (0.1, 0.3, 0.5)))
    assert why.endswith(
        "(0.74 of its life left; with its own mass setting the damage, a strike of 2.38 units/s would have destroyed it)"
    )


def test_a_later_bird_that_never_came_says_the_goal_was_met_first():
    """A second shot waits for the level: when the first shot's pig dies on the ground, the run
    is over before the next bird comes (Phy-Q's multiple forces), which is not a bird 'gone'."""
    from physc.dsl.scenario import ScenarioIR, TermIR
    from physc.simulation.trace import DestructionRecord

    terms = (TermIR("hit", ("bird", "pig"), ("left",), text="hit(bird, pig, left)"), TermIR("hit", ("bird2", "pig"), ("left",), text="hit(bird2, pig, left)"))
    scenario = ScenarioIR("Two", "", "angrybirds", (), terms, ())
    states = np.zeros((50, 3, 6))
    states[:, 1] = np.nan  # bird2: never in the run
    kinds = {"bird": "bird", "bird2": "bird", "pig": "pig"}
    solved = Trace(0.02, ("bird", "bird2", "pig"), kinds, states, destructions=(DestructionRecord(0.9, "pig", "damage", "ground"),), goal=("pig",), solved=True)
    why = why_stopped(scenario, solved, Fidelity(1, 2, (), False, (0.5,)))
    assert why == "bird2 never came into the run after `hit(bird, pig, left)`: the goal was met first (pig destroyed at 0.90 s by ground)"
    unsolved = Trace(0.02, ("bird", "bird2", "pig"), kinds, states, goal=("pig",))
    assert why_stopped(scenario, unsolved, Fidelity(1, 2, (), False, (0.5,))).endswith("it ended at 1.00 s before bird2 was due")
