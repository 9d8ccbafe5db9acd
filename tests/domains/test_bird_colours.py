"""The game's five birds drawn in their colours and at their sizes (physc/domains/angrybirds/picture.py):
a yellow bird is drawn yellow, not red (issue 73); the birds waiting to be shot, in their order."""

from __future__ import annotations

import matplotlib.pyplot as plt
import pytest
from matplotlib import colors, patches

from physc.domains import load_domain
from physc.domains.angrybirds.birds import BIRDS
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.picture import BIRD_COLOURS, KIND_COLOURS, bird_colour, draw_level
from physc.domains.angrybirds.worlds import PHYQ

PIG = LevelObject("Pig", "BasicSmall", 3.0, PHYQ.frame.ground_top + 0.236, 0.0, name="pig")
HUES = {"BirdRed": 0.0, "BirdYellow": 1 / 6 - 0.03, "BirdBlue": 0.58}  # hue in turns, near which each lies


def birds_drawn(level, bird: bool | tuple[float, float] = True):
    """(centre, radius, face colour as #rrggbb) of each bird circle the picture draws."""
    figure = draw_level(level, PHYQ, bird=bird)
    try:
        circles = [p for p in figure.axes[0].patches if isinstance(p, patches.Circle)]
        drawn = [(tuple(c.center), c.radius, colors.to_hex(c.get_facecolor())) for c in circles]
    finally:
        plt.close(figure)
    return [d for d in drawn if d[0] != (PIG.x, PIG.y)]


def test_each_of_the_five_birds_has_its_own_colour():
    assert set(BIRD_COLOURS) == {b.prefab for b in BIRDS}
    assert len(set(BIRD_COLOURS.values())) == 5
    for prefab, hue in HUES.items():
        h, s, v = colors.rgb_to_hsv(colors.to_rgb(BIRD_COLOURS[prefab]))
        assert min(abs(h - hue), 1 - abs(h - hue)) < 0.06 and s > 0.5 and v > 0.5, prefab
    assert colors.rgb_to_hsv(colors.to_rgb(BIRD_COLOURS["BirdBlack"]))[2] < 0.25
    white = colors.rgb_to_hsv(colors.to_rgb(BIRD_COLOURS["BirdWhite"]))
    assert white[1] < 0.1 and white[2] > 0.9
    assert bird_colour("BirdRed") == KIND_COLOURS["bird"] and bird_colour("BirdUnknown") == KIND_COLOURS["bird"]


@pytest.mark.parametrize("bird", BIRDS, ids=lambda b: b.prefab)
def test_a_levels_bird_is_drawn_in_its_colour_and_size_at_the_slingshot(bird):
    (drawn,) = birds_drawn(Level(objects=(PIG,), birds=(bird.prefab,)))
    assert drawn == (PHYQ.launch.bird_rest, bird.radius, BIRD_COLOURS[bird.prefab])
    (flying,) = birds_drawn(Level(objects=(PIG,), birds=(bird.prefab,)), bird=(0.0, 1.0))  # a frame of its flight
    assert flying == ((0.0, 1.0), bird.radius, BIRD_COLOURS[bird.prefab])


def test_the_birds_waiting_are_drawn_behind_the_slingshot_in_the_order_they_are_shot():
    order = ("BirdYellow", "BirdRed", "BirdBlue", "BirdBlack", "BirdWhite")
    level = Level(objects=(PIG,), birds=order)
    drawn = birds_drawn(level)
    assert [d[2] for d in drawn] == [BIRD_COLOURS[p] for p in order]
    assert drawn[0][0] == PHYQ.launch.bird_rest
    waiting = [d[0] for d in drawn[1:]]
    assert all(x < level.slingshot[0] for x, _ in waiting) and [x for x, _ in waiting] == sorted(
        (x for x, _ in waiting), reverse=True
    )  # behind the slingshot, the next one nearest
    assert [d[0] for d in birds_drawn(level, bird=False)] == waiting  # the first one gone, the others wait


def test_physc_render_draws_a_yellow_bird_yellow():
    svg = load_domain("angrybirds").files.draw(Level(objects=(PIG,), birds=("BirdYellow",)), "", {}, "svg").decode()
    assert f"fill: {BIRD_COLOURS['BirdYellow']}" in svg and KIND_COLOURS["bird"] not in svg
