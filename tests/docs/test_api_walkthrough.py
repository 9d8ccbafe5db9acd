"""docs/api.md is a notebook: its python blocks, run in order in a fresh folder beside physc's
examples, all work (issue 55: a new user reproduces a task, a shot and a small evaluation
from the docs alone)."""

from __future__ import annotations

import contextlib
import io
import re
import warnings

from conftest import EXAMPLES, ROOT

PAGE = ROOT / "docs" / "api.md"
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def test_the_walkthrough_runs(tmp_path, monkeypatch):
    blocks = BLOCK.findall(PAGE.read_text(encoding="utf-8"))
    assert len(blocks) >= 7
    (tmp_path / "examples").symlink_to(EXAMPLES)
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed), warnings.catch_warnings():
        warnings.simplefilter("ignore")  # Gymnasium's advice on spaces
        for index, block in enumerate(blocks):
            exec(compile(block, f"docs/api.md block {index + 1}", "exec"), namespace)  # noqa: S102 - the page's own code
    shown = printed.getvalue()
    assert "F phyq box2d" in shown
    assert "E0201" in shown
    assert (tmp_path / "out" / "ds" / "manifest.parquet").is_file()
    assert (tmp_path / "out" / "eval" / "results.md").is_file()


def test_the_readmes_library_example_runs(tmp_path, monkeypatch):
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## As a library"):readme.index("## The command line")]
    (block,) = BLOCK.findall(section)
    (tmp_path / "examples").symlink_to(EXAMPLES)
    (tmp_path / "out").mkdir()  # the README's first command makes it
    monkeypatch.chdir(tmp_path)
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(block, "README.md, As a library", "exec"), {})  # noqa: S102
    assert (tmp_path / "out" / "f.json").is_file()
