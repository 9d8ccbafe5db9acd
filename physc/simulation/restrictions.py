"""The restrictions of the `.phys` language, read against the interactions a run realised.

cannotHit(a, b, D) is violated by a hit(a, b, d) with d in D on a's direct approach (before a
bounce the scenario declares redirects it, as in the language's static checks; an incidental
bounce on some platform does not count); cannotFall(a) by any fall(a, …).
"""

from __future__ import annotations

import math

from physc.simulation.trace import Violation


def violations(interactions, restrictions, redirects=None) -> tuple[Violation, ...]:
    """Restrictions (TermIR-like: name, objects, directions) broken by the interactions.

    `redirects` are the (object, surface) pairs of the bounces the scenario declares:
    only such a bounce ends an object's direct approach (an incidental bounce on some
    platform does not lift `cannotHit`). None: every bounce redirects (no scenario)."""
    out = []
    redirected_at: dict[str, float] = {}
    for i in interactions:
        if i.name == "bounce" and (redirects is None or tuple(i.objects) in redirects):
            redirected_at.setdefault(i.objects[0], i.time)
    for restriction in restrictions:
        for i in interactions:
            if restriction.name == "cannotHit" and i.name == "hit" and i.objects == tuple(restriction.objects[:2]):
                direct = i.time < redirected_at.get(i.objects[0], math.inf)
                if direct and i.direction in restriction.directions:
                    out.append(Violation(restriction.text or f"cannotHit({', '.join(restriction.objects)})", i))
            elif restriction.name == "cannotFall" and i.name == "fall" and i.objects[0] == restriction.objects[0]:
                out.append(Violation(restriction.text or f"cannotFall({restriction.objects[0]})", i))
    return tuple(sorted(out, key=lambda v: v.interaction.time))
