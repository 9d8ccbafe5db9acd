"""The catalogue of diagnostic codes.

Codes are stable: once released, a code keeps its meaning. `docs/errors.md` lists
every code here with a minimal example, and a test keeps the two in step.

Groups:
    E00xx  reading the input file
    E01xx  syntax
    E02xx  terms and their arguments
    E03xx  objects and declarations (W03xx: warnings about objects)
    E04xx  causality and goals
    E05xx  restrictions
    E06xx  structure of a file and of a scenario
    E07xx  domains (plugins)
    E08xx  generation: well-formed scenarios that yield no task (exit status 3)
    E09xx  Science Birds level files
"""

from __future__ import annotations

import functools
import re
from importlib import resources

import attrs


@attrs.frozen
class ErrorCode:
    code: str
    severity: str  # "error" | "warning"
    summary: str
    exit_status: int = 1


_CODES = [
    ErrorCode("E0001", "error", "the input file cannot be read", exit_status=2),
    ErrorCode("E0002", "error", "the input file is not valid UTF-8"),
    ErrorCode("E0003", "error", "the input file holds no scenario"),
    ErrorCode("E0101", "error", "a character that cannot start any token"),
    ErrorCode("E0102", "error", "a token where the grammar does not allow it"),
    ErrorCode("E0103", "error", "the input ends inside an unfinished construct"),
    ErrorCode("E0104", "error", "a string is not closed on its line"),
    ErrorCode("E0105", "error", 'an escape sequence in a string other than \\" or \\\\'),
    ErrorCode("E0106", "error", "two restrictions on one line without a separator"),
    ErrorCode("E0201", "error", "a term that the domain does not define"),
    ErrorCode("E0202", "error", "a term with the wrong number of arguments"),
    ErrorCode("E0203", "error", "an object whose type does not fit the term's parameter"),
    ErrorCode("E0204", "error", "a direction where the term expects an object"),
    ErrorCode("E0205", "error", "an object where the term expects a direction"),
    ErrorCode("E0206", "error", "a direction that the term does not allow"),
    ErrorCode("E0207", "error", "alternatives given for an object argument"),
    ErrorCode("E0208", "error", "an interaction among restrictions, or a restriction among interactions"),
    ErrorCode("E0301", "error", "an object whose type cannot be inferred from its name"),
    ErrorCode("E0302", "error", "a declaration with an unknown object term"),
    ErrorCode("E0303", "error", "a concrete object that the declared term does not allow"),
    ErrorCode("E0304", "error", "an object declared twice"),
    ErrorCode("E0305", "error", "a direction word used as an object name"),
    ErrorCode("E0306", "error", "a material that the declared object cannot be made of"),
    ErrorCode("W0301", "warning", "a declared object that no term uses"),
    ErrorCode("W0302", "warning", "more of the player's objects than compile places"),
    ErrorCode("E0401", "error", "the first interaction is not performed by the player's object"),
    ErrorCode("E0402", "error", "an object acts before anything set it in motion"),
    ErrorCode("E0403", "error", "destroy(a, b) without an earlier hit(a, b, ...)"),
    ErrorCode("E0404", "error", "a goal object that no interaction completes"),
    ErrorCode("E0405", "error", "an object takes part in an interaction after it was destroyed"),
    ErrorCode("E0501", "error", "a restriction leaves an interaction no allowed direction"),
    ErrorCode("E0502", "error", "a restriction forbids an interaction of the sequence"),
    ErrorCode("E0503", "error", "a property restriction whose objects the sequence does not take as it says"),
    ErrorCode("E0601", "error", "two scenarios with the same name in one file"),
    ErrorCode("E0602", "error", "a section given twice in one scenario"),
    ErrorCode("E0603", "error", "a scenario without an interactions section"),
    ErrorCode("E0701", "error", "a domain that is not installed"),
    ErrorCode("E0702", "error", "a domain plugin that fails to load", exit_status=2),
    ErrorCode("E0703", "error", "a domain that lacks what the command asks of it", exit_status=2),
    ErrorCode("E0901", "error", "a level file that is not a Science Birds level"),
    ErrorCode("E0902", "error", "a level object with a missing or malformed attribute"),
    ErrorCode("E0903", "error", "a level object or bird of an unknown type"),
    ErrorCode("E0904", "error", "a level number outside its documented range"),
    ErrorCode("E0905", "error", "a block whose material is missing or unknown"),
    ErrorCode("E0906", "error", "a level file larger than physc reads"),
    ErrorCode("E0907", "error", "a shot asked for on a level without birds"),
    ErrorCode("E0908", "error", "a level whose objects are stacked into one another"),
    ErrorCode("E0801", "error", "the layout constraints of a scenario cannot hold together", exit_status=3),
    ErrorCode("E0802", "error", "the search budget ran out before a layout was found", exit_status=3),
    ErrorCode("E0803", "error", "a scenario larger than the layout search takes", exit_status=3),
    ErrorCode("E0804", "error", "a scenario that compile cannot generate in this version", exit_status=3),
]

CODES: dict[str, ErrorCode] = {entry.code: entry for entry in _CODES}


def lookup(code: str) -> ErrorCode:
    return CODES[code]


@functools.cache
def _explanations() -> dict[str, str]:
    """docs/errors.md (shipped in the package as physc/errors.md) cut into its sections, by code."""
    try:
        text = resources.files("physc").joinpath("errors.md").read_text(encoding="utf-8")
    except OSError:
        return {}
    sections: dict[str, str] = {}
    for part in re.split(r"^## ", text, flags=re.MULTILINE)[1:]:
        code = part.split(":", 1)[0].strip()
        if code in CODES:
            sections[code] = "## " + part.strip()
    return sections


def explanation(code: str) -> str | None:
    """The section of docs/errors.md about `code` (Markdown: what it means, an example, the fix)."""
    return _explanations().get(code)
