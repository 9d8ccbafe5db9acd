"""Real Science Birds levels load and stand when nothing is shot (docs/angrybirds.md explains each failure)."""

from __future__ import annotations

import pytest
from conftest import GENERATED, TEMPLATES

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level_xml import read_level
from physc.domains.angrybirds.worlds import catalogue_model
from physc.simulation.stability import largest_shift

# Templates that do not stand in the default engine (Box2D at the game's settings), by collider
# model, and why (docs/angrybirds.md, "The Phy-Q templates"). With the game's own colliders every
# one stands: they were built in that engine with those colliders.
PHYQ_CIRCLES = {"3_5_1_1", "3_5_2_1", "3_7_5_1"}  # regular polygons and ellipse pigs: not the game's shapes
ROLL_OFF_ROUND = PHYQ_CIRCLES | {"3_5_5_1", "3_6_7_1", "3_7_4_1", "3_8_1_1", "3_8_2_1"}  # rest on flat-footed circles


BOX2D = load_backend("box2d")

def moved(path, colliders):
    trace = Game(read_level(path.read_bytes()), catalogue_model(colliders), BOX2D).simulate(None, 10.0, stop_at_rest=False)
    return largest_shift(trace), trace.destructions


@pytest.mark.parametrize("colliders, expected", [("game", set()), ("phyq", PHYQ_CIRCLES), ("round", ROLL_OFF_ROUND)])
def test_templates_stand_for_ten_seconds(colliders, expected):
    unstable = set()
    for path in TEMPLATES:
        shift, destroyed = moved(path, colliders)
        if shift > 0.1 or destroyed:
            unstable.add(path.stem)
    assert unstable == expected
    assert (len(TEMPLATES) - len(unstable)) / len(TEMPLATES) >= {"game": 74 / 75, "phyq": 0.95, "round": 0.89}[colliders]


@pytest.mark.parametrize("circles", ["game", "round", "phyq"])
def test_generated_levels_load_and_stand_for_ten_seconds(circles):
    # A sample of Phy-Q's and NovPhy's generated levels; benchmarks/real_levels.py measures all 750.
    unstable = {}
    for path in GENERATED:
        shift, destroyed = moved(path, circles)
        if shift > 0.1 or destroyed:
            unstable[path.stem] = (shift, destroyed)
    assert len(GENERATED) == 60 and unstable == {}
