"""The driver of a compile: one run from a scenario to a task. The stage table (stages.py) lists
the passes in order; the pipeline (pipeline.py) runs them for one scenario, seed and world within
one time budget; the layout loop (layout_loop.py) hands the search placed layouts until one is a
task or the budget is spent; a job (job.py) is one such run as `physc generate` and `physc eval`
hand it to a worker; RunSettings (run_settings.py) is the run's settings as one value."""
