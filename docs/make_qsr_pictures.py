"""Draw one picture per QSR for docs/qsr.md:  python docs/make_qsr_pictures.py

Each picture places object a (blue) relative to the reference object b (grey)
with physc's own solver (`physc.compiler.dimension_graphs`): b is fixed at the
origin, and a's centre is put in the middle of the interval its constraints
allow on each axis. Dotted lines mark b's extent (the tiles of the directional
relations); the five points of both objects are drawn. The result is checked
with the reference evaluator before it is saved.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import patches  # noqa: E402

from physc.compiler.concrete_layout import Body, PlacedObject  # noqa: E402
from physc.compiler.dimension_graphs import (  # noqa: E402
    LayoutParameters,
    base_constraints,
    new_systems,
    point,
    relation_constraints,
)
from physc.compiler.geometry import Geometry, polygon  # noqa: E402
from physc.compiler.qsr import RELATIONS  # noqa: E402
from physc.compiler.qsr_evaluate import holds  # noqa: E402

OUT = Path(__file__).resolve().parent / "images" / "qsr"
PARAMETERS = LayoutParameters(clearance=0.3, far=1.5, left=-6.0, right=6.0, bottom=-3.5, top=3.5)


def place(relation: str, rotation: float) -> dict[str, PlacedObject]:
    small = relation.startswith("Meet") and relation not in ("MeetNW", "MeetW", "MeetSW")
    bodies = {
        "b": Body("b", "object", "box", Geometry(3.0, 0.8, rotation), fixed=(0.0, 0.0)),
        "a": Body("a", "object", "box", Geometry(0.8 if small else 1.6, 0.8 if small else 0.6)),
    }
    systems = new_systems(bodies)
    for c in base_constraints(bodies, PARAMETERS) + relation_constraints(relation, bodies["a"], bodies["b"], PARAMETERS, ""):
        systems[c.axis].add(c.u, c.v, c.weight)
    centre = []
    for axis in ("x", "y"):
        low, high = systems[axis].bounds(point("a", "c"))
        value = (low + high) / 2
        systems[axis].fix(point("a", "c"), value)
        centre.append(value)
    return {
        "a": PlacedObject("a", "object", "box", None, centre[0], centre[1], 0.0, bodies["a"].geometry.width, bodies["a"].geometry.height),
        "b": PlacedObject("b", "object", "box", None, 0.0, 0.0, rotation, 3.0, 0.8),
    }


def draw(relation: str) -> Path:
    rotation = -20.0 if relation in ("MeetNW", "MeetW", "MeetSW") else 0.0
    objects = place(relation, rotation)
    assert holds(relation, objects["a"], objects["b"], PARAMETERS.clearance, PARAMETERS.far), relation
    figure, axes = plt.subplots(figsize=(3.6, 2.4), dpi=90)
    for name, colour in (("b", "#bdbdbd"), ("a", "#6baed6")):
        obj = objects[name]
        axes.add_patch(patches.Polygon(polygon(obj.points()), facecolor=colour, edgecolor="black", linewidth=0.8))
        for label, (x, y) in obj.points().items():
            axes.plot(x, y, "k.", markersize=3)
            if name == "a" or relation.startswith("Meet"):
                axes.annotate(label, (x, y), fontsize=5, xytext=(2, 2), textcoords="offset points")
        axes.annotate(name, (obj.x, obj.y), ha="center", va="center", fontsize=9, weight="bold")
    b = objects["b"]
    xs = [p[0] for p in b.points().values()]
    ys = [p[1] for p in b.points().values()]
    for x in (min(xs), max(xs)):
        axes.axvline(x, color="#999999", linestyle=":", linewidth=0.7)
    for y in (min(ys), max(ys)):
        axes.axhline(y, color="#999999", linestyle=":", linewidth=0.7)
    axes.set_xlim(-6.3, 6.3)
    axes.set_ylim(-3.8, 3.8)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(f"{relation}(a, b)", fontsize=9)
    figure.tight_layout()
    path = OUT / f"{relation}.png"
    figure.savefig(path, metadata={"Software": None})
    plt.close(figure)
    return path


if __name__ == "__main__":
    OUT.mkdir(parents=True, exist_ok=True)
    for relation in RELATIONS:
        print(draw(relation).relative_to(OUT.parent.parent))
