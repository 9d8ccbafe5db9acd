"""A release angle as the shot Phy-Q's agent framework sends: a drag in screen pixels.

Phy-Q's agents shoot with `env.step([dx, dy, tap_time])` (phy-q/benchmark
`sciencebirdsagents/SBEnvironment/SBEnvironmentWrapper.py` `step`): a release point in screen
pixels relative to the slingshot's reference point, y up, each truncated to an integer. The
game (`AIBirdsConnection.cs` `TapShoot`, `HUD.cs`, `ABBird.cs` `DragBird`/`LaunchBird`) reads
that point back into the world with the camera, drags the bird there from its rest point
(clamped to the drag radius, 1 unit) and launches it at 10 units/s times the stretch, away
from the point. So a full-stretch shot at angle θ is any release point at least one unit from
the rest point, on the ray from it at θ + 180°. docs/angrybirds.md ("Playing a task in Phy-Q's
game") cites each step and value.

Phy-Q's agents aim in two ways, and a task must hold for both (physc.search.precision): the
DQN agent drags AGENT_DRAG pixels from the reference point (`agent_action`: the whole pixel
there whose launch is nearest the angle; `neighbours`: the 8 pixels around it), and the
trajectory planner's `find_release_point` releases PLANNER_STRETCH slingshot heights from it,
truncated (`planner_release`).

The functions here use only `math`, so that the replay script a dataset ships
(physc.domains.angrybirds.phyq_levels) carries their source as it is into the agents'
own Python: `drag` and `launch_angle` are the exact geometry (floats); `agent_action` the
integer action nearest the angle, with the angle the game will launch it at.
"""

import math

SCREEN = (840, 480)  # the game's window, ProjectSettings.asset `defaultScreenWidth`, `defaultScreenHeight`
REST_OFFSET = (-0.15, 0.8)  # the bird's rest point from the slingshot: −ABConstants.SLING_SELECT_POS
DRAG_RADIUS = 1.0  # BirdRed.prefab `_dragRadius`: a drag this long or longer is full stretch
# The slingshot's box as the game's ground truth reports it (SymbolicGameState.cs: the left and
# top edges of `slingshot_front`'s sprite, the right and bottom of `slingshot_back`'s; the
# sprites' rects in effects.png.meta at 100 pixels a unit, their places in Slingshot.prefab),
# in units from the slingshot: left, right, bottom, top.
SLINGSHOT_BOX = (-0.485, 0.2, -1.005, 1.05)
REFERENCE = (0.45, 0.35)  # trajectory_planner.py `get_reference_point`: X + 0.45·w, Y + 0.35·w (both of the width)
# DQNDiscreteAgent.py `__degToShot`: [200·cos(deg), 200·sin(deg)], truncated by the wrapper's `step`
AGENT_DRAG = 200  # pixels from the reference point: the drag Phy-Q's agents send
PLANNER_STRETCH = 5  # trajectory_planner.py `find_release_point`: `mag = sling.height * 5` pixels


def view(camera_y, max_width, screen=SCREEN):
    """(pixels a unit, camera centre) of the game's camera zoomed out fully, as the agent
    framework leaves it after loading a level (`fully_zoom_out`): the level's `maxWidth`
    across the screen, centred at x 0 and the level's camera y (ABGameplayCamera.cs)."""
    return screen[0] / max_width, (0.0, camera_y)


def to_screen(point, camera_y, max_width, screen=SCREEN):
    """A world point in the agent's screen pixels (origin top left, y down)."""
    scale, centre = view(camera_y, max_width, screen)
    x = (point[0] - centre[0]) * scale + screen[0] / 2
    y = (point[1] - centre[1]) * scale + screen[1] / 2
    return x, screen[1] - y


def to_world(pixel, camera_y, max_width, screen=SCREEN):
    """The inverse of `to_screen`: what the game's ScreenToWorldPoint makes of an agent's pixel."""
    scale, centre = view(camera_y, max_width, screen)
    return (pixel[0] - screen[0] / 2) / scale + centre[0], (screen[1] - pixel[1] - screen[1] / 2) / scale + centre[1]


def sling_box(slingshot, camera_y, max_width, screen=SCREEN):
    """The ground truth's slingshot box as the framework reads it: (X, Y, width, height) in
    screen pixels, X and Y its top left, each edge rounded to a whole pixel as the game rounds
    it (the wrapper swaps `cv_utils.Rectangle`'s width and height back to these)."""
    left, right, bottom, top = SLINGSHOT_BOX
    x_left = round(to_screen((slingshot[0] + left, 0.0), camera_y, max_width, screen)[0])
    x_right = round(to_screen((slingshot[0] + right, 0.0), camera_y, max_width, screen)[0])
    y_top = round(to_screen((0.0, slingshot[1] + top), camera_y, max_width, screen)[1])
    y_bottom = round(to_screen((0.0, slingshot[1] + bottom), camera_y, max_width, screen)[1])
    return x_left, y_top, x_right - x_left, y_bottom - y_top


def reference_point(slingshot, camera_y, max_width, screen=SCREEN):
    """The framework's `sling_center`: from the ground truth's slingshot box (`sling_box`),
    X + 0.45·w, Y + 0.35·w, truncated."""
    x, y, width, _ = sling_box(slingshot, camera_y, max_width, screen)
    return int(x + REFERENCE[0] * width), int(y + REFERENCE[1] * width)


def rest_point(slingshot):
    return slingshot[0] + REST_OFFSET[0], slingshot[1] + REST_OFFSET[1]


def launch_angle(action, slingshot, camera_y, max_width, screen=SCREEN, reference=None):
    """The release angle (degrees) and stretch (0 to 1) the game launches the agent's action
    `[dx, dy, …]` at: its release point, truncated as the framework truncates it, read back
    into the world, the bird dragged there from its rest point."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    pixel = (int(ref[0] + int(action[0])), int(ref[1] - int(action[1])))
    released = to_world(pixel, camera_y, max_width, screen)
    rest = rest_point(slingshot)
    pull = (rest[0] - released[0], rest[1] - released[1])
    return math.degrees(math.atan2(pull[1], pull[0])), min(math.hypot(*pull) / DRAG_RADIUS, 1.0)


def drag(angle, slingshot, camera_y, max_width, length, screen=SCREEN, reference=None):
    """The release point of a full-stretch shot at `angle`, `length` pixels from the rest
    point, as the agent's (dx, dy) from the reference point, in exact (fractional) pixels."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    rest = to_screen(rest_point(slingshot), camera_y, max_width, screen)
    theta = math.radians(angle)
    x, y = rest[0] - length * math.cos(theta), rest[1] + length * math.sin(theta)
    return x - ref[0], ref[1] - y


def agent_length(angle, slingshot, camera_y, max_width, screen=SCREEN, reference=None):
    """The length (pixels from the rest point) of the full-stretch drag at `angle` whose
    release point lies AGENT_DRAG pixels from the reference point, as Phy-Q's agents drag."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    rest = to_screen(rest_point(slingshot), camera_y, max_width, screen)
    theta = math.radians(angle)
    offset = (rest[0] - ref[0], ref[1] - rest[1])  # the rest point from the reference point, y up
    along = -offset[0] * math.cos(theta) - offset[1] * math.sin(theta)
    return -along + math.sqrt(along * along - offset[0] ** 2 - offset[1] ** 2 + AGENT_DRAG**2)


def agent_action(angle, slingshot, camera_y, max_width, screen=SCREEN, reference=None):
    """([dx, dy, 0], the angle the game launches it at): of the whole pixels around the exact
    full-stretch drag at `angle` AGENT_DRAG pixels from the reference point (the floor and the
    ceiling of each of dx and dy), the one whose launch angle is nearest `angle`. The release
    point may lie off the screen (the game reads any point back into the world; the DQN agent's
    own drags do). The tap time is 0: no tap (a red bird has none)."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    length = agent_length(angle, slingshot, camera_y, max_width, screen, ref)
    dx, dy = drag(angle, slingshot, camera_y, max_width, length, screen, ref)
    best = None
    for x in (math.floor(dx), math.ceil(dx)):
        for y in (math.floor(dy), math.ceil(dy)):
            launched, stretch = launch_angle((x, y), slingshot, camera_y, max_width, screen, ref)
            error = abs(launched - angle)
            if stretch >= 1.0 and (best is None or error < best[0] - 1e-12):
                best = (error, [x, y, 0], launched)
    if best is None:
        raise ValueError(f"no whole-pixel drag of {AGENT_DRAG} pixels at {angle:g}° is at full stretch")
    return best[1], best[2]


def neighbours(action):
    """The 8 whole pixels around an action's release point, as [dx, dy, tap] (its tap kept)."""
    return [[action[0] + i, action[1] + j, *action[2:]] for i in (-1, 0, 1) for j in (-1, 0, 1) if (i, j) != (0, 0)]


def planner_release(angle, slingshot, camera_y, max_width, screen=SCREEN, reference=None):
    """[dx, dy, 0]: the release point `find_release_point(sling, θ)` of Phy-Q's trajectory
    planner gives for `angle` (θ), PLANNER_STRETCH times the box's height from the reference
    point, each coordinate truncated, as the action from the reference point."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    magnitude = sling_box(slingshot, camera_y, max_width, screen)[3] * PLANNER_STRETCH
    theta = math.radians(angle)
    release = (int(ref[0] - magnitude * math.cos(theta)), int(ref[1] + magnitude * math.sin(theta)))
    return [release[0] - ref[0], ref[1] - release[1], 0]
