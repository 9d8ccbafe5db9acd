"""Hypothesis strategies: random `.phys` syntax trees and random ways to write them; mutations of
real inputs for fuzzing (tests/dsl/test_fuzz.py, benchmarks/fuzz.py)."""

from __future__ import annotations

import re

from hypothesis import strategies as st

from physc.dsl import ast

KEYWORDS = {"scenario", "domain", "objects", "interactions", "restrictions", "and", "or"}

names = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,7}", fullmatch=True).filter(lambda n: n not in KEYWORDS)
name_nodes = names.map(ast.Name)
titles = st.text(
    alphabet=st.characters(blacklist_categories=("Cs", "Cc"), blacklist_characters="\u2028\u2029\x85"),
    max_size=12,
).map(ast.Text)
arguments = st.lists(name_nodes, min_size=1, max_size=3).map(lambda ns: ast.Argument(tuple(ns)))
terms = st.builds(
    ast.Term, name_nodes, st.lists(arguments, max_size=4).map(tuple)
)
declarations = st.builds(
    ast.Declaration, name_nodes, name_nodes, st.lists(name_nodes, max_size=3).map(tuple),
    materials=st.lists(name_nodes, max_size=2).map(tuple),  # version 2: `name: term(stone | ice)`
)


@st.composite
def scenarios(draw) -> ast.Scenario:
    return ast.Scenario(
        name=draw(name_nodes),
        title=draw(st.none() | titles),
        domain=draw(st.none() | name_nodes),
        objects=tuple(draw(st.lists(declarations, max_size=3))),
        interactions=tuple(draw(st.lists(terms, min_size=1, max_size=4))),
        restrictions=tuple(draw(st.lists(terms, max_size=3))),
    )


files = st.lists(scenarios(), min_size=1, max_size=3).map(lambda ss: ast.File(tuple(ss)))


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


@st.composite
def written(draw, file: ast.File) -> str:
    """Some valid source text for `file`, in a random style, with random comments."""
    spaces = st.sampled_from([" ", "", "  ", "\n", "\n    "])
    comment = st.sampled_from(["# note", "// note", "#", "# > [x] { } \"quoted\""])

    def space() -> str:
        if draw(st.integers(0, 5)) == 0:
            return " " + draw(comment) + "\n"
        return draw(spaces)

    def gap() -> str:  # like space(), but never empty: it separates words
        return space() or " "

    def argument(a: ast.Argument) -> str:
        separators = st.sampled_from([" | ", "|", " ∨ ", " or "])
        text = a.alternatives[0].text
        for alternative in a.alternatives[1:]:
            text += draw(separators) + alternative.text
        return text

    def term(t: ast.Term) -> str:
        if t.arguments and draw(st.booleans()):
            body = t.name.text + "".join(f"({argument(a)})" for a in t.arguments)
        else:
            body = f"{t.name.text}({', '.join(argument(a) for a in t.arguments)})"
        for _ in range(draw(st.integers(0, 2))):
            body = f"[{body}]"
        return body

    def sequence(ts) -> str:
        return (space() + ">" + space()).join(term(t) for t in ts)

    def conjunction(ts) -> str:
        out = ""
        for index, t in enumerate(ts):
            if index:
                out += draw(st.sampled_from([", ", " and ", " & ", " ∧ ", "\n", " ,\n"]))
            out += term(t)
        return out

    parts = []
    for s in file.scenarios:
        head = f"scenario {s.name.text}" + (f" {_quote(s.title.value)}" if s.title else "")
        if s.domain is None and not s.objects and draw(st.booleans()):
            parts.append(f"{head} = {{{sequence(s.interactions)}}}, {{{conjunction(s.restrictions)}}}")
            continue
        sections = []
        if s.domain is not None:
            sections.append(f"domain {s.domain.text}")
        if s.objects or draw(st.booleans()):
            decls = []
            for d in s.objects:
                text = f"{d.name.text}: {d.term.text}"
                if d.materials:
                    text += "(" + " | ".join(m.text for m in d.materials) + ")"
                if d.concrete:
                    text += " = " + " | ".join(c.text for c in d.concrete)
                decls.append(text + draw(st.sampled_from(["", ","])))
            sections.append("objects {" + "\n".join(decls) + "}")
        sections.append("interactions {" + space() + sequence(s.interactions) + space() + "}")
        if s.restrictions or draw(st.booleans()):
            sections.append("restrictions {\n" + conjunction(s.restrictions) + "\n}")
        order = draw(st.permutations(sections))
        parts.append(head + " {" + space() + gap().join(order) + "\n}")
    prefix = draw(st.sampled_from(["", "# header\n\n", "// header\n"]))
    return prefix + "\n".join(p + space() for p in parts)


# ---- fuzzing: mutations of real inputs -----------------------------------------------------------
# Plain functions of a `random.Random`, so that hypothesis drives them through `st.randoms()` (and
# shrinks what they draw) in tests/dsl/test_fuzz.py, and benchmarks/fuzz.py runs them directly, fast.

# Pieces that `.phys` mutations insert: the language's tokens and words, and what a careless or
# hostile file may hold (terminal escapes, bidi controls, odd spaces and line breaks, long words).
PHYS_PIECES = [
    "scenario", "domain", "objects", "interactions", "restrictions", "and", "or", "{", "}", "(", ")",
    "[", "]", ",", ">", "|", "∨", "∧", "&", "=", ":", '"', '"t"', '"\\q"', "#", "//", "\n", "\t", " ",
    "hit", "roll", "fall", "slide", "bounce", "destroy", "cannotHit", "cannotFall", "bird", "pig",
    "pig2", "rBlock", "fBlock", "sBlock", "surface", "hSurface", "iSurface", "rollableBlock",
    "circle", "flatPlatform", "left", "right", "above", "below", "any", "angrybirds", "X", "_",
    "\x00", "\x1b[31m", "\x1b]0;title\x07", "\x9b2J", "\x7f", "\r", "\r\n", "\u202e", "\u2028",
    "\u00a0", "\ufeff", "→", "⋀", "猪", "e\u0301", "a" * 300, "9" * 40,
]
# Pieces for level XML: markup, element and attribute names, hostile declarations and values.
XML_PIECES = [
    "<", ">", "/>", "</", '"', "'", "=", "&amp;", "&#0;", "&#x1b;", "&#xD800;", "&lt;", "&undefined;",
    "<![CDATA[x]]>", "<!-- c -->", "<?xml version=\"1.0\"?>", '<?xml version="1.0" encoding="utf-16"?>',
    '<!DOCTYPE Level [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]>', "&b;",
    '<!DOCTYPE Level SYSTEM "file:///etc/passwd">', "<Level>", "</Level>", "<GameObjects>",
    "</GameObjects>", "<Birds>", "<Bird type=\"BirdRed\" />", "<Block type=\"Circle\" material=\"wood\" x=\"1\" y=\"2\" />",
    "<Pig type=\"BasicSmall\" x=\"0\" y=\"0\" />", "<TNT type=\"\" x=\"0\" y=\"0\" />", "<Platform type=\"Platform\" x=\"0\" y=\"0\" />",
    ' x="', ' y="', ' rotation="', ' scaleX="', ' scaleY="', ' type="', ' material="', ' width="',
    "nan", "inf", "-inf", "1e308", "-1e308", "1e999", "-0", "", "\x00", "\x1b[31m", "\u202e", "\n",
    "<Level>" * 50, "</Level>" * 50,
]
# Values for numeric command-line options: what a careless or hostile user types.
NUMBERS = [
    "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "-1", "0", "-0", "0.0", "1e-320", "4.9e-324",
    "1e308", "-1e308", "1e309", "1e9", "1e18", "9" * 30, "9" * 5000, "-" + "9" * 30, str(2**63),
    str(2**63 - 1), str(2**64), "0x10", "1_000", " 3 ", "", " ", "٣", "３", "1e", "--1", "+1", "1.5",
    "0.01", "0.5", "1", "2", "6", "7", "60", "60.0001", "90", "-90", "90.5", "1000", "1000.5", "abc",
    "\x00", "\x1b[31m1", "1\n", "1,2", "1,2,3,4", ",", "nan,0", "0,nan", "1e999,0", "-9,0.5,high", "1,1,sideways",
]


MAX_MUTANT = 50_000  # characters: room for long lines and deep nesting, small enough to fuzz fast


# Units that mutations copy, drop and swap whole: the terms of a scenario; the elements of a level.
TERM = re.compile(r"\[*[A-Za-z_][A-Za-z0-9_]*\([^()\n]*\)\]*")
ELEMENT = re.compile(r"<[A-Za-z][^<>]*/>")
ATTRIBUTE_VALUE = re.compile(r'(?<==)"[^"]*"')
LEVEL_WORDS = ["", "BirdRed", "BasicSmall", "Circle", "Platform", "wood", "ice", "stone", "TNT", "x" * 200, "Bird Red"]


def mutate_text(rng, text: str, pieces: list[str], corpus: list[str], unit: re.Pattern = TERM) -> str:
    """`text` after one to five random edits: insertions of `pieces`, deletions, copies, swaps,
    replaced characters, a splice with another member of `corpus`, a slice repeated many times,
    a word replaced; and edits of whole `unit`s (terms, elements): copied, dropped, swapped."""
    for _ in range(rng.randint(1, 5)):
        size = len(text)
        at = rng.randint(0, size)
        end = min(size, at + rng.choice((1, 2, 5, 20, 200)))
        kind = rng.choices(range(12), weights=(3, 2, 2, 2, 1, 1, 1, 4, 1, 4, 3, 3))[0]
        units = list(unit.finditer(text)) if kind >= 9 else []
        if kind == 0 or not text:
            text = text[:at] + rng.choice(pieces) + text[at:]
        elif kind == 1:
            text = text[:at] + text[end:]
        elif kind == 2:
            text = text[:end] + text[at:end] + text[end:]
        elif kind == 3:
            text = text[:at] + chr(rng.choice((rng.randint(0, 0x7F), rng.randint(0x80, 0x2FFF), rng.randint(0xE000, 0x10FFFF)))) + text[at + 1 :]
        elif kind == 4:
            other = rng.choice(corpus)
            text = text[:at] + other[rng.randint(0, len(other)) :]
        elif kind == 5:
            other_at = rng.randint(0, size)
            other_end = min(size, other_at + (end - at))
            if other_at >= end:
                text = text[:at] + text[other_at:other_end] + text[end:other_at] + text[at:end] + text[other_end:]
        elif kind == 6:  # a piece repeated: long lines, deep nesting, many terms
            text = text[:at] + text[at:end] * rng.choice((10, 100, 2000 // (end - at + 1))) + text[end:]
        elif kind == 7:  # a word of the text becomes another
            words = list(re.finditer(r"[A-Za-z_][A-Za-z0-9_]*|-?[0-9.]+(?:e-?[0-9]+)?", text))
            if words:
                word = rng.choice(words)
                text = text[: word.start()] + rng.choice(pieces + NUMBERS) + text[word.end() :]
        elif kind == 8:
            text = text[:at]
        elif not units:
            continue
        elif kind == 9:  # a unit copied, once or many times, here or elsewhere
            copied = rng.choice(units).group()
            separator = rng.choice((" > ", "\n", " ", ", "))
            text = text[:at] + (copied + separator) * rng.choice((1, 1, 2, 50, 500)) + text[at:]
        elif kind == 10:
            gone = rng.choice(units)
            text = text[: gone.start()] + text[gone.end() :]
        else:
            first, second = sorted(rng.sample(units, 2), key=lambda m: m.start()) if len(units) > 1 else (units[0], units[0])
            if first is not second:
                text = text[: first.start()] + second.group() + text[first.end() : second.start()] + first.group() + text[second.end() :]
        text = text[:MAX_MUTANT]
    return text


def mutate_level(rng, data: str, corpus: list[str]) -> bytes:
    """A real level's text, mutated, and encoded as a level file may be (UTF-8, UTF-16, with a
    byte-order mark, or with flipped bytes). Most edits keep the XML well-formed (a value replaced
    by a hostile number or name, an attribute dropped, elements copied or dropped), so that the
    checks after parsing are reached; the rest are the edits of `mutate_text`."""
    text = data
    for _ in range(rng.randint(1, 4)):
        values = list(ATTRIBUTE_VALUE.finditer(text))
        if rng.random() < 0.1 or not values:
            text = mutate_text(rng, text, XML_PIECES, corpus, ELEMENT)
            continue
        value = rng.choice(values)
        if rng.random() < 0.8:
            new = rng.choice(NUMBERS + LEVEL_WORDS).replace('"', "&quot;")
            text = text[: value.start()] + f'"{new}"' + text[value.end() :]
        else:  # the attribute goes
            start = text.rfind(" ", 0, value.start())
            text = text[:start] + text[value.end() :]
    encoding = rng.choice(("utf-8", "utf-8", "utf-8", "utf-8-sig", "utf-16", "latin-1"))
    raw = bytearray(text.encode(encoding, "replace"))
    for _ in range(rng.choice((0, 0, 0, 0, 0, 1, 3))):
        if raw:
            raw[rng.randrange(len(raw))] = rng.randrange(256)
    return bytes(raw)


def random_phys(rng) -> str:
    """Text made of the language's pieces, or of any characters."""
    if rng.random() < 0.5:
        return " ".join(rng.choice(PHYS_PIECES) for _ in range(rng.randint(0, 60)))
    return "".join(chr(rng.randint(1, 0x2FFF)) for _ in range(rng.randint(0, 200)))


def random_number(rng) -> str:
    """A value for a numeric option: a hostile or edge value, or any float or integer."""
    kind = rng.randrange(4)
    if kind < 2:
        return rng.choice(NUMBERS)
    if kind == 2:
        return repr(rng.choice((rng.uniform(-2, 100), rng.expovariate(1e-3), -rng.expovariate(1), rng.random() * 10 ** rng.randint(-300, 308))))
    return str(rng.choice((rng.randint(-5, 10), rng.randint(-(2**70), 2**70))))


# The numeric options of each command (physc/cli.py, physc/commands/).
NUMERIC_OPTIONS = {
    "compile": ["--seed", "--layouts", "--time-budget", "--clause-budget", "--min-robustness"],
    "simulate": ["--seconds", "--angle", "--shot"],
    "trace": ["--seconds", "--angle", "--shot"],
    "render": ["--seconds", "--angle", "--shot"],
    "eval": ["--tasks", "--jobs", "--seed", "--time-budget", "--min-robustness"],
}


def random_argv(rng, scenario: str, level: str, folder: str) -> list[str]:
    """A command line of physc with one to three numeric options given random values."""
    command = rng.choice(list(NUMERIC_OPTIONS))
    argv = {
        "compile": ["compile", scenario, "--emit", rng.choice(("scenario", "qsr", "level"))],
        "simulate": ["simulate", level],
        "trace": ["trace", level],
        "render": ["render", level, "-o", f"{folder}/fuzz.png"],
        "eval": ["eval", scenario, "--out", f"{folder}/eval"],
    }[command]
    for _ in range(rng.randint(1, 3)):
        option = rng.choice(NUMERIC_OPTIONS[command])
        value = random_number(rng)
        if option == "--shot":
            value = f"{value},{random_number(rng)}" + rng.choice(("", "", ",low", ",high", ",x"))
        argv += [f"{option}={value}"] if rng.random() < 0.5 or value.startswith("-") else [option, value]
    return argv


def _texts(paths) -> list[str]:
    return [p.read_bytes().decode("utf-8", "replace") for p in paths]


def _examples():
    from conftest import EXAMPLES

    return EXAMPLES


PHYS_CORPUS = _texts(sorted(_examples().rglob("*.phys")))  # every example .phys file, as text
randoms = st.randoms(use_true_random=False)


def fuzz(examples: int):
    """Settings of a short, deterministic fuzz: `examples` inputs, derandomized, no database."""
    from hypothesis import HealthCheck, settings

    return settings(
        max_examples=examples,
        derandomize=True,
        database=None,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much],
    )
