"""Generation: from placed layouts to a task, whatever the domain (the layout loop, its
budgets and fallbacks). The domain supplies the strategy that satisfies one layout."""
