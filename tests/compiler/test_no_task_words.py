"""Exit 3 (E0802) in words a reader takes right, and another world named only where it concerns
the scenario (issue 73): the weakest link is the one that failed, or the one that came closest to
failing, never a "weakest" link with a positive "best margin"; a world is tried and proposed only
where it differs from the scenario's in a kind of link the scenario has (World.concerns)."""

from __future__ import annotations

import attrs
from middle_end import DOMAIN, paper_scenarios

from physc.api.simulating import playable
from physc.compiler.infeasible import Exhausted, Infeasible
from physc.domains.angrybirds.worlds import PHYQ, ROLLING, WORLDS
from physc.driver import layout_loop
from physc.driver.layout_loop import LayoutLoop, Tally, concerned, elsewhere_text
from physc.driver.run_settings import RunSettings
from physc.search.elsewhere import Elsewhere
from physc.simulation.margin import Margin
from physc.worlds import differing_kinds

PAPER = paper_scenarios()
HELD = Margin.life("fall(fBlock, ground)", 1, value=25.1, scale=10.0, what="the life it had left")
FAILED = Margin.distance("fall(fBlock, ground)", 1, value=-0.4, scale=1.0, what="height beyond a fall's", held=False)


def test_a_link_that_held_came_closest_to_failing_and_one_that_failed_failed_by_its_margin():
    assert HELD.named_weakest("at best") == (
        "the link that came closest to failing was `fall(fBlock, ground)`: +25.1 life to spare at best"
        " (the life it had left)"
    )
    assert FAILED.named_weakest("at best") == (
        "the weakest link was `fall(fBlock, ground)`: it failed by 0.4 units at best (height beyond a fall's)"
    )
    unmeasured = Margin.failed("roll(ball, ramp)", 0, what="not realised")
    assert unmeasured.named_weakest() == "the weakest link was `roll(ball, ramp)`: it failed (not realised)"


def explained(weakest, other=None) -> str:
    scenario = PAPER["F"]
    loop = LayoutLoop(DOMAIN, scenario, None, RunSettings(time_budget=10.0, layouts=1, validate=False))  # type: ignore[arg-type]
    tally = Tally(best=len(scenario.interactions), weakest=weakest)
    failure = Infeasible("satisfy", "no task", budget=Exhausted.TIME)
    return loop.explained(failure, tally, other).message


def test_exit_3_names_the_strongest_weakest_link_in_words_that_match_its_sign():
    held = explained(HELD)
    assert "the link that came closest to failing was `fall(fBlock, ground)`: +25.1 life to spare at best" in held
    assert "weakest" not in held and "best margin" not in held
    failed = explained(FAILED)
    assert "the weakest link was `fall(fBlock, ground)`: it failed by 0.4 units at best" in failed
    assert "best margin" not in failed


def test_exit_3_names_the_property_that_gave_a_layout_up_and_what_broke_it():
    from physc.search.outcome import Outcome

    scenario = PAPER["F"]
    loop = LayoutLoop(DOMAIN, scenario, None, RunSettings(time_budget=10.0, layouts=1, validate=False))  # type: ignore[arg-type]
    tally = Tally(best=len(scenario.interactions))
    note = "nonGreedy(pig, pig2): once pig2 is taken first (bird: pig2.c, low), bird2: pig.c, low takes pig"
    tally.give_up(Outcome(False, 10, given_up="a property broke", broken=note), None, 6)  # type: ignore[arg-type]
    tally.give_up(Outcome(False, 10, given_up="a property broke", broken="timed(bird2): …"), None, 6)  # type: ignore[arg-type]
    message = loop.explained(Infeasible("satisfy", "no task", budget=Exhausted.TIME), tally).message
    assert f"the first layout given up for a declared property: {note}" in message and "timed" not in message


def test_the_world_named_elsewhere_has_its_weakest_link_worded_so_too():
    other = Elsewhere("rolling", 4, 4, Margin.angle("hit(bird2, pig, left)", 2, value=33.6, what="from another side"))
    text = elsewhere_text(other)
    assert text == (
        "in the world 'rolling', the best layout, replayed, realises 4 of the 4 interactions; the link that came"
        " closest to failing was `hit(bird2, pig, left)`: +33.6 degrees to spare (from another side):"
        " --world rolling may carry this scenario (physc worlds describes it)"
    )
    assert text in explained(FAILED, other)


def test_a_world_declares_the_kinds_of_link_its_changes_concern_and_worlds_differ_in_those():
    assert ROLLING.concerns == ("roll", "slide", "bounce") and PHYQ.concerns == ()
    assert (
        differing_kinds(PHYQ, ROLLING, WORLDS) == differing_kinds(ROLLING, PHYQ, WORLDS) == {"roll", "slide", "bounce"}
    )
    names = {term.name for scenario in PAPER.values() for term in scenario.interactions}
    assert set(ROLLING.concerns) <= names  # kinds of link the language has
    silent = PHYQ.derive("other", "a variant that says nothing of what it changes", "a test", gravity=5.0)
    assert silent.concerns == () and differing_kinds(PHYQ, silent, (PHYQ, silent)) is None  # any kind
    again = ROLLING.derive("again", "a variant of a variant", "a test", concerns=("fall",), gravity=5.0)
    assert differing_kinds(PHYQ, again, (*WORLDS, again)) == {"roll", "slide", "bounce", "fall"}
    assert differing_kinds(ROLLING, again, (*WORLDS, again)) == {"fall"}
    stranger = attrs.evolve(PHYQ, name="stranger")  # no ancestor shared with rolling
    assert differing_kinds(stranger, ROLLING, (stranger, ROLLING)) is None


def test_exit_3_tries_another_world_only_for_a_scenario_with_a_link_it_concerns(monkeypatch):
    """F (fall) in phyq: rolling is neither tried nor kept time for; R (roll): it is."""
    phyq = playable(DOMAIN.at("phyq"))
    assert [w.name for w in concerned(phyq, PAPER["F"]).worlds] == ["phyq"]
    assert [w.name for w in concerned(phyq, PAPER["SF"]).worlds] == ["phyq"]
    assert concerned(phyq, PAPER["R"]) is phyq and concerned(phyq, PAPER["B"]) is phyq
    assert [w.name for w in concerned(playable(DOMAIN.at("rolling")), PAPER["F"]).worlds] == ["rolling"]
    assert [w.name for w in phyq.worlds] == ["phyq", "rolling"]  # the domain itself is left as it is

    tried = []

    def fake_elsewhere(domain, scenario, *args):
        tried.append([w.name for w in domain.worlds])
        return Elsewhere("rolling", 1, 1, None) if len(domain.worlds) > 1 else None

    monkeypatch.setattr(layout_loop.elsewhere, "elsewhere", fake_elsewhere)
    monkeypatch.setattr(LayoutLoop, "_search", lambda self, placements, tally, started: Infeasible("satisfy", "none"))
    messages = {}
    for name in ("F", "R"):
        loop = LayoutLoop(phyq, PAPER[name], None, RunSettings(time_budget=10.0, layouts=1, validate=False))  # type: ignore[arg-type]
        try:
            loop.run(iter(()))
        except Infeasible as error:
            messages[name] = error.message
    assert tried == [["phyq"], ["phyq", "rolling"]]
    assert "--world rolling" not in messages["F"] and "--world rolling may carry this scenario" in messages["R"]


def test_exit_3_says_where_the_simulations_went():
    from physc.search.funnel import Passage

    scenario = PAPER["F"]
    loop = LayoutLoop(DOMAIN, scenario, None, RunSettings(time_budget=10.0, layouts=1, validate=False))  # type: ignore[arg-type]
    tally = Tally(best=1)
    tally.funnel.add(Passage(reached={(0, 1)}, spent={(0, 1): 12}), 12, False, "the sequence was not realised")
    message = loop.explained(Infeasible("satisfy", "no task", budget=Exhausted.TIME), tally).message
    assert "; where the simulations went: of 1 placed layout, stage 1 (`hit(bird, fBlock, left | above)`) realised in 0 of 1" in message
