"""'Did you mean …?' suggestions for misspelled names."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


def closest(word: str, candidates: Iterable[str], limit: int = 3) -> list[str]:
    """The candidates closest to `word`; a case-insensitive exact match comes first."""
    pool = list(dict.fromkeys(candidates))
    same_case = [c for c in pool if c.lower() == word.lower() and c != word]
    close = difflib.get_close_matches(word, pool, n=limit, cutoff=0.6)
    lowered = {c.lower(): c for c in pool}
    close += [lowered[c] for c in difflib.get_close_matches(word.lower(), list(lowered), n=limit, cutoff=0.6)]
    return list(dict.fromkeys(same_case + [c for c in close if c != word]))[:limit]


def did_you_mean(word: str, candidates: Iterable[str]) -> str | None:
    """A help sentence such as "did you mean 'rBlock'?", or None."""
    return asking(closest(word, candidates))


def asking(found: list[str]) -> str | None:
    """The help sentence for the names `closest` found: "did you mean 'a' or 'b'?", or None."""
    if not found:
        return None
    quoted = [f"'{c}'" for c in found]
    listed = quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " or " + quoted[-1]
    return f"did you mean {listed}?"


# Letters whose English names start with a vowel sound ("an f", "an r"), for abbreviations such as `rBlock`.
_VOWEL_LETTER_NAMES = set("aefhilmnorsx")


def article(word: str) -> str:
    """'a' or 'an' for `word`: by its first letter's name for an abbreviation such as `rBlock`
    (a lower-case letter then an upper-case one, read letter by letter: "an rBlock"), else by its
    first letter ("a surface", "an inclinedSurface")."""
    if not word:
        return "a"
    if len(word) > 1 and word[0].islower() and word[1].isupper():
        return "an" if word[0] in _VOWEL_LETTER_NAMES else "a"
    return "an" if word[0].lower() in "aeiou" else "a"
