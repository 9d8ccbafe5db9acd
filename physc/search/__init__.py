"""The search: from a placed layout to a task, whatever the domain. Its steps (search.py: stages,
proposals, placing, strengthening, contrasts, variants) work over two values alone, the layout's
`Problem` and the search's `Ledger`, and ask the domain's hooks (physc.domains.search_hooks) what
differs; the driver (physc.driver) runs it over layouts."""
