"""The commands of `physc`, one module each; `physc.cli` parses the command line."""
