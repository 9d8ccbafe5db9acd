"""Dimension graphs: the X and Y constraint graphs of a conjunction of QSRs.

Nodes are point coordinates: for every object its five points (ll, c, ur, ul,
lr) on that axis, plus the origin `0`. An edge u → v of weight w is the
difference constraint v − u ≤ w. Three kinds of edges:

* shape: each point is the centre plus a constant (both directions: an equality);
* bounds: corners stay inside the placement area; fixed objects stay put;
* QSR atoms of the chosen conjunction, and separations added by placement.

A conjunction is consistent exactly when neither graph has a negative cycle
(`physc.compiler.difference`).
"""

from __future__ import annotations

import attrs

from physc.compiler.concrete_layout import Body, ChosenRelation
from physc.compiler.difference import DifferenceSystem
from physc.compiler.geometry import CORNERS, POINTS
from physc.compiler.qsr import RELATIONS, Atom, feature_terms

AXES = ("x", "y")


@attrs.frozen
class LayoutParameters:
    """The domain's distances for QSRs and the area objects are placed in."""

    clearance: float  # the least gap of a directional relation
    far: float  # the least gap of a Far relation
    left: float
    right: float
    bottom: float
    top: float

    def gap(self, name: str) -> float:
        if name == "0":
            return 0.0
        sign = -1.0 if name[0] == "-" else 1.0
        return sign * {"clearance": self.clearance, "far": self.far}[name[1:]]


@attrs.frozen
class Constraint:
    """v − u ≤ weight on one axis, and why."""

    axis: str
    u: str
    v: str
    weight: float
    reason: str


def point(obj: str, name: str) -> str:
    return f"{obj}.{name}"


def _axis_index(axis: str) -> int:
    return 0 if axis == "x" else 1


def _extreme(body: Body, axis: str, which: str) -> str:
    k = _axis_index(axis)
    offsets = [(body.geometry.offset(p)[k], p) for p in CORNERS]
    value = min(offsets)[0] if which == "min" else max(offsets)[0]
    return next(p for off, p in offsets if abs(off - value) < 1e-12)


def resolve(body: Body, axis: str, feature: str) -> tuple[str, float]:
    """A feature as (node, constant): the feature's value is node + constant."""
    terms = feature_terms(feature)
    k = _axis_index(axis)
    names = {p: (_extreme(body, axis, p) if p in ("min", "max") else p) for p in terms}
    if len(terms) == 1:
        return point(body.name, names[next(iter(terms))]), 0.0
    constant = sum(weight * body.geometry.offset(names[p])[k] for p, weight in terms.items())
    return point(body.name, "c"), constant


def atom_constraints(atom: Atom, a: Body, b: Body, parameters: LayoutParameters, reason: str) -> list[Constraint]:
    left, right = (
        ((b, atom.feature_b), (a, atom.feature_a)) if atom.swapped else ((a, atom.feature_a), (b, atom.feature_b))
    )
    node_l, const_l = resolve(left[0], atom.axis, left[1])
    node_r, const_r = resolve(right[0], atom.axis, right[1])
    gap = parameters.gap(atom.gap)
    # left + cl <= right + cr + gap   ⟺   left − right <= cr − cl + gap
    out = [Constraint(atom.axis, node_r, node_l, const_r - const_l + gap, reason)]
    if atom.op == "=":
        out.append(Constraint(atom.axis, node_l, node_r, const_l - const_r - gap, reason))
    return out


def relation_constraints(relation: str, a: Body, b: Body, parameters: LayoutParameters, why: str) -> list[Constraint]:
    out = []
    for atom in RELATIONS[relation]:
        text = f"{relation}({a.name}, {b.name}): {atom.text(a.name, b.name)}"
        out += atom_constraints(atom, a, b, parameters, f"{text}  [{why}]" if why else text)
    return out


def base_constraints(bodies: dict[str, Body], parameters: LayoutParameters) -> list[Constraint]:
    out = []
    for body in bodies.values():
        centre = point(body.name, "c")
        for axis in AXES:
            k = _axis_index(axis)
            for p in POINTS:
                if p == "c":
                    continue
                offset = body.geometry.offset(p)[k]
                out.append(Constraint(axis, centre, point(body.name, p), offset, f"shape of {body.name}"))
                out.append(Constraint(axis, point(body.name, p), centre, -offset, f"shape of {body.name}"))
            if body.fixed is not None:
                value = body.fixed[k]
                out.append(Constraint(axis, "0", centre, value, f"{body.name} is fixed"))
                out.append(Constraint(axis, centre, "0", -value, f"{body.name} is fixed"))
                continue
            low, high = (parameters.left, parameters.right) if axis == "x" else (parameters.bottom, parameters.top)
            for p in CORNERS:
                out.append(Constraint(axis, "0", point(body.name, p), high, "placement area"))
                out.append(Constraint(axis, point(body.name, p), "0", -low, "placement area"))
    return out


def new_systems(bodies: dict[str, Body]) -> dict[str, DifferenceSystem]:
    names = ["0"] + [point(b, p) for b in bodies for p in POINTS]
    return {axis: DifferenceSystem(names) for axis in AXES}


@attrs.frozen
class DimensionGraphs:
    scenario: str
    seed: int
    dnf_size: int
    conjunctions_tried: int  # over all shape draws so far
    conjunctions_rejected: int
    shape_draws: int  # how many times shapes were drawn (each draw searches the DNF anew)
    conjunction: tuple[ChosenRelation, ...]
    bodies: tuple[Body, ...]
    constraints: tuple[Constraint, ...]  # every edge of both graphs
    systems: dict = attrs.field(eq=False, repr=False, metadata={"dump": False})  # axis → DifferenceSystem

    def edges(self, axis: str) -> tuple[Constraint, ...]:
        return tuple(c for c in self.constraints if c.axis == axis)

    def to_dot(self) -> str:
        lines = [f'digraph "{self.scenario}" {{', "  rankdir=LR;"]
        for axis in AXES:
            lines.append(f'  subgraph "cluster_{axis}" {{ label="{axis.upper()} graph";')
            for c in self.edges(axis):
                if c.reason.startswith("shape of") or c.reason == "placement area":
                    continue
                lines.append(f'    "{axis}:{c.u}" -> "{axis}:{c.v}" [label="{c.weight:.3g}"];')
            lines.append("  }")
        lines.append("}")
        return "\n".join(lines) + "\n"
