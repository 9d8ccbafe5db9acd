"""What the front end is handed of the domains: their vocabularies, looked up by name.

The front end loads no domain (the domains import it, not the other way round): the layers above
build a `Vocabularies` from the installed domains and hand it to the checks. The kinds below are the
words a vocabulary marks its terms and parameters with.
"""

from __future__ import annotations

from typing import Any, Callable

import attrs

# The domains' data classes (physc.domains.vocabulary), named for the reader: the front end reads
# them by duck typing and imports nothing of the domains, not even for its annotations.
Vocabulary = TermSignature = Parameter = ObjectTerm = Any

# The kinds of a term (the section it is written in) and of a parameter, as a vocabulary marks them.
OBJECT = "object"
DIRECTION = "direction"
INTERACTION = "interaction"
RESTRICTION = "restriction"


class VocabularyError(Exception):
    """Why a domain has no vocabulary, said as the diagnostic on the scenario's domain: its `code`
    (E0701: not installed, E0702: its plugin fails to load), and the installed names that the
    asked-for one may be a misspelling of (`suggestions`, its quick fixes)."""

    def __init__(self, code: str, message: str, help: str | None = None, suggestions: tuple[str, ...] = ()):
        super().__init__(message)
        self.code = code
        self.message = message
        self.help = help
        self.suggestions = suggestions


@attrs.frozen
class Vocabularies:
    """The vocabularies that the checks are handed: `lookup(name)` gives a domain's vocabulary or
    raises VocabularyError; `default` is the domain of a scenario that names none."""

    lookup: Callable[[str], Vocabulary]
    default: str
