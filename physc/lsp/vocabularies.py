"""The domain vocabularies that the editor features read, loaded as `physc check` loads them."""

from __future__ import annotations

from physc.domains.vocabulary import Vocabulary
from physc.domains.words import vocabulary
from physc.lsp.context import Place


def vocabulary_of(domain: str) -> Vocabulary | None:
    """The vocabulary of an installed domain; None for a domain that is not installed or fails to
    load (the diagnostics say why)."""
    try:
        return vocabulary(domain)
    except Exception:  # a broken plugin must not take the editor features down
        return None


def object_concrete(vocabulary: Vocabulary, place: Place, name: str) -> tuple[str | None, tuple[str, ...] | None]:
    """An object's term and its possible concrete objects: from its declaration in the scenario,
    else from its name (`rBlock2` is a rollableBlock); (None, None) when neither says."""
    declared = place.declared.get(name)
    term = vocabulary.object_term(declared) if declared else vocabulary.term_of_name(name)
    if term is None:
        return declared, None
    narrowed = tuple(c for c in term.concrete if c in place.narrowed.get(name, ())) if declared else ()
    return term.name, narrowed or term.concrete
