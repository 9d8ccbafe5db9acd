"""Domains are plugins: the example of docs/plugins.md works as written."""

from __future__ import annotations

import re
import sys
from importlib.metadata import EntryPoint

import pytest

from conftest import ROOT, run_physc
from physc import domains


@pytest.fixture
def phyre_domain(tmp_path, monkeypatch):
    doc = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")
    code = re.search(r"```python\n# phyre_physc/__init__.py\n(.*?)```", doc, re.S).group(1)
    package = tmp_path / "phyre_physc"
    package.mkdir()
    (package / "__init__.py").write_text(code)
    monkeypatch.syspath_prepend(str(tmp_path))
    installed = dict(domains.installed_domains())
    installed["phyre"] = EntryPoint("phyre", "phyre_physc:DOMAIN", domains.ENTRY_POINT_GROUP)
    monkeypatch.setattr(domains, "installed_domains", lambda: installed)
    domains.load_domain.cache_clear()
    yield
    domains.load_domain.cache_clear()
    sys.modules.pop("phyre_physc", None)


def test_documented_plugin_domain(phyre_domain, tmp_path):
    good = tmp_path / "good.phys"
    good.write_text("scenario P { domain phyre interactions { hit(ball, target, left) > destroy(ball, target) } }\n")
    assert run_physc("check", good).status == 0
    bad = tmp_path / "bad.phys"
    bad.write_text("scenario P { domain phyre interactions { hit(ball, bar, left) > roll(ball, bar, left) } }\n")
    run = run_physc("check", "--color", "never", bad)
    assert run.status == 1 and "error[E0201]: unknown interaction term 'roll'" in run.stderr
    listing = run_physc("domains", "phyre").stdout
    assert listing.startswith("phyre: PHYRE-like tasks")


def test_domains_come_from_entry_points():
    assert "angrybirds" in domains.installed_domains()
    assert domains.load_domain("angrybirds").vocabulary.player == "bird"
