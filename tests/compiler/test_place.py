"""place: every layout satisfies its QSRs, stands, stays apart, is reproducible and varied."""

from __future__ import annotations

import itertools
import json

import pytest
from conftest import EXAMPLES, run_physc
from middle_end import DOMAIN, paper_scenarios, pipeline

from physc.compiler.geometry import overlap_depth, polygon
from physc.compiler.qsr_evaluate import holds
from physc.serialize import dumps

NAMES = list(paper_scenarios())
PARAMETERS = DOMAIN.layout_parameters
SEEDS = range(25)


def check_layout(layout):
    objects = {o.name: o for o in layout.objects}
    for chosen in layout.conjunction + layout.separations:
        a, b = objects[chosen.a], objects[chosen.b]
        assert holds(chosen.relation, a, b, PARAMETERS.clearance, PARAMETERS.far), chosen
    solid = [o for o in layout.objects if o.concrete != "ground"]
    for first, second in itertools.combinations(solid, 2):
        depth = overlap_depth(polygon(first.points()), polygon(second.points()))
        assert depth <= 1e-5, (first.name, second.name, depth)
    for o in solid:
        if o.role == "player":
            continue
        xs = [p[0] for p in o.points().values()]
        ys = [p[1] for p in o.points().values()]
        assert PARAMETERS.left - 1e-6 <= min(xs) and max(xs) <= PARAMETERS.right + 1e-6, o.name
        assert PARAMETERS.bottom - 1e-6 <= min(ys) and max(ys) <= PARAMETERS.top + 1e-6, o.name


@pytest.mark.parametrize("name", NAMES)
def test_every_layout_satisfies_its_conjunction(name):
    for seed in SEEDS:
        check_layout(pipeline(name, seed).placed.layout)


@pytest.mark.parametrize("name", NAMES)
def test_every_dynamic_object_rests_on_its_support(name):
    layout = pipeline(name, 5).placed.layout
    graph = pipeline(name, 5).layout_graph
    dynamic = {n.name for n in graph.nodes if not n.static and n.role == "object"}
    resting = {c.a for c in layout.conjunction if c.relation in ("MeetN", "MeetDuringW", "MeetDuringE")}
    assert dynamic <= resting
    objects = {o.name: o for o in layout.objects}
    for c in layout.conjunction:
        if c.relation.startswith("MeetDuring") or c.relation == "MeetN":
            support = objects[c.b]
            assert support.rotation == 0.0
            assert abs((objects[c.a].y - objects[c.a].height / 2) - (support.y + support.height / 2)) < 1e-5


def test_the_birds_target_is_within_reach():
    for name in NAMES:
        layout = pipeline(name, 3).placed.layout
        target = {o.name: o for o in layout.objects}[DOMAIN.reach_targets(paper_scenarios()[name])[0]]
        assert any(DOMAIN.reachable(*p) for p in target.points().values()), name


@pytest.mark.parametrize("name", ["SF", "RS", "RRR"])
def test_same_seed_same_bytes(name):
    assert dumps(pipeline(name, 11).placed.layout) == dumps(pipeline(name, 11).placed.layout)


def test_cli_layout_is_deterministic():
    path = EXAMPLES / "paper" / "13_SRF.phys"
    first = run_physc("compile", path, "--emit", "layout", "--seed", "4")
    second = run_physc("compile", path, "--emit", "layout", "--seed", "4")
    assert first.status == 0 and first.stdout == second.stdout
    assert json.loads(first.stdout)["seed"] == 4


@pytest.mark.parametrize("name", NAMES)
def test_thirty_seeds_give_distinct_layouts(name):
    layouts = {dumps(pipeline(name, seed).placed.layout.objects) for seed in range(30)}
    assert len(layouts) >= 25


def test_layouts_keep_coming_while_the_caller_asks():
    """RS has 3 consistent conjunctions per shape draw: the first 12 draws give 36 layouts,
    and shapes are drawn on for more (a --layouts budget above 36 is not capped). The flat
    structure's stream (RS has a ramp structure too, whose layouts the pipeline interleaves)."""
    run = pipeline("RS", seed=1)
    assert run.structures == ("flat", "ramp")
    placed = list(itertools.islice(run._placements("flat", run.layout_graph, run.qsr), 45))
    assert len(placed) == 45
    assert max(p.graphs.shape_draws for p in placed) > 12
    assert len({dumps(p.layout.objects) for p in placed}) == 45
    for p in placed[36:]:
        check_layout(p.layout)


def test_infeasible_scenario_exits_3_and_names_the_conflict():
    path = EXAMPLES / "infeasible" / "E0801_fall_from_below.phys"
    run = run_physc("compile", path, "--emit", "layout", "--color", "never")
    assert run.status == 3 and run.stdout == ""
    assert f"{path}:4:10: error[E0801]" in run.stderr
    assert "locatedFar(fBlock, pig, aboveLeft) comes from interaction `fall(fBlock, pig)`" in run.stderr
    assert "inDirection(pig, fBlock, above) comes from interaction `hit(fBlock, pig, below)`" in run.stderr
    assert f"({path}:7:11)" in run.stderr and f"({path}:8:11)" in run.stderr


def test_layout_picture(tmp_path):
    out = tmp_path / "rs.png"
    run = run_physc("compile", EXAMPLES / "paper" / "09_RS.phys", "--emit", "layout", "--png", out)
    assert run.status == 0 and out.read_bytes().startswith(b"\x89PNG")
    svg = tmp_path / "rs.svg"
    assert run_physc("compile", EXAMPLES / "paper" / "09_RS.phys", "--emit", "layout", "--png", svg).status == 0
    assert b"<svg" in svg.read_bytes()[:400]


def test_png_needs_the_layout_stage(tmp_path):
    run = run_physc("compile", EXAMPLES / "paper" / "09_RS.phys", "--emit", "qsr", "--png", tmp_path / "x.png")
    assert run.status == 2 and "--emit layout" in run.stderr


@pytest.mark.parametrize("stage", ["layout-graph", "dimension-graphs"])
def test_dot_output(stage):
    run = run_physc("compile", EXAMPLES / "paper" / "06_S.phys", "--emit", stage, "--format", "dot")
    assert run.status == 0 and run.stdout.startswith('digraph "S" {')


def test_dot_is_only_for_graphs():
    run = run_physc("compile", EXAMPLES / "paper" / "06_S.phys", "--emit", "layout", "--format", "dot")
    assert run.status == 2


def test_the_structures_take_turns_and_each_layout_knows_its_own():
    run = pipeline("RS", seed=1)
    placed = list(itertools.islice(run.placements(), 6))
    assert [p.structure for p in placed] == ["flat", "ramp"] * 3
    for p in placed:
        surface = next(o for o in p.layout.objects if o.name == "surface")
        assert (surface.concrete == "inclinedPlatform") == (p.structure == "ramp")
