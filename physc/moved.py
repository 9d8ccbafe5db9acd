"""Old import paths kept for a release after a module moved: the old module is the new one (the
same classes and functions, so `isinstance` and patches agree), and importing it by its old name
warns once where it is imported."""

from __future__ import annotations

import importlib
import sys
import warnings
from types import ModuleType

REMOVED_IN = "0.3"  # the release whose tree no longer has the old paths


def alias(old: str, new: str) -> ModuleType:
    """Make the module named `old` the module `new`, with a DeprecationWarning at the import."""
    warnings.warn(f"{old} moved to {new}; the old path goes in physc {REMOVED_IN}", DeprecationWarning, stacklevel=3)
    module = importlib.import_module(new)
    sys.modules[old] = module
    return module
