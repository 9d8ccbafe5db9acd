"""Agents play physc's tasks: Gymnasium environments and a PHYRE-style ActionSimulator.

Importing this module registers one environment per installed domain that can be played
(`Domain.playing.env_id`): `physc/AngryBirds-v0`, and `physc/PhyreLike-v0` with the PHYRE-like
plugin. `gymnasium.make("physc.envs:physc/AngryBirds-v0", tasks=…)` imports it on the way.
"""

from __future__ import annotations

from physc.domains.playing import Playing
from physc.envs.simulator import ActionSimulator, Simulation, SimulationStatus

__all__ = ["ActionSimulator", "Playing", "Simulation", "SimulationStatus", "register_envs"]


def register_envs() -> list[str]:
    """Register the environment of every installed domain that can be played; their ids."""
    import gymnasium

    from physc.domains import installed_domains, load_domain
    from physc.domains.base import DomainError

    ids = []
    for name in installed_domains():
        try:
            playing = load_domain(name).playing
        except DomainError:  # a broken plugin is `physc domains`'s to report, not an import error here
            continue
        if playing is None or not playing.env_id:
            continue
        if playing.env_id not in gymnasium.registry:
            gymnasium.register(
                id=playing.env_id,
                entry_point="physc.envs.env:TaskEnv",
                kwargs={"domain": name},
                max_episode_steps=playing.max_attempts,
                disable_env_checker=False,
            )
        ids.append(playing.env_id)
    return ids


register_envs()
