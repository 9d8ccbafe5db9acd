"""The proposal model's priors of Science Birds' worlds, one `<world>.json` a world (physc.driver.link_prior)."""
