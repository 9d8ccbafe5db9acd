"""Level files are checked on reading: bad numbers, names, sizes and hostile XML are
LevelErrors with a code and a line, and the commands answer them with exit 1, never 70."""

from __future__ import annotations

import time

import pytest
from conftest import run_physc

from physc.domains.angrybirds.level_checks import MAX_BODIES, MAX_COORDINATE, MAX_LEVEL_BYTES
from physc.domains.angrybirds.level_xml import LevelError, parse_level, read_level


def level(*objects: str, birds: str = "<Birds><Bird type='BirdRed'/></Birds>", level_attributes: str = "", head: str = "") -> str:
    """A level whose game objects start on line 4 (one a line)."""
    return f"<Level{level_attributes}>\n{birds}{head}\n<GameObjects>\n" + "\n".join(objects) + "\n</GameObjects>\n</Level>\n"


def error_of(text: str | bytes) -> LevelError:
    with pytest.raises(LevelError) as caught:
        read_level(text) if isinstance(text, bytes) else parse_level(text)
    return caught.value


BLOCK = "<Block type='Circle' material='wood' x='1' y='2' {}/>"
PLATFORM = "<Platform type='Platform' x='1' y='2' {}/>"


@pytest.mark.parametrize(
    "element, code",
    [
        ("<Block type='Circle' material='wood' x='nan' y='2'/>", "E0902"),
        ("<Block type='Circle' material='wood' x='1' y='NaN'/>", "E0902"),
        ("<Block type='Circle' material='wood' x='inf' y='2'/>", "E0902"),
        ("<Block type='Circle' material='wood' x='-Infinity' y='2'/>", "E0902"),
        ("<Block type='Circle' material='wood' x='1e999' y='2'/>", "E0902"),  # overflows to infinity
        ("<Block type='Circle' material='wood' x='1_0' y='2'/>", "E0902"),  # Python's syntax, not the game's
        ("<Block type='Circle' material='wood' x='1e308' y='2'/>", "E0904"),
        ("<Pig type='BasicSmall' x='1' y='-1e308'/>", "E0904"),
        (f"<TNT x='{MAX_COORDINATE + 1:g}' y='2'/>", "E0904"),
        (BLOCK.format("rotation='nan'"), "E0902"),
        (BLOCK.format("rotation='1e9'"), "E0904"),
        (PLATFORM.format("scaleX='0'"), "E0904"),
        (PLATFORM.format("scaleY='-0'"), "E0904"),
        (PLATFORM.format("scaleX='0.001'"), "E0904"),
        (PLATFORM.format("scaleX='1e6'"), "E0904"),
        (PLATFORM.format("scaleY='-1e6'"), "E0904"),
        (PLATFORM.format("scaleX='inf'"), "E0902"),
        ("<Block type='Circle' material='glass' x='1' y='2'/>", "E0905"),
        ("<Block type='Circle' material='WOOD' x='1' y='2'/>", "E0905"),
        ("<Block type='Cirlce' material='wood' x='1' y='2'/>", "E0903"),
    ],
)
def test_a_bad_value_names_its_element_and_line(element, code):
    error = error_of(level(element))
    assert error.code == code
    assert error.line == 4 and error.column is not None
    tag = element[1:].split()[0]
    assert f"<{tag}>" in error.message


def test_the_column_is_the_attributes():
    error = error_of(level("   <Pig type='BasicSmall' x='1' y='nan'/>"))
    assert (error.line, error.column) == (4, 33)
    assert error.message == "<Pig> y=\"nan\" is not a finite number"


@pytest.mark.parametrize(
    "text, code, line",
    [
        (level(level_attributes=" width='0'"), "E0904", 1),
        (level(level_attributes=" width='nan'"), "E0902", 1),
        (level(head="<Camera x='nan' y='0' minWidth='25' maxWidth='35'/>"), "E0902", 2),
        (level(head="<Camera x='0' y='0' minWidth='-25' maxWidth='35'/>"), "E0904", 2),
        (level(head="<Slingshot x='-12' y='inf'/>"), "E0902", 2),
        (level(head="<Score highScore='nan'/>"), "E0902", 2),
    ],
)
def test_level_wide_numbers_are_checked_too(text, code, line):
    error = error_of(text)
    assert (error.code, error.line) == (code, line)


def test_values_at_the_limits_load():
    parsed = parse_level(
        level(
            f"<Pig type='BasicSmall' x='{MAX_COORDINATE:g}' y='-{MAX_COORDINATE:g}' rotation='-720'/>",
            PLATFORM.format("scaleX='-1.38868' scaleY='100'"),  # a negative scale mirrors (two Phy-Q templates have one)
            PLATFORM.format("scaleX='0.01'"),
        )
    )
    assert [o.scale_x for o in parsed.objects] == [None, -1.38868, 0.01]


def test_the_body_limit():
    pigs = [f"<Pig type='BasicSmall' x='{0.6 * k - 90:g}' y='2'/>" for k in range(MAX_BODIES + 5)]
    assert len(parse_level(level(*pigs[:MAX_BODIES])).objects) == MAX_BODIES
    error = error_of(level(*pigs))
    assert (error.code, error.line) == ("E0906", 4 + MAX_BODIES)  # the first object past the limit
    assert str(MAX_BODIES) in error.message


def test_objects_stacked_into_one_another_are_refused_past_the_limit():
    from physc.domains.angrybirds.level_checks import MAX_DEEP_OVERLAPS

    pig = "<Pig type='BasicSmall' x='1' y='2'/>"
    five = level(*[pig] * 5)  # 10 pairs: the most physc plays
    assert len(parse_level(five).objects) == 5 and MAX_DEEP_OVERLAPS == 10
    error = error_of(level(*[pig] * 6))  # 15 pairs
    assert error.code == "E0908" and "15 pairs" in error.message and error.line == 4 + 4  # pair (2, 4), the 11th
    # Touching neighbours, as in real levels (and platforms, which do not move), are not stacked.
    row = [f"<Block type='SquareSmall' material='wood' x='{0.39 * k:g}' y='0'/>" for k in range(40)]
    walls = ["<Platform type='Platform' x='0' y='0' scaleX='5'/>"] * 20
    assert len(parse_level(level(*row, *walls)).objects) == 60


BILLION_LAUGHS = (
    '<?xml version="1.0"?>\n<!DOCTYPE Level [\n<!ENTITY lol "lol">\n'
    + "".join(f'<!ENTITY lol{i} "{("&lol" + (str(i - 1) if i > 1 else "") + ";") * 10}">\n' for i in range(1, 10))
    + "]>\n<Level><Birds><Bird type='BirdRed'/></Birds><GameObjects>&lol9;</GameObjects></Level>\n"
)
HOSTILE = {
    "billion laughs": BILLION_LAUGHS,
    "external entity": '<?xml version="1.0"?>\n<!DOCTYPE Level [<!ENTITY e SYSTEM "file:///etc/passwd">]>\n<Level>&e;</Level>\n',
    "external DTD": '<!DOCTYPE Level SYSTEM "http://127.0.0.1:9/level.dtd">\n<Level/>\n',
    "parameter entity": '<!DOCTYPE Level [<!ENTITY % p SYSTEM "http://127.0.0.1:9/p.dtd"> %p;]>\n<Level/>\n',
    "undefined entity": "<Level>\n&e;</Level>\n",
    "deep nesting": "<Level>" + "<a>" * 100_000 + "</a>" * 100_000 + "</Level>",
    "NUL character": "<Level>\n<Birds>\x00</Birds></Level>",
}


@pytest.mark.parametrize("name", HOSTILE)
def test_hostile_xml_is_refused_at_once(name):
    start = time.perf_counter()
    error = error_of(HOSTILE[name].encode("utf-8"))
    assert error.code == "E0901"
    assert "root:" not in error.message  # nothing of /etc/passwd is read
    assert time.perf_counter() - start < 2.0


def test_a_doctype_is_refused_with_its_line():
    error = error_of(HOSTILE["external entity"].encode())
    assert (error.line, error.column) == (2, 1)
    assert "DOCTYPE" in error.message


def test_oversized_files_are_refused_before_parsing():
    padding = b" " * MAX_LEVEL_BYTES
    error = error_of(b"<Level>" + padding + b"</Level>")
    assert error.code == "E0906" and f"{MAX_LEVEL_BYTES:,}" in error.message
    assert error_of("<Level>" + " " * MAX_LEVEL_BYTES + "</Level>").code == "E0906"


def test_a_level_without_birds_loads():
    parsed = parse_level(level("<Pig type='BasicSmall' x='1' y='-3.27'/>", birds=""))
    assert not parsed.has_birds and len(parsed.objects) == 1
    assert parse_level(level()).has_birds


# ---- the commands -------------------------------------------------------------------
BAD_LEVELS = {
    "nan coordinate": level("<Block type='Circle' material='wood' x='nan' y='2'/>"),
    "huge coordinate": level("<Block type='Circle' material='wood' x='1e308' y='2'/>"),
    "scale 0": level(PLATFORM.format("scaleX='0'")),
    "unknown material": level("<Block type='Circle' material='glass' x='1' y='2'/>"),
    "unknown type": level("<Block type='Circel' material='wood' x='1' y='2'/>"),
    "too many bodies": level(*["<Pig type='BasicSmall' x='1' y='2'/>"] * (MAX_BODIES + 1)),
    "billion laughs": BILLION_LAUGHS,
    "deep nesting": HOSTILE["deep nesting"],
}
COMMANDS = {
    "simulate": ["simulate"],
    "trace": ["trace", "--shot", "0,-3"],
    "render": ["render", "-o", "{out}"],
    "render with a shot": ["render", "-o", "{out}", "--angle", "30"],
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("name", BAD_LEVELS)
def test_bad_levels_end_with_exit_1_and_a_diagnostic(name, command, tmp_path):
    path = tmp_path / "bad.xml"
    path.write_text(BAD_LEVELS[name], encoding="utf-8")
    arguments = [a.format(out=tmp_path / "out.png") for a in COMMANDS[command]]
    run = run_physc(arguments[0], path, *arguments[1:], "--color", "never")
    assert run.status == 1, run.stderr
    assert f"{path}:" in run.stderr and "error[E09" in run.stderr
    assert "Traceback" not in run.stderr and "internal error" not in run.stderr
    assert not (tmp_path / "out.png").exists()


def test_an_oversized_level_on_the_command_line(tmp_path):
    path = tmp_path / "big.xml"
    path.write_bytes(b"<Level>" + b" " * MAX_LEVEL_BYTES + b"</Level>")
    run = run_physc("simulate", path, "--color", "never")
    assert run.status == 1 and "error[E0906]" in run.stderr


def test_a_shot_at_a_level_without_birds_is_a_clear_error(tmp_path):
    path = tmp_path / "nobird.xml"
    path.write_text(level("<Pig type='BasicSmall' x='1' y='-3.27'/>", birds=""), encoding="utf-8")
    assert run_physc("simulate", path).status == 0  # watching it stand needs no bird
    assert run_physc("render", path, "-o", tmp_path / "still.png").status == 0
    for arguments in (["simulate", "--shot", "1,-3.27"], ["trace", "--angle", "30"], ["render", "-o", tmp_path / "shot.png", "--shot", "1,-3.27"]):
        run = run_physc(arguments[0], path, *arguments[1:], "--color", "never")
        assert run.status == 1
        assert f"{path}: error[E0907]: the level has no bird to shoot" in run.stderr
    assert not (tmp_path / "shot.png").exists()
