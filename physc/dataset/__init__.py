"""`physc generate`: a dataset of tasks, made on any executor, resumable and deterministic.

A dataset folder holds, per scenario, `<scenario>/scenario.phys` (as written) and, per task,
`<scenario>/<seed>.xml` (the level; `<seed>.level.json` for a domain whose levels are JSON),
`<seed>.json` (the task: solution, trace, robustness, what generation cost) and optionally
`<seed>.png`; `manifest.jsonl`, one row per task, appended as tasks finish and rewritten in task
order at the end; `manifest.parquet`, the same rows; `README.md`, a Hugging Face dataset card
written from a template; and the domain's own benchmark files, if it has any
(`files.benchmark_files`; the PHYRE-like plugin: `phyre/`). `worker.py` makes one task (in a
worker), `manifest.py` reads and writes the rows, `readme.py` the README, `build.py` runs the
whole.
"""
