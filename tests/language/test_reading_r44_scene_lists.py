"""Round 44: an opening order to set a scene with a list of people, each with a participle of what they are
doing ("Have two developers chatting in the kitchen and a lone first-aider sitting in reception", "Have
the twins playing ... and Mum cooking in the kitchen"), gives a group for every item, each where its own
words put it, though the parser joins the later items to the place before them."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,second,where", [
    ("office", "Have two developers chatting in the kitchen and a lone first-aider sitting in reception.",
     "a lone first-aider", "reception"),
    ("residential", "Have the twins playing in the bedroom and Mum cooking in the kitchen.", "Mum", "kitchen"),
    ("museum", "Have a couple of guards standing at the main entrance and Grandma resting on a bench in the great "
               "hall.", "Grandma", "great_hall_benches"),
])
def test_every_listed_doer_is_a_group(read, world, prompt, second, where):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    assert (groups[1].who, groups[1].count.value, groups[1].location) == (second, 1, where)


def test_things_after_the_order_are_no_doers(read):
    groups = read("office", "Have two developers chatting in the kitchen and the printer humming in the corner.").groups
    assert [g.who for g in groups] == ["two developers"]
