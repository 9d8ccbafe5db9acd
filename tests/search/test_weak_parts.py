"""What the raising of margins moves for a weak link (coordinates.weak_parts)."""

from types import SimpleNamespace

from middle_end import paper_scenarios

from physc.search.coordinates import weak_parts
from physc.simulation.margins import Margin


def problem(name):
    scenario = paper_scenarios()[name]
    return SimpleNamespace(scenario=scenario, interactions=scenario.interactions)


def margin(term, index):
    return Margin(term, index, -0.4, "damage", 1.0, "the blow")


def test_a_weak_destroy_moves_what_struck_its_actor_too():
    # R: hit(bird, rBlock) > roll(rBlock, surface) > hit(rBlock, pig) > destroy(rBlock, pig):
    # the destroy's blow is as strong as rBlock's speed, which the bird's hit set.
    r = problem("R")
    names, pairs = weak_parts(r, margin("destroy(rBlock, pig)", 3))
    assert names == {"bird", "rBlock", "pig"}
    assert pairs == [("bird", "rBlock"), ("rBlock", "pig")]  # the gap it rolls across slows it


def test_a_weak_first_hit_moves_its_own_objects_and_the_next_links():
    r = problem("R")
    names, pairs = weak_parts(r, margin("hit(bird, rBlock, left)", 0))
    assert names == {"bird", "rBlock", "surface"}
    assert pairs == [("bird", "rBlock")]


def test_a_restriction_moves_its_objects_and_what_its_first_rolls_on():
    scenario = paper_scenarios()["R"]
    fake = SimpleNamespace(
        scenario=SimpleNamespace(restrictions=[SimpleNamespace(text="cannotFall(rBlock)", objects=("rBlock",))]),
        interactions=scenario.interactions,
    )
    names, pairs = weak_parts(fake, Margin("cannotFall(rBlock)", None, -1.0, "u", 1.0, "w"))
    assert names == {"rBlock", "surface"} and pairs == []
