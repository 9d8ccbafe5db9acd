"""Domains are plugins: the example of docs/plugins.md works as written, the domain
interface is checked at load (E0702), and a domain that lacks a capability is refused
clearly when asked for it (E0703)."""

from __future__ import annotations

import re
import sys
from importlib.metadata import EntryPoint

import pytest
from conftest import ROOT, run_physc

from physc import domains
from physc.domains.base import CAPABILITIES, DEFAULTS, FILES, REQUIRED, Domain, MissingCapability, missing
from physc.domains.evaluation import Evaluation
from physc.domains.level_files import LevelFiles
from physc.driver.stages import BY_NAME, NEEDS

PLUGINS = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")
ERRORS = (ROOT / "docs" / "errors.md").read_text(encoding="utf-8")
SCENARIO = "scenario P {{\n    domain {domain}\n    interactions {{ hit(ball, target, left) > destroy(ball, target) }}\n}}\n"


@pytest.fixture
def install(tmp_path, monkeypatch):
    """install(name, code): a plugin package `<name>_physc` whose entry point `name` is its DOMAIN."""
    monkeypatch.syspath_prepend(str(tmp_path))
    installed = dict(domains.installed_domains())
    monkeypatch.setattr(domains, "installed_domains", lambda: installed)
    modules = []

    def install(name: str, code: str) -> None:
        package = tmp_path / f"{name}_physc"
        package.mkdir()
        (package / "__init__.py").write_text(code)
        installed[name] = EntryPoint(name, f"{name}_physc:DOMAIN", domains.ENTRY_POINT_GROUP)
        modules.append(package.name)
        domains.load_domain.cache_clear()

    yield install
    domains.load_domain.cache_clear()
    for module in modules:
        sys.modules.pop(module, None)


@pytest.fixture
def marbles_domain(install):
    install("marbles", re.search(r"```python\n# marbles_physc/__init__.py\n(.*?)```", PLUGINS, re.S).group(1))


def write_scenario(tmp_path, domain: str):
    path = tmp_path / "scenario.phys"
    path.write_text(SCENARIO.format(domain=domain))
    return path


def test_documented_plugin_domain(marbles_domain, tmp_path):
    good = tmp_path / "good.phys"
    good.write_text("scenario P { domain marbles interactions { hit(ball, target, left) > destroy(ball, target) } }\n")
    assert run_physc("check", good).status == 0
    bad = tmp_path / "bad.phys"
    bad.write_text("scenario P { domain marbles interactions { hit(ball, bar, left) > roll(ball, bar, left) } }\n")
    run = run_physc("check", "--color", "never", bad)
    assert run.status == 1 and "error[E0201]: unknown interaction term 'roll'" in run.stderr
    listing = run_physc("domains", "marbles").stdout
    assert listing.startswith("marbles: Marble runs")


def test_domains_come_from_entry_points():
    assert "angrybirds" in domains.installed_domains()
    assert domains.load_domain("angrybirds").vocabulary.player == "bird"


def test_a_subclass_with_only_the_required_attributes_loads_with_the_defaults(marbles_domain):
    domain = domains.load_domain("marbles")
    assert isinstance(domain, Domain)
    assert missing(domain, NEEDS["level"] + ("picture", "replay", "stability", "read_level", "draw")) == CAPABILITIES
    assert domain.reach_targets(None) == [] and domain.reachable(-1e6, 1e6) and domain.robustness_replays is None
    with pytest.raises(MissingCapability, match="the domain 'marbles' cannot .* it has no picture"):
        domain.files.picture(None)


def test_a_vocabulary_only_domain_checks_and_refuses_to_generate(marbles_domain, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write_scenario(tmp_path, "marbles")
    assert run_physc("check", "scenario.phys").status == 0
    assert run_physc("compile", "--emit", "scenario", "scenario.phys").status == 0
    # The default stage, level: what docs/errors.md shows for E0703, exit 2, before any work.
    command, expected = re.search(r"## E0703.*?```console\n\$ physc (.*?)\n(.*?)```", ERRORS, re.S).groups()
    run = run_physc(*command.split(), "--color", "never")
    assert (run.status, run.stderr, run.stdout) == (2, expected, "")
    run = run_physc("compile", "-q", "--color", "never", "--emit", "layout-graph", "scenario.phys")
    assert run.status == 2 and "error[E0703]: the domain 'marbles' cannot do what --emit layout-graph needs: it has no layout_rules\n" in run.stderr
    run = run_physc("compile", "-q", "--color", "never", "--emit", "task", "--png", "task.png", "scenario.phys")
    assert run.status == 2 and "it has no layout_rules, layout_parameters, concretize, satisfy, picture\n" in run.stderr
    run = run_physc("eval", "-q", "--color", "never", "scenario.phys", "--out", "results")
    assert run.status == 2 and "scenario.phys: error[E0703]: the domain 'marbles' cannot do what physc eval needs" in run.stderr
    assert not (tmp_path / "task.png").exists() and not (tmp_path / "results").exists()


DUCK = "class Duck:\n    name = {name!r}\n    description = 'a duck-typed domain'\n{body}\nDOMAIN = Duck(){call}\n"
SUBCLASS = "from physc.domains.base import Domain\nclass Duck(Domain):\n    name = {name!r}\n    description = 'a domain'\n{body}\nDOMAIN = Duck()\n"
VOCABULARY = "    from physc.domains.angrybirds import VOCABULARY as vocabulary\n"


@pytest.mark.parametrize(
    "code, problem",
    [
        (DUCK.format(name="duck", body=VOCABULARY, call=""), "is a Duck, not a physc.domains.base.Domain: subclass Domain (or SimulatedDomain)"),
        (
            "from physc.domains.base import Domain\nclass Duck(Domain):\n    name = 'duck'\nDOMAIN = Duck()\n",
            "fails to load: Can't instantiate abstract class Duck with abstract methods description, vocabulary",
        ),
        (SUBCLASS.format(name="duck", body="    vocabulary = {'bird': 'pig'}"), "has a 'vocabulary' that is a dict, not"),
        (SUBCLASS.format(name="goose", body=VOCABULARY), "calls itself 'goose': its 'name' must be its entry point's name, 'duck'"),
        (DUCK.format(name="duck", body=VOCABULARY, call="\nDOMAIN = Duck"), "names the class 'Duck', not a domain"),
    ],
    ids=["duck-typed", "subclass-without-description-and-vocabulary", "not-a-vocabulary", "name", "class"],
)
def test_a_plugin_that_is_not_a_domain_is_e0702(install, tmp_path, code, problem):
    install("duck", code)
    run = run_physc("check", "-q", "--color", "never", write_scenario(tmp_path, "duck"))
    assert run.status == 2
    assert f"error[E0702]: the plugin of domain 'duck' (duck_physc:DOMAIN) {problem}" in run.stderr
    assert "internal error" not in run.stderr


def test_a_domain_has_the_capabilities_it_declares_and_no_other(install, tmp_path):
    """A capability is declared (`capabilities`), not found by looking at the methods: a domain
    with layout rules that declares only them lays out, and E0703 names what it does not declare."""
    hooks = (
        "    from physc.compiler.layout_rules import LayoutRules\n"
        "    layout_rules = LayoutRules(player='bird', flat='flatPlatform', ground='ground')\n"
        "    capabilities = frozenset({'layout_rules'})\n"
    )
    install("duck", SUBCLASS.format(name="duck", body=VOCABULARY + hooks))
    path = tmp_path / "scenario.phys"
    path.write_text("scenario SF {\n    domain duck\n    interactions { hit(bird, pig, any) > destroy(bird, pig) }\n}\n")
    assert run_physc("check", path).status == 0
    run = run_physc("compile", "--emit", "layout-graph", path)
    assert run.status == 0 and '"pig"' in run.stdout
    run = run_physc("compile", "-q", "--color", "never", "--emit", "layout", path)
    assert run.status == 2
    assert "the domain 'duck' cannot do what --emit layout needs: it has no layout_parameters, concretize\n" in run.stderr


def test_every_stage_says_what_it_asks_of_a_domain_and_angrybirds_has_it_all():
    assert list(NEEDS) == list(BY_NAME)
    assert missing(domains.load_domain("angrybirds"), REQUIRED + CAPABILITIES + DEFAULTS) == ()


def test_the_interface_is_documented_hook_by_hook():
    """Every public attribute of Domain is required, a capability or a default, and a row
    of the table in docs/plugins.md, "The domain interface"."""
    public = {name for name in dir(Domain) if not name.startswith("_")}
    # `satisfy` is a capability without a method (physc's search); `capabilities` declares them;
    # FILES are members of the domain's files.
    assert public == set(REQUIRED + CAPABILITIES + DEFAULTS) - {"satisfy"} - set(FILES) | {"capabilities"}
    section = PLUGINS[PLUGINS.index("## The domain interface") :]
    section = section[: section.index("\n## ", 1)]  # to the next section
    rows = re.findall(r"^\| `(\w+)", section, re.M)
    files = {name for name in dir(LevelFiles) if not name.startswith("_")} - {"domain"}
    evaluation = {name for name in dir(Evaluation) if not name.startswith("_")} - {"domain"}
    assert set(FILES) <= files and not files & public and not evaluation & public
    assert sorted(rows) == sorted(public | {"satisfy"} | files | evaluation)  # the domain's table, its files', its evaluation's
    assert set(FILES) <= set(CAPABILITIES)


def test_science_birds_fills_the_hooks_as_any_plugin_does():
    """Angry Birds writes its game as the scene and rules of a play (`simulation`), not plays,
    replays or stability tests of its own: every play goes through physc's loop, and its noise
    model is its actions' alone. The base classes stay narrow (issue 65: SimulatedDomain had 69
    public members, inherited ones counted)."""
    from physc.domains.angrybirds import AngryBirds
    from physc.domains.simulated import SimulatedDomain

    assert not {"play", "playout", "replay", "stability", "scene", "rules"} & set(vars(AngryBirds))
    assert "simulation" in AngryBirds.capabilities and "simulation" in vars(AngryBirds)
    assert len([n for n in dir(SimulatedDomain) if not n.startswith("_")]) <= 34
    assert len([n for n in dir(Domain) if not n.startswith("_")]) <= 20
