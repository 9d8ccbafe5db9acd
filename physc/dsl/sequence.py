"""The checks of a scenario's sequence (spec section 5, items 3-5): causality, goals, restrictions.

A part of the scenario checker (physc/dsl/check.py), which resolves the terms first; these checks
read the resolved terms (objects, directions, signatures) and the checker's objects. Every check
here is linear in the size of the scenario: restrictions find the interactions they are about
through an index, not by a scan of the sequence each.
"""

from __future__ import annotations

import heapq

import attrs

from physc.diagnostics import Label, Span
from physc.dsl import ast
from physc.dsl.check_state import Immobile, Resolved
from physc.dsl.fixes import Advice, goal_help, latest, motion_help, start_help
from physc.dsl.objects import ObjectChecks
from physc.dsl.vocabularies import TermSignature


@attrs.define
class _Walk:
    """What the causal checks know at a point of the sequence, as they walk it."""

    players: set[str]  # the objects of the player's term
    in_motion: set[str]
    movers: dict[str, None]  # the objects set in motion so far that could act, in the order they started
    destroyed: dict[str, Span] = attrs.Factory(dict)
    completed: set[str] = attrs.Factory(set)  # the goal objects an interaction meets the goal for
    seen: set[tuple[str, tuple[str, ...]]] = attrs.Factory(set)  # (term, its first two objects)
    # Once an interaction fails to resolve, what it would have set in motion, hit or destroyed is
    # unknown: later causal errors would be guesses.
    complete: bool = True


class SequenceChecks(ObjectChecks):
    """Causality, goals and restrictions: the part of the scenario checker that reads the sequence,
    built on the object checks (whose help texts for a static object need the objects in motion)."""

    def could_enable(self, signature: TermSignature, actor: str) -> bool:
        """Whether `actor` may take the interaction that also enables `signature` (destroy after
        explode: only a TNT box explodes), so that a message may offer it."""
        enabling = self.vocabulary.term(signature.enabled_by) if signature.enabled_by else None
        if enabling is None or not enabling.object_parameters or actor not in self.objects:
            return False
        fits = enabling.object_parameters[0].fits
        return not fits or self.vocabulary.fits(self.objects[actor].concrete, fits)

    def check_causality(self, interactions: list[Resolved | None], restrictions: list[Resolved | None]) -> None:
        """Walk the sequence: who acts, is set in motion, destroyed or meets the goal, and when
        (E0401-E0405); then whether every goal object meets the goal (E0404)."""
        vocabulary = self.vocabulary
        players = {o.name for o in self.objects.values() if vocabulary.fits(o.concrete, vocabulary.player)}
        walk = _Walk(players, set(players), dict.fromkeys(sorted(players)))
        waiting: dict[int | None, list[Immobile]] = {}
        for item in self.immobile:
            waiting.setdefault(item.position, []).append(item)
        # Structures (version 2, on(a, b)): what rests on a body moves once that body moves or goes.
        carried = [tuple(r.objects[:2]) for r in restrictions if r is not None and r.signature.carries]
        for index, resolved in enumerate(interactions):
            for top, below in carried:
                if below in walk.in_motion or below in walk.destroyed:
                    walk.in_motion.add(top)
            if waiting and index in waiting:
                for item in waiting[index]:
                    self.explain_immobile(item, walk.movers)
            if resolved is None:
                walk.complete = False
                continue
            self._check_destroyed(walk, resolved)
            self._check_actors(walk, index, resolved)
            self._check_required(walk, resolved)
            self._record_effects(walk, resolved)
        if walk.complete:
            self._check_goals(walk, interactions[-1] if interactions else None, restrictions)
            self._check_properties(walk, interactions, restrictions)

    def _check_properties(
        self, walk: _Walk, interactions: list[Resolved | None], restrictions: list[Resolved | None]
    ) -> None:
        """E0503: a property (version 2: nonGreedy, blocks, timed) whose objects the sequence does not
        take as it says: nonGreedy(a, b) needs a destroyed, then b; blocks(a, b) needs b destroyed
        and a in the sequence; timed(a) needs a's action to start after the first."""
        order = list(walk.destroyed)
        named = [set(r.objects) for r in interactions if r is not None]
        first_actor = interactions[0].objects[0] if interactions and interactions[0] is not None else None
        for restriction in restrictions:
            if restriction is None:
                continue
            name, objects = restriction.signature.name, restriction.objects
            if name == "nonGreedy" and not (
                objects[0] in order and objects[1] in order and order.index(objects[0]) < order.index(objects[1])
            ):
                why = f"the sequence must destroy '{objects[0]}' and then '{objects[1]}'"
            elif name == "blocks" and not (objects[1] in order and any(objects[0] in n for n in named)):
                why = f"the sequence must move '{objects[0]}' and destroy '{objects[1]}'"
            elif name == "timed" and (objects[0] == first_actor or not any(objects[0] in n for n in named)):
                why = f"'{objects[0]}' must be a later action than the first, named in the sequence"
            else:
                continue
            self.error(
                "E0503",
                f"'{restriction.node.name.text}({', '.join(objects)})' does not fit the sequence: {why}",
                restriction.node.span,
                help="name the objects in the order the sequence takes them, or change the sequence",
            )

    def _calm(self, name: str) -> bool:
        """Whether `name` is no goal object: a goal that knocks another over is valid, but odd to propose."""
        return not self.vocabulary.fits(self.objects[name].concrete, self.vocabulary.goal)

    def _check_destroyed(self, walk: _Walk, resolved: Resolved) -> None:
        """E0405: an object that takes part in an interaction after it was destroyed."""
        for obj, span in zip(resolved.objects, resolved.object_spans, strict=True):
            if obj in walk.destroyed:
                self.error(
                    "E0405",
                    f"'{obj}' takes part in '{resolved.signature.name}' after it was destroyed",
                    span,
                    notes=[Label(walk.destroyed[obj], f"'{obj}' is destroyed here")],
                )

    def _check_actors(self, walk: _Walk, index: int, resolved: Resolved) -> None:
        """E0401: a first interaction that the player's object does not perform; E0402: an object
        that acts before anything set it in motion (each object reported once)."""
        vocabulary, signature = self.vocabulary, resolved.signature
        for parameter, obj, span in zip(
            signature.object_parameters, resolved.objects, resolved.object_spans, strict=False
        ):
            if not parameter.acts:
                continue
            if obj not in walk.in_motion:
                walk.in_motion.add(obj)  # report each object once
            else:
                continue
            if index == 0 and obj not in walk.players:
                self.advise(
                    "E0401",
                    f"the first interaction must be performed by the {vocabulary.player} "
                    f"(the player's only action), but here '{obj}' acts",
                    span,
                    start_help(vocabulary, obj),
                    resolved.node,
                )
            elif walk.complete:
                self.advise(
                    "E0402",
                    f"'{obj}' acts in '{signature.name}' before anything set it in motion",
                    span,
                    motion_help(vocabulary, obj, latest(walk.movers, self._calm) or latest(walk.movers, bool)),
                    resolved.node,
                )

    def _check_required(self, walk: _Walk, resolved: Resolved) -> None:
        """E0403: an interaction whose signature requires an earlier one with the same objects
        (or one of `enabled_by` by its first object) that the sequence does not have."""
        signature = resolved.signature
        enabled = signature.enabled_by and (signature.enabled_by, resolved.objects[:1]) in walk.seen
        if not walk.complete or not signature.requires or (signature.requires, resolved.objects) in walk.seen:
            return
        if enabled:
            return
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

    def _record_effects(self, walk: _Walk, resolved: Resolved) -> None:
        """What the interaction does to its objects: sets them in motion, destroys them, meets the
        goal for them; and that it happened (for the requirements of later ones)."""
        signature = resolved.signature
        for parameter, obj in zip(signature.object_parameters, resolved.objects, strict=False):
            if parameter.moves:
                walk.in_motion.add(obj)
                if not self.objects[obj].static:
                    walk.movers.pop(obj, None)
                    walk.movers[obj] = None
            if parameter.destroys:
                walk.destroyed.setdefault(obj, ast.located(resolved.node.span))
                walk.movers.pop(obj, None)
            if parameter.completes:
                walk.completed.add(obj)
        walk.seen.add((signature.name, resolved.objects[:2]))

    def _check_goals(self, walk: _Walk, last: Resolved | None, restrictions: list[Resolved | None]) -> None:
        """E0404: a goal object that the scenario uses and no interaction meets the goal for."""
        vocabulary = self.vocabulary
        goal = vocabulary.goal
        unhittable = None
        for obj in self.objects.values():
            if obj.name in self.unknown or not vocabulary.fits(obj.concrete, goal) or obj.name in walk.completed:
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
                goal_help(vocabulary, obj.name, last, self.actor_for(obj.name, walk.movers, unhittable), self.objects),
            )

    def actor_for(self, goal: str, movers: dict[str, None], unhittable: set[tuple[str, ...]]) -> str | None:
        """An object in motion at the end of the sequence that may collide with `goal`."""

        def free(name: str) -> bool:
            return name != goal and (name, goal) not in unhittable

        goals = self.vocabulary.goal
        return latest(
            movers, lambda m: free(m) and not self.vocabulary.fits(self.objects[m].concrete, goals)
        ) or latest(movers, free)

    def apply_restrictions(
        self, interactions: list[Resolved | None], restrictions: list[Resolved | None]
    ) -> dict[int, tuple[str, ...]]:
        """Narrow interaction directions; report restrictions that contradict the sequence."""
        narrowed = {i: r.directions for i, r in enumerate(interactions) if r is not None}
        # A restriction on how a reaches b constrains a's direct approach: the
        # interactions a performs before anything redirects it (e.g. a bounce).
        if not any(restrictions):
            return narrowed
        # Each restriction meets only the interactions it is about, found by (term, objects): checking
        # stays linear in the size of the scenario. A repeated restriction adds nothing.
        by_pair, by_actor = _approaches(interactions)
        seen: set[tuple[str, tuple[str, ...], tuple[str, ...]]] = set()
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
                assert interaction is not None  # the indexes hold resolved interactions only
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
                            notes=[Label(ast.located(restriction.node.span), "the restriction")],
                        )
                    narrowed[index] = left
                else:
                    self.error(
                        "E0502",
                        f"'{restriction.node.name.text}({restriction.objects[0]})' forbids this '{name}'",
                        interaction.node.span,
                        help="remove the restriction or the interaction",
                        notes=[Label(ast.located(restriction.node.span), "the restriction")],
                    )
        return narrowed


_Index = dict[tuple[str, tuple[str, ...]], list[int]]


def _approaches(interactions: list[Resolved | None]) -> tuple[_Index, _Index]:
    """The positions of the resolved interactions by (term, first two objects), only those of an
    actor's direct approach (before anything redirects it), and by (term, first object)."""
    redirected: set[str] = set()
    by_pair: _Index = {}  # the direct approaches
    by_actor: _Index = {}
    for index, interaction in enumerate(interactions):
        if interaction is None:
            continue
        name, objects = interaction.signature.name, interaction.objects
        if objects[0] not in redirected:
            by_pair.setdefault((name, objects[:2]), []).append(index)
        by_actor.setdefault((name, objects[:1]), []).append(index)
        for parameter, obj in zip(interaction.signature.object_parameters, objects, strict=False):
            if parameter.redirects:
                redirected.add(obj)
    return by_pair, by_actor
