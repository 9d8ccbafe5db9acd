"""The paper's layout inference rules, for any domain of the paper's interactions.

A domain configures them (`LayoutRules`: its player's object term, the concrete objects
of a flat support and of the ground, and the way the player's object flies, if it flies
one way) and hands them to the pipeline as its `layout_rules`; angrybirds and the
PHYRE-like plugin both do. The paper's table "Inferred layout constraints":

    hit(a, b, d)      → liesOnPath(b, a) ∧ inDirection(b, a, -d)
    roll(a, b, d)     → inDirection(a, b, -d)
    fall(a, b, d)     → locatedFar(a, b, d)
                        (d = aboveLeft when d is above and the hit before the fall pushes
                        a right, or, with fall_ahead_after_motion, a rolled or slid right
                        just before: it comes down ahead; see `pushes`)
    destroy, touch    → nothing of their own (the hit or fall before them places them)
    slide(a, b, d)    → inDirection(a, b, -d)
    bounce(a, b, d)   → inDirection(a, b, d), and for d left or right also inDirection(a, b, -d)
    cannotHit(a,b,d)  → pathObstructed(a, b, d)
    cannotFall(a)     → a chain of touching surfaces that a moves on (with
                        continuous_paths, every mover's path is one, unless it is declared to
                        fall between two of them)

and the layout optimisation that makes the task stand under gravity. Our precise
reading (docs/qsr.md, "From scenario to layout"):

* Every dynamic object except the player's object rests on a support:
  - an object hit sideways by an object that moves along surfaces rests on the
    last surface of that mover's path, on the side the mover comes towards
    (the target lies on the path);
  - otherwise an object that rolls or slides rests on a support platform of its
    own, which its path continues from (`roll(a, s, right)` puts `a` left of `s`);
  - otherwise a new support: a flat support, or the ground, at any location; for an
    object that will fall, a platform it can be pushed off (on the part of it that
    the hit pushes it towards).
* The path of an object that rolls or slides: its support, then its surfaces in
  order, then the support of an object it hits sideways if that one has a path
  of its own. `cannotFall(a)` links consecutive platforms of a's path with
  `touching(p, q, upperLeft)` (p's upper-right point is q's upper-left: one
  continuous top edge); for a path towards the left the arguments swap.
* A surface that a dynamic object rests on is horizontal (an inclined one would
  not hold it still): such surfaces are narrowed to the flat support.

Structures: the reading above is the `flat` structure, the paper's. Where the surface a mover
rolls or slides on before it hits a target sideways may be inclined, the `ramp` structure reads
it as the game's own designers build a roll (Phy-Q's templates 2_1_3, 2_1_6, 2_1_9): the
surface is a ramp descending towards the target, and the target rests at its foot on a support
of its own, which the mover's path continues onto. Gravity then carries what a strike cannot.
`LayoutRules.structures(scenario)` names the structures a scenario has; generation tries
them all (physc.driver.pipeline), and simulation decides.
"""

from __future__ import annotations

import attrs

from physc.compiler.layout_graph import LayoutGraph
from physc.compiler.layout_inference import AHEAD, SIDES, bounced_from, infer, opposite
from physc.dsl.scenario import ScenarioIR

# The inference's steps live in physc.compiler.layout_inference; these names are kept here.
__all__ = ["AHEAD", "SIDES", "LayoutRules", "bounced_from", "infer", "opposite"]


@attrs.frozen
class LayoutRules:
    """The rules (module docstring) for one domain: `player`, the object term the player
    sets in motion; `flat`, the concrete object of a horizontal support; `ground`, that of
    the ground (None: the domain has none to rest on); `player_heading`, the way the
    player's object flies until it bounces ("right": Angry Birds' bird, shot from the left;
    None: no one way, a dropped ball); `player_placed`, whether the layout places the
    player's object (the bird at its slingshot) or the action does (PHYRE's red ball: then
    the player and its edges are left out of the graph, and the action is found by
    simulation)."""

    player: str
    flat: str
    ground: str | None = None
    player_heading: str | None = None
    player_placed: bool = True
    fall_ahead_after_motion: bool = False
    """Whether a faller that rolled or slid just before its fall starts above and behind
    its target (it comes down ahead), as one pushed off sideways does. Without it
    (angrybirds) only a push says so."""
    continuous_paths: bool = False
    """Whether the consecutive surfaces of every path touch, one continuous top edge (a
    ledge running into a ramp), unless the mover is declared to fall between them. Without
    it they touch only under cannotFall (the paper's reading), and the satisfier's repairs
    close the gaps in simulation. angrybirds and the PHYRE-like plugin set it: a mover that
    starts beside its surface must reach it, and a layout that puts that surface above or far
    beyond it gives a chain no variant realises (docs/results.md, issue 74)."""

    inclined: str | None = None
    """The concrete object of an inclined surface (angrybirds: inclinedPlatform), for the
    `ramp` structure; None: the domain offers no ramps."""

    def infer(self, scenario: ScenarioIR, structure: str = "flat") -> LayoutGraph:
        return infer(scenario, self, structure)

    def structures(self, scenario: ScenarioIR) -> tuple[str, ...]:
        """The structures the scenario can be laid out in: "flat" (the paper's reading), and
        "ramp" where a mover's surface before a sideways hit may be inclined."""
        return ("flat", "ramp") if _ramps(scenario, self) else ("flat",)


def _ramps(scenario: ScenarioIR, rules: LayoutRules) -> bool:
    """Whether some target is hit sideways by a mover coming along a surface that may be inclined."""
    if rules.inclined is None:
        return False
    return infer(scenario, rules, "ramp") != infer(scenario, rules, "flat")
