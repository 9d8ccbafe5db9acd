"""Runs continued from a snapshot (physc.simulation.snapshot): every backend restores a
body's state, the run loop goes on from the cut with the events before it, the game's
rules rebuild their state, and the search confirms what a snapshot passes from the start."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physc.backends import BodySpec, Circle, Polygon, installed_backends, load_backend
from physc.backends.settings import EngineSettings
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ
from physc.simulation.snapshot import Snapshot

BOX2D = load_backend("box2d")

PLATFORM = LevelObject("Platform", "Platform", 2.0, -1.0, 0.0, scale_x=10 / 0.64, scale_y=0.5, name="platform")
BLOCK = LevelObject("Block", "SquareHole", -1.5, -1.0 + 0.16 + 0.42, 0.0, "wood", name="block")
PIG = LevelObject("Pig", "BasicSmall", 0.0, -3.5 + 0.236, 0.0, name="pig")
LEVEL = Level(objects=(PLATFORM, BLOCK))
SHOT = Shot(target=(-1.5, -0.6))


def play(level=LEVEL, shot=SHOT, resume=None):
    return Game(level, PHYQ, BOX2D).play(shot, 10.0, settle_after_solved=0.3, resume=resume)


@pytest.mark.parametrize("backend", sorted(installed_backends()))
def test_every_backend_puts_a_body_back_in_a_state(backend):
    world = load_backend(backend).create_world(9.81, EngineSettings())
    world.add(BodySpec("box", Polygon(((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5))), 0.0, 0.0, mass=1.0))
    world.add(BodySpec("ball", Circle(0.3), 3.0, 0.0, mass=1.0))
    world.restore("box", (1.0, 2.0, 0.3, 0.5, -0.25, 0.1))
    assert np.allclose(world.state("box"), (1.0, 2.0, 0.3, 0.5, -0.25, 0.1), atol=1e-5)
    world.step(0.02)
    x, y = world.state("box")[:2]
    assert 1.0 < x < 1.02 and y < 2.0  # it moved on from there, under gravity


def test_a_snapshot_holds_the_run_up_to_its_cut():
    trace = play()
    snapshot = Snapshot.of(trace, 100)
    assert snapshot.time == pytest.approx(2.0)
    assert snapshot.states.shape == (100, len(trace.names), 6)
    assert all(c.time <= 2.0 + 1e-9 for c in snapshot.contacts)
    assert frozenset(("block", "platform")) in snapshot.touching
    assert snapshot.state("bird") is not None and not snapshot.gone
    with pytest.raises(ValueError, match="must be cut after 1 to"):
        Snapshot.of(trace, trace.steps)


@pytest.mark.parametrize("cut", [10, 40, 120])
def test_a_run_continued_from_its_own_snapshot_goes_the_same_way(cut):
    full = play()
    safe = Snapshot.latest_cut(full, cut)
    if safe != cut:  # the block, destroyed at 2.28 s, stays in the world until 2.78 s: no cut in between
        with pytest.raises(ValueError, match="still in the world"):
            Snapshot.of(full, cut)
        assert any(d.until and d.time <= cut * full.dt < d.until for d in full.destructions)
        cut = safe
    continued = play(resume=Snapshot.of(full, cut))
    assert continued.sequence() == full.sequence()
    assert np.array_equal(continued.states[:cut], full.states[:cut], equal_nan=True)  # the rows before the cut are the run's
    assert continued.contacts[: len(Snapshot.of(full, cut).contacts)] == Snapshot.of(full, cut).contacts
    # no contact is begun twice: a pair touching at the cut is not a new contact
    touching = Snapshot.of(full, cut).touching
    assert not [c for c in continued.contacts if abs(c.time - (cut + 1) * full.dt) < 1e-9 and frozenset((c.a, c.b)) in touching]
    steps = min(full.steps, continued.steps)
    assert np.nanmax(np.abs(continued.states[:steps, :, :2] - full.states[:steps, :, :2])) < 0.05


def test_continuing_is_deterministic():
    full = play()
    a, b = (play(resume=Snapshot.of(full, 60)) for _ in range(2))
    assert np.array_equal(a.states, b.states, equal_nan=True) and a.contacts == b.contacts


def test_a_new_object_the_snapshot_lacks_waits_where_the_scene_put_it_and_is_met():
    """The stage's case: the prefix ran without the pig; the scene with it goes on from a
    cut before the bird gets there, and the pig is destroyed as in a run from the start."""
    prefix = play(Level(objects=()), Shot(target=(0.0, -3.27)))
    with_pig = Level(objects=(PIG,))
    full = play(with_pig, Shot(target=(0.0, -3.27)))
    continued = play(with_pig, Shot(target=(0.0, -3.27)), resume=Snapshot.of(prefix, 30))
    column = continued.index("pig")
    assert np.allclose(continued.states[:30, column, :2], (PIG.x, PIG.y))
    assert full.solved and continued.solved
    assert continued.sequence() == full.sequence()


def test_the_games_rules_go_on_from_the_lives_and_the_birds_checks():
    """Damage done before the cut counts: a pig wounded before it is not whole again after."""
    trace = play()
    damaged = [d for d in trace.damage if d.target == "block"]
    assert damaged, "the shot damages the block"
    cut = int(math.ceil(damaged[0].time / trace.dt)) + 1
    game = Game(LEVEL, PHYQ, BOX2D)
    continued = game.play(SHOT, 10.0, settle_after_solved=0.3, resume=Snapshot.of(trace, cut))
    assert [d for d in continued.damage if d.target == "block"][0] == damaged[0]
    assert game.life["block"] <= damaged[0].life
    assert "bird" in game.flights.struck
    assert [d.time for d in continued.destructions if d.name == "bird"] == [d.time for d in trace.destructions if d.name == "bird"]


def test_the_search_confirms_what_a_snapshot_passes_from_the_start(monkeypatch):
    """Later stages go on from snapshots of the parent's plays, but every attempt that
    realises a stage, which the next stage builds on, is a play from the start."""
    from middle_end import search

    from physc.search import chain

    resumed, simulate, realised = set(), chain.simulate, chain.realised

    def simulated(problem, ledger, layout, action, seconds=None, resume=None):
        attempt = simulate(problem, ledger, layout, action, seconds, resume)
        if resume is not None:
            resumed.add(id(attempt.trace))
        return attempt

    def checked(*args, **kwargs):
        good = realised(*args, **kwargs) or ()
        assert not [a for a in good if id(a.trace) in resumed]
        return good or None

    monkeypatch.setattr(chain, "simulate", simulated)
    monkeypatch.setattr(chain, "realised", checked)
    outcome = search("F", seed=2).run()
    assert outcome.satisfied
    assert resumed, "the second stage went on from a snapshot"


def test_with_snapshots_off_every_play_runs_from_the_start(monkeypatch):
    from middle_end import search

    from physc.search import chain

    cuts, simulate = [], chain.simulate
    monkeypatch.setattr(chain, "simulate", lambda *a, **k: cuts.append(a[5] if len(a) > 5 else k.get("resume")) or simulate(*a, **k))
    assert search("F", seed=2, snapshots=False).run().satisfied
    assert cuts and not any(cuts)


def test_a_run_cut_while_all_rests_ends_when_the_full_run_does():
    """The game stops 0.3 s after everything came to rest: a run continued from a cut inside
    that wait counts the rest before the cut, as the full run did."""
    full = Game(LEVEL, PHYQ, BOX2D).simulate(SHOT, 10.0)
    speeds = np.nan_to_num(np.abs(full.states[:, :, 3:6]).sum(axis=2)).max(axis=1)
    bird = full.names.index("bird")
    resting = [k for k in range(full.steps - 1) if np.isnan(full.states[k, bird, 0]) and speeds[k] < 0.02]
    assert resting, "the run comes to rest before it ends"
    cut = resting[-1]  # inside the last 0.3 s of rest
    continued = Game(LEVEL, PHYQ, BOX2D).simulate(SHOT, 10.0, resume=Snapshot.of(full, cut))
    assert continued.steps == full.steps
