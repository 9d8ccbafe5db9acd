"""QSR definitions: each relation, the solver against the evaluator, the DNF."""

from __future__ import annotations

import random

import pytest
from middle_end import DOMAIN, pipeline, scenario_from_text

from physc.compiler.concrete_layout import Body, PlacedObject
from physc.compiler.difference import DifferenceSystem, Inconsistent
from physc.compiler.dimension_graphs import base_constraints, new_systems, point, relation_constraints
from physc.compiler.geometry import Geometry
from physc.compiler.qsr import RELATIONS
from physc.compiler.qsr_evaluate import holds

PARAMETERS = DOMAIN.layout_parameters
CLEAR, FAR = PARAMETERS.clearance, PARAMETERS.far


def placed(name, x, y, w, h, rotation=0.0):
    return PlacedObject(name, "object", "box", None, x, y, rotation, w, h)


def check(relation, a, b):
    return holds(relation, a, b, CLEAR, FAR)


# ---- the definitions, on hand-made coordinates -------------------------------------
@pytest.mark.parametrize(
    "relation, a",
    [
        ("N", placed("a", 0.2, 2.0, 1, 1)),
        ("NE", placed("a", 2.0, 2.0, 1, 1)),
        ("E", placed("a", 2.0, 0.3, 1, 1)),
        ("SE", placed("a", 2.0, -2.0, 1, 1)),
        ("S", placed("a", -0.3, -2.0, 1, 1)),
        ("SW", placed("a", -2.0, -2.0, 1, 1)),
        ("W", placed("a", -2.0, 0.0, 1, 1)),
        ("NW", placed("a", -2.0, 2.0, 1, 1)),
        ("FarN", placed("a", 0.0, 4.0, 1, 1)),
        ("FarNE", placed("a", 4.0, 4.0, 1, 1)),
        ("FarW", placed("a", -4.0, 0.2, 1, 1)),
        ("MeetN", placed("a", 0.0, 1.0, 0.5, 1)),
        ("MeetDuringW", placed("a", -0.6, 1.0, 0.5, 1)),
        ("MeetDuringE", placed("a", 0.6, 1.0, 0.5, 1)),
        ("MeetNW", placed("a", -2.0, 0.25, 2, 0.5)),
        ("MeetW", placed("a", -2.0, 0.0, 2, 0.5)),
        ("MeetSW", placed("a", -2.0, -0.25, 2, 0.5)),
    ],
)
def test_relation_on_coordinates(relation, a):
    b = placed("b", 0.0, 0.0, 2.0, 1.0)  # spans x in [-1, 1], y in [-0.5, 0.5]
    assert check(relation, a, b)
    # The eight tiles are mutually exclusive.
    tiles = ["N", "NE", "E", "SE", "S", "SW", "W", "NW"]
    if relation in tiles:
        assert [t for t in tiles if check(t, a, b)] == [relation]


def test_near_is_not_far():
    b = placed("b", 0.0, 0.0, 2.0, 1.0)
    near = placed("a", 0.0, 1.5, 1, 1)  # 0.5 above b
    assert check("N", near, b) and not check("FarN", near, b)


def test_meet_nw_on_a_rotated_platform():
    b = placed("b", 0.0, 0.0, 3.0, 0.32, rotation=-20.0)
    from physc.compiler.qsr_evaluate import five_points

    ul = five_points(0.0, 0.0, 3.0, 0.32, -20.0)["ul"]
    a = placed("a", ul.real - 1.0, ul.imag - 0.16, 2.0, 0.32)  # its upper-right point at b's upper-left
    assert check("MeetNW", a, b) and not check("MeetSW", a, b)


# ---- the solver's constraints agree with the evaluator -----------------------------
def two_bodies(rotation=0.0):
    return {
        "a": Body("a", "object", "box", Geometry(0.8, 0.5)),
        "b": Body("b", "object", "box", Geometry(2.0, 0.4, rotation)),
    }


def solve(relations, bodies, seed):
    systems = new_systems(bodies)
    for c in base_constraints(bodies, PARAMETERS):
        systems[c.axis].add(c.u, c.v, c.weight)
    for relation, a, b in relations:
        for c in relation_constraints(relation, bodies[a], bodies[b], PARAMETERS, ""):
            systems[c.axis].add(c.u, c.v, c.weight)
    rng = random.Random(seed)
    centres = {}
    for name in bodies:
        values = []
        for axis in ("x", "y"):
            low, high = systems[axis].bounds(point(name, "c"))
            value = rng.uniform(low, high)
            systems[axis].fix(point(name, "c"), value)
            values.append(value)
        centres[name] = values
    return {n: placed(n, *centres[n], b.geometry.width, b.geometry.height, b.geometry.rotation) for n, b in bodies.items()}


@pytest.mark.parametrize("relation", sorted(RELATIONS))
@pytest.mark.parametrize("rotation", [0.0, 20.0, -35.0])
def test_solver_placements_satisfy_the_definition(relation, rotation):
    for seed in range(20):
        objects = solve([(relation, "a", "b")], two_bodies(rotation), seed)
        assert check(relation, objects["a"], objects["b"]), (relation, rotation, seed)


def test_papers_dimension_graph_example_is_consistent():
    bodies = {n: Body(n, "object", "box", Geometry(1.0, 1.0)) for n in "abc"}
    objects = solve([("N", "a", "b"), ("NE", "b", "c"), ("SW", "c", "a")], bodies, seed=3)
    assert check("N", objects["a"], objects["b"])
    assert check("NE", objects["b"], objects["c"])
    assert check("SW", objects["c"], objects["a"])


@pytest.mark.parametrize(
    "relations",
    [
        [("N", "a", "b"), ("N", "b", "c"), ("N", "c", "a")],  # a cycle of "above"
        [("N", "a", "b"), ("S", "a", "b")],
        [("E", "a", "b"), ("W", "a", "c"), ("W", "c", "b")],  # b < a < c < b
    ],
)
def test_contradictory_conjunctions_are_negative_cycles(relations):
    bodies = {n: Body(n, "object", "box", Geometry(1.0, 1.0)) for n in "abc"}
    with pytest.raises(Inconsistent):
        solve(relations, bodies, seed=0)


def test_difference_system_bounds():
    system = DifferenceSystem(["0", "x", "y"])
    system.add("0", "x", 5)  # x <= 5
    system.add("x", "0", 1)  # x >= -1
    system.add("x", "y", -2)  # y <= x - 2
    assert system.bounds("x") == (-1, 5)
    assert system.bounds("y") == (-float("inf"), 3)
    with pytest.raises(Inconsistent):
        system.add("y", "x", 1)  # x <= y + 1 contradicts y <= x - 2


# ---- the DNF ---------------------------------------------------------------------------
def test_dnf_size_is_exact_and_lazy():
    dnf = pipeline("RRF").qsr
    expected = 1
    for clause in dnf.clauses:
        expected *= len(clause.relations)
    assert dnf.size == expected == 11664
    first = list(zip(range(5), dnf.conjunctions()))
    assert [c for _, c in first] == [dnf.conjunction(i) for i in range(5)]


def test_astronomically_large_dnf_is_never_expanded():
    hits = " > ".join(f"hit(bird, pig{i}, any) > destroy(bird, pig{i})" for i in range(60))
    scenario = scenario_from_text(f"scenario MANY {{ interactions {{ {hits} }} }}")
    from physc.driver.pipeline import Pipeline

    dnf = Pipeline(DOMAIN, scenario, 0).qsr
    assert dnf.size == 8**60 * 3**60
    assert len(dnf.conjunction(dnf.size - 1)) == len(dnf.clauses)


def test_the_seed_orders_the_conjunctions():
    assert pipeline("RF", 1).qsr.conjunction(0) != pipeline("RF", 2).qsr.conjunction(0) or (
        pipeline("RF", 1).qsr.conjunction(1) != pipeline("RF", 2).qsr.conjunction(1)
    )
    assert pipeline("RF", 7).qsr.conjunction(0) == pipeline("RF", 7).qsr.conjunction(0)
