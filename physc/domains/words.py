"""The installed domains' vocabularies, as the layers above the front end hand them to it.

The front end (`physc.dsl`) loads no domain: `physc check`, the compiler and the editor features
hand its checks `INSTALLED`, and the Pygments lexer is made with `loadable_vocabularies()`.
"""

from __future__ import annotations

from physc.domains import DEFAULT_DOMAIN, DomainError, installed_domains, load_domain
from physc.domains.vocabulary import Vocabulary
from physc.dsl.vocabularies import Vocabularies, VocabularyError


def vocabulary(name: str) -> Vocabulary:
    """The vocabulary of the installed domain `name`; VocabularyError where `load_domain` says
    why there is none (E0701, E0702)."""
    try:
        return load_domain(name).vocabulary
    except DomainError as error:
        raise VocabularyError(error.code, error.message, error.help, error.suggestions) from error


INSTALLED = Vocabularies(vocabulary, DEFAULT_DOMAIN)


def loadable_vocabularies() -> list[Vocabulary]:
    """The vocabulary of each installed domain that loads, by name (a broken plugin is skipped:
    the lexer must still highlight)."""
    found = []
    for name in sorted(installed_domains()):
        try:
            found.append(load_domain(name).vocabulary)
        except Exception:
            continue
    return found
