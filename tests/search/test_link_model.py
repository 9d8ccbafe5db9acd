"""The proposal model (physc.search.link_model): what a placed layout's links look like
(link_features), what a layout teaches, how the model ranks, and the worlds' priors it starts
from (link_prior), which must be current: measured with the recognition the worlds have now."""

from __future__ import annotations

import json

import pytest
from conftest import EXAMPLES

from physc.api.compiling import selected
from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.domains import bound, load_domain
from physc.driver import link_prior
from physc.search.link_features import NAMES, LinkFeatures, features
from physc.search.link_model import FLOOR, LinkModel, examples

RUN = NAMES.index("run")


def placed(name, role, x, y, width, height, rotation=0.0, concrete="squareHole"):
    return PlacedObject(name, role, concrete, "wood", x, y, rotation, width, height)


def layout(*objects):
    return ConcreteLayout("S", "angrybirds", 0, tuple(objects), (), (), (), 1, 0, 1)


@pytest.fixture(scope="module")
def rolling():
    return bound(load_domain("angrybirds"), "rolling", None)


def test_a_roll_runs_to_the_end_of_its_support_in_the_way_it_goes(rolling):
    _, scenario, _ = selected(EXAMPLES / "paper" / "04_R.phys", None)
    roll = scenario.interactions[1]
    assert roll.name == "roll" and roll.directions == ("right",)
    ledge = placed("surface", "support", 2.0, 0.0, 4.0, 0.2, concrete="flatPlatform")
    ball = placed("rBlock", "object", 1.0, 0.4, 0.6, 0.6, concrete="circle")
    found = features(layout(ledge, ball), scenario.interactions, {"rBlock": "surface"}, rolling)
    assert found[1].kind == "roll" and found[1].values[RUN] == pytest.approx(3.0)  # from x=1 to the ledge's end at 4
    assert all(len(f.values) == len(NAMES) for f in found)  # the bird and the pig are not in this layout: zeros


def test_a_layout_teaches_its_links_up_to_the_first_it_did_not_realise():
    links = [LinkFeatures("hit", 0, (0.0,)), LinkFeatures("roll", 1, (1.0,)), LinkFeatures("hit", 2, (2.0,))]
    assert examples(links, 1) == [("hit", (0.0,), True), ("roll", (1.0,), False)]
    assert examples(links, 3) == [("hit", (0.0,), True), ("roll", (1.0,), True), ("hit", (2.0,), True)]


def test_the_model_ranks_a_link_where_it_happened_above_where_it_did_not():
    model = LinkModel()
    for k in range(40):  # rolls with a run of 1 to 3 happen; shorter or longer ones do not
        run = k / 8
        model.learn([LinkFeatures("roll", 0, (run, 0.5))], 1 if 1.0 <= run <= 3.0 else 0)
    inside, outside = (
        model.chance([LinkFeatures("roll", 0, (2.0, 0.5))]),
        model.chance([LinkFeatures("roll", 0, (4.8, 0.5))]),
    )
    assert inside > 0.5 > outside >= FLOOR
    again = LinkModel(own={k: list(v) for k, v in model.own.items()})
    assert again.chance([LinkFeatures("roll", 0, (2.0, 0.5))]) == inside  # the same examples, the same chance


def test_a_kind_seen_with_one_outcome_only_has_laplaces_chance():
    model = LinkModel()
    for _ in range(3):
        model.learn([LinkFeatures("fall", 0, (1.0,))], 0)
    assert model.chance([LinkFeatures("fall", 0, (9.0,))]) == pytest.approx(1 / 5)
    assert model.chance([LinkFeatures("bounce", 0, (1.0,))]) == 0.5  # never seen


def test_a_prior_is_written_whole_with_its_provenance_and_read_back(tmp_path, rolling):
    where = tmp_path / "rolling.json"
    prior = link_prior.write(where, rolling, [("roll", (1.0, 2.0), True)], {"made": "2026-12-06", "physc": "x"})
    data = json.loads(where.read_text())
    assert data["fingerprint"] == link_prior.recognition(rolling) and data["features"] == list(NAMES)
    assert prior.record(True) == {
        "world": "rolling",
        "fingerprint": prior.fingerprint,
        "examples": 1,
        "used": True,
        "made": "2026-12-06",
        "physc": "x",
    }
    assert not list(tmp_path.glob("*.partial"))


@pytest.mark.parametrize("world", ["phyq", "rolling"])
def test_the_shipped_prior_was_measured_with_the_recognition_the_world_has_now(world):
    """Fails when a world's recognition (its settings, the recogniser's code, the features') has
    changed since its prior was made: make it again (benchmarks/link_prior.py, its docstring)."""
    domain = bound(load_domain("angrybirds"), world, None)
    prior = link_prior.load(domain)
    assert prior is not None, f"angrybirds ships a prior for {world}"
    assert prior.fingerprint == link_prior.recognition(domain), "made with another recognition: make it again"
    assert prior.count >= 100 and {"hit", "roll", "fall"} <= set(prior.examples)
    assert {"scenarios", "seed", "seconds", "physc", "made", "command"} <= set(prior.provenance)
    assert not any("heldout" in s or "examples/long" in s or "shots" in s for s in prior.provenance["scenarios"])


def test_a_prior_measured_with_another_recognition_is_not_used_and_the_task_says_so(monkeypatch, rolling):
    from physc.driver.layout_loop import LayoutLoop
    from physc.driver.run_settings import RunSettings

    _, scenario, _ = selected(EXAMPLES / "paper" / "04_R.phys", None)
    shipped = link_prior.load(rolling)
    assert shipped is not None
    current = LayoutLoop(rolling, scenario, 0, RunSettings())
    assert current.model.prior == shipped.examples and current.proposals["prior"]["used"] is True
    stale = link_prior.Prior(shipped.world, "0" * 16, shipped.provenance, shipped.examples)
    monkeypatch.setattr(link_prior, "load", lambda domain: stale)
    loop = LayoutLoop(rolling, scenario, 0, RunSettings())
    assert loop.model.prior == {} and loop.proposals["prior"]["used"] is False
