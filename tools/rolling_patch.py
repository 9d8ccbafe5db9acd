"""Make patches/rolling/rolling.patch: Phy-Q's Unity project changed to play physc's `rolling` world.

    python tools/rolling_patch.py BENCHMARK [-o patches/rolling/rolling.patch]

BENCHMARK is a phy-q/benchmark checkout (the folder holding `tasks/`), or that repository's
bare git directory (its HEAD is read). The patch changes the game's prefabs under
`tasks/task_template_designer/Assets/Resources/Prefabs/GameWorld/` exactly as physc's world
`rolling` differs from `phyq` (physc.domains.angrybirds.worlds):

* every prefab whose first collider (in the GameObject's component order) is a disabled
  CircleCollider2D followed by an enabled PolygonCollider2D (Circle, CircleSmall and the pigs
  BasicSmall, BasicMedium, BasicBig) gets the circle enabled (`m_Enabled: 0` -> `1`) and the
  polygon disabled (`m_Enabled: 1` -> `0`);
* every block and pig prefab that physc's prefabs.json knows (kind `block` or `pig`) gets
  Rigidbody2D `m_AngularDrag: 2` -> `0.05`. Birds, TNT and the platform are left alone.

The prefabs come from physc/domains/angrybirds/prefabs.json (tools/extract_prefabs.py), and
each is checked against the Unity file itself: the generator stops, changing nothing, if a
file no longer says what the data says (a line to change missing or with another value, the
colliders in another order), so a new checkout that differs is noticed rather than patched
blindly. Block and pig prefab files that physc does not know are named on stderr.

The diff is written with git's headers (`diff --git`, the blobs' ids) and enough context that
every hunk shows the Unity class (`CircleCollider2D:`, `Rigidbody2D:`) of each line it changes;
a short preamble before the first `diff --git` (which `git apply` skips) says where it came
from. It is then checked: the original files are copied to a temporary folder and
`git apply --check -p1` must accept the patch there (and `git apply -R --check` the patched
files). Only the standard library and git are needed.
"""

from __future__ import annotations

import argparse
import difflib
import hashlib
import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PREFABS_JSON = ROOT / "physc/domains/angrybirds/prefabs.json"
OUT = ROOT / "patches/rolling/rolling.patch"
PROJECT = "tasks/task_template_designer"
GAMEWORLD = f"{PROJECT}/Assets/Resources/Prefabs/GameWorld"
FOLDERS = {"block": "Blocks", "pig": "Characters/Pigs"}
COLLIDERS = ("BoxCollider2D", "CircleCollider2D", "PolygonCollider2D")
OLD_DRAG, NEW_DRAG = "2", "0.05"
MODE = "100644"


class Source:
    """The benchmark repository's files: from a checkout's work tree or a bare git directory's HEAD."""

    def __init__(self, path: Path):
        self.path = path
        self.bare = not (path / PROJECT).is_dir()
        if self.bare and not (path / "HEAD").is_file():
            raise SystemExit(f"{path}: neither a phy-q/benchmark checkout (no {PROJECT}/) nor a git directory")
        self.commit = self._git("rev-parse", "HEAD").strip() if self._is_git() else None

    def _git(self, *args: str) -> str:
        where = ["--git-dir", str(self.path)] if self.bare else ["-C", str(self.path)]
        return subprocess.run(["git", *where, *args], check=True, capture_output=True, text=True).stdout

    def _is_git(self) -> bool:
        try:
            self._git("rev-parse", "HEAD")
            return True
        except (subprocess.CalledProcessError, FileNotFoundError):
            return False

    def read(self, rel: str) -> bytes:
        if not self.bare:
            return (self.path / rel).read_bytes()
        where = ["--git-dir", str(self.path)]
        return subprocess.run(["git", *where, "show", f"HEAD:{rel}"], check=True, capture_output=True).stdout

    def prefab_names(self, folder: str) -> set[str]:
        """The .prefab files directly in a GameWorld folder (not its subfolders)."""
        if not self.bare:
            return {p.stem for p in (self.path / GAMEWORLD / folder).glob("*.prefab")}
        names = self._git("ls-tree", "--name-only", f"HEAD:{GAMEWORLD}/{folder}").split("\n")
        return {n[: -len(".prefab")] for n in names if n.endswith(".prefab")}


def documents(lines: list[str]) -> list[tuple[str, str, int, int]]:
    """A Unity YAML file's objects: (file id, class name, index of the class line, end index)."""
    heads = [i for i, line in enumerate(lines) if line.startswith("--- !u!")]
    out = []
    for n, i in enumerate(heads):
        end = heads[n + 1] if n + 1 < len(heads) else len(lines)
        file_id = re.match(r"--- !u!\d+ &(-?\d+)", lines[i]).group(1)
        out.append((file_id, lines[i + 1].rstrip("\r\n").rstrip(":"), i + 1, end))
    return out


def component_order(lines: list[str], docs) -> list[str]:
    """The file ids of the GameObject's components, in order."""
    (_, _, start, end), = [d for d in docs if d[1] == "GameObject"]
    return re.findall(r"^  - component: \{fileID: (-?\d+)\}", "".join(lines[start:end]), flags=re.M)


def set_field(lines: list[str], doc, field: str, old: str, new: str, where: str) -> tuple[int, int]:
    """Change `  field: old` to `  field: new` in one object; (index of its class line, of the changed line)."""
    _, name, start, end = doc
    hits = [i for i in range(start, end) if re.match(rf"  {field}: ", lines[i])]
    if len(hits) != 1:
        raise SystemExit(f"{where}: {name} has {len(hits)} `{field}` lines, expected 1")
    i = hits[0]
    ending = lines[i][len(lines[i].rstrip("\r\n")):]
    value = lines[i].rstrip("\r\n").split(": ", 1)[1]
    if value != old:
        raise SystemExit(f"{where}: {name} {field} is {value}, expected {old}: the checkout differs from what physc knows")
    lines[i] = f"  {field}: {new}{ending}"
    return start, i


def circle_first(colliders: list[dict]) -> bool:
    """prefabs.json's rule: the first collider a disabled circle, the next an enabled polygon."""
    return (
        len(colliders) >= 2 and colliders[0]["type"] == "circle" and not colliders[0]["enabled"]
        and colliders[1]["type"] == "polygon" and colliders[1]["enabled"]
    )


def edit(text: str, where: str, drag: bool, circle: bool) -> tuple[str, list[tuple[int, int]]]:
    """The prefab's text changed for `rolling`, and (class line, changed line) for each change."""
    lines = text.splitlines(keepends=True)
    docs = documents(lines)
    by_id = {d[0]: d for d in docs}
    order = [by_id[c] for c in component_order(lines, docs)]
    colliders = [d for d in order if d[1] in COLLIDERS]
    changes = []
    file_circle_first = (
        len(colliders) >= 2 and colliders[0][1] == "CircleCollider2D" and colliders[1][1] == "PolygonCollider2D"
        and _value(lines, colliders[0], "m_Enabled") == "0" and _value(lines, colliders[1], "m_Enabled") == "1"
    )
    if file_circle_first != circle:
        raise SystemExit(f"{where}: the file {'has' if file_circle_first else 'lacks'} a disabled circle first, prefabs.json says otherwise")
    if circle:
        changes.append(set_field(lines, colliders[0], "m_Enabled", "0", "1", where))
        changes.append(set_field(lines, colliders[1], "m_Enabled", "1", "0", where))
    if drag:
        (body,) = [d for d in order if d[1] == "Rigidbody2D"]
        changes.append(set_field(lines, body, "m_AngularDrag", OLD_DRAG, NEW_DRAG, where))
    return "".join(lines), sorted(changes, key=lambda c: c[1])


def _value(lines: list[str], doc, field: str) -> str | None:
    _, _, start, end = doc
    for i in range(start, end):
        if lines[i].startswith(f"  {field}: "):
            return lines[i].rstrip("\r\n").split(": ", 1)[1]
    return None


def blob_id(data: bytes) -> str:
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def file_diff(rel: str, old: bytes, new: bytes, context: int) -> str:
    a = old.decode("utf-8").splitlines(keepends=True)
    b = new.decode("utf-8").splitlines(keepends=True)
    body = []
    for line in difflib.unified_diff(a, b, f"a/{rel}", f"b/{rel}", n=context):
        body.append(line if line.endswith("\n") else line + "\n\\ No newline at end of file\n")
    header = f"diff --git a/{rel} b/{rel}\nindex {blob_id(old)}..{blob_id(new)} {MODE}\n"
    return header + "".join(body)


def make(source: Source) -> tuple[str, dict[str, tuple[bytes, bytes]]]:
    """The patch's text, and each changed file's original and patched bytes."""
    known = json.loads(PREFABS_JSON.read_text(encoding="utf-8"))["prefabs"]
    for kind, folder in FOLDERS.items():
        unknown = source.prefab_names(folder) - {n for n, p in known.items() if p["kind"] == kind}
        if unknown:
            print(f"note: {GAMEWORLD}/{folder} has prefabs physc does not know, left alone: {', '.join(sorted(unknown))}", file=sys.stderr)
    files, edits = {}, {}
    for name in sorted(known):
        prefab = known[name]
        drag = prefab["kind"] in FOLDERS
        circle = circle_first(prefab["colliders"])
        if not (drag or circle):
            continue
        if circle and not drag:
            raise SystemExit(f"{name}: a {prefab['kind']} with a disabled circle first; the patch covers blocks and pigs")
        if float(prefab["rigidbody"]["angular_drag"]) != float(OLD_DRAG):
            raise SystemExit(f"{name}: prefabs.json's angular drag is {prefab['rigidbody']['angular_drag']}, expected {OLD_DRAG}")
        rel = f"{GAMEWORLD}/{FOLDERS[prefab['kind']]}/{name}.prefab"
        old = source.read(rel)
        new, changes = edit(old.decode("utf-8"), rel, drag, circle)
        files[rel] = (old, new.encode("utf-8"))
        edits[rel] = changes
    # Enough context that each hunk shows the class line of every line it changes.
    context = max(3, *(changed - cls for changes in edits.values() for cls, changed in changes))
    made_from = f"phy-q/benchmark commit {source.commit}" if source.commit else "a phy-q/benchmark checkout"
    preamble = (
        "physc world `rolling`: Phy-Q's Science Birds with the circle colliders of Circle, CircleSmall and the\n"
        "pigs enabled (their polygons disabled) and angular drag 0.05 on every block and pig.\n"
        f"Made by tools/rolling_patch.py from {made_from}; see patches/rolling/README.md.\n"
        "Apply from the repository root: git apply -p1 rolling.patch\n\n"
    )
    patch = preamble + "".join(file_diff(rel, *files[rel], context) for rel in sorted(files))
    return patch, files


def check(patch: str, files: dict[str, tuple[bytes, bytes]]) -> None:
    """`git apply --check` on copies of the originals (and `-R --check` on the patched files)."""
    with tempfile.TemporaryDirectory() as tmp:
        for side, reverse in ((0, []), (1, ["-R"])):
            tree = Path(tmp) / ("old", "new")[side]
            for rel, pair in files.items():
                (tree / rel).parent.mkdir(parents=True, exist_ok=True)
                (tree / rel).write_bytes(pair[side])
            (Path(tmp) / "rolling.patch").write_text(patch, encoding="utf-8")
            run = subprocess.run(["git", "apply", *reverse, "--check", "-p1", str(Path(tmp) / "rolling.patch")], cwd=tree, capture_output=True, text=True)
            if run.returncode:
                raise SystemExit(f"git apply {' '.join(reverse)} --check failed:\n{run.stderr}")
        old = Path(tmp) / "old"
        subprocess.run(["git", "apply", "-p1", str(Path(tmp) / "rolling.patch")], cwd=old, check=True)
        for rel, (_, new) in files.items():
            if (old / rel).read_bytes() != new:
                raise SystemExit(f"{rel}: git apply's result differs from the generator's")
        shutil.rmtree(old)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("benchmark", type=Path, help="a phy-q/benchmark checkout, or its bare git directory")
    parser.add_argument("-o", "--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    patch, files = make(Source(args.benchmark))
    check(patch, files)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(patch, encoding="utf-8", newline="\n")
    print(f"{len(files)} prefabs -> {args.out} (git apply --check: ok)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
