"""Language version 2's properties (nonGreedy, blocks, timed): what must fail, checked against
every shot the player could send (physc.search.properties, angrybirds' sweeps.py)."""

from __future__ import annotations

from types import SimpleNamespace

import attrs

from physc.domains.angrybirds import DOMAIN
from physc.domains.angrybirds.launch import Shot, Shots
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.sweeps import SWEEP_RANGE, SWEEP_STEP, retimed, sweep_angles, timing
from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze_text
from physc.search import properties, settings
from physc.search.attempt import Attempt
from physc.search.problem import Ledger

TWO = """scenario TwoShots {
    objects { bird2: bird  pig2: pig }
    interactions { hit(bird, pig, left) > destroy(bird, pig) > hit(bird2, pig2, left) > destroy(bird2, pig2) }
    restrictions { nonGreedy(pig, pig2), timed(bird2) }
}
"""
PIG = LevelObject("Pig", "BasicSmall", 6.0, -3.26, 0.0, name="pig")
PIG2 = LevelObject("Pig", "BasicSmall", 2.0, -3.26, 0.0, name="pig2")
SHELTER = (  # platforms on either side of the pig and over it: no shot reaches it
    LevelObject("Platform", "Platform", 5.2, -2.6, 0.0, scale_x=0.5, scale_y=4.0, name="w1"),
    LevelObject("Platform", "Platform", 6.8, -2.6, 0.0, scale_x=0.5, scale_y=4.0, name="w2"),
    LevelObject("Platform", "Platform", 6.0, -1.6, 0.0, scale_x=4.0, scale_y=0.5, name="roof"),
)


def scenario(text: str = TWO):
    analysis = analyze_text("t.phys", text, INSTALLED)
    assert not [d for d in analysis.diagnostics if d.is_error], analysis.diagnostics
    return analysis.scenarios[0]


def problem(ir):
    """What the property checks read of a search's Problem: the domain, the scenario, a play's seconds."""
    return SimpleNamespace(domain=DOMAIN, scenario=ir, seconds=DOMAIN.search.seconds or DOMAIN.seconds)


def test_a_sweep_covers_every_release_angle_the_agents_send_coarse_first():
    angles = sweep_angles()
    assert len(angles) == len(set(angles)) == int((SWEEP_RANGE[1] - SWEEP_RANGE[0]) / SWEEP_STEP)
    assert min(angles) == SWEEP_RANGE[0] and max(angles) == SWEEP_RANGE[1] - SWEEP_STEP
    assert all(abs((a - SWEEP_RANGE[0]) % 8.0) < 1e-9 for a in angles[:23])  # every 16 steps first
    assert angles[23] not in angles[:23] and abs((angles[23] - SWEEP_RANGE[0]) % 4.0) < 1e-9


def test_the_next_birds_sweep_starts_with_its_candidates_and_extends_the_shots_before():
    level = Level(objects=(PIG, PIG2), birds=("BirdRed", "BirdRed"))
    first = DOMAIN.actions.sweep(level, scenario(), at="pig")
    assert first[0][0].startswith("bird: pig.") and isinstance(first[0][1], Shot)
    assert first[-1][1] == Shot(angle=first[-1][1].angle, bird="bird")
    before = Shot(angle=20.0)
    later = DOMAIN.actions.sweep(level, scenario(), before=before, at="pig2")
    assert all(isinstance(a, Shots) and a.shots[0] == before and a.shots[1].bird == "bird2" for _, a in later)
    assert DOMAIN.actions.sweep(level, scenario(), before=Shots((before, Shot(angle=1.0, bird="bird2")))) == []


def test_a_timed_shot_is_retimed_and_a_first_shot_cannot_be():
    action = Shots((Shot(angle=20.0), Shot(angle=30.0, bird="bird2", wait=1.0)))
    assert timing(action, "bird2") == 1.0 and timing(action, "bird") is None
    assert retimed(action, "bird2", None).shots[1].wait is None
    assert retimed(action, "bird2", 2.5).shots[1].wait == 2.5
    assert retimed(action, "bird", 2.0) is None


def test_blocks_holds_of_a_sheltered_pig_and_not_of_one_in_the_open():
    ir = scenario()
    sheltered = Level(objects=(PIG, *SHELTER), birds=("BirdRed", "BirdRed"))
    ledger = Ledger()
    swept = DOMAIN.actions.sweep(sheltered, ir, at="pig")
    assert properties.first_taking(problem(ir), ledger, sheltered, swept, "pig") is None
    assert ledger.simulations >= len(swept)  # every shot played (in each reading that changes it)
    open_level = Level(objects=(PIG,), birds=("BirdRed", "BirdRed"))
    found = properties.first_taking(problem(ir), Ledger(), open_level, DOMAIN.actions.sweep(open_level, ir, at="pig"), "pig")
    assert found is not None and found[0].startswith("bird: pig.")


def test_non_greedy_fails_where_the_later_pig_can_be_taken_first_and_the_other_after():
    ir = scenario()
    level = Level(objects=(PIG, PIG2), birds=("BirdRed", "BirdRed"))
    term = next(t for t in ir.restrictions if t.name == "nonGreedy")
    why, note = properties.non_greedy(problem(ir), Ledger(), level, term)
    assert why == settings.PROPERTY_BROKEN and "once pig2 is taken first" in note and "takes pig" in note


def test_non_greedy_holds_where_the_later_pig_cannot_be_taken_first():
    ir = scenario()
    sheltered = attrs.evolve(PIG, name="pig2")  # the later pig in the shelter, the first in the open
    level = Level(objects=(attrs.evolve(PIG2, name="pig"), sheltered, *SHELTER), birds=("BirdRed", "BirdRed"))
    term = next(t for t in ir.restrictions if t.name == "nonGreedy")
    why, note = properties.non_greedy(problem(ir), Ledger(), level, term)
    assert why is None and note == "no first action takes pig2 and spares pig", note


def test_timed_fails_where_the_shot_also_solves_once_the_level_rests():
    ir = scenario()
    level = Level(objects=(PIG, PIG2), birds=("BirdRed", "BirdRed"))
    trace = DOMAIN.play(level, Shot(target=(PIG.x, PIG.y)), None)
    assert "pig" in trace.destroyed
    later = DOMAIN.actions.candidates(level, ir, 2, Shot(target=(PIG.x, PIG.y)), trace)
    action = next(a for label, a in later if "pig2.c, low" in label)
    solution = Attempt("", action, trace, None)
    term = next(t for t in ir.restrictions if t.name == "timed")
    why, note = properties.timed(problem(ir), Ledger(), level, solution, term)
    assert why == settings.PROPERTY_BROKEN and "once the level rests solves the task too" in note, note


def test_a_later_shot_keeps_a_goal_in_its_stage_so_the_game_goes_on_to_it():
    from physc.search.problem import goals_kept

    text = """scenario DirectThenFall {
    objects { pig2: pig  bird2: bird  fBlock: fallableBlock }
    interactions { hit(bird, pig, left) > destroy(bird, pig) > hit(bird2, fBlock, left) > fall(fBlock, pig2) > hit(fBlock, pig2, above) > destroy(fBlock, pig2) }
}
"""
    ir = scenario(text)
    entry = {"bird": 0, "bird2": 0, "pig": 0, "fBlock": 2, "pig2": 3}
    assert goals_kept(entry, ir, (2,), "pig")["pig2"] == 2  # else the first shot ends the game: no pig left
    assert goals_kept(entry, ir, (), "pig") == entry
    two = scenario(TWO)
    kept = {"bird": 0, "bird2": 0, "pig": 0, "pig2": 2}
    assert goals_kept(kept, two, (2,), "pig") == kept  # pig2 enters as bird2's shot starts already
