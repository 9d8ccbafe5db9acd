"""Pictures of angrybirds layouts (PNG or SVG), drawn with matplotlib.

The picture shows a level as Science Birds lays it out: the ground, the
slingshot, platforms (dark grey; supports the compiler added light grey), blocks
coloured by material (wood, stone, ice), pigs green, each labelled with its name, and
the level's birds in the game's colours at their own sizes (birds.py: red, blue, yellow,
black, white): the first at the slingshot, the others waiting on the ground behind it,
named as traces name them (bird2, bird3, …). Optional dashed arrows show the paths of
moving objects, like the paper's figure of its 16 generated tasks (`physc render --shot …`).
"""

from __future__ import annotations

import math

import matplotlib
import matplotlib.pyplot as plt
from matplotlib import patches

from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.angrybirds.catalogue import BY_PREFAB, extent
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.to_level import level_from_layout
from physc.picture import save  # noqa: F401 - angrybirds' pictures are saved as every domain's

matplotlib.use("Agg")  # drawn off-screen; pyplot resolves its backend lazily, so Agg it is

MATERIAL_COLOURS = {"wood": "#c8914b", "stone": "#9a9a9a", "ice": "#9fd8f0"}
KIND_COLOURS = {"pig": "#6cc24a", "bird": "#d9342b", "platform": "#5b5b5b", "tnt": "#d62728"}
# Each bird's colour in the game (its prefab's sprite), by prefab (birds.BIRDS): a white bird
# and a black one keep a black edge, as every bird does.
BIRD_COLOURS = {
    "BirdRed": KIND_COLOURS["bird"],
    "BirdBlue": "#5aa9e6",
    "BirdYellow": "#f4d03f",
    "BirdBlack": "#2b2b2b",
    "BirdWhite": "#f4f4f4",
}
QUEUE_STEP = 0.7  # units between the birds waiting behind the slingshot


def _outline(obj: LevelObject):
    """The patch of a level object, from its catalogue shape."""
    catalogue = BY_PREFAB[obj.type]
    angle = math.radians(obj.rotation or 0.0)
    cos, sin = math.cos(angle), math.sin(angle)
    if catalogue.kind == "platform":
        w, h = (size / 2 for size in extent(obj))
        points = ((-w, -h), (w, -h), (w, h), (-w, h))
    elif catalogue.round:
        return patches.Circle((obj.x, obj.y), catalogue.width / 2)
    else:
        points = catalogue.outline_points()
    return patches.Polygon([(obj.x + px * cos - py * sin, obj.y + px * sin + py * cos) for px, py in points])


def picture_top(level: Level) -> float:
    """The upper edge of a level's picture: above its highest object, and never below 6.5."""
    return max([o.y + 1.0 for o in level.objects] + [6.0]) + 0.5


def draw_level(
    level: Level,
    world,
    title: str = "",
    paths=None,
    supports=frozenset(),
    bird: bool | tuple[float, float] = True,
    top: float | None = None,
):
    """A matplotlib figure of a level in `world` (its frame: bounds, ground, the bird's rest);
    `paths` maps names to [(x, y), …], drawn as arrows. `bird`: drawn at rest (True), at a
    point (x, y), or not at all (False); `top`: the picture's upper edge (by default above
    the highest object), so that the frames of one play share their scale."""
    frame = world.frame
    left, right, ground = frame.left, frame.right, frame.ground_top
    figure, axes = plt.subplots(figsize=(12, 5.2), dpi=100)
    axes.set_xlim(left - 0.5, right + 0.5)
    axes.set_ylim(ground - 1.2, top if top is not None else picture_top(level))
    axes.set_aspect("equal")
    axes.add_patch(patches.Rectangle((left, ground - 1.2), right - left, 1.2, color="#8fbf5a", zorder=0))
    sling_x, sling_y = level.slingshot
    axes.add_patch(patches.Rectangle((sling_x - 0.12, ground), 0.24, sling_y + 0.9 - ground, color="#6b4226", zorder=1))
    _draw_birds(axes, level, world, bird)
    for obj in level.objects:
        kind = BY_PREFAB[obj.type].kind
        if kind == "platform":
            colour = "#b5b5b5" if obj.name in supports else KIND_COLOURS["platform"]
        elif kind == "block":
            colour = MATERIAL_COLOURS.get(obj.material or "", "#c8914b")
        else:
            colour = KIND_COLOURS[kind]
        artist = _outline(obj)
        artist.set_facecolor(colour)
        artist.set_edgecolor("black")
        artist.set_linewidth(0.8)
        artist.set_zorder(3)
        axes.add_patch(artist)
        if obj.name:
            axes.annotate(
                obj.name,
                (obj.x, obj.y),
                ha="center",
                va="center",
                fontsize=6,
                zorder=6,
                bbox={"boxstyle": "round,pad=0.1", "fc": "white", "alpha": 0.6, "lw": 0},
            )
    for points in (paths or {}).values():
        if len(points) < 2:
            continue
        xs, ys = zip(*points, strict=False)
        axes.plot(xs, ys, linestyle="--", linewidth=1.0, color="#333333", zorder=4)
        axes.annotate(
            "", points[-1], points[-2], arrowprops={"arrowstyle": "->", "color": "#333333", "lw": 1.2}, zorder=4
        )
    axes.set_title(title, fontsize=10)
    axes.tick_params(labelsize=7)
    figure.tight_layout()
    return figure


def bird_colour(prefab: str) -> str:
    """The colour a bird of `prefab` is drawn in (BIRD_COLOURS; red for a prefab physc does not know)."""
    return BIRD_COLOURS.get(prefab, KIND_COLOURS["bird"])


def _draw_birds(axes, level: Level, world, bird) -> None:
    """The level's birds, each in its colour and at its size: the first at the slingshot's rest
    point (`bird` True), at a point (`bird` (x, y)) or not at all (False); the others waiting
    on the ground behind the slingshot, in the order they are shot, labelled bird2, bird3, …"""
    from physc.domains.angrybirds.birds import BY_PREFAB as BIRDS

    ground, sling_x = world.frame.ground_top, level.slingshot[0]
    for k, prefab in enumerate(level.birds or ("BirdRed",)):
        radius = BIRDS[prefab].radius if prefab in BIRDS else 0.17
        if k == 0:
            if bird is False:
                continue
            centre = world.launch.bird_rest if bird is True else bird
        else:
            centre = (sling_x - 0.5 - QUEUE_STEP * k, ground + radius)
        circle = patches.Circle(centre, radius, facecolor=bird_colour(prefab), edgecolor="black", zorder=3)
        axes.add_patch(circle)
        if k:
            axes.annotate(f"bird{k + 1}", (centre[0], centre[1] + radius + 0.25), ha="center", fontsize=5, zorder=6)


def render(layout: ConcreteLayout, fmt: str, world, title: str | None = None, paths=None) -> bytes:
    """A picture of a concrete layout: as the Science Birds level it becomes in `world`."""
    supports = frozenset(o.name for o in layout.objects if o.role == "support")
    figure = draw_level(
        level_from_layout(layout), world, title or f"{layout.scenario} (seed {layout.seed})", paths, supports
    )
    return save(figure, fmt)
