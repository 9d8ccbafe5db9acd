"""infer-layout: the layout graphs of the paper's scenarios (golden dumps: test_golden_stages.py)."""

from __future__ import annotations

import pytest
from middle_end import DOMAIN, pipeline, scenario_from_text

from physc.driver.pipeline import Pipeline


def edges(name):
    return {e.text() for e in pipeline(name).layout_graph.edges}


def test_sliding_scenario_structure():
    graph = pipeline("S").layout_graph
    assert [n.name for n in graph.nodes if n.role == "support"] == ["support_sBlock"]
    assert {
        "inDirection(sBlock, bird, right)",
        "inDirection(sBlock, hSurface, left)",
        "inDirection(pig, sBlock, right)",
        "pathObstructed(bird, pig, all)",
        "onLocation(sBlock, support_sBlock, right)",
        "onLocation(pig, hSurface, right)",
        "touching(support_sBlock, hSurface, upperLeft)",
    } <= edges("S")


def test_provenance_points_at_the_source():
    graph = pipeline("RS").layout_graph
    roll = next(e for e in graph.edges if e.text() == "inDirection(rBlock, surface, left)")
    (why,) = roll.provenance
    assert why.rule == "interaction" and why.text == "roll(rBlock, surface, right)"
    assert why.span.line == 19  # all.paper.phys, scenario RS
    chain = next(e for e in graph.edges if e.text() == "touching(surface, hSurface, upperLeft)")
    assert chain.provenance[0].text == "cannotFall(sBlock)"


def test_every_dynamic_object_gets_a_support():
    for name in ("SF", "R", "F", "RRR", "SFR", "BF"):
        graph = pipeline(name).layout_graph
        supported = {e.a for e in graph.edges if e.term == "onLocation"}
        dynamic = {n.name for n in graph.nodes if not n.static and n.role == "object"}
        assert dynamic <= supported, name


def test_surfaces_things_rest_on_become_flat():
    graph = pipeline("R").layout_graph
    assert graph.node("surface").concrete == ("flatPlatform",)
    assert pipeline("B").layout_graph.node("iSurface").concrete == ("inclinedPlatform",)


def test_redundant_edges_are_merged():
    graph = pipeline("BF").layout_graph
    bird_surface = [e for e in graph.edges if {e.a, e.b} == {"bird", "iSurface"} and e.term == "inDirection"]
    assert len(bird_surface) == 1
    assert bird_surface[0].values == ("below",)
    assert [p.text for p in bird_surface[0].provenance] == ["bounce(bird, iSurface, below)", "hit(bird, iSurface, any)"]


def test_an_object_knocked_off_from_one_side_falls_ahead():
    # hit(rBlock, fBlock, left) pushes fBlock right: it starts above the pig or up to its left.
    assert "locatedFar(fBlock, pig, aboveLeft)" in edges("RF")
    assert "locatedFar(fBlock, pig, aboveLeft)" in edges("RRF")
    # The bird flies right from the slingshot: its hit, from the left or above, pushes right too,
    # and the block waits at the right edge of its support.
    assert {"locatedFar(fBlock, pig, aboveLeft)", "onLocation(fBlock, support_fBlock, right)"} <= edges("F")
    assert {"locatedFar(fBlock, rBlock, aboveLeft)", "onLocation(fBlock, support_fBlock, right)"} <= edges("FR")
    # After a bounce it may fly either way: the block may be knocked off either way.
    assert {"locatedFar(fBlock, pig, above)", "onLocation(fBlock, support_fBlock, right | left)"} <= edges("BF")


def test_falling_ahead_keeps_the_straight_drop_and_the_near_side():
    from physc.compiler.to_qsr import relations_for

    assert set(relations_for("locatedFar", ("aboveLeft",))) == {"FarN", "FarNW"}
    assert set(relations_for("locatedFar", ("aboveRight",))) == {"FarN", "FarNE"}


SHARED = """
scenario Shared {{
    objects {{ shelf: {term} }}
    interactions {{
        hit(bird, {a}, left) > {move}({a}, shelf, right) > hit({a}, {b}, left)
        > {move}({b}, shelf, right) > hit({b}, pig, left) > destroy({b}, pig)
    }}
}}
"""


@pytest.mark.parametrize(
    "term, a, b, move", [("horizontalSurface", "sBlock1", "sBlock2", "slide"), ("surface", "rBlock1", "rBlock2", "roll")]
)
def test_bodies_moving_in_turn_along_one_surface_are_consistent(term, a, b, move):
    # The second body rests on the shelf the first comes along, in its middle, and starts its
    # own motion there: no inDirection(b, shelf, left) against its onLocation (was E0801).
    scenario = scenario_from_text(SHARED.format(term=term, a=a, b=b, move=move))
    run = Pipeline(DOMAIN, scenario, 0)
    texts = {e.text() for e in run.layout_graph.edges}
    assert f"onLocation({b}, shelf, centre)" in texts
    assert f"inDirection({b}, shelf, left)" not in texts
    assert f"inDirection({a}, shelf, left)" in texts  # the first starts beside it, on its own support
    layout = run.placed.layout
    objects = {o.name: o for o in layout.objects}
    assert objects[a].x < objects[b].x < objects["pig"].x


GLANCING = """
scenario Glancing {
    objects { ledge: horizontalSurface }
    interactions {
        hit(bird, ledge, any) > bounce(bird, ledge, right) > hit(bird, pig, left) > destroy(bird, pig)
    }
}
"""


def test_a_bounce_means_where_the_object_goes_in_the_layout_as_in_the_recogniser():
    """`bounce(a, b, d)`: a leaves b heading d (docs/language.md; the recogniser reads the
    heading after the bounce). Heading right off a ledge, the bird came from the left and
    glanced off it, or from the right and was thrown back: the layout allows both, and the
    bird, shot from the left, is laid out (this was E0801, 486 conjunctions inconsistent)."""
    from physc.compiler.layout_rules import bounced_from

    assert bounced_from(("right",)) == ("right", "left") and bounced_from(("below",)) == ("below",)
    run = Pipeline(DOMAIN, scenario_from_text(GLANCING), 0)
    texts = {e.text() for e in run.layout_graph.edges}
    assert "inDirection(bird, ledge, right | left)" in texts or "inDirection(bird, ledge, left | right)" in texts, texts
    objects = {o.name: o for o in run.placed.layout.objects}
    assert objects["bird"].x < objects["ledge"].x < objects["pig"].x
