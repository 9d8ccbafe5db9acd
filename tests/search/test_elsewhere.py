"""The best play of a run that gave no task, replayed in the domain's other worlds (physc.search.elsewhere)."""

from types import SimpleNamespace

from middle_end import paper_scenarios

from physc.api.compiling import BUDGET_HELP
from physc.compiler.infeasible import Exhausted
from physc.search import elsewhere
from physc.simulation.margins import Margin

R = paper_scenarios()["R"]


class World(SimpleNamespace):
    pass


class Domain:
    """Two worlds: in `here` the play realises `here_matched` links, in `there` all of them."""

    def __init__(self, name="here", matched=None, weakest=None):
        self.worlds = [World(name="here"), World(name="there")]
        self.world = World(name=name)
        self.matched = matched or {"here": 2, "there": 4}
        self.weakest = weakest or {}

    def at(self, name):
        return Domain(name, self.matched, self.weakest)

    def play(self, level, action, scenario, seconds=None):
        return SimpleNamespace(matched=self.matched[self.world.name])

    seconds = 10.0
    search = SimpleNamespace(seconds=9.0)  # the search's plays (physc.search.problem.search_seconds)
    actions = SimpleNamespace(candidates=lambda level, scenario: [])
    capabilities = frozenset()

    def margins(self, scenario, trace):
        return SimpleNamespace(weakest=self.weakest.get(self.world.name))


def fake_fidelity(scenario, trace):
    total = len(scenario.interactions)
    return SimpleNamespace(matched=trace.matched, valid=trace.matched == total)


def test_a_world_that_gets_further_is_named(monkeypatch):
    monkeypatch.setattr(elsewhere, "fidelity", fake_fidelity)
    found = elsewhere.elsewhere(Domain(), R, [(0.5, "level", "shot", None)], best=2, weakest=None)
    assert found is not None and found.world == "there" and found.matched == 4
    from physc.driver.layout_loop import elsewhere_text

    text = elsewhere_text(found)  # the words exit 3 uses
    assert "--world there" in text and "in the world 'there', the best layout, replayed, realises 4 of the 4 interactions" in text


def test_a_world_no_better_is_not_named(monkeypatch):
    monkeypatch.setattr(elsewhere, "fidelity", fake_fidelity)
    assert elsewhere.elsewhere(Domain(matched={"here": 4, "there": 3}), R, [(1.0, "level", "shot", None)], best=4, weakest=None) is None
    assert elsewhere.elsewhere(Domain(), R, [], best=0, weakest=None) is None


def test_a_whole_chain_counts_elsewhere_only_with_a_stronger_weakest_link(monkeypatch):
    monkeypatch.setattr(elsewhere, "fidelity", fake_fidelity)
    weak = Margin("destroy(rBlock, pig)", 3, -0.4, "damage", 1.0, "the blow", held=False)
    held = Margin("destroy(rBlock, pig)", 3, 0.3, "damage", 1.0, "the blow")
    failing = Margin("destroy(rBlock, pig)", 3, -0.1, "damage", 1.0, "the blow", held=False)
    both = {"here": 4, "there": 4}
    assert elsewhere.elsewhere(Domain(matched=both, weakest={"there": held}), R, [(1.0, 1, 2, None)], best=4, weakest=weak).world == "there"
    assert elsewhere.elsewhere(Domain(matched=both, weakest={"there": failing}), R, [(1.0, 1, 2, None)], best=4, weakest=weak) is None


def test_the_reserve_is_kept_only_where_there_is_another_world():
    assert elsewhere.reserve(Domain(), 60.0) == elsewhere.RESERVE_MOST
    assert elsewhere.reserve(Domain(), 10.0) == 1.0
    one = Domain()
    one.worlds = one.worlds[:1]
    assert elsewhere.reserve(one, 60.0) == 0.0


def test_exit_3_tells_more_time_from_a_space_used_up():
    assert "more time may help" in BUDGET_HELP[Exhausted.TIME]
    assert "cannot help" in BUDGET_HELP[Exhausted.ALLOWED]
