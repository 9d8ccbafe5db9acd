"""The old home of the search and the driver (before physc 0.2): physc.search and physc.driver.
The modules docs/plugins.md names as plugin API keep their old paths for a release."""
