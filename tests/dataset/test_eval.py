"""physc eval: a small smoke run, independence from --jobs, resuming."""

from __future__ import annotations

import json

from conftest import EXAMPLES, run_physc

SF = EXAMPLES / "paper" / "01_SF.phys"


def records(folder):
    out = {}
    for line in (folder / "records.jsonl").read_text().splitlines():
        record = json.loads(line)
        record.pop("generation_seconds")
        out[(record["scenario"], record["seed"])] = record
    return out


def test_smoke_run_writes_the_report(tmp_path):
    run = run_physc("eval", SF, "--tasks", "2", "--seed", "1", "--out", tmp_path, "-q")
    assert run.status == 0, run.stderr
    names = {p.name for p in tmp_path.iterdir()}
    assert {"records.jsonl", "results.md", "results.json", "results.csv", "plot_intended_noisy.png", "plot_accidental.png"} <= names
    assert any(n.startswith("task_SF_") for n in names)
    report = (tmp_path / "results.md").read_text()
    assert "| Intended solvability (10 noisy replays) | " in report and "(1.00 ± 0.00)" in report
    assert "| Layouts tried per task | 1.00 ± 0.00 |" in report  # SF's first layouts work
    summary = json.loads((tmp_path / "results.json").read_text())
    assert summary["interactions"]["2"]["generated"] == 2
    (first, second) = records(tmp_path).values()
    assert second["stable"] and second["generated"]
    # SF seed 2: the agent finds no point of interest in reach, so no play and no figure
    # (a fraction of nothing is not 0, and must not pull the mean down).
    assert second["agent_plays"] == 0 and second["accidental"] is None
    assert first["agent_plays"] > 0 and 0 <= first["accidental"] <= 1
    assert summary["interactions"]["2"]["accidental"] == [first["accidental"], 0.0]
    assert "| Tasks where the agent found no play (no accidental solvability) | 1 |" in report


def test_results_do_not_depend_on_jobs(tmp_path):
    assert run_physc("eval", SF, "--tasks", "2", "--jobs", "2", "--out", tmp_path / "two", "-q").status == 0
    assert run_physc("eval", SF, "--tasks", "2", "--jobs", "1", "--out", tmp_path / "one", "-q").status == 0
    assert records(tmp_path / "two") == records(tmp_path / "one")


def test_a_killed_run_resumes(tmp_path):
    assert run_physc("eval", SF, "--tasks", "2", "--out", tmp_path, "-q").status == 0
    lines = (tmp_path / "records.jsonl").read_text().splitlines()
    (tmp_path / "records.jsonl").write_text(lines[0] + "\n" + lines[1][:40])  # killed while writing
    run = run_physc("eval", SF, "--tasks", "2", "--out", tmp_path)
    assert run.status == 0 and "resuming: 1 of 2 tasks already done" in run.stderr
    assert len((tmp_path / "records.jsonl").read_text().splitlines()) == 2


def test_eval_reports_input_errors(tmp_path):
    run = run_physc("eval", EXAMPLES / "errors" / "E0201_unknown_term.phys", "--out", tmp_path, "-q")
    assert run.status == 1 and "E0201" in run.stderr


def test_records_made_with_other_settings_are_made_again(tmp_path):
    assert run_physc("eval", SF, "--tasks", "1", "--out", tmp_path, "-q").status == 0
    run = run_physc("eval", SF, "--tasks", "1", "--min-robustness", "6", "--out", tmp_path)
    assert run.status == 0 and "resuming" not in run.stderr
    (record,) = records(tmp_path).values()
    assert record["min_robustness"] == 6 and record["robustness"] == [6, 6]
    header, row = (tmp_path / "results.csv").read_text().splitlines()[:2]
    assert header.endswith(",min_robustness,robustness,layouts_tried,simulations,structure")
    assert row.endswith(f",6,6/6,{record['layouts_tried']},{record['simulations']},flat") and record["layouts_tried"] >= 1
    assert record["simulations"] >= sum(why["simulations"] for why in record["given_up"].values())


def test_records_of_a_changed_scenario_or_time_budget_are_made_again(tmp_path):
    source = tmp_path / "sf.phys"
    source.write_text(SF.read_text())
    out = tmp_path / "out"
    assert run_physc("eval", source, "--tasks", "1", "--out", out, "-q").status == 0
    # Only layout and comments changed: the scenario says the same, the record stands.
    source.write_text("# a comment\n\n" + SF.read_text())
    run = run_physc("eval", source, "--tasks", "1", "--out", out)
    assert run.status == 0 and "resuming: 1 of 1 tasks already done" in run.stderr
    run = run_physc("eval", source, "--tasks", "1", "--time-budget", "59", "--out", out)
    assert run.status == 0 and "resuming" not in run.stderr
    (record,) = records(out).values()
    assert record["settings"]["time_budget"] == 59
    # A changed interaction is another scenario.
    changed = source.read_text().replace("hit(bird, pig, any)", "hit(bird, pig, left)")
    assert changed != source.read_text()
    source.write_text(changed)
    run = run_physc("eval", source, "--tasks", "1", "--time-budget", "59", "--out", out)
    assert run.status == 0 and "resuming" not in run.stderr


def test_records_made_by_other_code_are_made_again(tmp_path, monkeypatch):
    from physc.driver import job as generation_job

    assert run_physc("eval", SF, "--tasks", "1", "--out", tmp_path, "-q").status == 0
    assert run_physc("eval", SF, "--tasks", "1", "--out", tmp_path).stderr.count("resuming: 1 of 1") == 1
    monkeypatch.setattr(generation_job, "code_fingerprint", lambda domain, backends=(): "edited")
    run = run_physc("eval", SF, "--tasks", "1", "--out", tmp_path)
    assert run.status == 0 and "resuming" not in run.stderr
    (record,) = records(tmp_path).values()
    assert record["settings"]["code"] == "edited"


def test_the_code_fingerprint_follows_python_source_only(tmp_path):
    from physc.fingerprint import code_fingerprint, source_fingerprint

    package = tmp_path / "plugin"
    (package / "sub").mkdir(parents=True)
    (package / "__init__.py").write_text("X = 1\n")
    (package / "sub" / "rules.py").write_text("Y = 2\n")
    before = source_fingerprint(package)
    (package / "README.md").write_text("notes")
    assert source_fingerprint(package) == before
    (package / "sub" / "rules.py").write_text("Y = 3\n")
    edited = source_fingerprint(package)
    assert edited != before
    (package / "sub" / "rules.py").rename(package / "rules.py")  # same content, elsewhere
    assert source_fingerprint(package) != edited
    assert source_fingerprint(package / "__init__.py") != source_fingerprint(package)  # one module's file
    # The built-in domain is physc's own code: nothing beyond physc's source counts.
    assert code_fingerprint("angrybirds") == code_fingerprint("no such domain")


def test_the_report_says_where_the_simulations_went():
    from physc.evaluation import report

    def record(scenario, layouts, simulations, given_up):
        return {"scenario": scenario, "interactions": 8, "generated": True, "robustness": [6, 6], "layouts_tried": layouts, "simulations": simulations, "given_up": given_up}

    records = [
        record("SRF", 3, 100, {"the sequence was not realised": {"layouts": 2, "simulations": 60}}),
        record("SFR", 2, 300, {"the solution was too fragile": {"layouts": 1, "simulations": 30}}),
        {"scenario": "RRR", "interactions": 8, "generated": False, "reason": "no layout"},
        record("SF", 1, 10, {}) | {"interactions": 2},
    ]
    summary = report.summarise(records)
    eight = summary["interactions"][8]
    assert eight["layouts_tried"] == (2.5, 0.5) and eight["simulations"] == (200, 100)
    assert eight["given_up"] == {"the sequence was not realised": 0.15, "the solution was too fragile": 0.075}
    text = report.markdown(summary, "physc eval", 1.0)
    assert "| Simulations per task | 10 ± 0 | 200 ± 100 |" in text
    assert "| Simulations on layouts given up: the sequence was not realised | 0.0 % | 15.0 % |" in text


def test_the_report_says_where_the_placed_layouts_went_made_or_not():
    """The records' funnels (physc.search.funnel), tasks made or not: the share of placed layouts
    that never realised the chain, were lost after it, and gave the task."""
    from physc.evaluation import report

    def funnel(placed, chain, kept, lost):
        stage = {"interactions": "hit(bird, pig, left)", "reached": placed, "realised": chain, "simulations": 100}
        return {"placed": placed, "stages": [stage], "chain_realised": chain, "kept": kept, "lost": lost, "simulations_after_chain": 50}

    records = [
        {"scenario": "A", "interactions": 4, "generated": True, "robustness": [6, 6], "funnel": funnel(4, 2, 1, {"noise": 1})},
        {"scenario": "B", "interactions": 4, "generated": False, "reason": "no task", "funnel": funnel(6, 1, 0, {"a later check": 1})},
    ]
    summary = report.summarise(records)
    four = summary["interactions"][4]["funnel"]
    assert four["placed"] == 10 and four["never"] == 0.7 and four["kept"] == 0.1
    assert four["lost"] == {"a later check": 0.1, "noise": 0.1}
    text = report.markdown(summary, "physc eval", 1.0)
    assert "| Never realised the chain | 70.0 % |" in text and "| Realised the chain, lost to noise | 10.0 % |" in text
    assert "| B | 6 | 83.3 % | 0.0 % | 0.0 % |" in text
