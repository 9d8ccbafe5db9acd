"""The README's tables say things briefly: no cell over 60 words."""

import re

from conftest import ROOT

MOST_WORDS = 60


def cells(text: str):
    for line in text.splitlines():
        if line.startswith("|") and not re.fullmatch(r"\|[-| ]+\|", line):
            for cell in re.split(r"(?<!\\)\|", line.strip().strip("|")):
                yield cell.strip()


def test_no_readme_cell_is_over_60_words():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    long = [cell[:80] for cell in cells(readme) if len(cell.split()) > MOST_WORDS]
    assert not long, long


def test_the_readme_starts_with_compiling_and_says_which_world():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    heads = re.findall(r"^## (.+)$", readme, re.M)
    assert heads[:3] == ["Getting started", "Which world", "What it gives: the paper's 16"]
    table = readme[readme.index("## What works today"):]
    assert re.search(r"^\| \*\*compile a scenario", table, re.M)  # compile's row first
