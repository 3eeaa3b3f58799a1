"""Round 44: someone whose turn ends in a fronted time clause ("Once the lecturer wraps up, sixty students
pour out of lecture theatre 1") is the scene's moment, not a group of it; a pronoun after the comma ("...,
she walks to the green room") keeps the one who finishes."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,who,count", [
    ("office", "Once the CEO wraps up, twelve staff leave the boardroom.", "twelve staff", 12),
    ("university", "Once the lecturer wraps up, sixty students pour out of lecture theatre 1.", "sixty students", 60),
    ("concert_venue", "When the warm-up comic finishes his set, forty fans head to the bar.", "forty fans", 40),
])
def test_one_who_finishes_is_no_group(read, world, prompt, who, count):
    (g,) = read(world, prompt).groups
    assert (g.who, g.count.value, g.intent) == (who, count, "walk")


def test_a_pronoun_after_the_comma_keeps_them(read):
    (g,) = read("concert_venue", "Once the headliner comes off stage, she walks to the green room.").groups
    assert (g.who.lower(), g.destination) == ("the headliner", "green_room")
