"""Hypothesis strategies: random `.phys` syntax trees and random ways to write them."""

from __future__ import annotations

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
    ast.Declaration, name_nodes, name_nodes, st.lists(name_nodes, max_size=3).map(tuple)
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
