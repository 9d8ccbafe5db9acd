"""The physics-aware choice of concrete objects, mitred platform joints, and pathObstructed as a repair."""

from __future__ import annotations

import random

from middle_end import DOMAIN, paper_scenarios, scenario_from_text

from physc.compiler.concrete_layout import ChosenRelation
from physc.compiler.geometry import Geometry, overlap_depth, polygon
from physc.compiler.infer_layout import InferLayout
from physc.compiler.passes import PassContext
from physc.compiler.qsr import joined
from physc.domains.angrybirds.preferences import choose_concrete


def draws(name: str, seeds=range(40)):
    scenario = paper_scenarios()[name]
    graph = InferLayout(DOMAIN).run(scenario, PassContext(scenario, random.Random(0), 0))
    return [choose_concrete(scenario, graph, random.Random(seed)) for seed in seeds]


def test_round_blocks_in_a_chain_share_their_size():
    chains = draws("RRR")
    assert all(d["rBlock1"] == d["rBlock2"] == d["rBlock3"] for d in chains)
    assert {d["rBlock1"] for d in chains} == {"circle", "circleSmall"}


def test_a_pig_at_the_end_of_a_chain_is_small():
    # The destroyer got its momentum through at least two collisions: the pig is small.
    for name in ("RF", "RS", "FR", "SR", "RRF", "RRR"):
        assert {d["pig"] for d in draws(name)} == {"pigSmall"}, name
    # The bird hits the destroyer itself (R, F, S, BF) or destroys the pig (SF, B): either pig.
    for name in ("SF", "R", "F", "S", "B", "BF"):
        assert {d["pig"] for d in draws(name)} == {"pigSmall", "pigMedium"}, name


def test_a_declared_pig_is_kept_at_the_end_of_a_chain():
    scenario = scenario_from_text(
        "scenario X {\n  objects {\n    pig: pig = pigMedium\n  }\n"
        "  interactions {\n    hit(bird, rBlock1, left) > roll(rBlock1, surface1, right) > hit(rBlock1, rBlock2, left)\n"
        "    > roll(rBlock2, surface2, right) > hit(rBlock2, pig, left) > destroy(rBlock2, pig)\n  }\n}\n"
    )
    graph = InferLayout(DOMAIN).run(scenario, PassContext(scenario, random.Random(0), 0))
    assert {choose_concrete(scenario, graph, random.Random(s))["pig"] for s in range(20)} == {"pigMedium"}


def test_declared_objects_are_kept():
    scenario = scenario_from_text(
        "scenario X {\n  objects {\n    rBlock2: rollableBlock = circle\n  }\n"
        "  interactions {\n    hit(bird, rBlock1, left) > roll(rBlock1, surface1, right) > hit(rBlock1, rBlock2, left)\n"
        "    > roll(rBlock2, surface2, right) > hit(rBlock2, pig, left) > destroy(rBlock2, pig)\n  }\n}\n"
    )
    graph = InferLayout(DOMAIN).run(scenario, PassContext(scenario, random.Random(0), 0))
    chosen = [choose_concrete(scenario, graph, random.Random(s)) for s in range(20)]
    assert {d["rBlock1"] for d in chosen} == {"circle", "circleSmall"}
    assert {d["rBlock2"] for d in chosen} == {"circle"}


def test_joined_platforms_may_overlap_at_the_joint_and_nothing_else_may():
    flat = Geometry(2.0, 0.32, 0.0)
    ramp = Geometry(2.0, 0.32, -20.0)
    flat_points = flat.points(0.0, 0.0)
    # The ramp's upper-left point on the flat platform's upper-right point.
    ur = flat_points["ur"]
    probe = ramp.points(0.0, 0.0)
    dx, dy = ur[0] - probe["ul"][0], ur[1] - probe["ul"][1]
    ramp_points = ramp.points(dx, dy)
    assert overlap_depth(polygon(flat_points), polygon(ramp_points)) > 1e-3  # a mitred joint
    pairs = joined([ChosenRelation("MeetNW", "a", "b", ""), ChosenRelation("W", "a", "c", "")])
    assert pairs == {frozenset(("a", "b"))}


def materials_drawn(name: str, seeds=range(30)):
    scenario = paper_scenarios()[name]
    graph = InferLayout(DOMAIN).run(scenario, PassContext(scenario, random.Random(0), 0))
    out = []
    for seed in seeds:
        bodies = DOMAIN.concretize(graph, scenario, random.Random(seed))
        out.append({n: b.material for n, b in bodies.items()})
    return out


DENSER = {("wood", "stone"), ("ice", "wood"), ("ice", "stone")}  # (lighter, heavier)


def test_momentum_passes_down_a_chain_from_heavier_to_lighter():
    # A block the bird hits and that then moves is never stone; a block hit by a block
    # is never denser than its hitter.
    for name in ("R", "S", "RF", "RS", "FR", "SR", "RRR", "SFR"):
        scenario = paper_scenarios()[name]
        hits = [t.objects for t in scenario.interactions if t.name == "hit" and t.objects[1] != "pig"]
        for drawn in materials_drawn(name):
            for hitter, target in hits:
                if hitter == "bird":
                    assert drawn[target] != "stone", (name, target)
                else:
                    assert (drawn[hitter], drawn[target]) not in DENSER, (name, hitter, target, drawn)


def test_a_moving_block_keeps_both_light_materials():
    # Stone becomes wood; wood and ice are still both drawn, at the head of a chain and
    # (taking the hitter's material) where a falling block hits it.
    assert {d["fBlock"] for d in materials_drawn("F")} == {"wood", "ice"}
    assert {d["rBlock1"] for d in materials_drawn("RRR")} == {"wood", "ice"}
    assert {d["rBlock"] for d in materials_drawn("FR")} == {"wood", "ice"}


def test_a_block_set_moving_by_a_rolling_or_sliding_block_is_ice():
    # Ball against ball, wood grips at friction 4 and turns the struck ball the wrong way.
    for name, blocks in (
        ("RRR", ("rBlock2", "rBlock3")),
        ("RS", ("sBlock",)),
        ("SR", ("rBlock",)),
        ("RRF", ("rBlock2", "fBlock")),
    ):
        for drawn in materials_drawn(name):
            assert all(drawn[b] == "ice" for b in blocks), (name, drawn)


def test_a_block_a_ball_hits_sideways_is_a_square():
    # RF's fBlock and RS's sBlock are hit from the left by rBlock: never a triangle.
    assert {d["fBlock"] for d in draws("RF")} == {"squareHole", "circle", "circleSmall"}
    assert {d["sBlock"] for d in draws("RS")} == {"squareHole"}
    # S's sBlock is hit by the bird: both shapes stay.
    assert {d["sBlock"] for d in draws("S")} == {"squareHole", "triangleHole"}


def test_a_block_that_falls_on_a_block_that_moves_next_is_not_round():
    # A falling ball rolls off the top of a ball at rest; a square lands and pushes it.
    assert {d["fBlock"] for d in draws("FR")} == {"squareHole", "triangleHole"}
    assert {d["fBlock"] for d in draws("SFR")} == {"squareHole", "triangleHole"}
    # Falling on a pig (F, RF): every fallable shape stays.
    assert {d["fBlock"] for d in draws("F")} == {"squareHole", "triangleHole", "circle", "circleSmall"}


def test_a_ball_that_destroys_the_pig_after_a_block_hit_it_is_large():
    # SR's rBlock is struck by a sliding block and kills the pig: its damage grows with its mass.
    assert {d["rBlock"] for d in draws("SR")} == {"circle"}
    # Struck by the bird (R) or by a ball of its own size (RRR): both sizes stay.
    assert {d["rBlock"] for d in draws("R")} == {"circle", "circleSmall"}
    assert {d["rBlock3"] for d in draws("RRR")} == {"circle", "circleSmall"}
