"""docs/architecture.md and the other docs hold against the tree: the floors' table names every
package and top module of physc/ and only those, every import runs down the floors, and every
path or module a doc cites exists (issue 72). History pages (docs/*-history.md) cite what was at
their commits and are left out."""

from __future__ import annotations

import ast
import importlib
import re
import warnings
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PHYSC = ROOT / "physc"
OUTSIDE = {"benchmarks/": ROOT / "benchmarks"}  # floors the table gives to folders outside physc/
CURRENT_DOCS = sorted(
    [p for p in (ROOT / "docs").glob("*.md") if not p.name.endswith("-history.md")]
    + [ROOT / "README.md", ROOT / "plugins" / "physc-phyre" / "README.md"]
)


def _outside_parentheses(text: str) -> str:
    """`text` without what stands in (nested) parentheses: the table's asides name classes and
    files inside a unit, not units."""
    kept, depth = [], 0
    for char in text:
        depth += char == "("
        if depth == 0:
            kept.append(char)
        depth -= char == ")" and depth > 0
    return "".join(kept)


def floors() -> dict[str, int]:
    """The floors' table of docs/architecture.md: unit (a package as `dsl/`, a module as `budget`)
    → its floor; a row "11–13" gives its units the floors in turn."""
    table = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8").split("## The floors", 1)[1]
    found: dict[str, int] = {}
    for row in re.finditer(r"^\| (\d+)(?:–(\d+))? \| (.+?) \| .+ \|$", table, re.M):
        first = int(row.group(1))
        for k, name in enumerate(re.findall(r"`([\w/]+)`", _outside_parentheses(row.group(3)))):
            found[name] = first + k if row.group(2) else first
    return found


def units() -> set[str]:
    """physc's packages (`dsl/`) and top modules (`budget`), as the table names them."""
    packages = {f"{p.name}/" for p in PHYSC.iterdir() if p.is_dir() and any(p.glob("*.py"))}
    modules = {p.stem for p in PHYSC.glob("*.py") if p.stem != "__init__"}
    return packages | modules


def unit_of(module: str) -> str | None:
    """The unit a dotted module name of physc belongs to (None: physc itself)."""
    parts = module.split(".")
    if parts[0] != "physc" or len(parts) == 1:
        return None
    if (PHYSC / parts[1]).is_dir():
        return f"{parts[1]}/"
    return parts[1] if (PHYSC / f"{parts[1]}.py").exists() else None  # else a name physc exports


def imports(path: Path) -> set[str]:
    """Every physc module `path` imports, at the top, inside functions or for types alone."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found |= {node.module} | {f"{node.module}.{alias.name}" for alias in node.names}
    return {name for name in found if name.startswith("physc.")}


def test_the_floors_name_every_unit_of_physc_and_nothing_else():
    table = floors()
    named = {name for name in table if name not in OUTSIDE}
    assert named == units(), (sorted(units() - named), sorted(named - units()))
    assert all(path.is_dir() for path in OUTSIDE.values())


def test_every_import_runs_down_the_floors():
    table = floors()
    upward = []
    for path in sorted(PHYSC.rglob("*.py")):
        module = ".".join(path.relative_to(ROOT).with_suffix("").parts).removesuffix(".__init__")
        own = unit_of(module)
        if own is None:
            continue  # physc/__init__.py: it exports names lazily and imports nothing at import time
        for name in imports(path):
            other = unit_of(name)
            if other is not None and other != own and table[other] >= table[own]:
                upward.append(f"{module} ({own}, floor {table[own]}) imports {name} (floor {table[other]})")
    assert not upward, "\n".join(upward)


TOP = "physc|plugins|tests|benchmarks|tools|docs|examples|grammar"  # the tree's top folders
PATH = re.compile(rf"(?<![\w/.-])((?:{TOP})/[\w./*\[\]{{}},-]*[\w*\]}}])")
MODULE = re.compile(r"(?<![\w./-])(physc(?:_phyre)?(?:\.\w+)+)")
NOT_PATHS = re.compile(r"^physc/\w+-v\d+$")  # Gymnasium's environment ids (physc/AngryBirds-v0)
OTHER_TREES = {"phyre-sources.md"}  # its paths are PHYRE's repository's
NOT_MODULES = {"physc.path", "physc.trace.server", "physc.actions", "physc.names"}  # editor settings, task fields


def _exists(cited: str) -> bool:
    """Whether a cited path names something in the tree: itself, what its glob matches, or (a
    family of result folders cited by its stem, `phyq-scenarios-15-*`) a name it begins."""
    for base in (ROOT, ROOT / "plugins" / "physc-phyre"):
        if any(char in cited for char in "*[{"):
            if any(base.glob(re.sub(r"\{[^}]*\}", "*", cited))):
                return True
        elif (base / cited).exists() or any((base / cited).parent.glob(Path(cited).name + "*")):
            return True
    return False


def _resolves(name: str) -> bool:
    """Whether a dotted name is a module of physc or its plugin, or a name in one."""
    parts = name.split(".")
    for k in range(len(parts), 0, -1):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", DeprecationWarning)  # the old paths of physc.generation
                found = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for attribute in parts[k:]:
            if not hasattr(found, attribute):
                return False
            found = getattr(found, attribute)
        return True
    return False


@pytest.mark.parametrize("doc", CURRENT_DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_path_and_module_a_doc_cites_exists(doc):
    text = doc.read_text(encoding="utf-8")
    missing = set()
    for line in text.splitlines():
        if "git history" in line or "git show" in line:
            continue  # what the line says is in git history, not the tree
        if doc.name not in OTHER_TREES:
            paths = {p[:-1] if p.endswith("]") and "[" not in p else p for p in PATH.findall(line)}
            missing |= {p for p in paths if not NOT_PATHS.match(p) and not _exists(p)}
        missing |= {m for m in MODULE.findall(line) if m not in NOT_MODULES and not _resolves(m)}
    assert not missing, sorted(missing)


MODULE_LINES = 400  # the most lines a module of physc/ has (issue 72)
FUNCTION_LINES = 80  # the most lines a function of physc/ has, its docstring included


def test_modules_and_functions_stay_small():
    over = []
    for path in sorted(PHYSC.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if len(text.splitlines()) > MODULE_LINES:
            over.append(f"{path.relative_to(ROOT)}: {len(text.splitlines())} lines")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                length = (node.end_lineno or node.lineno) - node.lineno + 1
                if length > FUNCTION_LINES:
                    over.append(f"{path.relative_to(ROOT)}:{node.lineno} {node.name}: {length} lines")
    assert not over, "\n".join(over)
