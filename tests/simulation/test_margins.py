"""Margins (issue 61, point 1): how far each link of a trace was from failing, in its own units."""

from __future__ import annotations

import attrs
import numpy as np
import pytest

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ
from physc.simulation.margins import Margin, MarginReader, Margins, Recognised, side_margin
from physc.simulation.trace import ContactRecord, DamageRecord, DestructionRecord, Interaction, Trace

BOX2D = load_backend("box2d")
READER = MarginReader(PHYQ.recogniser)
GROUND_TOP = PHYQ.frame.ground_top


@attrs.frozen
class Term:
    name: str
    objects: tuple
    directions: tuple = ()
    text: str = ""


@attrs.frozen
class Scenario:
    interactions: tuple
    restrictions: tuple = ()


def test_a_side_margin_is_the_degrees_inside_the_nearest_allowed_sector():
    assert side_margin(-1.0, 0.0, {"left"}) == pytest.approx(45.0)  # straight from the left
    assert side_margin(-1.0, 1.0, {"left"}) == pytest.approx(0.0)  # on the diagonal: at the edge
    assert side_margin(-1.0, 2.0, {"left"}) < 0 < side_margin(-1.0, 2.0, {"left", "above"})


def _strike(speed: float, least: float, life: float = 1.0) -> Trace:
    """A block coming from the left at `speed` into a pig, which takes `speed` damage (`least`
    under the worst reading) and, if that is its life, is destroyed."""
    states = np.zeros((50, 2, 6))
    states[:, 0, 0] = np.linspace(-2.0, -0.4, 50)
    states[:, 0, 3] = speed
    states[:, 1, 0] = 0.0
    contact = ContactRecord(0.5, "block", "pig", (-0.2, 0.0), (1.0, 0.0), (speed, 0.0), (speed, 0.0), (0.0, 0.0))
    damage = (DamageRecord(0.5, "pig", speed, life - speed, "block", "block", life, least, speed),)
    found = [Interaction("hit", ("block", "pig"), "left", 0.5)]
    destructions = ()
    if speed >= life:
        found.append(Interaction("destroy", ("block", "pig"), None, 0.5))
        destructions = (DestructionRecord(0.5, "pig", "damage", "block"),)
    outlines = {"block": (0.0, 0.0, 0.0, 0.2, 0.2), "pig": (0.0, 0.0, 0.0, 0.2, 0.2)}
    return Trace(0.02, ("block", "pig"), {"block": "block", "pig": "pig"}, states, (contact,), (), damage, destructions, ("pig",), bool(destructions), tuple(found), outlines=outlines)


STRIKE = Scenario((Term("hit", ("block", "pig"), ("left",), "hit(block, pig, left)"), Term("destroy", ("block", "pig"), (), "destroy(block, pig)")))


def test_a_destroy_is_measured_under_the_worst_reading():
    margins = READER.read(STRIKE, _strike(3.0, least=1.5))
    hit, destroy = margins.links
    assert hit.unit == "degrees" and hit.value == pytest.approx(45.0) and hit.held
    assert destroy.unit == "damage" and destroy.value == pytest.approx(0.5) and destroy.held  # 1.5 under the worst reading, against a life of 1
    assert margins.weakest is destroy
    # Another reading deals less than the life: held in this run, negative under the worst reading.
    weak = READER.read(STRIKE, _strike(3.0, least=0.4)).weakest
    assert weak.term == "destroy(block, pig)" and weak.value == pytest.approx(-0.6) and weak.held


def test_a_link_that_failed_is_the_weakest_and_says_by_how_much():
    margins = READER.read(STRIKE, _strike(0.7, least=0.7))
    failed = margins.weakest
    assert failed.term == "destroy(block, pig)" and not failed.held and failed.value == pytest.approx(-0.3)
    assert [m.held for m in margins.links] == [True, False]


def test_a_falling_block_has_its_air_time_drop_and_landing_measured():
    """A wood block dropped 1.2 units onto a platform: a fall with time, height and a landing
    well inside the platform's top."""
    platform = LevelObject("Platform", "Platform", 0.0, GROUND_TOP + 0.5, 0.0, scale_x=4.0, name="ledge")
    block = LevelObject("Block", "RectSmall", 0.3, GROUND_TOP + 2.0, 0.0, "wood", name="block")
    game = Game(Level(objects=(platform, block)), PHYQ, BOX2D)
    trace = game.play(None, 3.0, settle_after_solved=None)
    (fall,) = [i for i in trace.interactions if i.name == "fall"]
    assert fall.objects == ("block", "ledge")
    margin = READER.read(Scenario((Term("fall", ("block", "ledge"), (), "fall(block, ledge)"),)), trace).links[0]
    assert margin.held and margin.share > 0
    assert margin.unit in ("s", "units", "units of overlap")


def test_a_clearance_is_kept_and_a_trace_with_no_scenario_reads_its_own_interactions():
    cannot = Term("cannotHit", ("block", "pig"), ("left", "right", "above", "below"), "cannotHit(block, pig, any)")
    trace = _strike(3.0, least=3.0)
    far = attrs.evolve(trace, contacts=(), interactions=(), damage=(), destructions=())
    clearance = READER.read(Scenario((), (cannot,)), far).links[0]
    assert clearance.unit == "units of clearance" and clearance.value == pytest.approx(0.0, abs=1e-9) and clearance.held
    own = READER.read(Recognised.of(trace), trace)
    assert [m.term for m in own.links] == ["hit(block, pig, left)", "destroy(block, pig)"]


def test_the_weakest_link_prefers_a_failed_one_then_the_smallest_share():
    held = Margin("a", 0, 0.1, "s", 0.2, "x")
    failed = Margin("b", 1, 5.0, "s", 0.2, "x", held=False)
    assert Margins((held, failed)).weakest is failed
    assert Margins((held, Margin("c", 2, 1.0, "s", 0.2, "x"))).weakest is held and Margins().weakest is None


def test_a_hit_by_a_part_of_the_actor_is_measured_on_that_part():
    """A blue bird's split adds two birds that are the bird as the scenario names it
    (Trace.parts): the hit one of them makes is read from its contact and its path, not as
    the gap the bird itself kept (which read -9.6 units for Phy-Q's manoeuvring)."""
    strike = _strike(3.0, least=3.0)
    states = np.concatenate([np.full((50, 1, 6), np.nan), strike.states], axis=1)
    states[:, 0, 0] = -8.0  # the bird itself stays far off, then is gone
    contact = attrs.evolve(strike.contacts[0], a="bird_2")
    trace = attrs.evolve(
        strike, names=("bird", "bird_2", "pig"), kinds={"bird": "bird", "bird_2": "bird", "pig": "pig"},
        states=np.concatenate([states[:, :1], strike.states[:, :1], strike.states[:, 1:]], axis=1),
        contacts=(contact,), interactions=(Interaction("hit", ("bird", "pig"), "left", 0.5),),
        outlines={"bird": (0.0, 0.0, 0.0, 0.2, 0.2), "bird_2": (0.0, 0.0, 0.0, 0.2, 0.2), "pig": (0.0, 0.0, 0.0, 0.2, 0.2)},
        parts={"bird_2": "bird"},
    )
    hit = READER.read(Scenario((Term("hit", ("bird", "pig"), ("left",), "hit(bird, pig, left)"),)), trace).links[0]
    assert hit.held and hit.unit == "degrees" and hit.value == pytest.approx(45.0)
    cannot = Term("cannotHit", ("bird", "pig"), ("above",), "cannotHit(bird, pig, above)")
    kept = READER.read(Scenario((), (cannot,)), trace).links[0]
    assert kept.unit == "degrees" and kept.value > 0  # from the left: away from the forbidden side


def test_a_link_whose_target_was_destroyed_first_fails_by_how_much_it_was_overkilled():
    """The second bird's hit cannot happen once the first blow has knocked the pig off to die on
    the ground: the failure is graded by the life the pig had left under the worst reading (a
    raising can climb it), where a link not realised is a flat -1."""
    strike = _strike(3.0, least=3.0)
    states = np.concatenate([strike.states, np.full((50, 1, 6), np.nan)], axis=1)  # bird2 never comes
    blows = (DamageRecord(0.5, "pig", 0.4, 0.6, "block", "block", 1.0, 0.4, 0.4), DamageRecord(0.8, "pig", 0.9, -0.3, "ground", "pig", None, 0.7, 1.2))
    trace = attrs.evolve(
        strike, names=("block", "pig", "bird2"), kinds={"block": "block", "pig": "pig", "bird2": "bird"}, states=states,
        damage=blows, destructions=(DestructionRecord(0.8, "pig", "damage", "ground"),), interactions=strike.interactions[:1],
    )
    scenario = Scenario((Term("hit", ("block", "pig"), ("left",), "hit(block, pig, left)"), Term("hit", ("bird2", "pig"), ("left",), "hit(bird2, pig, left)")))
    first, second = READER.read(scenario, trace).links
    assert first.held
    assert not second.held and second.unit == "life" and second.value == pytest.approx(1.0 - 0.4 - 1.2)  # the worst reading of each blow
    assert "destroyed first by ground" in second.what
    # Destroyed by the link's own actor (a hit from the wrong side that still killed): the link's own margin.
    own = attrs.evolve(trace, destructions=(DestructionRecord(0.8, "pig", "damage", "bird2"),))
    assert READER.read(scenario, own).links[1].unit != "life"
