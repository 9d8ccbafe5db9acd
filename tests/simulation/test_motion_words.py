"""The motion words as Phy-Q's own levels mean them (docs/angrybirds.md, "What the motion words mean").

Phy-Q's templates are labelled examples: in its rolling levels a round body travels along a
platform into the pig, in hops lower than its radius in the game's flat-footed circles; in two
of its sliding levels the block stands against the pig, so no slide can come before the blow.
"""

from __future__ import annotations

import attrs
import numpy as np
import pytest
from conftest import ROOT

import physc
from physc.api.simulating import bound_domain
from physc.domains.angrybirds.worlds import PHYQ, ROLLING
from physc.simulation.ending import Ending
from physc.simulation.recognise import contact_intervals

TEMPLATES = ROOT / "tests" / "data" / "sciencebirds" / "phyq-templates"


def played(template: str, angle: float, world: str = "phyq"):
    domain = bound_domain("angrybirds", world, None)
    level = physc.read_level(TEMPLATES / f"{template}.xml")
    return domain.play(level, physc.Shot(angle=angle), None, domain.seconds, ending=Ending.WHOLE)


def before_destroy(trace) -> list[str]:
    """The interactions up to the first destroy of a pig, as text."""
    texts = [i.text() for i in trace.interactions]
    first = next(k for k, i in enumerate(trace.interactions) if i.name == "destroy" and trace.kinds.get(i.objects[1]) == "pig")
    return texts[: first + 1]


@pytest.mark.parametrize(
    ("template", "angle", "roller"),
    [("2_1_2_1", 47, "bird"), ("2_1_5_1", 49, "circle1"), ("2_1_8_1", 37, "circle1")],
)
def test_phyqs_rolling_levels_roll_into_the_pig(template, angle, roller):
    trace = played(template, angle)
    seen = before_destroy(trace)
    assert trace.solved and seen[-1].startswith(f"destroy({roller}, ")
    assert any(t.startswith(f"roll({roller}, ") for t in seen), seen


def test_a_roll_joins_hops_lower_than_the_bodys_size_and_the_papers_words_do_not():
    trace = played("2_1_8_1", 37)
    roll = next(i for i in trace.interactions if i.text() == "roll(circle1, platform1, right)")
    touches = [s for s in contact_intervals(trace)[frozenset(("circle1", "platform1"))] if s[0] >= roll.time - 0.5]
    assert len(touches) > 1  # it hopped
    strict = attrs.evolve(PHYQ.recogniser, hop_rise=0.0, roll_slip=ROLLING.recogniser.roll_slip)
    found = strict.recognise(trace, trace.radii)
    assert roll not in found  # touch by touch, as the rolling world reads, it is no such roll


def test_a_block_standing_against_the_pig_does_not_slide_before_it_strikes_it():
    # Sliding 2_3_2: the block's side is 0.01 units from the pig's; the bird drives it into
    # the pig, which dies in the same blow. Its travel before the blow is below any floor.
    trace = played("2_3_2_1", 38)
    seen = before_destroy(trace)
    assert seen[-1] == "destroy(squareHole1, pigSmall1)"
    assert not any(t.startswith("slide(") for t in seen)
    met = next(c.time for c in trace.contacts if {c.a, c.b} == {"squareHole1", "pigSmall1"})
    path = trace.states[: int(round(met / trace.dt)), trace.index("squareHole1"), :2]
    assert np.hypot(*(path[-1] - path[0])) < PHYQ.recogniser.travel


def test_a_round_body_rolls_and_a_block_slides_in_phyq():
    assert not PHYQ.recogniser.round_slides and ROLLING.recogniser.round_slides
    for template, angle in (("2_1_5_1", 49), ("2_1_6_1", 43)):
        trace = played(template, angle)
        round_ones = {name for name, r in trace.radii.items() if r}
        assert not [i for i in trace.interactions if i.name == "slide" and i.objects[0] in round_ones]


def test_a_single_force_shot_hits_with_no_motion_word_between():
    trace = played("1_1_2_1", 18)
    seen = before_destroy(trace)
    assert seen[-1] == "destroy(bird, pigSmall1)" and not any(t.startswith(("roll(", "slide(")) for t in seen), seen


def test_a_bounce_off_a_wall_counts_in_phyq_as_phyqs_bouncing_levels_mean():
    # Bouncing 2_4_4: the pig sits in a box; the bird glances off the box's side (platform6,
    # struck from the left) and comes up under the pig. Read with upper sides only, as the
    # rolling world's words are, the bounce off the wall is not there.
    trace = played("2_4_4_1", 30)
    seen = before_destroy(trace)
    assert "bounce(bird, platform6, above)" in seen and "hit(bird, pigMedium1, below)" in seen
    upper = attrs.evolve(PHYQ.recogniser, bounce_walls=False)
    assert not any(i.text() == "bounce(bird, platform6, above)" for i in upper.recognise(trace, trace.radii))
    assert PHYQ.recogniser.bounce_walls and not ROLLING.recogniser.bounce_walls
