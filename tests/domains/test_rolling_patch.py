"""patches/rolling/rolling.patch says what the world `rolling` says.

The patch (made by tools/rolling_patch.py from phy-q/benchmark) changes Phy-Q's Unity prefabs so
that the game plays physc's `rolling` world. These tests read the patch as text (no checkout of
the game is needed) and check it against physc: its prefab data (prefabs.json) and the worlds
PHYQ and ROLLING.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[2]
PATCH = ROOT / "patches/rolling/rolling.patch"
PREFABS_JSON = ROOT / "physc/domains/angrybirds/prefabs.json"
GAMEWORLD = "tasks/task_template_designer/Assets/Resources/Prefabs/GameWorld/"
FOLDERS = {"block": "Blocks/", "pig": "Characters/Pigs/"}
# The only lines the patch may change: (Unity class, field) -> (old value, new value).
ALLOWED = {
    ("CircleCollider2D", "m_Enabled"): ("0", "1"),
    ("PolygonCollider2D", "m_Enabled"): ("1", "0"),
    ("Rigidbody2D", "m_AngularDrag"): ("2", "0.05"),
}
HUNK = re.compile(r"^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@")
FIELD = re.compile(r"^  (m_\w+): (.*)$")


def parse(text: str) -> dict[str, list[tuple[str, str, str, str]]]:
    """The patch's files (path → changes), each change (class, field, old value, new value).

    The class of a changed line is the last Unity class line (`Rigidbody2D:` at column 0) before
    it in its hunk; the generator gives every hunk enough context to show it."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    files: dict[str, list] = {}
    i = 0
    while i < len(lines) and not lines[i].startswith("diff --git "):
        i += 1  # the preamble, which git apply skips
    assert i < len(lines), "the patch has no diff --git"
    path = None
    while i < len(lines):
        line = lines[i]
        if line.startswith("diff --git "):
            a, b = line[len("diff --git "):].split(" ")
            assert a.startswith("a/") and b.startswith("b/") and a[2:] == b[2:], line
            path = a[2:]
            assert path not in files, f"{path} twice"
            files[path] = []
            i += 1
            while i < len(lines) and not lines[i].startswith("@@"):
                header = lines[i]
                assert header.startswith(("index ", "--- ", "+++ ")), header
                if header.startswith("--- "):
                    assert header == f"--- a/{path}", header
                if header.startswith("+++ "):
                    assert header == f"+++ b/{path}", header
                i += 1
            continue
        match = HUNK.match(line)
        assert match and path, f"unexpected line {i + 1}: {line!r}"
        old_n = int(match.group(2) or 1)
        new_n = int(match.group(4) or 1)
        i += 1
        cls = None
        removed: list[str] = []
        while old_n or new_n:
            assert i < len(lines), f"{path}: the hunk is shorter than its header says"
            body = lines[i]
            i += 1
            mark, content = body[:1], body[1:]
            if mark in (" ", "-") and re.fullmatch(r"[A-Za-z0-9]+:", content):
                cls = content[:-1]
            if mark == " ":
                assert not removed, f"{path}: a removed line with no replacement"
                old_n -= 1
                new_n -= 1
            elif mark == "-":
                removed.append(content)
                old_n -= 1
            elif mark == "+":
                assert removed, f"{path}: an added line that replaces nothing: {content!r}"
                old = FIELD.match(removed.pop(0))
                new = FIELD.match(content)
                assert old and new and old.group(1) == new.group(1), f"{path}: {content!r}"
                assert cls is not None, f"{path}: no Unity class in the hunk before {content!r}"
                files[path].append((cls, old.group(1), old.group(2), new.group(2)))
                new_n -= 1
            else:
                raise AssertionError(f"{path}: bad hunk line {body!r}")
            assert old_n >= 0 and new_n >= 0, f"{path}: the hunk is longer than its header says"
        assert not removed, f"{path}: a removed line with no replacement"
        while i < len(lines) and lines[i].startswith("\\"):
            i += 1  # "\ No newline at end of file"
    return files


@pytest.fixture(scope="module")
def patch() -> dict[str, list[tuple[str, str, str, str]]]:
    return parse(PATCH.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def known() -> dict:
    return json.loads(PREFABS_JSON.read_text(encoding="utf-8"))["prefabs"]


def prefab_name(path: str) -> str:
    return path.rsplit("/", 1)[1].removesuffix(".prefab")


def changed(patch, cls: str, field: str) -> dict[str, tuple[str, str]]:
    """Prefab name → (old, new) for each prefab whose `cls`'s `field` the patch changes."""
    out = {}
    for path, changes in patch.items():
        hits = [(old, new) for c, f, old, new in changes if (c, f) == (cls, field)]
        assert len(hits) <= 1, f"{path}: {cls}.{field} changed {len(hits)} times"
        if hits:
            out[prefab_name(path)] = hits[0]
    return out


def round_in_data(prefab: dict) -> bool:
    """prefabs.json: the first collider a disabled circle, the next an enabled polygon."""
    c = prefab["colliders"]
    return len(c) >= 2 and c[0]["type"] == "circle" and not c[0]["enabled"] and c[1]["type"] == "polygon" and c[1]["enabled"]


def test_the_patch_changes_only_prefabs_of_the_game_world_and_only_the_three_fields(patch, known):
    assert patch
    for path, changes in patch.items():
        assert path.startswith(GAMEWORLD) and path.endswith(".prefab"), path
        name = prefab_name(path)
        assert name in known, f"{path}: a prefab physc does not know"
        assert path == GAMEWORLD + FOLDERS[known[name]["kind"]] + name + ".prefab", path
        assert changes, f"{path}: no change"
        for cls, field, old, new in changes:
            assert ALLOWED.get((cls, field)) == (old, new), f"{path}: {cls}.{field} {old} -> {new}"


def test_the_drag_changes_on_every_block_and_pig_and_nothing_else(patch, known):
    drag = changed(patch, "Rigidbody2D", "m_AngularDrag")
    assert set(drag) == {n for n, p in known.items() if p["kind"] in ("block", "pig")}
    for name, (old, new) in drag.items():
        assert float(old) == known[name]["rigidbody"]["angular_drag"] == 2.0, name
        assert float(new) == 0.05, name
    untouched = {n for n, p in known.items() if p["kind"] in ("bird", "tnt", "platform")}
    assert untouched and not untouched & {prefab_name(p) for p in patch}


def test_the_circles_enabled_are_the_prefabs_with_a_disabled_circle_first(patch, known):
    circles = changed(patch, "CircleCollider2D", "m_Enabled")
    polygons = changed(patch, "PolygonCollider2D", "m_Enabled")
    expected = {n for n, p in known.items() if round_in_data(p)}
    assert expected == {"Circle", "CircleSmall", "BasicSmall", "BasicMedium", "BasicBig"}
    assert set(circles) == set(polygons) == expected
    assert set(circles.values()) == {("0", "1")} and set(polygons.values()) == {("1", "0")}


def test_the_patch_gives_the_rolling_worlds_angular_drag(patch):
    from physc.domains.angrybirds.worlds import PHYQ, ROLLING

    drag = changed(patch, "Rigidbody2D", "m_AngularDrag")
    assert drag
    for name, (old, new) in drag.items():
        assert float(old) == PHYQ.bodies.angular_drag, name
        assert float(new) == ROLLING.bodies.angular_drag, name


def test_the_prefabs_made_round_are_those_the_rolling_world_treats_as_round(patch, known):
    from physc.domains.angrybirds.prefabs import circle_first
    from physc.domains.angrybirds.worlds import PHYQ, ROLLING

    assert ROLLING.bodies.circle_colliders is True and PHYQ.bodies.circle_colliders is False
    circles = changed(patch, "CircleCollider2D", "m_Enabled")
    assert set(circles) == {name for name in known if circle_first(name)}
