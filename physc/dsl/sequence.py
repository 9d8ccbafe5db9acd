"""The checks of a scenario's sequence (spec section 5, items 3-5): causality, goals, restrictions.

A mixin of the scenario checker (physc/dsl/check.py), which resolves the terms first; these checks
read the resolved terms (objects, directions, signatures) and the checker's objects. Every check
here is linear in the size of the scenario: restrictions find the interactions they are about
through an index, not by a scan of the sequence each.
"""

from __future__ import annotations

import heapq

from physc.diagnostics import Label, Span
from physc.dsl.fixes import Advice, goal_help, latest, motion_help, start_help


class SequenceChecks:
    """Causality, goals and restrictions; mixed into the scenario checker, whose state they read."""

    def could_enable(self, signature, actor: str) -> bool:
        """Whether `actor` may take the interaction that also enables `signature` (destroy after
        explode: only a TNT box explodes), so that a message may offer it."""
        enabling = self.vocabulary.term(signature.enabled_by) if signature.enabled_by else None
        if enabling is None or not enabling.object_parameters or actor not in self.objects:
            return False
        fits = enabling.object_parameters[0].fits
        return not fits or self.vocabulary.fits(self.objects[actor].concrete, fits)

    def check_causality(self, interactions: list, restrictions: list) -> None:
        vocabulary = self.vocabulary
        players = {o.name for o in self.objects.values() if vocabulary.fits(o.concrete, vocabulary.player)}
        in_motion = set(players)
        # The objects set in motion so far that could act, in the order they started (for help texts).
        movers: dict[str, None] = dict.fromkeys(sorted(players))
        destroyed: dict[str, Span] = {}
        completed: set[str] = set()  # the goal objects an interaction meets the goal for

        def calm(name: str) -> bool:  # a goal that knocks another over is valid, but odd to propose
            return not vocabulary.fits(self.objects[name].concrete, vocabulary.goal)

        seen: set[tuple[str, tuple[str, ...]]] = set()
        # Once an interaction fails to resolve, what it would have set in motion,
        # hit or destroyed is unknown: later causal errors would be guesses.
        complete = True
        waiting: dict[int, list] = {}
        for item in self.immobile:
            waiting.setdefault(item[1], []).append(item)
        # Structures (version 2, on(a, b)): what rests on a body moves once that body moves or goes.
        carried = [tuple(r.objects[:2]) for r in restrictions if r is not None and r.signature.carries]
        for index, resolved in enumerate(interactions):
            for top, below in carried:
                if below in in_motion or below in destroyed:
                    in_motion.add(top)
            if waiting and index in waiting:
                for item in waiting[index]:
                    self.explain_immobile(item, movers)
            if resolved is None:
                complete = False
                continue
            signature = resolved.signature
            for obj, span in zip(resolved.objects, resolved.object_spans):
                if obj in destroyed:
                    self.error(
                        "E0405",
                        f"'{obj}' takes part in '{signature.name}' after it was destroyed",
                        span,
                        notes=[Label(destroyed[obj], f"'{obj}' is destroyed here")],
                    )
            for parameter, obj, span in zip(signature.object_parameters, resolved.objects, resolved.object_spans):
                if not parameter.acts:
                    continue
                if obj not in in_motion:
                    in_motion.add(obj)  # report each object once
                else:
                    continue
                if index == 0 and obj not in players:
                    self.advise(
                        "E0401",
                        f"the first interaction must be performed by the {vocabulary.player} "
                        f"(the player's only action), but here '{obj}' acts",
                        span,
                        start_help(vocabulary, obj),
                        resolved.node,
                    )
                elif complete:
                    self.advise(
                        "E0402",
                        f"'{obj}' acts in '{signature.name}' before anything set it in motion",
                        span,
                        motion_help(vocabulary, obj, latest(movers, calm) or latest(movers, bool)),
                        resolved.node,
                    )
            enabled = signature.enabled_by and (signature.enabled_by, resolved.objects[:1]) in seen
            if complete and signature.requires and (signature.requires, resolved.objects) not in seen and not enabled:
                pair = ", ".join(resolved.objects)
                added = f"{signature.requires}({pair}, any)"
                other = (
                    f" or '{signature.enabled_by}({resolved.objects[0]})'"
                    if self.could_enable(signature, resolved.objects[0])
                    else ""
                )
                self.advise(
                    "E0403",
                    f"'{signature.name}({pair})' needs an earlier '{signature.requires}({pair}, …)'{other}",
                    resolved.node.span,
                    Advice(f"add `{added}` before it", before=added),
                    resolved.node,
                )
            for parameter, obj, span in zip(signature.object_parameters, resolved.objects, resolved.object_spans):
                if parameter.moves:
                    in_motion.add(obj)
                    if not self.objects[obj].static:
                        movers.pop(obj, None)
                        movers[obj] = None
                if parameter.destroys:
                    destroyed.setdefault(obj, resolved.node.span)
                    movers.pop(obj, None)
                if parameter.completes:
                    completed.add(obj)
            seen.add((signature.name, resolved.objects[:2]))
        goal = vocabulary.goal
        last = interactions[-1] if interactions else None
        unhittable = None
        for obj in self.objects.values() if complete else ():
            if obj.name in self.unknown or not vocabulary.fits(obj.concrete, goal) or obj.name in completed:
                continue
            if not obj.used:
                continue
            if unhittable is None:
                unhittable = {tuple(r.objects[:2]) for r in restrictions if r is not None and r.signature.narrows}
            self.advise(
                "E0404",
                f"the {goal} '{obj.name}' {vocabulary.goal_unmet}"
                + (f" ({vocabulary.goal_rule})" if vocabulary.goal_rule else ""),
                obj.span,
                goal_help(vocabulary, obj.name, last, self.actor_for(obj.name, movers, unhittable), self.objects),
            )

    def actor_for(self, goal: str, movers: dict[str, None], unhittable: set) -> str | None:
        """An object in motion at the end of the sequence that may collide with `goal`."""

        def free(name: str) -> bool:
            return name != goal and (name, goal) not in unhittable

        goals = self.vocabulary.goal
        return latest(
            movers, lambda m: free(m) and not self.vocabulary.fits(self.objects[m].concrete, goals)
        ) or latest(movers, free)

    def apply_restrictions(self, interactions, restrictions) -> dict[int, tuple[str, ...]]:
        """Narrow interaction directions; report restrictions that contradict the sequence."""
        narrowed = {i: r.directions for i, r in enumerate(interactions) if r is not None}
        # A restriction on how a reaches b constrains a's direct approach: the
        # interactions a performs before anything redirects it (e.g. a bounce).
        if not any(restrictions):
            return narrowed
        # Each restriction meets only the interactions it is about, found by (term, objects): checking
        # stays linear in the size of the scenario. A repeated restriction adds nothing.
        redirected: set[str] = set()
        by_pair: dict[tuple, list[int]] = {}  # the direct approaches
        by_actor: dict[tuple, list[int]] = {}
        for index, interaction in enumerate(interactions):
            if interaction is None:
                continue
            name, objects = interaction.signature.name, interaction.objects
            if objects[0] not in redirected:
                by_pair.setdefault((name, objects[:2]), []).append(index)
            by_actor.setdefault((name, objects[:1]), []).append(index)
            for parameter, obj in zip(interaction.signature.object_parameters, objects):
                if parameter.redirects:
                    redirected.add(obj)
        seen: set[tuple] = set()
        for restriction in restrictions:
            if restriction is None:
                continue
            signature = restriction.signature
            key = (signature.name, restriction.objects, restriction.directions)
            if key in seen:
                continue
            seen.add(key)
            narrowing = by_pair.get((signature.narrows, restriction.objects[:2]), []) if signature.narrows else []
            forbidden = by_actor.get((signature.forbids, restriction.objects[:1]), []) if signature.forbids else []
            if forbidden and signature.forbids == signature.narrows:
                narrowing_set = set(narrowing)
                forbidden = [i for i in forbidden if i not in narrowing_set]
            met = [(i, True) for i in narrowing]
            if forbidden:
                met = list(heapq.merge(met, [(i, False) for i in forbidden]))
            for index, narrows in met:
                interaction = interactions[index]
                name = interaction.signature.name
                if narrows:
                    if not narrowed[index]:
                        continue  # already reported: nothing is left to forbid
                    left = tuple(d for d in narrowed[index] if d not in restriction.directions)
                    if not left:
                        self.error(
                            "E0501",
                            f"'{restriction.node.name.text}' forbids every direction "
                            f"that this '{name}' allows ({', '.join(narrowed[index])})",
                            interaction.direction_span or interaction.node.span,
                            help="allow more directions in the interaction or fewer in the restriction",
                            notes=[Label(restriction.node.span, "the restriction")],
                        )
                    narrowed[index] = left
                else:
                    self.error(
                        "E0502",
                        f"'{restriction.node.name.text}({restriction.objects[0]})' forbids this '{name}'",
                        interaction.node.span,
                        help="remove the restriction or the interaction",
                        notes=[Label(restriction.node.span, "the restriction")],
                    )
        return narrowed
