"""Static semantics: the Scenario IR of well-formed scenarios."""

from __future__ import annotations

import pytest

from conftest import EXAMPLES
from physc.dsl.check import check_file
from physc.dsl.parser import parse_text


def check(text: str):
    parsed = parse_text(text)
    assert parsed.diagnostics == ()
    return check_file(parsed.file)


def ir(text: str):
    result = check(text)
    assert [d for d in result.diagnostics if d.is_error] == [], result.diagnostics
    return result.scenarios[0]


def codes(text: str):
    return [d.code for d in check(text).diagnostics]


def test_all_paper_scenarios_check_cleanly():
    parsed = parse_text((EXAMPLES / "paper" / "all.paper.phys").read_text(encoding="utf-8"))
    result = check_file(parsed.file)
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
