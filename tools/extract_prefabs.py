"""Read Science Birds' physics facts from the game's own Unity files into physc's data file.

    python tools/extract_prefabs.py UNITY_PROJECT [-o physc/domains/angrybirds/prefabs.json]

UNITY_PROJECT is the Unity project of the game (Phy-Q: phy-q/benchmark,
`tasks/task_template_designer/`). For every prefab under
`Assets/Resources/Prefabs/GameWorld/` that physc plays (the blocks, the pigs, the birds, TNT,
the platform) it writes, in the prefab's own component order:

* the Rigidbody2D: body type, mass as saved (Unity's auto mass at collider density 1),
  angular and linear drag, gravity scale, collision detection (0 discrete, 1 continuous) and
  its physics material;
* each Collider2D: its type (box, circle, polygon), whether it is enabled, its offset, its
  size, radius or paths, its density and its own physics material;
* the game script's fields (life, density, defence, a block's life per material, TNT's
  explosion, a bird's drag radius and launch gravity, its damage multipliers) and of its
  ABParticleSystem (`_systemLifetime`: how long a dying object stays before Destroy);

and the friction and bounciness of every physics material it names. Reading Unity's YAML
needs PyYAML (a maintenance tool, not a dependency of physc). physc's angrybirds domain reads
the JSON file this writes (physc.domains.angrybirds.prefabs); docs/angrybirds.md cites it.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path

import yaml

KINDS = {"Blocks": "block", "Characters/Pigs": "pig", "Characters/Birds": "bird"}
SINGLE = {"TNT": "tnt", "Platform": "platform"}
COLLIDERS = {"BoxCollider2D": "box", "CircleCollider2D": "circle", "PolygonCollider2D": "polygon"}
SCRIPT_FIELDS = (
    "_life", "_density", "_defense", "_woodLife", "_stoneLife", "_iceLife", "_explosionArea", "_explosionPower",
    "_explosionDamage", "_dragRadius", "_launchGravity", "_woodDamageMultiplier", "_stoneDamageMultiplier",
    "_iceDamageMultiplier", "lifeTime", "_systemLifetime",
)


def documents(path: Path) -> dict[str, tuple[str, dict]]:
    """A Unity YAML file's objects: file id → (class name, fields)."""
    text = path.read_text(encoding="utf-8-sig").replace("\r", "")
    out = {}
    parts = re.split(r"^--- !u!\d+ &(-?\d+).*$", text, flags=re.M)
    for file_id, body in zip(parts[1::2], parts[2::2]):
        data = yaml.safe_load(body) or {}
        (name, fields), = data.items()
        out[file_id] = (name, fields or {})
    return out


def materials(project: Path) -> dict[str, dict]:
    """Every physics material of the project: guid → name, friction, bounciness."""
    out = {}
    for path in sorted(project.glob("Assets/**/*.physicsMaterial2D")):
        guid = re.search(r"^guid: (\w+)", Path(str(path) + ".meta").read_text(), re.M).group(1)
        (_, fields), = documents(path).values()
        out[guid] = {"name": fields["m_Name"], "friction": float(fields["friction"]), "bounciness": float(fields["bounciness"])}
    return out


def _material(reference: dict, known: dict) -> str | None:
    guid = (reference or {}).get("guid")
    return known[guid]["name"] if guid in known else None


def prefab(path: Path, kind: str, known: dict) -> dict:
    objects = documents(path)
    root = next(fields for name, fields in objects.values() if name == "GameObject")
    order = [str(c["component"]["fileID"]) for c in root["m_Component"]]
    out = {"kind": kind, "colliders": [], "script": {}}
    for file_id in order:
        name, fields = objects[file_id]
        if name == "Rigidbody2D":
            out["rigidbody"] = {
                "body_type": int(fields["m_BodyType"]), "mass": float(fields["m_Mass"]), "angular_drag": float(fields["m_AngularDrag"]),
                "linear_drag": float(fields["m_LinearDrag"]), "gravity_scale": float(fields["m_GravityScale"]),
                "collision_detection": int(fields["m_CollisionDetection"]), "material": _material(fields.get("m_Material"), known),
            }
        elif name in COLLIDERS:
            collider = {
                "type": COLLIDERS[name], "enabled": bool(fields["m_Enabled"]), "density": float(fields.get("m_Density", 1)),
                "offset": [float(fields["m_Offset"]["x"]), float(fields["m_Offset"]["y"])], "material": _material(fields.get("m_Material"), known),
            }
            if name == "BoxCollider2D":
                collider["size"] = [float(fields["m_Size"]["x"]), float(fields["m_Size"]["y"])]
            elif name == "CircleCollider2D":
                collider["radius"] = float(fields["m_Radius"])
            else:
                collider["paths"] = [[[float(p["x"]), float(p["y"])] for p in path_] for path_ in fields["m_Points"]["m_Paths"]]
            out["colliders"].append(collider)
        elif name == "MonoBehaviour":
            out["script"].update({k: float(fields[k]) for k in SCRIPT_FIELDS if k in fields})
    return out


def extract(project: Path) -> dict:
    known = materials(project)
    root = project / "Assets/Resources/Prefabs/GameWorld"
    prefabs = {}
    for folder, kind in KINDS.items():
        for path in sorted((root / folder).glob("*.prefab")):  # not the birds "Not Used"
            prefabs[path.stem] = prefab(path, kind, known)
    for name, kind in SINGLE.items():
        prefabs[name] = prefab(root / f"{name}.prefab", kind, known)
    return {"source": "phy-q/benchmark tasks/task_template_designer", "materials": {m["name"]: m for m in known.values()}, "prefabs": prefabs}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("project", type=Path)
    parser.add_argument("-o", "--out", type=Path, default=Path(__file__).parents[1] / "physc/domains/angrybirds/prefabs.json")
    args = parser.parse_args(argv)
    data = extract(args.project)
    args.out.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    print(f"{len(data['prefabs'])} prefabs, {len(data['materials'])} materials -> {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
