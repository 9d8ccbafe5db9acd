"""The shots `physc simulate`, `trace` and `render` are asked for on the command line.

Each of --shot X,Y[,low|high], --angle DEG and --action DX,DY[,TAP] aims one shot, and the
level's birds are shot in turn, one for each such option in the order given (named bird, bird2,
bird3, … as traces name them; with --task and the task's own level, as its scenario names
them). --tap S and --wait S belong to the shot aimed just before them: --tap taps its bird S
seconds after the launch (a blue bird splits, a yellow one speeds up, a black one blasts, a white
one drops its egg); --wait takes a later shot S seconds after the game brought its bird onto the
slingshot (when the bird before struck something or used its power) instead of once the level
rests, as Phy-Q's agents shoot. --action is what Phy-Q's agents send, `env.step([dx, dy,
tap_time])`, played at the angle and stretch the game launches it at (agent_shots.py). A
mistake (a tap before any shot, two taps for one, more shots than birds) is a usage error,
exit 2, that says what to write instead.
"""

from __future__ import annotations

import argparse

import attrs

from physc.commands import arguments
from physc.commands.common import UsageError, plural

AIMS = ("--shot", "--angle", "--action")  # each aims a shot of its own


class Ordered(argparse.Action):
    """Keeps each option of the shots with its value in `args.aims`, in the order given (argparse
    alone keeps each option's values apart, losing which --tap follows which --angle)."""

    def __call__(self, parser, namespace, values, option_string=None):
        kept = list(getattr(namespace, self.dest, None) or [])
        kept.append((self.option_strings[0], values))
        setattr(namespace, self.dest, kept)


def add_shot_options(parser) -> None:
    """--shot, --angle, --action, --tap and --wait, kept in order in `args.aims`."""

    def add(flag: str, kind, metavar: str, help_text: str) -> None:
        parser.add_argument(flag, dest="aims", action=Ordered, type=kind, metavar=metavar, help=help_text)

    add(
        "--shot",
        arguments.shot,
        "X,Y[,low|high]",
        "shoot at a target point, on the low (default) or high trajectory (a negative X as it is: --shot -9,0.5);"
        " each --shot, --angle or --action shoots the next of the level's birds",
    )
    add(
        "--angle",
        arguments.angle,
        "DEG",
        "shoot at a release angle (degrees), at full stretch; repeat it for the next bird",
    )
    add(
        "--action",
        arguments.agent_action,
        "DX,DY[,TAP]",
        "shoot as Phy-Q's agents do, env.step([dx, dy, tap_time]): the release point in whole screen pixels"
        " from the slingshot's reference point (y up), the tap in ms after the launch (0: none);"
        " repeat it for the next bird",
    )
    add(
        "--tap",
        arguments.tap,
        "S",
        "tap the bird of the shot given just before, S seconds after its launch (its power)",
    )
    add(
        "--wait",
        arguments.wait,
        "S",
        "take the (later) shot given just before S seconds after its bird came onto the slingshot (the bird before"
        " struck something), not once the level rests",
    )


@attrs.frozen
class Asked:
    """One shot as the command line asks for it: how it is aimed, and its tap and wait."""

    option: str  # one of AIMS
    value: object  # its value as arguments.py parsed it
    tap: float | None = None
    wait: float | None = None

    def text(self) -> str:
        """The option as it could have been typed: `--angle 30`, `--action -100,-93,0`."""
        value = self.value
        if self.option == "--angle":
            assert isinstance(value, float)
            return f"--angle {value:g}"
        assert isinstance(value, tuple)
        if self.option == "--shot":
            return f"--shot {value[0]:g},{value[1]:g},{value[2]}"
        return f"--action {value[0]},{value[1]},{value[2]}"

    def sent(self) -> str | None:
        """What Phy-Q's agents send for it (an --action's), else None."""
        if self.option != "--action":
            return None
        assert isinstance(self.value, tuple)
        return f"env.step([{', '.join(str(v) for v in self.value)}])"


def asked(aims) -> list[Asked]:
    """The shots `aims` ((option, value) in order) ask for; UsageError for a --tap or --wait that
    belongs to no shot, or is given twice for one, or a first shot's --wait."""
    shots: list[Asked] = []
    for option, value in aims or ():
        if option in AIMS:
            shots.append(Asked(option, value))
            continue
        what = "taps" if option == "--tap" else "times"
        if not shots:
            raise UsageError(
                f"{option} {value:g} comes before any shot: put it after the --angle, --action or --shot"
                f" of the shot it {what}"
            )
        last = shots[-1]
        if getattr(last, option[2:]) is not None:
            raise UsageError(f"{option} is given twice for the shot of {last.text()}: one {option} a shot")
        if option == "--tap" and last.option == "--action" and last.value[2] > 0:  # type: ignore[index]
            raise UsageError(
                f"{last.text()} taps its bird already ({last.value[2]} ms after the launch) and --tap {value:g}"  # type: ignore[index]
                " taps it again: give the tap once, in the action or with --tap"
            )
        if option == "--wait" and len(shots) == 1:
            raise UsageError(
                f"--wait {value:g} follows the first shot ({last.text()}), which is taken at once: --wait times a"
                " later shot, after its --angle, --action or --shot"
            )
        shots[-1] = attrs.evolve(last, **{option[2:]: value})
    return shots


def shots(aims, level, names=()):
    """The action `aims` ask for in `level` (a Shot, Shots for several, None for none), its birds
    named by `names` (a task's scenario's) or bird, bird2, …; UsageError for a mistake. A level
    without birds gets its shots all the same (the caller reports E0907)."""
    from physc.domains.angrybirds.agent_shots import agent_shot, bird_names
    from physc.domains.angrybirds.launch import Shot, Shots

    wanted = asked(aims)
    if not wanted:
        return None
    if level.birds and len(wanted) > len(level.birds):
        several = len({w.option for w in wanted}) > 1
        raise UsageError(
            f"{plural(len(wanted), 'shot')} asked for ({', '.join(w.text() for w in wanted)}), but the level has"
            f" {plural(len(level.birds), 'bird')}: one --angle, --action or --shot a bird, in the order shot"
            + ("; each of them aims a shot of its own, so give one of them for each shot" if several else "")
        )
    birds = bird_names(max(len(level.birds), len(wanted)), names)
    made = []
    for bird, want in zip(birds, wanted, strict=False):
        if want.option == "--action":
            try:
                shot = agent_shot(level, want.value, bird, want.wait)
            except ValueError as error:
                raise UsageError(f"{want.text()}: {error}") from None
            made.append(shot if want.tap is None else attrs.evolve(shot, tap=want.tap))
        elif want.option == "--angle":
            made.append(Shot(angle=want.value, tap=want.tap, bird=bird, wait=want.wait))  # type: ignore[arg-type]
        else:
            x, y, trajectory = want.value  # type: ignore[misc]
            made.append(Shot(target=(x, y), trajectory=trajectory, tap=want.tap, bird=bird, wait=want.wait))
    return made[0] if len(made) == 1 else Shots(tuple(made))


def described(action, aims, world) -> list[dict]:
    """Each shot of `action` as `physc simulate --format json` lists it: its bird, in words, its
    release angle (degrees) and stretch, its tap and wait (seconds; None: none), and what Phy-Q's
    agents send for it where --action gave it."""
    from physc.domains.angrybirds.launch import shots_of

    wanted = asked(aims)
    out = []
    for k, shot in enumerate(shots_of(action)):
        sent = wanted[k].value if k < len(wanted) and wanted[k].option == "--action" else None
        out.append(
            {
                "bird": shot.bird,
                "text": shot.text(),
                "release_angle": round(shot.release_angle(world), 4),
                "stretch": round(shot.stretch, 4),
                "tap": shot.tap,
                "wait": shot.wait,
                "agent_action": None if sent is None else list(sent),  # type: ignore[arg-type]
            }
        )
    return out
