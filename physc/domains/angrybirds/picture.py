"""Pictures of angrybirds layouts (PNG or SVG), drawn with matplotlib.

The picture shows the level as Science Birds lays it out: the ground, the
slingshot, platforms (grey; supports added by the compiler lighter), blocks
coloured by material, pigs green, the bird red, each labelled with its name.
Optional arrows show paths of moving objects (used by `physc render`).
"""

from __future__ import annotations

import io

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import patches  # noqa: E402

from physc.compiler.concrete_layout import ConcreteLayout  # noqa: E402
from physc.compiler.geometry import polygon  # noqa: E402
from physc.domains.angrybirds.catalogue import shape  # noqa: E402
from physc.domains.angrybirds.world import GROUND_TOP, LEVEL_LEFT, LEVEL_RIGHT, SLINGSHOT  # noqa: E402

MATERIAL_COLOURS = {"wood": "#c8914b", "stone": "#9a9a9a", "ice": "#9fd8f0", None: "#c8914b"}
KIND_COLOURS = {"pig": "#6cc24a", "bird": "#d9342b", "platform": "#5b5b5b"}


def draw_layout(layout: ConcreteLayout, title: str | None = None, paths=None):
    """A matplotlib figure of the layout; `paths` maps names to [(x, y), …] to draw as arrows."""
    figure, axes = plt.subplots(figsize=(12, 5.2), dpi=100)
    axes.set_xlim(LEVEL_LEFT - 0.5, LEVEL_RIGHT + 0.5)
    top = max([o.y + o.height for o in layout.objects] + [6.0])
    axes.set_ylim(GROUND_TOP - 1.2, top + 0.8)
    axes.set_aspect("equal")
    axes.add_patch(patches.Rectangle((LEVEL_LEFT, GROUND_TOP - 1.2), LEVEL_RIGHT - LEVEL_LEFT, 1.2, color="#8fbf5a", zorder=0))
    axes.add_patch(patches.Rectangle((SLINGSHOT[0] - 0.12, GROUND_TOP), 0.24, SLINGSHOT[1] + 0.9 - GROUND_TOP, color="#6b4226", zorder=1))
    for obj in layout.objects:
        if obj.concrete == "ground":
            continue
        kind = shape(obj.concrete).kind
        if kind == "platform":
            colour = "#b5b5b5" if obj.role == "support" else KIND_COLOURS["platform"]
        else:
            colour = KIND_COLOURS.get(kind, MATERIAL_COLOURS.get(obj.material, "#c8914b"))
        if shape(obj.concrete).round:
            artist = patches.Circle((obj.x, obj.y), obj.width / 2, facecolor=colour, edgecolor="black", linewidth=0.8)
        elif obj.concrete == "triangleHole":
            w, h = obj.width / 2, obj.height / 2
            artist = patches.Polygon([(obj.x - w, obj.y - h), (obj.x + w, obj.y - h), (obj.x, obj.y + h)], facecolor=colour, edgecolor="black", linewidth=0.8)
        else:
            artist = patches.Polygon(polygon(obj.points()), facecolor=colour, edgecolor="black", linewidth=0.8)
        artist.set_zorder(3)
        axes.add_patch(artist)
        label_y = obj.y + obj.height / 2 + 0.12 if kind != "platform" else obj.y - obj.height / 2 - 0.32
        axes.annotate(obj.name, (obj.x, label_y), ha="center", fontsize=7, zorder=5)
    for name, points in (paths or {}).items():
        xs, ys = zip(*points)
        axes.plot(xs, ys, linestyle="--", linewidth=1.0, color="#333333", zorder=4)
        if len(points) > 1:
            (x0, y0), (x1, y1) = points[-2], points[-1]
            axes.annotate("", (x1, y1), (x0, y0), arrowprops={"arrowstyle": "->", "color": "#333333"}, zorder=4)
    axes.set_title(title or f"{layout.scenario} (seed {layout.seed})", fontsize=10)
    axes.tick_params(labelsize=7)
    figure.tight_layout()
    return figure


def render(layout: ConcreteLayout, fmt: str = "png", title: str | None = None, paths=None) -> bytes:
    """The picture as PNG or SVG bytes (deterministic for the same layout)."""
    figure = draw_layout(layout, title, paths)
    buffer = io.BytesIO()
    metadata = {"Software": None} if fmt == "png" else {"Date": None, "Creator": None}
    figure.savefig(buffer, format=fmt, metadata=metadata)
    plt.close(figure)
    return buffer.getvalue()
