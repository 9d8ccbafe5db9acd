"""Candidate actions of PHYRE's two-ball tier: both red balls placed at once.

A scenario that declares two red balls is a two-ball task (PHYRE's TWO_BALLS tier; its
templates 00100-00124 are built so that both balls are needed). Each ball is dropped as in
the ball tier (actions.drops) onto the target of its own first interaction: the first ball's
is the scenario's first interaction, the second ball's the first one it acts in. A pair is a
drop of each, kept when PHYRE's mapper would place it (the centres r1 + r2 + 1 px apart)
and neither ball occludes a body.

The second ball acts after the first, so pairs whose second ball falls from higher come
first; then near-first-first (the i-th and j-th drops before any whose i + j is larger). As
many pairs as the first ball has drops: the search simulates every candidate of its first
layout, so a two-ball layout costs it what a one-ball layout does.
"""

from __future__ import annotations

import attrs

from physc_phyre.actions import apart, drops, valid
from physc_phyre.level import PhyreLevel, TwoBallAction, outline_box


def first_acts(scenario, name: str):
    """The first interaction in which `name` acts (is the first argument), or None."""
    return next((term for term in scenario.interactions if term.objects and term.objects[0] == name), None)


def candidate_pairs(level: PhyreLevel, scenario) -> list[tuple[str, TwoBallAction]]:
    """(label, action) for pairs of drops of the two red balls (module docstring); none when
    the second ball never acts, or its first target is not in the level yet."""
    acting = [first_acts(scenario, name) for name in level.players]
    firsts = [term for term in acting if term is not None]
    if len(firsts) < len(acting):
        return []
    one, two = (drops(level, term) for term in firsts)
    tops = [outline_box(level.body(term.objects[1]))[3] for term in firsts]
    heights = [
        [ball.y - ball.radius - top for _, ball in candidates]
        for candidates, top in zip((one, two), tops, strict=False)
    ]
    pairs = sorted(
        ((i, j) for i in range(len(one)) for j in range(len(two))),
        key=lambda p: (heights[1][p[1]] <= heights[0][p[0]], p[0] + p[1], p[0]),
    )
    out = []
    for i, j in pairs:
        (label1, ball1), (label2, ball2) = one[i], two[j]
        label = f"{level.players[0]}: {label1}; {level.players[1]}: {label2}"
        action = TwoBallAction(attrs.evolve(ball1, aimed_at=label1), attrs.evolve(ball2, aimed_at=label2), label)
        if apart(*action.balls) and valid(level, action):  # as PHYRE's mapper places them
            out.append((label, action))
            if len(out) == len(one):
                break
    return out
