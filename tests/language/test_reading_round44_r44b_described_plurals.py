"""Round 44 (r44b): a plural of people said with describing words only and opening its sentence, then
a collective "of them" in apposition ("Bored teenagers, a gang of them, loiter ..."): the small parser
makes the plural the sentence's root, and it was taken for a verb, its adjective for a name (two
groups). The plural is the people the aside counts: one group (language/singular_verbs.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,low,high", [
    ("mall", "Bored teenagers, a gang of them, loiter by the fountain.", 3, 5),
    ("mall", "Tired shoppers, a whole crowd of them, queue at the tills.", 15, 30),
    ("museum", "Sleepy toddlers, a little gaggle of them, trail after the robot.", 5, 12),
    ("zoo", "Curious kids, a small bunch of them, press up against the penguin pool.", 3, 5),
])
def test_described_plural_then_a_collective_of_them_is_one_group(read, world, prompt, low, high):
    (group,) = read(world, prompt).groups
    assert low <= group.count.value <= high
    assert group.who.split()[0][0].isupper() and len(group.who.split()) >= 2


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Mum cooks in the kitchen."),
    ("mall", "Nervous students wait outside the cinema."),
])
def test_plain_subjects_keep_their_reading(read, world, prompt):
    assert len(read(world, prompt).groups) == 1
