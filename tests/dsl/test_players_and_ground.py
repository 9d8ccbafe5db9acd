"""Several birds are several shots (version 2); more of the player's objects than a domain
places are said by check (W0302) and compile (E0804); the level's ground can be named."""

from conftest import run_physc

TWO_BIRDS = """scenario TB {
    interactions {
        hit(bird, pig, left) > destroy(bird, pig) > hit(bird2, pig2, left) > destroy(bird2, pig2)
    }
}
"""

GROUND = """scenario G {
    interactions {
        hit(bird, pig, left) > destroy(bird, pig) > bounce(bird, ground, right)
    }
}
"""


THREE_BALLS = """scenario ThreeDrops {
    domain phyre
    objects {
        first: redBall
        second: redBall
        third: redBall
        green: greenObject = greenBall
        target: targetObject = purpleFloor
    }
    interactions {
        hit(first, green, above) > hit(second, green, above) > hit(third, green, above) > fall(green, target) > touch(green, target)
    }
}
"""


def test_a_second_bird_is_a_second_shot(tmp_path):
    path = tmp_path / "two.phys"
    path.write_text(TWO_BIRDS)
    checked = run_physc("check", path, "--color", "never")
    assert checked.status == 0 and "W0302" not in checked.stderr
    compiled = run_physc("compile", path, "-q", "--color", "never", "-o", tmp_path / "tb.xml")
    assert compiled.status == 0, compiled.stderr
    assert (tmp_path / "tb.xml").read_text().count('<Bird type="BirdRed" />') == 2


def test_a_third_ball_is_warned_of_by_check_and_refused_at_once_by_compile(tmp_path):
    path = tmp_path / "three.phys"
    path.write_text(THREE_BALLS)
    checked = run_physc("check", path, "--color", "never")
    assert checked.status == 0 and "warning[W0302]: 'third' is a third redBall" in checked.stderr
    compiled = run_physc("compile", path, "-q", "--color", "never", "-o", tmp_path / "tb.json")
    assert compiled.status == 3 and "error[E0804]" in compiled.stderr and "3 redBalls (first, second, third)" in compiled.stderr
    assert not (tmp_path / "tb.json").exists()


def test_the_ground_as_traces_name_it_can_be_named_in_a_scenario(tmp_path):
    path = tmp_path / "ground.phys"
    path.write_text(GROUND)
    assert run_physc("check", path).status == 0
    graph = run_physc("compile", path, "--emit", "layout-graph")
    assert graph.status == 0 and "inDirection(bird, ground" not in graph.stdout  # the ground spans the scene
    level = tmp_path / "g.xml"
    run = run_physc("compile", path, "-q", "-o", level)
    assert run.status == 0 and "ground" not in level.read_text()  # the level's own ground, not a new platform
