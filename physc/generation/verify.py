"""Cross-engine verification: a task's intended solution replayed in another backend.

A task is checked in the engine that generated it; a solution that also solves the level,
and realises the declared sequence, in an engine with another contact solver shows that
the physics is the scenario's and not an artefact of one solver. `verify` replays the
solution once as recorded and, if asked, under the domain's noise, with the domain's
`replay`, the domain simulating in the same world with the other engine (`Domain.at`). `physc verify`, `physc compile
--verify-backend` and `physc eval --verify-backend` all use it. Nothing here depends on a
domain.
"""

from __future__ import annotations

import random

import attrs

from physc.simulation.fidelity import fidelity


@attrs.frozen
class Verification:
    backend: str
    solved: bool  # the recorded solution solves the level (the domain's goal is met)
    realised: bool  # and its simulation realises the declared sequence, breaking no restriction
    noisy_passed: int  # noisy replays that realised the sequence
    noisy_run: int
    trace: str  # the interactions the recorded solution realises, in .phys syntax
    why: str  # what the replay got wrong, in words ("" when it passed)

    def passes(self, noisy_needed: int = 0) -> bool:
        """The recorded solution solves the level and realises the sequence, and at least
        `noisy_needed` noisy replays realise it too."""
        return self.solved and self.realised and self.noisy_passed >= noisy_needed

    def summary(self) -> str:
        parts = [
            "solved" if self.solved else "not solved",
            "sequence realised" if self.realised else "sequence not realised",
        ]
        if self.noisy_run:
            parts.append(f"{self.noisy_passed} of {self.noisy_run} noisy replays realise it")
        return f"in {self.backend}: " + ", ".join(parts)


def noisy_replays(domain) -> int:
    """The noisy replays a solution is put through by default: the domain's own (none for a
    domain without a noise model)."""
    return domain.robustness_replays or 0


def verify(domain, scenario, level, solution, backend: str, noisy: int = 0) -> Verification:
    """Replay `solution` in `level` with `backend`: once as recorded, then `noisy` times
    under the domain's noise (drawn from a generator seeded by the backend and the
    solution, so a verification is the same whenever and wherever it runs). The world is the
    domain's (`Domain.at`)."""
    there = domain.at(backend=backend)
    trace = there.replay(level, solution, scenario)
    check = fidelity(scenario, trace)
    rng = random.Random(f"physc-verify/{backend}/{scenario.name}/{solution!r}")
    passed = sum(fidelity(scenario, there.replay(level, solution, scenario, rng)).valid for _ in range(noisy))
    why = ""
    if not trace.solved:
        why = "the solution does not solve the level"
    elif check.violations:
        why = "it breaks " + ", ".join(check.violations)
    elif not check.valid:
        missing = scenario.interactions[check.matched].text
        why = f"it realises {check.matched} of {check.total} interactions in order (never `{missing}`)"
    elif passed < noisy:
        why = f"{passed} of {noisy} noisy replays realise the sequence"
    return Verification(backend, trace.solved, check.valid, passed, noisy, trace.sequence(), why)
