"""physc's exit statuses, which every command and the executable's entry point share."""

EXIT_OK, EXIT_INPUT, EXIT_USAGE, EXIT_INFEASIBLE, EXIT_INTERNAL = 0, 1, 2, 3, 70
EXIT_INTERRUPTED = 130  # Ctrl-C: 128 + SIGINT, as shells report it
EXIT_STATUSES = (
    "exit status: 0 ok, 1 input errors, 2 usage or unreadable file, 3 no task could be generated, "
    "70 internal error (a bug in physc), 130 interrupted (Ctrl-C)"
)
