"""Packaging metadata that current setuptools accepts without warnings, and a README whose
set-up commands write nothing into the repository that git would see (issue 55)."""

from __future__ import annotations

import re
import subprocess
import tomllib

from conftest import ROOT

PROJECTS = (ROOT / "pyproject.toml", ROOT / "plugins" / "physc-phyre" / "pyproject.toml")


def test_the_licence_is_an_spdx_expression_and_no_classifier_repeats_it():
    """PEP 639: `license` a string, no `License ::` classifiers (setuptools warns of the table
    form and the classifiers, and refuses them from 2027-02-18); a build backend that reads it."""
    for path in PROJECTS:
        project = tomllib.loads(path.read_text(encoding="utf-8"))
        assert project["project"]["license"] == "MIT", path
        assert not any(c.startswith("License ::") for c in project["project"].get("classifiers", ())), path
        assert "Programming Language :: Python :: 3.11" in project["project"]["classifiers"], path
        assert any(re.fullmatch(r"setuptools>=(\d+)", r) and int(r.split(">=")[1]) >= 77 for r in project["build-system"]["requires"]), path


def test_gitignore_lists_each_pattern_once():
    lines = [line for line in (ROOT / ".gitignore").read_text(encoding="utf-8").splitlines() if line and not line.startswith("#")]
    assert len(lines) == len(set(lines))
    assert "*.vsix" in lines  # `npm run package` in grammar/


def test_the_readmes_first_command_writes_only_where_git_does_not_look():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    first = re.search(r"```sh\n(pip install -e \. [^\n]*)\n```", readme).group(1)
    outputs = re.findall(r"(?:-o|--task|--png) (\S+)", first)
    assert outputs and all(path.startswith("out/") for path in outputs), outputs
    ignored = subprocess.run(["git", "check-ignore", "-q", "out/f.xml"], cwd=ROOT).returncode
    assert ignored == 0  # /out/ is in .gitignore


def test_install_hints_name_what_works_from_a_checkout():
    """physc is on no package index: a hint says `pip install -e '.[lsp]'` (in physc's
    checkout), never `pip install 'physc[lsp]'`, which no index can serve."""
    places = [*ROOT.glob("physc/**/*.py"), *ROOT.glob("*.md"), *ROOT.glob("docs/*.md"), ROOT / "grammar" / "README.md",
              ROOT / "grammar" / "extension.js", ROOT / "grammar" / "package.json"]
    for path in places:
        text = path.read_text(encoding="utf-8")
        assert not re.search(r"pip install '?physc\[", text), path
        assert "needs physc[" not in text, path


def test_no_link_to_a_package_page_that_does_not_exist():
    """physc is on no package index: no page of one is linked (the extension, the Pygments
    lexer, the dataset card)."""
    for path in (ROOT / "grammar" / "package.json", ROOT / "physc" / "dsl" / "pygments_lexer.py", ROOT / "physc" / "dataset" / "templates" / "README.md.j2"):
        assert "pypi.org" not in path.read_text(encoding="utf-8"), path
