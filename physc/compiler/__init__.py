"""Compiler IRs and passes, and the stage table behind `physc compile --emit`."""
