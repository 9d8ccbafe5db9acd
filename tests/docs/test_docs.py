"""docs/errors.md and the code catalogue stay in step, and its examples are true."""

from __future__ import annotations

import re
from importlib.metadata import EntryPoint

import pytest
from conftest import ROOT, run_physc

from physc import domains, error_codes

DOC = (ROOT / "docs" / "errors.md").read_text(encoding="utf-8")
SECTIONS = {m.group(1): m.group(0) for m in re.finditer(r"^## (\w+): .*?(?=^## |\Z)", DOC, re.M | re.S)}


def test_every_code_is_documented_once_with_its_summary():
    headings = re.findall(r"^## (\w+): (.*)$", DOC, re.M)
    assert [code for code, _ in headings] == list(error_codes.CODES)
    for code, summary in headings:
        assert summary == error_codes.lookup(code).summary


@pytest.mark.parametrize("code", [c for c in error_codes.CODES if "```phys" in SECTIONS[c]])
def test_documented_example_prints_what_the_doc_says(code, tmp_path, monkeypatch):
    """A ```text block is what `physc check` prints; a ```console block names its command."""
    section = SECTIONS[code]
    source = re.search(r"```phys\n(.*?)```", section, re.S).group(1)
    (tmp_path / "example.phys").write_text(source, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    console = re.search(r"```console\n\$ physc (.*?)\n(.*?)```", section, re.S)
    if console:
        command, expected = console.group(1).split() + ["--color", "never"], console.group(2)
    else:
        command = ["check", "-q", "--color", "never", "example.phys"]
        expected = re.search(r"```text\n(.*?)```", section, re.S).group(1)
    run = run_physc(*command)
    assert run.stderr == expected
    assert f"[{code}]" in run.stderr.splitlines()[0]


def test_broken_plugin_is_e0702(tmp_path, monkeypatch):
    broken = EntryPoint("marbles", "marbles_physc_missing:DOMAIN", domains.ENTRY_POINT_GROUP)
    monkeypatch.setattr(domains, "installed_domains", lambda: {"marbles": broken})
    domains.load_domain.cache_clear()
    try:
        path = tmp_path / "scenario.phys"
        path.write_text("scenario SF {\n    domain marbles\n    interactions { hit(bird, pig, any) }\n}\n")
        run = run_physc("check", "-q", "--color", "never", path)
    finally:
        domains.load_domain.cache_clear()
    assert run.status == 2
    assert (
        f"{path}:2:12: error[E0702]: the plugin of domain 'marbles' (marbles_physc_missing:DOMAIN) fails to load: "
        "No module named 'marbles_physc_missing'"
    ) in run.stderr


def test_the_readme_picture_is_what_its_caption_makes():
    """The picture is a build artefact of the command its caption names (tools/readme_picture.py
    makes it again); the task also does what the caption says."""
    import subprocess
    import sys

    run = subprocess.run([sys.executable, str(ROOT / "tools" / "readme_picture.py"), "--check"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
