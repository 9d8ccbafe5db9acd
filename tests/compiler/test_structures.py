"""Structures (issue 53): the layout rules' `ramp` reading of a roll before a sideways hit, as
the game's designers build one (Phy-Q's templates 2_1_3, 2_1_6, 2_1_9), beside the paper's."""

from __future__ import annotations

from middle_end import DOMAIN, paper_scenarios

from physc.compiler.concrete_layout import PlacedObject
from physc.compiler.layout_graph import ON_LOCATION, TOUCHING
from physc.domains.angrybirds.search_hooks import toughness
from physc.domains.angrybirds.worlds import PHYQ
from physc.search.choosing import next_act, worth


def edges(graph, term):
    return {(e.a, e.b, e.values) for e in graph.edges if e.term == term}


def test_a_roll_into_a_sideways_hit_has_a_ramp_structure_and_other_chains_do_not():
    rules = DOMAIN.layout_rules
    paper = paper_scenarios()
    assert [name for name, s in paper.items() if rules.structures(s) == ("flat", "ramp")] == [
        "R", "RF", "RS", "FR", "SR", "SRF", "SFR", "RRF", "RRR",
    ]
    assert rules.structures(paper["SF"]) == ("flat",)


def test_the_ramp_descends_to_the_target_which_rests_at_its_foot():
    scenario = paper_scenarios()["R"]
    flat = DOMAIN.layout_rules.infer(scenario)
    ramp = DOMAIN.layout_rules.infer(scenario, "ramp")
    concrete = {n.name: n.concrete for n in ramp.nodes}
    assert {n.name: n.concrete for n in flat.nodes}["surface"] == ("flatPlatform",)  # the pig rests on it
    assert concrete["surface"] == ("inclinedPlatform",) and concrete["support_pig"] == ("flatPlatform",)
    assert ("pig", "surface", ("right",)) in edges(flat, ON_LOCATION)
    assert ("pig", "support_pig", ("left",)) in edges(ramp, ON_LOCATION)  # at the foot, facing the ramp
    # cannotFall(rBlock): ledge, ramp and the pig's support make one continuous top edge.
    assert edges(ramp, TOUCHING) == {("support_rBlock", "surface", ("upperLeft",)), ("surface", "support_pig", ("upperLeft",))}


def test_a_goal_object_is_given_the_weakest_body_the_damage_rule_allows():
    scenario = paper_scenarios()["R"]
    assert next_act(scenario.interactions, "pig", 2) == "destroyed"
    pig = PlacedObject("pig", "object", "pigMedium", None, 0.0, 0.0, 0.0, 0.779, 0.756)
    options = {body.concrete: body for body in DOMAIN.search.bodies(pig, scenario)}
    assert set(options) == {"pigSmall", "pigMedium"}
    assert (toughness(options["pigSmall"], PHYQ), toughness(options["pigMedium"], PHYQ)) == (2.0, 16.0)  # life + defence
    assert worth("destroyed", 0.1, 0.7, 0.4, 2.0) > worth("destroyed", 0.4, 0.7, 0.4, 16.0)


def test_a_ramp_takes_the_angle_and_length_of_the_worlds_own_ramps():
    import random

    scenario = paper_scenarios()["R"]
    graph = DOMAIN.layout_rules.infer(scenario, "ramp")
    assert graph.ramps == ("surface",)
    assert (PHYQ.incline.ramp, PHYQ.incline.ramp_length) == ((12.7, 26.8), (5.4, 7.1))  # Phy-Q's 2_1_3, 2_1_6, 2_1_9
    for seed in range(20):
        ramp = DOMAIN.concretize(graph, scenario, random.Random(seed))["surface"].geometry
        assert 12.7 <= -ramp.rotation <= 26.8 and 5.4 <= ramp.width <= 7.1  # descending to the right, towards the pig
