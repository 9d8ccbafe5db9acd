"""physc simulate, trace and render on level files."""

from __future__ import annotations

import json

from conftest import SCIENCEBIRDS, run_physc

ONE_PIG = SCIENCEBIRDS / "phyq-templates" / "1_1_1_1.xml"


def test_simulate(tmp_path):
    run = run_physc("simulate", ONE_PIG, "--shot", "0,-3.27")
    assert run.status == 0
    assert "1 object, 1 pig;" in run.stdout and "1 of 1 pig destroyed: solved" in run.stdout
    data = json.loads(run_physc("simulate", ONE_PIG, "--shot", "0,-3.27", "--format", "json").stdout)
    assert data["solved"] and data["pigs"] == ["pigSmall1"]
    missed = json.loads(run_physc("simulate", ONE_PIG, "--angle", "70", "--format", "json").stdout)
    assert not missed["solved"]


def test_trace_prints_phys_syntax():
    run = run_physc("trace", ONE_PIG, "--shot", "0,-3.27")
    lines = run.stdout.splitlines()
    assert lines[1].startswith("hit(bird, pigSmall1, left)") and lines[2].startswith("> destroy(bird, pigSmall1)")
    assert len({line.index("# t = ") for line in lines[1:] if not line.startswith("#")}) == 1  # the times in one column


def test_trace_gives_each_link_its_margin_and_names_the_weakest():
    data = json.loads(run_physc("trace", ONE_PIG, "--shot", "0,-3.27", "--format", "json").stdout)
    hit, destroy = data["interactions"][:2]
    assert hit["term"] == "hit(bird, pigSmall1, left)" and hit["margin"]["unit"] == "degrees" and hit["margin"]["held"]
    assert destroy["margin"]["unit"] == "damage" and destroy["margin"]["value"] > 0  # the bird's blow, under the worst reading
    assert data["weakest"]["share"] == min(i["margin"]["share"] for i in data["interactions"] if i["margin"])
    text = run_physc("trace", ONE_PIG, "--shot", "0,-3.27").stdout
    assert "margin +" in text.splitlines()[1]
    assert "# the link that came closest to failing was `" in text and " to spare (" in text  # a solved shot's held
    assert "weakest" not in text


def test_render(tmp_path):
    out = tmp_path / "level.png"
    assert run_physc("render", ONE_PIG, "-o", out, "--shot", "0,-3.27").status == 0
    assert out.read_bytes().startswith(b"\x89PNG")
    svg = tmp_path / "level.svg"
    assert run_physc("render", ONE_PIG, "-o", svg).status == 0
    assert run_physc("render", ONE_PIG, "-o", tmp_path / "level.gif").status == 2


def test_bad_shots_are_usage_errors():
    assert run_physc("simulate", ONE_PIG, "--shot", "0").status == 2
    assert run_physc("simulate", ONE_PIG, "--shot", "a,b").status == 2
    run = run_physc("simulate", ONE_PIG, "--shot", "30,9")
    assert run.status == 2 and "out of reach" in run.stderr
    assert run_physc("simulate", ONE_PIG, "--backend", "bulet").status == 2
