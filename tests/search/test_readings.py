"""Every reading of what a world's files leave open (issue 61, point 3): declared once by the
world, read by the game's damage rule, explored where a run shows it decides something, and
checked by `physc verify`, which names the readings that failed."""

from __future__ import annotations

import attrs
import pytest

from physc.backends import load_backend
from physc.domains.actions import Actions
from physc.domains.angrybirds.damage import Party, Strike
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ
from physc.search.verify import verify
from physc.simulation.trace import DependenceRecord, Interaction, Trace
from physc.worlds import OpenPoint, World, under_readings

BOX2D = load_backend("box2d")
RULES = PHYQ.rules
GROUND_TOP = PHYQ.frame.ground_top


def strike(this_velocity, other_kind="platform", other_velocity=(0.0, 0.0), relative=(0.0, -3.0)) -> Strike:
    """An ice block (mass 0.2, defence 0.5) striking `other` at 3 units/s."""
    this = Party("block", "block", 0.2, this_velocity)
    other = Party("other", other_kind, 0.3, other_velocity)
    return Strike(this, other, 3.0, relative, 0.5, "ice")


def test_the_platform_attacks_a_block_that_moves_against_relative_velocity_with_the_mass_read():
    """A block landing on a platform (its velocity less the platform's: down) and still going
    down a little after the step: read as other-minus-this, relativeVelocity points up, the
    block's projection is below the platform's 0, and the platform attacks with its mass."""
    landing = strike((0.0, -0.2))
    amount, attacker, _ = landing.dealt(RULES, platform_mass=1.0)
    assert attacker == "other" and amount == pytest.approx(3.0 * 1.0 * 11.22 * 0.5 - 0.5)
    assert landing.dealt(RULES, platform_mass=0.0)[0] == 0.0  # a massless attacker deals nothing
    # Read the other way, the block's projection is positive: it attacks itself with its own mass.
    own, attacker, _ = landing.dealt(RULES, relative_velocity="this-minus-other")
    assert attacker == "block" and own == pytest.approx(3.0 * 0.2 * 11.22 * 0.5 - 0.5)
    # The ground has no Rigidbody2D: the block always attacks itself.
    assert strike((0.0, -0.2), "ground").dealt(RULES, platform_mass=1.0)[1] == "block"


def test_a_near_tie_goes_the_way_the_reading_says():
    """Projections within rules.tie_band of each other: the comparison as written (`>`) gives
    the object itself; the other reading gives the other body."""
    tie = strike((1.0, 0.0), "block", (1.0 + RULES.tie_band / 2, 0.0), relative=(3.0, 0.0))
    assert tie.dealt(RULES, near_tie="this")[1] == "block"
    assert tie.dealt(RULES, near_tie="other")[1] == "other"
    clear = strike((1.0, 0.0), "block", (1.1, 0.0), relative=(3.0, 0.0))
    assert {clear.dealt(RULES, near_tie=t)[1] for t in ("this", "other")} == {clear.dealt(RULES)[1]}


def test_a_block_landing_on_a_platform_depends_on_the_platforms_mass_and_the_run_says_so():
    """An ice block dropped onto a platform: the game records where the platform's mass
    decided its damage, and the readings explored for the run include mass 0."""
    platform = LevelObject("Platform", "Platform", 0.0, GROUND_TOP + 1.0, 0.0, scale_x=4.0, name="ledge")
    block = LevelObject("Block", "RectSmall", 0.0, GROUND_TOP + 2.6, 0.0, "ice", name="block")
    level = Level(objects=(platform, block))

    def run(world):
        return Game(level, world, BOX2D).simulate(None, 3.0, stop_at_rest=False, invulnerable=0.0)

    readings = under_readings(PHYQ, run)
    assert readings[0][0] is PHYQ and "rules.platform_mass" in readings[0][1].decisive
    damage = {w.open_values(): [d for d in t.damage if d.target == "block" and d.amount > 0] for w, t in readings}
    # Read as this-minus-other, the block bounces against relativeVelocity: with the stored mass
    # the platform is its attacker and all but breaks it; massless, it deals nothing.
    (struck,) = damage["this-minus-other", 1.0, "this"]
    assert struck.attacker == "ledge" and struck.amount > 10 and struck.least == 0.0
    assert damage["this-minus-other", 0.0, "this"] == [] and damage["other-minus-this", 1.0, "this"] == []


@attrs.frozen(kw_only=True)
class Toy(World):
    """A world with one open point, `x`, whose reading 1 breaks the toy's chain."""

    x: float = 0.0

    def open_points(self):
        return (OpenPoint("x", (0.0, 1.0), "the toy's open point", "the toy's files", "x = {value:g}"),)


TOY = Toy(name="toy", description="", engine=PHYQ.engine, gravity=1.0, recogniser=PHYQ.recogniser, incline=PHYQ.incline)


@attrs.frozen
class Term:
    name: str
    objects: tuple
    directions: tuple = ()
    text: str = "hit(bird, pig)"


@attrs.frozen
class Scenario:
    name: str = "toy"
    interactions: tuple = (Term("hit", ("bird", "pig")),)
    restrictions: tuple = ()


class ToyDomain:
    """Plays a trace that realises the chain unless the world reads x as 1; the decision is
    recorded only when `decides` is set."""

    robustness_replays = 2
    actions = Actions(None)  # the defaults: the solution is what players send

    def __init__(self, world=TOY, decides=True, runs=None):
        self.world, self.decides, self.runs = world, decides, runs if runs is not None else []

    def at(self, world=None, backend=None):
        return ToyDomain(world or self.world, self.decides, self.runs)

    def replay(self, level, solution, scenario, rng=None):
        import numpy as np

        self.runs.append(self.world.x)
        hit = () if self.world.x else (Interaction("hit", ("bird", "pig"), None, 1.0),)
        depends = (DependenceRecord(0.5, "pig", ("x",)),) if self.decides else ()
        if rng is not None:
            rng.random()
        return Trace(0.1, ("bird",), {}, np.zeros((20, 1, 6)), interactions=hit, solved=bool(hit), depends=depends)


def test_verify_plays_every_reading_a_run_shows_to_decide_something_and_names_those_that_fail():
    domain = ToyDomain()
    check = verify(domain, Scenario(), None, "shot", "box2d", noisy=2)
    assert not check.passes(0) and check.failed == ("toy, x = 1",) and check.readings == 2
    assert check.simulations == 6 == len(domain.runs)
    assert "x = 1" in check.why


def test_a_reading_no_run_depends_on_is_not_played():
    domain = ToyDomain(decides=False)
    check = verify(domain, Scenario(), None, "shot", "box2d", noisy=2)
    assert check.passes(2) and check.failed == () and check.simulations == 3 == len(domain.runs)
