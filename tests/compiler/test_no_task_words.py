"""Exit 3 (E0802) in words a reader takes right, and another world named only where it concerns
the scenario (issue 73): the weakest link is the one that failed, or the one that came closest to
failing, never a "weakest" link with a positive "best margin"; a world is tried and proposed only
where it differs from the scenario's in a kind of link the scenario has (World.concerns)."""

from __future__ import annotations

from middle_end import DOMAIN, paper_scenarios

from physc.compiler.infeasible import Exhausted, Infeasible
from physc.driver.layout_loop import LayoutLoop, Tally, elsewhere_text
from physc.driver.run_settings import RunSettings
from physc.search.elsewhere import Elsewhere
from physc.simulation.margin import Margin

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


def test_the_world_named_elsewhere_has_its_weakest_link_worded_so_too():
    other = Elsewhere("rolling", 4, 4, Margin.angle("hit(bird2, pig, left)", 2, value=33.6, what="from another side"))
    text = elsewhere_text(other)
    assert text == (
        "in the world 'rolling', the best layout, replayed, realises 4 of the 4 interactions; the link that came"
        " closest to failing was `hit(bird2, pig, left)`: +33.6 degrees to spare (from another side):"
        " --world rolling may carry this scenario (physc worlds describes it)"
    )
    assert text in explained(FAILED, other)
