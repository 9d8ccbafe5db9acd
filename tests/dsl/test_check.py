"""Static semantics: the Scenario IR of well-formed scenarios."""

from __future__ import annotations

import re

import pytest
from conftest import EXAMPLES

from physc.domains.words import INSTALLED
from physc.dsl.check import check_file
from physc.dsl.parser import parse_text
from physc.suggest import article


def check(text: str):
    parsed = parse_text(text)
    assert parsed.diagnostics == ()
    return check_file(parsed.file, vocabularies=INSTALLED)


def ir(text: str):
    result = check(text)
    assert [d for d in result.diagnostics if d.is_error] == [], result.diagnostics
    return result.scenarios[0]


def codes(text: str):
    return [d.code for d in check(text).diagnostics]


def test_all_paper_scenarios_check_cleanly():
    parsed = parse_text((EXAMPLES / "paper" / "all.paper.phys").read_text(encoding="utf-8"))
    result = check_file(parsed.file, vocabularies=INSTALLED)
    assert result.diagnostics == ()
    assert len(result.scenarios) == 16


def test_objects_typed_by_spelling():
    scenario = ir(
        "scenario X = {hit(bird)(rBlock2)(left) > roll(rBlock2)(surface1)(right) > hit(rBlock2)(pig)(left)"
        " > destroy(rBlock2)(pig)}, {}"
    )
    objects = {o.name: (o.term, o.concrete, o.static, o.declared) for o in scenario.objects}
    assert objects == {
        "bird": ("bird", ("redBird",), False, False),
        "rBlock2": ("rollableBlock", ("circleSmall", "circle"), False, False),
        "surface1": ("surface", ("flatPlatform", "inclinedPlatform"), True, False),
        "pig": ("pig", ("pigSmall", "pigMedium"), False, False),
    }


def test_declarations_narrow_concrete_objects():
    scenario = ir(
        "scenario X { objects { ball: rollableBlock = circle\n target: pig = pigMedium }"
        " interactions { hit(bird, ball, left) > hit(ball, target, left) > destroy(ball, target) } }"
    )
    assert scenario.object("ball").concrete == ("circle",)
    assert scenario.object("target").term == "pig" and scenario.object("target").declared


def test_a_declared_fallable_circle_may_roll():
    scenario = ir(
        "scenario X { objects { fBlock: fallableBlock = circle }"
        " interactions { hit(bird, fBlock, left) > roll(fBlock, surface, right)"
        " > hit(fBlock, pig, left) > destroy(fBlock, pig) } }"
    )
    assert scenario.object("fBlock").concrete == ("circle",)


@pytest.mark.parametrize(
    "restriction, directions",
    [("above", ("left", "right", "below")), ("left", ("right", "above", "below")), ("left | right", ("above", "below"))],
)
def test_restrictions_narrow_directions(restriction, directions):
    scenario = ir(
        f"scenario X = {{[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}}, {{[cannotHit(bird)(pig)({restriction})]}}"
    )
    hit = scenario.interactions[0]
    assert hit.written == ("left", "right", "above", "below")
    assert hit.directions == directions


def test_a_bounce_ends_the_direct_approach():
    # The paper's scenario B: the bird may not hit the pig directly, but may after bouncing.
    scenario = ir(
        "scenario B = {[hit(bird)(iSurface)(any)] > [bounce(bird)(iSurface)(below)] > [hit(bird)(pig)(above)]"
        " > [destroy(bird)(pig)]}, {[cannotHit(bird)(pig)(any)]}"
    )
    assert scenario.interactions[2].directions == ("above",)
    assert codes(
        "scenario B2 = {[hit(bird)(pig)(above)] > [destroy(bird)(pig)]}, {[cannotHit(bird)(pig)(any)]}"
    ) == ["E0501"]


def test_fall_direction_defaults_to_above():
    scenario = ir(
        "scenario F = {[hit(bird)(fBlock)(left)] > [fall(fBlock)(pig)] > [hit(fBlock)(pig)(above)]"
        " > [destroy(fBlock)(pig)]}, {}"
    )
    assert scenario.interactions[1].directions == ("above",)


def test_surfaces_cannot_act():
    assert "E0203" in codes("scenario X = {[hit(surface)(pig)(any)] > [destroy(surface)(pig)]}, {}")


def test_every_pig_must_be_destroyed_once():
    assert codes(
        "scenario X = {[hit(bird)(pig1)(any)] > [destroy(bird)(pig1)] > [hit(bird)(pig2)(left)]"
        " > [destroy(bird)(pig2)]}, {}"
    ) == []
    assert codes("scenario X = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {[cannotHit(bird)(pig2)(any)]}") == [
        "E0404"
    ]


def test_all_errors_of_a_file_in_one_run():
    text = (
        "scenario A = {[hit(bird)(pig)(up)] > [destroy(bird)(pig)]}, {}\n"
        "scenario B = {[hti(bird)(pig)(any)] > [destroy(bird)(pig)]}, {}\n"
        "scenario C = {[hit(bird)(ball)(any)] > [destroy(bird)(pig)]}, {}\n"
    )
    assert codes(text) == ["E0206", "E0201", "E0301"]


def test_unknown_domain_suggests_installed_one():
    (diagnostic,) = check("scenario X { domain angrybird interactions { hit(bird, pig, any) } }").diagnostics
    assert diagnostic.code == "E0701" and diagnostic.help == "did you mean 'angrybirds'?"


# ---- help texts: the fix they propose, applied, leaves a valid scenario ----------------------------
def _apply(text: str, diagnostic) -> str:
    """`text` with the fix that the diagnostic's help proposes (the forms check.py writes)."""
    help_text, span = diagnostic.help, diagnostic.span
    declared = re.match(r"declare it as `(\w+): ([^`]*)`", help_text)
    if declared:
        name = declared.group(1)
        text = re.sub(rf"\b{name}: [^\n]*\n", "", text)  # its old declaration, if any
        return text.replace("objects {\n", f"objects {{\n        {declared.group(0)[15:-1]}\n", 1)
    replaced = re.match(r"(?:use a separate object here|use an object that moves here), e\.g\. `(\w+)`", help_text)
    if replaced:
        return text[: span.start] + replaced.group(1) + text[span.end :]
    earlier = re.match(r"(?:add an earlier interaction that sets it in motion, e\.g\. `|start the sequence .*e\.g\. )([^`]*)`?$", help_text)
    if earlier:
        line_start = text.rfind("\n", 0, span.start) + 1
        indent = len(text[line_start:]) - len(text[line_start:].lstrip("> "))
        return text[: line_start + indent] + earlier.group(1) + " > " + text[line_start + indent :]
    appended = re.match(r"add `(> [^`]*)` at the end of the interactions", help_text)
    if appended:
        end = text.index("\n    }", text.index("interactions {"))
        return text[:end] + "\n        " + appended.group(1) + text[end:]
    raise AssertionError(f"no fix to apply in {help_text!r}")


def _scenario(interactions: str, objects: str = "", restrictions: str = "") -> str:
    lines = "\n        > ".join(interactions.split(" > "))
    return (
        f"scenario X {{\n    objects {{\n{objects}    }}\n    interactions {{\n        {lines}\n    }}\n"
        f"    restrictions {{\n        {restrictions}\n    }}\n}}\n"
    )


BROKEN = {
    # The case: a pig used as a surface must stay a pig for the later destroy.
    "pig as surface": _scenario("hit(bird, rBlock, left) > roll(rBlock, pig, right) > hit(rBlock, pig, left) > destroy(rBlock, pig)"),
    "pig only as surface": _scenario("hit(bird, rBlock, left) > roll(rBlock, pig, right) > hit(rBlock, pig2, left) > destroy(rBlock, pig2)"),
    "fBlock rolls": _scenario("hit(bird, fBlock, left) > roll(fBlock, surface, right) > hit(fBlock, pig, left) > destroy(fBlock, pig)"),
    "fBlock rolls, rBlock taken": _scenario(
        "hit(bird, fBlock, left) > roll(fBlock, surface, right) > hit(fBlock, rBlock, left) > hit(rBlock, pig, left) > destroy(rBlock, pig)"
    ),
    "declared fallable rolls": _scenario(
        "hit(bird, f, left) > roll(f, surface, right) > hit(f, pig, left) > destroy(f, pig)", "        f: fallableBlock\n"
    ),
    "declared pig as surface": _scenario(
        "hit(bird, rBlock, left) > roll(rBlock, p, right) > hit(rBlock, pig, left) > destroy(rBlock, pig)", "        p: pig\n"
    ),
    "declared pig as surface, destroyed": _scenario(
        "hit(bird, rBlock, left) > roll(rBlock, p, right) > hit(rBlock, p, left) > destroy(rBlock, p)", "        p: pig = pigSmall\n"
    ),
    "surface acts": _scenario("hit(bird, rBlock, left) > roll(rBlock, surface, right) > hit(surface, pig, left) > destroy(rBlock, pig)"),
    "surface rolls": _scenario("hit(bird, rBlock, left) > roll(surface, hSurface, right) > hit(rBlock, pig, left) > destroy(rBlock, pig)"),
    "acts before moving": _scenario("hit(bird, rBlock, left) > fall(fBlock, pig) > hit(fBlock, pig, above) > destroy(fBlock, pig)"),
    "first actor": _scenario("roll(rBlock, surface, right) > hit(rBlock, pig, left) > destroy(rBlock, pig)"),
    "pig hit last": _scenario("hit(bird, pig, any) > destroy(bird, pig) > hit(bird, pig2, left)"),
    "pig never hit": _scenario(
        "hit(bird, rBlock, left) > hit(rBlock, pig, left) > destroy(rBlock, pig)", restrictions="cannotHit(bird, pig2, any)"
    ),
    "pig hit, then more": _scenario(
        "hit(bird, rBlock, left) > hit(rBlock, pig, left) > hit(rBlock, sBlock, left) > slide(sBlock, surface, left)",
        restrictions="cannotHit(sBlock, pig, any)",
    ),
}


@pytest.mark.parametrize("name", BROKEN)
def test_the_fix_a_help_proposes_gives_a_valid_scenario(name):
    text = BROKEN[name]
    assert [d for d in check(text).diagnostics if d.is_error]
    for _ in range(3):  # one fix at a time, as a user would
        errors = [d for d in check(text).diagnostics if d.is_error]
        if not errors:
            break
        assert all(d.help for d in errors), errors
        text = _apply(text, errors[0])
    assert [d for d in check(text).diagnostics if d.is_error] == [], text


def _help(text: str, code: str) -> str:
    return next(d.help for d in check(text).diagnostics if d.code == code)


def test_a_pig_used_as_a_surface_is_told_to_use_a_separate_surface():
    help_text = _help(BROKEN["pig as surface"], "E0203")
    assert help_text == (
        "use a separate object here, e.g. `surface` (a surface); 'pig' cannot also be a surface: "
        "'destroy' needs it as a pig"
    )
    assert "an surface" not in help_text


def test_help_names_a_new_object_that_the_scenario_does_not_have():
    assert _help(BROKEN["fBlock rolls"], "E0203") == "declare it as `fBlock: rollableBlock` or use an rBlock"
    assert _help(BROKEN["fBlock rolls, rBlock taken"], "E0203") == "declare it as `fBlock: rollableBlock` or use an rBlock2"


def test_articles_follow_the_word():
    message = next(d.message for d in check(_scenario("hit(bird, rBlock, left) > hit(iSurface, pig, left)")).diagnostics)
    assert "is an inclinedSurface" in message
    assert [article(w) for w in ("rBlock", "surface", "inclinedSurface", "bird", "uBlock", "hSurface")] == [
        "an", "a", "an", "a", "a", "an",
    ]


def test_repeated_restrictions_report_once():
    text = _scenario(
        "hit(bird, rBlock, left) > fall(rBlock, pig) > hit(rBlock, pig, above) > destroy(rBlock, pig)",
        restrictions="\n        ".join(["cannotFall(rBlock)"] * 50 + ["cannotHit(rBlock, pig, above)"] * 50),
    )
    assert sorted(codes(text)) == ["E0501", "E0502"]


def test_restrictions_meet_only_their_interactions():
    """Each restriction narrows the interactions of its own pair, in a long sequence too."""
    chain = " > ".join(f"hit(bird, pig{i}, any) > destroy(bird, pig{i})" for i in range(200))
    scenario = ir(_scenario(chain, restrictions="\n        ".join(f"cannotHit(bird, pig{i}, above)" for i in range(0, 200, 2))))
    hits = [t for t in scenario.interactions if t.name == "hit"]
    assert [len(t.directions) for t in hits] == [3, 4] * 100
