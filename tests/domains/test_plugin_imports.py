"""The PHYRE-like plugin is written as a third party would write it: it imports from
physc only the modules docs/plugins.md names as the public API ("What a plugin may
import"), no private name, nothing of angrybirds; and it stays small (issue 33: about
1,000 lines, no search, simulation or robustness loop of its own)."""

from __future__ import annotations

import ast
import re

from conftest import ROOT

PLUGIN = ROOT / "plugins" / "physc-phyre" / "physc_phyre"
PLUGINS_DOC = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")


def public_modules() -> set[str]:
    section = PLUGINS_DOC[PLUGINS_DOC.index("## What a plugin may import") :]
    section = section[: section.index("\n## ", 1)]
    return set(re.findall(r"^\| `(physc[\w.]*)` \|", section, re.M))


def imports(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] == "physc":
            yield node.module, [alias.name for alias in node.names]
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "physc":
                    yield alias.name, []


def test_the_plugin_imports_only_physcs_public_api():
    public = public_modules()
    assert {"physc.domains.simulated", "physc.backends", "physc.simulation.scene"} <= public
    sources = sorted(PLUGIN.rglob("*.py"))
    assert sources
    for path in sources:
        for module, names in imports(path):
            assert module in public, f"{path.name} imports {module}, which is not physc's public API"
            assert not module.startswith("physc.domains.angrybirds")
            assert not any(name.startswith("_") for name in names), f"{path.name} imports a private name from {module}"


def test_the_plugin_is_small_and_has_no_loop_of_its_own():
    from physc_phyre import Phyre

    from physc.domains.simulated import SimulatedDomain

    # The domain (what physc needs to generate its tasks) stays about 1,000 lines (issue 33;
    # 1,100 with issue 44's objects, acceptance and distractors; 1,300 with its two-ball tier,
    # balls held in jars and objects dropped at the start; 1,330 with its world as one value,
    # issue 52; 1,700 with issue 54's furniture, PHYRE's own jars, ball goal and occlusion
    # test, and its acceptance per tier and template; 1,730 with its peg rows, PHYRE's 00012 and
    # 00013; 1,760 with issue 63's outcome playouts: rules that ask the world and settle early,
    # balls judged in doubles away from the limit, the level's bodies made once; 1,790 with
    # issue 64's jar that comes to its ball (PHYRE's 00005, 00010) and issue 65's declared
    # capabilities, 1,810 with its search and files as parts; 2,030 as ruff formats the same code,
    # issue 72, from 1,758 lines the line before; 2,075 with issue 72's types, its long lines
    # rewrapped and concretize in its parts); PHYRE's own formats, pools, simulation cache, folds
    # and agent scoring, which a PHYRE researcher reads the tasks with (issues 44, 54), and how
    # agents play them (playing.py: PHYRE's action, features and picture, issue 55), and PHYRE's
    # evaluation (its acceptance rule, random agent and AUCCESS, in physc's core until issue 65:
    # acceptance.py, evaluation.py) are counted apart.
    phyres_own = {
        "phyre_format.py", "observation.py", "folds.py", "benchmark.py", "agents.py", "pool.py", "simulation_cache.py", "cache.py",
        "playing.py", "acceptance.py", "evaluation.py",
    }
    counted = {path.name: len(path.read_text(encoding="utf-8").splitlines()) for path in PLUGIN.rglob("*.py")}
    assert sum(n for name, n in counted.items() if name not in phyres_own) <= 2075, counted
    assert sum(n for name, n in counted.items() if name in phyres_own) <= 1680, counted  # 1,000; 1,100 with playing.py; 1,550 with its evaluation; 1,680 formatted (1,544 before)
    assert issubclass(Phyre, SimulatedDomain)
    # The search, the replays, stability and the agent are physc's: the plugin overrides none.
    assert not {"satisfy", "replay", "stability", "accidental", "play"} & set(vars(Phyre))
    for path in PLUGIN.rglob("*.py"):
        assert ".step(" not in path.read_text(encoding="utf-8"), f"{path.name} steps a world itself"
