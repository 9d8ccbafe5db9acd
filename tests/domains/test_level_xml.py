"""Science Birds level files: the 75 real templates and generated levels, round trips, the exact format."""

from __future__ import annotations

import re

import pytest
from conftest import GENERATED, TEMPLATES, run_physc

from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.level_xml import LevelError, emit_level, parse_level, read_level


def test_the_real_levels_are_here():
    assert len(TEMPLATES) == 75
    assert len(GENERATED) == 60
    assert sum(b'<TNT type=""' in path.read_bytes() for path in GENERATED) == 30


@pytest.mark.parametrize("path", TEMPLATES + GENERATED, ids=lambda p: p.stem)
def test_import_emit_import_is_lossless(path):
    data = path.read_bytes()
    assert data.startswith(b'<?xml version="1.0" encoding="utf-16"?>')  # declared utf-16, actually ASCII
    level = read_level(data)
    assert len(level.objects) == data.count(b"<Block") + data.count(b"<Pig") + data.count(b"<Platform") + data.count(b"<TNT")
    again = parse_level(emit_level(level))
    assert again == level
    assert emit_level(again) == emit_level(level)


def test_real_utf16_files_are_read_too():
    text = emit_level(Level(objects=(LevelObject("Pig", "BasicSmall", 1.5, -3.26, 0.0),)))
    assert read_level(text.encode("utf-16")) == parse_level(text)


def test_emitted_format():
    level = Level(
        objects=(
            LevelObject("Block", "Circle", -3.9246, 4.3121, 0.1114, "wood"),
            LevelObject("Pig", "BasicSmall", -7.692, 2.5967, 1.1086, ""),
            LevelObject("Platform", "Platform", -7.782, 2.1181, 0.0, "", 3.2197, 0.758),
            LevelObject("TNT", "TNT", 1.566, 0.03508, 0.0),
        )
    )
    assert emit_level(level) == (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        '<Level width="2">\n'
        '  <Camera x="0" y="-1" minWidth="25" maxWidth="35" />\n'
        '  <Score highScore="0" />\n'
        "  <Birds>\n"
        '    <Bird type="BirdRed" />\n'
        "  </Birds>\n"
        '  <Slingshot x="-12" y="-2.5" />\n'
        "  <GameObjects>\n"
        '    <Block type="Circle" material="wood" x="-3.9246" y="4.3121" rotation="0.1114" />\n'
        '    <Pig type="BasicSmall" material="" x="-7.692" y="2.5967" rotation="1.1086" />\n'
        '    <Platform type="Platform" material="" x="-7.782" y="2.1181" rotation="0" scaleX="3.2197" scaleY="0.758" />\n'
        '    <TNT type="TNT" x="1.566" y="0.03508" rotation="0" />\n'
        "  </GameObjects>\n"
        "</Level>\n"
    )


def test_one_element_per_line_and_no_comments():
    for path in TEMPLATES[:10]:
        text = emit_level(read_level(path.read_bytes()))
        assert "<!--" not in text
        assert all(line.count("<") == 1 for line in text.splitlines())
        assert not re.search(r"\d[eE][-+]?\d", text)


def test_tnt_and_platform_are_their_prefab_whatever_their_type_says():
    # Phy-Q's generator writes <TNT type="">; the game's loader never reads a TNT's or a platform's type.
    text = (
        "<Level><GameObjects>\n"
        '<TNT type="" x="1.5499" y="3.4444" rotation="0.0" />\n'
        '<TNT x="2" y="3" />\n'
        '<Platform type="" material="" x="0" y="0" scaleX="-1.3" />\n'
        '<Pig type="BasicSmall" material="" x="1" y="2" />\n'
        "</GameObjects></Level>"
    )
    tnt, bare, platform, pig = parse_level(text).objects
    assert (tnt.type, tnt.name, bare.type, bare.name) == ("TNT", "tnt1", "TNT", "tnt2")
    assert (platform.type, platform.scale_x, platform.rotation) == ("Platform", -1.3, None)
    assert pig.material == ""  # what the file says; the game ignores a pig's material
    assert '<TNT type="TNT" x="1.5499" y="3.4444" rotation="0" />' in emit_level(parse_level(text))


def test_a_real_generated_level_with_tnt_type_empty_loads():
    path = next(p for p in GENERATED if b'<TNT type=""' in p.read_bytes())
    level = read_level(path.read_bytes())
    assert [o.type for o in level.objects if o.element == "TNT"] == ["TNT"]


@pytest.mark.parametrize(
    "text, code",
    [
        ("<Level><GameObjects><Block type='Circel' material='wood' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><Block type='Circle' material='wood' x='1'/></GameObjects></Level>", "E0902"),
        ("<Level><GameObjects><Block type='Circle' material='wood' x='one' y='2'/></GameObjects></Level>", "E0902"),
        ("<Level><GameObjects><Block type='Circle' material='wood' x='' y='2'/></GameObjects></Level>", "E0902"),
        ("<Level><GameObjects><Block type='Circle' material='wood' x='1' y=2/></GameObjects></Level>", "E0901"),
        ("<Scene/>", "E0901"),
        ("<Level><Birds><Bird type='BirdPink'/></Birds></Level>", "E0903"),
        ("<Level><Birds><Bird/></Birds></Level>", "E0903"),
        ("<Level><GameObjects><Rock type='Circle' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><Block material='wood' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><Block type='BasicSmall' material='wood' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><Pig type='Circle' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><TNT type='Circle' x='1' y='2'/></GameObjects></Level>", "E0903"),
        ("<Level><GameObjects><Block type='Circle' x='1' y='2'/></GameObjects></Level>", "E0905"),
        ("<Level><GameObjects><Block type='Circle' material='' x='1' y='2'/></GameObjects></Level>", "E0905"),
    ],
)
def test_bad_levels_are_level_errors(text, code):
    with pytest.raises(LevelError) as caught:
        parse_level(text)
    assert caught.value.code == code


def test_an_unknown_type_names_the_element_its_line_and_the_known_types():
    text = '<?xml version="1.0" encoding="utf-16"?>\n<Level>\n  <GameObjects>\n    <Pig type="BasicSmall" x="1" y="2" />\n    <Block type="Circel" material="wood" x="1" y="2"/>\n  </GameObjects>\n</Level>\n'
    with pytest.raises(LevelError) as caught:
        parse_level(text)
    error = caught.value
    assert (error.code, error.line, error.column) == ("E0903", 5, 12)  # the type attribute
    assert error.message == "unknown object type 'Circel' for <Block>"
    assert error.help.startswith("did you mean 'Circle'? (<Block> types: ") and "RectFat" in error.help
    assert str(error) == "line 5:12: unknown object type 'Circel' for <Block>"


def test_an_unknown_material_suggests_the_right_one():
    with pytest.raises(LevelError) as caught:
        parse_level("<Level>\n<GameObjects>\n<Block type='Circle' material='Wood' x='1' y='2'/></GameObjects></Level>")
    assert (caught.value.code, caught.value.line) == ("E0905", 3)
    assert caught.value.help == "did you mean 'wood'? (materials: wood, stone, ice)"


def test_bad_level_on_the_command_line(tmp_path):
    path = tmp_path / "bad.xml"
    path.write_text("<Level>\n<GameObjects><Block type='Circel' material='wood' x='1' y='2'/></GameObjects></Level>")
    run = run_physc("simulate", path, "--color", "never")
    assert run.status == 1
    assert f"{path}:2:21: error[E0903]: unknown object type 'Circel' for <Block>" in run.stderr
    assert "did you mean 'Circle'?" in run.stderr
    assert run_physc("simulate", tmp_path / "none.xml").status == 2
    binary = tmp_path / "binary.xml"
    binary.write_bytes(bytes(range(256)))
    assert run_physc("simulate", binary).status == 1


def test_emitted_files_are_what_they_declare():
    """Issue 55: the declaration is utf-8 and the bytes are UTF-8 (ASCII), so standard parsers
    read the file from its bytes; physc reads its own form, the game's (utf-16 declared over
    ASCII) and true UTF-16 alike."""
    import xml.etree.ElementTree as ElementTree

    from lxml import etree

    level = read_level(GENERATED[0].read_bytes())
    data = emit_level(level).encode("utf-8")
    assert data.startswith(b'<?xml version="1.0" encoding="utf-8"?>')
    assert data.isascii()
    assert ElementTree.fromstring(data).tag == "Level"
    assert etree.fromstring(data).tag == "Level"
    assert len(ElementTree.fromstring(data).find("GameObjects")) == len(level.objects)
    games_form = data.replace(b'encoding="utf-8"', b'encoding="utf-16"')
    for form in (data, games_form, emit_level(level).encode("utf-16")):
        assert read_level(form) == level
