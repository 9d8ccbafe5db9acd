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
LONGEST_DRAG = 200  # pixels: the longest drag searched (Phy-Q's DQN agent drags 200 pixels)


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


def reference_point(slingshot, camera_y, max_width, screen=SCREEN):
    """The framework's `sling_center`: from the ground truth's slingshot box (edges rounded
    to whole pixels as the game rounds them), X + 0.45·w, Y + 0.35·w, truncated."""
    left, right, bottom, top = SLINGSHOT_BOX
    x_left = round(to_screen((slingshot[0] + left, 0.0), camera_y, max_width, screen)[0])
    x_right = round(to_screen((slingshot[0] + right, 0.0), camera_y, max_width, screen)[0])
    y_top = round(to_screen((0.0, slingshot[1] + top), camera_y, max_width, screen)[1])
    width = x_right - x_left
    return int(x_left + REFERENCE[0] * width), int(y_top + REFERENCE[1] * width)


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


def agent_action(angle, slingshot, camera_y, max_width, screen=SCREEN, reference=None):
    """([dx, dy, 0], the angle the game launches it at): the whole-pixel action whose launch
    angle is nearest `angle`, among full-stretch drags that keep the release point on the
    screen, the shorter first among equals. The tap time is 0: no tap (a red bird has none)."""
    ref = reference or reference_point(slingshot, camera_y, max_width, screen)
    scale = view(camera_y, max_width, screen)[0]
    shortest = math.ceil(DRAG_RADIUS * scale) + 2
    best = None
    for length in range(shortest, LONGEST_DRAG + 1):
        dx, dy = drag(angle, slingshot, camera_y, max_width, length, screen, ref)
        for x in (math.floor(dx), math.ceil(dx)):
            for y in (math.floor(dy), math.ceil(dy)):
                pixel = (ref[0] + x, ref[1] - y)
                if not (0 <= pixel[0] < screen[0] and 0 <= pixel[1] < screen[1]):
                    continue
                launched, stretch = launch_angle((x, y), slingshot, camera_y, max_width, screen, ref)
                if stretch < 1.0:
                    continue
                error = abs(launched - angle)
                if best is None or error < best[0] - 1e-12:
                    best = (error, [x, y, 0], launched)
    if best is None:
        raise ValueError(f"no full-stretch drag at {angle:g}° keeps the release point on the screen")
    return best[1], best[2]
