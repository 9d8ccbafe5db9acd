"""An agent given on the command line (`physc eval --agent MODULE:NAME`): found, and its own
failures told apart from physc's.

An agent is the user's code: a Python callable that a domain's `score_agent` shows tasks to
(docs/plugins.md). `load` imports it; a domain wraps every call into the agent's code with
`calling`, so that an exception raised there is reported as the agent's (AgentError: the
message, exit status 1), not as an internal error of physc.
"""

from __future__ import annotations

import contextlib
import importlib
import sys
from pathlib import Path


class AgentError(Exception):
    """The agent could not be loaded, or its own code raised."""


def load(spec: str):
    """The callable `MODULE:NAME` names (NAME may be dotted); the current folder is searched
    first, as `python -m` does."""
    module, _, name = spec.partition(":")
    if not module or not name:
        raise AgentError(f"--agent takes MODULE:NAME (a Python callable), not '{spec}'")
    if str(Path.cwd()) not in sys.path:
        sys.path.insert(0, str(Path.cwd()))
    try:
        found = importlib.import_module(module)
    except Exception as error:  # the user's module: any error it raises on import is its own
        raise AgentError(f"cannot import the agent's module '{module}': {type(error).__name__}: {error}") from None
    for part in name.split("."):
        if not hasattr(found, part):
            raise AgentError(f"the module '{module}' has no '{name}'")
        found = getattr(found, part)
    if not callable(found):
        raise AgentError(f"'{spec}' is not callable: an agent is a function of a task's observation")
    return found


@contextlib.contextmanager
def calling(what: str):
    """Around a call into the agent's code: what it raises becomes an AgentError."""
    try:
        yield
    except (KeyboardInterrupt, AgentError):
        raise
    except Exception as error:
        raise AgentError(f"the agent raised {type(error).__name__} {what}: {error}") from None
