"""Language version 2, a body's shape and material: the game's other bodies pinned by a
declaration, and the materials it may be made of; version-1 scenarios keep their meaning."""

from __future__ import annotations

import random

from physc.domains.angrybirds import DOMAIN
from physc.domains.words import INSTALLED
from physc.dsl.fmt import format_file
from physc.dsl.frontend import analyze_text, scenario_in
from physc.dsl.parser import parse_text
from physc.serialize import dumps

V2 = """scenario RectFall {
    objects {
        fBlock: fallableBlock(stone | ice) = rectFat
        pig: pig = pigBig
    }
    interactions {
        hit(bird, fBlock, left) > fall(fBlock, pig) > hit(fBlock, pig, above) > destroy(fBlock, pig)
    }
}
"""


def codes(text: str) -> list[str]:
    return [d.code for d in analyze_text("x.phys", text, INSTALLED).diagnostics]


def test_a_declaration_pins_another_body_of_the_game_and_names_its_materials():
    scenario = scenario_in("x.phys", V2, "RectFall", INSTALLED)
    block = next(o for o in scenario.objects if o.name == "fBlock")
    assert (block.concrete, block.materials) == (("rectFat",), ("stone", "ice"))
    assert next(o for o in scenario.objects if o.name == "pig").concrete == ("pigBig",)
    assert '"materials"' in dumps(scenario)


def test_the_formatter_prints_the_materials_and_reads_them_back():
    formatted = format_file(parse_text(V2).file, V2)
    assert "fBlock: fallableBlock(stone | ice) = rectFat" in formatted
    assert parse_text(formatted).file.scenarios[0].objects == parse_text(V2).file.scenarios[0].objects


def test_a_material_the_body_cannot_be_made_of_is_e0306():
    assert codes(V2.replace("(stone | ice)", "(glass)")) == ["E0306"]
    assert codes(V2.replace("pig: pig = pigBig", "pig: pig(stone) = pigBig")) == ["E0306"]


def test_a_body_left_open_never_becomes_one_only_a_declaration_may_pin():
    text = V2.replace("fBlock: fallableBlock(stone | ice) = rectFat\n", "").replace("pig: pig = pigBig\n", "")
    scenario = scenario_in("x.phys", text, "RectFall", INSTALLED)
    assert next(o for o in scenario.objects if o.name == "fBlock").concrete == ("circleSmall", "circle", "squareHole", "triangleHole")
    assert '"materials"' not in dumps(scenario)  # a version-1 scenario dumps as before
    assert codes(V2.replace("= rectFat", "= circle").replace("fallableBlock", "rollableBlock")) == []
    assert codes(V2.replace("fallableBlock(stone | ice) = rectFat", "rollableBlock = rectFat")) == ["E0303"]


def test_the_declared_materials_are_the_ones_laid_out():
    scenario = scenario_in("x.phys", V2, "RectFall", INSTALLED)
    graph = DOMAIN.layout_rules.infer(scenario)
    for seed in range(20):
        bodies = DOMAIN.concretize(graph, scenario, random.Random(seed))
        assert bodies["fBlock"].concrete == "rectFat" and bodies["fBlock"].material in ("stone", "ice")
        assert bodies["pig"].concrete == "pigBig"


BLAST = """scenario Blast {
    interactions {
        hit(bird, tnt, left) > explode(tnt) > destroy(tnt, pig)
    }
    restrictions {
        cannotHit(bird, pig, any)
    }
}
"""


def test_a_tnt_box_explodes_and_its_blast_destroys_the_pig():
    assert codes(BLAST) == []
    without = BLAST.replace(" > explode(tnt)", "")
    found = analyze_text("x.phys", without, INSTALLED).diagnostics
    assert [d.code for d in found] == ["E0403"] and "or 'explode(tnt)'" in found[0].message


def test_the_blast_s_target_is_laid_out_beside_the_tnt():
    scenario = scenario_in("x.phys", BLAST, "Blast", INSTALLED)
    graph = DOMAIN.layout_rules.infer(scenario)
    supports = {e.a: e.b for e in graph.edges if e.term == "onLocation"}
    assert supports["pig"] == supports["tnt"]


def test_a_tnt_box_destroyed_by_a_blow_is_recognised_as_explode():
    import numpy as np

    from physc.domains.angrybirds.worlds import PHYQ
    from physc.simulation.trace import DestructionRecord, Trace

    destructions = (DestructionRecord(1.0, "tnt", "damage", "bird"), DestructionRecord(1.0, "pig", "damage", "tnt"))
    trace = Trace(0.02, ("tnt", "pig"), {"tnt": "tnt", "pig": "pig"}, np.zeros((60, 2, 6)), destructions=destructions)
    found = [i.text() for i in PHYQ.recogniser.recognise(trace, {})]
    assert found == ["explode(tnt)", "destroy(bird, tnt)", "destroy(tnt, pig)"]


def test_a_blast_s_margin_is_its_damage_not_the_tnt_s_survival():
    import attrs
    import numpy as np

    from physc.domains.angrybirds.worlds import PHYQ
    from physc.simulation.trace import ContactRecord, DamageRecord, DestructionRecord, Trace

    scenario = scenario_in("x.phys", BLAST, "Blast", INSTALLED)
    names = ("bird", "tnt", "pig")
    contact = ContactRecord(0.98, "bird", "tnt", (1.0, 0.0), (1.0, 0.0), (5.0, 0.0), (5.0, 0.0), (0.0, 0.0))
    damage = (DamageRecord(0.98, "tnt", 5.0, -2.0, "bird"), DamageRecord(1.0, "pig", 34.0, -19.0, "tnt"))
    destructions = (DestructionRecord(1.0, "tnt", "damage", "bird"), DestructionRecord(1.0, "pig", "damage", "tnt"))
    states = np.zeros((60, 3, 6))
    states[:, 1, 0], states[:, 2, 0] = 1.2, 2.0
    trace = Trace(0.02, names, {"bird": "bird", "tnt": "tnt", "pig": "pig"}, states, (contact,), (), damage, destructions, ("pig",), True)
    trace = attrs.evolve(trace, interactions=PHYQ.recogniser.recognise(trace, {}))
    blast = next(m for m in DOMAIN.at("phyq").margins(scenario, trace).links if m.term == "destroy(tnt, pig)")
    assert (blast.unit, blast.value) == ("damage", 19.0)  # 34 dealt, 15 life: not the TNT's life, spent by design


def test_birds_taps_structures_and_contrasts_are_terms_of_the_language():
    text = """scenario S {
    objects {
        bird: bird = blueBird
        weak: fallableBlock = squareSmall
        top: fallableBlock(stone) = rectFat
        other: fallableBlock(stone) = rectFat
    }
    interactions {
        tap(bird) > hit(bird, weak, left) > fall(top, pig) > hit(top, pig, above) > destroy(top, pig)
    }
    restrictions {
        on(top, weak), contrast(other, top)
    }
}
"""
    assert codes(text) == []
    assert "E0402" in codes(text.replace("on(top, weak), ", ""))  # nothing set `top` moving
    assert "E0203" in codes(text.replace("tap(bird) >", "tap(weak) >"))  # only a bird is tapped
    formatted = format_file(parse_text(text).file, text)
    assert "tap(bird)" in formatted and "on(top, weak)" in formatted and "contrast(other, top)" in formatted


def test_the_meetover_relation_lets_a_plank_rest_on_a_narrower_post():
    from physc.compiler.qsr_evaluate import holds

    class Box:
        def __init__(self, x, y, width, height):
            self.x, self.y, self.width, self.height, self.rotation = x, y, width, height, 0.0

    post, plank = Box(0.0, 0.0, 0.2, 1.0), Box(0.05, 0.6, 1.0, 0.2)
    assert holds("MeetOver", plank, post, 0.1, 1.5) and not holds("MeetN", plank, post, 0.1, 1.5)
    assert not holds("MeetOver", Box(0.3, 0.6, 1.0, 0.2), post, 0.1, 1.5)  # its centre beyond the post
