"""Generation: from placed layouts to a task, whatever the domain. The one search
(search.py) makes a placed layout a task with a domain's hooks; the layout loop
(layout_loop.py) runs it over layouts, with the budgets and fallbacks; the pipeline
(pipeline.py) drives one run: the compiler's passes, then the layout loop."""
