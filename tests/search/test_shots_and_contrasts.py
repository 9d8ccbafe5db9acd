"""Language version 2 through the one search: several shots, taps, structures, contrasts."""

from __future__ import annotations

import csv
import io
import json

import pytest
from conftest import run_physc

from physc.domains.angrybirds import DOMAIN
from physc.domains.angrybirds.phyq_levels import benchmark_files
from physc.domains.angrybirds.shots import WAIT_SPAN, WAITS, birds, candidates, shot_starts, timed, waits
from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze_text
from physc.search.chain_stages import stages

TWO = """scenario TwoShots {
    objects { bird2: bird  pig2: pig }
    interactions { hit(bird, pig, left) > destroy(bird, pig) > hit(bird2, pig2, left) > destroy(bird2, pig2) }
}
"""
SPLIT = """scenario Split {
    objects { bird: bird = blueBird  pig2: pig }
    interactions { tap(bird) > hit(bird, pig, left) > destroy(bird, pig) > hit(bird, pig2, left) > destroy(bird, pig2) }
}
"""
TIMED = """scenario Timed {
    objects { bird2: bird  rBlock: rollableBlock  pig2: pig }
    interactions { hit(bird, rBlock, left) > roll(rBlock, surface, right) > hit(bird2, pig2, left) > destroy(bird2, pig2) > hit(rBlock, pig, left) > destroy(rBlock, pig) }
}
"""


def scenario(text):
    analysis = analyze_text("t.phys", text, INSTALLED)
    assert not [d for d in analysis.diagnostics if d.is_error], analysis.diagnostics
    return analysis.scenarios[0]


def test_each_bird_is_a_shot_in_the_order_the_sequence_names_them():
    ir = scenario(TWO)
    assert birds(ir, "bird") == ["bird", "bird2"] and shot_starts(ir, "bird") == (2,)
    assert DOMAIN.reach_targets(ir) == ["pig", "pig2"]
    timing = scenario(TIMED)
    assert timed(timing, 2, ["bird", "bird2"]) and not timed(ir, 2, ["bird", "bird2"])


def test_a_later_shot_starts_a_stage_and_a_tap_brings_in_what_follows_it():
    ir = scenario(TWO)
    plan = stages(ir.interactions, {"bird": 0, "bird2": 0, "pig": 0, "pig2": 2}, (2,))
    assert [(s.start, s.end) for s in plan] == [(0, 2), (2, 4)]
    from physc.search.chain_stages import introduced

    class Placed:
        def __init__(self, name, role, concrete):
            self.name, self.role, self.concrete = name, role, concrete

    class Layout:
        objects = [Placed("bird", "player", "blueBird"), Placed("pig", "object", "pigSmall"), Placed("pig2", "object", "pigSmall")]
        conjunction = ()

    entry = introduced(Layout(), scenario(SPLIT).interactions)
    assert entry["pig"] == 0 and entry["pig2"] == 3  # the tap's stage has the bird's target


def test_a_later_birds_candidates_extend_the_shots_before_and_a_timed_one_waits():
    from physc.domains.angrybirds.launch import Shot, Shots
    from physc.domains.angrybirds.level import Level, LevelObject

    level = Level(objects=(LevelObject("Pig", "BasicSmall", -4.0, -3.26, 0.0, name="pig"), LevelObject("Pig", "BasicSmall", -2.0, -3.26, 0.0, name="pig2"),
                           LevelObject("Circle", "Circle", -6.0, -3.1, 0.0, "wood", name="rBlock")))
    first = Shot(target=(-4.0, -3.26))
    later = candidates(DOMAIN, level, scenario(TWO), 2, first)
    assert later and all(isinstance(a, Shots) and a.shots[0] == first and a.shots[1].bird == "bird2" for _, a in later)
    assert all(label.startswith("bird2: pig2.") for label, _ in later)
    waited = candidates(DOMAIN, level, scenario(TIMED), 2, first)
    earliest = DOMAIN.world.rules.earliest_wait
    spread = {round(earliest + WAIT_SPAN * k / (WAITS - 1), 2) for k in range(WAITS)}
    assert {a.shots[1].wait for _, a in waited} == spread  # no play to go by: from the game's earliest on
    tapped = candidates(DOMAIN, level, scenario(SPLIT))
    assert tapped and all(a.tap is not None and a.tap > 0 for _, a in tapped)


def compiled(tmp_path, text: str, name: str):
    """(the task file's data, its path) of `text` compiled to `name`.xml and `name`.json."""
    source = tmp_path / f"{name}.phys"
    source.write_text(text)
    task = tmp_path / f"{name}.json"
    run = run_physc("compile", source, "-q", "--task", task, "-o", tmp_path / f"{name}.xml")
    assert run.status == 0, run.stderr
    return json.loads(task.read_text()), task


def test_two_shots_compile_to_a_level_of_two_birds_that_verify_replays(tmp_path):
    data, task = compiled(tmp_path, TWO, "two")
    shots = data["solution"]["shots"]
    assert data["solution"]["node"] == "ShotsSolution" and [s["bird"] for s in shots] == ["bird", "bird2"]
    assert all(len(s["agent_action"]) == 3 and s["agent_action"][2] == 0 for s in shots)
    assert (tmp_path / "two.xml").read_text().count('<Bird type="BirdRed" />') == 2
    verified = run_physc("verify", tmp_path / "two.xml", "--task", task)
    assert verified.status == 0 and "passes" in verified.stdout
    played = run_physc("simulate", tmp_path / "two.xml", "--task", task)  # the task's own shots, both
    assert played.status == 0 and "2 of 2 pigs destroyed: solved" in played.stdout and "by bird2" in played.stdout
    rows = list(csv.DictReader(io.StringIO(benchmark_files([({"scenario": "TwoShots", "seed": 0, "solution": data["solution"]}, (tmp_path / "two.xml").read_text())])["phyq/shots.csv"].decode())))
    assert [r["shot"] for r in rows] == ["1", "2"] and [int(r["dx"]) for r in rows] == [s["agent_action"][0] for s in shots]


def test_a_tapped_blue_bird_is_recorded_with_its_tap_in_milliseconds(tmp_path):
    data, _ = compiled(tmp_path, SPLIT, "split")
    (shot,) = data["solution"]["shots"]
    assert shot["tap"] > 0 and shot["agent_action"][2] == round(shot["tap"] * 1000)
    terms = iter(data["trace"].split(" > "))
    assert next(terms) == "tap(bird)"  # the tap is read first, then the declared links in order
    assert all(t in terms for t in ("hit(bird, pig, left)", "destroy(bird, pig)", "hit(bird, pig2, left)", "destroy(bird, pig2)")), data["trace"]
    assert '<Bird type="BirdBlue" />' in (tmp_path / "split.xml").read_text()


CONTRAST = """scenario Weight {
    objects { rBlock: rollableBlock(stone) = circleSmall  heavy: rollableBlock(stone) = circle }
    interactions { hit(bird, rBlock, left) > roll(rBlock, surface, right) > hit(rBlock, pig, left) > destroy(rBlock, pig) }
    restrictions { cannotHit(bird, pig, any), contrast(heavy, rBlock) }
}
"""
STRUCTURE = """scenario Stack {
    objects { weak: fallableBlock(ice) = squareSmall  top: fallableBlock(stone) = rectFat }
    interactions { hit(bird, weak, left) > fall(top, pig) > hit(top, pig, above) > destroy(top, pig) }
    restrictions { on(top, weak) }
}
"""


def test_a_contrast_rests_as_its_counterpart_and_a_structure_stacks(tmp_path):
    source = tmp_path / "c.phys"
    source.write_text(CONTRAST + STRUCTURE)
    def edges(name):
        out = run_physc("compile", source, "--scenario", name, "--emit", "layout-graph")
        assert out.status == 0, out.stderr
        return {(e["term"], e["a"], e["b"], tuple(e["values"])) for e in json.loads(out.stdout)["edges"]}

    assert ("onLocation", "heavy", "support_rBlock", ("left", "centre", "right")) in edges("Weight")
    assert ("onLocation", "top", "weak", ("over",)) in edges("Stack")


def test_a_contrast_is_checked_by_aiming_the_shot_at_it():
    from physc.domains.angrybirds.launch import Shot
    from physc.domains.angrybirds.level import Level, LevelObject

    a = LevelObject("Block", "CircleSmall", -4.0, -3.29, 0.0, "stone", name="rBlock")
    b = LevelObject("Block", "Circle", -6.0, -3.125, 0.0, "stone", name="heavy")
    shot = Shot(target=(-4.0 - 0.21, -3.29), trajectory="low")
    aimed = DOMAIN.actions.contrasted(Level(objects=(a, b)), shot, "rBlock", "heavy")
    assert aimed.target[0] == -6.0 - 0.375 and aimed.target[1] == -3.125 and aimed.trajectory == "low"
    assert DOMAIN.actions.contrasted(Level(objects=(a, b)), Shot(target=(3.0, 0.0)), "rBlock", "heavy") is None


def test_a_later_bird_is_aimed_where_the_shots_before_left_its_target():
    from physc.domains.angrybirds.launch import Shot
    from physc.domains.angrybirds.level import Level, LevelObject
    from physc.domains.angrybirds.shots import where_left

    pig = LevelObject("Pig", "BasicSmall", -6.0, -3.26, 0.0, name="pig")
    pig2 = LevelObject("Pig", "BasicBig", -3.0, -3.03, 0.0, name="pig2")
    level = Level(objects=(pig, pig2), birds=("BirdRed", "BirdRed"))
    first = Shot(target=(pig.x, pig.y))
    trace = DOMAIN.play(level, first, None)
    moved = where_left(level, trace)
    assert "pig" not in {o.name for o in moved.objects}  # destroyed by the first shot
    (left,) = [o for o in moved.objects if o.name == "pig2"]
    later = DOMAIN.actions.candidates(level, scenario(TWO), 2, first, trace)
    centre = next(a.shots[1].target for label, a in later if label.endswith("pig2.c, low"))
    assert centre == (round(left.x, 5), round(left.y, 5))


def test_a_timed_shots_waits_span_the_time_the_play_before_still_moves():
    """From the game's earliest release (1.2 s: HUD.cs drags 1 s once the bird is on the
    slingshot) to the latest whose bird gets to its target before the play comes to rest."""
    from types import SimpleNamespace

    from physc.domains.angrybirds.launch import Shot

    world = DOMAIN.world
    assert world.rules.earliest_wait == pytest.approx(1.2)
    shot = Shot(target=(0.0, -3.0), bird="bird2")
    (x, _), (vx, _) = shot.start(world)
    flight = (0.0 - x) / vx
    struck = SimpleNamespace(time=1.0, a="bird", b="pig")
    long = waits(world, shot, "bird", SimpleNamespace(contacts=(struck,), duration=9.0))
    assert len(long) == WAITS and long[0] == pytest.approx(1.2)
    assert long[-1] == pytest.approx(9.0 - 1.0 - flight, abs=0.01)  # arrives as the play comes to rest
    short = waits(world, shot, "bird", SimpleNamespace(contacts=(struck,), duration=2.5))
    assert short == (1.2,)  # rests too soon for any later wait: the earliest alone


def test_a_cannot_hit_of_what_a_later_bird_hits_is_judged_not_guarded():
    """A first bird that must not hit the pig a second bird then destroys (clearing a path): a bar
    against the first bird's direct shots would bar the second's, so no obstacle is asked for."""
    from types import SimpleNamespace

    from physc.search import guards

    clear = scenario("""scenario Clear {
    objects { bird2: bird  fBlock: fallableBlock }
    interactions { hit(bird, fBlock, left) > fall(fBlock, ground) > hit(bird2, pig, left) > destroy(bird2, pig) }
    restrictions { cannotHit(bird, pig, any), cannotHit(bird, fBlock, above) }
}
""")
    problem = SimpleNamespace(players=frozenset({"bird", "bird2"}), interactions=clear.interactions)
    pig, block = clear.restrictions
    assert guards.struck_later(problem, pig) and not guards.struck_later(problem, block)


CLEARING = """scenario Clearing {
    objects { pig: pig = pigSmall  bird2: bird  fBlock: fallableBlock(stone) = rectFat }
    interactions { hit(bird, fBlock, left) > fall(fBlock, ground) > hit(bird2, pig, left) > destroy(bird2, pig) }
    restrictions { blocks(fBlock, pig) }
}
"""


def test_two_birds_at_the_slingshot_leave_a_layouts_objects_free_to_move():
    """The player's objects start in turn from one place: their overlap is no conflict of the
    layout's, which once refused every object the search moved in a scenario of two birds."""
    from middle_end import searching

    from physc.driver.pipeline import Pipeline
    from physc.search import placing

    ir = scenario(CLEARING)
    layout = Pipeline(DOMAIN, ir, 0).placed.layout
    players = [o for o in layout.objects if o.role == "player"]
    assert len(players) == 2 and placing.box(players[0]) == placing.box(players[1])
    parameters = searching(DOMAIN, ir, layout).problem.parameters
    assert placing.consistent(layout, parameters, {"fBlock"})


def test_what_a_block_bars_the_way_to_is_offered_behind_it():
    """blocks(fBlock, pig): the pig's structure, level with the block, beyond it as the birds come."""
    from middle_end import searching

    from physc.driver.pipeline import Pipeline
    from physc.search import placing
    from physc.search.variants import behind

    ir = scenario(CLEARING)
    for seed in range(6):  # a layout whose pig has a support of its own to move with
        layout = Pipeline(DOMAIN, ir, seed).placed.layout
        s = searching(DOMAIN, ir, layout, seed)
        offered = list(behind(s.problem, layout, next(st for st in s.plan if "pig" in st.new)))
        if offered:
            break
    assert offered, "some seed's pig stands on a support"
    note, moved = offered[0]
    objects = {o.name: o for o in moved.objects}
    _, block_bottom, block_right, _ = placing.box(objects["fBlock"])
    pig_left, pig_bottom, _, _ = placing.box(objects["pig"])
    assert note.startswith("pig behind fBlock") and abs(pig_bottom - block_bottom) < 1e-4 and pig_left > block_right
