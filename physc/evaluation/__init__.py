"""`physc eval`: reproduce the paper's results table for any set of scenarios."""
